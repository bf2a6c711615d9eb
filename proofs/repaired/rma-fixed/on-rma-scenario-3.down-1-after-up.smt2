; Obligation: rma-fixed, form on-rma, r's case scenario-3.down-1-after-up; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; search up fails: each of its candidates 1..4 within view has a visible blocker (witnesses k); candidate 1 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
; Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg toward their destination (never farther right, never left of r), or a repair's own: repair-align to the greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun r.d.y () Real)
(declare-fun r.d.x () Real)
(declare-fun r.k+1.y () Real)
(declare-fun r.k+1.x () Real)
(declare-fun r.k+2.y () Real)
(declare-fun r.k+2.x () Real)
(declare-fun r.k+3.y () Real)
(declare-fun r.k+3.x () Real)
(declare-fun r.k+4.y () Real)
(declare-fun r.k+4.x () Real)
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
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y))))))
  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                  (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))))
  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                  (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))))
  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                  (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))))
  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                  (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))))
  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x))
                  (* (- r.w.y r.d.y) (- r.w.y r.d.y))))))
  (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x))
                  (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))))
  (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x))
                  (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))))
  (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k+3.x) (- r.w.x r.k+3.x))
                  (* (- r.w.y r.k+3.y) (- r.w.y r.k+3.y))))))
  (or (and (= r.w.x r.k+3.x) (= r.w.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k+4.x) (- r.w.x r.k+4.x))
                  (* (- r.w.y r.k+4.y) (- r.w.y r.k+4.y))))))
  (or (and (= r.w.x r.k+4.x) (= r.w.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x))
                  (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))))
  (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x))
                  (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))))
  (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+3.x) (- r.c.x r.k+3.x))
                  (* (- r.c.y r.k+3.y) (- r.c.y r.k+3.y))))))
  (or (and (= r.c.x r.k+3.x) (= r.c.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+4.x) (- r.c.x r.k+4.x))
                  (* (- r.c.y r.k+4.y) (- r.c.y r.k+4.y))))))
  (or (and (= r.c.x r.k+4.x) (= r.c.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x))
                  (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))))
  (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+2.x) (- r.d.x r.k+2.x))
                  (* (- r.d.y r.k+2.y) (- r.d.y r.k+2.y))))))
  (or (and (= r.d.x r.k+2.x) (= r.d.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+3.x) (- r.d.x r.k+3.x))
                  (* (- r.d.y r.k+3.y) (- r.d.y r.k+3.y))))))
  (or (and (= r.d.x r.k+3.x) (= r.d.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+4.x) (- r.d.x r.k+4.x))
                  (* (- r.d.y r.k+4.y) (- r.d.y r.k+4.y))))))
  (or (and (= r.d.x r.k+4.x) (= r.d.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x))
                  (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))))
  (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x))
                  (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))))
  (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+4.x) (- r.k+1.x r.k+4.x))
                  (* (- r.k+1.y r.k+4.y) (- r.k+1.y r.k+4.y))))))
  (or (and (= r.k+1.x r.k+4.x) (= r.k+1.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x))
                  (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))))
  (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!8 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!10 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!11 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!12 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!13 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!16 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!17 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!18 (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
               (- (- r.k+1.x 0.0) (- r.w.x 0.0))))
      (a!21 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!23 (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
               (- (- r.k+2.x 0.0) (- r.w.x 0.0))))
      (a!26 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0))))
      (a!27 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!28 (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
               (- (- r.k+3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!32 (>= 16.0
                (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                   (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!33 (* (- (- r.k+4.x 0.0) (- r.w.x 0.0))
               (- (- r.k+4.x 0.0) (- r.w.x 0.0))))
      (a!36 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!37 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!45 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 1.0)) (- (- 0.0 0.0) (- 1.0)))))
      (a!51 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 1.0)) (- (- r.w.y 0.0) (- 1.0)))))
      (a!53 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!60 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 1.0)) (- (- r.c.y 0.0) (- 1.0)))))
      (a!67 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 1.0)) (- (- r.d.y 0.0) (- 1.0)))))
      (a!69 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!70 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!80 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!81 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!91 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!92 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!102 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!103 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!14 (or (and a!12 (< 0.0 (- r.d.y 0.0)))
                (and a!12 (> 0.0 (- r.d.y 0.0)))
                (and a!13 (< 0.0 (- r.d.x 0.0)))
                (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!19 (+ a!18 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!24 (+ a!23 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!29 (+ a!28 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!34 (+ a!33 (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))
      (a!38 (or (and a!37 (< 0.0 (- 0.0 0.0))) (and a!37 (> 0.0 (- 0.0 0.0)))))
      (a!40 (not (and a!37 (> 0.0 (- 0.0 0.0)))))
      (a!48 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!54 (or (and a!53 (< 0.0 (- r.c.y 0.0)))
                (and a!53 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!56 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!63 (not (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!71 (or (and a!69 (< 0.0 (- r.k+1.y 0.0)))
                (and a!69 (> 0.0 (- r.k+1.y 0.0)))
                (and a!70 (< 0.0 (- r.k+1.x 0.0)))
                (and a!70 (> 0.0 (- r.k+1.x 0.0)))))
      (a!73 (not (and a!70 (> 0.0 (- r.k+1.x 0.0)))))
      (a!78 (+ a!18 (* (- (- r.k+1.y 0.0) (- 1.0)) (- (- r.k+1.y 0.0) (- 1.0)))))
      (a!82 (or (and a!80 (< 0.0 (- r.k+2.y 0.0)))
                (and a!80 (> 0.0 (- r.k+2.y 0.0)))
                (and a!81 (< 0.0 (- r.k+2.x 0.0)))
                (and a!81 (> 0.0 (- r.k+2.x 0.0)))))
      (a!84 (not (and a!81 (> 0.0 (- r.k+2.x 0.0)))))
      (a!89 (+ a!23 (* (- (- r.k+2.y 0.0) (- 1.0)) (- (- r.k+2.y 0.0) (- 1.0)))))
      (a!93 (or (and a!91 (< 0.0 (- r.k+3.y 0.0)))
                (and a!91 (> 0.0 (- r.k+3.y 0.0)))
                (and a!92 (< 0.0 (- r.k+3.x 0.0)))
                (and a!92 (> 0.0 (- r.k+3.x 0.0)))))
      (a!95 (not (and a!92 (> 0.0 (- r.k+3.x 0.0)))))
      (a!100 (+ a!28
                (* (- (- r.k+3.y 0.0) (- 1.0)) (- (- r.k+3.y 0.0) (- 1.0)))))
      (a!104 (or (and a!102 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!102 (> 0.0 (- r.k+4.y 0.0)))
                 (and a!103 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!103 (> 0.0 (- r.k+4.x 0.0)))))
      (a!106 (not (and a!103 (> 0.0 (- r.k+4.x 0.0)))))
      (a!111 (+ a!33
                (* (- (- r.k+4.y 0.0) (- 1.0)) (- (- r.k+4.y 0.0) (- 1.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!20 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))) a!17 (> 4.0 a!19)))
      (a!25 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))) a!22 (> 4.0 a!24)))
      (a!30 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))) a!27 (> 4.0 a!29)))
      (a!35 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))) a!32 (> 4.0 a!34)))
      (a!39 (not (and (not (or a!38 a!38))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!41 (not (and (not (or a!38 a!38))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!42 (and (not (or a!38 a!38)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!47 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!49 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!55 (not (and (not a!54) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!57 (not (and (not a!54) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!58 (and (not a!54) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!62 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!64 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!65 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!72 (not (and (not a!71)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!74 (not (and (not a!71)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!75 (and (not a!71) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!83 (not (and (not a!82)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!85 (not (and (not a!82)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!86 (and (not a!82) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!94 (not (and (not a!93)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!96 (not (and (not a!93)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!97 (and (not a!93) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!105 (not (and (not a!104)
                       (> 0.0 (- r.k+4.x 0.0))
                       (< 0.0 (- r.k+4.y 0.0)))))
      (a!107 (not (and (not a!104)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!108 (and (not a!104) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0)))))
(let ((a!6 (or a!5
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!43 (or a!42
                (and a!37 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!38 a!38))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!44 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!42))
      (a!50 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!5))
      (a!59 (or a!58
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!54) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!66 (or a!65 (and a!13 (< 0.0 (- r.d.x 0.0))) a!15))
      (a!76 (or a!75
                (and a!70 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!71) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!77 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!75))
      (a!87 (or a!86
                (and a!81 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!82) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!88 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!86))
      (a!98 (or a!97
                (and a!92 (< 0.0 (- r.k+3.x 0.0)))
                (and (not a!93) (< 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0)))))
      (a!99 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 a!97))
      (a!109 (or a!108
                 (and a!103 (< 0.0 (- r.k+4.x 0.0)))
                 (and (not a!104)
                      (< 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!110 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!108)))
(let ((a!46 (and a!39
                 a!40
                 a!41
                 (=> a!43 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!44)
                 (not (> 4.0 a!45))))
      (a!52 (and a!47
                 a!48
                 a!49
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!50)
                 (not (> 4.0 a!51))))
      (a!61 (and a!55
                 a!56
                 a!57
                 (=> a!59 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!58))
                 (not (> 4.0 a!60))))
      (a!68 (and a!62
                 a!63
                 a!64
                 (=> a!66 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!11 a!65))
                 (not (> 4.0 a!67))))
      (a!79 (and a!72
                 a!73
                 a!74
                 (=> a!76 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!77)
                 (not (> 4.0 a!78))))
      (a!90 (and a!83
                 a!84
                 a!85
                 (=> a!87 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!88)
                 (not (> 4.0 a!89))))
      (a!101 (and a!94
                  a!95
                  a!96
                  (=> a!98 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!99)
                  (not (> 4.0 a!100))))
      (a!112 (and a!105
                  a!106
                  a!107
                  (=> a!109 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!110)
                  (not (> 4.0 a!111)))))
(let ((a!113 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!6
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!7
                  a!8
                  (and a!9 (< 0.0 (- r.c.x 0.0)))
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  a!10
                  a!11
                  a!15
                  (or (not a!16) a!20)
                  (or (not a!21) a!25)
                  (or (not a!26) a!30)
                  (or (not a!31) a!35)
                  a!16
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!36 a!46))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!52))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!7 a!61))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!10 a!68))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!17 a!79))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!22 a!90))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!27 a!101))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!32 a!112)))))
  (=> r.case0 a!113))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
