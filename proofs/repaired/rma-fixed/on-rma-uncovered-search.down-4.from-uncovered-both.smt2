; Obligation: rma-fixed, form on-rma, r's case uncovered-search.down-4.from-uncovered-both; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b, c, d in R_psi n B, C, D; candidates 1..3 down are blocked (witnesses k); candidate 4 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c, r.d, r.k-1, r.k-2, r.k-3 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
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
               (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                  (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))))
  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                  (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))))
  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) a!1)))
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
               (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x))
                  (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))))
  (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x))
                  (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))))
  (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) a!1)))
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
               (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x))
                  (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))))
  (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x))
                  (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))))
  (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x))
                  (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))))
  (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x))
                  (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))))
  (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x))
                  (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))))
  (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x))
                  (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))))
  (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k-2.x) (- r.d.x r.k-2.x))
                  (* (- r.d.y r.k-2.y) (- r.d.y r.k-2.y))))))
  (or (and (= r.d.x r.k-2.x) (= r.d.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k-3.x) (- r.d.x r.k-3.x))
                  (* (- r.d.y r.k-3.y) (- r.d.y r.k-3.y))))))
  (or (and (= r.d.x r.k-3.x) (= r.d.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x))
                  (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))))
  (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x))
                  (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))))
  (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x))
                  (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))))
  (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) a!1)))
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
      (a!21 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!22 (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
               (- (- r.k-2.x 0.0) (- r.w.x 0.0))))
      (a!24 (>= 16.0
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!25 (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
               (- (- r.k-3.x 0.0) (- r.w.x 0.0))))
      (a!27 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!28 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!29 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!35 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 4.0)) (- (- 0.0 0.0) (- 4.0)))))
      (a!40 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 4.0)) (- (- r.w.y 0.0) (- 4.0)))))
      (a!46 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) (- 4.0)) (- (- r.b.y 0.0) (- 4.0)))))
      (a!48 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!54 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 4.0)) (- (- r.c.y 0.0) (- 4.0)))))
      (a!60 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 4.0)) (- (- r.d.y 0.0) (- 4.0)))))
      (a!62 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!63 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!71 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!72 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!80 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!81 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0)))))
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
      (a!23 (+ a!22 (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))
      (a!26 (+ a!25 (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))
      (a!30 (or (and a!29 (< 0.0 (- 0.0 0.0))) (and a!29 (> 0.0 (- 0.0 0.0)))))
      (a!32 (not (and a!29 (> 0.0 (- 0.0 0.0)))))
      (a!38 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!43 (not (and a!8 (> 0.0 (- r.b.x 0.0)))))
      (a!49 (or (and a!48 (< 0.0 (- r.c.y 0.0)))
                (and a!48 (> 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!51 (not (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!57 (not (and a!15 (> 0.0 (- r.d.x 0.0)))))
      (a!64 (or (and a!62 (< 0.0 (- r.k-1.y 0.0)))
                (and a!62 (> 0.0 (- r.k-1.y 0.0)))
                (and a!63 (< 0.0 (- r.k-1.x 0.0)))
                (and a!63 (> 0.0 (- r.k-1.x 0.0)))))
      (a!66 (not (and a!63 (> 0.0 (- r.k-1.x 0.0)))))
      (a!69 (+ a!19 (* (- (- r.k-1.y 0.0) (- 4.0)) (- (- r.k-1.y 0.0) (- 4.0)))))
      (a!73 (or (and a!71 (< 0.0 (- r.k-2.y 0.0)))
                (and a!71 (> 0.0 (- r.k-2.y 0.0)))
                (and a!72 (< 0.0 (- r.k-2.x 0.0)))
                (and a!72 (> 0.0 (- r.k-2.x 0.0)))))
      (a!75 (not (and a!72 (> 0.0 (- r.k-2.x 0.0)))))
      (a!78 (+ a!22 (* (- (- r.k-2.y 0.0) (- 4.0)) (- (- r.k-2.y 0.0) (- 4.0)))))
      (a!82 (or (and a!80 (< 0.0 (- r.k-3.y 0.0)))
                (and a!80 (> 0.0 (- r.k-3.y 0.0)))
                (and a!81 (< 0.0 (- r.k-3.x 0.0)))
                (and a!81 (> 0.0 (- r.k-3.x 0.0)))))
      (a!84 (not (and a!81 (> 0.0 (- r.k-3.x 0.0)))))
      (a!87 (+ a!25 (* (- (- r.k-3.y 0.0) (- 4.0)) (- (- r.k-3.y 0.0) (- 4.0))))))
(let ((a!5 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!10 (and (not a!9) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!17 (and (not a!16) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!31 (not (and (not (or a!30 a!30))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!33 (not (and (not (or a!30 a!30))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!34 (or (and (not (or a!30 a!30))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!29 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!30 a!30))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!37 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!39 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!42 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!44 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!50 (not (and (not a!49) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!52 (not (and (not a!49) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!53 (or (and (not a!49) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and (not a!49) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!56 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!58 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!65 (not (and (not a!64)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!67 (not (and (not a!64)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!68 (or (and (not a!64) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                (and a!63 (< 0.0 (- r.k-1.x 0.0)))
                (and (not a!64) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!74 (not (and (not a!73)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!76 (not (and (not a!73)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!77 (or (and (not a!73) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                (and a!72 (< 0.0 (- r.k-2.x 0.0)))
                (and (not a!73) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
      (a!83 (not (and (not a!82)
                      (> 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))))
      (a!85 (not (and (not a!82)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!86 (or (and (not a!82) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))
                (and a!81 (< 0.0 (- r.k-3.x 0.0)))
                (and (not a!82) (< 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0))))))
(let ((a!36 (and a!31
                 a!32
                 a!33
                 (=> a!34 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!35))))
      (a!41 (and a!37
                 a!38
                 a!39
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!40))))
      (a!45 (or a!10
                (and a!8 (< 0.0 (- r.b.x 0.0)))
                (and (not a!9) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!55 (and a!50
                 a!51
                 a!52
                 (=> a!53 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!54))))
      (a!59 (or (and (not a!16) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                (and a!15 (< 0.0 (- r.d.x 0.0)))
                a!17))
      (a!70 (and a!65
                 a!66
                 a!67
                 (=> a!68 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!69))))
      (a!79 (and a!74
                 a!75
                 a!76
                 (=> a!77 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!78))))
      (a!88 (and a!83
                 a!84
                 a!85
                 (=> a!86 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!87)))))
(let ((a!47 (and a!42
                 a!43
                 a!44
                 (=> a!45 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!46))))
      (a!61 (and a!56
                 a!57
                 a!58
                 (=> a!59 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!60)))))
(let ((a!89 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                 (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 a!21
                 (> 4.0 a!23)
                 (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                 a!24
                 (> 4.0 a!26)
                 a!27
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!28 a!36))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!41))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!6 a!47))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!11 a!55))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!13 a!61))
                 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!18 a!70))
                 (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!21 a!79))
                 (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!24 a!88)))))
  (=> r.case0 a!89))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
