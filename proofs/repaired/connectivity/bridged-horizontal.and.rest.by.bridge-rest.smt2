; Obligation: connectivity, form bridged, r's leg horizontal, the other robot o at rest; the witness b of role bridge at rest; model repaired, move family repaired-legs, scheduler ssync, timing any-speed.
; Claim: r-o is an edge after the round, or r-b and b-o are.
; Family: the repaired rules' legs: one radius or less along one axis, under the lock, clear paths and kept edges. Classes: horizontal: (dx, 0) with 0 < dx <= 1; top: (0, dy) with 0 < |dy| <= 1, no robot seen above on its vertical; bottom: (0, dy) with 0 < dy <= 1, every robot seen on its vertical above it, ending >= 3 below each. Longest move 1 radii. Every decision of the rule set is held to the family as it runs (the step lemma in-family) and on every view of the lattice (the row in-family/views).
; Named robots: r, o, b (r at the origin), pairwise disjoint discs; each mover's shape, not held (at_rest), and its guard for every named robot it sees (forall: each named robot; exists: true, or the named witness where the form names it).
; Why unsat covers swarms of every size: each asserted condition is implied by the family's guards for the named robots in any swarm; every collision, and every edge with a mover at one end, is an instance of one obligation (fatline_verify/prove/smt/family.py, the module docstring), so each edge before the round is a path of at most two edges after it and the swarm stays connected.
; Rests on: nothing outside the family.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun o.y () Real)
(declare-fun o.x () Real)
(declare-fun b.y () Real)
(declare-fun b.x () Real)
(declare-fun r.end.x () Real)
(declare-fun r.end.y () Real)
(assert (<= 4.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (<= 4.0 (+ (* (- 0.0 b.x) (- 0.0 b.x)) (* (- 0.0 b.y) (- 0.0 b.y)))))
(assert (<= 4.0 (+ (* (- o.x b.x) (- o.x b.x)) (* (- o.y b.y) (- o.y b.y)))))
(assert (and (= 0.0 (+ 0.0 r.end.y (* 0.0 (- 1.0))))
     (< 0.0 (+ 0.0 r.end.x (* 0.0 (- 1.0))))
     (>= 0.0 (+ (- 1.0) r.end.x (* 0.0 (- 1.0))))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
      (a!3 (>= 16.0 (+ (* (- 0.0 b.x) (- 0.0 b.x)) (* (- 0.0 b.y) (- 0.0 b.y))))))
(let ((a!2 (=> a!1 (<= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0))))))
      (a!4 (=> a!3 (<= 0.0 (+ 0.0 b.x (* 0.0 (- 1.0)))))))
  (not (not (and a!2 a!4))))))
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
      (a!9 (>= 16.0 (+ (* (- 0.0 b.x) (- 0.0 b.x)) (* (- 0.0 b.y) (- 0.0 b.y)))))
      (a!10 (>= 16.0
                (+ (* (- r.end.x b.x) (- r.end.x b.x))
                   (* (- r.end.y b.y) (- r.end.y b.y)))))
      (a!11 (>= 16.0
                (+ (* (- b.x o.x) (- b.x o.x)) (* (- b.y o.y) (- b.y o.y)))))
      (a!12 (not (= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0))))))
      (a!13 (+ (* (- b.x (+ o.x 1.0)) (- b.x (+ o.x 1.0)))
               (* (- b.y (+ o.y 0.0)) (- b.y (+ o.y 0.0)))))
      (a!14 (not (< 0.0 (+ 0.0 o.y (* 0.0 (- 1.0))))))
      (a!15 (* (- b.x (+ o.x 0.0)) (- b.x (+ o.x 0.0))))
      (a!22 (+ (* (- b.x 0.0) (- r.end.x 0.0)) (* (- b.y 0.0) (- r.end.y 0.0))))
      (a!23 (+ (* (- b.x 0.0) (- b.x 0.0)) (* (- b.y 0.0) (- b.y 0.0))))
      (a!24 (> 4.0
               (+ (* (- b.x r.end.x) (- b.x r.end.x))
                  (* (- b.y r.end.y) (- b.y r.end.y))))))
(let ((a!6 (and (< 0.0 a!2)
                (< a!2 a!4)
                (< (- (* a!3 a!4) (* a!2 a!2)) (* 2.0 2.0 a!4))))
      (a!16 (+ a!15 (* (- b.y (+ o.y 1.0)) (- b.y (+ o.y 1.0)))))
      (a!17 (+ a!15 (* (- b.y (+ o.y (- 1.0))) (- b.y (+ o.y (- 1.0))))))
      (a!25 (and (< 0.0 a!22)
                 (< a!22 a!4)
                 (< (- (* a!23 a!4) (* a!22 a!22)) (* 2.0 2.0 a!4)))))
(let ((a!7 (not (or (and (>= 0.0 a!2) (> 4.0 a!3)) (and (>= a!2 a!4) a!5) a!6)))
      (a!18 (and (>= 16.0 a!13) (or a!14 (and (>= 16.0 a!16) (>= 16.0 a!17)))))
      (a!26 (not (or (and (>= 0.0 a!22) (> 4.0 a!23))
                     (and (>= a!22 a!4) a!24)
                     a!25))))
(let ((a!19 (and a!9
                 (or (distinct b.x o.x) (distinct b.y o.y))
                 (< 0.0 (+ 0.0 b.x (* 0.0 (- 1.0))))
                 a!10
                 a!11
                 (or a!12 a!18)))
      (a!20 (and (<= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0)))) a!7 (or a!8 false)))
      (a!27 (and (<= 0.0 (+ 0.0 b.x (* 0.0 (- 1.0)))) a!26 (or a!10 true))))
(let ((a!21 (and (<= 0.0 (+ 0.0 o.x (* 0.0 (- 1.0))))
                 a!7
                 (or a!8 a!19)
                 (not a!20))))
  (and (=> a!1 a!21) (=> a!9 a!27))))))))
(assert (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- r.end.x o.x) (- r.end.x o.x))
                  (* (- r.end.y o.y) (- r.end.y o.y)))))
      (a!2 (>= 16.0
               (+ (* (- r.end.x b.x) (- r.end.x b.x))
                  (* (- r.end.y b.y) (- r.end.y b.y)))))
      (a!3 (>= 16.0 (+ (* (- b.x o.x) (- b.x o.x)) (* (- b.y o.y) (- b.y o.y))))))
  (and (not a!1) (not (and a!2 a!3)))))
(check-sat)
