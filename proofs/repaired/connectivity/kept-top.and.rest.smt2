; Obligation: connectivity, form kept, r's leg top, the other robot o at rest; model repaired, move family repaired-legs, scheduler ssync, timing any-speed.
; Claim: r and o, within view before the round, are within view after it.
; Family: the repaired rules' legs: one radius or less along one axis, under the lock, clear paths and kept edges. Classes: horizontal: (dx, 0) with 0 < dx <= 1; top: (0, dy) with 0 < |dy| <= 1, no robot seen above on its vertical; bottom: (0, dy) with 0 < dy <= 1, every robot seen on its vertical above it, ending >= 3 below each. Longest move 1 radii. Every decision of the rule set is held to the family as it runs (the step lemma in-family) and on every view of the lattice (the row in-family/views).
; Named robots: r, o (r at the origin), pairwise disjoint discs; each mover's shape, not held (at_rest), and its guard for every named robot it sees (forall: each named robot; exists: true, or the named witness where the form names it).
; Why unsat covers swarms of every size: each asserted condition is implied by the family's guards for the named robots in any swarm; every collision, and every edge with a mover at one end, is an instance of one obligation (fatline_verify/prove/smt/family.py, the module docstring), so each edge before the round is a path of at most two edges after it and the swarm stays connected.
; Rests on: nothing outside the family.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun o.y () Real)
(declare-fun o.x () Real)
(declare-fun r.end.y () Real)
(declare-fun r.end.x () Real)
(assert (<= 4.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (and (= 0.0 (+ 0.0 r.end.x (* 0.0 (- 1.0))))
     (distinct 0.0 (+ 0.0 r.end.y (* 0.0 (- 1.0))))
     (<= 0.0 (+ 1.0 r.end.y (* 0.0 (- 1.0))))
     (>= 0.0 (+ (- 1.0) r.end.y (* 0.0 (- 1.0))))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y))))))
(let ((a!2 (=> a!1 (<= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0)))))))
  (not (not (and a!2))))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
      (a!2 (+ (* (- o.x 0.0) (- r.end.x 0.0)) (* (- o.y 0.0) (- r.end.y 0.0))))
      (a!3 (+ (* (- o.x 0.0) (- o.x 0.0)) (* (- o.y 0.0) (- o.y 0.0))))
      (a!4 (+ (* (- r.end.x 0.0) (- r.end.x 0.0))
              (* (- r.end.y 0.0) (- r.end.y 0.0))))
      (a!5 (> 4.0
              (+ (* (- o.x r.end.x) (- o.x r.end.x))
                 (* (- o.y r.end.y) (- o.y r.end.y)))))
      (a!8 (>= 16.0
               (+ (* (- r.end.x o.x) (- r.end.x o.x))
                  (* (- r.end.y o.y) (- r.end.y o.y)))))
      (a!9 (not (= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0))))))
      (a!10 (+ (* (- r.end.x (+ o.x 1.0)) (- r.end.x (+ o.x 1.0)))
               (* (- r.end.y (+ o.y 0.0)) (- r.end.y (+ o.y 0.0)))))
      (a!12 (and (= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0))))
                 (< 0.0 (+ 0.0 o.y (* 0.0 (- 1.0)))))))
(let ((a!6 (and (< 0.0 a!2)
                (< a!2 a!4)
                (< (- (* a!3 a!4) (* a!2 a!2)) (* 2.0 2.0 a!4))))
      (a!11 (or (and a!8 (or a!9 (>= 16.0 a!10))) false)))
(let ((a!7 (not (or (and (>= 0.0 a!2) (> 4.0 a!3)) (and (>= a!2 a!4) a!5) a!6))))
(let ((a!13 (and (<= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0)))) a!7 a!11 (not a!12))))
  (and (=> a!1 a!13)))))))
(assert (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- r.end.x o.x) (- r.end.x o.x))
                  (* (- r.end.y o.y) (- r.end.y o.y))))))
  (not a!1)))
(check-sat)
