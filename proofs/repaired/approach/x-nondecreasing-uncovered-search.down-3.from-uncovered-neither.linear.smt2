; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 13; cuts: 190
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!52 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!75 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!85 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!86 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!88 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!89 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!90 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!121 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) (- 3.0)) (- (- 0.0 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!140 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) (- 3.0)) (- (- r.w.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!172 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) (- 3.0)) (- (- r.c.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!212 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 3.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!252 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 3.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (> 4.0 a!1))
(set-logic QF_LRA)
(declare-fun relaxed!3 () Bool)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun relaxed!8 () Bool)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun relaxed!13 () Bool)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun relaxed!18 () Bool)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun relaxed!23 () Bool)
(declare-fun relaxed!28 () Bool)
(declare-fun relaxed!33 () Bool)
(declare-fun relaxed!38 () Bool)
(declare-fun relaxed!43 () Bool)
(declare-fun relaxed!48 () Bool)
(declare-fun relaxed!252 () Bool)
(declare-fun relaxed!88 () Bool)
(declare-fun relaxed!212 () Bool)
(declare-fun relaxed!85 () Bool)
(declare-fun relaxed!172 () Bool)
(declare-fun relaxed!75 () Bool)
(declare-fun relaxed!140 () Bool)
(declare-fun relaxed!52 () Bool)
(declare-fun relaxed!121 () Bool)
(declare-fun relaxed!90 () Bool)
(declare-fun relaxed!89 () Bool)
(declare-fun relaxed!86 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!18))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!23))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!28))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!33))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!38))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!43))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!48))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!8 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!9 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!17 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!22 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!24 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!33 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!34 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!42 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))))
      (a!44 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!45 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!53 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!10 (or (and a!9 (< 0.0 (- 0.0 0.0))) (and a!9 (> 0.0 (- 0.0 0.0)))))
      (a!12 (not (and a!9 (> 0.0 (- 0.0 0.0)))))
      (a!20 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!25 (or (and a!24 (< 0.0 (- r.c.y 0.0)))
                (and a!24 (> 0.0 (- r.c.y 0.0)))
                (and a!8 (< 0.0 (- r.c.x 0.0)))
                (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!27 (not (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!35 (or (and a!33 (< 0.0 (- r.k-1.y 0.0)))
                (and a!33 (> 0.0 (- r.k-1.y 0.0)))
                (and a!34 (< 0.0 (- r.k-1.x 0.0)))
                (and a!34 (> 0.0 (- r.k-1.x 0.0)))))
      (a!37 (not (and a!34 (> 0.0 (- r.k-1.x 0.0)))))
      (a!46 (or (and a!44 (< 0.0 (- r.k-2.y 0.0)))
                (and a!44 (> 0.0 (- r.k-2.y 0.0)))
                (and a!45 (< 0.0 (- r.k-2.x 0.0)))
                (and a!45 (> 0.0 (- r.k-2.x 0.0)))))
      (a!48 (not (and a!45 (> 0.0 (- r.k-2.x 0.0))))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!5 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!11 (not (and (not (or a!10 a!10))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!13 (not (and (not (or a!10 a!10))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!14 (and (not (or a!10 a!10)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!15 (and (not (or a!10 a!10)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!19 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!21 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!26 (not (and (not a!25) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!28 (not (and (not a!25) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!29 (and (not a!25) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!30 (and (not a!25) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0))))
      (a!36 (not (and (not a!35)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!38 (not (and (not a!35)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!39 (and (not a!35) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!40 (and (not a!35) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0))))
      (a!47 (not (and (not a!46)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!49 (not (and (not a!46)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!50 (and (not a!46) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!51 (and (not a!46) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
(let ((a!6 (or a!4 (and a!2 (< 0.0 (- r.w.x 0.0))) a!5))
      (a!16 (or a!14 (and a!9 (< 0.0 (- 0.0 0.0))) a!15))
      (a!31 (or a!29 (and a!8 (< 0.0 (- r.c.x 0.0))) a!30))
      (a!41 (or a!39 (and a!34 (< 0.0 (- r.k-1.x 0.0))) a!40))
      (a!52 (or a!50 (and a!45 (< 0.0 (- r.k-2.x 0.0))) a!51)))
(let ((a!18 (and a!11
                 a!12
                 a!13
                 (=> a!16 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!17 a!14))
                 (not (and a!17 a!15))
                 (not relaxed!121)))
      (a!23 (and a!19
                 a!20
                 a!21
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!22 a!4))
                 (not (and a!22 a!5))
                 (not relaxed!140)))
      (a!32 (and a!26
                 a!27
                 a!28
                 (=> a!31 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!7 a!29))
                 (not (and a!7 a!30))
                 (not relaxed!172)))
      (a!43 (and a!36
                 a!37
                 a!38
                 (=> a!41 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (and a!42 a!39))
                 (not (and a!42 a!40))
                 (not relaxed!212)))
      (a!54 (and a!47
                 a!48
                 a!49
                 (=> a!52 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not (and a!53 a!50))
                 (not (and a!53 a!51))
                 (not relaxed!252))))
(let ((a!55 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 relaxed!52
                 a!6
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 relaxed!75
                 a!7
                 (and a!8 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                 relaxed!85
                 relaxed!86
                 (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 relaxed!88
                 relaxed!89
                 relaxed!90
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!18))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!52 a!23))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!75 a!32))
                 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) (=> relaxed!85 a!43))
                 (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) (=> relaxed!88 a!54)))))
  (=> r.case0 a!55))))))))
(assert (or r.case0))
(assert (> 0.0 (+ 0.0 (- r.w.x 0.0))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!13)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!18)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!52 a!1)))
; cut relaxed!52
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!52) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!75 a!1)))
; cut relaxed!75
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!75) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!85 a!1)))
; cut relaxed!85
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!85) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!86
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!86 (<= a!1 2.0))))
; cut relaxed!86
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!86) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!88 a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!88) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!89
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!89 (<= a!1 2.0))))
; cut relaxed!89
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!89) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!90 a!1)))
; cut relaxed!90
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!90) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!121
(assert (not relaxed!121))
; cut relaxed!140
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) (- 3.0))) (* 0.0 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 3.0))) (* 1.0 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) (- 3.0))) (* 0.0 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 3.0))) (* (- 1.0) 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!140 (<= a!1 2.0))))
; cut relaxed!140
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!140) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!172
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!172 (<= a!1 2.0))))
; cut relaxed!172
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> (not relaxed!172) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!212
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!212 (<= a!1 2.0))))
; cut relaxed!212
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> (not relaxed!212) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> (not relaxed!252) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
