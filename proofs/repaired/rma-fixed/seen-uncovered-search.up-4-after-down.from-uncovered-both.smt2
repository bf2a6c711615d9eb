; Obligation: rma-fixed, form seen, r's case uncovered-search.up-4-after-down.from-uncovered-both; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r does not move right of every robot it sees (and of itself).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b, c, d in R_psi n B, C, D; search down fails: each of its candidates 1..4 within view has a visible blocker (witnesses k); candidates 1..3 up are blocked (witnesses k); candidate 4 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c, r.d, r.k-1, r.k-2, r.k-3, r.k-4, r.k+1, r.k+2, r.k+3 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun r.k+1.y () Real)
(declare-fun r.k+1.x () Real)
(declare-fun r.k+2.y () Real)
(declare-fun r.k+2.x () Real)
(declare-fun r.k+3.y () Real)
(declare-fun r.k+3.x () Real)
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
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))))
  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) a!1)))
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
               (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x))
                  (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))))
  (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) a!1)))
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
               (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x))
                  (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))))
  (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k+1.x) (- r.b.x r.k+1.x))
                  (* (- r.b.y r.k+1.y) (- r.b.y r.k+1.y))))))
  (or (and (= r.b.x r.k+1.x) (= r.b.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k+2.x) (- r.b.x r.k+2.x))
                  (* (- r.b.y r.k+2.y) (- r.b.y r.k+2.y))))))
  (or (and (= r.b.x r.k+2.x) (= r.b.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k+3.x) (- r.b.x r.k+3.x))
                  (* (- r.b.y r.k+3.y) (- r.b.y r.k+3.y))))))
  (or (and (= r.b.x r.k+3.x) (= r.b.y r.k+3.y)) a!1)))
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
               (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x))
                  (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))))
  (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) a!1)))
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
               (+ (* (- r.d.x r.k-4.x) (- r.d.x r.k-4.x))
                  (* (- r.d.y r.k-4.y) (- r.d.y r.k-4.y))))))
  (or (and (= r.d.x r.k-4.x) (= r.d.y r.k-4.y)) a!1)))
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
               (+ (* (- r.k-1.x r.k+1.x) (- r.k-1.x r.k+1.x))
                  (* (- r.k-1.y r.k+1.y) (- r.k-1.y r.k+1.y))))))
  (or (and (= r.k-1.x r.k+1.x) (= r.k-1.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k+2.x) (- r.k-1.x r.k+2.x))
                  (* (- r.k-1.y r.k+2.y) (- r.k-1.y r.k+2.y))))))
  (or (and (= r.k-1.x r.k+2.x) (= r.k-1.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k+3.x) (- r.k-1.x r.k+3.x))
                  (* (- r.k-1.y r.k+3.y) (- r.k-1.y r.k+3.y))))))
  (or (and (= r.k-1.x r.k+3.x) (= r.k-1.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x))
                  (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))))
  (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x))
                  (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))))
  (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k+1.x) (- r.k-2.x r.k+1.x))
                  (* (- r.k-2.y r.k+1.y) (- r.k-2.y r.k+1.y))))))
  (or (and (= r.k-2.x r.k+1.x) (= r.k-2.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k+2.x) (- r.k-2.x r.k+2.x))
                  (* (- r.k-2.y r.k+2.y) (- r.k-2.y r.k+2.y))))))
  (or (and (= r.k-2.x r.k+2.x) (= r.k-2.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k+3.x) (- r.k-2.x r.k+3.x))
                  (* (- r.k-2.y r.k+3.y) (- r.k-2.y r.k+3.y))))))
  (or (and (= r.k-2.x r.k+3.x) (= r.k-2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x))
                  (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))))
  (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k+1.x) (- r.k-3.x r.k+1.x))
                  (* (- r.k-3.y r.k+1.y) (- r.k-3.y r.k+1.y))))))
  (or (and (= r.k-3.x r.k+1.x) (= r.k-3.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k+2.x) (- r.k-3.x r.k+2.x))
                  (* (- r.k-3.y r.k+2.y) (- r.k-3.y r.k+2.y))))))
  (or (and (= r.k-3.x r.k+2.x) (= r.k-3.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k+3.x) (- r.k-3.x r.k+3.x))
                  (* (- r.k-3.y r.k+3.y) (- r.k-3.y r.k+3.y))))))
  (or (and (= r.k-3.x r.k+3.x) (= r.k-3.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k+1.x) (- r.k-4.x r.k+1.x))
                  (* (- r.k-4.y r.k+1.y) (- r.k-4.y r.k+1.y))))))
  (or (and (= r.k-4.x r.k+1.x) (= r.k-4.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k+2.x) (- r.k-4.x r.k+2.x))
                  (* (- r.k-4.y r.k+2.y) (- r.k-4.y r.k+2.y))))))
  (or (and (= r.k-4.x r.k+2.x) (= r.k-4.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x r.k+3.x) (- r.k-4.x r.k+3.x))
                  (* (- r.k-4.y r.k+3.y) (- r.k-4.y r.k+3.y))))))
  (or (and (= r.k-4.x r.k+3.x) (= r.k-4.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x))
                  (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))))
  (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x))
                  (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))))
  (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
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
      (a!18 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!19 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!20 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!23 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!24 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!25 (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
               (- (- r.k-2.x 0.0) (- r.w.x 0.0))))
      (a!28 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0))))
      (a!29 (>= 16.0
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!30 (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
               (- (- r.k-3.x 0.0) (- r.w.x 0.0))))
      (a!33 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!34 (>= 16.0
                (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                   (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y)))))
      (a!35 (* (- (- r.k-4.x 0.0) (- r.w.x 0.0))
               (- (- r.k-4.x 0.0) (- r.w.x 0.0))))
      (a!38 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!39 (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
               (- (- r.k+1.x 0.0) (- r.w.x 0.0))))
      (a!41 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!42 (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
               (- (- r.k+2.x 0.0) (- r.w.x 0.0))))
      (a!44 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!45 (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
               (- (- r.k+3.x 0.0) (- r.w.x 0.0))))
      (a!47 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!48 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!54 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 4.0) (- (- 0.0 0.0) 4.0))))
      (a!59 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 4.0) (- (- r.w.y 0.0) 4.0))))
      (a!65 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) 4.0) (- (- r.b.y 0.0) 4.0))))
      (a!67 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!73 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 4.0) (- (- r.c.y 0.0) 4.0))))
      (a!79 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 4.0) (- (- r.d.y 0.0) 4.0))))
      (a!81 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!82 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!90 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!91 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!99 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!100 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!108 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!109 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!117 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!118 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!126 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!127 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!135 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!136 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0)))))
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
      (a!21 (+ a!20 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!26 (+ a!25 (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))
      (a!31 (+ a!30 (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))
      (a!36 (+ a!35 (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))
      (a!40 (+ a!39 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!43 (+ a!42 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!46 (+ a!45 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!49 (or (and a!48 (< 0.0 (- 0.0 0.0))) (and a!48 (> 0.0 (- 0.0 0.0)))))
      (a!51 (not (and a!48 (> 0.0 (- 0.0 0.0)))))
      (a!57 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!62 (not (and a!8 (> 0.0 (- r.b.x 0.0)))))
      (a!68 (or (and a!67 (< 0.0 (- r.c.y 0.0)))
                (and a!67 (> 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!70 (not (and a!12 (> 0.0 (- r.c.x 0.0)))))
      (a!76 (not (and a!15 (> 0.0 (- r.d.x 0.0)))))
      (a!83 (or (and a!81 (< 0.0 (- r.k-1.y 0.0)))
                (and a!81 (> 0.0 (- r.k-1.y 0.0)))
                (and a!82 (< 0.0 (- r.k-1.x 0.0)))
                (and a!82 (> 0.0 (- r.k-1.x 0.0)))))
      (a!85 (not (and a!82 (> 0.0 (- r.k-1.x 0.0)))))
      (a!88 (+ a!20 (* (- (- r.k-1.y 0.0) 4.0) (- (- r.k-1.y 0.0) 4.0))))
      (a!92 (or (and a!90 (< 0.0 (- r.k-2.y 0.0)))
                (and a!90 (> 0.0 (- r.k-2.y 0.0)))
                (and a!91 (< 0.0 (- r.k-2.x 0.0)))
                (and a!91 (> 0.0 (- r.k-2.x 0.0)))))
      (a!94 (not (and a!91 (> 0.0 (- r.k-2.x 0.0)))))
      (a!97 (+ a!25 (* (- (- r.k-2.y 0.0) 4.0) (- (- r.k-2.y 0.0) 4.0))))
      (a!101 (or (and a!99 (< 0.0 (- r.k-3.y 0.0)))
                 (and a!99 (> 0.0 (- r.k-3.y 0.0)))
                 (and a!100 (< 0.0 (- r.k-3.x 0.0)))
                 (and a!100 (> 0.0 (- r.k-3.x 0.0)))))
      (a!103 (not (and a!100 (> 0.0 (- r.k-3.x 0.0)))))
      (a!106 (+ a!30 (* (- (- r.k-3.y 0.0) 4.0) (- (- r.k-3.y 0.0) 4.0))))
      (a!110 (or (and a!108 (< 0.0 (- r.k-4.y 0.0)))
                 (and a!108 (> 0.0 (- r.k-4.y 0.0)))
                 (and a!109 (< 0.0 (- r.k-4.x 0.0)))
                 (and a!109 (> 0.0 (- r.k-4.x 0.0)))))
      (a!112 (not (and a!109 (> 0.0 (- r.k-4.x 0.0)))))
      (a!115 (+ a!35 (* (- (- r.k-4.y 0.0) 4.0) (- (- r.k-4.y 0.0) 4.0))))
      (a!119 (or (and a!117 (< 0.0 (- r.k+1.y 0.0)))
                 (and a!117 (> 0.0 (- r.k+1.y 0.0)))
                 (and a!118 (< 0.0 (- r.k+1.x 0.0)))
                 (and a!118 (> 0.0 (- r.k+1.x 0.0)))))
      (a!121 (not (and a!118 (> 0.0 (- r.k+1.x 0.0)))))
      (a!124 (+ a!39 (* (- (- r.k+1.y 0.0) 4.0) (- (- r.k+1.y 0.0) 4.0))))
      (a!128 (or (and a!126 (< 0.0 (- r.k+2.y 0.0)))
                 (and a!126 (> 0.0 (- r.k+2.y 0.0)))
                 (and a!127 (< 0.0 (- r.k+2.x 0.0)))
                 (and a!127 (> 0.0 (- r.k+2.x 0.0)))))
      (a!130 (not (and a!127 (> 0.0 (- r.k+2.x 0.0)))))
      (a!133 (+ a!42 (* (- (- r.k+2.y 0.0) 4.0) (- (- r.k+2.y 0.0) 4.0))))
      (a!137 (or (and a!135 (< 0.0 (- r.k+3.y 0.0)))
                 (and a!135 (> 0.0 (- r.k+3.y 0.0)))
                 (and a!136 (< 0.0 (- r.k+3.x 0.0)))
                 (and a!136 (> 0.0 (- r.k+3.x 0.0)))))
      (a!139 (not (and a!136 (> 0.0 (- r.k+3.x 0.0)))))
      (a!142 (+ a!45 (* (- (- r.k+3.y 0.0) 4.0) (- (- r.k+3.y 0.0) 4.0)))))
(let ((a!5 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!10 (and (not a!9) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!17 (and (not a!16) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!22 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))) a!19 (> 4.0 a!21)))
      (a!27 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))) a!24 (> 4.0 a!26)))
      (a!32 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))) a!29 (> 4.0 a!31)))
      (a!37 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))) a!34 (> 4.0 a!36)))
      (a!50 (not (and (not (or a!49 a!49))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!52 (not (and (not (or a!49 a!49))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!53 (or (and (not (or a!49 a!49))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!48 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!49 a!49))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!56 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!58 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!61 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!63 (not (and (not a!9) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!69 (not (and (not a!68) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!71 (not (and (not a!68) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!72 (or (and (not a!68) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!12 (< 0.0 (- r.c.x 0.0)))
                (and (not a!68) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!75 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!77 (not (and (not a!16) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!84 (not (and (not a!83)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!86 (not (and (not a!83)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!87 (or (and (not a!83) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                (and a!82 (< 0.0 (- r.k-1.x 0.0)))
                (and (not a!83) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!93 (not (and (not a!92)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!95 (not (and (not a!92)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!96 (or (and (not a!92) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                (and a!91 (< 0.0 (- r.k-2.x 0.0)))
                (and (not a!92) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
      (a!102 (not (and (not a!101)
                       (> 0.0 (- r.k-3.x 0.0))
                       (< 0.0 (- r.k-3.y 0.0)))))
      (a!104 (not (and (not a!101)
                       (> 0.0 (- r.k-3.x 0.0))
                       (> 0.0 (- r.k-3.y 0.0)))))
      (a!105 (or (and (not a!101)
                      (< 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))
                 (and a!100 (< 0.0 (- r.k-3.x 0.0)))
                 (and (not a!101)
                      (< 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!111 (not (and (not a!110)
                       (> 0.0 (- r.k-4.x 0.0))
                       (< 0.0 (- r.k-4.y 0.0)))))
      (a!113 (not (and (not a!110)
                       (> 0.0 (- r.k-4.x 0.0))
                       (> 0.0 (- r.k-4.y 0.0)))))
      (a!114 (or (and (not a!110)
                      (< 0.0 (- r.k-4.x 0.0))
                      (< 0.0 (- r.k-4.y 0.0)))
                 (and a!109 (< 0.0 (- r.k-4.x 0.0)))
                 (and (not a!110)
                      (< 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!120 (not (and (not a!119)
                       (> 0.0 (- r.k+1.x 0.0))
                       (< 0.0 (- r.k+1.y 0.0)))))
      (a!122 (not (and (not a!119)
                       (> 0.0 (- r.k+1.x 0.0))
                       (> 0.0 (- r.k+1.y 0.0)))))
      (a!123 (or (and (not a!119)
                      (< 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))
                 (and a!118 (< 0.0 (- r.k+1.x 0.0)))
                 (and (not a!119)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!129 (not (and (not a!128)
                       (> 0.0 (- r.k+2.x 0.0))
                       (< 0.0 (- r.k+2.y 0.0)))))
      (a!131 (not (and (not a!128)
                       (> 0.0 (- r.k+2.x 0.0))
                       (> 0.0 (- r.k+2.y 0.0)))))
      (a!132 (or (and (not a!128)
                      (< 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))
                 (and a!127 (< 0.0 (- r.k+2.x 0.0)))
                 (and (not a!128)
                      (< 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!138 (not (and (not a!137)
                       (> 0.0 (- r.k+3.x 0.0))
                       (< 0.0 (- r.k+3.y 0.0)))))
      (a!140 (not (and (not a!137)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!141 (or (and (not a!137)
                      (< 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))
                 (and a!136 (< 0.0 (- r.k+3.x 0.0)))
                 (and (not a!137)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0))))))
(let ((a!55 (and a!50
                 a!51
                 a!52
                 (=> a!53 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!54))))
      (a!60 (and a!56
                 a!57
                 a!58
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!59))))
      (a!64 (or a!10
                (and a!8 (< 0.0 (- r.b.x 0.0)))
                (and (not a!9) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!74 (and a!69
                 a!70
                 a!71
                 (=> a!72 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!73))))
      (a!78 (or (and (not a!16) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                (and a!15 (< 0.0 (- r.d.x 0.0)))
                a!17))
      (a!89 (and a!84
                 a!85
                 a!86
                 (=> a!87 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!88))))
      (a!98 (and a!93
                 a!94
                 a!95
                 (=> a!96 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!97))))
      (a!107 (and a!102
                  a!103
                  a!104
                  (=> a!105 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  (not (> 4.0 a!106))))
      (a!116 (and a!111
                  a!112
                  a!113
                  (=> a!114 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                  (not (> 4.0 a!115))))
      (a!125 (and a!120
                  a!121
                  a!122
                  (=> a!123 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                  (not (> 4.0 a!124))))
      (a!134 (and a!129
                  a!130
                  a!131
                  (=> a!132 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                  (not (> 4.0 a!133))))
      (a!143 (and a!138
                  a!139
                  a!140
                  (=> a!141 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not (> 4.0 a!142)))))
(let ((a!66 (and a!61
                 a!62
                 a!63
                 (=> a!64 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!65))))
      (a!80 (and a!75
                 a!76
                 a!77
                 (=> a!78 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (> 4.0 a!79)))))
(let ((a!144 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                  (or (not a!18) a!22)
                  (or (not a!23) a!27)
                  (or (not a!28) a!32)
                  (or (not a!33) a!37)
                  (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                  a!38
                  (> 4.0 a!40)
                  (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                  a!41
                  (> 4.0 a!43)
                  (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                  a!44
                  (> 4.0 a!46)
                  a!33
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!47 a!55))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!60))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!6 a!66))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!11 a!74))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!13 a!80))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!19 a!89))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!24 a!98))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!29 a!107))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) (=> a!34 a!116))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!38 a!125))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!41 a!134))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!44 a!143)))))
  (=> r.case0 a!144))))))))
(assert (or r.case0))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!3 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!5 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!7 (>= 16.0
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!9 (>= 16.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!11 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!13 (>= 16.0
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!15 (>= 16.0
                (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                   (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y)))))
      (a!17 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!19 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!21 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))))
(let ((a!2 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y))
               (not a!1)
               (< r.w.x (+ 0.0 (- r.w.x 0.0)))))
      (a!4 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y))
               (not a!3)
               (< r.b.x (+ 0.0 (- r.w.x 0.0)))))
      (a!6 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y))
               (not a!5)
               (< r.c.x (+ 0.0 (- r.w.x 0.0)))))
      (a!8 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y))
               (not a!7)
               (< r.d.x (+ 0.0 (- r.w.x 0.0)))))
      (a!10 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                (not a!9)
                (< r.k-1.x (+ 0.0 (- r.w.x 0.0)))))
      (a!12 (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                (not a!11)
                (< r.k-2.x (+ 0.0 (- r.w.x 0.0)))))
      (a!14 (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                (not a!13)
                (< r.k-3.x (+ 0.0 (- r.w.x 0.0)))))
      (a!16 (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                (not a!15)
                (< r.k-4.x (+ 0.0 (- r.w.x 0.0)))))
      (a!18 (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                (not a!17)
                (< r.k+1.x (+ 0.0 (- r.w.x 0.0)))))
      (a!20 (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                (not a!19)
                (< r.k+2.x (+ 0.0 (- r.w.x 0.0)))))
      (a!22 (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))
                (not a!21)
                (< r.k+3.x (+ 0.0 (- r.w.x 0.0))))))
  (and (< 0.0 (+ 0.0 (- r.w.x 0.0)))
       a!2
       a!4
       a!6
       a!8
       a!10
       a!12
       a!14
       a!16
       a!18
       a!20
       a!22))))
(check-sat)
