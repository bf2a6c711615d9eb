; Obligation: connectivity, form one-mover, r's case scenario-3.down-3-after-up; model paper-centralized, scheduler centralized.
; Claim: whenever r decides this case, every robot o at rest that r saw before the round is still visible after it.
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; search up fails: each of its candidates 1..4 within view has a visible blocker (witnesses k); candidates 1..2 down are blocked (witnesses k); candidate 3 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4, r.k-1, r.k-2, o (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun o.y () Real)
(declare-fun o.x () Real)
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
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                  (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))))
  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) a!1)))
(assert (<= 4.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
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
               (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x))
                  (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))))
  (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x))
                  (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))))
  (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x o.x) (- r.w.x o.x))
                  (* (- r.w.y o.y) (- r.w.y o.y))))))
  (or (and (= r.w.x o.x) (= r.w.y o.y)) a!1)))
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
               (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x))
                  (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))))
  (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x))
                  (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))))
  (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x o.x) (- r.c.x o.x))
                  (* (- r.c.y o.y) (- r.c.y o.y))))))
  (or (and (= r.c.x o.x) (= r.c.y o.y)) a!1)))
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
               (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x))
                  (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))))
  (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k-2.x) (- r.d.x r.k-2.x))
                  (* (- r.d.y r.k-2.y) (- r.d.y r.k-2.y))))))
  (or (and (= r.d.x r.k-2.x) (= r.d.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x o.x) (- r.d.x o.x))
                  (* (- r.d.y o.y) (- r.d.y o.y))))))
  (or (and (= r.d.x o.x) (= r.d.y o.y)) a!1)))
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
               (+ (* (- r.k+1.x r.k-1.x) (- r.k+1.x r.k-1.x))
                  (* (- r.k+1.y r.k-1.y) (- r.k+1.y r.k-1.y))))))
  (or (and (= r.k+1.x r.k-1.x) (= r.k+1.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k-2.x) (- r.k+1.x r.k-2.x))
                  (* (- r.k+1.y r.k-2.y) (- r.k+1.y r.k-2.y))))))
  (or (and (= r.k+1.x r.k-2.x) (= r.k+1.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x o.x) (- r.k+1.x o.x))
                  (* (- r.k+1.y o.y) (- r.k+1.y o.y))))))
  (or (and (= r.k+1.x o.x) (= r.k+1.y o.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x))
                  (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))))
  (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k-1.x) (- r.k+2.x r.k-1.x))
                  (* (- r.k+2.y r.k-1.y) (- r.k+2.y r.k-1.y))))))
  (or (and (= r.k+2.x r.k-1.x) (= r.k+2.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k-2.x) (- r.k+2.x r.k-2.x))
                  (* (- r.k+2.y r.k-2.y) (- r.k+2.y r.k-2.y))))))
  (or (and (= r.k+2.x r.k-2.x) (= r.k+2.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x o.x) (- r.k+2.x o.x))
                  (* (- r.k+2.y o.y) (- r.k+2.y o.y))))))
  (or (and (= r.k+2.x o.x) (= r.k+2.y o.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k-1.x) (- r.k+3.x r.k-1.x))
                  (* (- r.k+3.y r.k-1.y) (- r.k+3.y r.k-1.y))))))
  (or (and (= r.k+3.x r.k-1.x) (= r.k+3.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k-2.x) (- r.k+3.x r.k-2.x))
                  (* (- r.k+3.y r.k-2.y) (- r.k+3.y r.k-2.y))))))
  (or (and (= r.k+3.x r.k-2.x) (= r.k+3.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x o.x) (- r.k+3.x o.x))
                  (* (- r.k+3.y o.y) (- r.k+3.y o.y))))))
  (or (and (= r.k+3.x o.x) (= r.k+3.y o.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-1.x) (- r.k+4.x r.k-1.x))
                  (* (- r.k+4.y r.k-1.y) (- r.k+4.y r.k-1.y))))))
  (or (and (= r.k+4.x r.k-1.x) (= r.k+4.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-2.x) (- r.k+4.x r.k-2.x))
                  (* (- r.k+4.y r.k-2.y) (- r.k+4.y r.k-2.y))))))
  (or (and (= r.k+4.x r.k-2.x) (= r.k+4.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x o.x) (- r.k+4.x o.x))
                  (* (- r.k+4.y o.y) (- r.k+4.y o.y))))))
  (or (and (= r.k+4.x o.x) (= r.k+4.y o.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x))
                  (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))))
  (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x o.x) (- r.k-1.x o.x))
                  (* (- r.k-1.y o.y) (- r.k-1.y o.y))))))
  (or (and (= r.k-1.x o.x) (= r.k-1.y o.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x o.x) (- r.k-2.x o.x))
                  (* (- r.k-2.y o.y) (- r.k-2.y o.y))))))
  (or (and (= r.k-2.x o.x) (= r.k-2.y o.y)) a!1)))
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
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!37 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!39 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!40 (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
               (- (- r.k-2.x 0.0) (- r.w.x 0.0))))
      (a!42 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!43 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!51 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 3.0)) (- (- 0.0 0.0) (- 3.0)))))
      (a!57 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 3.0)) (- (- r.w.y 0.0) (- 3.0)))))
      (a!59 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!66 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 3.0)) (- (- r.c.y 0.0) (- 3.0)))))
      (a!73 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 3.0)) (- (- r.d.y 0.0) (- 3.0)))))
      (a!75 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!76 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!86 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!87 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!97 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!98 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!108 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!109 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!119 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!120 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!130 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!131 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!141 (>= 16.0
                 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
      (a!142 (and (> (- o.x 0.0) (- 2.0)) (> 2.0 (- o.x 0.0))))
      (a!143 (and (> (- o.y 0.0) (- 2.0)) (> 2.0 (- o.y 0.0))))
      (a!151 (+ (* (- (- o.x 0.0) (- r.w.x 0.0)) (- (- o.x 0.0) (- r.w.x 0.0)))
                (* (- (- o.y 0.0) (- 3.0)) (- (- o.y 0.0) (- 3.0))))))
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
      (a!38 (+ a!37 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!41 (+ a!40 (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))
      (a!44 (or (and a!43 (< 0.0 (- 0.0 0.0))) (and a!43 (> 0.0 (- 0.0 0.0)))))
      (a!46 (not (and a!43 (> 0.0 (- 0.0 0.0)))))
      (a!54 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!60 (or (and a!59 (< 0.0 (- r.c.y 0.0)))
                (and a!59 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!62 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!69 (not (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!77 (or (and a!75 (< 0.0 (- r.k+1.y 0.0)))
                (and a!75 (> 0.0 (- r.k+1.y 0.0)))
                (and a!76 (< 0.0 (- r.k+1.x 0.0)))
                (and a!76 (> 0.0 (- r.k+1.x 0.0)))))
      (a!79 (not (and a!76 (> 0.0 (- r.k+1.x 0.0)))))
      (a!84 (+ a!18 (* (- (- r.k+1.y 0.0) (- 3.0)) (- (- r.k+1.y 0.0) (- 3.0)))))
      (a!88 (or (and a!86 (< 0.0 (- r.k+2.y 0.0)))
                (and a!86 (> 0.0 (- r.k+2.y 0.0)))
                (and a!87 (< 0.0 (- r.k+2.x 0.0)))
                (and a!87 (> 0.0 (- r.k+2.x 0.0)))))
      (a!90 (not (and a!87 (> 0.0 (- r.k+2.x 0.0)))))
      (a!95 (+ a!23 (* (- (- r.k+2.y 0.0) (- 3.0)) (- (- r.k+2.y 0.0) (- 3.0)))))
      (a!99 (or (and a!97 (< 0.0 (- r.k+3.y 0.0)))
                (and a!97 (> 0.0 (- r.k+3.y 0.0)))
                (and a!98 (< 0.0 (- r.k+3.x 0.0)))
                (and a!98 (> 0.0 (- r.k+3.x 0.0)))))
      (a!101 (not (and a!98 (> 0.0 (- r.k+3.x 0.0)))))
      (a!106 (+ a!28
                (* (- (- r.k+3.y 0.0) (- 3.0)) (- (- r.k+3.y 0.0) (- 3.0)))))
      (a!110 (or (and a!108 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!108 (> 0.0 (- r.k+4.y 0.0)))
                 (and a!109 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!109 (> 0.0 (- r.k+4.x 0.0)))))
      (a!112 (not (and a!109 (> 0.0 (- r.k+4.x 0.0)))))
      (a!117 (+ a!33
                (* (- (- r.k+4.y 0.0) (- 3.0)) (- (- r.k+4.y 0.0) (- 3.0)))))
      (a!121 (or (and a!119 (< 0.0 (- r.k-1.y 0.0)))
                 (and a!119 (> 0.0 (- r.k-1.y 0.0)))
                 (and a!120 (< 0.0 (- r.k-1.x 0.0)))
                 (and a!120 (> 0.0 (- r.k-1.x 0.0)))))
      (a!123 (not (and a!120 (> 0.0 (- r.k-1.x 0.0)))))
      (a!128 (+ a!37
                (* (- (- r.k-1.y 0.0) (- 3.0)) (- (- r.k-1.y 0.0) (- 3.0)))))
      (a!132 (or (and a!130 (< 0.0 (- r.k-2.y 0.0)))
                 (and a!130 (> 0.0 (- r.k-2.y 0.0)))
                 (and a!131 (< 0.0 (- r.k-2.x 0.0)))
                 (and a!131 (> 0.0 (- r.k-2.x 0.0)))))
      (a!134 (not (and a!131 (> 0.0 (- r.k-2.x 0.0)))))
      (a!139 (+ a!40
                (* (- (- r.k-2.y 0.0) (- 3.0)) (- (- r.k-2.y 0.0) (- 3.0)))))
      (a!144 (or (and a!142 (< 0.0 (- o.y 0.0)))
                 (and a!142 (> 0.0 (- o.y 0.0)))
                 (and a!143 (< 0.0 (- o.x 0.0)))
                 (and a!143 (> 0.0 (- o.x 0.0)))))
      (a!146 (not (and a!143 (> 0.0 (- o.x 0.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!20 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))) a!17 (> 4.0 a!19)))
      (a!25 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))) a!22 (> 4.0 a!24)))
      (a!30 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))) a!27 (> 4.0 a!29)))
      (a!35 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))) a!32 (> 4.0 a!34)))
      (a!45 (not (and (not (or a!44 a!44))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!47 (not (and (not (or a!44 a!44))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!48 (and (not (or a!44 a!44)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!53 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!55 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!61 (not (and (not a!60) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!63 (not (and (not a!60) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!64 (and (not a!60) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!68 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!70 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!71 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!78 (not (and (not a!77)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!80 (not (and (not a!77)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!81 (and (not a!77) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!89 (not (and (not a!88)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!91 (not (and (not a!88)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!92 (and (not a!88) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!100 (not (and (not a!99)
                       (> 0.0 (- r.k+3.x 0.0))
                       (< 0.0 (- r.k+3.y 0.0)))))
      (a!102 (not (and (not a!99)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!103 (and (not a!99) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!111 (not (and (not a!110)
                       (> 0.0 (- r.k+4.x 0.0))
                       (< 0.0 (- r.k+4.y 0.0)))))
      (a!113 (not (and (not a!110)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!114 (and (not a!110) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!122 (not (and (not a!121)
                       (> 0.0 (- r.k-1.x 0.0))
                       (< 0.0 (- r.k-1.y 0.0)))))
      (a!124 (not (and (not a!121)
                       (> 0.0 (- r.k-1.x 0.0))
                       (> 0.0 (- r.k-1.y 0.0)))))
      (a!125 (and (not a!121) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!133 (not (and (not a!132)
                       (> 0.0 (- r.k-2.x 0.0))
                       (< 0.0 (- r.k-2.y 0.0)))))
      (a!135 (not (and (not a!132)
                       (> 0.0 (- r.k-2.x 0.0))
                       (> 0.0 (- r.k-2.y 0.0)))))
      (a!136 (and (not a!132) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!145 (not (and (not a!144) (> 0.0 (- o.x 0.0)) (< 0.0 (- o.y 0.0)))))
      (a!147 (not (and (not a!144) (> 0.0 (- o.x 0.0)) (> 0.0 (- o.y 0.0)))))
      (a!148 (and (not a!144) (< 0.0 (- o.x 0.0)) (< 0.0 (- o.y 0.0)))))
(let ((a!6 (or a!5
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!49 (or a!48
                (and a!43 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!44 a!44))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!50 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!48))
      (a!56 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!5))
      (a!65 (or a!64
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!60) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!72 (or a!71 (and a!13 (< 0.0 (- r.d.x 0.0))) a!15))
      (a!82 (or a!81
                (and a!76 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!77) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!83 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!81))
      (a!93 (or a!92
                (and a!87 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!88) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!94 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!92))
      (a!104 (or a!103
                 (and a!98 (< 0.0 (- r.k+3.x 0.0)))
                 (and (not a!99)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!105 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!103))
      (a!115 (or a!114
                 (and a!109 (< 0.0 (- r.k+4.x 0.0)))
                 (and (not a!110)
                      (< 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!116 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!114))
      (a!126 (or a!125
                 (and a!120 (< 0.0 (- r.k-1.x 0.0)))
                 (and (not a!121)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!127 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  a!125))
      (a!137 (or a!136
                 (and a!131 (< 0.0 (- r.k-2.x 0.0)))
                 (and (not a!132)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!138 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  a!136))
      (a!149 (or a!148
                 (and a!143 (< 0.0 (- o.x 0.0)))
                 (and (not a!144) (< 0.0 (- o.x 0.0)) (> 0.0 (- o.y 0.0)))))
      (a!150 (and (> (- (- o.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- o.x 0.0) (- r.w.x 0.0)))
                  a!148)))
(let ((a!52 (and a!45
                 a!46
                 a!47
                 (=> a!49 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!50)
                 (not (> 4.0 a!51))))
      (a!58 (and a!53
                 a!54
                 a!55
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!56)
                 (not (> 4.0 a!57))))
      (a!67 (and a!61
                 a!62
                 a!63
                 (=> a!65 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!64))
                 (not (> 4.0 a!66))))
      (a!74 (and a!68
                 a!69
                 a!70
                 (=> a!72 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!11 a!71))
                 (not (> 4.0 a!73))))
      (a!85 (and a!78
                 a!79
                 a!80
                 (=> a!82 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!83)
                 (not (> 4.0 a!84))))
      (a!96 (and a!89
                 a!90
                 a!91
                 (=> a!93 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!94)
                 (not (> 4.0 a!95))))
      (a!107 (and a!100
                  a!101
                  a!102
                  (=> a!104 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!105)
                  (not (> 4.0 a!106))))
      (a!118 (and a!111
                  a!112
                  a!113
                  (=> a!115 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!116)
                  (not (> 4.0 a!117))))
      (a!129 (and a!122
                  a!123
                  a!124
                  (=> a!126 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  (not a!127)
                  (not (> 4.0 a!128))))
      (a!140 (and a!133
                  a!134
                  a!135
                  (=> a!137 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  (not a!138)
                  (not (> 4.0 a!139))))
      (a!152 (and a!145
                  a!146
                  a!147
                  (=> a!149 (>= (- o.x 0.0) (- r.w.x 0.0)))
                  (not a!150)
                  (not (> 4.0 a!151)))))
(let ((a!153 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  a!36
                  (> 4.0 a!38)
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  a!39
                  (> 4.0 a!41)
                  a!26
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!42 a!52))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!58))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!7 a!67))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!10 a!74))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!17 a!85))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!22 a!96))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!27 a!107))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!32 a!118))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!36 a!129))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!39 a!140))
                  (or (and (= 0.0 o.x) (= 0.0 o.y)) (=> a!141 a!152)))))
  (=> r.case0 a!153))))))))
(assert (or r.case0))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
      (a!2 (* (- (+ 0.0 (- r.w.x 0.0)) o.x) (- (+ 0.0 (- r.w.x 0.0)) o.x))))
(let ((a!3 (+ a!2 (* (- (+ 0.0 (- 3.0)) o.y) (- (+ 0.0 (- 3.0)) o.y)))))
  (and a!1 (not (>= 16.0 a!3))))))
(check-sat)
