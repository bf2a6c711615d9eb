; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 18; cuts: 253
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x)) (* (- r.w.y r.d.y) (- r.w.y r.d.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x)) (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x)) (* (- r.c.y r.d.y) (- r.c.y r.d.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x)) (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x)) (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.d.x r.k+2.x) (- r.d.x r.k+2.x)) (* (- r.d.y r.k+2.y) (- r.d.y r.k+2.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x)) (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))
; atom relaxed!77 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!100 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!110 (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!134 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!135 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!137 (>= 16.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!138 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!139 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!168 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) 3.0) (- (- 0.0 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!185 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) 3.0) (- (- r.w.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!215 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) 3.0) (- (- r.c.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!231 (let ((a!1 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (- r.d.y 0.0) 3.0) (- (- r.d.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!269 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 3.0) (- (- r.k+1.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!307 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 3.0) (- (- r.k+2.y 0.0) 3.0))))) (> 4.0 a!1))
(set-logic QF_LRA)
(declare-fun relaxed!3 () Bool)
(declare-fun r.w.y () Real)
(declare-fun r.w.x () Real)
(declare-fun relaxed!8 () Bool)
(declare-fun r.c.y () Real)
(declare-fun r.c.x () Real)
(declare-fun relaxed!13 () Bool)
(declare-fun r.d.y () Real)
(declare-fun r.d.x () Real)
(declare-fun relaxed!18 () Bool)
(declare-fun r.k+1.y () Real)
(declare-fun r.k+1.x () Real)
(declare-fun relaxed!23 () Bool)
(declare-fun r.k+2.y () Real)
(declare-fun r.k+2.x () Real)
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
(declare-fun relaxed!307 () Bool)
(declare-fun relaxed!137 () Bool)
(declare-fun relaxed!269 () Bool)
(declare-fun relaxed!134 () Bool)
(declare-fun relaxed!231 () Bool)
(declare-fun relaxed!110 () Bool)
(declare-fun relaxed!215 () Bool)
(declare-fun relaxed!100 () Bool)
(declare-fun relaxed!185 () Bool)
(declare-fun relaxed!77 () Bool)
(declare-fun relaxed!168 () Bool)
(declare-fun relaxed!139 () Bool)
(declare-fun relaxed!138 () Bool)
(declare-fun relaxed!135 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) relaxed!13))
(assert (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) relaxed!18))
(assert (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) relaxed!23))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!28))
(assert (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) relaxed!33))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!38))
(assert (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) relaxed!43))
(assert (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) relaxed!48))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!53))
(assert (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) relaxed!58))
(assert (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) relaxed!63))
(assert (or (and (= r.d.x r.k+2.x) (= r.d.y r.k+2.y)) relaxed!68))
(assert (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) relaxed!73))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!6 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!7 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!8 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!10 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!13 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!27 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!41 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!42 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!51 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!52 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (or (and a!9 (< 0.0 (- r.d.y 0.0)))
                (and a!9 (> 0.0 (- r.d.y 0.0)))
                (and a!10 (< 0.0 (- r.d.x 0.0)))
                (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!14 (or (and a!13 (< 0.0 (- 0.0 0.0))) (and a!13 (> 0.0 (- 0.0 0.0)))))
      (a!16 (not (and a!13 (> 0.0 (- 0.0 0.0)))))
      (a!23 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!28 (or (and a!27 (< 0.0 (- r.c.y 0.0)))
                (and a!27 (> 0.0 (- r.c.y 0.0)))
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!30 (not (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!36 (not (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!43 (or (and a!41 (< 0.0 (- r.k+1.y 0.0)))
                (and a!41 (> 0.0 (- r.k+1.y 0.0)))
                (and a!42 (< 0.0 (- r.k+1.x 0.0)))
                (and a!42 (> 0.0 (- r.k+1.x 0.0)))))
      (a!45 (not (and a!42 (> 0.0 (- r.k+1.x 0.0)))))
      (a!53 (or (and a!51 (< 0.0 (- r.k+2.y 0.0)))
                (and a!51 (> 0.0 (- r.k+2.y 0.0)))
                (and a!52 (< 0.0 (- r.k+2.x 0.0)))
                (and a!52 (> 0.0 (- r.k+2.x 0.0)))))
      (a!55 (not (and a!52 (> 0.0 (- r.k+2.x 0.0))))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!12 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!15 (not (and (not (or a!14 a!14))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!17 (not (and (not (or a!14 a!14))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!18 (and (not (or a!14 a!14)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!22 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!24 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!29 (not (and (not a!28) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!31 (not (and (not a!28) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!32 (and (not a!28) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!35 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!37 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!38 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!44 (not (and (not a!43)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!46 (not (and (not a!43)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!47 (and (not a!43) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!54 (not (and (not a!53)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!56 (not (and (not a!53)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!57 (and (not a!53) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0)))))
(let ((a!5 (or a!4
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!19 (or a!18
                (and a!13 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!14 a!14))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!20 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!18))
      (a!25 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!4))
      (a!33 (or a!32
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and (not a!28) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!39 (or a!38 (and a!10 (< 0.0 (- r.d.x 0.0))) a!12))
      (a!48 (or a!47
                (and a!42 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!43) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!49 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!47))
      (a!58 (or a!57
                (and a!52 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!53) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!59 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!57)))
(let ((a!21 (and a!15
                 a!16
                 a!17
                 (=> a!19 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!20)
                 (not relaxed!168)))
      (a!26 (and a!22
                 a!23
                 a!24
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!25)
                 (not relaxed!185)))
      (a!34 (and a!29
                 a!30
                 a!31
                 (=> a!33 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!6 a!32))
                 (not relaxed!215)))
      (a!40 (and a!35
                 a!36
                 a!37
                 (=> a!39 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!38))
                 (not relaxed!231)))
      (a!50 (and a!44
                 a!45
                 a!46
                 (=> a!48 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!49)
                 (not relaxed!269)))
      (a!60 (and a!54
                 a!55
                 a!56
                 (=> a!58 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!59)
                 (not relaxed!307))))
(let ((a!61 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 relaxed!77
                 a!5
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 relaxed!100
                 a!6
                 (and a!7 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                 relaxed!110
                 a!8
                 a!12
                 (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                 relaxed!134
                 relaxed!135
                 (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                 relaxed!137
                 relaxed!138
                 relaxed!139
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!21))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!77 a!26))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!100 a!34))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> relaxed!110 a!40))
                 (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                     (=> relaxed!134 a!50))
                 (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                     (=> relaxed!137 a!60)))))
  (=> r.case0 a!61))))))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 2.0))) (=> (not relaxed!13) a!1)))
; cut relaxed!13
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!13)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!18)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* 1.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* (- 1.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 9.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 8.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* 1.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* (- 1.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 9.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 8.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* 1.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* (- 1.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 9.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 8.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* 1.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* (- 1.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 9.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 8.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* 1.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* (- 1.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 9.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 8.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* 1.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* (- 1.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 9.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 8.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* 1.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* (- 1.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 9.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 8.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* 1.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* (- 1.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!100 a!1)))
; cut relaxed!100
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!100) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!110 a!1)))
; cut relaxed!110
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0)))) (=> (not relaxed!110) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!134 a!1)))
; cut relaxed!134
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!134) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!135
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!135 (<= a!1 2.0))))
; cut relaxed!135
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!135) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!137 a!1)))
; cut relaxed!137
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0)))) (=> (not relaxed!137) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!138 (<= a!1 2.0))))
; cut relaxed!138
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> (not relaxed!138) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!139 a!1)))
; cut relaxed!139
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!139) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (not relaxed!168))
; cut relaxed!185
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) 3.0)) (* 0.0 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 3.0)) (* 1.0 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) 3.0)) (* 0.0 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 3.0)) (* (- 1.0) 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!185 (<= a!1 2.0))))
; cut relaxed!185
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!185) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!215
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!215 (<= a!1 2.0))))
; cut relaxed!215
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> (not relaxed!215) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!231
(assert (let ((a!1 (+ (* 1.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) 3.0))))) (=> relaxed!231 (<= a!1 2.0))))
; cut relaxed!231
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.d.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.d.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.d.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.d.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) 3.0))))) (=> (not relaxed!231) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!269
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!269 (<= a!1 2.0))))
; cut relaxed!269
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> (not relaxed!269) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!307
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!307 (<= a!1 2.0))))
; cut relaxed!307
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> (not relaxed!307) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
