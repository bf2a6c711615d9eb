; Obligation: rma-fixed, form on-rma, r's case uncovered-search.down-2.from-uncovered-both; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b, c, d in R_psi n B, C, D; candidates 1..1 down are blocked (witnesses k); candidate 2 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c, r.d, r.k-1 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.d.y () Real)
(declare-fun r.d.x () Real)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
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
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y))))))
  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x))
                  (* (- r.w.y r.b.y) (- r.w.y r.b.y))))))
  (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x))
                  (* (- r.w.y r.d.y) (- r.w.y r.d.y))))))
  (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x))
                  (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))))
  (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.d.x) (- r.b.x r.d.x))
                  (* (- r.b.y r.d.y) (- r.b.y r.d.y))))))
  (or (and (= r.b.x r.d.x) (= r.b.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x))
                  (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))))
  (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x))
                  (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))))
  (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x))
                  (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))))
  (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!6 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!7 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!8 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!11 (>= 16.0
                (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                   (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!12 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!13 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!14 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!15 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!18 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!19 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!21 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!23 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!29 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 2.0)) (- (- 0.0 0.0) (- 2.0)))))
      (a!34 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 2.0)) (- (- r.w.y 0.0) (- 2.0)))))
      (a!40 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) (- 2.0)) (- (- r.b.y 0.0) (- 2.0)))))
      (a!42 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!48 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 2.0)) (- (- r.c.y 0.0) (- 2.0)))))
      (a!54 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 2.0)) (- (- r.d.y 0.0) (- 2.0)))))
      (a!56 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!57 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!9 (or (and a!7 (< 0.0 (- r.b.y 0.0)))
               (and a!7 (> 0.0 (- r.b.y 0.0)))
               (and a!8 (< 0.0 (- r.b.x 0.0)))
               (and a!8 (> 0.0 (- r.b.x 0.0)))))
      (a!16 (or (and a!14 (< 0.0 (- r.d.y 0.0)))
                (and a!14 (> 0.0 (- r.d.y 0.0)))
                (and a!15 (< 0.0 (- r.d.x 0.0)))
                (and a!15 (> 0.0 (- r.d.x 0.0)))))
      (a!20 (+ a!19 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!24 (or (and a!23 (< 0.0 (- 0.0 0.0))) (and a!23 (> 0.0 (- 0.0 0.0)))))
      (a!26 (not (and a!23 (> 0.0 (- 0.0 0.0)))))
      (a!32 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!37 (not (and a!8 (> 0.0 (- r.b.x 0.0)))))
      (a!43 (or (and a!42 (< 0.0 (- r.c.y 0.0)))
                (and a!42 (> 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!45 (not (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!51 (not (and a!15 (> 0.0 (- r.d.x 0.0)))))
      (a!58 (or (and a!56 (< 0.0 (- r.k-1.y 0.0)))
                (and a!56 (> 0.0 (- r.k-1.y 0.0)))
                (and a!57 (< 0.0 (- r.k-1.x 0.0)))
                (and a!57 (> 0.0 (- r.k-1.x 0.0)))))
      (a!60 (not (and a!57 (> 0.0 (- r.k-1.x 0.0)))))
      (a!63 (+ a!19 (* (- (- r.k-1.y 0.0) (- 2.0)) (- (- r.k-1.y 0.0) (- 2.0))))))
(let ((a!5 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!10 (and (not a!9) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!17 (and (not a!16) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!25 (not (and (not (or a!24 a!24))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!27 (not (and (not (or a!24 a!24))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!28 (or (and (not (or a!24 a!24))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!23 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!24 a!24))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!31 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!33 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!36 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!38 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!44 (not (and (not a!43) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!46 (not (and (not a!43) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!47 (or (and (not a!43) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and (not a!43) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!50 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!52 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!59 (not (and (not a!58)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!61 (not (and (not a!58)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!62 (or (and (not a!58) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                (and a!57 (< 0.0 (- r.k-1.x 0.0)))
                (and (not a!58) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0))))))
(let ((a!30 (and a!25
                 a!26
                 a!27
                 (=> a!28 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!29))))
      (a!35 (and a!31
                 a!32
                 a!33
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!34))))
      (a!39 (or a!10
                (and a!8 (< 0.0 (- r.b.x 0.0)))
                (and (not a!9) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!49 (and a!44
                 a!45
                 a!46
                 (=> a!47 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!48))))
      (a!53 (or (and (not a!16) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                (and a!15 (< 0.0 (- r.d.x 0.0)))
                a!17))
      (a!64 (and a!59
                 a!60
                 a!61
                 (=> a!62 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!63)))))
(let ((a!41 (and a!36
                 a!37
                 a!38
                 (=> a!39 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!40))))
      (a!55 (and a!50
                 a!51
                 a!52
                 (=> a!53 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!54)))))
(let ((a!65 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!5
                 (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                 a!6
                 (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!10
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 a!11
                 (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))
                 (and a!12 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                 a!13
                 (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!17
                 (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                 a!18
                 (> 4.0 a!20)
                 a!21
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!22 a!30))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!35))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!6 a!41))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!11 a!49))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!13 a!55))
                 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!18 a!64)))))
  (=> r.case0 a!65))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k-1.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
