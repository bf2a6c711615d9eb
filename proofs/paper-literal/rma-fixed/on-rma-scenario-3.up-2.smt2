; Obligation: rma-fixed, form on-rma, r's case scenario-3.up-2; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; candidates 1..1 up are blocked (witnesses k); candidate 2 up is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x))
                  (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))))
  (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x))
                  (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))))
  (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) a!1)))
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
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!26 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!35 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) 2.0) (- (- 0.0 0.0) 2.0))))
      (a!41 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) 2.0) (- (- r.w.y 0.0) 2.0))))
      (a!49 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) 2.0) (- (- r.c.y 0.0) 2.0))))
      (a!56 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) 2.0) (- (- r.d.y 0.0) 2.0))))
      (a!58 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!60 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!13 (or (and a!12 (< 0.0 (- r.c.y 0.0)))
                (and a!12 (> 0.0 (- r.c.y 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- r.d.y 0.0)))
                (and a!17 (> 0.0 (- r.d.y 0.0)))))
      (a!24 (+ a!23 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!27 (or (and a!26 (< 0.0 (- 0.0 0.0))) (and a!26 (> 0.0 (- 0.0 0.0)))))
      (a!59 (or (and a!58 (< 0.0 (- r.k+1.y 0.0)))
                (and a!58 (> 0.0 (- r.k+1.y 0.0)))))
      (a!69 (+ a!23 (* (- (- r.k+1.y 0.0) 2.0) (- (- r.k+1.y 0.0) 2.0)))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!14 (and (and a!11 (< 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!20 (or a!18
                (and a!19 (< 0.0 (- r.d.x 0.0)))
                (and a!19 (> 0.0 (- r.d.x 0.0)))))
      (a!28 (not (and (not (or a!27 a!27))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!29 (and (and a!26 (> 0.0 (- 0.0 0.0))) (not a!27)))
      (a!30 (not (and (not (or a!27 a!27))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!31 (and (not (or a!27 a!27)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!32 (and (and a!26 (< 0.0 (- 0.0 0.0))) (not a!27)))
      (a!38 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!43 (or a!13
                (and a!11 (< 0.0 (- r.c.x 0.0)))
                (and a!11 (> 0.0 (- r.c.x 0.0)))))
      (a!45 (and (and a!11 (> 0.0 (- r.c.x 0.0))) (not a!13)))
      (a!52 (and (and a!19 (> 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!55 (and (and a!19 (< 0.0 (- r.d.x 0.0))) (not a!18)))
      (a!61 (or a!59
                (and a!60 (< 0.0 (- r.k+1.x 0.0)))
                (and a!60 (> 0.0 (- r.k+1.x 0.0)))))
      (a!63 (and (and a!60 (> 0.0 (- r.k+1.x 0.0))) (not a!59)))
      (a!66 (and (and a!60 (< 0.0 (- r.k+1.x 0.0))) (not a!59))))
(let ((a!6 (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!21 (and (not a!20) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!33 (or a!31
                a!32
                (and (not (or a!27 a!27))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!34 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!31))
      (a!37 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!39 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!44 (not (and (not a!43) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!46 (not (and (not a!43) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!47 (and (not a!43) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!51 (not (and (not a!20) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!53 (not (and (not a!20) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!54 (and (not a!20) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!62 (not (and (not a!61)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!64 (not (and (not a!61)
                      (< 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!65 (and (not a!61) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
(let ((a!8 (or a!6
               a!7
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!36 (and a!28
                 (not a!29)
                 a!30
                 (=> a!33 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!34)
                 (not (> 4.0 a!35))))
      (a!40 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!48 (or a!47
                a!14
                (and (not a!43) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!57 (and a!51
                 (not a!52)
                 a!53
                 (=> (or a!54 a!55 a!21) (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!16 a!54))
                 (not (> 4.0 a!56))))
      (a!67 (or a!65
                a!66
                (and (not a!61) (> 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))))
      (a!68 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!65)))
(let ((a!42 (and a!37
                 (not a!38)
                 a!39
                 (=> a!8 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!40)
                 (not (> 4.0 a!41))))
      (a!50 (and a!44
                 (not a!45)
                 a!46
                 (=> a!48 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!10 a!47))
                 (not (> 4.0 a!49))))
      (a!70 (and a!62
                 (not a!63)
                 a!64
                 (=> a!67 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!68)
                 (not (> 4.0 a!69)))))
(let ((a!71 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                 true
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!25 a!36))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!42))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!9 a!50))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!15 a!57))
                 (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!22 a!70)))))
  (=> r.case0 a!71)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.k+1.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
(check-sat)
