; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 48; cuts: 622
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x)) (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x)) (* (- r.w.y r.b.y) (- r.w.y r.b.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.w.x r.k-5.x) (- r.w.x r.k-5.x)) (* (- r.w.y r.k-5.y) (- r.w.y r.k-5.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.w.x r.k-6.x) (- r.w.x r.k-6.x)) (* (- r.w.y r.k-6.y) (- r.w.y r.k-6.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x)) (* (- r.b.y r.c.y) (- r.b.y r.c.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x)) (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x)) (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x)) (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x)) (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.b.x r.k-5.x) (- r.b.x r.k-5.x)) (* (- r.b.y r.k-5.y) (- r.b.y r.k-5.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.b.x r.k-6.x) (- r.b.x r.k-6.x)) (* (- r.b.y r.k-6.y) (- r.b.y r.k-6.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.c.x r.k-5.x) (- r.c.x r.k-5.x)) (* (- r.c.y r.k-5.y) (- r.c.y r.k-5.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.c.x r.k-6.x) (- r.c.x r.k-6.x)) (* (- r.c.y r.k-6.y) (- r.c.y r.k-6.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.k-1.x r.k-5.x) (- r.k-1.x r.k-5.x)) (* (- r.k-1.y r.k-5.y) (- r.k-1.y r.k-5.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.k-1.x r.k-6.x) (- r.k-1.x r.k-6.x)) (* (- r.k-1.y r.k-6.y) (- r.k-1.y r.k-6.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!183 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!188 (<= 4.0 (+ (* (- r.k-2.x r.k-5.x) (- r.k-2.x r.k-5.x)) (* (- r.k-2.y r.k-5.y) (- r.k-2.y r.k-5.y))))
; atom relaxed!193 (<= 4.0 (+ (* (- r.k-2.x r.k-6.x) (- r.k-2.x r.k-6.x)) (* (- r.k-2.y r.k-6.y) (- r.k-2.y r.k-6.y))))
; atom relaxed!198 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!203 (<= 4.0 (+ (* (- r.k-3.x r.k-5.x) (- r.k-3.x r.k-5.x)) (* (- r.k-3.y r.k-5.y) (- r.k-3.y r.k-5.y))))
; atom relaxed!208 (<= 4.0 (+ (* (- r.k-3.x r.k-6.x) (- r.k-3.x r.k-6.x)) (* (- r.k-3.y r.k-6.y) (- r.k-3.y r.k-6.y))))
; atom relaxed!213 (<= 4.0 (+ (* (- r.k-4.x r.k-5.x) (- r.k-4.x r.k-5.x)) (* (- r.k-4.y r.k-5.y) (- r.k-4.y r.k-5.y))))
; atom relaxed!218 (<= 4.0 (+ (* (- r.k-4.x r.k-6.x) (- r.k-4.x r.k-6.x)) (* (- r.k-4.y r.k-6.y) (- r.k-4.y r.k-6.y))))
; atom relaxed!223 (<= 4.0 (+ (* (- r.k-5.x r.k-6.x) (- r.k-5.x r.k-6.x)) (* (- r.k-5.y r.k-6.y) (- r.k-5.y r.k-6.y))))
; atom relaxed!227 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!252 (>= 16.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!276 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!296 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!297 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!299 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!300 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!302 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!303 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!305 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!306 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!308 (>= 16.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!309 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (> 4.0 a!1))
; atom relaxed!311 (>= 16.0 (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x)) (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y))))
; atom relaxed!312 (let ((a!1 (+ (* (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-6.y 0.0) (- 6.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!345 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) (- 7.0)) (- (- 0.0 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!363 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) (- 7.0)) (- (- r.w.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!382 (let ((a!1 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (- r.b.y 0.0) (- 7.0)) (- (- r.b.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!405 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) (- 7.0)) (- (- r.c.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!446 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 7.0)) (- (- r.k-1.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!487 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 7.0)) (- (- r.k-2.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!528 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 7.0)) (- (- r.k-3.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!569 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 7.0)) (- (- r.k-4.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!610 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 7.0)) (- (- r.k-5.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!651 (let ((a!1 (+ (* (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-6.y 0.0) (- 7.0)) (- (- r.k-6.y 0.0) (- 7.0)))))) (> 4.0 a!1))
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
(declare-fun r.k-6.y () Real)
(declare-fun r.k-6.x () Real)
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
(declare-fun relaxed!183 () Bool)
(declare-fun relaxed!188 () Bool)
(declare-fun relaxed!193 () Bool)
(declare-fun relaxed!198 () Bool)
(declare-fun relaxed!203 () Bool)
(declare-fun relaxed!208 () Bool)
(declare-fun relaxed!213 () Bool)
(declare-fun relaxed!218 () Bool)
(declare-fun relaxed!223 () Bool)
(declare-fun relaxed!651 () Bool)
(declare-fun relaxed!311 () Bool)
(declare-fun relaxed!610 () Bool)
(declare-fun relaxed!308 () Bool)
(declare-fun relaxed!569 () Bool)
(declare-fun relaxed!305 () Bool)
(declare-fun relaxed!528 () Bool)
(declare-fun relaxed!302 () Bool)
(declare-fun relaxed!487 () Bool)
(declare-fun relaxed!299 () Bool)
(declare-fun relaxed!446 () Bool)
(declare-fun relaxed!296 () Bool)
(declare-fun relaxed!405 () Bool)
(declare-fun relaxed!276 () Bool)
(declare-fun relaxed!382 () Bool)
(declare-fun relaxed!252 () Bool)
(declare-fun relaxed!363 () Bool)
(declare-fun relaxed!227 () Bool)
(declare-fun relaxed!345 () Bool)
(declare-fun relaxed!312 () Bool)
(declare-fun relaxed!309 () Bool)
(declare-fun relaxed!306 () Bool)
(declare-fun relaxed!303 () Bool)
(declare-fun relaxed!300 () Bool)
(declare-fun relaxed!297 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) relaxed!8))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!28))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!33))
(assert (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)) relaxed!38))
(assert (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)) relaxed!43))
(assert (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) relaxed!48))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!53))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!58))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!63))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!68))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!73))
(assert (or (and (= r.w.x r.k-5.x) (= r.w.y r.k-5.y)) relaxed!78))
(assert (or (and (= r.w.x r.k-6.x) (= r.w.y r.k-6.y)) relaxed!83))
(assert (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) relaxed!88))
(assert (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) relaxed!93))
(assert (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) relaxed!98))
(assert (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) relaxed!103))
(assert (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) relaxed!108))
(assert (or (and (= r.b.x r.k-5.x) (= r.b.y r.k-5.y)) relaxed!113))
(assert (or (and (= r.b.x r.k-6.x) (= r.b.y r.k-6.y)) relaxed!118))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!123))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!128))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!133))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!138))
(assert (or (and (= r.c.x r.k-5.x) (= r.c.y r.k-5.y)) relaxed!143))
(assert (or (and (= r.c.x r.k-6.x) (= r.c.y r.k-6.y)) relaxed!148))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!153))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!158))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!163))
(assert (or (and (= r.k-1.x r.k-5.x) (= r.k-1.y r.k-5.y)) relaxed!168))
(assert (or (and (= r.k-1.x r.k-6.x) (= r.k-1.y r.k-6.y)) relaxed!173))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!178))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!183))
(assert (or (and (= r.k-2.x r.k-5.x) (= r.k-2.y r.k-5.y)) relaxed!188))
(assert (or (and (= r.k-2.x r.k-6.x) (= r.k-2.y r.k-6.y)) relaxed!193))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!198))
(assert (or (and (= r.k-3.x r.k-5.x) (= r.k-3.y r.k-5.y)) relaxed!203))
(assert (or (and (= r.k-3.x r.k-6.x) (= r.k-3.y r.k-6.y)) relaxed!208))
(assert (or (and (= r.k-4.x r.k-5.x) (= r.k-4.y r.k-5.y)) relaxed!213))
(assert (or (and (= r.k-4.x r.k-6.x) (= r.k-4.y r.k-6.y)) relaxed!218))
(assert (or (and (= r.k-5.x r.k-6.x) (= r.k-5.y r.k-6.y)) relaxed!223))
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
      (a!97 (and (> (- r.k-5.y 0.0) (- 2.0)) (> 2.0 (- r.k-5.y 0.0))))
      (a!107 (and (> (- r.k-6.x 0.0) (- 2.0)) (> 2.0 (- r.k-6.x 0.0))))
      (a!109 (and (> (- r.k-6.y 0.0) (- 2.0)) (> 2.0 (- r.k-6.y 0.0)))))
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
                (and a!95 (> 0.0 (- r.k-5.y 0.0)))))
      (a!108 (or (and a!107 (< 0.0 (- r.k-6.y 0.0)))
                 (and a!107 (> 0.0 (- r.k-6.y 0.0))))))
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
      (a!102 (and (and a!97 (< 0.0 (- r.k-5.x 0.0))) (not a!96)))
      (a!110 (or a!108
                 (and a!109 (< 0.0 (- r.k-6.x 0.0)))
                 (and a!109 (> 0.0 (- r.k-6.x 0.0)))))
      (a!112 (and (and a!109 (> 0.0 (- r.k-6.x 0.0))) (not a!108)))
      (a!114 (and (and a!109 (< 0.0 (- r.k-6.x 0.0))) (not a!108))))
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
      (a!103 (and (not a!98) (> 0.0 (- r.k-5.x 0.0)) (< 0.0 (- r.k-5.y 0.0))))
      (a!111 (not (and (not a!110)
                       (> 0.0 (- r.k-6.x 0.0))
                       (> 0.0 (- r.k-6.y 0.0)))))
      (a!113 (not (and (not a!110)
                       (< 0.0 (- r.k-6.x 0.0))
                       (> 0.0 (- r.k-6.y 0.0)))))
      (a!115 (and (not a!110) (> 0.0 (- r.k-6.x 0.0)) (< 0.0 (- r.k-6.y 0.0)))))
(let ((a!7 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!5
               a!6))
      (a!28 (and a!21
                 (not a!22)
                 a!23
                 (=> a!26 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!27)
                 (not relaxed!345)))
      (a!32 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!39 (and a!34
                 (not a!35)
                 a!36
                 (=> (or a!13 a!37 a!38) (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!38))
                 (not relaxed!382)))
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
                  a!103))
      (a!116 (or (and (not a!110)
                      (< 0.0 (- r.k-6.x 0.0))
                      (< 0.0 (- r.k-6.y 0.0)))
                 a!114
                 a!115))
      (a!117 (and (> (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0)))
                  a!115)))
(let ((a!33 (and a!29
                 (not a!30)
                 a!31
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!32)
                 (not relaxed!363)))
      (a!46 (and a!41
                 (not a!42)
                 a!43
                 (=> a!45 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!14 a!44))
                 (not relaxed!405)))
      (a!58 (and a!51
                 (not a!52)
                 a!53
                 (=> a!56 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!57)
                 (not relaxed!446)))
      (a!70 (and a!63
                 (not a!64)
                 a!65
                 (=> a!68 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not a!69)
                 (not relaxed!487)))
      (a!82 (and a!75
                 (not a!76)
                 a!77
                 (=> a!80 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not a!81)
                 (not relaxed!528)))
      (a!94 (and a!87
                 (not a!88)
                 a!89
                 (=> a!92 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not a!93)
                 (not relaxed!569)))
      (a!106 (and a!99
                  (not a!100)
                  a!101
                  (=> a!104 (>= (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  (not a!105)
                  (not relaxed!610)))
      (a!118 (and a!111
                  (not a!112)
                  a!113
                  (=> a!116 (>= (- r.k-6.x 0.0) (- r.w.x 0.0)))
                  (not a!117)
                  (not relaxed!651))))
(let ((a!119 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!227
                  a!7
                  (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                  relaxed!252
                  a!8
                  a!13
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!276
                  a!14
                  a!18
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  relaxed!296
                  relaxed!297
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  relaxed!299
                  relaxed!300
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  relaxed!302
                  relaxed!303
                  (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                  relaxed!305
                  relaxed!306
                  (not (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)))
                  relaxed!308
                  relaxed!309
                  (not (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)))
                  relaxed!311
                  relaxed!312
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!28))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!227 a!33))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> relaxed!252 a!39))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!276 a!46))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!296 a!58))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!299 a!70))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!302 a!82))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!305 a!94))
                  (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y))
                      (=> relaxed!308 a!106))
                  (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y))
                      (=> relaxed!311 a!118)))))
  (=> r.case0 a!119)))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.b.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (>= 0.0 r.k-4.x)
     (>= 0.0 r.k-5.x)
     (>= 0.0 r.k-6.x)
     (distinct 0.0 (+ 0.0 (- r.w.x 0.0)))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* 1.0 (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* (- 1.0) (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 9.0 5.0) (- 0.0 r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 8.0 5.0) (- 0.0 r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* 1.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* (- 1.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 9.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 8.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* 1.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* (- 1.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 9.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 8.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-6.x)) (* 0.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-6.x)) (* (/ 4.0 5.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-6.x)) (* 1.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 3.0 5.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-6.x)) (* 0.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-6.x)) (* (- 1.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-6.x)) (* (/ 4.0 5.0) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-6.x)) (* (/ 9.0 5.0) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 8.0 5.0) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 3.0 5.0) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* 1.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* (- 1.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 9.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 8.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* 1.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* (- 1.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 9.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 8.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* 1.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* (- 1.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 9.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 8.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* 1.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* (- 1.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 9.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 8.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* 1.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* (- 1.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 9.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 8.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* 1.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* (- 1.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 9.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 8.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-6.x)) (* 0.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-6.x)) (* (/ 4.0 5.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-6.x)) (* 1.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 3.0 5.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-6.x)) (* 0.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-6.x)) (* (- 1.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-6.x)) (* (/ 4.0 5.0) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-6.x)) (* (/ 9.0 5.0) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 8.0 5.0) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 3.0 5.0) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* 1.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* (- 1.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 9.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 8.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-6.x)) (* 0.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-6.x)) (* (/ 4.0 5.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-6.x)) (* 1.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 3.0 5.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-6.x)) (* 0.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-6.x)) (* (- 1.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-6.x)) (* (/ 4.0 5.0) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-6.x)) (* (/ 9.0 5.0) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 8.0 5.0) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 3.0 5.0) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* 1.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* (- 1.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-6.x)) (* 0.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-6.x)) (* 1.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-6.x)) (* 0.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-6.x)) (* (- 1.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!183)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* 1.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* (- 1.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!188)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-6.x)) (* 0.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-6.x)) (* 1.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-6.x)) (* 0.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-6.x)) (* (- 1.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!193)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!198)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* 1.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* (- 1.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!203)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-6.x)) (* 0.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-6.x)) (* 1.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-6.x)) (* 0.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-6.x)) (* (- 1.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!208)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* 1.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* (- 1.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!213)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-6.x)) (* 0.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-6.x)) (* 1.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-6.x)) (* 0.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-6.x)) (* (- 1.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!218)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-5.x r.k-6.x)) (* 0.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-6.x)) (* 1.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-5.x r.k-6.x)) (* 0.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-6.x)) (* (- 1.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!223)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!227 a!1)))
; cut relaxed!227
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!227) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!252 a!1)))
; cut relaxed!252
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0)))) (=> (not relaxed!252) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!276 a!1)))
; cut relaxed!276
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!276) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!296 a!1)))
; cut relaxed!296
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!296) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!297
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!297) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!299 a!1)))
; cut relaxed!299
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!299) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!300
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!300 (<= a!1 2.0))))
; cut relaxed!300
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!300) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!302 a!1)))
; cut relaxed!302
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!302) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!303
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!303 (<= a!1 2.0))))
; cut relaxed!303
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!303) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!305 a!1)))
; cut relaxed!305
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!305) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!306
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!306 (<= a!1 2.0))))
; cut relaxed!306
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!306) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* 1.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* (- 1.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!308 a!1)))
; cut relaxed!308
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 9.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 8.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0)))) (=> (not relaxed!308) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!309
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!309 (<= a!1 2.0))))
; cut relaxed!309
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> (not relaxed!309) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* 1.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* (- 1.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!311 a!1)))
; cut relaxed!311
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 9.0 5.0) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 8.0 5.0) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) (/ 36.0 5.0)))) (=> (not relaxed!311) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!312
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!312 (<= a!1 2.0))))
; cut relaxed!312
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> (not relaxed!312) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!345
(assert (not relaxed!345))
; cut relaxed!363
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) (- 7.0))) (* 0.0 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 7.0))) (* 1.0 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) (- 7.0))) (* 0.0 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 7.0))) (* (- 1.0) 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!363 (<= a!1 2.0))))
; cut relaxed!363
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) (- 7.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!363) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 1.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 7.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.b.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.b.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.b.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.b.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 7.0)))))) (=> (not relaxed!382) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!405
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 7.0)))))) (=> relaxed!405 (<= a!1 2.0))))
; cut relaxed!405
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 7.0)))))) (=> (not relaxed!405) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 7.0)))))) (=> (not relaxed!446) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!487
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> relaxed!487 (<= a!1 2.0))))
; cut relaxed!487
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 7.0)))))) (=> (not relaxed!487) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 7.0)))))) (=> (not relaxed!528) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 7.0)))))) (=> (not relaxed!569) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!610
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> relaxed!610 (<= a!1 2.0))))
; cut relaxed!610
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 7.0)))))) (=> (not relaxed!610) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!651
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> relaxed!651 (<= a!1 2.0))))
; cut relaxed!651
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-6.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-6.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 7.0)))))) (=> (not relaxed!651) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
