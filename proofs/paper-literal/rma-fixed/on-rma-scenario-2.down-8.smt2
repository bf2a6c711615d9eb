; Obligation: rma-fixed, form on-rma, r's case scenario-2.down-8; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b in R_psi n B, c in R_psi n C; universal: no visible robot in R_psi n D; candidates 1..7 down are blocked (witnesses k); candidate 8 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c, r.k-1, r.k-2, r.k-3, r.k-4, r.k-5, r.k-6, r.k-7 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.b.y () Real)
(declare-fun r.b.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun r.k-5.y () Real)
(declare-fun r.k-5.x () Real)
(declare-fun r.k-6.y () Real)
(declare-fun r.k-6.x () Real)
(declare-fun r.k-7.y () Real)
(declare-fun r.k-7.x () Real)
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
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))))
  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x))
                  (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))))
  (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x))
                  (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y))))))
  (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-7.x) (- 0.0 r.k-7.x))
                  (* (- 0.0 r.k-7.y) (- 0.0 r.k-7.y))))))
  (or (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x))
                  (* (- r.w.y r.b.y) (- r.w.y r.b.y))))))
  (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
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
               (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x))
                  (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))))
  (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-5.x) (- r.w.x r.k-5.x))
                  (* (- r.w.y r.k-5.y) (- r.w.y r.k-5.y))))))
  (or (and (= r.w.x r.k-5.x) (= r.w.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-6.x) (- r.w.x r.k-6.x))
                  (* (- r.w.y r.k-6.y) (- r.w.y r.k-6.y))))))
  (or (and (= r.w.x r.k-6.x) (= r.w.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-7.x) (- r.w.x r.k-7.x))
                  (* (- r.w.y r.k-7.y) (- r.w.y r.k-7.y))))))
  (or (and (= r.w.x r.k-7.x) (= r.w.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
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
               (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x))
                  (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))))
  (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-5.x) (- r.b.x r.k-5.x))
                  (* (- r.b.y r.k-5.y) (- r.b.y r.k-5.y))))))
  (or (and (= r.b.x r.k-5.x) (= r.b.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-6.x) (- r.b.x r.k-6.x))
                  (* (- r.b.y r.k-6.y) (- r.b.y r.k-6.y))))))
  (or (and (= r.b.x r.k-6.x) (= r.b.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-7.x) (- r.b.x r.k-7.x))
                  (* (- r.b.y r.k-7.y) (- r.b.y r.k-7.y))))))
  (or (and (= r.b.x r.k-7.x) (= r.b.y r.k-7.y)) a!1)))
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
               (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x))
                  (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))))
  (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-5.x) (- r.c.x r.k-5.x))
                  (* (- r.c.y r.k-5.y) (- r.c.y r.k-5.y))))))
  (or (and (= r.c.x r.k-5.x) (= r.c.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-6.x) (- r.c.x r.k-6.x))
                  (* (- r.c.y r.k-6.y) (- r.c.y r.k-6.y))))))
  (or (and (= r.c.x r.k-6.x) (= r.c.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-7.x) (- r.c.x r.k-7.x))
                  (* (- r.c.y r.k-7.y) (- r.c.y r.k-7.y))))))
  (or (and (= r.c.x r.k-7.x) (= r.c.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x))
                  (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))))
  (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x))
                  (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))))
  (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x))
                  (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))))
  (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-5.x) (- r.k-1.x r.k-5.x))
                  (* (- r.k-1.y r.k-5.y) (- r.k-1.y r.k-5.y))))))
  (or (and (= r.k-1.x r.k-5.x) (= r.k-1.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-6.x) (- r.k-1.x r.k-6.x))
                  (* (- r.k-1.y r.k-6.y) (- r.k-1.y r.k-6.y))))))
  (or (and (= r.k-1.x r.k-6.x) (= r.k-1.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-7.x) (- r.k-1.x r.k-7.x))
                  (* (- r.k-1.y r.k-7.y) (- r.k-1.y r.k-7.y))))))
  (or (and (= r.k-1.x r.k-7.x) (= r.k-1.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x))
                  (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))))
  (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x))
                  (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))))
  (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-5.x) (- r.k-2.x r.k-5.x))
                  (* (- r.k-2.y r.k-5.y) (- r.k-2.y r.k-5.y))))))
  (or (and (= r.k-2.x r.k-5.x) (= r.k-2.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-6.x) (- r.k-2.x r.k-6.x))
                  (* (- r.k-2.y r.k-6.y) (- r.k-2.y r.k-6.y))))))
  (or (and (= r.k-2.x r.k-6.x) (= r.k-2.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-7.x) (- r.k-2.x r.k-7.x))
                  (* (- r.k-2.y r.k-7.y) (- r.k-2.y r.k-7.y))))))
  (or (and (= r.k-2.x r.k-7.x) (= r.k-2.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x))
                  (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))))
  (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-5.x) (- r.k-3.x r.k-5.x))
                  (* (- r.k-3.y r.k-5.y) (- r.k-3.y r.k-5.y))))))
  (or (and (= r.k-3.x r.k-5.x) (= r.k-3.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-6.x) (- r.k-3.x r.k-6.x))
                  (* (- r.k-3.y r.k-6.y) (- r.k-3.y r.k-6.y))))))
  (or (and (= r.k-3.x r.k-6.x) (= r.k-3.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-7.x) (- r.k-3.x r.k-7.x))
                  (* (- r.k-3.y r.k-7.y) (- r.k-3.y r.k-7.y))))))
  (or (and (= r.k-3.x r.k-7.x) (= r.k-3.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k-5.x) (- r.k-4.x r.k-5.x))
                  (* (- r.k-4.y r.k-5.y) (- r.k-4.y r.k-5.y))))))
  (or (and (= r.k-4.x r.k-5.x) (= r.k-4.y r.k-5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k-6.x) (- r.k-4.x r.k-6.x))
                  (* (- r.k-4.y r.k-6.y) (- r.k-4.y r.k-6.y))))))
  (or (and (= r.k-4.x r.k-6.x) (= r.k-4.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k-7.x) (- r.k-4.x r.k-7.x))
                  (* (- r.k-4.y r.k-7.y) (- r.k-4.y r.k-7.y))))))
  (or (and (= r.k-4.x r.k-7.x) (= r.k-4.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-5.x r.k-6.x) (- r.k-5.x r.k-6.x))
                  (* (- r.k-5.y r.k-6.y) (- r.k-5.y r.k-6.y))))))
  (or (and (= r.k-5.x r.k-6.x) (= r.k-5.y r.k-6.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-5.x r.k-7.x) (- r.k-5.x r.k-7.x))
                  (* (- r.k-5.y r.k-7.y) (- r.k-5.y r.k-7.y))))))
  (or (and (= r.k-5.x r.k-7.x) (= r.k-5.y r.k-7.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-6.x r.k-7.x) (- r.k-6.x r.k-7.x))
                  (* (- r.k-6.y r.k-7.y) (- r.k-6.y r.k-7.y))))))
  (or (and (= r.k-6.x r.k-7.x) (= r.k-6.y r.k-7.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!4 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!9 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!10 (and (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))))
      (a!11 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!13 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!16 (>= 16.0
                (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                   (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!17 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!18 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!19 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!23 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!25 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!26 (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
               (- (- r.k-2.x 0.0) (- r.w.x 0.0))))
      (a!28 (>= 16.0
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!29 (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
               (- (- r.k-3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0
                (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                   (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y)))))
      (a!32 (* (- (- r.k-4.x 0.0) (- r.w.x 0.0))
               (- (- r.k-4.x 0.0) (- r.w.x 0.0))))
      (a!34 (>= 16.0
                (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x))
                   (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y)))))
      (a!35 (* (- (- r.k-5.x 0.0) (- r.w.x 0.0))
               (- (- r.k-5.x 0.0) (- r.w.x 0.0))))
      (a!37 (>= 16.0
                (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x))
                   (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y)))))
      (a!38 (* (- (- r.k-6.x 0.0) (- r.w.x 0.0))
               (- (- r.k-6.x 0.0) (- r.w.x 0.0))))
      (a!40 (>= 16.0
                (+ (* (- 0.0 r.k-7.x) (- 0.0 r.k-7.x))
                   (* (- 0.0 r.k-7.y) (- 0.0 r.k-7.y)))))
      (a!41 (* (- (- r.k-7.x 0.0) (- r.w.x 0.0))
               (- (- r.k-7.x 0.0) (- r.w.x 0.0))))
      (a!43 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!44 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!53 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 8.0)) (- (- 0.0 0.0) (- 8.0)))))
      (a!59 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 8.0)) (- (- r.w.y 0.0) (- 8.0)))))
      (a!66 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) (- 8.0)) (- (- r.b.y 0.0) (- 8.0)))))
      (a!74 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 8.0)) (- (- r.c.y 0.0) (- 8.0)))))
      (a!76 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!78 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!89 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!91 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!102 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!104 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!115 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!117 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!128 (and (> (- r.k-5.x 0.0) (- 2.0)) (> 2.0 (- r.k-5.x 0.0))))
      (a!130 (and (> (- r.k-5.y 0.0) (- 2.0)) (> 2.0 (- r.k-5.y 0.0))))
      (a!141 (and (> (- r.k-6.x 0.0) (- 2.0)) (> 2.0 (- r.k-6.x 0.0))))
      (a!143 (and (> (- r.k-6.y 0.0) (- 2.0)) (> 2.0 (- r.k-6.y 0.0))))
      (a!154 (and (> (- r.k-7.x 0.0) (- 2.0)) (> 2.0 (- r.k-7.x 0.0))))
      (a!156 (and (> (- r.k-7.y 0.0) (- 2.0)) (> 2.0 (- r.k-7.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!12 (or (and a!11 (< 0.0 (- r.b.y 0.0)))
                (and a!11 (> 0.0 (- r.b.y 0.0)))))
      (a!20 (or (and a!19 (< 0.0 (- r.c.y 0.0)))
                (and a!19 (> 0.0 (- r.c.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!27 (+ a!26 (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))
      (a!30 (+ a!29 (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))
      (a!33 (+ a!32 (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))
      (a!36 (+ a!35 (* (- (- r.k-5.y 0.0) (- 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))
      (a!39 (+ a!38 (* (- (- r.k-6.y 0.0) (- 6.0)) (- (- r.k-6.y 0.0) (- 6.0)))))
      (a!42 (+ a!41 (* (- (- r.k-7.y 0.0) (- 7.0)) (- (- r.k-7.y 0.0) (- 7.0)))))
      (a!45 (or (and a!44 (< 0.0 (- 0.0 0.0))) (and a!44 (> 0.0 (- 0.0 0.0)))))
      (a!77 (or (and a!76 (< 0.0 (- r.k-1.y 0.0)))
                (and a!76 (> 0.0 (- r.k-1.y 0.0)))))
      (a!87 (+ a!23 (* (- (- r.k-1.y 0.0) (- 8.0)) (- (- r.k-1.y 0.0) (- 8.0)))))
      (a!90 (or (and a!89 (< 0.0 (- r.k-2.y 0.0)))
                (and a!89 (> 0.0 (- r.k-2.y 0.0)))))
      (a!100 (+ a!26
                (* (- (- r.k-2.y 0.0) (- 8.0)) (- (- r.k-2.y 0.0) (- 8.0)))))
      (a!103 (or (and a!102 (< 0.0 (- r.k-3.y 0.0)))
                 (and a!102 (> 0.0 (- r.k-3.y 0.0)))))
      (a!113 (+ a!29
                (* (- (- r.k-3.y 0.0) (- 8.0)) (- (- r.k-3.y 0.0) (- 8.0)))))
      (a!116 (or (and a!115 (< 0.0 (- r.k-4.y 0.0)))
                 (and a!115 (> 0.0 (- r.k-4.y 0.0)))))
      (a!126 (+ a!32
                (* (- (- r.k-4.y 0.0) (- 8.0)) (- (- r.k-4.y 0.0) (- 8.0)))))
      (a!129 (or (and a!128 (< 0.0 (- r.k-5.y 0.0)))
                 (and a!128 (> 0.0 (- r.k-5.y 0.0)))))
      (a!139 (+ a!35
                (* (- (- r.k-5.y 0.0) (- 8.0)) (- (- r.k-5.y 0.0) (- 8.0)))))
      (a!142 (or (and a!141 (< 0.0 (- r.k-6.y 0.0)))
                 (and a!141 (> 0.0 (- r.k-6.y 0.0)))))
      (a!152 (+ a!38
                (* (- (- r.k-6.y 0.0) (- 8.0)) (- (- r.k-6.y 0.0) (- 8.0)))))
      (a!155 (or (and a!154 (< 0.0 (- r.k-7.y 0.0)))
                 (and a!154 (> 0.0 (- r.k-7.y 0.0)))))
      (a!165 (+ a!41
                (* (- (- r.k-7.y 0.0) (- 8.0)) (- (- r.k-7.y 0.0) (- 8.0))))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!6 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (or a!12
                (and a!13 (< 0.0 (- r.b.x 0.0)))
                (and a!13 (> 0.0 (- r.b.x 0.0)))))
      (a!21 (and (and a!18 (< 0.0 (- r.c.x 0.0))) (not a!20)))
      (a!46 (not (and (not (or a!45 a!45))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!47 (and (and a!44 (> 0.0 (- 0.0 0.0))) (not a!45)))
      (a!48 (not (and (not (or a!45 a!45))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!49 (and (and a!44 (< 0.0 (- 0.0 0.0))) (not a!45)))
      (a!50 (and (not (or a!45 a!45)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!56 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!62 (and (and a!13 (> 0.0 (- r.b.x 0.0))) (not a!12)))
      (a!64 (and (and a!13 (< 0.0 (- r.b.x 0.0))) (not a!12)))
      (a!68 (or a!20
                (and a!18 (< 0.0 (- r.c.x 0.0)))
                (and a!18 (> 0.0 (- r.c.x 0.0)))))
      (a!70 (and (and a!18 (> 0.0 (- r.c.x 0.0))) (not a!20)))
      (a!79 (or a!77
                (and a!78 (< 0.0 (- r.k-1.x 0.0)))
                (and a!78 (> 0.0 (- r.k-1.x 0.0)))))
      (a!81 (and (and a!78 (> 0.0 (- r.k-1.x 0.0))) (not a!77)))
      (a!83 (and (and a!78 (< 0.0 (- r.k-1.x 0.0))) (not a!77)))
      (a!92 (or a!90
                (and a!91 (< 0.0 (- r.k-2.x 0.0)))
                (and a!91 (> 0.0 (- r.k-2.x 0.0)))))
      (a!94 (and (and a!91 (> 0.0 (- r.k-2.x 0.0))) (not a!90)))
      (a!96 (and (and a!91 (< 0.0 (- r.k-2.x 0.0))) (not a!90)))
      (a!105 (or a!103
                 (and a!104 (< 0.0 (- r.k-3.x 0.0)))
                 (and a!104 (> 0.0 (- r.k-3.x 0.0)))))
      (a!107 (and (and a!104 (> 0.0 (- r.k-3.x 0.0))) (not a!103)))
      (a!109 (and (and a!104 (< 0.0 (- r.k-3.x 0.0))) (not a!103)))
      (a!118 (or a!116
                 (and a!117 (< 0.0 (- r.k-4.x 0.0)))
                 (and a!117 (> 0.0 (- r.k-4.x 0.0)))))
      (a!120 (and (and a!117 (> 0.0 (- r.k-4.x 0.0))) (not a!116)))
      (a!122 (and (and a!117 (< 0.0 (- r.k-4.x 0.0))) (not a!116)))
      (a!131 (or a!129
                 (and a!130 (< 0.0 (- r.k-5.x 0.0)))
                 (and a!130 (> 0.0 (- r.k-5.x 0.0)))))
      (a!133 (and (and a!130 (> 0.0 (- r.k-5.x 0.0))) (not a!129)))
      (a!135 (and (and a!130 (< 0.0 (- r.k-5.x 0.0))) (not a!129)))
      (a!144 (or a!142
                 (and a!143 (< 0.0 (- r.k-6.x 0.0)))
                 (and a!143 (> 0.0 (- r.k-6.x 0.0)))))
      (a!146 (and (and a!143 (> 0.0 (- r.k-6.x 0.0))) (not a!142)))
      (a!148 (and (and a!143 (< 0.0 (- r.k-6.x 0.0))) (not a!142)))
      (a!157 (or a!155
                 (and a!156 (< 0.0 (- r.k-7.x 0.0)))
                 (and a!156 (> 0.0 (- r.k-7.x 0.0)))))
      (a!159 (and (and a!156 (> 0.0 (- r.k-7.x 0.0))) (not a!155)))
      (a!161 (and (and a!156 (< 0.0 (- r.k-7.x 0.0))) (not a!155))))
(let ((a!7 (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!51 (or (and (not (or a!45 a!45))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                a!49
                a!50))
      (a!52 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!50))
      (a!55 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!57 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!61 (not (and (not a!14) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!63 (not (and (not a!14) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!65 (and (not a!14) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!69 (not (and (not a!68) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!71 (not (and (not a!68) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!72 (and (not a!68) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!80 (not (and (not a!79)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!82 (not (and (not a!79)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!84 (and (not a!79) (> 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!93 (not (and (not a!92)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!95 (not (and (not a!92)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!97 (and (not a!92) (> 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!106 (not (and (not a!105)
                       (> 0.0 (- r.k-3.x 0.0))
                       (> 0.0 (- r.k-3.y 0.0)))))
      (a!108 (not (and (not a!105)
                       (< 0.0 (- r.k-3.x 0.0))
                       (> 0.0 (- r.k-3.y 0.0)))))
      (a!110 (and (not a!105) (> 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0))))
      (a!119 (not (and (not a!118)
                       (> 0.0 (- r.k-4.x 0.0))
                       (> 0.0 (- r.k-4.y 0.0)))))
      (a!121 (not (and (not a!118)
                       (< 0.0 (- r.k-4.x 0.0))
                       (> 0.0 (- r.k-4.y 0.0)))))
      (a!123 (and (not a!118) (> 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0))))
      (a!132 (not (and (not a!131)
                       (> 0.0 (- r.k-5.x 0.0))
                       (> 0.0 (- r.k-5.y 0.0)))))
      (a!134 (not (and (not a!131)
                       (< 0.0 (- r.k-5.x 0.0))
                       (> 0.0 (- r.k-5.y 0.0)))))
      (a!136 (and (not a!131) (> 0.0 (- r.k-5.x 0.0)) (< 0.0 (- r.k-5.y 0.0))))
      (a!145 (not (and (not a!144)
                       (> 0.0 (- r.k-6.x 0.0))
                       (> 0.0 (- r.k-6.y 0.0)))))
      (a!147 (not (and (not a!144)
                       (< 0.0 (- r.k-6.x 0.0))
                       (> 0.0 (- r.k-6.y 0.0)))))
      (a!149 (and (not a!144) (> 0.0 (- r.k-6.x 0.0)) (< 0.0 (- r.k-6.y 0.0))))
      (a!158 (not (and (not a!157)
                       (> 0.0 (- r.k-7.x 0.0))
                       (> 0.0 (- r.k-7.y 0.0)))))
      (a!160 (not (and (not a!157)
                       (< 0.0 (- r.k-7.x 0.0))
                       (> 0.0 (- r.k-7.y 0.0)))))
      (a!162 (and (not a!157) (> 0.0 (- r.k-7.x 0.0)) (< 0.0 (- r.k-7.y 0.0)))))
(let ((a!8 (or (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!6
               a!7))
      (a!54 (and a!46
                 (not a!47)
                 a!48
                 (=> a!51 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!52)
                 (not (> 4.0 a!53))))
      (a!58 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!7))
      (a!67 (and a!61
                 (not a!62)
                 a!63
                 (=> (or a!15 a!64 a!65) (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!65))
                 (not (> 4.0 a!66))))
      (a!73 (or (and (not a!68) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                a!21
                a!72))
      (a!85 (or (and (not a!79) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                a!83
                a!84))
      (a!86 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 a!84))
      (a!98 (or (and (not a!92) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                a!96
                a!97))
      (a!99 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 a!97))
      (a!111 (or (and (not a!105)
                      (< 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))
                 a!109
                 a!110))
      (a!112 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  a!110))
      (a!124 (or (and (not a!118)
                      (< 0.0 (- r.k-4.x 0.0))
                      (< 0.0 (- r.k-4.y 0.0)))
                 a!122
                 a!123))
      (a!125 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))
                  a!123))
      (a!137 (or (and (not a!131)
                      (< 0.0 (- r.k-5.x 0.0))
                      (< 0.0 (- r.k-5.y 0.0)))
                 a!135
                 a!136))
      (a!138 (and (> (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  a!136))
      (a!150 (or (and (not a!144)
                      (< 0.0 (- r.k-6.x 0.0))
                      (< 0.0 (- r.k-6.y 0.0)))
                 a!148
                 a!149))
      (a!151 (and (> (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0)))
                  a!149))
      (a!163 (or (and (not a!157)
                      (< 0.0 (- r.k-7.x 0.0))
                      (< 0.0 (- r.k-7.y 0.0)))
                 a!161
                 a!162))
      (a!164 (and (> (- (- r.k-7.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0)))
                  a!162)))
(let ((a!60 (and a!55
                 (not a!56)
                 a!57
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!58)
                 (not (> 4.0 a!59))))
      (a!75 (and a!69
                 (not a!70)
                 a!71
                 (=> a!73 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!17 a!72))
                 (not (> 4.0 a!74))))
      (a!88 (and a!80
                 (not a!81)
                 a!82
                 (=> a!85 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!86)
                 (not (> 4.0 a!87))))
      (a!101 (and a!93
                  (not a!94)
                  a!95
                  (=> a!98 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  (not a!99)
                  (not (> 4.0 a!100))))
      (a!114 (and a!106
                  (not a!107)
                  a!108
                  (=> a!111 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  (not a!112)
                  (not (> 4.0 a!113))))
      (a!127 (and a!119
                  (not a!120)
                  a!121
                  (=> a!124 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                  (not a!125)
                  (not (> 4.0 a!126))))
      (a!140 (and a!132
                  (not a!133)
                  a!134
                  (=> a!137 (>= (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  (not a!138)
                  (not (> 4.0 a!139))))
      (a!153 (and a!145
                  (not a!146)
                  a!147
                  (=> a!150 (>= (- r.k-6.x 0.0) (- r.w.x 0.0)))
                  (not a!151)
                  (not (> 4.0 a!152))))
      (a!166 (and a!158
                  (not a!159)
                  a!160
                  (=> a!163 (>= (- r.k-7.x 0.0) (- r.w.x 0.0)))
                  (not a!164)
                  (not (> 4.0 a!165)))))
(let ((a!167 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!8
                  (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                  a!9
                  a!10
                  a!15
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!16
                  a!17
                  a!21
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  a!22
                  (> 4.0 a!24)
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  a!25
                  (> 4.0 a!27)
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  a!28
                  (> 4.0 a!30)
                  (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                  a!31
                  (> 4.0 a!33)
                  (not (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)))
                  a!34
                  (> 4.0 a!36)
                  (not (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)))
                  a!37
                  (> 4.0 a!39)
                  (not (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y)))
                  a!40
                  (> 4.0 a!42)
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!43 a!54))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!60))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!9 a!67))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!16 a!75))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!22 a!88))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!25 a!101))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!28 a!114))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) (=> a!31 a!127))
                  (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)) (=> a!34 a!140))
                  (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)) (=> a!37 a!153))
                  (or (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y)) (=> a!40 a!166)))))
  (=> r.case0 a!167)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (>= 0.0 r.k-4.x)
     (>= 0.0 r.k-5.x)
     (>= 0.0 r.k-6.x)
     (>= 0.0 r.k-7.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
