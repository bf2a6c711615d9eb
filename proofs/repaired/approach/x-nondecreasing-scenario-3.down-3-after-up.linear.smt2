; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 48; cuts: 657
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x)) (* (- r.w.y r.d.y) (- r.w.y r.d.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x)) (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k+3.x) (- r.w.x r.k+3.x)) (* (- r.w.y r.k+3.y) (- r.w.y r.k+3.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k+4.x) (- r.w.x r.k+4.x)) (* (- r.w.y r.k+4.y) (- r.w.y r.k+4.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x)) (* (- r.c.y r.d.y) (- r.c.y r.d.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x)) (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.c.x r.k+3.x) (- r.c.x r.k+3.x)) (* (- r.c.y r.k+3.y) (- r.c.y r.k+3.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.c.x r.k+4.x) (- r.c.x r.k+4.x)) (* (- r.c.y r.k+4.y) (- r.c.y r.k+4.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x)) (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.d.x r.k+2.x) (- r.d.x r.k+2.x)) (* (- r.d.y r.k+2.y) (- r.d.y r.k+2.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.d.x r.k+3.x) (- r.d.x r.k+3.x)) (* (- r.d.y r.k+3.y) (- r.d.y r.k+3.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.d.x r.k+4.x) (- r.d.x r.k+4.x)) (* (- r.d.y r.k+4.y) (- r.d.y r.k+4.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x)) (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.d.x r.k-2.x) (- r.d.x r.k-2.x)) (* (- r.d.y r.k-2.y) (- r.d.y r.k-2.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x)) (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x)) (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.k+1.x r.k+4.x) (- r.k+1.x r.k+4.x)) (* (- r.k+1.y r.k+4.y) (- r.k+1.y r.k+4.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.k+1.x r.k-1.x) (- r.k+1.x r.k-1.x)) (* (- r.k+1.y r.k-1.y) (- r.k+1.y r.k-1.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.k+1.x r.k-2.x) (- r.k+1.x r.k-2.x)) (* (- r.k+1.y r.k-2.y) (- r.k+1.y r.k-2.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x)) (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))
; atom relaxed!183 (<= 4.0 (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x)) (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))
; atom relaxed!188 (<= 4.0 (+ (* (- r.k+2.x r.k-1.x) (- r.k+2.x r.k-1.x)) (* (- r.k+2.y r.k-1.y) (- r.k+2.y r.k-1.y))))
; atom relaxed!193 (<= 4.0 (+ (* (- r.k+2.x r.k-2.x) (- r.k+2.x r.k-2.x)) (* (- r.k+2.y r.k-2.y) (- r.k+2.y r.k-2.y))))
; atom relaxed!198 (<= 4.0 (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x)) (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))
; atom relaxed!203 (<= 4.0 (+ (* (- r.k+3.x r.k-1.x) (- r.k+3.x r.k-1.x)) (* (- r.k+3.y r.k-1.y) (- r.k+3.y r.k-1.y))))
; atom relaxed!208 (<= 4.0 (+ (* (- r.k+3.x r.k-2.x) (- r.k+3.x r.k-2.x)) (* (- r.k+3.y r.k-2.y) (- r.k+3.y r.k-2.y))))
; atom relaxed!213 (<= 4.0 (+ (* (- r.k+4.x r.k-1.x) (- r.k+4.x r.k-1.x)) (* (- r.k+4.y r.k-1.y) (- r.k+4.y r.k-1.y))))
; atom relaxed!218 (<= 4.0 (+ (* (- r.k+4.x r.k-2.x) (- r.k+4.x r.k-2.x)) (* (- r.k+4.y r.k-2.y) (- r.k+4.y r.k-2.y))))
; atom relaxed!223 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!227 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!250 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!260 (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!283 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0)))
; atom relaxed!286 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!287 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!290 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0)))
; atom relaxed!293 (>= 16.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!294 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!297 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!300 (>= 16.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!301 (let ((a!1 (+ (* (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!304 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0)))
; atom relaxed!307 (>= 16.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!308 (let ((a!1 (+ (* (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))) (> 4.0 a!1))
; atom relaxed!312 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!313 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!315 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!316 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!345 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) (- 3.0)) (- (- 0.0 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!362 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) (- 3.0)) (- (- r.w.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!392 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) (- 3.0)) (- (- r.c.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!408 (let ((a!1 (+ (* (- (- r.d.x 0.0) (- r.w.x 0.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (- r.d.y 0.0) (- 3.0)) (- (- r.d.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!446 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) (- 3.0)) (- (- r.k+1.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!484 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) (- 3.0)) (- (- r.k+2.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!522 (let ((a!1 (+ (* (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+3.y 0.0) (- 3.0)) (- (- r.k+3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!560 (let ((a!1 (+ (* (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+4.y 0.0) (- 3.0)) (- (- r.k+4.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!598 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 3.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!636 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 3.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (> 4.0 a!1))
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
(declare-fun r.k+3.y () Real)
(declare-fun r.k+3.x () Real)
(declare-fun relaxed!33 () Bool)
(declare-fun r.k+4.y () Real)
(declare-fun r.k+4.x () Real)
(declare-fun relaxed!38 () Bool)
(declare-fun r.k-1.y () Real)
(declare-fun r.k-1.x () Real)
(declare-fun relaxed!43 () Bool)
(declare-fun r.k-2.y () Real)
(declare-fun r.k-2.x () Real)
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
(declare-fun relaxed!636 () Bool)
(declare-fun relaxed!315 () Bool)
(declare-fun relaxed!598 () Bool)
(declare-fun relaxed!312 () Bool)
(declare-fun relaxed!560 () Bool)
(declare-fun relaxed!307 () Bool)
(declare-fun relaxed!522 () Bool)
(declare-fun relaxed!300 () Bool)
(declare-fun relaxed!484 () Bool)
(declare-fun relaxed!293 () Bool)
(declare-fun relaxed!446 () Bool)
(declare-fun relaxed!286 () Bool)
(declare-fun relaxed!408 () Bool)
(declare-fun relaxed!260 () Bool)
(declare-fun relaxed!392 () Bool)
(declare-fun relaxed!250 () Bool)
(declare-fun relaxed!362 () Bool)
(declare-fun relaxed!227 () Bool)
(declare-fun relaxed!345 () Bool)
(declare-fun relaxed!297 () Bool)
(declare-fun relaxed!316 () Bool)
(declare-fun relaxed!313 () Bool)
(declare-fun relaxed!308 () Bool)
(declare-fun relaxed!304 () Bool)
(declare-fun relaxed!301 () Bool)
(declare-fun relaxed!294 () Bool)
(declare-fun relaxed!290 () Bool)
(declare-fun relaxed!287 () Bool)
(declare-fun relaxed!283 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) relaxed!13))
(assert (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) relaxed!18))
(assert (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) relaxed!23))
(assert (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) relaxed!28))
(assert (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) relaxed!33))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!38))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!43))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!48))
(assert (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) relaxed!53))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!58))
(assert (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) relaxed!63))
(assert (or (and (= r.w.x r.k+3.x) (= r.w.y r.k+3.y)) relaxed!68))
(assert (or (and (= r.w.x r.k+4.x) (= r.w.y r.k+4.y)) relaxed!73))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!78))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!83))
(assert (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) relaxed!88))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!93))
(assert (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) relaxed!98))
(assert (or (and (= r.c.x r.k+3.x) (= r.c.y r.k+3.y)) relaxed!103))
(assert (or (and (= r.c.x r.k+4.x) (= r.c.y r.k+4.y)) relaxed!108))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!113))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!118))
(assert (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) relaxed!123))
(assert (or (and (= r.d.x r.k+2.x) (= r.d.y r.k+2.y)) relaxed!128))
(assert (or (and (= r.d.x r.k+3.x) (= r.d.y r.k+3.y)) relaxed!133))
(assert (or (and (= r.d.x r.k+4.x) (= r.d.y r.k+4.y)) relaxed!138))
(assert (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) relaxed!143))
(assert (or (and (= r.d.x r.k-2.x) (= r.d.y r.k-2.y)) relaxed!148))
(assert (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) relaxed!153))
(assert (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) relaxed!158))
(assert (or (and (= r.k+1.x r.k+4.x) (= r.k+1.y r.k+4.y)) relaxed!163))
(assert (or (and (= r.k+1.x r.k-1.x) (= r.k+1.y r.k-1.y)) relaxed!168))
(assert (or (and (= r.k+1.x r.k-2.x) (= r.k+1.y r.k-2.y)) relaxed!173))
(assert (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) relaxed!178))
(assert (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) relaxed!183))
(assert (or (and (= r.k+2.x r.k-1.x) (= r.k+2.y r.k-1.y)) relaxed!188))
(assert (or (and (= r.k+2.x r.k-2.x) (= r.k+2.y r.k-2.y)) relaxed!193))
(assert (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) relaxed!198))
(assert (or (and (= r.k+3.x r.k-1.x) (= r.k+3.y r.k-1.y)) relaxed!203))
(assert (or (and (= r.k+3.x r.k-2.x) (= r.k+3.y r.k-2.y)) relaxed!208))
(assert (or (and (= r.k+4.x r.k-1.x) (= r.k+4.y r.k-1.y)) relaxed!213))
(assert (or (and (= r.k+4.x r.k-2.x) (= r.k+4.y r.k-2.y)) relaxed!218))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!223))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!6 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!7 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!8 (and (> (- (- r.d.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.d.x 0.0) (- r.w.x 0.0)))))
      (a!9 (and (> (- r.d.x 0.0) (- 2.0)) (> 2.0 (- r.d.x 0.0))))
      (a!10 (and (> (- r.d.y 0.0) (- 2.0)) (> 2.0 (- r.d.y 0.0))))
      (a!13 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                 relaxed!286
                 relaxed!287))
      (a!14 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                 relaxed!293
                 relaxed!294))
      (a!15 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                 relaxed!300
                 relaxed!301))
      (a!16 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)))
                 relaxed!307
                 relaxed!308))
      (a!17 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!31 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!45 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!46 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!55 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!56 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!65 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!66 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!75 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!76 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!85 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!86 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!95 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!96 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (or (and a!9 (< 0.0 (- r.d.y 0.0)))
                (and a!9 (> 0.0 (- r.d.y 0.0)))
                (and a!10 (< 0.0 (- r.d.x 0.0)))
                (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!18 (or (and a!17 (< 0.0 (- 0.0 0.0))) (and a!17 (> 0.0 (- 0.0 0.0)))))
      (a!20 (not (and a!17 (> 0.0 (- 0.0 0.0)))))
      (a!27 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!32 (or (and a!31 (< 0.0 (- r.c.y 0.0)))
                (and a!31 (> 0.0 (- r.c.y 0.0)))
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!34 (not (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!40 (not (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!47 (or (and a!45 (< 0.0 (- r.k+1.y 0.0)))
                (and a!45 (> 0.0 (- r.k+1.y 0.0)))
                (and a!46 (< 0.0 (- r.k+1.x 0.0)))
                (and a!46 (> 0.0 (- r.k+1.x 0.0)))))
      (a!49 (not (and a!46 (> 0.0 (- r.k+1.x 0.0)))))
      (a!57 (or (and a!55 (< 0.0 (- r.k+2.y 0.0)))
                (and a!55 (> 0.0 (- r.k+2.y 0.0)))
                (and a!56 (< 0.0 (- r.k+2.x 0.0)))
                (and a!56 (> 0.0 (- r.k+2.x 0.0)))))
      (a!59 (not (and a!56 (> 0.0 (- r.k+2.x 0.0)))))
      (a!67 (or (and a!65 (< 0.0 (- r.k+3.y 0.0)))
                (and a!65 (> 0.0 (- r.k+3.y 0.0)))
                (and a!66 (< 0.0 (- r.k+3.x 0.0)))
                (and a!66 (> 0.0 (- r.k+3.x 0.0)))))
      (a!69 (not (and a!66 (> 0.0 (- r.k+3.x 0.0)))))
      (a!77 (or (and a!75 (< 0.0 (- r.k+4.y 0.0)))
                (and a!75 (> 0.0 (- r.k+4.y 0.0)))
                (and a!76 (< 0.0 (- r.k+4.x 0.0)))
                (and a!76 (> 0.0 (- r.k+4.x 0.0)))))
      (a!79 (not (and a!76 (> 0.0 (- r.k+4.x 0.0)))))
      (a!87 (or (and a!85 (< 0.0 (- r.k-1.y 0.0)))
                (and a!85 (> 0.0 (- r.k-1.y 0.0)))
                (and a!86 (< 0.0 (- r.k-1.x 0.0)))
                (and a!86 (> 0.0 (- r.k-1.x 0.0)))))
      (a!89 (not (and a!86 (> 0.0 (- r.k-1.x 0.0)))))
      (a!97 (or (and a!95 (< 0.0 (- r.k-2.y 0.0)))
                (and a!95 (> 0.0 (- r.k-2.y 0.0)))
                (and a!96 (< 0.0 (- r.k-2.x 0.0)))
                (and a!96 (> 0.0 (- r.k-2.x 0.0)))))
      (a!99 (not (and a!96 (> 0.0 (- r.k-2.x 0.0))))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!12 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!19 (not (and (not (or a!18 a!18))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!21 (not (and (not (or a!18 a!18))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!22 (and (not (or a!18 a!18)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!26 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!28 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!33 (not (and (not a!32) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!35 (not (and (not a!32) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!36 (and (not a!32) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!39 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!41 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!42 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!48 (not (and (not a!47)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!50 (not (and (not a!47)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!51 (and (not a!47) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!58 (not (and (not a!57)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!60 (not (and (not a!57)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!61 (and (not a!57) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!68 (not (and (not a!67)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!70 (not (and (not a!67)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!71 (and (not a!67) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!78 (not (and (not a!77)
                      (> 0.0 (- r.k+4.x 0.0))
                      (< 0.0 (- r.k+4.y 0.0)))))
      (a!80 (not (and (not a!77)
                      (> 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!81 (and (not a!77) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!88 (not (and (not a!87)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!90 (not (and (not a!87)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!91 (and (not a!87) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!98 (not (and (not a!97)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!100 (not (and (not a!97)
                       (> 0.0 (- r.k-2.x 0.0))
                       (> 0.0 (- r.k-2.y 0.0)))))
      (a!101 (and (not a!97) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0)))))
(let ((a!5 (or a!4
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!23 (or a!22
                (and a!17 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!18 a!18))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!24 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!22))
      (a!29 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!4))
      (a!37 (or a!36
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and (not a!32) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!43 (or a!42 (and a!10 (< 0.0 (- r.d.x 0.0))) a!12))
      (a!52 (or a!51
                (and a!46 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!47) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!53 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!51))
      (a!62 (or a!61
                (and a!56 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!57) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!63 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!61))
      (a!72 (or a!71
                (and a!66 (< 0.0 (- r.k+3.x 0.0)))
                (and (not a!67) (< 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0)))))
      (a!73 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 a!71))
      (a!82 (or a!81
                (and a!76 (< 0.0 (- r.k+4.x 0.0)))
                (and (not a!77) (< 0.0 (- r.k+4.x 0.0)) (> 0.0 (- r.k+4.y 0.0)))))
      (a!83 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 a!81))
      (a!92 (or a!91
                (and a!86 (< 0.0 (- r.k-1.x 0.0)))
                (and (not a!87) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0)))))
      (a!93 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 a!91))
      (a!102 (or a!101
                 (and a!96 (< 0.0 (- r.k-2.x 0.0)))
                 (and (not a!97)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!103 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  a!101)))
(let ((a!25 (and a!19
                 a!20
                 a!21
                 (=> a!23 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!24)
                 (not relaxed!345)))
      (a!30 (and a!26
                 a!27
                 a!28
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!29)
                 (not relaxed!362)))
      (a!38 (and a!33
                 a!34
                 a!35
                 (=> a!37 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!6 a!36))
                 (not relaxed!392)))
      (a!44 (and a!39
                 a!40
                 a!41
                 (=> a!43 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!42))
                 (not relaxed!408)))
      (a!54 (and a!48
                 a!49
                 a!50
                 (=> a!52 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!53)
                 (not relaxed!446)))
      (a!64 (and a!58
                 a!59
                 a!60
                 (=> a!62 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!63)
                 (not relaxed!484)))
      (a!74 (and a!68
                 a!69
                 a!70
                 (=> a!72 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 (not a!73)
                 (not relaxed!522)))
      (a!84 (and a!78
                 a!79
                 a!80
                 (=> a!82 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 (not a!83)
                 (not relaxed!560)))
      (a!94 (and a!88
                 a!89
                 a!90
                 (=> a!92 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!93)
                 (not relaxed!598)))
      (a!104 (and a!98
                  a!99
                  a!100
                  (=> a!102 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  (not a!103)
                  (not relaxed!636))))
(let ((a!105 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!227
                  a!5
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!250
                  a!6
                  (and a!7 (< 0.0 (- r.c.x 0.0)))
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  relaxed!260
                  a!8
                  a!12
                  (or (not relaxed!283) a!13)
                  (or (not relaxed!290) a!14)
                  (or (not relaxed!297) a!15)
                  (or (not relaxed!304) a!16)
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  relaxed!312
                  relaxed!313
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  relaxed!315
                  relaxed!316
                  relaxed!297
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!25))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!227 a!30))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!250 a!38))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> relaxed!260 a!44))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                      (=> relaxed!286 a!54))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                      (=> relaxed!293 a!64))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))
                      (=> relaxed!300 a!74))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))
                      (=> relaxed!307 a!84))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!312 a!94))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!315 a!104)))))
  (=> r.case0 a!105))))))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* 1.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* (- 1.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 9.0 5.0) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 8.0 5.0) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* 1.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* (- 1.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 9.0 5.0) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 8.0 5.0) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* 1.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* (- 1.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 9.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 8.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* 1.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* (- 1.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 9.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 8.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* 1.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* (- 1.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 9.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 8.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* 1.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* (- 1.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 9.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 8.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* 1.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* (- 1.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 9.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 8.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* 1.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* (- 1.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 9.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 8.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* 1.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* (- 1.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 9.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 8.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* 1.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* (- 1.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 9.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 8.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* 1.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* (- 1.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 9.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 8.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* 1.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* (- 1.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 9.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 8.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* 1.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* (- 1.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 9.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 8.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+3.x)) (* 0.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+3.x)) (* (/ 4.0 5.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+3.x)) (* 1.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 3.0 5.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+3.x)) (* 0.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+3.x)) (* (- 1.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+3.x)) (* (/ 4.0 5.0) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+3.x)) (* (/ 9.0 5.0) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 8.0 5.0) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 3.0 5.0) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+4.x)) (* 0.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+4.x)) (* (/ 4.0 5.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+4.x)) (* 1.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 3.0 5.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+4.x)) (* 0.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+4.x)) (* (- 1.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+4.x)) (* (/ 4.0 5.0) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+4.x)) (* (/ 9.0 5.0) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 8.0 5.0) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 3.0 5.0) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* 1.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* (- 1.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 9.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 8.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* 1.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* (- 1.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 9.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 8.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* 1.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* (- 1.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* 1.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* (- 1.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* 1.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* (- 1.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-1.x)) (* 0.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-1.x)) (* 1.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-1.x)) (* 0.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-1.x)) (* (- 1.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-2.x)) (* 0.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-2.x)) (* 1.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-2.x)) (* 0.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-2.x)) (* (- 1.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* 1.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* (- 1.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* 1.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* (- 1.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!183)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-1.x)) (* 0.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-1.x)) (* 1.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-1.x)) (* 0.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-1.x)) (* (- 1.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!188)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-2.x)) (* 0.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-2.x)) (* 1.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-2.x)) (* 0.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-2.x)) (* (- 1.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!193)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* 1.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* (- 1.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!198)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-1.x)) (* 0.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-1.x)) (* 1.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-1.x)) (* 0.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-1.x)) (* (- 1.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!203)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-2.x)) (* 0.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-2.x)) (* 1.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-2.x)) (* 0.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-2.x)) (* (- 1.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!208)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-1.x)) (* 0.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-1.x)) (* 1.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-1.x)) (* 0.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-1.x)) (* (- 1.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!213)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-2.x)) (* 0.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-2.x)) (* 1.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-2.x)) (* 0.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-2.x)) (* (- 1.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!218)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!223)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!250 a!1)))
; cut relaxed!250
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!250) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!260 a!1)))
; cut relaxed!260
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0)))) (=> (not relaxed!260) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!283 a!1)))
; cut relaxed!283
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0)))) (=> (not relaxed!283) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!286 a!1)))
; cut relaxed!286
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!286) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!287
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!287 (<= a!1 2.0))))
; cut relaxed!287
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!287) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!290 a!1)))
; cut relaxed!290
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0)))) (=> (not relaxed!290) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!293 a!1)))
; cut relaxed!293
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0)))) (=> (not relaxed!293) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!294
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!294 (<= a!1 2.0))))
; cut relaxed!294
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> (not relaxed!294) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!297 a!1)))
; cut relaxed!297
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!297) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* 1.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* (- 1.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!300 a!1)))
; cut relaxed!300
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 9.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 8.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0)))) (=> (not relaxed!300) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!301
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!301 (<= a!1 2.0))))
; cut relaxed!301
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> (not relaxed!301) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) 0.0))) (=> relaxed!304 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* 1.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* (- 1.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!307 a!1)))
; cut relaxed!307
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 9.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 8.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0)))) (=> (not relaxed!307) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!308
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!308 (<= a!1 2.0))))
; cut relaxed!308
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> (not relaxed!308) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!312 a!1)))
; cut relaxed!312
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!312) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!313
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!313 (<= a!1 2.0))))
; cut relaxed!313
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!313) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!315 a!1)))
; cut relaxed!315
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!315) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!316
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!316 (<= a!1 2.0))))
; cut relaxed!316
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!316) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!345
(assert (not relaxed!345))
; cut relaxed!362
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) (- 3.0))) (* 0.0 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 3.0))) (* 1.0 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) (- 3.0))) (* 0.0 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 3.0))) (* (- 1.0) 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!362 (<= a!1 2.0))))
; cut relaxed!362
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) (- 3.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!362) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!392
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> relaxed!392 (<= a!1 2.0))))
; cut relaxed!392
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 3.0)))))) (=> (not relaxed!392) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!408
(assert (let ((a!1 (+ (* 1.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* 0.0 (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) (- 3.0)))))) (=> relaxed!408 (<= a!1 2.0))))
; cut relaxed!408
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.d.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.d.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.d.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.d.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.d.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.d.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.d.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.d.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.d.y 0.0) (- 3.0)))))) (=> (not relaxed!408) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> relaxed!446 (<= a!1 2.0))))
; cut relaxed!446
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) (- 3.0)))))) (=> (not relaxed!446) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!484
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> relaxed!484 (<= a!1 2.0))))
; cut relaxed!484
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) (- 3.0)))))) (=> (not relaxed!484) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!522
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> relaxed!522 (<= a!1 2.0))))
; cut relaxed!522
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) (- 3.0)))))) (=> (not relaxed!522) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!560
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> relaxed!560 (<= a!1 2.0))))
; cut relaxed!560
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+4.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+4.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) (- 3.0)))))) (=> (not relaxed!560) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!598
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> relaxed!598 (<= a!1 2.0))))
; cut relaxed!598
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 3.0)))))) (=> (not relaxed!598) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!636
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> relaxed!636 (<= a!1 2.0))))
; cut relaxed!636
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 3.0)))))) (=> (not relaxed!636) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
