; Obligation: termination, form measure, r's case scenario-1; model paper-centralized (rule set paper), scheduler centralized, motion rigid.
; Claim: every move makes the mover's term of the measure fall lexicographically by a lattice unit or more.
; Named robots: r, w (r at the origin); two names are one robot (equal centres) or disjoint discs.
; Measure: lexicographic (sum of -x, sum of y) over the robots: a move goes right, or stays on its vertical and goes down; components (a, b) per robot a*X + b*Y: [(-1, 0), (0, 1)].
; Negated: r moves in this case (its destination is not its centre) and its own term does not fall lexicographically by at least one lattice unit.
; On the model's lattice q = 1 (integer coordinates, one radius = q): a fall is at least one lattice unit (the fixed epsilon).
; Why unsat covers swarms of every size: the case's conditions are universal over the robots r sees or name a witness, and r's term depends on r's own move only. Any set of movers the scheduler allows (one: centralized; any non-empty set: ssync; every enabled robot: fsync) changes the sum by the sum of the movers' falls, and the lexicographic order of integer vectors is compatible with addition, so every round with a mover makes the measure fall by a unit or more (rigid moves: each mover reaches its destination).
; Bounded below: sum of -x: bounded below while no robot moves right of every robot it sees (rma-fixed's `seen` obligations: the right-most vertical never moves right); sum of y: NOT argued (nothing in the paper's rules bounds how far Scenario 4 moves down), so these rows prove the fall only.
; Termination for every n, with a fair scheduler: every enabledness obligation PROVED (a non-goal connected swarm has an enabled robot, which stays enabled until it moves, since nothing moves before), every measure obligation PROVED, the bound argued, and connectivity and no-collision PROVED.
; Assumptions: exact arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NIA)
(declare-fun r.w.y () Int)
(declare-fun r.w.x () Int)
(assert (let ((a!1 (<= 4 (+ (* (- 0 r.w.x) (- 0 r.w.x)) (* (- 0 r.w.y) (- 0 r.w.y))))))
  (or (and (= 0 r.w.x) (= 0 r.w.y)) a!1)))
(assert (not (and (= 0 r.w.x) (= 0 r.w.y))))
(assert (>= 16 (+ (* (- 0 r.w.x) (- 0 r.w.x)) (* (- 0 r.w.y) (- 0 r.w.y)))))
(assert (let ((a!1 (and (> (- r.w.x 0) (- 2)) (> 2 (- r.w.x 0))))
      (a!2 (and (> (- r.w.y 0) (- 2)) (> 2 (- r.w.y 0)))))
(let ((a!3 (or (and a!1 (< 0 (- r.w.y 0)))
               (and a!1 (> 0 (- r.w.y 0)))
               (and a!2 (< 0 (- r.w.x 0)))
               (and a!2 (> 0 (- r.w.x 0))))))
  (or (and (not a!3) (< 0 (- r.w.x 0)) (< 0 (- r.w.y 0)))
      (and a!2 (< 0 (- r.w.x 0)))
      (and (not a!3) (< 0 (- r.w.x 0)) (> 0 (- r.w.y 0)))))))
(assert (let ((a!1 (>= 16 (+ (* (- 0 r.w.x) (- 0 r.w.x)) (* (- 0 r.w.y) (- 0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0) (- 2)) (> 2 (- r.w.x 0))))
      (a!3 (and (> (- r.w.y 0) (- 2)) (> 2 (- r.w.y 0)))))
(let ((a!4 (or (and a!2 (< 0 (- r.w.y 0)))
               (and a!2 (> 0 (- r.w.y 0)))
               (and a!3 (< 0 (- r.w.x 0)))
               (and a!3 (> 0 (- r.w.x 0)))))
      (a!6 (not (and a!3 (> 0 (- r.w.x 0)))))
      (a!9 (and (> (- (- r.w.x 0) (- r.w.x 0)) (- 2))
                (> 2 (- (- r.w.x 0) (- r.w.x 0)))
                (and a!3 (< 0 (- r.w.x 0))))))
(let ((a!5 (not (and (not a!4) (> 0 (- r.w.x 0)) (< 0 (- r.w.y 0)))))
      (a!7 (not (and (not a!4) (> 0 (- r.w.x 0)) (> 0 (- r.w.y 0)))))
      (a!8 (or (and (not a!4) (< 0 (- r.w.x 0)) (< 0 (- r.w.y 0)))
               (and a!3 (< 0 (- r.w.x 0)))
               (and (not a!4) (< 0 (- r.w.x 0)) (> 0 (- r.w.y 0))))))
(let ((a!10 (and a!5 a!6 a!7 (=> a!8 (>= (- r.w.x 0) (- r.w.x 0))) (not a!9))))
  (or (and (= 0 r.w.x) (= 0 r.w.y)) (=> a!1 a!10)))))))
(assert (or (distinct 0 (- r.w.x 0)) (distinct 0 0)))
(assert (let ((a!1 (>= (- 1) (+ (* (- 1) (- r.w.x 0)) (* 0 0))))
      (a!2 (= (+ (* (- 1) (- r.w.x 0)) (* 0 0)) 0))
      (a!3 (>= (- 1) (+ (* 0 (- r.w.x 0)) (* 1 0)))))
  (not (or (and a!1) (and a!2 a!3)))))
(check-sat)
