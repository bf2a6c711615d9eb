; Obligation: rma-fixed, form on-rma, r's case scenario-3.up-5; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; candidates 1..4 up are blocked (witnesses k); candidate 5 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x))
                  (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))))
  (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
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
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!35 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!44 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 5.0) (- (- 0.0 0.0) 5.0))))
      (a!50 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 5.0) (- (- r.w.y 0.0) 5.0))))
      (a!58 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 5.0) (- (- r.c.y 0.0) 5.0))))
      (a!65 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 5.0) (- (- r.d.y 0.0) 5.0))))
      (a!67 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!69 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!80 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!82 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!93 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!95 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!106 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!108 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- r.c.y 0.0)))
                (and a!12 (> 0.0 (- r.c.y 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- r.d.y 0.0)))
                (and a!17 (> 0.0 (- r.d.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!27 (+ a!26 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!30 (+ a!29 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!33 (+ a!32 (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))
      (a!36 (or (and a!35 (< 0.0 (- 0.0 0.0))) (and a!35 (> 0.0 (- 0.0 0.0)))))
      (a!68 (or (and a!67 (< 0.0 (- r.k+1.y 0.0)))
                (and a!67 (> 0.0 (- r.k+1.y 0.0)))))
      (a!78 (+ a!23 (* (- (- r.k+1.y 0.0) 5.0) (- (- r.k+1.y 0.0) 5.0))))
      (a!81 (or (and a!80 (< 0.0 (- r.k+2.y 0.0)))
                (and a!80 (> 0.0 (- r.k+2.y 0.0)))))
      (a!91 (+ a!26 (* (- (- r.k+2.y 0.0) 5.0) (- (- r.k+2.y 0.0) 5.0))))
      (a!94 (or (and a!93 (< 0.0 (- r.k+3.y 0.0)))
                (and a!93 (> 0.0 (- r.k+3.y 0.0)))))
      (a!104 (+ a!29 (* (- (- r.k+3.y 0.0) 5.0) (- (- r.k+3.y 0.0) 5.0))))
      (a!107 (or (and a!106 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!106 (> 0.0 (- r.k+4.y 0.0)))))
      (a!117 (+ a!32 (* (- (- r.k+4.y 0.0) 5.0) (- (- r.k+4.y 0.0) 5.0)))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (and (and a!11 (< 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!20 (or a!18
                (and a!19 (< 0.0 (- r.d.x 0.0)))
                (and a!19 (> 0.0 (- r.d.x 0.0)))))
      (a!37 (not (and (not (or a!36 a!36))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!38 (and (and a!35 (> 0.0 (- 0.0 0.0))) (not a!36)))
      (a!39 (not (and (not (or a!36 a!36))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!40 (and (not (or a!36 a!36)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!41 (and (and a!35 (< 0.0 (- 0.0 0.0))) (not a!36)))
      (a!47 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!52 (or a!13
                (and a!11 (< 0.0 (- r.c.x 0.0)))
                (and a!11 (> 0.0 (- r.c.x 0.0)))))
      (a!54 (and (and a!11 (> 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!61 (and (and a!19 (> 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!64 (and (and a!19 (< 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!70 (or a!68
                (and a!69 (< 0.0 (- r.k+1.x 0.0)))
                (and a!69 (> 0.0 (- r.k+1.x 0.0)))))
      (a!72 (and (and a!69 (> 0.0 (- r.k+1.x 0.0))) (not a!68)))
      (a!75 (and (and a!69 (< 0.0 (- r.k+1.x 0.0))) (not a!68)))
      (a!83 (or a!81
                (and a!82 (< 0.0 (- r.k+2.x 0.0)))
                (and a!82 (> 0.0 (- r.k+2.x 0.0)))))
      (a!85 (and (and a!82 (> 0.0 (- r.k+2.x 0.0))) (not a!81)))
      (a!88 (and (and a!82 (< 0.0 (- r.k+2.x 0.0))) (not a!81)))
      (a!96 (or a!94
                (and a!95 (< 0.0 (- r.k+3.x 0.0)))
                (and a!95 (> 0.0 (- r.k+3.x 0.0)))))
      (a!98 (and (and a!95 (> 0.0 (- r.k+3.x 0.0))) (not a!94)))
      (a!101 (and (and a!95 (< 0.0 (- r.k+3.x 0.0))) (not a!94)))
      (a!109 (or a!107
                 (and a!108 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!108 (> 0.0 (- r.k+4.x 0.0)))))
      (a!111 (and (and a!108 (> 0.0 (- r.k+4.x 0.0))) (not a!107)))
      (a!114 (and (and a!108 (< 0.0 (- r.k+4.x 0.0))) (not a!107))))
(let ((a!6 (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!21 (and (not a!20) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!42 (or a!40
                a!41
                (and (not (or a!36 a!36))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!43 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!40))
      (a!46 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!48 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!53 (not (and (not a!52) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!55 (not (and (not a!52) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!56 (and (not a!52) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!60 (not (and (not a!20) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!62 (not (and (not a!20) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!63 (and (not a!20) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!71 (not (and (not a!70)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!73 (not (and (not a!70)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!74 (and (not a!70) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!84 (not (and (not a!83)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!86 (not (and (not a!83)
                      (< 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!87 (and (not a!83) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!97 (not (and (not a!96)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!99 (not (and (not a!96)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!100 (and (not a!96) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!110 (not (and (not a!109)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!112 (not (and (not a!109)
                       (< 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!113 (and (not a!109) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0)))))
(let ((a!8 (or a!6
               a!7
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!45 (and a!37
                 (not a!38)
                 a!39
                 (=> a!42 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!43)
                 (not (> 4.0 a!44))))
      (a!49 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!57 (or a!56
                a!14
                (and (not a!52) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!66 (and a!60
                 (not a!61)
                 a!62
                 (=> (or a!63 a!64 a!21) (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!16 a!63))
                 (not (> 4.0 a!65))))
      (a!76 (or a!74
                a!75
                (and (not a!70) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!77 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!74))
      (a!89 (or a!87
                a!88
                (and (not a!83) (> 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
      (a!90 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!87))
      (a!102 (or a!100
                 a!101
                 (and (not a!96)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!103 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!100))
      (a!115 (or a!113
                 a!114
                 (and (not a!109)
                      (> 0.0 (- r.k+4.x 0.0))
                      (< 0.0 (- r.k+4.y 0.0)))))
      (a!116 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!113)))
(let ((a!51 (and a!46
                 (not a!47)
                 a!48
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!49)
                 (not (> 4.0 a!50))))
      (a!59 (and a!53
                 (not a!54)
                 a!55
                 (=> a!57 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!56))
                 (not (> 4.0 a!58))))
      (a!79 (and a!71
                 (not a!72)
                 a!73
                 (=> a!76 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!77)
                 (not (> 4.0 a!78))))
      (a!92 (and a!84
                 (not a!85)
                 a!86
                 (=> a!89 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!90)
                 (not (> 4.0 a!91))))
      (a!105 (and a!97
                  (not a!98)
                  a!99
                  (=> a!102 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!103)
                  (not (> 4.0 a!104))))
      (a!118 (and a!110
                  (not a!111)
                  a!112
                  (=> a!115 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!116)
                  (not (> 4.0 a!117)))))
(let ((a!119 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!34 a!45))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!51))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!9 a!59))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!15 a!66))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!22 a!79))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!25 a!92))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!28 a!105))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!31 a!118)))))
  (=> r.case0 a!119)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
