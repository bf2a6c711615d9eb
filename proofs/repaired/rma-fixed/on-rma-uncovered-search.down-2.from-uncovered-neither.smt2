; Obligation: rma-fixed, form on-rma, r's case uncovered-search.down-2.from-uncovered-neither; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C; universal: no visible robot in R_psi n B and R_psi n D; candidates 1..1 down are blocked (witnesses k); candidate 2 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.k-1 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
; Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg toward their destination (never farther right, never left of r), or a repair's own: repair-align to the greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun r.case0 () Bool)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y))))))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y))))))
  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x))
                  (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))))
  (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x))
                  (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))))
  (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!8 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!9 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!10 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!11 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!12 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!14 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!15 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!16 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!24 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!25 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 2.0)) (- (- 0.0 0.0) (- 2.0)))))
      (a!30 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!31 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 2.0)) (- (- r.w.y 0.0) (- 2.0)))))
      (a!33 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!41 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 2.0)) (- (- r.c.y 0.0) (- 2.0)))))
      (a!43 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!44 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!52 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!13 (+ a!12 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!17 (or (and a!16 (< 0.0 (- 0.0 0.0))) (and a!16 (> 0.0 (- 0.0 0.0)))))
      (a!19 (not (and a!16 (> 0.0 (- 0.0 0.0)))))
      (a!28 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!34 (or (and a!33 (< 0.0 (- r.c.y 0.0)))
                (and a!33 (> 0.0 (- r.c.y 0.0)))
                (and a!10 (< 0.0 (- r.c.x 0.0)))
                (and a!10 (> 0.0 (- r.c.x 0.0)))))
      (a!36 (not (and a!10 (> 0.0 (- r.c.x 0.0)))))
      (a!45 (or (and a!43 (< 0.0 (- r.k-1.y 0.0)))
                (and a!43 (> 0.0 (- r.k-1.y 0.0)))
                (and a!44 (< 0.0 (- r.k-1.x 0.0)))
                (and a!44 (> 0.0 (- r.k-1.x 0.0)))))
      (a!47 (not (and a!44 (> 0.0 (- r.k-1.x 0.0)))))
      (a!53 (+ a!12 (* (- (- r.k-1.y 0.0) (- 2.0)) (- (- r.k-1.y 0.0) (- 2.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!6 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!18 (not (and (not (or a!17 a!17))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!20 (not (and (not (or a!17 a!17))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!21 (and (not (or a!17 a!17)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!22 (and (not (or a!17 a!17)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!27 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!29 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!35 (not (and (not a!34) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!37 (not (and (not a!34) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!38 (and (not a!34) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!39 (and (not a!34) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0))))
      (a!46 (not (and (not a!45)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!48 (not (and (not a!45)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!49 (and (not a!45) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!50 (and (not a!45) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
(let ((a!7 (or a!5 (and a!3 (< 0.0 (- r.w.x 0.0))) a!6))
      (a!23 (or a!21 (and a!16 (< 0.0 (- 0.0 0.0))) a!22))
      (a!40 (or a!38 (and a!10 (< 0.0 (- r.c.x 0.0))) a!39))
      (a!51 (or a!49 (and a!44 (< 0.0 (- r.k-1.x 0.0))) a!50)))
(let ((a!26 (and a!18
                 a!19
                 a!20
                 (=> a!23 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!24 a!21))
                 (not (and a!24 a!22))
                 (not (> 4.0 a!25))))
      (a!32 (and a!27
                 a!28
                 a!29
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!30 a!5))
                 (not (and a!30 a!6))
                 (not (> 4.0 a!31))))
      (a!42 (and a!35
                 a!36
                 a!37
                 (=> a!40 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!9 a!38))
                 (not (and a!9 a!39))
                 (not (> 4.0 a!41))))
      (a!54 (and a!46
                 a!47
                 a!48
                 (=> a!51 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (and a!52 a!49))
                 (not (and a!52 a!50))
                 (not (> 4.0 a!53)))))
(let ((a!55 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!7
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 a!8
                 a!9
                 (and a!10 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                 a!11
                 (> 4.0 a!13)
                 a!14
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!15 a!26))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!32))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!8 a!42))
                 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!11 a!54)))))
  (=> r.case0 a!55))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.k-1.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
