; Obligation: rma-fixed, form on-rma, r's case scenario-3.down-4-after-up; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; search up fails: each of its candidates 1..4 within view has a visible blocker (witnesses k); candidates 1..3 down are blocked (witnesses k); candidate 4 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4, r.k-1, r.k-2, r.k-3 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                  (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))))
  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) a!1)))
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
               (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x))
                  (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))))
  (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) a!1)))
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
               (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x))
                  (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))))
  (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) a!1)))
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
               (+ (* (- r.d.x r.k-3.x) (- r.d.x r.k-3.x))
                  (* (- r.d.y r.k-3.y) (- r.d.y r.k-3.y))))))
  (or (and (= r.d.x r.k-3.x) (= r.d.y r.k-3.y)) a!1)))
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
               (+ (* (- r.k+1.x r.k-3.x) (- r.k+1.x r.k-3.x))
                  (* (- r.k+1.y r.k-3.y) (- r.k+1.y r.k-3.y))))))
  (or (and (= r.k+1.x r.k-3.x) (= r.k+1.y r.k-3.y)) a!1)))
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
               (+ (* (- r.k+2.x r.k-3.x) (- r.k+2.x r.k-3.x))
                  (* (- r.k+2.y r.k-3.y) (- r.k+2.y r.k-3.y))))))
  (or (and (= r.k+2.x r.k-3.x) (= r.k+2.y r.k-3.y)) a!1)))
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
               (+ (* (- r.k+3.x r.k-3.x) (- r.k+3.x r.k-3.x))
                  (* (- r.k+3.y r.k-3.y) (- r.k+3.y r.k-3.y))))))
  (or (and (= r.k+3.x r.k-3.x) (= r.k+3.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-1.x) (- r.k+4.x r.k-1.x))
                  (* (- r.k+4.y r.k-1.y) (- r.k+4.y r.k-1.y))))))
  (or (and (= r.k+4.x r.k-1.x) (= r.k+4.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-2.x) (- r.k+4.x r.k-2.x))
                  (* (- r.k+4.y r.k-2.y) (- r.k+4.y r.k-2.y))))))
  (or (and (= r.k+4.x r.k-2.x) (= r.k+4.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-3.x) (- r.k+4.x r.k-3.x))
                  (* (- r.k+4.y r.k-3.y) (- r.k+4.y r.k-3.y))))))
  (or (and (= r.k+4.x r.k-3.x) (= r.k+4.y r.k-3.y)) a!1)))
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
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!43 (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
               (- (- r.k-3.x 0.0) (- r.w.x 0.0))))
      (a!45 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!46 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!54 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 4.0)) (- (- 0.0 0.0) (- 4.0)))))
      (a!60 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 4.0)) (- (- r.w.y 0.0) (- 4.0)))))
      (a!62 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!69 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 4.0)) (- (- r.c.y 0.0) (- 4.0)))))
      (a!76 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 4.0)) (- (- r.d.y 0.0) (- 4.0)))))
      (a!78 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!79 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!89 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!90 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!100 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!101 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!111 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!112 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!122 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!123 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!133 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!134 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!144 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!145 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0)))))
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
      (a!44 (+ a!43 (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))
      (a!47 (or (and a!46 (< 0.0 (- 0.0 0.0))) (and a!46 (> 0.0 (- 0.0 0.0)))))
      (a!49 (not (and a!46 (> 0.0 (- 0.0 0.0)))))
      (a!57 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!63 (or (and a!62 (< 0.0 (- r.c.y 0.0)))
                (and a!62 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!65 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!72 (not (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!80 (or (and a!78 (< 0.0 (- r.k+1.y 0.0)))
                (and a!78 (> 0.0 (- r.k+1.y 0.0)))
                (and a!79 (< 0.0 (- r.k+1.x 0.0)))
                (and a!79 (> 0.0 (- r.k+1.x 0.0)))))
      (a!82 (not (and a!79 (> 0.0 (- r.k+1.x 0.0)))))
      (a!87 (+ a!18 (* (- (- r.k+1.y 0.0) (- 4.0)) (- (- r.k+1.y 0.0) (- 4.0)))))
      (a!91 (or (and a!89 (< 0.0 (- r.k+2.y 0.0)))
                (and a!89 (> 0.0 (- r.k+2.y 0.0)))
                (and a!90 (< 0.0 (- r.k+2.x 0.0)))
                (and a!90 (> 0.0 (- r.k+2.x 0.0)))))
      (a!93 (not (and a!90 (> 0.0 (- r.k+2.x 0.0)))))
      (a!98 (+ a!23 (* (- (- r.k+2.y 0.0) (- 4.0)) (- (- r.k+2.y 0.0) (- 4.0)))))
      (a!102 (or (and a!100 (< 0.0 (- r.k+3.y 0.0)))
                 (and a!100 (> 0.0 (- r.k+3.y 0.0)))
                 (and a!101 (< 0.0 (- r.k+3.x 0.0)))
                 (and a!101 (> 0.0 (- r.k+3.x 0.0)))))
      (a!104 (not (and a!101 (> 0.0 (- r.k+3.x 0.0)))))
      (a!109 (+ a!28
                (* (- (- r.k+3.y 0.0) (- 4.0)) (- (- r.k+3.y 0.0) (- 4.0)))))
      (a!113 (or (and a!111 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!111 (> 0.0 (- r.k+4.y 0.0)))
                 (and a!112 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!112 (> 0.0 (- r.k+4.x 0.0)))))
      (a!115 (not (and a!112 (> 0.0 (- r.k+4.x 0.0)))))
      (a!120 (+ a!33
                (* (- (- r.k+4.y 0.0) (- 4.0)) (- (- r.k+4.y 0.0) (- 4.0)))))
      (a!124 (or (and a!122 (< 0.0 (- r.k-1.y 0.0)))
                 (and a!122 (> 0.0 (- r.k-1.y 0.0)))
                 (and a!123 (< 0.0 (- r.k-1.x 0.0)))
                 (and a!123 (> 0.0 (- r.k-1.x 0.0)))))
      (a!126 (not (and a!123 (> 0.0 (- r.k-1.x 0.0)))))
      (a!131 (+ a!37
                (* (- (- r.k-1.y 0.0) (- 4.0)) (- (- r.k-1.y 0.0) (- 4.0)))))
      (a!135 (or (and a!133 (< 0.0 (- r.k-2.y 0.0)))
                 (and a!133 (> 0.0 (- r.k-2.y 0.0)))
                 (and a!134 (< 0.0 (- r.k-2.x 0.0)))
                 (and a!134 (> 0.0 (- r.k-2.x 0.0)))))
      (a!137 (not (and a!134 (> 0.0 (- r.k-2.x 0.0)))))
      (a!142 (+ a!40
                (* (- (- r.k-2.y 0.0) (- 4.0)) (- (- r.k-2.y 0.0) (- 4.0)))))
      (a!146 (or (and a!144 (< 0.0 (- r.k-3.y 0.0)))
                 (and a!144 (> 0.0 (- r.k-3.y 0.0)))
                 (and a!145 (< 0.0 (- r.k-3.x 0.0)))
                 (and a!145 (> 0.0 (- r.k-3.x 0.0)))))
      (a!148 (not (and a!145 (> 0.0 (- r.k-3.x 0.0)))))
      (a!153 (+ a!43
                (* (- (- r.k-3.y 0.0) (- 4.0)) (- (- r.k-3.y 0.0) (- 4.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!20 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))) a!17 (> 4.0 a!19)))
      (a!25 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))) a!22 (> 4.0 a!24)))
      (a!30 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))) a!27 (> 4.0 a!29)))
      (a!35 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))) a!32 (> 4.0 a!34)))
      (a!48 (not (and (not (or a!47 a!47))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!50 (not (and (not (or a!47 a!47))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!51 (and (not (or a!47 a!47)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!56 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!58 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!64 (not (and (not a!63) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!66 (not (and (not a!63) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!67 (and (not a!63) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!71 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!73 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!74 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!81 (not (and (not a!80)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!83 (not (and (not a!80)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!84 (and (not a!80) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!92 (not (and (not a!91)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!94 (not (and (not a!91)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!95 (and (not a!91) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!103 (not (and (not a!102)
                       (> 0.0 (- r.k+3.x 0.0))
                       (< 0.0 (- r.k+3.y 0.0)))))
      (a!105 (not (and (not a!102)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!106 (and (not a!102) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!114 (not (and (not a!113)
                       (> 0.0 (- r.k+4.x 0.0))
                       (< 0.0 (- r.k+4.y 0.0)))))
      (a!116 (not (and (not a!113)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!117 (and (not a!113) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!125 (not (and (not a!124)
                       (> 0.0 (- r.k-1.x 0.0))
                       (< 0.0 (- r.k-1.y 0.0)))))
      (a!127 (not (and (not a!124)
                       (> 0.0 (- r.k-1.x 0.0))
                       (> 0.0 (- r.k-1.y 0.0)))))
      (a!128 (and (not a!124) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!136 (not (and (not a!135)
                       (> 0.0 (- r.k-2.x 0.0))
                       (< 0.0 (- r.k-2.y 0.0)))))
      (a!138 (not (and (not a!135)
                       (> 0.0 (- r.k-2.x 0.0))
                       (> 0.0 (- r.k-2.y 0.0)))))
      (a!139 (and (not a!135) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!147 (not (and (not a!146)
                       (> 0.0 (- r.k-3.x 0.0))
                       (< 0.0 (- r.k-3.y 0.0)))))
      (a!149 (not (and (not a!146)
                       (> 0.0 (- r.k-3.x 0.0))
                       (> 0.0 (- r.k-3.y 0.0)))))
      (a!150 (and (not a!146) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))))
(let ((a!6 (or a!5
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!52 (or a!51
                (and a!46 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!47 a!47))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!53 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!51))
      (a!59 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!5))
      (a!68 (or a!67
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!63) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!75 (or a!74 (and a!13 (< 0.0 (- r.d.x 0.0))) a!15))
      (a!85 (or a!84
                (and a!79 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!80) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!86 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!84))
      (a!96 (or a!95
                (and a!90 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!91) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!97 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!95))
      (a!107 (or a!106
                 (and a!101 (< 0.0 (- r.k+3.x 0.0)))
                 (and (not a!102)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!108 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!106))
      (a!118 (or a!117
                 (and a!112 (< 0.0 (- r.k+4.x 0.0)))
                 (and (not a!113)
                      (< 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!119 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!117))
      (a!129 (or a!128
                 (and a!123 (< 0.0 (- r.k-1.x 0.0)))
                 (and (not a!124)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!130 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  a!128))
      (a!140 (or a!139
                 (and a!134 (< 0.0 (- r.k-2.x 0.0)))
                 (and (not a!135)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!141 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  a!139))
      (a!151 (or a!150
                 (and a!145 (< 0.0 (- r.k-3.x 0.0)))
                 (and (not a!146)
                      (< 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!152 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  a!150)))
(let ((a!55 (and a!48
                 a!49
                 a!50
                 (=> a!52 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!53)
                 (not (> 4.0 a!54))))
      (a!61 (and a!56
                 a!57
                 a!58
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!59)
                 (not (> 4.0 a!60))))
      (a!70 (and a!64
                 a!65
                 a!66
                 (=> a!68 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!67))
                 (not (> 4.0 a!69))))
      (a!77 (and a!71
                 a!72
                 a!73
                 (=> a!75 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!11 a!74))
                 (not (> 4.0 a!76))))
      (a!88 (and a!81
                 a!82
                 a!83
                 (=> a!85 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!86)
                 (not (> 4.0 a!87))))
      (a!99 (and a!92
                 a!93
                 a!94
                 (=> a!96 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!97)
                 (not (> 4.0 a!98))))
      (a!110 (and a!103
                  a!104
                  a!105
                  (=> a!107 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!108)
                  (not (> 4.0 a!109))))
      (a!121 (and a!114
                  a!115
                  a!116
                  (=> a!118 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!119)
                  (not (> 4.0 a!120))))
      (a!132 (and a!125
                  a!126
                  a!127
                  (=> a!129 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  (not a!130)
                  (not (> 4.0 a!131))))
      (a!143 (and a!136
                  a!137
                  a!138
                  (=> a!140 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  (not a!141)
                  (not (> 4.0 a!142))))
      (a!154 (and a!147
                  a!148
                  a!149
                  (=> a!151 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  (not a!152)
                  (not (> 4.0 a!153)))))
(let ((a!155 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  a!42
                  (> 4.0 a!44)
                  a!31
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!45 a!55))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!61))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!7 a!70))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!10 a!77))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!17 a!88))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!22 a!99))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!27 a!110))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!32 a!121))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!36 a!132))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!39 a!143))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!42 a!154)))))
  (=> r.case0 a!155))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
