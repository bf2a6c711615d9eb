; Obligation: progress, form enabled, r's case scenario-4-I-empty.from-scenario-3; model paper-drop-touch (rule set paper), scheduler ssync, motion rigid.
; Claim: a robot of the left-most vertical that sees a robot right of it moves (so some robot is enabled).
; Named robots: r, w, c, d, k+1, k+2, k+3, k+4, k-1, k-2, k-3, k-4, g (r at the origin); two names are one robot (equal centres) or disjoint discs.
; Negated: r sees no robot left of it (universal over the robots it sees), sees g with g.x > r.x, and decides scenario-4-I-empty.from-scenario-3 and stays (its destination is its own centre).
; Why unsat covers swarms of every size: a connected swarm that is not a goal (not every centre on one vertical) has a robot r on its left-most vertical seeing a robot g off it (a path of edges leads from that vertical to a robot off it; take its first edge that leaves it). Nothing r sees is left of it. If r stayed in this case, its witnesses and g would be a solution (the case's other conditions are universal over the robots r sees). Unsat for every case: r moves, so some robot is enabled, in every connected non-goal swarm of any size (connectivity is its own lemma).
; Over the reals (one radius = 1).
; Assumptions: exact arithmetic; unit discs; one shared snapshot per round.
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
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun g.y () Real)
(declare-fun g.x () Real)
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
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))))
  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y))))))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) a!1)))
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
               (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x))
                  (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))))
  (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x g.x) (- r.w.x g.x))
                  (* (- r.w.y g.y) (- r.w.y g.y))))))
  (or (and (= r.w.x g.x) (= r.w.y g.y)) a!1)))
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
               (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x))
                  (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))))
  (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x g.x) (- r.c.x g.x))
                  (* (- r.c.y g.y) (- r.c.y g.y))))))
  (or (and (= r.c.x g.x) (= r.c.y g.y)) a!1)))
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
               (+ (* (- r.d.x r.k-4.x) (- r.d.x r.k-4.x))
                  (* (- r.d.y r.k-4.y) (- r.d.y r.k-4.y))))))
  (or (and (= r.d.x r.k-4.x) (= r.d.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x g.x) (- r.d.x g.x))
                  (* (- r.d.y g.y) (- r.d.y g.y))))))
  (or (and (= r.d.x g.x) (= r.d.y g.y)) a!1)))
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
               (+ (* (- r.k+1.x r.k-4.x) (- r.k+1.x r.k-4.x))
                  (* (- r.k+1.y r.k-4.y) (- r.k+1.y r.k-4.y))))))
  (or (and (= r.k+1.x r.k-4.x) (= r.k+1.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x g.x) (- r.k+1.x g.x))
                  (* (- r.k+1.y g.y) (- r.k+1.y g.y))))))
  (or (and (= r.k+1.x g.x) (= r.k+1.y g.y)) a!1)))
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
               (+ (* (- r.k+2.x r.k-4.x) (- r.k+2.x r.k-4.x))
                  (* (- r.k+2.y r.k-4.y) (- r.k+2.y r.k-4.y))))))
  (or (and (= r.k+2.x r.k-4.x) (= r.k+2.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x g.x) (- r.k+2.x g.x))
                  (* (- r.k+2.y g.y) (- r.k+2.y g.y))))))
  (or (and (= r.k+2.x g.x) (= r.k+2.y g.y)) a!1)))
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
               (+ (* (- r.k+3.x r.k-4.x) (- r.k+3.x r.k-4.x))
                  (* (- r.k+3.y r.k-4.y) (- r.k+3.y r.k-4.y))))))
  (or (and (= r.k+3.x r.k-4.x) (= r.k+3.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x g.x) (- r.k+3.x g.x))
                  (* (- r.k+3.y g.y) (- r.k+3.y g.y))))))
  (or (and (= r.k+3.x g.x) (= r.k+3.y g.y)) a!1)))
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
               (+ (* (- r.k+4.x r.k-4.x) (- r.k+4.x r.k-4.x))
                  (* (- r.k+4.y r.k-4.y) (- r.k+4.y r.k-4.y))))))
  (or (and (= r.k+4.x r.k-4.x) (= r.k+4.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x g.x) (- r.k+4.x g.x))
                  (* (- r.k+4.y g.y) (- r.k+4.y g.y))))))
  (or (and (= r.k+4.x g.x) (= r.k+4.y g.y)) a!1)))
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
               (+ (* (- r.k-1.x g.x) (- r.k-1.x g.x))
                  (* (- r.k-1.y g.y) (- r.k-1.y g.y))))))
  (or (and (= r.k-1.x g.x) (= r.k-1.y g.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x))
                  (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))))
  (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x))
                  (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))))
  (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x g.x) (- r.k-2.x g.x))
                  (* (- r.k-2.y g.y) (- r.k-2.y g.y))))))
  (or (and (= r.k-2.x g.x) (= r.k-2.y g.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x))
                  (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))))
  (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-3.x g.x) (- r.k-3.x g.x))
                  (* (- r.k-3.y g.y) (- r.k-3.y g.y))))))
  (or (and (= r.k-3.x g.x) (= r.k-3.y g.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-4.x g.x) (- r.k-4.x g.x))
                  (* (- r.k-4.y g.y) (- r.k-4.y g.y))))))
  (or (and (= r.k-4.x g.x) (= r.k-4.y g.y)) a!1)))
(assert (not (and (= 0.0 r.w.x) (= 0.0 r.w.y))))
(assert (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0))))))
  (or (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
      (and a!2 (< 0.0 (- r.w.x 0.0)))
      (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))))
(assert (not (and (= 0.0 r.c.x) (= 0.0 r.c.y))))
(assert (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
(assert (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
     (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
(assert (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0)) (< 0.0 (- r.c.x 0.0))))
(assert (not (and (= 0.0 r.d.x) (= 0.0 r.d.y))))
(assert (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
(assert (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
     (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
(assert (let ((a!1 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!2 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.d.y 0.0)))
               (and a!1 (> 0.0 (- r.d.y 0.0)))
               (and a!2 (< 0.0 (- r.d.x 0.0)))
               (and a!2 (> 0.0 (- r.d.x 0.0))))))
  (and (not a!3) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                  (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!3 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
                 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0)))))
(let ((a!4 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                  (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!3 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
                 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0)))))
(let ((a!4 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                  (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!3 (+ (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
                 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0)))))
(let ((a!4 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                  (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!3 (+ (* (- (- r.k+4.x 0.0) (- r.w.x 0.0))
                 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0)))))
(let ((a!4 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!3 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
                 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0))))))
(let ((a!4 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                  (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!3 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
                 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0))))))
(let ((a!4 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                  (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!3 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
                 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0))))))
(let ((a!4 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!2 (>= 16.0
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y)))))
      (a!3 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0))
                 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))
              (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0))))))
(let ((a!4 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))) a!2 (> 4.0 a!3))))
  (or (not a!1) a!4))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.w.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!10 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!2 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!3 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.c.y 0.0)))
               (and a!2 (> 0.0 (- r.c.y 0.0)))
               (and a!3 (< 0.0 (- r.c.x 0.0)))
               (and a!3 (> 0.0 (- r.c.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.c.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.c.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.c.x 0.0)))
               (and (not a!4) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!10 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!2 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!3 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.d.y 0.0)))
               (and a!2 (> 0.0 (- r.d.y 0.0)))
               (and a!3 (< 0.0 (- r.d.x 0.0)))
               (and a!3 (> 0.0 (- r.d.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.d.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.d.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.d.x 0.0)))
               (and (not a!4) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!10 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                  (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!2 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!3 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k+1.y 0.0)))
               (and a!2 (> 0.0 (- r.k+1.y 0.0)))
               (and a!3 (< 0.0 (- r.k+1.x 0.0)))
               (and a!3 (> 0.0 (- r.k+1.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k+1.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k+1.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k+1.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!10 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                  (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!2 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!3 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k+2.y 0.0)))
               (and a!2 (> 0.0 (- r.k+2.y 0.0)))
               (and a!3 (< 0.0 (- r.k+2.x 0.0)))
               (and a!3 (> 0.0 (- r.k+2.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k+2.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k+2.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k+2.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!10 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                  (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!2 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!3 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k+3.y 0.0)))
               (and a!2 (> 0.0 (- r.k+3.y 0.0)))
               (and a!3 (< 0.0 (- r.k+3.x 0.0)))
               (and a!3 (> 0.0 (- r.k+3.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k+3.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k+3.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k+3.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0)))))
      (a!10 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                  (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!2 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!3 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k+4.y 0.0)))
               (and a!2 (> 0.0 (- r.k+4.y 0.0)))
               (and a!3 (< 0.0 (- r.k+4.x 0.0)))
               (and a!3 (> 0.0 (- r.k+4.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k+4.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k+4.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k+4.x 0.0)) (> 0.0 (- r.k+4.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k+4.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k+4.x 0.0)) (> 0.0 (- r.k+4.y 0.0)))))
      (a!10 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!2 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!3 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k-1.y 0.0)))
               (and a!2 (> 0.0 (- r.k-1.y 0.0)))
               (and a!3 (< 0.0 (- r.k-1.x 0.0)))
               (and a!3 (> 0.0 (- r.k-1.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k-1.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k-1.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k-1.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!10 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                  (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!2 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!3 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k-2.y 0.0)))
               (and a!2 (> 0.0 (- r.k-2.y 0.0)))
               (and a!3 (< 0.0 (- r.k-2.x 0.0)))
               (and a!3 (> 0.0 (- r.k-2.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k-2.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k-2.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k-2.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
      (a!10 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                  (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!2 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!3 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k-3.y 0.0)))
               (and a!2 (> 0.0 (- r.k-3.y 0.0)))
               (and a!3 (< 0.0 (- r.k-3.x 0.0)))
               (and a!3 (> 0.0 (- r.k-3.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k-3.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k-3.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k-3.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0)))))
      (a!10 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y)))))
      (a!2 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!3 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.k-4.y 0.0)))
               (and a!2 (> 0.0 (- r.k-4.y 0.0)))
               (and a!3 (< 0.0 (- r.k-4.x 0.0)))
               (and a!3 (> 0.0 (- r.k-4.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- r.k-4.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- r.k-4.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- r.k-4.x 0.0)) (> 0.0 (- r.k-4.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- r.k-4.x 0.0)))
               (and (not a!4) (< 0.0 (- r.k-4.x 0.0)) (> 0.0 (- r.k-4.y 0.0)))))
      (a!10 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) (=> a!1 a!12))))))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y)))))
      (a!2 (and (> (- g.x 0.0) (- 2.0)) (> 2.0 (- g.x 0.0))))
      (a!3 (and (> (- g.y 0.0) (- 2.0)) (> 2.0 (- g.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- g.y 0.0)))
               (and a!2 (> 0.0 (- g.y 0.0)))
               (and a!3 (< 0.0 (- g.x 0.0)))
               (and a!3 (> 0.0 (- g.x 0.0)))))
      (a!6 (not (and a!3 (> 0.0 (- g.x 0.0)))))
      (a!11 (not (and a!2 (> 0.0 (- g.y 0.0))))))
(let ((a!5 (not (and (not a!4) (> 0.0 (- g.x 0.0)) (< 0.0 (- g.y 0.0)))))
      (a!7 (not (and (not a!4) (> 0.0 (- g.x 0.0)) (> 0.0 (- g.y 0.0)))))
      (a!8 (and (not a!4) (< 0.0 (- g.x 0.0)) (< 0.0 (- g.y 0.0)))))
(let ((a!9 (or a!8
               (and a!3 (< 0.0 (- g.x 0.0)))
               (and (not a!4) (< 0.0 (- g.x 0.0)) (> 0.0 (- g.y 0.0)))))
      (a!10 (and (> (- (- g.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- g.x 0.0) (- r.w.x 0.0)))
                 a!8)))
(let ((a!12 (and a!5
                 a!6
                 a!7
                 (=> a!9 (>= (- g.x 0.0) (- r.w.x 0.0)))
                 (not a!10)
                 a!11)))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) (=> a!1 a!12))))))))
(assert (= 0.0 0.0))
(assert (= (- 3.0) 0.0))
(assert (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y)))))
(assert (< 0.0 g.x))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y))))))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 (<= 0.0 r.w.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y))))))
  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!1 (<= 0.0 r.c.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y))))))
  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!1 (<= 0.0 r.d.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                  (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))))
  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!1 (<= 0.0 r.k+1.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                  (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))))
  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!1 (<= 0.0 r.k+2.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                  (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))))
  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!1 (<= 0.0 r.k+3.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                  (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))))
  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!1 (<= 0.0 r.k+4.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!1 (<= 0.0 r.k-1.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                  (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))))
  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!1 (<= 0.0 r.k-2.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                  (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))))
  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!1 (<= 0.0 r.k-3.x)))))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x))
                  (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))))
  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) (=> a!1 (<= 0.0 r.k-4.x)))))
(assert (let ((a!1 (>= 16.0 (+ (* (- 0.0 g.x) (- 0.0 g.x)) (* (- 0.0 g.y) (- 0.0 g.y))))))
  (or (and (= 0.0 g.x) (= 0.0 g.y)) (=> a!1 (<= 0.0 g.x)))))
(check-sat)
