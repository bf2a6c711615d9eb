; Obligation: rma-fixed, form on-rma, r's case scenario-1; model paper-line-meets-discs, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; universal: no visible robot in R_psi n C.
; Named robots: r, r.w (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.case0 () Bool)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y))))))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!6 (>= 16.0 (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!7 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!8 (or (and a!7 (< 0.0 (- 0.0 0.0))) (and a!7 (> 0.0 (- 0.0 0.0)))))
      (a!10 (not (and a!7 (> 0.0 (- 0.0 0.0)))))
      (a!13 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 (and a!7 (< 0.0 (- 0.0 0.0)))))
      (a!16 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!18 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 (and a!3 (< 0.0 (- r.w.x 0.0))))))
(let ((a!5 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!9 (not (and (not (or a!8 a!8)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))))
      (a!11 (not (and (not (or a!8 a!8))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!12 (or (and (not (or a!8 a!8)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))
                (and a!7 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!8 a!8)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0)))))
      (a!15 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!17 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))))
(let ((a!14 (and a!9
                 a!10
                 a!11
                 (=> a!12 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!13)))
      (a!19 (and a!15
                 a!16
                 a!17
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!18))))
(let ((a!20 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!5
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!6 a!14))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!19)))))
  (=> r.case0 a!20)))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x) (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
