; Obligation: rma-fixed, form seen, r's case repair-align.nomovement-4-only-AI; model repaired, scheduler ssync.
; Claim: whenever r decides this case, r does not move right of every robot it sees (and of itself).
; r's destination is the repaired rule set's own, in place of the case's: repair_stack = align: r, seeing only A u I, moves to the greatest x it sees, if right of r (fatline_verify/rules/repaired/algorithm.py); its conditions are asserted with the case's.
; r's case: witness a: a visible robot in A u I; universal: no visible robot in B u C u D u E u F u G.
; Named robots: r, r.a, r.m (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
; Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg toward their destination (never farther right, never left of r), or a repair's own: repair-align to the greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical.
(set-logic QF_NRA)
(declare-fun r.a.y () Real)
(declare-fun r.a.x () Real)
(declare-fun r.m.y () Real)
(declare-fun r.m.x () Real)
(declare-fun r.case0 () Bool)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x))
                  (* (- 0.0 r.a.y) (- 0.0 r.a.y))))))
  (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.m.x) (- 0.0 r.m.x))
                  (* (- 0.0 r.m.y) (- 0.0 r.m.y))))))
  (or (and (= 0.0 r.m.x) (= 0.0 r.m.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.a.x r.m.x) (- r.a.x r.m.x))
                  (* (- r.a.y r.m.y) (- r.a.y r.m.y))))))
  (or (and (= r.a.x r.m.x) (= r.a.y r.m.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x))
                  (* (- 0.0 r.a.y) (- 0.0 r.a.y)))))
      (a!2 (and (> (- r.a.x 0.0) (- 2.0)) (> 2.0 (- r.a.x 0.0))))
      (a!4 (>= 16.0 (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!5 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!8 (and (> (- r.a.y 0.0) (- 2.0)) (> 2.0 (- r.a.y 0.0))))
      (a!11 (>= 16.0
                (+ (* (- 0.0 r.m.x) (- 0.0 r.m.x))
                   (* (- 0.0 r.m.y) (- 0.0 r.m.y)))))
      (a!12 (and (> (- r.m.x 0.0) (- 2.0)) (> 2.0 (- r.m.x 0.0))))
      (a!13 (and (> (- r.m.y 0.0) (- 2.0)) (> 2.0 (- r.m.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.a.y 0.0))) (and a!2 (> 0.0 (- r.a.y 0.0)))))
      (a!6 (or (and a!5 (< 0.0 (- 0.0 0.0))) (and a!5 (> 0.0 (- 0.0 0.0)))))
      (a!14 (or (and a!12 (< 0.0 (- r.m.y 0.0)))
                (and a!12 (> 0.0 (- r.m.y 0.0)))
                (and a!13 (< 0.0 (- r.m.x 0.0)))
                (and a!13 (> 0.0 (- r.m.x 0.0))))))
(let ((a!7 (or (and (not (or a!6 a!6)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))
               (and a!5 (< 0.0 (- 0.0 0.0)))
               (and (not (or a!6 a!6)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0)))
               (and (not (or a!6 a!6)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))
               (and a!5 (> 0.0 (- 0.0 0.0)))
               (and (not (or a!6 a!6)) (> 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0)))))
      (a!9 (or a!3
               (and a!8 (< 0.0 (- r.a.x 0.0)))
               (and a!8 (> 0.0 (- r.a.x 0.0)))))
      (a!15 (or (and (not a!14) (< 0.0 (- r.m.x 0.0)) (< 0.0 (- r.m.y 0.0)))
                (and a!13 (< 0.0 (- r.m.x 0.0)))
                (and (not a!14) (< 0.0 (- r.m.x 0.0)) (> 0.0 (- r.m.y 0.0)))
                (and (not a!14) (> 0.0 (- r.m.x 0.0)) (< 0.0 (- r.m.y 0.0)))
                (and a!13 (> 0.0 (- r.m.x 0.0)))
                (and (not a!14) (> 0.0 (- r.m.x 0.0)) (> 0.0 (- r.m.y 0.0))))))
(let ((a!10 (or (and (not a!9) (< 0.0 (- r.a.x 0.0)) (< 0.0 (- r.a.y 0.0)))
                (and a!8 (< 0.0 (- r.a.x 0.0)))
                (and (not a!9) (< 0.0 (- r.a.x 0.0)) (> 0.0 (- r.a.y 0.0)))
                (and (not a!9) (> 0.0 (- r.a.x 0.0)) (< 0.0 (- r.a.y 0.0)))
                (and a!8 (> 0.0 (- r.a.x 0.0)))
                (and (not a!9) (> 0.0 (- r.a.x 0.0)) (> 0.0 (- r.a.y 0.0))))))
(let ((a!16 (and (not (and (= 0.0 r.a.x) (= 0.0 r.a.y)))
                 a!1
                 a!3
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!4 (not a!7)))
                 (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) (=> a!1 (not a!10)))
                 (or (and (= 0.0 r.m.x) (= 0.0 r.m.y)) (=> a!11 (not a!15))))))
  (=> r.case0 a!16)))))))
(assert (or r.case0))
(assert (not (and (= 0.0 r.m.x) (= 0.0 r.m.y))))
(assert (>= 16.0 (+ (* (- 0.0 r.m.x) (- 0.0 r.m.x)) (* (- 0.0 r.m.y) (- 0.0 r.m.y)))))
(assert (< 0.0 r.m.x))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0))))))
  (or (and (= 0.0 0.0) (= 0.0 0.0)) (not a!1) (<= 0.0 r.m.x))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x))
                  (* (- 0.0 r.a.y) (- 0.0 r.a.y))))))
  (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) (not a!1) (<= r.a.x r.m.x))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.m.x) (- 0.0 r.m.x))
                  (* (- 0.0 r.m.y) (- 0.0 r.m.y))))))
  (or (and (= 0.0 r.m.x) (= 0.0 r.m.y)) (not a!1) (<= r.m.x r.m.x))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x))
                  (* (- 0.0 r.a.y) (- 0.0 r.a.y)))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.m.x) (- 0.0 r.m.x))
                  (* (- 0.0 r.m.y) (- 0.0 r.m.y))))))
  (and (< 0.0 r.m.x)
       (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) (not a!1) (< r.a.x r.m.x))
       (or (and (= 0.0 r.m.x) (= 0.0 r.m.y)) (not a!2) (< r.m.x r.m.x)))))
(check-sat)
