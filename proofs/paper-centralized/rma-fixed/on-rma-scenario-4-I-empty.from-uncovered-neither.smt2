; Obligation: rma-fixed, form on-rma, r's case scenario-4-I-empty.from-uncovered-neither; model paper-centralized, scheduler centralized.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C; universal: no visible robot in R_psi n B and R_psi n D; universal: no visible robot in I.
; Named robots: r, r.w, r.c (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
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
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!8 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!9 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!10 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!11 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!12 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!20 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!25 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!28 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- 0.0 0.0))) (and a!12 (> 0.0 (- 0.0 0.0)))))
      (a!15 (not (and a!12 (> 0.0 (- 0.0 0.0)))))
      (a!23 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!26 (not (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!29 (or (and a!28 (< 0.0 (- r.c.y 0.0)))
                (and a!28 (> 0.0 (- r.c.y 0.0)))
                (and a!10 (< 0.0 (- r.c.x 0.0)))
                (and a!10 (> 0.0 (- r.c.x 0.0)))))
      (a!31 (not (and a!10 (> 0.0 (- r.c.x 0.0)))))
      (a!36 (not (and a!28 (> 0.0 (- r.c.y 0.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!6 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!14 (not (and (not (or a!13 a!13))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!16 (not (and (not (or a!13 a!13))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!17 (and (not (or a!13 a!13)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!18 (and (not (or a!13 a!13)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!22 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!24 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!30 (not (and (not a!29) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!32 (not (and (not a!29) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!33 (and (not a!29) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!34 (and (not a!29) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
(let ((a!7 (or a!5 (and a!3 (< 0.0 (- r.w.x 0.0))) a!6))
      (a!19 (or a!17 (and a!12 (< 0.0 (- 0.0 0.0))) a!18))
      (a!35 (or a!33 (and a!10 (< 0.0 (- r.c.x 0.0))) a!34)))
(let ((a!21 (and a!14
                 a!15
                 a!16
                 (=> a!19 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!20 a!17))
                 (not (and a!20 a!18))
                 a!15))
      (a!27 (and a!22
                 a!23
                 a!24
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!25 a!5))
                 (not (and a!25 a!6))
                 a!26))
      (a!37 (and a!30
                 a!31
                 a!32
                 (=> a!35 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!9 a!33))
                 (not (and a!9 a!34))
                 a!36)))
(let ((a!38 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!7
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 a!8
                 a!9
                 (and a!10 (< 0.0 (- r.c.x 0.0)))
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!11 a!21))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!27))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!8 a!37)))))
  (=> r.case0 a!38))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x) (>= 0.0 r.c.x) (distinct 0.0 (+ 0.0 0.0))))
(check-sat)
