; Obligation: connectivity, form kept, r's leg bottom, the other robot o at rest; model repaired (the repaired rule set), scheduler ssync, timing any-speed.
; Claim: r and o, within view before the round, are within view after it.
; Legs: horizontal (dx, 0) with 0 < dx <= 1 (a horizontal leg goes right: it is one radius or less toward the paper's destination, whose x never decreases (the approach obligations of the same run: x-nondecreasing for every case of the paper's rules under these readings), or toward the repairs' own (repair-align: the greatest x r sees, right of r; repair-approach: 2 radii short of psi_right, used only if right of r: their x-nondecreasing-repair-* obligations; repair-detour, when on: toward a destination right of r, or at most to the greatest x r sees)); top (0, dy) with 0 < |dy| <= 1 seeing no robot above on its vertical; bottom (0, dy) with 0 < dy <= 1 seeing none below on its vertical and ending >= 3 below each robot above it there. Whatever rule chose the move (fatline_verify/rules/repaired/algorithm.py, leg_of).
; Each mover's conditions for every named robot it sees (repairs.allowed): not strictly left of it (the lock), clear of its swept disc (repair_clear), its leg class's condition on its vertical. kept: the mover ends within view of the robot (and of it one radius right when the mover is vertical and the robot on its vertical). bridged: b right of r, seen by r, sees r's end and o wherever o may move; b sees r strictly left of it, so the lock holds b at rest.
; Named robots: r, o (r at the origin), pairwise disjoint discs.
; Why unsat covers swarms of every size: the conditions asserted are universal over the robots a mover sees (so they hold for the named ones in any swarm), and every collision, and every edge with a mover at one end, is an instance of one leg obligation (the module docstring of fatline_verify/prove/smt/legs.py); each edge before the round is then a path of at most two edges after it, and the swarm stays connected. tests/test_legs.py checks the leg classes and each condition on the repaired rules' own decisions.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.step () Real)
(declare-fun o.y () Real)
(declare-fun o.x () Real)
(assert (< 0.0 r.step))
(assert (>= 1.0 r.step))
(assert (<= 4.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
      (a!2 (+ (* (- o.x 0.0) (- 0.0 0.0))
              (* (- o.y 0.0) (- (+ 0.0 r.step) 0.0))))
      (a!3 (+ (* (- o.x 0.0) (- o.x 0.0)) (* (- o.y 0.0) (- o.y 0.0))))
      (a!4 (+ (* (- 0.0 0.0) (- 0.0 0.0))
              (* (- (+ 0.0 r.step) 0.0) (- (+ 0.0 r.step) 0.0))))
      (a!5 (+ (* (- o.x 0.0) (- o.x 0.0))
              (* (- o.y (+ 0.0 r.step)) (- o.y (+ 0.0 r.step)))))
      (a!8 (=> (= 0.0 o.x) (and (< 0.0 o.y) (<= (+ 0.0 r.step) (- o.y 3.0))))))
(let ((a!6 (and (< 0.0 a!2)
                (< a!2 a!4)
                (< (- (* a!3 a!4) (* a!2 a!2)) (* 2.0 2.0 a!4)))))
(let ((a!7 (not (or (and (>= 0.0 a!2) (> 4.0 a!3))
                    (and (>= a!2 a!4) (> 4.0 a!5))
                    a!6))))
  (=> a!1 (and (<= 0.0 o.x) a!7 a!8))))))
(assert (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (let ((a!1 (* (- (+ 0.0 r.step) o.y) (- (+ 0.0 r.step) o.y))))
(let ((a!2 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) a!1)))
      (a!3 (+ (* (- 0.0 (+ o.x 1.0)) (- 0.0 (+ o.x 1.0))) a!1)))
  (and a!2 (=> (= 0.0 o.x) (>= 16.0 a!3))))))
(assert (let ((a!1 (+ (* (- 0.0 o.x) (- 0.0 o.x))
              (* (- (+ 0.0 r.step) o.y) (- (+ 0.0 r.step) o.y)))))
  (not (>= 16.0 a!1))))
(check-sat)
