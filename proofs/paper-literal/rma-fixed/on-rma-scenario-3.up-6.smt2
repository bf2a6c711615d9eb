; Obligation: rma-fixed, form on-rma, r's case scenario-3.up-6; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; candidates 1..5 up are blocked (witnesses k); candidate 6 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4, r.k+5 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
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
(declare-fun r.k+5.y () Real)
(declare-fun r.k+5.x () Real)
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
               (+ (* (- 0.0 r.k+5.x) (- 0.0 r.k+5.x))
                  (* (- 0.0 r.k+5.y) (- 0.0 r.k+5.y))))))
  (or (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)) a!1)))
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
               (+ (* (- r.w.x r.k+5.x) (- r.w.x r.k+5.x))
                  (* (- r.w.y r.k+5.y) (- r.w.y r.k+5.y))))))
  (or (and (= r.w.x r.k+5.x) (= r.w.y r.k+5.y)) a!1)))
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
               (+ (* (- r.c.x r.k+5.x) (- r.c.x r.k+5.x))
                  (* (- r.c.y r.k+5.y) (- r.c.y r.k+5.y))))))
  (or (and (= r.c.x r.k+5.x) (= r.c.y r.k+5.y)) a!1)))
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
               (+ (* (- r.d.x r.k+5.x) (- r.d.x r.k+5.x))
                  (* (- r.d.y r.k+5.y) (- r.d.y r.k+5.y))))))
  (or (and (= r.d.x r.k+5.x) (= r.d.y r.k+5.y)) a!1)))
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
               (+ (* (- r.k+1.x r.k+5.x) (- r.k+1.x r.k+5.x))
                  (* (- r.k+1.y r.k+5.y) (- r.k+1.y r.k+5.y))))))
  (or (and (= r.k+1.x r.k+5.x) (= r.k+1.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x))
                  (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))))
  (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+5.x) (- r.k+2.x r.k+5.x))
                  (* (- r.k+2.y r.k+5.y) (- r.k+2.y r.k+5.y))))))
  (or (and (= r.k+2.x r.k+5.x) (= r.k+2.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+5.x) (- r.k+3.x r.k+5.x))
                  (* (- r.k+3.y r.k+5.y) (- r.k+3.y r.k+5.y))))))
  (or (and (= r.k+3.x r.k+5.x) (= r.k+3.y r.k+5.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k+5.x) (- r.k+4.x r.k+5.x))
                  (* (- r.k+4.y r.k+5.y) (- r.k+4.y r.k+5.y))))))
  (or (and (= r.k+4.x r.k+5.x) (= r.k+4.y r.k+5.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!4 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!9 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!10 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!11 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!12 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!15 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!16 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!17 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!19 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!23 (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
               (- (- r.k+1.x 0.0) (- r.w.x 0.0))))
      (a!25 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!26 (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
               (- (- r.k+2.x 0.0) (- r.w.x 0.0))))
      (a!28 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!29 (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
               (- (- r.k+3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0
                (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                   (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!32 (* (- (- r.k+4.x 0.0) (- r.w.x 0.0))
               (- (- r.k+4.x 0.0) (- r.w.x 0.0))))
      (a!34 (>= 16.0
                (+ (* (- 0.0 r.k+5.x) (- 0.0 r.k+5.x))
                   (* (- 0.0 r.k+5.y) (- 0.0 r.k+5.y)))))
      (a!35 (* (- (- r.k+5.x 0.0) (- r.w.x 0.0))
               (- (- r.k+5.x 0.0) (- r.w.x 0.0))))
      (a!37 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!38 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!47 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 6.0) (- (- 0.0 0.0) 6.0))))
      (a!53 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 6.0) (- (- r.w.y 0.0) 6.0))))
      (a!61 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 6.0) (- (- r.c.y 0.0) 6.0))))
      (a!68 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 6.0) (- (- r.d.y 0.0) 6.0))))
      (a!70 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!72 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!83 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!85 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!96 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!98 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!109 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!111 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!122 (and (> (- r.k+5.x 0.0) (- 2.0)) (> 2.0 (- r.k+5.x 0.0))))
      (a!124 (and (> (- r.k+5.y 0.0) (- 2.0)) (> 2.0 (- r.k+5.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- r.c.y 0.0)))
                (and a!12 (> 0.0 (- r.c.y 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- r.d.y 0.0)))
                (and a!17 (> 0.0 (- r.d.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!27 (+ a!26 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!30 (+ a!29 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!33 (+ a!32 (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))
      (a!36 (+ a!35 (* (- (- r.k+5.y 0.0) 5.0) (- (- r.k+5.y 0.0) 5.0))))
      (a!39 (or (and a!38 (< 0.0 (- 0.0 0.0))) (and a!38 (> 0.0 (- 0.0 0.0)))))
      (a!71 (or (and a!70 (< 0.0 (- r.k+1.y 0.0)))
                (and a!70 (> 0.0 (- r.k+1.y 0.0)))))
      (a!81 (+ a!23 (* (- (- r.k+1.y 0.0) 6.0) (- (- r.k+1.y 0.0) 6.0))))
      (a!84 (or (and a!83 (< 0.0 (- r.k+2.y 0.0)))
                (and a!83 (> 0.0 (- r.k+2.y 0.0)))))
      (a!94 (+ a!26 (* (- (- r.k+2.y 0.0) 6.0) (- (- r.k+2.y 0.0) 6.0))))
      (a!97 (or (and a!96 (< 0.0 (- r.k+3.y 0.0)))
                (and a!96 (> 0.0 (- r.k+3.y 0.0)))))
      (a!107 (+ a!29 (* (- (- r.k+3.y 0.0) 6.0) (- (- r.k+3.y 0.0) 6.0))))
      (a!110 (or (and a!109 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!109 (> 0.0 (- r.k+4.y 0.0)))))
      (a!120 (+ a!32 (* (- (- r.k+4.y 0.0) 6.0) (- (- r.k+4.y 0.0) 6.0))))
      (a!123 (or (and a!122 (< 0.0 (- r.k+5.y 0.0)))
                 (and a!122 (> 0.0 (- r.k+5.y 0.0)))))
      (a!133 (+ a!35 (* (- (- r.k+5.y 0.0) 6.0) (- (- r.k+5.y 0.0) 6.0)))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (and (and a!11 (< 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!20 (or a!18
                (and a!19 (< 0.0 (- r.d.x 0.0)))
                (and a!19 (> 0.0 (- r.d.x 0.0)))))
      (a!40 (not (and (not (or a!39 a!39))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!41 (and (and a!38 (> 0.0 (- 0.0 0.0))) (not a!39)))
      (a!42 (not (and (not (or a!39 a!39))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!43 (and (not (or a!39 a!39)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!44 (and (and a!38 (< 0.0 (- 0.0 0.0))) (not a!39)))
      (a!50 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!55 (or a!13
                (and a!11 (< 0.0 (- r.c.x 0.0)))
                (and a!11 (> 0.0 (- r.c.x 0.0)))))
      (a!57 (and (and a!11 (> 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!64 (and (and a!19 (> 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!67 (and (and a!19 (< 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!73 (or a!71
                (and a!72 (< 0.0 (- r.k+1.x 0.0)))
                (and a!72 (> 0.0 (- r.k+1.x 0.0)))))
      (a!75 (and (and a!72 (> 0.0 (- r.k+1.x 0.0))) (not a!71)))
      (a!78 (and (and a!72 (< 0.0 (- r.k+1.x 0.0))) (not a!71)))
      (a!86 (or a!84
                (and a!85 (< 0.0 (- r.k+2.x 0.0)))
                (and a!85 (> 0.0 (- r.k+2.x 0.0)))))
      (a!88 (and (and a!85 (> 0.0 (- r.k+2.x 0.0))) (not a!84)))
      (a!91 (and (and a!85 (< 0.0 (- r.k+2.x 0.0))) (not a!84)))
      (a!99 (or a!97
                (and a!98 (< 0.0 (- r.k+3.x 0.0)))
                (and a!98 (> 0.0 (- r.k+3.x 0.0)))))
      (a!101 (and (and a!98 (> 0.0 (- r.k+3.x 0.0))) (not a!97)))
      (a!104 (and (and a!98 (< 0.0 (- r.k+3.x 0.0))) (not a!97)))
      (a!112 (or a!110
                 (and a!111 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!111 (> 0.0 (- r.k+4.x 0.0)))))
      (a!114 (and (and a!111 (> 0.0 (- r.k+4.x 0.0))) (not a!110)))
      (a!117 (and (and a!111 (< 0.0 (- r.k+4.x 0.0))) (not a!110)))
      (a!125 (or a!123
                 (and a!124 (< 0.0 (- r.k+5.x 0.0)))
                 (and a!124 (> 0.0 (- r.k+5.x 0.0)))))
      (a!127 (and (and a!124 (> 0.0 (- r.k+5.x 0.0))) (not a!123)))
      (a!130 (and (and a!124 (< 0.0 (- r.k+5.x 0.0))) (not a!123))))
(let ((a!6 (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!21 (and (not a!20) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!45 (or a!43
                a!44
                (and (not (or a!39 a!39))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!46 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!43))
      (a!49 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!51 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!56 (not (and (not a!55) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!58 (not (and (not a!55) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!59 (and (not a!55) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!63 (not (and (not a!20) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!65 (not (and (not a!20) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!66 (and (not a!20) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!74 (not (and (not a!73)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!76 (not (and (not a!73)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!77 (and (not a!73) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!87 (not (and (not a!86)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!89 (not (and (not a!86)
                      (< 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!90 (and (not a!86) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!100 (not (and (not a!99)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!102 (not (and (not a!99)
                       (< 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!103 (and (not a!99) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!113 (not (and (not a!112)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!115 (not (and (not a!112)
                       (< 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!116 (and (not a!112) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!126 (not (and (not a!125)
                       (> 0.0 (- r.k+5.x 0.0))
                       (> 0.0 (- r.k+5.y 0.0)))))
      (a!128 (not (and (not a!125)
                       (< 0.0 (- r.k+5.x 0.0))
                       (> 0.0 (- r.k+5.y 0.0)))))
      (a!129 (and (not a!125) (< 0.0 (- r.k+5.x 0.0)) (< 0.0 (- r.k+5.y 0.0)))))
(let ((a!8 (or a!6
               a!7
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!48 (and a!40
                 (not a!41)
                 a!42
                 (=> a!45 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!46)
                 (not (> 4.0 a!47))))
      (a!52 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!60 (or a!59
                a!14
                (and (not a!55) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!69 (and a!63
                 (not a!64)
                 a!65
                 (=> (or a!66 a!67 a!21) (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!16 a!66))
                 (not (> 4.0 a!68))))
      (a!79 (or a!77
                a!78
                (and (not a!73) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!80 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!77))
      (a!92 (or a!90
                a!91
                (and (not a!86) (> 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
      (a!93 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!90))
      (a!105 (or a!103
                 a!104
                 (and (not a!99)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!106 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!103))
      (a!118 (or a!116
                 a!117
                 (and (not a!112)
                      (> 0.0 (- r.k+4.x 0.0))
                      (< 0.0 (- r.k+4.y 0.0)))))
      (a!119 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!116))
      (a!131 (or a!129
                 a!130
                 (and (not a!125)
                      (> 0.0 (- r.k+5.x 0.0))
                      (< 0.0 (- r.k+5.y 0.0)))))
      (a!132 (and (> (- (- r.k+5.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+5.x 0.0) (- r.w.x 0.0)))
                  a!129)))
(let ((a!54 (and a!49
                 (not a!50)
                 a!51
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!52)
                 (not (> 4.0 a!53))))
      (a!62 (and a!56
                 (not a!57)
                 a!58
                 (=> a!60 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!59))
                 (not (> 4.0 a!61))))
      (a!82 (and a!74
                 (not a!75)
                 a!76
                 (=> a!79 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!80)
                 (not (> 4.0 a!81))))
      (a!95 (and a!87
                 (not a!88)
                 a!89
                 (=> a!92 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!93)
                 (not (> 4.0 a!94))))
      (a!108 (and a!100
                  (not a!101)
                  a!102
                  (=> a!105 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!106)
                  (not (> 4.0 a!107))))
      (a!121 (and a!113
                  (not a!114)
                  a!115
                  (=> a!118 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!119)
                  (not (> 4.0 a!120))))
      (a!134 (and a!126
                  (not a!127)
                  a!128
                  (=> a!131 (>= (- r.k+5.x 0.0) (- r.w.x 0.0)))
                  (not a!132)
                  (not (> 4.0 a!133)))))
(let ((a!135 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!8
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!9
                  a!10
                  a!14
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  a!15
                  a!16
                  a!21
                  (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                  a!22
                  (> 4.0 a!24)
                  (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                  a!25
                  (> 4.0 a!27)
                  (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                  a!28
                  (> 4.0 a!30)
                  (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)))
                  a!31
                  (> 4.0 a!33)
                  (not (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)))
                  a!34
                  (> 4.0 a!36)
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!37 a!48))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!54))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!9 a!62))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!15 a!69))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!22 a!82))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!25 a!95))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!28 a!108))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!31 a!121))
                  (or (and (= 0.0 r.k+5.x) (= 0.0 r.k+5.y)) (=> a!34 a!134)))))
  (=> r.case0 a!135)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (>= 0.0 r.k+5.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
