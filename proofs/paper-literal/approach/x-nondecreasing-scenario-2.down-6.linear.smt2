; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 39; cuts: 514
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x)) (* (- r.w.y r.b.y) (- r.w.y r.b.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k-5.x) (- r.w.x r.k-5.x)) (* (- r.w.y r.k-5.y) (- r.w.y r.k-5.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x)) (* (- r.b.y r.c.y) (- r.b.y r.c.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x)) (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x)) (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x)) (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x)) (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.b.x r.k-5.x) (- r.b.x r.k-5.x)) (* (- r.b.y r.k-5.y) (- r.b.y r.k-5.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.c.x r.k-5.x) (- r.c.x r.k-5.x)) (* (- r.c.y r.k-5.y) (- r.c.y r.k-5.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.k-1.x r.k-5.x) (- r.k-1.x r.k-5.x)) (* (- r.k-1.y r.k-5.y) (- r.k-1.y r.k-5.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.k-2.x r.k-5.x) (- r.k-2.x r.k-5.x)) (* (- r.k-2.y r.k-5.y) (- r.k-2.y r.k-5.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.k-3.x r.k-5.x) (- r.k-3.x r.k-5.x)) (* (- r.k-3.y r.k-5.y) (- r.k-3.y r.k-5.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k-4.x r.k-5.x) (- r.k-4.x r.k-5.x)) (* (- r.k-4.y r.k-5.y) (- r.k-4.y r.k-5.y))))
; atom relaxed!182 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!207 (>= 16.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!231 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!251 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!252 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!254 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!255 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!257 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!258 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!260 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!261 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!263 (>= 16.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!264 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (> 4.0 a!1))
; atom relaxed!297 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) (- 6.0)) (- (- 0.0 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!315 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) (- 6.0)) (- (- r.w.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!334 (let ((a!1 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (- r.b.y 0.0) (- 6.0)) (- (- r.b.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!357 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) (- 6.0)) (- (- r.c.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!398 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 6.0)) (- (- r.k-1.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!439 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 6.0)) (- (- r.k-2.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!480 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 6.0)) (- (- r.k-3.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!521 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 6.0)) (- (- r.k-4.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!562 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 6.0)) (- (- r.k-5.y 0.0) (- 6.0)))))) (> 4.0 a!1))
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
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun relaxed!23 () Bool)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun relaxed!28 () Bool)
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun relaxed!33 () Bool)
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun relaxed!38 () Bool)
(declare-fun r.k-5.y () Real)
(declare-fun r.k-5.x () Real)
(declare-fun relaxed!43 () Bool)
(declare-fun relaxed!48 () Bool)
(declare-fun relaxed!53 () Bool)
(declare-fun relaxed!58 () Bool)
(declare-fun relaxed!63 () Bool)
(declare-fun relaxed!68 () Bool)
(declare-fun relaxed!73 () Bool)
(declare-fun relaxed!78 () Bool)
(declare-fun relaxed!83 () Bool)
(declare-fun relaxed!88 () Bool)
(declare-fun relaxed!93 () Bool)
(declare-fun relaxed!98 () Bool)
(declare-fun relaxed!103 () Bool)
(declare-fun relaxed!108 () Bool)
(declare-fun relaxed!113 () Bool)
(declare-fun relaxed!118 () Bool)
(declare-fun relaxed!123 () Bool)
(declare-fun relaxed!128 () Bool)
(declare-fun relaxed!133 () Bool)
(declare-fun relaxed!138 () Bool)
(declare-fun relaxed!143 () Bool)
(declare-fun relaxed!148 () Bool)
(declare-fun relaxed!153 () Bool)
(declare-fun relaxed!158 () Bool)
(declare-fun relaxed!163 () Bool)
(declare-fun relaxed!168 () Bool)
(declare-fun relaxed!173 () Bool)
(declare-fun relaxed!178 () Bool)
(declare-fun relaxed!562 () Bool)
(declare-fun relaxed!263 () Bool)
(declare-fun relaxed!521 () Bool)
(declare-fun relaxed!260 () Bool)
(declare-fun relaxed!480 () Bool)
(declare-fun relaxed!257 () Bool)
(declare-fun relaxed!439 () Bool)
(declare-fun relaxed!254 () Bool)
(declare-fun relaxed!398 () Bool)
(declare-fun relaxed!251 () Bool)
(declare-fun relaxed!357 () Bool)
(declare-fun relaxed!231 () Bool)
(declare-fun relaxed!334 () Bool)
(declare-fun relaxed!207 () Bool)
(declare-fun relaxed!315 () Bool)
(declare-fun relaxed!182 () Bool)
(declare-fun relaxed!297 () Bool)
(declare-fun relaxed!264 () Bool)
(declare-fun relaxed!261 () Bool)
(declare-fun relaxed!258 () Bool)
(declare-fun relaxed!255 () Bool)
(declare-fun relaxed!252 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) relaxed!8))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!28))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!33))
(assert (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)) relaxed!38))
(assert (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) relaxed!43))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!48))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!53))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!58))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!63))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!68))
(assert (or (and (= r.w.x r.k-5.x) (= r.w.y r.k-5.y)) relaxed!73))
(assert (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) relaxed!78))
(assert (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) relaxed!83))
(assert (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) relaxed!88))
(assert (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) relaxed!93))
(assert (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) relaxed!98))
(assert (or (and (= r.b.x r.k-5.x) (= r.b.y r.k-5.y)) relaxed!103))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!108))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!113))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!118))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!123))
(assert (or (and (= r.c.x r.k-5.x) (= r.c.y r.k-5.y)) relaxed!128))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!133))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!138))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!143))
(assert (or (and (= r.k-1.x r.k-5.x) (= r.k-1.y r.k-5.y)) relaxed!148))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!153))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!158))
(assert (or (and (= r.k-2.x r.k-5.x) (= r.k-2.y r.k-5.y)) relaxed!163))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!168))
(assert (or (and (= r.k-3.x r.k-5.x) (= r.k-3.y r.k-5.y)) relaxed!173))
(assert (or (and (= r.k-4.x r.k-5.x) (= r.k-4.y r.k-5.y)) relaxed!178))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!3 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!8 (and (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!11 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!14 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!15 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!16 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!19 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!47 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!49 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!59 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!61 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!71 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!73 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!83 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!85 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!95 (and (> (- r.k-5.x 0.0) (- 2.0)) (> 2.0 (- r.k-5.x 0.0))))
      (a!97 (and (> (- r.k-5.y 0.0) (- 2.0)) (> 2.0 (- r.k-5.y 0.0)))))
(let ((a!2 (or (and a!1 (< 0.0 (- r.w.y 0.0))) (and a!1 (> 0.0 (- r.w.y 0.0)))))
      (a!10 (or (and a!9 (< 0.0 (- r.b.y 0.0))) (and a!9 (> 0.0 (- r.b.y 0.0)))))
      (a!17 (or (and a!16 (< 0.0 (- r.c.y 0.0)))
                (and a!16 (> 0.0 (- r.c.y 0.0)))))
      (a!20 (or (and a!19 (< 0.0 (- 0.0 0.0))) (and a!19 (> 0.0 (- 0.0 0.0)))))
      (a!48 (or (and a!47 (< 0.0 (- r.k-1.y 0.0)))
                (and a!47 (> 0.0 (- r.k-1.y 0.0)))))
      (a!60 (or (and a!59 (< 0.0 (- r.k-2.y 0.0)))
                (and a!59 (> 0.0 (- r.k-2.y 0.0)))))
      (a!72 (or (and a!71 (< 0.0 (- r.k-3.y 0.0)))
                (and a!71 (> 0.0 (- r.k-3.y 0.0)))))
      (a!84 (or (and a!83 (< 0.0 (- r.k-4.y 0.0)))
                (and a!83 (> 0.0 (- r.k-4.y 0.0)))))
      (a!96 (or (and a!95 (< 0.0 (- r.k-5.y 0.0)))
                (and a!95 (> 0.0 (- r.k-5.y 0.0))))))
(let ((a!4 (or a!2
               (and a!3 (< 0.0 (- r.w.x 0.0)))
               (and a!3 (> 0.0 (- r.w.x 0.0)))))
      (a!5 (and (and a!3 (< 0.0 (- r.w.x 0.0))) (not a!2)))
      (a!12 (or a!10
                (and a!11 (< 0.0 (- r.b.x 0.0)))
                (and a!11 (> 0.0 (- r.b.x 0.0)))))
      (a!18 (and (and a!15 (< 0.0 (- r.c.x 0.0))) (not a!17)))
      (a!21 (not (and (not (or a!20 a!20))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!22 (and (and a!19 (> 0.0 (- 0.0 0.0))) (not a!20)))
      (a!23 (not (and (not (or a!20 a!20))
                      (< 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!24 (and (and a!19 (< 0.0 (- 0.0 0.0))) (not a!20)))
      (a!25 (and (not (or a!20 a!20)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!30 (and (and a!3 (> 0.0 (- r.w.x 0.0))) (not a!2)))
      (a!35 (and (and a!11 (> 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!37 (and (and a!11 (< 0.0 (- r.b.x 0.0))) (not a!10)))
      (a!40 (or a!17
                (and a!15 (< 0.0 (- r.c.x 0.0)))
                (and a!15 (> 0.0 (- r.c.x 0.0)))))
      (a!42 (and (and a!15 (> 0.0 (- r.c.x 0.0))) (not a!17)))
      (a!50 (or a!48
                (and a!49 (< 0.0 (- r.k-1.x 0.0)))
                (and a!49 (> 0.0 (- r.k-1.x 0.0)))))
      (a!52 (and (and a!49 (> 0.0 (- r.k-1.x 0.0))) (not a!48)))
      (a!54 (and (and a!49 (< 0.0 (- r.k-1.x 0.0))) (not a!48)))
      (a!62 (or a!60
                (and a!61 (< 0.0 (- r.k-2.x 0.0)))
                (and a!61 (> 0.0 (- r.k-2.x 0.0)))))
      (a!64 (and (and a!61 (> 0.0 (- r.k-2.x 0.0))) (not a!60)))
      (a!66 (and (and a!61 (< 0.0 (- r.k-2.x 0.0))) (not a!60)))
      (a!74 (or a!72
                (and a!73 (< 0.0 (- r.k-3.x 0.0)))
                (and a!73 (> 0.0 (- r.k-3.x 0.0)))))
      (a!76 (and (and a!73 (> 0.0 (- r.k-3.x 0.0))) (not a!72)))
      (a!78 (and (and a!73 (< 0.0 (- r.k-3.x 0.0))) (not a!72)))
      (a!86 (or a!84
                (and a!85 (< 0.0 (- r.k-4.x 0.0)))
                (and a!85 (> 0.0 (- r.k-4.x 0.0)))))
      (a!88 (and (and a!85 (> 0.0 (- r.k-4.x 0.0))) (not a!84)))
      (a!90 (and (and a!85 (< 0.0 (- r.k-4.x 0.0))) (not a!84)))
      (a!98 (or a!96
                (and a!97 (< 0.0 (- r.k-5.x 0.0)))
                (and a!97 (> 0.0 (- r.k-5.x 0.0)))))
      (a!100 (and (and a!97 (> 0.0 (- r.k-5.x 0.0))) (not a!96)))
      (a!102 (and (and a!97 (< 0.0 (- r.k-5.x 0.0))) (not a!96))))
(let ((a!6 (and (not a!4) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!13 (and (not a!12) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!26 (or (and (not (or a!20 a!20))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                a!24
                a!25))
      (a!27 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!25))
      (a!29 (not (and (not a!4) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!31 (not (and (not a!4) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!34 (not (and (not a!12) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!36 (not (and (not a!12) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!38 (and (not a!12) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!41 (not (and (not a!40) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!43 (not (and (not a!40) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!44 (and (not a!40) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!51 (not (and (not a!50)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!53 (not (and (not a!50)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!55 (and (not a!50) (> 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!63 (not (and (not a!62)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!65 (not (and (not a!62)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!67 (and (not a!62) (> 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!75 (not (and (not a!74)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!77 (not (and (not a!74)
                      (< 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!79 (and (not a!74) (> 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0))))
      (a!87 (not (and (not a!86)
                      (> 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!89 (not (and (not a!86)
                      (< 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!91 (and (not a!86) (> 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0))))
      (a!99 (not (and (not a!98)
                      (> 0.0 (- r.k-5.x 0.0))
                      (> 0.0 (- r.k-5.y 0.0)))))
      (a!101 (not (and (not a!98)
                       (< 0.0 (- r.k-5.x 0.0))
                       (> 0.0 (- r.k-5.y 0.0)))))
      (a!103 (and (not a!98) (> 0.0 (- r.k-5.x 0.0)) (< 0.0 (- r.k-5.y 0.0)))))
(let ((a!7 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!5
               a!6))
      (a!28 (and a!21
                 (not a!22)
                 a!23
                 (=> a!26 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!27)
                 (not relaxed!297)))
      (a!32 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!39 (and a!34
                 (not a!35)
                 a!36
                 (=> (or a!13 a!37 a!38) (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!38))
                 (not relaxed!334)))
      (a!45 (or (and (not a!40) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                a!18
                a!44))
      (a!56 (or (and (not a!50) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                a!54
                a!55))
      (a!57 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 a!55))
      (a!68 (or (and (not a!62) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                a!66
                a!67))
      (a!69 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 a!67))
      (a!80 (or (and (not a!74) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))
                a!78
                a!79))
      (a!81 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 a!79))
      (a!92 (or (and (not a!86) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0)))
                a!90
                a!91))
      (a!93 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 a!91))
      (a!104 (or (and (not a!98)
                      (< 0.0 (- r.k-5.x 0.0))
                      (< 0.0 (- r.k-5.y 0.0)))
                 a!102
                 a!103))
      (a!105 (and (> (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  a!103)))
(let ((a!33 (and a!29
                 (not a!30)
                 a!31
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!32)
                 (not relaxed!315)))
      (a!46 (and a!41
                 (not a!42)
                 a!43
                 (=> a!45 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!14 a!44))
                 (not relaxed!357)))
      (a!58 (and a!51
                 (not a!52)
                 a!53
                 (=> a!56 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!57)
                 (not relaxed!398)))
      (a!70 (and a!63
                 (not a!64)
                 a!65
                 (=> a!68 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not a!69)
                 (not relaxed!439)))
      (a!82 (and a!75
                 (not a!76)
                 a!77
                 (=> a!80 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not a!81)
                 (not relaxed!480)))
      (a!94 (and a!87
                 (not a!88)
                 a!89
                 (=> a!92 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not a!93)
                 (not relaxed!521)))
      (a!106 (and a!99
                  (not a!100)
                  a!101
                  (=> a!104 (>= (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  (not a!105)
                  (not relaxed!562))))
(let ((a!107 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!182
                  a!7
                  (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                  relaxed!207
                  a!8
                  a!13
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!231
                  a!14
                  a!18
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  relaxed!251
                  relaxed!252
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  relaxed!254
                  relaxed!255
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  relaxed!257
                  relaxed!258
                  (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                  relaxed!260
                  relaxed!261
                  (not (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)))
                  relaxed!263
                  relaxed!264
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!28))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!182 a!33))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> relaxed!207 a!39))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!231 a!46))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!251 a!58))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!254 a!70))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!257 a!82))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!260 a!94))
                  (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y))
                      (=> relaxed!263 a!106)))))
  (=> r.case0 a!107)))))))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!18) a!1)))
; cut relaxed!18
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!18)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* 1.0 (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* (- 1.0) (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 9.0 5.0) (- 0.0 r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 8.0 5.0) (- 0.0 r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* 1.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* (- 1.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 9.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 8.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* 1.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* (- 1.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 9.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 8.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* 1.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* (- 1.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 9.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 8.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* 1.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* (- 1.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 9.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 8.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* 1.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* (- 1.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 9.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 8.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* 1.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* (- 1.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 9.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 8.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* 1.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* (- 1.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 9.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 8.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* 1.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* (- 1.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 9.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 8.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* 1.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* (- 1.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 9.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 8.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* 1.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* (- 1.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* 1.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* (- 1.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* 1.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* (- 1.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* 1.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* (- 1.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!182 a!1)))
; cut relaxed!182
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!182) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!207 a!1)))
; cut relaxed!207
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0)))) (=> (not relaxed!207) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!231) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!251 a!1)))
; cut relaxed!251
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!251) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!252 (<= a!1 2.0))))
; cut relaxed!252
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!252) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!254 a!1)))
; cut relaxed!254
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!254) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!255
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!255 (<= a!1 2.0))))
; cut relaxed!255
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!255) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!257 a!1)))
; cut relaxed!257
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!257) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!258
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!258 (<= a!1 2.0))))
; cut relaxed!258
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!258) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!260) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!261
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!261 (<= a!1 2.0))))
; cut relaxed!261
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!261) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* 1.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* (- 1.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!263 a!1)))
; cut relaxed!263
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 9.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 8.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0)))) (=> (not relaxed!263) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!264
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!264 (<= a!1 2.0))))
; cut relaxed!264
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> (not relaxed!264) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!297
(assert (not relaxed!297))
; cut relaxed!315
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) (- 6.0))) (* 0.0 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 6.0))) (* 1.0 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) (- 6.0))) (* 0.0 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 6.0))) (* (- 1.0) 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!315 (<= a!1 2.0))))
; cut relaxed!315
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) (- 6.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!315) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!334
(assert (let ((a!1 (+ (* 1.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 6.0)))))) (=> relaxed!334 (<= a!1 2.0))))
; cut relaxed!334
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.b.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.b.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.b.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.b.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 6.0)))))) (=> (not relaxed!334) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!357
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 6.0)))))) (=> relaxed!357 (<= a!1 2.0))))
; cut relaxed!357
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 6.0)))))) (=> (not relaxed!357) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 6.0)))))) (=> (not relaxed!398) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!439
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> relaxed!439 (<= a!1 2.0))))
; cut relaxed!439
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 6.0)))))) (=> (not relaxed!439) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!480
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> relaxed!480 (<= a!1 2.0))))
; cut relaxed!480
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 6.0)))))) (=> (not relaxed!480) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!521
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> relaxed!521 (<= a!1 2.0))))
; cut relaxed!521
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 6.0)))))) (=> (not relaxed!521) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!562
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> relaxed!562 (<= a!1 2.0))))
; cut relaxed!562
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 6.0)))))) (=> (not relaxed!562) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
