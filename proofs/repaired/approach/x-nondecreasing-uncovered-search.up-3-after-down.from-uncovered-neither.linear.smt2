; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 39; cuts: 558
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x)) (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x)) (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.k-1.x r.k+1.x) (- r.k-1.x r.k+1.x)) (* (- r.k-1.y r.k+1.y) (- r.k-1.y r.k+1.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.k-1.x r.k+2.x) (- r.k-1.x r.k+2.x)) (* (- r.k-1.y r.k+2.y) (- r.k-1.y r.k+2.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.k-2.x r.k+1.x) (- r.k-2.x r.k+1.x)) (* (- r.k-2.y r.k+1.y) (- r.k-2.y r.k+1.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.k-2.x r.k+2.x) (- r.k-2.x r.k+2.x)) (* (- r.k-2.y r.k+2.y) (- r.k-2.y r.k+2.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.k-3.x r.k+1.x) (- r.k-3.x r.k+1.x)) (* (- r.k-3.y r.k+1.y) (- r.k-3.y r.k+1.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.k-3.x r.k+2.x) (- r.k-3.x r.k+2.x)) (* (- r.k-3.y r.k+2.y) (- r.k-3.y r.k+2.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.k-4.x r.k+1.x) (- r.k-4.x r.k+1.x)) (* (- r.k-4.y r.k+1.y) (- r.k-4.y r.k+1.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.k-4.x r.k+2.x) (- r.k-4.x r.k+2.x)) (* (- r.k-4.y r.k+2.y) (- r.k-4.y r.k+2.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x)) (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))
; atom relaxed!182 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!205 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!214 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0)))
; atom relaxed!217 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!218 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!221 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0)))
; atom relaxed!224 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!225 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!228 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!231 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!232 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!235 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0)))
; atom relaxed!238 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!239 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!243 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!244 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!246 (>= 16.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!247 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!278 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) 3.0) (- (- 0.0 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!297 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) 3.0) (- (- r.w.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!329 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) 3.0) (- (- r.c.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!369 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) 3.0) (- (- r.k-1.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!409 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) 3.0) (- (- r.k-2.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!449 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) 3.0) (- (- r.k-3.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!489 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) 3.0) (- (- r.k-4.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!529 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 3.0) (- (- r.k+1.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!569 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 3.0) (- (- r.k+2.y 0.0) 3.0))))) (> 4.0 a!1))
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
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun relaxed!28 () Bool)
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun relaxed!33 () Bool)
(declare-fun r.k+1.y () Real)
(declare-fun r.k+1.x () Real)
(declare-fun relaxed!38 () Bool)
(declare-fun r.k+2.y () Real)
(declare-fun r.k+2.x () Real)
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
(declare-fun relaxed!569 () Bool)
(declare-fun relaxed!246 () Bool)
(declare-fun relaxed!529 () Bool)
(declare-fun relaxed!243 () Bool)
(declare-fun relaxed!489 () Bool)
(declare-fun relaxed!238 () Bool)
(declare-fun relaxed!449 () Bool)
(declare-fun relaxed!231 () Bool)
(declare-fun relaxed!409 () Bool)
(declare-fun relaxed!224 () Bool)
(declare-fun relaxed!369 () Bool)
(declare-fun relaxed!217 () Bool)
(declare-fun relaxed!329 () Bool)
(declare-fun relaxed!205 () Bool)
(declare-fun relaxed!297 () Bool)
(declare-fun relaxed!182 () Bool)
(declare-fun relaxed!278 () Bool)
(declare-fun relaxed!228 () Bool)
(declare-fun relaxed!247 () Bool)
(declare-fun relaxed!244 () Bool)
(declare-fun relaxed!239 () Bool)
(declare-fun relaxed!235 () Bool)
(declare-fun relaxed!232 () Bool)
(declare-fun relaxed!225 () Bool)
(declare-fun relaxed!221 () Bool)
(declare-fun relaxed!218 () Bool)
(declare-fun relaxed!214 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!28))
(assert (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) relaxed!33))
(assert (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) relaxed!38))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!43))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!48))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!53))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!58))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!63))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!68))
(assert (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) relaxed!73))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!78))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!83))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!88))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!93))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!98))
(assert (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) relaxed!103))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!108))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!113))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!118))
(assert (or (and (= r.k-1.x r.k+1.x) (= r.k-1.y r.k+1.y)) relaxed!123))
(assert (or (and (= r.k-1.x r.k+2.x) (= r.k-1.y r.k+2.y)) relaxed!128))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!133))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!138))
(assert (or (and (= r.k-2.x r.k+1.x) (= r.k-2.y r.k+1.y)) relaxed!143))
(assert (or (and (= r.k-2.x r.k+2.x) (= r.k-2.y r.k+2.y)) relaxed!148))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!153))
(assert (or (and (= r.k-3.x r.k+1.x) (= r.k-3.y r.k+1.y)) relaxed!158))
(assert (or (and (= r.k-3.x r.k+2.x) (= r.k-3.y r.k+2.y)) relaxed!163))
(assert (or (and (= r.k-4.x r.k+1.x) (= r.k-4.y r.k+1.y)) relaxed!168))
(assert (or (and (= r.k-4.x r.k+2.x) (= r.k-4.y r.k+2.y)) relaxed!173))
(assert (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) relaxed!178))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!8 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!9 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                relaxed!217
                relaxed!218))
      (a!10 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 relaxed!224
                 relaxed!225))
      (a!11 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                 relaxed!231
                 relaxed!232))
      (a!12 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                 relaxed!238
                 relaxed!239))
      (a!13 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!21 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!26 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!28 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!37 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!38 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!46 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))))
      (a!48 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!49 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!57 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))))
      (a!59 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!60 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!68 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))))
      (a!70 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!71 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!79 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))))
      (a!81 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!82 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!90 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))))
      (a!92 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!93 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!101 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!14 (or (and a!13 (< 0.0 (- 0.0 0.0))) (and a!13 (> 0.0 (- 0.0 0.0)))))
      (a!16 (not (and a!13 (> 0.0 (- 0.0 0.0)))))
      (a!24 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!29 (or (and a!28 (< 0.0 (- r.c.y 0.0)))
                (and a!28 (> 0.0 (- r.c.y 0.0)))
                (and a!8 (< 0.0 (- r.c.x 0.0)))
                (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!31 (not (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!39 (or (and a!37 (< 0.0 (- r.k-1.y 0.0)))
                (and a!37 (> 0.0 (- r.k-1.y 0.0)))
                (and a!38 (< 0.0 (- r.k-1.x 0.0)))
                (and a!38 (> 0.0 (- r.k-1.x 0.0)))))
      (a!41 (not (and a!38 (> 0.0 (- r.k-1.x 0.0)))))
      (a!50 (or (and a!48 (< 0.0 (- r.k-2.y 0.0)))
                (and a!48 (> 0.0 (- r.k-2.y 0.0)))
                (and a!49 (< 0.0 (- r.k-2.x 0.0)))
                (and a!49 (> 0.0 (- r.k-2.x 0.0)))))
      (a!52 (not (and a!49 (> 0.0 (- r.k-2.x 0.0)))))
      (a!61 (or (and a!59 (< 0.0 (- r.k-3.y 0.0)))
                (and a!59 (> 0.0 (- r.k-3.y 0.0)))
                (and a!60 (< 0.0 (- r.k-3.x 0.0)))
                (and a!60 (> 0.0 (- r.k-3.x 0.0)))))
      (a!63 (not (and a!60 (> 0.0 (- r.k-3.x 0.0)))))
      (a!72 (or (and a!70 (< 0.0 (- r.k-4.y 0.0)))
                (and a!70 (> 0.0 (- r.k-4.y 0.0)))
                (and a!71 (< 0.0 (- r.k-4.x 0.0)))
                (and a!71 (> 0.0 (- r.k-4.x 0.0)))))
      (a!74 (not (and a!71 (> 0.0 (- r.k-4.x 0.0)))))
      (a!83 (or (and a!81 (< 0.0 (- r.k+1.y 0.0)))
                (and a!81 (> 0.0 (- r.k+1.y 0.0)))
                (and a!82 (< 0.0 (- r.k+1.x 0.0)))
                (and a!82 (> 0.0 (- r.k+1.x 0.0)))))
      (a!85 (not (and a!82 (> 0.0 (- r.k+1.x 0.0)))))
      (a!94 (or (and a!92 (< 0.0 (- r.k+2.y 0.0)))
                (and a!92 (> 0.0 (- r.k+2.y 0.0)))
                (and a!93 (< 0.0 (- r.k+2.x 0.0)))
                (and a!93 (> 0.0 (- r.k+2.x 0.0)))))
      (a!96 (not (and a!93 (> 0.0 (- r.k+2.x 0.0))))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!5 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!15 (not (and (not (or a!14 a!14))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!17 (not (and (not (or a!14 a!14))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!18 (and (not (or a!14 a!14)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!19 (and (not (or a!14 a!14)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!23 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!25 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!30 (not (and (not a!29) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!32 (not (and (not a!29) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!33 (and (not a!29) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!34 (and (not a!29) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0))))
      (a!40 (not (and (not a!39)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!42 (not (and (not a!39)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!43 (and (not a!39) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!44 (and (not a!39) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0))))
      (a!51 (not (and (not a!50)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!53 (not (and (not a!50)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!54 (and (not a!50) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!55 (and (not a!50) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0))))
      (a!62 (not (and (not a!61)
                      (> 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))))
      (a!64 (not (and (not a!61)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!65 (and (not a!61) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0))))
      (a!66 (and (not a!61) (< 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0))))
      (a!73 (not (and (not a!72)
                      (> 0.0 (- r.k-4.x 0.0))
                      (< 0.0 (- r.k-4.y 0.0)))))
      (a!75 (not (and (not a!72)
                      (> 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!76 (and (not a!72) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0))))
      (a!77 (and (not a!72) (< 0.0 (- r.k-4.x 0.0)) (> 0.0 (- r.k-4.y 0.0))))
      (a!84 (not (and (not a!83)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!86 (not (and (not a!83)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!87 (and (not a!83) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!88 (and (not a!83) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0))))
      (a!95 (not (and (not a!94)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!97 (not (and (not a!94)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!98 (and (not a!94) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!99 (and (not a!94) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
(let ((a!6 (or a!4 (and a!2 (< 0.0 (- r.w.x 0.0))) a!5))
      (a!20 (or a!18 (and a!13 (< 0.0 (- 0.0 0.0))) a!19))
      (a!35 (or a!33 (and a!8 (< 0.0 (- r.c.x 0.0))) a!34))
      (a!45 (or a!43 (and a!38 (< 0.0 (- r.k-1.x 0.0))) a!44))
      (a!56 (or a!54 (and a!49 (< 0.0 (- r.k-2.x 0.0))) a!55))
      (a!67 (or a!65 (and a!60 (< 0.0 (- r.k-3.x 0.0))) a!66))
      (a!78 (or a!76 (and a!71 (< 0.0 (- r.k-4.x 0.0))) a!77))
      (a!89 (or a!87 (and a!82 (< 0.0 (- r.k+1.x 0.0))) a!88))
      (a!100 (or a!98 (and a!93 (< 0.0 (- r.k+2.x 0.0))) a!99)))
(let ((a!22 (and a!15
                 a!16
                 a!17
                 (=> a!20 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!21 a!18))
                 (not (and a!21 a!19))
                 (not relaxed!278)))
      (a!27 (and a!23
                 a!24
                 a!25
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!26 a!4))
                 (not (and a!26 a!5))
                 (not relaxed!297)))
      (a!36 (and a!30
                 a!31
                 a!32
                 (=> a!35 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!7 a!33))
                 (not (and a!7 a!34))
                 (not relaxed!329)))
      (a!47 (and a!40
                 a!41
                 a!42
                 (=> a!45 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (and a!46 a!43))
                 (not (and a!46 a!44))
                 (not relaxed!369)))
      (a!58 (and a!51
                 a!52
                 a!53
                 (=> a!56 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not (and a!57 a!54))
                 (not (and a!57 a!55))
                 (not relaxed!409)))
      (a!69 (and a!62
                 a!63
                 a!64
                 (=> a!67 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not (and a!68 a!65))
                 (not (and a!68 a!66))
                 (not relaxed!449)))
      (a!80 (and a!73
                 a!74
                 a!75
                 (=> a!78 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not (and a!79 a!76))
                 (not (and a!79 a!77))
                 (not relaxed!489)))
      (a!91 (and a!84
                 a!85
                 a!86
                 (=> a!89 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not (and a!90 a!87))
                 (not (and a!90 a!88))
                 (not relaxed!529)))
      (a!102 (and a!95
                  a!96
                  a!97
                  (=> a!100 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                  (not (and a!101 a!98))
                  (not (and a!101 a!99))
                  (not relaxed!569))))
(let ((a!103 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!182
                  a!6
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!205
                  a!7
                  (and a!8 (< 0.0 (- r.c.x 0.0)))
                  (or (not relaxed!214) a!9)
                  (or (not relaxed!221) a!10)
                  (or (not relaxed!228) a!11)
                  (or (not relaxed!235) a!12)
                  (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                  relaxed!243
                  relaxed!244
                  (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                  relaxed!246
                  relaxed!247
                  relaxed!228
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!22))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!182 a!27))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!205 a!36))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!217 a!47))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!224 a!58))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!231 a!69))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!238 a!80))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                      (=> relaxed!243 a!91))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                      (=> relaxed!246 a!102)))))
  (=> r.case0 a!103))))))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!23) a!1)))
; cut relaxed!23
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!23)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!28) a!1)))
; cut relaxed!28
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!28)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 2.0))) (=> (not relaxed!33) a!1)))
; cut relaxed!33
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!33)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 2.0))) (=> (not relaxed!38) a!1)))
; cut relaxed!38
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!38)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* 1.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* (- 1.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 9.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 8.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* 1.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* (- 1.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 9.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 8.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* 1.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* (- 1.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 9.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 8.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* 1.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* (- 1.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+2.x)) (* 0.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+2.x)) (* 1.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+2.x)) (* 0.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+2.x)) (* (- 1.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* 1.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* (- 1.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+2.x)) (* 0.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+2.x)) (* 1.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+2.x)) (* 0.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+2.x)) (* (- 1.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* 1.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* (- 1.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+2.x)) (* 0.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+2.x)) (* 1.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+2.x)) (* 0.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+2.x)) (* (- 1.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* 1.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* (- 1.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+2.x)) (* 0.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+2.x)) (* 1.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+2.x)) (* 0.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+2.x)) (* (- 1.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* 1.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* (- 1.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!205 a!1)))
; cut relaxed!205
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!205) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!214 a!1)))
; cut relaxed!214
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0)))) (=> (not relaxed!214) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!217 a!1)))
; cut relaxed!217
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!217) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!218 (<= a!1 2.0))))
; cut relaxed!218
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!218) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!221 a!1)))
; cut relaxed!221
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0)))) (=> (not relaxed!221) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!224 a!1)))
; cut relaxed!224
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!224) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!225
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!225 (<= a!1 2.0))))
; cut relaxed!225
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!225) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!228 a!1)))
; cut relaxed!228
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!228) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!231 a!1)))
; cut relaxed!231
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!231) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!232
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!232 (<= a!1 2.0))))
; cut relaxed!232
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!232) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!235
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) 0.0))) (=> relaxed!235 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!238 a!1)))
; cut relaxed!238
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!238) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!239
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!239 (<= a!1 2.0))))
; cut relaxed!239
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!239) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!243 a!1)))
; cut relaxed!243
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!243) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!244
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!244 (<= a!1 2.0))))
; cut relaxed!244
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!244) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!246 a!1)))
; cut relaxed!246
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0)))) (=> (not relaxed!246) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!247
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!247 (<= a!1 2.0))))
; cut relaxed!247
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> (not relaxed!247) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!278
(assert (not relaxed!278))
; cut relaxed!297
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) 3.0)) (* 0.0 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 3.0)) (* 1.0 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) 3.0)) (* 0.0 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) 3.0)) (* (- 1.0) 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!297 (<= a!1 2.0))))
; cut relaxed!297
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) 3.0)) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) 3.0)) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!297) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!329
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> relaxed!329 (<= a!1 2.0))))
; cut relaxed!329
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) 3.0))))) (=> (not relaxed!329) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!369
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) 3.0))))) (=> relaxed!369 (<= a!1 2.0))))
; cut relaxed!369
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) 3.0))))) (=> (not relaxed!369) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) 3.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) 3.0))))) (=> (not relaxed!409) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!449
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) 3.0))))) (=> relaxed!449 (<= a!1 2.0))))
; cut relaxed!449
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) 3.0))))) (=> (not relaxed!449) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!489
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) 3.0))))) (=> relaxed!489 (<= a!1 2.0))))
; cut relaxed!489
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) 3.0))))) (=> (not relaxed!489) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!529
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> relaxed!529 (<= a!1 2.0))))
; cut relaxed!529
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 3.0))))) (=> (not relaxed!529) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> relaxed!569 (<= a!1 2.0))))
; cut relaxed!569
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 3.0))))) (=> (not relaxed!569) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
(check-sat)
