; Obligation: rma-fixed, form on-rma, r's case scenario-2.down-1; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b in R_psi n B, c in R_psi n C; universal: no visible robot in R_psi n D; candidate 1 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
; Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg toward their destination (never farther right, never left of r), or a repair's own: repair-align to the greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.b.y () Real)
(declare-fun r.b.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun r.case0 () Bool)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y))))))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y))))))
  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y))))))
  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x))
                  (* (- r.w.y r.b.y) (- r.w.y r.b.y))))))
  (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!8 (and (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!10 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!13 (>= 16.0
                (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                   (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!14 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!15 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!16 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!17 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!18 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!26 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 1.0)) (- (- 0.0 0.0) (- 1.0)))))
      (a!32 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 1.0)) (- (- r.w.y 0.0) (- 1.0)))))
      (a!39 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) (- 1.0)) (- (- r.b.y 0.0) (- 1.0)))))
      (a!41 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!48 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 1.0)) (- (- r.c.y 0.0) (- 1.0))))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (or (and a!9 (< 0.0 (- r.b.y 0.0)))
                (and a!9 (> 0.0 (- r.b.y 0.0)))
                (and a!10 (< 0.0 (- r.b.x 0.0)))
                (and a!10 (> 0.0 (- r.b.x 0.0)))))
      (a!19 (or (and a!18 (< 0.0 (- 0.0 0.0))) (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!21 (not (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!29 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!35 (not (and a!10 (> 0.0 (- r.b.x 0.0)))))
      (a!42 (or (and a!41 (< 0.0 (- r.c.y 0.0)))
                (and a!41 (> 0.0 (- r.c.y 0.0)))
                (and a!15 (< 0.0 (- r.c.x 0.0)))
                (and a!15 (> 0.0 (- r.c.x 0.0)))))
      (a!44 (not (and a!15 (> 0.0 (- r.c.x 0.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!12 (and (not a!11) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!20 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!22 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!23 (and (not (or a!19 a!19)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!28 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!30 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!34 (not (and (not a!11) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!36 (not (and (not a!11) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!37 (and (not a!11) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0))))
      (a!43 (not (and (not a!42) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!45 (not (and (not a!42) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!46 (and (not a!42) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
(let ((a!6 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               a!5))
      (a!24 (or (and (not (or a!19 a!19))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!18 (< 0.0 (- 0.0 0.0)))
                a!23))
      (a!25 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!23))
      (a!31 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!5))
      (a!38 (or a!12 (and a!10 (< 0.0 (- r.b.x 0.0))) a!37))
      (a!47 (or (and (not a!42) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!15 (< 0.0 (- r.c.x 0.0)))
                a!46)))
(let ((a!27 (and a!20
                 a!21
                 a!22
                 (=> a!24 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!25)
                 (not (> 4.0 a!26))))
      (a!33 (and a!28
                 a!29
                 a!30
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!31)
                 (not (> 4.0 a!32))))
      (a!40 (and a!34
                 a!35
                 a!36
                 (=> a!38 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!37))
                 (not (> 4.0 a!39))))
      (a!49 (and a!43
                 a!44
                 a!45
                 (=> a!47 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!14 a!46))
                 (not (> 4.0 a!48)))))
(let ((a!50 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!6
                 (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                 a!7
                 a!8
                 a!12
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 a!13
                 a!14
                 (and a!15 (< 0.0 (- r.c.x 0.0)))
                 a!16
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!17 a!27))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!33))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!7 a!40))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!13 a!49)))))
  (=> r.case0 a!50))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
