; Obligation: progress, form enabled, r's case nomovement-3-EFG; model paper (rule set paper), scheduler ssync, motion rigid.
; Claim: a robot of the left-most vertical that sees a robot right of it moves (so some robot is enabled).
; Named robots: r, e, g (r at the origin); two names are one robot (equal centres) or disjoint discs.
; Negated: r sees no robot left of it (universal over the robots it sees), sees g with g.x > r.x, and decides nomovement-3-EFG and stays.
; Why unsat covers swarms of every size: a connected swarm that is not a goal (not every centre on one vertical) has a robot r on its left-most vertical seeing a robot g off it (a path of edges leads from that vertical to a robot off it; take its first edge that leaves it). Nothing r sees is left of it. If r stayed in this case, its witnesses and g would be a solution (the case's other conditions are universal over the robots r sees). Unsat for every case: r moves, so some robot is enabled, in every connected non-goal swarm of any size (connectivity is its own lemma).
; Over the reals (one radius = 1).
; Assumptions: exact arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.e.y () Real)
(declare-fun r.e.x () Real)
(declare-fun g.y () Real)
(declare-fun g.x () Real)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.e.x) (- 0.0 r.e.x))
                  (* (- 0.0 r.e.y) (- 0.0 r.e.y))))))
  (or (and (= 0.0 r.e.x) (= 0.0 r.e.y)) a!1)))
(assert (let ((a!1 (<= 4.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y))))))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.e.x g.x) (- r.e.x g.x))
                  (* (- r.e.y g.y) (- r.e.y g.y))))))
  (or (and (= r.e.x g.x) (= r.e.y g.y)) a!1)))
(assert (not (and (= 0.0 r.e.x) (= 0.0 r.e.y))))
(assert (>= 16.0 (+ (* (- 0.0 r.e.x) (- 0.0 r.e.x)) (* (- 0.0 r.e.y) (- 0.0 r.e.y)))))
(assert (let ((a!1 (and (> (- r.e.x 0.0) (- 2.0)) (> 2.0 (- r.e.x 0.0))))
      (a!2 (and (> (- r.e.y 0.0) (- 2.0)) (> 2.0 (- r.e.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.e.y 0.0)))
               (and a!1 (> 0.0 (- r.e.y 0.0)))
               (and a!2 (< 0.0 (- r.e.x 0.0)))
               (and a!2 (> 0.0 (- r.e.x 0.0))))))
  (or (and (not a!3) (> 0.0 (- r.e.x 0.0)) (< 0.0 (- r.e.y 0.0)))
      (and (not a!3) (> 0.0 (- r.e.x 0.0)) (> 0.0 (- r.e.y 0.0)))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.e.x) (- 0.0 r.e.x))
                  (* (- 0.0 r.e.y) (- 0.0 r.e.y)))))
      (a!2 (not (and (> (- r.e.y 0.0) (- 2.0))
                     (> 2.0 (- r.e.y 0.0))
                     (> 0.0 (- r.e.x 0.0))))))
  (or (and (= 0.0 r.e.x) (= 0.0 r.e.y)) (=> a!1 a!2))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y)))))
      (a!2 (not (and (> (- g.y 0.0) (- 2.0))
                     (> 2.0 (- g.y 0.0))
                     (> 0.0 (- g.x 0.0))))))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) (=> a!1 a!2))))
(assert (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y)))))
(assert (< 0.0 g.x))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.e.x) (- 0.0 r.e.x))
                  (* (- 0.0 r.e.y) (- 0.0 r.e.y))))))
  (or (and (= 0.0 r.e.x) (= 0.0 r.e.y)) (=> a!1 (<= 0.0 r.e.x)))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y))))))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) (=> a!1 (<= 0.0 g.x)))))
(check-sat)
