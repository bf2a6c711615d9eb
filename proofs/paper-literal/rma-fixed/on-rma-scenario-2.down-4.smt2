; Obligation: rma-fixed, form on-rma, r's case scenario-2.down-4; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b in R_psi n B, c in R_psi n C; universal: no visible robot in R_psi n D; candidates 1..3 down are blocked (witnesses k); candidate 4 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.b, r.c, r.k-1, r.k-2, r.k-3 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
; Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)
; How unsat may be shown: on the obligation's linearization (every comparison that multiplies two non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes outside it), which every solution of the obligation also solves; an unsat linearization is an unsat obligation.
; Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.
(set-logic QF_NRA)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun r.b.y () Real)
(declare-fun r.b.x () Real)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun r.case0 () Bool)
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y))))))
  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y))))))
  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y))))))
  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) a!1)))
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
               (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x))
                  (* (- r.w.y r.b.y) (- r.w.y r.b.y))))))
  (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
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
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x))
                  (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))))
  (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x))
                  (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))))
  (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x))
                  (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))))
  (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) a!1)))
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
               (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x))
                  (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))))
  (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x))
                  (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))))
  (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x))
                  (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))))
  (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!4 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!9 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!10 (and (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))))
      (a!11 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!13 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!16 (>= 16.0
                (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                   (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!17 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!18 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!19 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!23 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!25 (>= 16.0
                (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x))
                   (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y)))))
      (a!26 (* (- (- r.k-2.x 0.0) (- r.w.x 0.0))
               (- (- r.k-2.x 0.0) (- r.w.x 0.0))))
      (a!28 (>= 16.0
                (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x))
                   (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y)))))
      (a!29 (* (- (- r.k-3.x 0.0) (- r.w.x 0.0))
               (- (- r.k-3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!32 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!41 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 4.0)) (- (- 0.0 0.0) (- 4.0)))))
      (a!47 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 4.0)) (- (- r.w.y 0.0) (- 4.0)))))
      (a!54 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0))
                  (- (- r.b.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.b.y 0.0) (- 4.0)) (- (- r.b.y 0.0) (- 4.0)))))
      (a!62 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 4.0)) (- (- r.c.y 0.0) (- 4.0)))))
      (a!64 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!66 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!77 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!79 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!90 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!92 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!12 (or (and a!11 (< 0.0 (- r.b.y 0.0)))
                (and a!11 (> 0.0 (- r.b.y 0.0)))))
      (a!20 (or (and a!19 (< 0.0 (- r.c.y 0.0)))
                (and a!19 (> 0.0 (- r.c.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!27 (+ a!26 (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))
      (a!30 (+ a!29 (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))
      (a!33 (or (and a!32 (< 0.0 (- 0.0 0.0))) (and a!32 (> 0.0 (- 0.0 0.0)))))
      (a!65 (or (and a!64 (< 0.0 (- r.k-1.y 0.0)))
                (and a!64 (> 0.0 (- r.k-1.y 0.0)))))
      (a!75 (+ a!23 (* (- (- r.k-1.y 0.0) (- 4.0)) (- (- r.k-1.y 0.0) (- 4.0)))))
      (a!78 (or (and a!77 (< 0.0 (- r.k-2.y 0.0)))
                (and a!77 (> 0.0 (- r.k-2.y 0.0)))))
      (a!88 (+ a!26 (* (- (- r.k-2.y 0.0) (- 4.0)) (- (- r.k-2.y 0.0) (- 4.0)))))
      (a!91 (or (and a!90 (< 0.0 (- r.k-3.y 0.0)))
                (and a!90 (> 0.0 (- r.k-3.y 0.0)))))
      (a!101 (+ a!29
                (* (- (- r.k-3.y 0.0) (- 4.0)) (- (- r.k-3.y 0.0) (- 4.0))))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!6 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (or a!12
                (and a!13 (< 0.0 (- r.b.x 0.0)))
                (and a!13 (> 0.0 (- r.b.x 0.0)))))
      (a!21 (and (and a!18 (< 0.0 (- r.c.x 0.0))) (not a!20)))
      (a!34 (not (and (not (or a!33 a!33))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!35 (and (and a!32 (> 0.0 (- 0.0 0.0))) (not a!33)))
      (a!36 (not (and (not (or a!33 a!33))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!37 (and (and a!32 (< 0.0 (- 0.0 0.0))) (not a!33)))
      (a!38 (and (not (or a!33 a!33)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!44 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!50 (and (and a!13 (> 0.0 (- r.b.x 0.0))) (not a!12)))
      (a!52 (and (and a!13 (< 0.0 (- r.b.x 0.0))) (not a!12)))
      (a!56 (or a!20
                (and a!18 (< 0.0 (- r.c.x 0.0)))
                (and a!18 (> 0.0 (- r.c.x 0.0)))))
      (a!58 (and (and a!18 (> 0.0 (- r.c.x 0.0))) (not a!20)))
      (a!67 (or a!65
                (and a!66 (< 0.0 (- r.k-1.x 0.0)))
                (and a!66 (> 0.0 (- r.k-1.x 0.0)))))
      (a!69 (and (and a!66 (> 0.0 (- r.k-1.x 0.0))) (not a!65)))
      (a!71 (and (and a!66 (< 0.0 (- r.k-1.x 0.0))) (not a!65)))
      (a!80 (or a!78
                (and a!79 (< 0.0 (- r.k-2.x 0.0)))
                (and a!79 (> 0.0 (- r.k-2.x 0.0)))))
      (a!82 (and (and a!79 (> 0.0 (- r.k-2.x 0.0))) (not a!78)))
      (a!84 (and (and a!79 (< 0.0 (- r.k-2.x 0.0))) (not a!78)))
      (a!93 (or a!91
                (and a!92 (< 0.0 (- r.k-3.x 0.0)))
                (and a!92 (> 0.0 (- r.k-3.x 0.0)))))
      (a!95 (and (and a!92 (> 0.0 (- r.k-3.x 0.0))) (not a!91)))
      (a!97 (and (and a!92 (< 0.0 (- r.k-3.x 0.0))) (not a!91))))
(let ((a!7 (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!39 (or (and (not (or a!33 a!33))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                a!37
                a!38))
      (a!40 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!38))
      (a!43 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!45 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!49 (not (and (not a!14) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!51 (not (and (not a!14) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!53 (and (not a!14) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!57 (not (and (not a!56) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!59 (not (and (not a!56) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!60 (and (not a!56) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!68 (not (and (not a!67)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!70 (not (and (not a!67)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!72 (and (not a!67) (> 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!81 (not (and (not a!80)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!83 (not (and (not a!80)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!85 (and (not a!80) (> 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!94 (not (and (not a!93)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!96 (not (and (not a!93)
                      (< 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!98 (and (not a!93) (> 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))))
(let ((a!8 (or (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!6
               a!7))
      (a!42 (and a!34
                 (not a!35)
                 a!36
                 (=> a!39 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!40)
                 (not (> 4.0 a!41))))
      (a!46 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!7))
      (a!55 (and a!49
                 (not a!50)
                 a!51
                 (=> (or a!15 a!52 a!53) (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!53))
                 (not (> 4.0 a!54))))
      (a!61 (or (and (not a!56) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                a!21
                a!60))
      (a!73 (or (and (not a!67) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                a!71
                a!72))
      (a!74 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 a!72))
      (a!86 (or (and (not a!80) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                a!84
                a!85))
      (a!87 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 a!85))
      (a!99 (or (and (not a!93) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))
                a!97
                a!98))
      (a!100 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  a!98)))
(let ((a!48 (and a!43
                 (not a!44)
                 a!45
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!46)
                 (not (> 4.0 a!47))))
      (a!63 (and a!57
                 (not a!58)
                 a!59
                 (=> a!61 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!17 a!60))
                 (not (> 4.0 a!62))))
      (a!76 (and a!68
                 (not a!69)
                 a!70
                 (=> a!73 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!74)
                 (not (> 4.0 a!75))))
      (a!89 (and a!81
                 (not a!82)
                 a!83
                 (=> a!86 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not a!87)
                 (not (> 4.0 a!88))))
      (a!102 (and a!94
                  (not a!95)
                  a!96
                  (=> a!99 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  (not a!100)
                  (not (> 4.0 a!101)))))
(let ((a!103 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!8
                  (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                  a!9
                  a!10
                  a!15
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!16
                  a!17
                  a!21
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  a!22
                  (> 4.0 a!24)
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  a!25
                  (> 4.0 a!27)
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  a!28
                  (> 4.0 a!30)
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!31 a!42))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!48))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!9 a!55))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!16 a!63))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!22 a!76))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> a!25 a!89))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) (=> a!28 a!102)))))
  (=> r.case0 a!103)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
