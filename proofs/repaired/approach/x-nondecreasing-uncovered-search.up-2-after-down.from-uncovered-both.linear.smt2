; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 48; cuts: 648
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x)) (* (- r.w.y r.b.y) (- r.w.y r.b.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x)) (* (- r.w.y r.d.y) (- r.w.y r.d.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x)) (* (- r.b.y r.c.y) (- r.b.y r.c.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.b.x r.d.x) (- r.b.x r.d.x)) (* (- r.b.y r.d.y) (- r.b.y r.d.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x)) (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x)) (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x)) (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x)) (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.b.x r.k+1.x) (- r.b.x r.k+1.x)) (* (- r.b.y r.k+1.y) (- r.b.y r.k+1.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x)) (* (- r.c.y r.d.y) (- r.c.y r.d.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x)) (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.d.x r.k-2.x) (- r.d.x r.k-2.x)) (* (- r.d.y r.k-2.y) (- r.d.y r.k-2.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.d.x r.k-3.x) (- r.d.x r.k-3.x)) (* (- r.d.y r.k-3.y) (- r.d.y r.k-3.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.d.x r.k-4.x) (- r.d.x r.k-4.x)) (* (- r.d.y r.k-4.y) (- r.d.y r.k-4.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x)) (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!183 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!188 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!193 (<= 4.0 (+ (* (- r.k-1.x r.k+1.x) (- r.k-1.x r.k+1.x)) (* (- r.k-1.y r.k+1.y) (- r.k-1.y r.k+1.y))))
; atom relaxed!198 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!203 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!208 (<= 4.0 (+ (* (- r.k-2.x r.k+1.x) (- r.k-2.x r.k+1.x)) (* (- r.k-2.y r.k+1.y) (- r.k-2.y r.k+1.y))))
; atom relaxed!213 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!218 (<= 4.0 (+ (* (- r.k-3.x r.k+1.x) (- r.k-3.x r.k+1.x)) (* (- r.k-3.y r.k+1.y) (- r.k-3.y r.k+1.y))))
; atom relaxed!223 (<= 4.0 (+ (* (- r.k-4.x r.k+1.x) (- r.k-4.x r.k+1.x)) (* (- r.k-4.y r.k+1.y) (- r.k-4.y r.k+1.y))))
; atom relaxed!227 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!250 (>= 16.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!274 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!284 (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!307 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0)))
; atom relaxed!310 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!311 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!314 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0)))
; atom relaxed!317 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!318 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!321 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!324 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!325 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!328 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0)))
; atom relaxed!331 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!332 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!336 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!337 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!361 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) 2.0) (- (- 0.0 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!373 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) 2.0) (- (- r.w.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!387 (let ((a!1 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (- r.b.y 0.0) 2.0) (- (- r.b.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!415 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) 2.0) (- (- r.c.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!429 (let ((a!1 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (- r.d.y 0.0) 2.0) (- (- r.d.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!462 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) 2.0) (- (- r.k-1.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!495 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) 2.0) (- (- r.k-2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!528 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) 2.0) (- (- r.k-3.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!561 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) 2.0) (- (- r.k-4.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!594 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 2.0) (- (- r.k+1.y 0.0) 2.0))))) (> 4.0 a!1))
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
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun relaxed!28 () Bool)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
(declare-fun relaxed!33 () Bool)
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun relaxed!38 () Bool)
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun relaxed!43 () Bool)
(declare-fun r.k+1.y () Real)
(declare-fun r.k+1.x () Real)
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
(declare-fun relaxed!594 () Bool)
(declare-fun relaxed!336 () Bool)
(declare-fun relaxed!561 () Bool)
(declare-fun relaxed!331 () Bool)
(declare-fun relaxed!528 () Bool)
(declare-fun relaxed!324 () Bool)
(declare-fun relaxed!495 () Bool)
(declare-fun relaxed!317 () Bool)
(declare-fun relaxed!462 () Bool)
(declare-fun relaxed!310 () Bool)
(declare-fun relaxed!429 () Bool)
(declare-fun relaxed!284 () Bool)
(declare-fun relaxed!415 () Bool)
(declare-fun relaxed!274 () Bool)
(declare-fun relaxed!387 () Bool)
(declare-fun relaxed!250 () Bool)
(declare-fun relaxed!373 () Bool)
(declare-fun relaxed!227 () Bool)
(declare-fun relaxed!361 () Bool)
(declare-fun relaxed!314 () Bool)
(declare-fun relaxed!337 () Bool)
(declare-fun relaxed!332 () Bool)
(declare-fun relaxed!328 () Bool)
(declare-fun relaxed!325 () Bool)
(declare-fun relaxed!321 () Bool)
(declare-fun relaxed!318 () Bool)
(declare-fun relaxed!311 () Bool)
(declare-fun relaxed!307 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) relaxed!8))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!13))
(assert (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!28))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!33))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!38))
(assert (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) relaxed!43))
(assert (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) relaxed!48))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!53))
(assert (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) relaxed!58))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!63))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!68))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!73))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!78))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!83))
(assert (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) relaxed!88))
(assert (or (and (= r.b.x r.d.x) (= r.b.y r.d.y)) relaxed!93))
(assert (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) relaxed!98))
(assert (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) relaxed!103))
(assert (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) relaxed!108))
(assert (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) relaxed!113))
(assert (or (and (= r.b.x r.k+1.x) (= r.b.y r.k+1.y)) relaxed!118))
(assert (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) relaxed!123))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!128))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!133))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!138))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!143))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!148))
(assert (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) relaxed!153))
(assert (or (and (= r.d.x r.k-2.x) (= r.d.y r.k-2.y)) relaxed!158))
(assert (or (and (= r.d.x r.k-3.x) (= r.d.y r.k-3.y)) relaxed!163))
(assert (or (and (= r.d.x r.k-4.x) (= r.d.y r.k-4.y)) relaxed!168))
(assert (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) relaxed!173))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!178))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!183))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!188))
(assert (or (and (= r.k-1.x r.k+1.x) (= r.k-1.y r.k+1.y)) relaxed!193))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!198))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!203))
(assert (or (and (= r.k-2.x r.k+1.x) (= r.k-2.y r.k+1.y)) relaxed!208))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!213))
(assert (or (and (= r.k-3.x r.k+1.x) (= r.k-3.y r.k+1.y)) relaxed!218))
(assert (or (and (= r.k-4.x r.k+1.x) (= r.k-4.y r.k+1.y)) relaxed!223))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!5 (and (> (- r.b.x 0.0) (- 2.0)) (> 2.0 (- r.b.x 0.0))))
      (a!6 (and (> (- r.b.y 0.0) (- 2.0)) (> 2.0 (- r.b.y 0.0))))
      (a!9 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!10 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!11 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!14 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                 relaxed!310
                 relaxed!311))
      (a!15 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 relaxed!317
                 relaxed!318))
      (a!16 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                 relaxed!324
                 relaxed!325))
      (a!17 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                 relaxed!331
                 relaxed!332))
      (a!18 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!34 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!46 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!47 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!54 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!55 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!62 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!63 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!70 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!71 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!78 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!79 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0)))))
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
      (a!19 (or (and a!18 (< 0.0 (- 0.0 0.0))) (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!21 (not (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!26 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!30 (not (and a!6 (> 0.0 (- r.b.x 0.0)))))
      (a!35 (or (and a!34 (< 0.0 (- r.c.y 0.0)))
                (and a!34 (> 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!37 (not (and a!9 (> 0.0 (- r.c.x 0.0)))))
      (a!42 (not (and a!11 (> 0.0 (- r.d.x 0.0)))))
      (a!48 (or (and a!46 (< 0.0 (- r.k-1.y 0.0)))
                (and a!46 (> 0.0 (- r.k-1.y 0.0)))
                (and a!47 (< 0.0 (- r.k-1.x 0.0)))
                (and a!47 (> 0.0 (- r.k-1.x 0.0)))))
      (a!50 (not (and a!47 (> 0.0 (- r.k-1.x 0.0)))))
      (a!56 (or (and a!54 (< 0.0 (- r.k-2.y 0.0)))
                (and a!54 (> 0.0 (- r.k-2.y 0.0)))
                (and a!55 (< 0.0 (- r.k-2.x 0.0)))
                (and a!55 (> 0.0 (- r.k-2.x 0.0)))))
      (a!58 (not (and a!55 (> 0.0 (- r.k-2.x 0.0)))))
      (a!64 (or (and a!62 (< 0.0 (- r.k-3.y 0.0)))
                (and a!62 (> 0.0 (- r.k-3.y 0.0)))
                (and a!63 (< 0.0 (- r.k-3.x 0.0)))
                (and a!63 (> 0.0 (- r.k-3.x 0.0)))))
      (a!66 (not (and a!63 (> 0.0 (- r.k-3.x 0.0)))))
      (a!72 (or (and a!70 (< 0.0 (- r.k-4.y 0.0)))
                (and a!70 (> 0.0 (- r.k-4.y 0.0)))
                (and a!71 (< 0.0 (- r.k-4.x 0.0)))
                (and a!71 (> 0.0 (- r.k-4.x 0.0)))))
      (a!74 (not (and a!71 (> 0.0 (- r.k-4.x 0.0)))))
      (a!80 (or (and a!78 (< 0.0 (- r.k+1.y 0.0)))
                (and a!78 (> 0.0 (- r.k+1.y 0.0)))
                (and a!79 (< 0.0 (- r.k+1.x 0.0)))
                (and a!79 (> 0.0 (- r.k+1.x 0.0)))))
      (a!82 (not (and a!79 (> 0.0 (- r.k+1.x 0.0))))))
(let ((a!4 (or (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!8 (and (not a!7) (< 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0))))
      (a!13 (and (not a!12) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!20 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!22 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!23 (or (and (not (or a!19 a!19))
                     (< 0.0 (- 0.0 0.0))
                     (< 0.0 (- 0.0 0.0)))
                (and a!18 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!19 a!19))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!25 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!27 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!29 (not (and (not a!7) (> 0.0 (- r.b.x 0.0)) (< 0.0 (- r.b.y 0.0)))))
      (a!31 (not (and (not a!7) (> 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!36 (not (and (not a!35) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!38 (not (and (not a!35) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!39 (or (and (not a!35) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))
                (and a!9 (< 0.0 (- r.c.x 0.0)))
                (and (not a!35) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!41 (not (and (not a!12) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!43 (not (and (not a!12) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!49 (not (and (not a!48)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!51 (not (and (not a!48)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!52 (or (and (not a!48) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0)))
                (and a!47 (< 0.0 (- r.k-1.x 0.0)))
                (and (not a!48) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!57 (not (and (not a!56)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!59 (not (and (not a!56)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!60 (or (and (not a!56) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))
                (and a!55 (< 0.0 (- r.k-2.x 0.0)))
                (and (not a!56) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0)))))
      (a!65 (not (and (not a!64)
                      (> 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))))
      (a!67 (not (and (not a!64)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!68 (or (and (not a!64) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0)))
                (and a!63 (< 0.0 (- r.k-3.x 0.0)))
                (and (not a!64) (< 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0)))))
      (a!73 (not (and (not a!72)
                      (> 0.0 (- r.k-4.x 0.0))
                      (< 0.0 (- r.k-4.y 0.0)))))
      (a!75 (not (and (not a!72)
                      (> 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!76 (or (and (not a!72) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0)))
                (and a!71 (< 0.0 (- r.k-4.x 0.0)))
                (and (not a!72) (< 0.0 (- r.k-4.x 0.0)) (> 0.0 (- r.k-4.y 0.0)))))
      (a!81 (not (and (not a!80)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!83 (not (and (not a!80)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!84 (or (and (not a!80) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0)))
                (and a!79 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!80) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0))))))
(let ((a!24 (and a!20
                 a!21
                 a!22
                 (=> a!23 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not relaxed!361)))
      (a!28 (and a!25
                 a!26
                 a!27
                 (=> a!4 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!373)))
      (a!32 (or a!8
                (and a!6 (< 0.0 (- r.b.x 0.0)))
                (and (not a!7) (< 0.0 (- r.b.x 0.0)) (> 0.0 (- r.b.y 0.0)))))
      (a!40 (and a!36
                 a!37
                 a!38
                 (=> a!39 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!415)))
      (a!44 (or (and (not a!12) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))
                (and a!11 (< 0.0 (- r.d.x 0.0)))
                a!13))
      (a!53 (and a!49
                 a!50
                 a!51
                 (=> a!52 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!462)))
      (a!61 (and a!57
                 a!58
                 a!59
                 (=> a!60 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!495)))
      (a!69 (and a!65
                 a!66
                 a!67
                 (=> a!68 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!528)))
      (a!77 (and a!73
                 a!74
                 a!75
                 (=> a!76 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!561)))
      (a!85 (and a!81
                 a!82
                 a!83
                 (=> a!84 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!594))))
(let ((a!33 (and a!29
                 a!30
                 a!31
                 (=> a!32 (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!387)))
      (a!45 (and a!41
                 a!42
                 a!43
                 (=> a!44 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not relaxed!429))))
(let ((a!86 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                 relaxed!227
                 a!4
                 (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                 relaxed!250
                 (> (- (- r.b.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.b.x 0.0) (- r.w.x 0.0)))
                 a!8
                 (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                 relaxed!274
                 (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))
                 (and a!9 (< 0.0 (- r.c.x 0.0)))
                 (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                 relaxed!284
                 (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))
                 a!13
                 (or (not relaxed!307) a!14)
                 (or (not relaxed!314) a!15)
                 (or (not relaxed!321) a!16)
                 (or (not relaxed!328) a!17)
                 (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                 relaxed!336
                 relaxed!337
                 relaxed!314
                 (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!24))
                 (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!227 a!28))
                 (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> relaxed!250 a!33))
                 (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!274 a!40))
                 (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> relaxed!284 a!45))
                 (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                     (=> relaxed!310 a!53))
                 (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                     (=> relaxed!317 a!61))
                 (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                     (=> relaxed!324 a!69))
                 (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                     (=> relaxed!331 a!77))
                 (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                     (=> relaxed!336 a!85)))))
  (=> r.case0 a!86))))))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* 1.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* (- 1.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 9.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 8.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* 1.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* (- 1.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 9.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 8.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.d.x)) (* 0.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.d.x)) (* (/ 4.0 5.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.d.x)) (* 1.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.d.x)) (* (/ 3.0 5.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.d.x)) (* 0.0 (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.d.x)) (* (- 1.0) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.d.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.d.x)) (* (/ 4.0 5.0) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.d.x)) (* (/ 9.0 5.0) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.d.x)) (* (/ 8.0 5.0) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.d.x)) (* (/ 3.0 5.0) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* 1.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* (- 1.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 9.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 8.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* 1.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* (- 1.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 9.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 8.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* 1.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* (- 1.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 9.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 8.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* 1.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* (- 1.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 9.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 8.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k+1.x)) (* 0.0 (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k+1.x)) (* (/ 4.0 5.0) (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k+1.x)) (* 1.0 (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k+1.x)) (* (/ 3.0 5.0) (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k+1.x)) (* 0.0 (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k+1.x)) (* (- 1.0) (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k+1.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k+1.x)) (* (/ 4.0 5.0) (- r.b.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k+1.x)) (* (/ 9.0 5.0) (- r.b.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k+1.x)) (* (/ 8.0 5.0) (- r.b.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k+1.x)) (* (/ 3.0 5.0) (- r.b.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* 1.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* (- 1.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 9.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 8.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* 1.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* (- 1.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 9.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 8.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* 1.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* (- 1.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 9.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 8.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-3.x)) (* 0.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-3.x)) (* (/ 4.0 5.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-3.x)) (* 1.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 3.0 5.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-3.x)) (* 0.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-3.x)) (* (- 1.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-3.x)) (* (/ 4.0 5.0) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-3.x)) (* (/ 9.0 5.0) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 8.0 5.0) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 3.0 5.0) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-4.x)) (* 0.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-4.x)) (* (/ 4.0 5.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-4.x)) (* 1.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 3.0 5.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-4.x)) (* 0.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-4.x)) (* (- 1.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-4.x)) (* (/ 4.0 5.0) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-4.x)) (* (/ 9.0 5.0) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 8.0 5.0) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 3.0 5.0) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* 1.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* (- 1.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 9.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 8.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!183)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!188)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* 1.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* (- 1.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!193)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!198)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!203)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* 1.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* (- 1.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!208)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!213)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* 1.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* (- 1.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!218)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* 1.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* (- 1.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!223)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0)))) (=> (not relaxed!250) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!274 a!1)))
; cut relaxed!274
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!274) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!284 a!1)))
; cut relaxed!284
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0)))) (=> (not relaxed!284) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0)))) (=> (not relaxed!307) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!310 a!1)))
; cut relaxed!310
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!310) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!311
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!311 (<= a!1 2.0))))
; cut relaxed!311
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!311) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!314 a!1)))
; cut relaxed!314
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0)))) (=> (not relaxed!314) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!317 a!1)))
; cut relaxed!317
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!317) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!318
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!318 (<= a!1 2.0))))
; cut relaxed!318
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!318) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!321 a!1)))
; cut relaxed!321
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!321) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!324 a!1)))
; cut relaxed!324
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!324) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!325
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!325 (<= a!1 2.0))))
; cut relaxed!325
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!325) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) 0.0))) (=> relaxed!328 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!331 a!1)))
; cut relaxed!331
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!331) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!332
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!332 (<= a!1 2.0))))
; cut relaxed!332
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!332) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!336 a!1)))
; cut relaxed!336
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!336) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!337
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!337 (<= a!1 2.0))))
; cut relaxed!337
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!337) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!361
(assert (not relaxed!361))
; cut relaxed!373
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) 2.0)) (* 0.0 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 2.0)) (* 1.0 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) 2.0)) (* 0.0 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 2.0)) (* (- 1.0) 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!373 (<= a!1 2.0))))
; cut relaxed!373
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 2.0)) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) 2.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!373) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!387
(assert (let ((a!1 (+ (* 1.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) 2.0))))) (=> relaxed!387 (<= a!1 2.0))))
; cut relaxed!387
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.b.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.b.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.b.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.b.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) 2.0))))) (=> (not relaxed!387) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!415
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 2.0))))) (=> relaxed!415 (<= a!1 2.0))))
; cut relaxed!415
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 2.0))))) (=> (not relaxed!415) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!429
(assert (let ((a!1 (+ (* 1.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) 2.0))))) (=> relaxed!429 (<= a!1 2.0))))
; cut relaxed!429
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.d.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.d.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.d.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.d.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) 2.0))))) (=> (not relaxed!429) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!462
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) 2.0))))) (=> relaxed!462 (<= a!1 2.0))))
; cut relaxed!462
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) 2.0))))) (=> (not relaxed!462) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!495
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) 2.0))))) (=> relaxed!495 (<= a!1 2.0))))
; cut relaxed!495
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) 2.0))))) (=> (not relaxed!495) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) 2.0))))) (=> relaxed!528 (<= a!1 2.0))))
; cut relaxed!528
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) 2.0))))) (=> (not relaxed!528) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!561
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) 2.0))))) (=> relaxed!561 (<= a!1 2.0))))
; cut relaxed!561
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) 2.0))))) (=> (not relaxed!561) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!594
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 2.0))))) (=> relaxed!594 (<= a!1 2.0))))
; cut relaxed!594
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 2.0))))) (=> (not relaxed!594) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
