; Obligation: rma-fixed, form on-rma, r's case scenario-3.up-4; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; candidates 1..3 up are blocked (witnesses k); candidate 4 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
               (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x))
                  (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))))
  (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x))
                  (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))))
  (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x))
                  (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))))
  (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) a!1)))
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
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!32 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!41 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 4.0) (- (- 0.0 0.0) 4.0))))
      (a!47 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 4.0) (- (- r.w.y 0.0) 4.0))))
      (a!55 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 4.0) (- (- r.c.y 0.0) 4.0))))
      (a!62 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 4.0) (- (- r.d.y 0.0) 4.0))))
      (a!64 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!66 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!77 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!79 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!90 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!92 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- r.c.y 0.0)))
                (and a!12 (> 0.0 (- r.c.y 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- r.d.y 0.0)))
                (and a!17 (> 0.0 (- r.d.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!27 (+ a!26 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!30 (+ a!29 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!33 (or (and a!32 (< 0.0 (- 0.0 0.0))) (and a!32 (> 0.0 (- 0.0 0.0)))))
      (a!65 (or (and a!64 (< 0.0 (- r.k+1.y 0.0)))
                (and a!64 (> 0.0 (- r.k+1.y 0.0)))))
      (a!75 (+ a!23 (* (- (- r.k+1.y 0.0) 4.0) (- (- r.k+1.y 0.0) 4.0))))
      (a!78 (or (and a!77 (< 0.0 (- r.k+2.y 0.0)))
                (and a!77 (> 0.0 (- r.k+2.y 0.0)))))
      (a!88 (+ a!26 (* (- (- r.k+2.y 0.0) 4.0) (- (- r.k+2.y 0.0) 4.0))))
      (a!91 (or (and a!90 (< 0.0 (- r.k+3.y 0.0)))
                (and a!90 (> 0.0 (- r.k+3.y 0.0)))))
      (a!101 (+ a!29 (* (- (- r.k+3.y 0.0) 4.0) (- (- r.k+3.y 0.0) 4.0)))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (and (and a!11 (< 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!20 (or a!18
                (and a!19 (< 0.0 (- r.d.x 0.0)))
                (and a!19 (> 0.0 (- r.d.x 0.0)))))
      (a!34 (not (and (not (or a!33 a!33))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!35 (and (and a!32 (> 0.0 (- 0.0 0.0))) (not a!33)))
      (a!36 (not (and (not (or a!33 a!33))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!37 (and (not (or a!33 a!33)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!38 (and (and a!32 (< 0.0 (- 0.0 0.0))) (not a!33)))
      (a!44 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!49 (or a!13
                (and a!11 (< 0.0 (- r.c.x 0.0)))
                (and a!11 (> 0.0 (- r.c.x 0.0)))))
      (a!51 (and (and a!11 (> 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!58 (and (and a!19 (> 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!61 (and (and a!19 (< 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!67 (or a!65
                (and a!66 (< 0.0 (- r.k+1.x 0.0)))
                (and a!66 (> 0.0 (- r.k+1.x 0.0)))))
      (a!69 (and (and a!66 (> 0.0 (- r.k+1.x 0.0))) (not a!65)))
      (a!72 (and (and a!66 (< 0.0 (- r.k+1.x 0.0))) (not a!65)))
      (a!80 (or a!78
                (and a!79 (< 0.0 (- r.k+2.x 0.0)))
                (and a!79 (> 0.0 (- r.k+2.x 0.0)))))
      (a!82 (and (and a!79 (> 0.0 (- r.k+2.x 0.0))) (not a!78)))
      (a!85 (and (and a!79 (< 0.0 (- r.k+2.x 0.0))) (not a!78)))
      (a!93 (or a!91
                (and a!92 (< 0.0 (- r.k+3.x 0.0)))
                (and a!92 (> 0.0 (- r.k+3.x 0.0)))))
      (a!95 (and (and a!92 (> 0.0 (- r.k+3.x 0.0))) (not a!91)))
      (a!98 (and (and a!92 (< 0.0 (- r.k+3.x 0.0))) (not a!91))))
(let ((a!6 (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!21 (and (not a!20) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!39 (or a!37
                a!38
                (and (not (or a!33 a!33))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!40 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!37))
      (a!43 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!45 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!50 (not (and (not a!49) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!52 (not (and (not a!49) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!53 (and (not a!49) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!57 (not (and (not a!20) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!59 (not (and (not a!20) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!60 (and (not a!20) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!68 (not (and (not a!67)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!70 (not (and (not a!67)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!71 (and (not a!67) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!81 (not (and (not a!80)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!83 (not (and (not a!80)
                      (< 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!84 (and (not a!80) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!94 (not (and (not a!93)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!96 (not (and (not a!93)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!97 (and (not a!93) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0)))))
(let ((a!8 (or a!6
               a!7
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!42 (and a!34
                 (not a!35)
                 a!36
                 (=> a!39 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!40)
                 (not (> 4.0 a!41))))
      (a!46 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!54 (or a!53
                a!14
                (and (not a!49) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!63 (and a!57
                 (not a!58)
                 a!59
                 (=> (or a!60 a!61 a!21) (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!16 a!60))
                 (not (> 4.0 a!62))))
      (a!73 (or a!71
                a!72
                (and (not a!67) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!74 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!71))
      (a!86 (or a!84
                a!85
                (and (not a!80) (> 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
      (a!87 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!84))
      (a!99 (or a!97
                a!98
                (and (not a!93) (> 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0)))))
      (a!100 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!97)))
(let ((a!48 (and a!43
                 (not a!44)
                 a!45
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!46)
                 (not (> 4.0 a!47))))
      (a!56 (and a!50
                 (not a!51)
                 a!52
                 (=> a!54 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!53))
                 (not (> 4.0 a!55))))
      (a!76 (and a!68
                 (not a!69)
                 a!70
                 (=> a!73 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!74)
                 (not (> 4.0 a!75))))
      (a!89 (and a!81
                 (not a!82)
                 a!83
                 (=> a!86 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!87)
                 (not (> 4.0 a!88))))
      (a!102 (and a!94
                  (not a!95)
                  a!96
                  (=> a!99 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!100)
                  (not (> 4.0 a!101)))))
(let ((a!103 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!31 a!42))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!48))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!9 a!56))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!15 a!63))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!22 a!76))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!25 a!89))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!28 a!102)))))
  (=> r.case0 a!103)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
