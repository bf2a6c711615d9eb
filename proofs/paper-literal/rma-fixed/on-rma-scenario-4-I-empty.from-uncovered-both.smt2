; Obligation: rma-fixed, form on-rma, r's case scenario-4-I-empty.from-uncovered-both; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b, c, d in R_psi n B, C, D; universal: no visible robot in I.
; Named robots: r, r.w, r.b, r.c, r.d (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.d.y () Real)
(declare-fun r.d.x () Real)
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
               (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                  (* (- 0.0 r.d.y) (- 0.0 r.d.y))))))
  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x))
                  (* (- r.w.y r.b.y) (- r.w.y r.b.y))))))
  (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x))
                  (* (- r.w.y r.c.y) (- r.w.y r.c.y))))))
  (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x))
                  (* (- r.w.y r.d.y) (- r.w.y r.d.y))))))
  (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.d.x) (- r.b.x r.d.x))
                  (* (- r.b.y r.d.y) (- r.b.y r.d.y))))))
  (or (and (= r.b.x r.d.x) (= r.b.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!4 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!8 (>= 16.0
               (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x))
                  (* (- 0.0 r.b.y) (- 0.0 r.b.y)))))
      (a!9 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!11 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!14 (>= 16.0
                (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                   (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!15 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!16 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!19 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!20 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!22 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!25 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!26 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!10 (or (and a!9 (< 0.0 (- r.b.y 0.0))) (and a!9 (> 0.0 (- r.b.y 0.0)))))
      (a!17 (or (and a!16 (< 0.0 (- r.c.y 0.0)))
                (and a!16 (> 0.0 (- r.c.y 0.0)))))
      (a!21 (or (and a!20 (< 0.0 (- r.d.y 0.0)))
                (and a!20 (> 0.0 (- r.d.y 0.0)))))
      (a!27 (or (and a!26 (< 0.0 (- 0.0 0.0))) (and a!26 (> 0.0 (- 0.0 0.0)))))
      (a!33 (not (and a!26 (> 0.0 (- 0.0 0.0)))))
      (a!38 (not (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!45 (not (and a!9 (> 0.0 (- r.b.y 0.0)))))
      (a!52 (not (and a!16 (> 0.0 (- r.c.y 0.0)))))
      (a!59 (not (and a!20 (> 0.0 (- r.d.y 0.0))))))
(let ((a!5 (or a!3
               (and a!4 (< 0.0 (- r.w.x 0.0)))
               (and a!4 (> 0.0 (- r.w.x 0.0)))))
      (a!6 (and (and a!4 (< 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!12 (or a!10
                (and a!11 (< 0.0 (- r.b.x 0.0)))
                (and a!11 (> 0.0 (- r.b.x 0.0)))))
      (a!18 (and (and a!15 (< 0.0 (- r.c.x 0.0))) (not a!17)))
      (a!23 (or a!21
                (and a!22 (< 0.0 (- r.d.x 0.0)))
                (and a!22 (> 0.0 (- r.d.x 0.0)))))
      (a!28 (not (and (not (or a!27 a!27))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!29 (and (and a!26 (> 0.0 (- 0.0 0.0))) (not a!27)))
      (a!30 (not (and (not (or a!27 a!27))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!31 (and (and a!26 (< 0.0 (- 0.0 0.0))) (not a!27)))
      (a!36 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!41 (and (and a!11 (> 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!43 (and (and a!11 (< 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!47 (or a!17
                (and a!15 (< 0.0 (- r.c.x 0.0)))
                (and a!15 (> 0.0 (- r.c.x 0.0)))))
      (a!49 (and (and a!15 (> 0.0 (- r.c.x 0.0))) (not a!17)))
      (a!55 (and (and a!22 (> 0.0 (- r.d.x 0.0))) (not a!21)))
      (a!57 (and (and a!22 (< 0.0 (- r.d.x 0.0))) (not a!21))))
(let ((a!7 (or (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!6
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!13 (and (not a!12) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!24 (and (not a!23) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!32 (or (and (not (or a!27 a!27))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                a!31
                (and (not (or a!27 a!27))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!35 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!37 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!40 (not (and (not a!12) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!42 (not (and (not a!12) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!48 (not (and (not a!47) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!50 (not (and (not a!47) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!51 (or (and (not a!47) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                a!18
                (and (not a!47) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!54 (not (and (not a!23) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!56 (not (and (not a!23) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))))
(let ((a!34 (and a!28
                 (not a!29)
                 a!30
                 (=> a!32 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 a!33))
      (a!39 (and a!35
                 (not a!36)
                 a!37
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!38))
      (a!44 (or a!13
                a!43
                (and (not a!12) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!53 (and a!48
                 (not a!49)
                 a!50
                 (=> a!51 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 a!52))
      (a!58 (or (and (not a!23) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                a!57
                a!24)))
(let ((a!46 (and a!40
                 (not a!41)
                 a!42
                 (=> a!44 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!45))
      (a!60 (and a!54
                 (not a!55)
                 a!56
                 (=> a!58 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!59)))
(let ((a!61 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 a!1
                 a!7
                 (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                 a!8
                 (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!13
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 a!14
                 (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))
                 a!18
                 (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                 a!19
                 (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!24
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!25 a!34))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!39))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!8 a!46))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!14 a!53))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!19 a!60)))))
  (=> r.case0 a!61)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (distinct 0.0 (+ 0.0 0.0))))
(check-sat)
