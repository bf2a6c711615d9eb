; Obligation: rma-fixed, form on-rma, r's case scenario-4-I-nonempty.from-uncovered-both; model paper-literal, scheduler ssync.
; Claim: whenever r decides this case, r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis).
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses b, c, d in R_psi n B, C, D; witness t: the highest visible robot of I; universal: no visible I robot above it.
; Named robots: r, r.w, r.b, r.c, r.d, r.t (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.t.y () Real)
(declare-fun r.t.x () Real)
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
               (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x))
                  (* (- 0.0 r.t.y) (- 0.0 r.t.y))))))
  (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) a!1)))
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
               (+ (* (- r.w.x r.t.x) (- r.w.x r.t.x))
                  (* (- r.w.y r.t.y) (- r.w.y r.t.y))))))
  (or (and (= r.w.x r.t.x) (= r.w.y r.t.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x))
                  (* (- r.b.y r.c.y) (- r.b.y r.c.y))))))
  (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.d.x) (- r.b.x r.d.x))
                  (* (- r.b.y r.d.y) (- r.b.y r.d.y))))))
  (or (and (= r.b.x r.d.x) (= r.b.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.b.x r.t.x) (- r.b.x r.t.x))
                  (* (- r.b.y r.t.y) (- r.b.y r.t.y))))))
  (or (and (= r.b.x r.t.x) (= r.b.y r.t.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x))
                  (* (- r.c.y r.d.y) (- r.c.y r.d.y))))))
  (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.c.x r.t.x) (- r.c.x r.t.x))
                  (* (- r.c.y r.t.y) (- r.c.y r.t.y))))))
  (or (and (= r.c.x r.t.x) (= r.c.y r.t.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.d.x r.t.x) (- r.d.x r.t.x))
                  (* (- r.d.y r.t.y) (- r.d.y r.t.y))))))
  (or (and (= r.d.x r.t.x) (= r.d.y r.t.y)) a!1)))
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
                (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x))
                   (* (- 0.0 r.t.y) (- 0.0 r.t.y)))))
      (a!26 (and (> (- r.t.x 0.0) (- 2.0)) (> 2.0 (- r.t.x 0.0))))
      (a!27 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!28 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!64 (and (> (- r.t.y 0.0) (- 2.0)) (> 2.0 (- r.t.y 0.0)))))
(let ((a!3 (or (and a!2 (< 0.0 (- r.w.y 0.0))) (and a!2 (> 0.0 (- r.w.y 0.0)))))
      (a!10 (or (and a!9 (< 0.0 (- r.b.y 0.0))) (and a!9 (> 0.0 (- r.b.y 0.0)))))
      (a!17 (or (and a!16 (< 0.0 (- r.c.y 0.0)))
                (and a!16 (> 0.0 (- r.c.y 0.0)))))
      (a!21 (or (and a!20 (< 0.0 (- r.d.y 0.0)))
                (and a!20 (> 0.0 (- r.d.y 0.0)))))
      (a!29 (or (and a!28 (< 0.0 (- 0.0 0.0))) (and a!28 (> 0.0 (- 0.0 0.0)))))
      (a!35 (=> (and a!28 (> 0.0 (- 0.0 0.0))) (<= (- 0.0 0.0) (- r.t.y 0.0))))
      (a!40 (=> (and a!2 (> 0.0 (- r.w.y 0.0)))
                (<= (- r.w.y 0.0) (- r.t.y 0.0))))
      (a!47 (=> (and a!9 (> 0.0 (- r.b.y 0.0)))
                (<= (- r.b.y 0.0) (- r.t.y 0.0))))
      (a!54 (=> (and a!16 (> 0.0 (- r.c.y 0.0)))
                (<= (- r.c.y 0.0) (- r.t.y 0.0))))
      (a!61 (=> (and a!20 (> 0.0 (- r.d.y 0.0)))
                (<= (- r.d.y 0.0) (- r.t.y 0.0))))
      (a!63 (or (and a!26 (< 0.0 (- r.t.y 0.0)))
                (and a!26 (> 0.0 (- r.t.y 0.0)))))
      (a!71 (=> (and a!26 (> 0.0 (- r.t.y 0.0)))
                (<= (- r.t.y 0.0) (- r.t.y 0.0)))))
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
      (a!30 (not (and (not (or a!29 a!29))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!31 (and (and a!28 (> 0.0 (- 0.0 0.0))) (not a!29)))
      (a!32 (not (and (not (or a!29 a!29))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!33 (and (and a!28 (< 0.0 (- 0.0 0.0))) (not a!29)))
      (a!38 (and (and a!4 (> 0.0 (- r.w.x 0.0))) (not a!3)))
      (a!43 (and (and a!11 (> 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!45 (and (and a!11 (< 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!49 (or a!17
                (and a!15 (< 0.0 (- r.c.x 0.0)))
                (and a!15 (> 0.0 (- r.c.x 0.0)))))
      (a!51 (and (and a!15 (> 0.0 (- r.c.x 0.0))) (not a!17)))
      (a!57 (and (and a!22 (> 0.0 (- r.d.x 0.0))) (not a!21)))
      (a!59 (and (and a!22 (< 0.0 (- r.d.x 0.0))) (not a!21)))
      (a!65 (or a!63
                (and a!64 (< 0.0 (- r.t.x 0.0)))
                (and a!64 (> 0.0 (- r.t.x 0.0)))))
      (a!67 (and (and a!64 (> 0.0 (- r.t.x 0.0))) (not a!63)))
      (a!69 (and (and a!64 (< 0.0 (- r.t.x 0.0))) (not a!63))))
(let ((a!7 (or (and (not a!5) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!6
               (and (not a!5) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!13 (and (not a!12) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!24 (and (not a!23) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!34 (or (and (not (or a!29 a!29))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                a!33
                (and (not (or a!29 a!29))
                     (> 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))))
      (a!37 (not (and (not a!5) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!39 (not (and (not a!5) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!42 (not (and (not a!12) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!44 (not (and (not a!12) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!50 (not (and (not a!49) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!52 (not (and (not a!49) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!53 (or (and (not a!49) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                a!18
                (and (not a!49) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!56 (not (and (not a!23) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!58 (not (and (not a!23) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!66 (not (and (not a!65) (> 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!68 (not (and (not a!65) (< 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!70 (or (and (not a!65) (< 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))
                a!69
                (and (not a!65) (> 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0))))))
(let ((a!36 (and a!30
                 (not a!31)
                 a!32
                 (=> a!34 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 a!35))
      (a!41 (and a!37
                 (not a!38)
                 a!39
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!40))
      (a!46 (or a!13
                a!45
                (and (not a!12) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!55 (and a!50
                 (not a!51)
                 a!52
                 (=> a!53 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 a!54))
      (a!60 (or (and (not a!23) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                a!59
                a!24))
      (a!72 (and a!66
                 (not a!67)
                 a!68
                 (=> a!70 (>= (- r.t.x 0.0) (- r.w.x 0.0)))
                 a!71)))
(let ((a!48 (and a!42
                 (not a!43)
                 a!44
                 (=> a!46 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!47))
      (a!62 (and a!56
                 (not a!57)
                 a!58
                 (=> a!60 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!61)))
(let ((a!73 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
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
                 (not (and (= 0.0 r.t.x) (= 0.0 r.t.y)))
                 a!25
                 (and a!26 (> 0.0 (- r.t.y 0.0)))
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!27 a!36))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!41))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> a!8 a!48))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!14 a!55))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!19 a!62))
                 (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) (=> a!25 a!72)))))
  (=> r.case0 a!73)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.d.x)
     (>= 0.0 r.t.x)
     (distinct 0.0 (+ 0.0 0.0))))
(check-sat)
