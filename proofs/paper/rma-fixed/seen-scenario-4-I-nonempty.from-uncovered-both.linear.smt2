; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 18; cuts: 180
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x)) (* (- r.w.y r.b.y) (- r.w.y r.b.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x)) (* (- r.w.y r.d.y) (- r.w.y r.d.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- r.w.x r.t.x) (- r.w.x r.t.x)) (* (- r.w.y r.t.y) (- r.w.y r.t.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x)) (* (- r.b.y r.c.y) (- r.b.y r.c.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.b.x r.d.x) (- r.b.x r.d.x)) (* (- r.b.y r.d.y) (- r.b.y r.d.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.b.x r.t.x) (- r.b.x r.t.x)) (* (- r.b.y r.t.y) (- r.b.y r.t.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x)) (* (- r.c.y r.d.y) (- r.c.y r.d.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.c.x r.t.x) (- r.c.x r.t.x)) (* (- r.c.y r.t.y) (- r.c.y r.t.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.d.x r.t.x) (- r.d.x r.t.x)) (* (- r.d.y r.t.y) (- r.d.y r.t.y))))
; atom relaxed!77 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!100 (>= 16.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!124 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!134 (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!158 (>= 16.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
(set-logic QF_LRA)
(declare-fun relaxed!3 () Bool)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun relaxed!8 () Bool)
(declare-fun r.b.y () Real)
(declare-fun r.b.x () Real)
(declare-fun relaxed!13 () Bool)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun relaxed!18 () Bool)
(declare-fun r.d.y () Real)
(declare-fun r.d.x () Real)
(declare-fun relaxed!23 () Bool)
(declare-fun r.t.y () Real)
(declare-fun r.t.x () Real)
(declare-fun relaxed!28 () Bool)
(declare-fun relaxed!33 () Bool)
(declare-fun relaxed!38 () Bool)
(declare-fun relaxed!43 () Bool)
(declare-fun relaxed!48 () Bool)
(declare-fun relaxed!53 () Bool)
(declare-fun relaxed!58 () Bool)
(declare-fun relaxed!63 () Bool)
(declare-fun relaxed!68 () Bool)
(declare-fun relaxed!73 () Bool)
(declare-fun relaxed!158 () Bool)
(declare-fun relaxed!134 () Bool)
(declare-fun relaxed!124 () Bool)
(declare-fun relaxed!100 () Bool)
(declare-fun relaxed!77 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) relaxed!8))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!13))
(assert (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) relaxed!18))
(assert (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) relaxed!23))
(assert (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) relaxed!28))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!33))
(assert (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) relaxed!38))
(assert (or (and (= r.w.x r.t.x) (= r.w.y r.t.y)) relaxed!43))
(assert (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) relaxed!48))
(assert (or (and (= r.b.x r.d.x) (= r.b.y r.d.y)) relaxed!53))
(assert (or (and (= r.b.x r.t.x) (= r.b.y r.t.y)) relaxed!58))
(assert (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) relaxed!63))
(assert (or (and (= r.c.x r.t.x) (= r.c.y r.t.y)) relaxed!68))
(assert (or (and (= r.d.x r.t.x) (= r.d.y r.t.y)) relaxed!73))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!5 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!6 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!9 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!10 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!11 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!14 (and (> (- r.t.x 0.0) (- 2.0)) (> 2.0 (- r.t.x 0.0))))
      (a!15 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!34 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!48 (and (> (- r.t.y 0.0) (- 2.0)) (> 2.0 (- r.t.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!7 (or (and a!5 (< 0.0 (- r.b.y 0.0)))
               (and a!5 (> 0.0 (- r.b.y 0.0)))
               (and a!6 (< 0.0 (- r.b.x 0.0)))
               (and a!6 (> 0.0 (- r.b.x 0.0)))))
      (a!12 (or (and a!10 (< 0.0 (- r.d.y 0.0)))
                (and a!10 (> 0.0 (- r.d.y 0.0)))
                (and a!11 (< 0.0 (- r.d.x 0.0)))
                (and a!11 (> 0.0 (- r.d.x 0.0)))))
      (a!16 (or (and a!15 (< 0.0 (- 0.0 0.0))) (and a!15 (> 0.0 (- 0.0 0.0)))))
      (a!18 (not (and a!15 (> 0.0 (- 0.0 0.0)))))
      (a!21 (=> (and a!15 (> 0.0 (- 0.0 0.0))) (<= (- 0.0 0.0) (- r.t.y 0.0))))
      (a!24 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!26 (=> (and a!1 (> 0.0 (- r.w.y 0.0)))
                (<= (- r.w.y 0.0) (- r.t.y 0.0))))
      (a!29 (not (and a!6 (> 0.0 (- r.b.x 0.0)))))
      (a!32 (=> (and a!5 (> 0.0 (- r.b.y 0.0)))
                (<= (- r.b.y 0.0) (- r.t.y 0.0))))
      (a!35 (or (and a!34 (< 0.0 (- r.c.y 0.0)))
                (and a!34 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!37 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!40 (=> (and a!34 (> 0.0 (- r.c.y 0.0)))
                (<= (- r.c.y 0.0) (- r.t.y 0.0))))
      (a!43 (not (and a!11 (> 0.0 (- r.d.x 0.0)))))
      (a!46 (=> (and a!10 (> 0.0 (- r.d.y 0.0)))
                (<= (- r.d.y 0.0) (- r.t.y 0.0))))
      (a!49 (or (and a!14 (< 0.0 (- r.t.y 0.0)))
                (and a!14 (> 0.0 (- r.t.y 0.0)))
                (and a!48 (< 0.0 (- r.t.x 0.0)))
                (and a!48 (> 0.0 (- r.t.x 0.0)))))
      (a!51 (not (and a!48 (> 0.0 (- r.t.x 0.0)))))
      (a!54 (=> (and a!14 (> 0.0 (- r.t.y 0.0)))
                (<= (- r.t.y 0.0) (- r.t.y 0.0)))))
(let ((a!4 (or (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!8 (and (not a!7) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!13 (and (not a!12) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!17 (not (and (not (or a!16 a!16))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!19 (not (and (not (or a!16 a!16))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!20 (or (and (not (or a!16 a!16))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!15 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!16 a!16))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!23 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!25 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!28 (not (and (not a!7) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!30 (not (and (not a!7) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!36 (not (and (not a!35) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!38 (not (and (not a!35) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!39 (or (and (not a!35) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!35) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!42 (not (and (not a!12) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!44 (not (and (not a!12) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!50 (not (and (not a!49) (> 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))))
      (a!52 (not (and (not a!49) (> 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!53 (or (and (not a!49) (< 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))
                (and a!48 (< 0.0 (- r.t.x 0.0)))
                (and (not a!49) (< 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0))))))
(let ((a!22 (and a!17 a!18 a!19 (=> a!20 (>= (- 0.0 0.0) (- r.w.x 0.0))) a!21))
      (a!27 (and a!23 a!24 a!25 (=> a!4 (>= (- r.w.x 0.0) (- r.w.x 0.0))) a!26))
      (a!31 (or a!8
                (and a!6 (< 0.0 (- r.b.x 0.0)))
                (and (not a!7) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!41 (and a!36 a!37 a!38 (=> a!39 (>= (- r.c.x 0.0) (- r.w.x 0.0))) a!40))
      (a!45 (or (and (not a!12) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                (and a!11 (< 0.0 (- r.d.x 0.0)))
                a!13))
      (a!55 (and a!50 a!51 a!52 (=> a!53 (>= (- r.t.x 0.0) (- r.w.x 0.0))) a!54)))
(let ((a!33 (and a!28 a!29 a!30 (=> a!31 (>= (- r.b.x 0.0) (- r.w.x 0.0))) a!32))
      (a!47 (and a!42 a!43 a!44 (=> a!45 (>= (- r.d.x 0.0) (- r.w.x 0.0))) a!46)))
(let ((a!56 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 relaxed!77
                 a!4
                 (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                 relaxed!100
                 (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!8
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 relaxed!124
                 (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))
                 (and a!9 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                 relaxed!134
                 (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!13
                 (not (and (= 0.0 r.t.x) (= 0.0 r.t.y)))
                 relaxed!158
                 (and a!14 (> 0.0 (- r.t.y 0.0)))
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!22))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!77 a!27))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> relaxed!100 a!33))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!124 a!41))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> relaxed!134 a!47))
                 (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) (=> relaxed!158 a!55)))))
  (=> r.case0 a!56))))))))
(assert (or r.case0))
(assert (and (< 0.0 (+ 0.0 0.0))
     (or (and (= 0.0 r.w.x) (= 0.0 r.w.y))
         (not relaxed!77)
         (< r.w.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.b.x) (= 0.0 r.b.y))
         (not relaxed!100)
         (< r.b.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.c.x) (= 0.0 r.c.y))
         (not relaxed!124)
         (< r.c.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.d.x) (= 0.0 r.d.y))
         (not relaxed!134)
         (< r.d.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.t.x) (= 0.0 r.t.y))
         (not relaxed!158)
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 2.0))) (=> (not relaxed!8) a!1)))
; cut relaxed!8
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!8)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!13)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!18)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* 1.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* (- 1.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 9.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 8.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* 1.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* (- 1.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 9.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 8.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* 1.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* (- 1.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 9.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 8.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* 1.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* (- 1.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 9.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 8.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.d.x)) (* 0.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.d.x)) (* (/ 4.0 5.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.d.x)) (* 1.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.d.x)) (* (/ 3.0 5.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.d.x)) (* 0.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.d.x)) (* (- 1.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.d.x)) (* (/ 4.0 5.0) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.d.x)) (* (/ 9.0 5.0) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.d.x)) (* (/ 8.0 5.0) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.d.x)) (* (/ 3.0 5.0) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.t.x)) (* 0.0 (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.t.x)) (* (/ 4.0 5.0) (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.t.x)) (* 1.0 (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.t.x)) (* (/ 3.0 5.0) (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.t.x)) (* 0.0 (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.t.x)) (* (- 1.0) (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.t.x)) (* (/ 4.0 5.0) (- r.b.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.t.x)) (* (/ 9.0 5.0) (- r.b.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.t.x)) (* (/ 8.0 5.0) (- r.b.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.t.x)) (* (/ 3.0 5.0) (- r.b.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* 1.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* (- 1.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 9.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 8.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* 1.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* (- 1.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 9.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 8.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.t.x)) (* 0.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.t.x)) (* (/ 4.0 5.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.t.x)) (* 1.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.t.x)) (* (/ 3.0 5.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.t.x)) (* 0.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.t.x)) (* (- 1.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.t.x)) (* (/ 4.0 5.0) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.t.x)) (* (/ 9.0 5.0) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.t.x)) (* (/ 8.0 5.0) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.t.x)) (* (/ 3.0 5.0) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!77 a!1)))
; cut relaxed!77
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!77) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0)))) (=> (not relaxed!100) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!124 a!1)))
; cut relaxed!124
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!124) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0)))) (=> (not relaxed!134) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!158 a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0)))) (=> (not relaxed!158) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
(check-sat)
