; Obligation: rma-fixed, form on-rma, r's case scenario-3.up-7; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; candidates 1..6 up are blocked (witnesses k); candidate 7 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4, r.k+5, r.k+6 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
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
(declare-fun r.k+5.y () Real)
(declare-fun r.k+5.x () Real)
(declare-fun r.k+6.y () Real)
(declare-fun r.k+6.x () Real)
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
               (+ (* (- 0.0 r.k+5.x) (- 0.0 r.k+5.x))
                  (* (- 0.0 r.k+5.y) (- 0.0 r.k+5.y))))))
  (or (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k+6.x) (- 0.0 r.k+6.x))
                  (* (- 0.0 r.k+6.y) (- 0.0 r.k+6.y))))))
  (or (and (= 0.0 r.k+6.x) (= 0.0 r.k+6.y)) a!1)))
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
               (+ (* (- r.w.x r.k+5.x) (- r.w.x r.k+5.x))
                  (* (- r.w.y r.k+5.y) (- r.w.y r.k+5.y))))))
  (or (and (= r.w.x r.k+5.x) (= r.w.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k+6.x) (- r.w.x r.k+6.x))
                  (* (- r.w.y r.k+6.y) (- r.w.y r.k+6.y))))))
  (or (and (= r.w.x r.k+6.x) (= r.w.y r.k+6.y)) a!1)))
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
               (+ (* (- r.c.x r.k+5.x) (- r.c.x r.k+5.x))
                  (* (- r.c.y r.k+5.y) (- r.c.y r.k+5.y))))))
  (or (and (= r.c.x r.k+5.x) (= r.c.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+6.x) (- r.c.x r.k+6.x))
                  (* (- r.c.y r.k+6.y) (- r.c.y r.k+6.y))))))
  (or (and (= r.c.x r.k+6.x) (= r.c.y r.k+6.y)) a!1)))
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
               (+ (* (- r.d.x r.k+5.x) (- r.d.x r.k+5.x))
                  (* (- r.d.y r.k+5.y) (- r.d.y r.k+5.y))))))
  (or (and (= r.d.x r.k+5.x) (= r.d.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+6.x) (- r.d.x r.k+6.x))
                  (* (- r.d.y r.k+6.y) (- r.d.y r.k+6.y))))))
  (or (and (= r.d.x r.k+6.x) (= r.d.y r.k+6.y)) a!1)))
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
               (+ (* (- r.k+1.x r.k+5.x) (- r.k+1.x r.k+5.x))
                  (* (- r.k+1.y r.k+5.y) (- r.k+1.y r.k+5.y))))))
  (or (and (= r.k+1.x r.k+5.x) (= r.k+1.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+6.x) (- r.k+1.x r.k+6.x))
                  (* (- r.k+1.y r.k+6.y) (- r.k+1.y r.k+6.y))))))
  (or (and (= r.k+1.x r.k+6.x) (= r.k+1.y r.k+6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x))
                  (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))))
  (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+5.x) (- r.k+2.x r.k+5.x))
                  (* (- r.k+2.y r.k+5.y) (- r.k+2.y r.k+5.y))))))
  (or (and (= r.k+2.x r.k+5.x) (= r.k+2.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+6.x) (- r.k+2.x r.k+6.x))
                  (* (- r.k+2.y r.k+6.y) (- r.k+2.y r.k+6.y))))))
  (or (and (= r.k+2.x r.k+6.x) (= r.k+2.y r.k+6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+5.x) (- r.k+3.x r.k+5.x))
                  (* (- r.k+3.y r.k+5.y) (- r.k+3.y r.k+5.y))))))
  (or (and (= r.k+3.x r.k+5.x) (= r.k+3.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+6.x) (- r.k+3.x r.k+6.x))
                  (* (- r.k+3.y r.k+6.y) (- r.k+3.y r.k+6.y))))))
  (or (and (= r.k+3.x r.k+6.x) (= r.k+3.y r.k+6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k+5.x) (- r.k+4.x r.k+5.x))
                  (* (- r.k+4.y r.k+5.y) (- r.k+4.y r.k+5.y))))))
  (or (and (= r.k+4.x r.k+5.x) (= r.k+4.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k+6.x) (- r.k+4.x r.k+6.x))
                  (* (- r.k+4.y r.k+6.y) (- r.k+4.y r.k+6.y))))))
  (or (and (= r.k+4.x r.k+6.x) (= r.k+4.y r.k+6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+5.x r.k+6.x) (- r.k+5.x r.k+6.x))
                  (* (- r.k+5.y r.k+6.y) (- r.k+5.y r.k+6.y))))))
  (or (and (= r.k+5.x r.k+6.x) (= r.k+5.y r.k+6.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!4 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!9 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!10 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!11 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!12 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!15 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!16 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!17 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!19 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!23 (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
               (- (- r.k+1.x 0.0) (- r.w.x 0.0))))
      (a!25 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!26 (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
               (- (- r.k+2.x 0.0) (- r.w.x 0.0))))
      (a!28 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!29 (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
               (- (- r.k+3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0
                (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                   (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!32 (* (- (- r.k+4.x 0.0) (- r.w.x 0.0))
               (- (- r.k+4.x 0.0) (- r.w.x 0.0))))
      (a!34 (>= 16.0
                (+ (* (- 0.0 r.k+5.x) (- 0.0 r.k+5.x))
                   (* (- 0.0 r.k+5.y) (- 0.0 r.k+5.y)))))
      (a!35 (* (- (- r.k+5.x 0.0) (- r.w.x 0.0))
               (- (- r.k+5.x 0.0) (- r.w.x 0.0))))
      (a!37 (>= 16.0
                (+ (* (- 0.0 r.k+6.x) (- 0.0 r.k+6.x))
                   (* (- 0.0 r.k+6.y) (- 0.0 r.k+6.y)))))
      (a!38 (* (- (- r.k+6.x 0.0) (- r.w.x 0.0))
               (- (- r.k+6.x 0.0) (- r.w.x 0.0))))
      (a!40 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!41 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!50 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 7.0) (- (- 0.0 0.0) 7.0))))
      (a!56 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 7.0) (- (- r.w.y 0.0) 7.0))))
      (a!64 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 7.0) (- (- r.c.y 0.0) 7.0))))
      (a!71 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 7.0) (- (- r.d.y 0.0) 7.0))))
      (a!73 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!75 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!86 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!88 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!99 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!101 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!112 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!114 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!125 (and (> (- r.k+5.x 0.0) (- 2.0)) (> 2.0 (- r.k+5.x 0.0))))
      (a!127 (and (> (- r.k+5.y 0.0) (- 2.0)) (> 2.0 (- r.k+5.y 0.0))))
      (a!138 (and (> (- r.k+6.x 0.0) (- 2.0)) (> 2.0 (- r.k+6.x 0.0))))
      (a!140 (and (> (- r.k+6.y 0.0) (- 2.0)) (> 2.0 (- r.k+6.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- r.c.y 0.0)))
                (and a!12 (> 0.0 (- r.c.y 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- r.d.y 0.0)))
                (and a!17 (> 0.0 (- r.d.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!27 (+ a!26 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!30 (+ a!29 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!33 (+ a!32 (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))
      (a!36 (+ a!35 (* (- (- r.k+5.y 0.0) 5.0) (- (- r.k+5.y 0.0) 5.0))))
      (a!39 (+ a!38 (* (- (- r.k+6.y 0.0) 6.0) (- (- r.k+6.y 0.0) 6.0))))
      (a!42 (or (and a!41 (< 0.0 (- 0.0 0.0))) (and a!41 (> 0.0 (- 0.0 0.0)))))
      (a!74 (or (and a!73 (< 0.0 (- r.k+1.y 0.0)))
                (and a!73 (> 0.0 (- r.k+1.y 0.0)))))
      (a!84 (+ a!23 (* (- (- r.k+1.y 0.0) 7.0) (- (- r.k+1.y 0.0) 7.0))))
      (a!87 (or (and a!86 (< 0.0 (- r.k+2.y 0.0)))
                (and a!86 (> 0.0 (- r.k+2.y 0.0)))))
      (a!97 (+ a!26 (* (- (- r.k+2.y 0.0) 7.0) (- (- r.k+2.y 0.0) 7.0))))
      (a!100 (or (and a!99 (< 0.0 (- r.k+3.y 0.0)))
                 (and a!99 (> 0.0 (- r.k+3.y 0.0)))))
      (a!110 (+ a!29 (* (- (- r.k+3.y 0.0) 7.0) (- (- r.k+3.y 0.0) 7.0))))
      (a!113 (or (and a!112 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!112 (> 0.0 (- r.k+4.y 0.0)))))
      (a!123 (+ a!32 (* (- (- r.k+4.y 0.0) 7.0) (- (- r.k+4.y 0.0) 7.0))))
      (a!126 (or (and a!125 (< 0.0 (- r.k+5.y 0.0)))
                 (and a!125 (> 0.0 (- r.k+5.y 0.0)))))
      (a!136 (+ a!35 (* (- (- r.k+5.y 0.0) 7.0) (- (- r.k+5.y 0.0) 7.0))))
      (a!139 (or (and a!138 (< 0.0 (- r.k+6.y 0.0)))
                 (and a!138 (> 0.0 (- r.k+6.y 0.0)))))
      (a!149 (+ a!38 (* (- (- r.k+6.y 0.0) 7.0) (- (- r.k+6.y 0.0) 7.0)))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (and (and a!11 (< 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!20 (or a!18
                (and a!19 (< 0.0 (- r.d.x 0.0)))
                (and a!19 (> 0.0 (- r.d.x 0.0)))))
      (a!43 (not (and (not (or a!42 a!42))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!44 (and (and a!41 (> 0.0 (- 0.0 0.0))) (not a!42)))
      (a!45 (not (and (not (or a!42 a!42))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!46 (and (not (or a!42 a!42)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!47 (and (and a!41 (< 0.0 (- 0.0 0.0))) (not a!42)))
      (a!53 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!58 (or a!13
                (and a!11 (< 0.0 (- r.c.x 0.0)))
                (and a!11 (> 0.0 (- r.c.x 0.0)))))
      (a!60 (and (and a!11 (> 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!67 (and (and a!19 (> 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!70 (and (and a!19 (< 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!76 (or a!74
                (and a!75 (< 0.0 (- r.k+1.x 0.0)))
                (and a!75 (> 0.0 (- r.k+1.x 0.0)))))
      (a!78 (and (and a!75 (> 0.0 (- r.k+1.x 0.0))) (not a!74)))
      (a!81 (and (and a!75 (< 0.0 (- r.k+1.x 0.0))) (not a!74)))
      (a!89 (or a!87
                (and a!88 (< 0.0 (- r.k+2.x 0.0)))
                (and a!88 (> 0.0 (- r.k+2.x 0.0)))))
      (a!91 (and (and a!88 (> 0.0 (- r.k+2.x 0.0))) (not a!87)))
      (a!94 (and (and a!88 (< 0.0 (- r.k+2.x 0.0))) (not a!87)))
      (a!102 (or a!100
                 (and a!101 (< 0.0 (- r.k+3.x 0.0)))
                 (and a!101 (> 0.0 (- r.k+3.x 0.0)))))
      (a!104 (and (and a!101 (> 0.0 (- r.k+3.x 0.0))) (not a!100)))
      (a!107 (and (and a!101 (< 0.0 (- r.k+3.x 0.0))) (not a!100)))
      (a!115 (or a!113
                 (and a!114 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!114 (> 0.0 (- r.k+4.x 0.0)))))
      (a!117 (and (and a!114 (> 0.0 (- r.k+4.x 0.0))) (not a!113)))
      (a!120 (and (and a!114 (< 0.0 (- r.k+4.x 0.0))) (not a!113)))
      (a!128 (or a!126
                 (and a!127 (< 0.0 (- r.k+5.x 0.0)))
                 (and a!127 (> 0.0 (- r.k+5.x 0.0)))))
      (a!130 (and (and a!127 (> 0.0 (- r.k+5.x 0.0))) (not a!126)))
      (a!133 (and (and a!127 (< 0.0 (- r.k+5.x 0.0))) (not a!126)))
      (a!141 (or a!139
                 (and a!140 (< 0.0 (- r.k+6.x 0.0)))
                 (and a!140 (> 0.0 (- r.k+6.x 0.0)))))
      (a!143 (and (and a!140 (> 0.0 (- r.k+6.x 0.0))) (not a!139)))
      (a!146 (and (and a!140 (< 0.0 (- r.k+6.x 0.0))) (not a!139))))
(let ((a!6 (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!21 (and (not a!20) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!48 (or a!46
                a!47
                (and (not (or a!42 a!42))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!49 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!46))
      (a!52 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!54 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!59 (not (and (not a!58) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!61 (not (and (not a!58) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!62 (and (not a!58) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!66 (not (and (not a!20) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!68 (not (and (not a!20) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!69 (and (not a!20) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!77 (not (and (not a!76)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!79 (not (and (not a!76)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!80 (and (not a!76) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!90 (not (and (not a!89)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!92 (not (and (not a!89)
                      (< 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!93 (and (not a!89) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!103 (not (and (not a!102)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!105 (not (and (not a!102)
                       (< 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!106 (and (not a!102) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!116 (not (and (not a!115)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!118 (not (and (not a!115)
                       (< 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!119 (and (not a!115) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!129 (not (and (not a!128)
                       (> 0.0 (- r.k+5.x 0.0))
                       (> 0.0 (- r.k+5.y 0.0)))))
      (a!131 (not (and (not a!128)
                       (< 0.0 (- r.k+5.x 0.0))
                       (> 0.0 (- r.k+5.y 0.0)))))
      (a!132 (and (not a!128) (< 0.0 (- r.k+5.x 0.0)) (< 0.0 (- r.k+5.y 0.0))))
      (a!142 (not (and (not a!141)
                       (> 0.0 (- r.k+6.x 0.0))
                       (> 0.0 (- r.k+6.y 0.0)))))
      (a!144 (not (and (not a!141)
                       (< 0.0 (- r.k+6.x 0.0))
                       (> 0.0 (- r.k+6.y 0.0)))))
      (a!145 (and (not a!141) (< 0.0 (- r.k+6.x 0.0)) (< 0.0 (- r.k+6.y 0.0)))))
(let ((a!8 (or a!6
               a!7
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!51 (and a!43
                 (not a!44)
                 a!45
                 (=> a!48 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!49)
                 (not (> 4.0 a!50))))
      (a!55 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!63 (or a!62
                a!14
                (and (not a!58) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!72 (and a!66
                 (not a!67)
                 a!68
                 (=> (or a!69 a!70 a!21) (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!16 a!69))
                 (not (> 4.0 a!71))))
      (a!82 (or a!80
                a!81
                (and (not a!76) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!83 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!80))
      (a!95 (or a!93
                a!94
                (and (not a!89) (> 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
      (a!96 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!93))
      (a!108 (or a!106
                 a!107
                 (and (not a!102)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!109 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!106))
      (a!121 (or a!119
                 a!120
                 (and (not a!115)
                      (> 0.0 (- r.k+4.x 0.0))
                      (< 0.0 (- r.k+4.y 0.0)))))
      (a!122 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!119))
      (a!134 (or a!132
                 a!133
                 (and (not a!128)
                      (> 0.0 (- r.k+5.x 0.0))
                      (< 0.0 (- r.k+5.y 0.0)))))
      (a!135 (and (> (- (- r.k+5.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+5.x 0.0) (- r.w.x 0.0)))
                  a!132))
      (a!147 (or a!145
                 a!146
                 (and (not a!141)
                      (> 0.0 (- r.k+6.x 0.0))
                      (< 0.0 (- r.k+6.y 0.0)))))
      (a!148 (and (> (- (- r.k+6.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+6.x 0.0) (- r.w.x 0.0)))
                  a!145)))
(let ((a!57 (and a!52
                 (not a!53)
                 a!54
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!55)
                 (not (> 4.0 a!56))))
      (a!65 (and a!59
                 (not a!60)
                 a!61
                 (=> a!63 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!62))
                 (not (> 4.0 a!64))))
      (a!85 (and a!77
                 (not a!78)
                 a!79
                 (=> a!82 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!83)
                 (not (> 4.0 a!84))))
      (a!98 (and a!90
                 (not a!91)
                 a!92
                 (=> a!95 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!96)
                 (not (> 4.0 a!97))))
      (a!111 (and a!103
                  (not a!104)
                  a!105
                  (=> a!108 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!109)
                  (not (> 4.0 a!110))))
      (a!124 (and a!116
                  (not a!117)
                  a!118
                  (=> a!121 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!122)
                  (not (> 4.0 a!123))))
      (a!137 (and a!129
                  (not a!130)
                  a!131
                  (=> a!134 (>= (- r.k+5.x 0.0) (- r.w.x 0.0)))
                  (not a!135)
                  (not (> 4.0 a!136))))
      (a!150 (and a!142
                  (not a!143)
                  a!144
                  (=> a!147 (>= (- r.k+6.x 0.0) (- r.w.x 0.0)))
                  (not a!148)
                  (not (> 4.0 a!149)))))
(let ((a!151 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!8
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!9
                  a!10
                  a!14
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  a!15
                  a!16
                  a!21
                  (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                  a!22
                  (> 4.0 a!24)
                  (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                  a!25
                  (> 4.0 a!27)
                  (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                  a!28
                  (> 4.0 a!30)
                  (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)))
                  a!31
                  (> 4.0 a!33)
                  (not (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)))
                  a!34
                  (> 4.0 a!36)
                  (not (and (= 0.0 r.k+6.x) (= 0.0 r.k+6.y)))
                  a!37
                  (> 4.0 a!39)
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!40 a!51))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!57))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!9 a!65))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!15 a!72))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!22 a!85))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!25 a!98))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!28 a!111))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!31 a!124))
                  (or (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)) (=> a!34 a!137))
                  (or (and (= 0.0 r.k+6.x) (= 0.0 r.k+6.y)) (=> a!37 a!150)))))
  (=> r.case0 a!151)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (>= 0.0 r.k+5.x)
     (>= 0.0 r.k+6.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
