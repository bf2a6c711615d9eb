; Obligation: approach, form x-nondecreasing, r's case scenario-3.down-2-after-up; model paper-drop-touch, scheduler ssync.
; Claim: whenever r decides this case, r's move does not decrease its x.
; r's case: witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot in E u F u G, every visible B u C u D robot has x >= x_w; witnesses c in R_psi n C, d in R_psi n D; universal: no visible robot in R_psi n B; search up fails: each of its candidates 1..4 within view has a visible blocker (witnesses k); candidates 1..1 down are blocked (witnesses k); candidate 2 down is within the search bound; universal: it is vacant.
; Named robots: r, r.w, r.c, r.d, r.k+1, r.k+2, r.k+3, r.k+4, r.k-1 (r at the origin). Two names are one robot iff their centres are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot the decider sees.
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
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
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
               (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                  (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))))
  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) a!1)))
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
               (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x))
                  (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))))
  (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+3.x r.k-1.x) (- r.k+3.x r.k-1.x))
                  (* (- r.k+3.y r.k-1.y) (- r.k+3.y r.k-1.y))))))
  (or (and (= r.k+3.x r.k-1.x) (= r.k+3.y r.k-1.y)) a!1)))
(assert (let ((a!1 (<= 4.0
               (+ (* (- r.k+4.x r.k-1.x) (- r.k+4.x r.k-1.x))
                  (* (- r.k+4.y r.k-1.y) (- r.k+4.y r.k-1.y))))))
  (or (and (= r.k+4.x r.k-1.x) (= r.k+4.y r.k-1.y)) a!1)))
(assert (let ((a!1 (>= 16.0
               (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x))
                  (* (- 0.0 r.w.y) (- 0.0 r.w.y)))))
      (a!2 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (>= 16.0
               (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x))
                  (* (- 0.0 r.c.y) (- 0.0 r.c.y)))))
      (a!8 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!10 (>= 16.0
                (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x))
                   (* (- 0.0 r.d.y) (- 0.0 r.d.y)))))
      (a!11 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!12 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!13 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!16 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0))))
      (a!17 (>= 16.0
                (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x))
                   (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y)))))
      (a!18 (* (- (- r.k+1.x 0.0) (- r.w.x 0.0))
               (- (- r.k+1.x 0.0) (- r.w.x 0.0))))
      (a!21 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0))))
      (a!22 (>= 16.0
                (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x))
                   (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y)))))
      (a!23 (* (- (- r.k+2.x 0.0) (- r.w.x 0.0))
               (- (- r.k+2.x 0.0) (- r.w.x 0.0))))
      (a!26 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0))))
      (a!27 (>= 16.0
                (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x))
                   (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y)))))
      (a!28 (* (- (- r.k+3.x 0.0) (- r.w.x 0.0))
               (- (- r.k+3.x 0.0) (- r.w.x 0.0))))
      (a!31 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0))))
      (a!32 (>= 16.0
                (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x))
                   (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y)))))
      (a!33 (* (- (- r.k+4.x 0.0) (- r.w.x 0.0))
               (- (- r.k+4.x 0.0) (- r.w.x 0.0))))
      (a!36 (>= 16.0
                (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x))
                   (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y)))))
      (a!37 (* (- (- r.k-1.x 0.0) (- r.w.x 0.0))
               (- (- r.k-1.x 0.0) (- r.w.x 0.0))))
      (a!39 (>= 16.0
                (+ (* (- 0.0 0.0) (- 0.0 0.0)) (* (- 0.0 0.0) (- 0.0 0.0)))))
      (a!40 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!48 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0)))
               (* (- (- 0.0 0.0) (- 2.0)) (- (- 0.0 0.0) (- 2.0)))))
      (a!54 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0))
                  (- (- r.w.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.w.y 0.0) (- 2.0)) (- (- r.w.y 0.0) (- 2.0)))))
      (a!56 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!63 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0))
                  (- (- r.c.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.c.y 0.0) (- 2.0)) (- (- r.c.y 0.0) (- 2.0)))))
      (a!70 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0))
                  (- (- r.d.x 0.0) (- r.w.x 0.0)))
               (* (- (- r.d.y 0.0) (- 2.0)) (- (- r.d.y 0.0) (- 2.0)))))
      (a!72 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!73 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!83 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!84 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!94 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!95 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!105 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!106 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!116 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!117 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0)))))
(let ((a!4 (or (and a!2 (< 0.0 (- r.w.y 0.0)))
               (and a!2 (> 0.0 (- r.w.y 0.0)))
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!14 (or (and a!12 (< 0.0 (- r.d.y 0.0)))
                (and a!12 (> 0.0 (- r.d.y 0.0)))
                (and a!13 (< 0.0 (- r.d.x 0.0)))
                (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!19 (+ a!18 (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))
      (a!24 (+ a!23 (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))
      (a!29 (+ a!28 (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))
      (a!34 (+ a!33 (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))
      (a!38 (+ a!37 (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))
      (a!41 (or (and a!40 (< 0.0 (- 0.0 0.0))) (and a!40 (> 0.0 (- 0.0 0.0)))))
      (a!43 (not (and a!40 (> 0.0 (- 0.0 0.0)))))
      (a!51 (not (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!57 (or (and a!56 (< 0.0 (- r.c.y 0.0)))
                (and a!56 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!59 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!66 (not (and a!13 (> 0.0 (- r.d.x 0.0)))))
      (a!74 (or (and a!72 (< 0.0 (- r.k+1.y 0.0)))
                (and a!72 (> 0.0 (- r.k+1.y 0.0)))
                (and a!73 (< 0.0 (- r.k+1.x 0.0)))
                (and a!73 (> 0.0 (- r.k+1.x 0.0)))))
      (a!76 (not (and a!73 (> 0.0 (- r.k+1.x 0.0)))))
      (a!81 (+ a!18 (* (- (- r.k+1.y 0.0) (- 2.0)) (- (- r.k+1.y 0.0) (- 2.0)))))
      (a!85 (or (and a!83 (< 0.0 (- r.k+2.y 0.0)))
                (and a!83 (> 0.0 (- r.k+2.y 0.0)))
                (and a!84 (< 0.0 (- r.k+2.x 0.0)))
                (and a!84 (> 0.0 (- r.k+2.x 0.0)))))
      (a!87 (not (and a!84 (> 0.0 (- r.k+2.x 0.0)))))
      (a!92 (+ a!23 (* (- (- r.k+2.y 0.0) (- 2.0)) (- (- r.k+2.y 0.0) (- 2.0)))))
      (a!96 (or (and a!94 (< 0.0 (- r.k+3.y 0.0)))
                (and a!94 (> 0.0 (- r.k+3.y 0.0)))
                (and a!95 (< 0.0 (- r.k+3.x 0.0)))
                (and a!95 (> 0.0 (- r.k+3.x 0.0)))))
      (a!98 (not (and a!95 (> 0.0 (- r.k+3.x 0.0)))))
      (a!103 (+ a!28
                (* (- (- r.k+3.y 0.0) (- 2.0)) (- (- r.k+3.y 0.0) (- 2.0)))))
      (a!107 (or (and a!105 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!105 (> 0.0 (- r.k+4.y 0.0)))
                 (and a!106 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!106 (> 0.0 (- r.k+4.x 0.0)))))
      (a!109 (not (and a!106 (> 0.0 (- r.k+4.x 0.0)))))
      (a!114 (+ a!33
                (* (- (- r.k+4.y 0.0) (- 2.0)) (- (- r.k+4.y 0.0) (- 2.0)))))
      (a!118 (or (and a!116 (< 0.0 (- r.k-1.y 0.0)))
                 (and a!116 (> 0.0 (- r.k-1.y 0.0)))
                 (and a!117 (< 0.0 (- r.k-1.x 0.0)))
                 (and a!117 (> 0.0 (- r.k-1.x 0.0)))))
      (a!120 (not (and a!117 (> 0.0 (- r.k-1.x 0.0)))))
      (a!125 (+ a!37
                (* (- (- r.k-1.y 0.0) (- 2.0)) (- (- r.k-1.y 0.0) (- 2.0))))))
(let ((a!5 (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!15 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!20 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))) a!17 (> 4.0 a!19)))
      (a!25 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))) a!22 (> 4.0 a!24)))
      (a!30 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))) a!27 (> 4.0 a!29)))
      (a!35 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))) a!32 (> 4.0 a!34)))
      (a!42 (not (and (not (or a!41 a!41))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!44 (not (and (not (or a!41 a!41))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!45 (and (not (or a!41 a!41)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!50 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!52 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!58 (not (and (not a!57) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!60 (not (and (not a!57) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!61 (and (not a!57) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!65 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!67 (not (and (not a!14) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!68 (and (not a!14) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!75 (not (and (not a!74)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!77 (not (and (not a!74)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!78 (and (not a!74) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!86 (not (and (not a!85)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!88 (not (and (not a!85)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!89 (and (not a!85) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!97 (not (and (not a!96)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!99 (not (and (not a!96)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!100 (and (not a!96) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!108 (not (and (not a!107)
                       (> 0.0 (- r.k+4.x 0.0))
                       (< 0.0 (- r.k+4.y 0.0)))))
      (a!110 (not (and (not a!107)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!111 (and (not a!107) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!119 (not (and (not a!118)
                       (> 0.0 (- r.k-1.x 0.0))
                       (< 0.0 (- r.k-1.y 0.0)))))
      (a!121 (not (and (not a!118)
                       (> 0.0 (- r.k-1.x 0.0))
                       (> 0.0 (- r.k-1.y 0.0)))))
      (a!122 (and (not a!118) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))))
(let ((a!6 (or a!5
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!46 (or a!45
                (and a!40 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!41 a!41))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!47 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!45))
      (a!53 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!5))
      (a!62 (or a!61
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!57) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!69 (or a!68 (and a!13 (< 0.0 (- r.d.x 0.0))) a!15))
      (a!79 (or a!78
                (and a!73 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!74) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!80 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!78))
      (a!90 (or a!89
                (and a!84 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!85) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!91 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!89))
      (a!101 (or a!100
                 (and a!95 (< 0.0 (- r.k+3.x 0.0)))
                 (and (not a!96)
                      (< 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!102 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  a!100))
      (a!112 (or a!111
                 (and a!106 (< 0.0 (- r.k+4.x 0.0)))
                 (and (not a!107)
                      (< 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!113 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  a!111))
      (a!123 (or a!122
                 (and a!117 (< 0.0 (- r.k-1.x 0.0)))
                 (and (not a!118)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!124 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  a!122)))
(let ((a!49 (and a!42
                 a!43
                 a!44
                 (=> a!46 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!47)
                 (not (> 4.0 a!48))))
      (a!55 (and a!50
                 a!51
                 a!52
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!53)
                 (not (> 4.0 a!54))))
      (a!64 (and a!58
                 a!59
                 a!60
                 (=> a!62 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!61))
                 (not (> 4.0 a!63))))
      (a!71 (and a!65
                 a!66
                 a!67
                 (=> a!69 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!11 a!68))
                 (not (> 4.0 a!70))))
      (a!82 (and a!75
                 a!76
                 a!77
                 (=> a!79 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!80)
                 (not (> 4.0 a!81))))
      (a!93 (and a!86
                 a!87
                 a!88
                 (=> a!90 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!91)
                 (not (> 4.0 a!92))))
      (a!104 (and a!97
                  a!98
                  a!99
                  (=> a!101 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not a!102)
                  (not (> 4.0 a!103))))
      (a!115 (and a!108
                  a!109
                  a!110
                  (=> a!112 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not a!113)
                  (not (> 4.0 a!114))))
      (a!126 (and a!119
                  a!120
                  a!121
                  (=> a!123 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  (not a!124)
                  (not (> 4.0 a!125)))))
(let ((a!127 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  a!1
                  a!6
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  a!7
                  a!8
                  (and a!9 (< 0.0 (- r.c.x 0.0)))
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  a!10
                  a!11
                  a!15
                  (or (not a!16) a!20)
                  (or (not a!21) a!25)
                  (or (not a!26) a!30)
                  (or (not a!31) a!35)
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  a!36
                  (> 4.0 a!38)
                  a!21
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> a!39 a!49))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> a!1 a!55))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> a!7 a!64))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> a!10 a!71))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) (=> a!17 a!82))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) (=> a!22 a!93))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) (=> a!27 a!104))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) (=> a!32 a!115))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> a!36 a!126)))))
  (=> r.case0 a!127))))))))
(assert (or r.case0))
(assert (> 0.0 (+ 0.0 (- r.w.x 0.0))))
(check-sat)
