; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 9; cuts: 81
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- r.w.x r.t.x) (- r.w.x r.t.x)) (* (- r.w.y r.t.y) (- r.w.y r.t.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- r.c.x r.t.x) (- r.c.x r.t.x)) (* (- r.c.y r.t.y) (- r.c.y r.t.y))))
; atom relaxed!32 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!55 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!65 (>= 16.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
(set-logic QF_LRA)
(declare-fun relaxed!3 () Bool)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun relaxed!8 () Bool)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun relaxed!13 () Bool)
(declare-fun r.t.y () Real)
(declare-fun r.t.x () Real)
(declare-fun relaxed!18 () Bool)
(declare-fun relaxed!23 () Bool)
(declare-fun relaxed!28 () Bool)
(declare-fun relaxed!65 () Bool)
(declare-fun relaxed!55 () Bool)
(declare-fun relaxed!32 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) relaxed!13))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!18))
(assert (or (and (= r.w.x r.t.x) (= r.w.y r.t.y)) relaxed!23))
(assert (or (and (= r.c.x r.t.x) (= r.c.y r.t.y)) relaxed!28))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!8 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!9 (and (> (- r.t.x 0.0) (- 2.0)) (> 2.0 (- r.t.x 0.0))))
      (a!10 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!18 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!24 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!27 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!37 (and (> (- r.t.y 0.0) (- 2.0)) (> 2.0 (- r.t.y 0.0))))
      (a!45 (and (> (- (- r.t.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.t.x 0.0) (- r.w.x 0.0))))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (or (and a!10 (< 0.0 (- 0.0 0.0))) (and a!10 (> 0.0 (- 0.0 0.0)))))
      (a!13 (not (and a!10 (> 0.0 (- 0.0 0.0)))))
      (a!19 (=> (and a!10 (> 0.0 (- 0.0 0.0))) (<= (- 0.0 0.0) (- r.t.y 0.0))))
      (a!22 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!25 (=> (and a!1 (> 0.0 (- r.w.y 0.0)))
                (<= (- r.w.y 0.0) (- r.t.y 0.0))))
      (a!28 (or (and a!27 (< 0.0 (- r.c.y 0.0)))
                (and a!27 (> 0.0 (- r.c.y 0.0)))
                (and a!8 (< 0.0 (- r.c.x 0.0)))
                (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!30 (not (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!35 (=> (and a!27 (> 0.0 (- r.c.y 0.0)))
                (<= (- r.c.y 0.0) (- r.t.y 0.0))))
      (a!38 (or (and a!9 (< 0.0 (- r.t.y 0.0)))
                (and a!9 (> 0.0 (- r.t.y 0.0)))
                (and a!37 (< 0.0 (- r.t.x 0.0)))
                (and a!37 (> 0.0 (- r.t.x 0.0)))))
      (a!40 (not (and a!37 (> 0.0 (- r.t.x 0.0)))))
      (a!46 (=> (and a!9 (> 0.0 (- r.t.y 0.0)))
                (<= (- r.t.y 0.0) (- r.t.y 0.0)))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!5 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!12 (not (and (not (or a!11 a!11))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!14 (not (and (not (or a!11 a!11))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!15 (and (not (or a!11 a!11)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!16 (and (not (or a!11 a!11)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!21 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!23 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!29 (not (and (not a!28) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!31 (not (and (not a!28) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!32 (and (not a!28) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!33 (and (not a!28) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0))))
      (a!39 (not (and (not a!38) (> 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))))
      (a!41 (not (and (not a!38) (> 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!42 (and (not a!38) (< 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0))))
      (a!43 (and (not a!38) (< 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
(let ((a!6 (or a!4 (and a!2 (< 0.0 (- r.w.x 0.0))) a!5))
      (a!17 (or a!15 (and a!10 (< 0.0 (- 0.0 0.0))) a!16))
      (a!34 (or a!32 (and a!8 (< 0.0 (- r.c.x 0.0))) a!33))
      (a!44 (or a!42 (and a!37 (< 0.0 (- r.t.x 0.0))) a!43)))
(let ((a!20 (and a!12
                 a!13
                 a!14
                 (=> a!17 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!18 a!15))
                 (not (and a!18 a!16))
                 a!19))
      (a!26 (and a!21
                 a!22
                 a!23
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!24 a!4))
                 (not (and a!24 a!5))
                 a!25))
      (a!36 (and a!29
                 a!30
                 a!31
                 (=> a!34 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!7 a!32))
                 (not (and a!7 a!33))
                 a!35))
      (a!47 (and a!39
                 a!40
                 a!41
                 (=> a!44 (>= (- r.t.x 0.0) (- r.w.x 0.0)))
                 (not (and a!45 a!42))
                 (not (and a!45 a!43))
                 a!46)))
(let ((a!48 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 relaxed!32
                 a!6
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 relaxed!55
                 a!7
                 (and a!8 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.t.x) (= 0.0 r.t.y)))
                 relaxed!65
                 (and a!9 (> 0.0 (- r.t.y 0.0)))
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!20))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!32 a!26))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!55 a!36))
                 (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) (=> relaxed!65 a!47)))))
  (=> r.case0 a!48))))))))
(assert (or r.case0))
(assert (and (< 0.0 (+ 0.0 0.0))
     (or (and (= 0.0 r.w.x) (= 0.0 r.w.y))
         (not relaxed!32)
         (< r.w.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.c.x) (= 0.0 r.c.y))
         (not relaxed!55)
         (< r.c.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.t.x) (= 0.0 r.t.y))
         (not relaxed!65)
         (< r.t.x (+ 0.0 0.0)))))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!3)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!8)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!13)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!18)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* 1.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* (- 1.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 9.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 8.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* 1.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* (- 1.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 9.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 8.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!32 a!1)))
; cut relaxed!32
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!32) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!55 a!1)))
; cut relaxed!55
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!55) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!65 a!1)))
; cut relaxed!65
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0)))) (=> (not relaxed!65) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
(check-sat)
