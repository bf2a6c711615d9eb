; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 69; cuts: 800
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x)) (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.w.x r.k+3.x) (- r.w.x r.k+3.x)) (* (- r.w.y r.k+3.y) (- r.w.y r.k+3.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.w.x r.k+4.x) (- r.w.x r.k+4.x)) (* (- r.w.y r.k+4.y) (- r.w.y r.k+4.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.w.x r.t.x) (- r.w.x r.t.x)) (* (- r.w.y r.t.y) (- r.w.y r.t.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x)) (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.c.x r.k+3.x) (- r.c.x r.k+3.x)) (* (- r.c.y r.k+3.y) (- r.c.y r.k+3.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.c.x r.k+4.x) (- r.c.x r.k+4.x)) (* (- r.c.y r.k+4.y) (- r.c.y r.k+4.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.c.x r.t.x) (- r.c.x r.t.x)) (* (- r.c.y r.t.y) (- r.c.y r.t.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.k-1.x r.k+1.x) (- r.k-1.x r.k+1.x)) (* (- r.k-1.y r.k+1.y) (- r.k-1.y r.k+1.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.k-1.x r.k+2.x) (- r.k-1.x r.k+2.x)) (* (- r.k-1.y r.k+2.y) (- r.k-1.y r.k+2.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.k-1.x r.k+3.x) (- r.k-1.x r.k+3.x)) (* (- r.k-1.y r.k+3.y) (- r.k-1.y r.k+3.y))))
; atom relaxed!183 (<= 4.0 (+ (* (- r.k-1.x r.k+4.x) (- r.k-1.x r.k+4.x)) (* (- r.k-1.y r.k+4.y) (- r.k-1.y r.k+4.y))))
; atom relaxed!188 (<= 4.0 (+ (* (- r.k-1.x r.t.x) (- r.k-1.x r.t.x)) (* (- r.k-1.y r.t.y) (- r.k-1.y r.t.y))))
; atom relaxed!193 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!198 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!203 (<= 4.0 (+ (* (- r.k-2.x r.k+1.x) (- r.k-2.x r.k+1.x)) (* (- r.k-2.y r.k+1.y) (- r.k-2.y r.k+1.y))))
; atom relaxed!208 (<= 4.0 (+ (* (- r.k-2.x r.k+2.x) (- r.k-2.x r.k+2.x)) (* (- r.k-2.y r.k+2.y) (- r.k-2.y r.k+2.y))))
; atom relaxed!213 (<= 4.0 (+ (* (- r.k-2.x r.k+3.x) (- r.k-2.x r.k+3.x)) (* (- r.k-2.y r.k+3.y) (- r.k-2.y r.k+3.y))))
; atom relaxed!218 (<= 4.0 (+ (* (- r.k-2.x r.k+4.x) (- r.k-2.x r.k+4.x)) (* (- r.k-2.y r.k+4.y) (- r.k-2.y r.k+4.y))))
; atom relaxed!223 (<= 4.0 (+ (* (- r.k-2.x r.t.x) (- r.k-2.x r.t.x)) (* (- r.k-2.y r.t.y) (- r.k-2.y r.t.y))))
; atom relaxed!228 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!233 (<= 4.0 (+ (* (- r.k-3.x r.k+1.x) (- r.k-3.x r.k+1.x)) (* (- r.k-3.y r.k+1.y) (- r.k-3.y r.k+1.y))))
; atom relaxed!238 (<= 4.0 (+ (* (- r.k-3.x r.k+2.x) (- r.k-3.x r.k+2.x)) (* (- r.k-3.y r.k+2.y) (- r.k-3.y r.k+2.y))))
; atom relaxed!243 (<= 4.0 (+ (* (- r.k-3.x r.k+3.x) (- r.k-3.x r.k+3.x)) (* (- r.k-3.y r.k+3.y) (- r.k-3.y r.k+3.y))))
; atom relaxed!248 (<= 4.0 (+ (* (- r.k-3.x r.k+4.x) (- r.k-3.x r.k+4.x)) (* (- r.k-3.y r.k+4.y) (- r.k-3.y r.k+4.y))))
; atom relaxed!253 (<= 4.0 (+ (* (- r.k-3.x r.t.x) (- r.k-3.x r.t.x)) (* (- r.k-3.y r.t.y) (- r.k-3.y r.t.y))))
; atom relaxed!258 (<= 4.0 (+ (* (- r.k-4.x r.k+1.x) (- r.k-4.x r.k+1.x)) (* (- r.k-4.y r.k+1.y) (- r.k-4.y r.k+1.y))))
; atom relaxed!263 (<= 4.0 (+ (* (- r.k-4.x r.k+2.x) (- r.k-4.x r.k+2.x)) (* (- r.k-4.y r.k+2.y) (- r.k-4.y r.k+2.y))))
; atom relaxed!268 (<= 4.0 (+ (* (- r.k-4.x r.k+3.x) (- r.k-4.x r.k+3.x)) (* (- r.k-4.y r.k+3.y) (- r.k-4.y r.k+3.y))))
; atom relaxed!273 (<= 4.0 (+ (* (- r.k-4.x r.k+4.x) (- r.k-4.x r.k+4.x)) (* (- r.k-4.y r.k+4.y) (- r.k-4.y r.k+4.y))))
; atom relaxed!278 (<= 4.0 (+ (* (- r.k-4.x r.t.x) (- r.k-4.x r.t.x)) (* (- r.k-4.y r.t.y) (- r.k-4.y r.t.y))))
; atom relaxed!283 (<= 4.0 (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x)) (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))
; atom relaxed!288 (<= 4.0 (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x)) (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))
; atom relaxed!293 (<= 4.0 (+ (* (- r.k+1.x r.k+4.x) (- r.k+1.x r.k+4.x)) (* (- r.k+1.y r.k+4.y) (- r.k+1.y r.k+4.y))))
; atom relaxed!298 (<= 4.0 (+ (* (- r.k+1.x r.t.x) (- r.k+1.x r.t.x)) (* (- r.k+1.y r.t.y) (- r.k+1.y r.t.y))))
; atom relaxed!303 (<= 4.0 (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x)) (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))
; atom relaxed!308 (<= 4.0 (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x)) (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))
; atom relaxed!313 (<= 4.0 (+ (* (- r.k+2.x r.t.x) (- r.k+2.x r.t.x)) (* (- r.k+2.y r.t.y) (- r.k+2.y r.t.y))))
; atom relaxed!318 (<= 4.0 (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x)) (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))
; atom relaxed!323 (<= 4.0 (+ (* (- r.k+3.x r.t.x) (- r.k+3.x r.t.x)) (* (- r.k+3.y r.t.y) (- r.k+3.y r.t.y))))
; atom relaxed!328 (<= 4.0 (+ (* (- r.k+4.x r.t.x) (- r.k+4.x r.t.x)) (* (- r.k+4.y r.t.y) (- r.k+4.y r.t.y))))
; atom relaxed!332 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!355 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!364 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0)))
; atom relaxed!367 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!368 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!371 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0)))
; atom relaxed!374 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!375 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!378 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!381 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!382 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!385 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0)))
; atom relaxed!388 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!389 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!393 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!394 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!398 (>= 16.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!399 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!403 (>= 16.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!404 (let ((a!1 (+ (* (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!408 (>= 16.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!409 (let ((a!1 (+ (* (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))) (> 4.0 a!1))
; atom relaxed!413 (>= 16.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
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
(declare-fun r.k+3.y () Real)
(declare-fun r.k+3.x () Real)
(declare-fun relaxed!48 () Bool)
(declare-fun r.k+4.y () Real)
(declare-fun r.k+4.x () Real)
(declare-fun relaxed!53 () Bool)
(declare-fun r.t.y () Real)
(declare-fun r.t.x () Real)
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
(declare-fun relaxed!228 () Bool)
(declare-fun relaxed!233 () Bool)
(declare-fun relaxed!238 () Bool)
(declare-fun relaxed!243 () Bool)
(declare-fun relaxed!248 () Bool)
(declare-fun relaxed!253 () Bool)
(declare-fun relaxed!258 () Bool)
(declare-fun relaxed!263 () Bool)
(declare-fun relaxed!268 () Bool)
(declare-fun relaxed!273 () Bool)
(declare-fun relaxed!278 () Bool)
(declare-fun relaxed!283 () Bool)
(declare-fun relaxed!288 () Bool)
(declare-fun relaxed!293 () Bool)
(declare-fun relaxed!298 () Bool)
(declare-fun relaxed!303 () Bool)
(declare-fun relaxed!308 () Bool)
(declare-fun relaxed!313 () Bool)
(declare-fun relaxed!318 () Bool)
(declare-fun relaxed!323 () Bool)
(declare-fun relaxed!328 () Bool)
(declare-fun relaxed!413 () Bool)
(declare-fun relaxed!408 () Bool)
(declare-fun relaxed!403 () Bool)
(declare-fun relaxed!398 () Bool)
(declare-fun relaxed!393 () Bool)
(declare-fun relaxed!388 () Bool)
(declare-fun relaxed!381 () Bool)
(declare-fun relaxed!374 () Bool)
(declare-fun relaxed!367 () Bool)
(declare-fun relaxed!355 () Bool)
(declare-fun relaxed!332 () Bool)
(declare-fun relaxed!409 () Bool)
(declare-fun relaxed!385 () Bool)
(declare-fun relaxed!404 () Bool)
(declare-fun relaxed!378 () Bool)
(declare-fun relaxed!399 () Bool)
(declare-fun relaxed!371 () Bool)
(declare-fun relaxed!394 () Bool)
(declare-fun relaxed!364 () Bool)
(declare-fun relaxed!389 () Bool)
(declare-fun relaxed!382 () Bool)
(declare-fun relaxed!375 () Bool)
(declare-fun relaxed!368 () Bool)
(declare-fun r.case0 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!8))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!28))
(assert (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)) relaxed!33))
(assert (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)) relaxed!38))
(assert (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)) relaxed!43))
(assert (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)) relaxed!48))
(assert (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) relaxed!53))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!58))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!63))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!68))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!73))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!78))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!83))
(assert (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) relaxed!88))
(assert (or (and (= r.w.x r.k+3.x) (= r.w.y r.k+3.y)) relaxed!93))
(assert (or (and (= r.w.x r.k+4.x) (= r.w.y r.k+4.y)) relaxed!98))
(assert (or (and (= r.w.x r.t.x) (= r.w.y r.t.y)) relaxed!103))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!108))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!113))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!118))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!123))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!128))
(assert (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) relaxed!133))
(assert (or (and (= r.c.x r.k+3.x) (= r.c.y r.k+3.y)) relaxed!138))
(assert (or (and (= r.c.x r.k+4.x) (= r.c.y r.k+4.y)) relaxed!143))
(assert (or (and (= r.c.x r.t.x) (= r.c.y r.t.y)) relaxed!148))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!153))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!158))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!163))
(assert (or (and (= r.k-1.x r.k+1.x) (= r.k-1.y r.k+1.y)) relaxed!168))
(assert (or (and (= r.k-1.x r.k+2.x) (= r.k-1.y r.k+2.y)) relaxed!173))
(assert (or (and (= r.k-1.x r.k+3.x) (= r.k-1.y r.k+3.y)) relaxed!178))
(assert (or (and (= r.k-1.x r.k+4.x) (= r.k-1.y r.k+4.y)) relaxed!183))
(assert (or (and (= r.k-1.x r.t.x) (= r.k-1.y r.t.y)) relaxed!188))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!193))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!198))
(assert (or (and (= r.k-2.x r.k+1.x) (= r.k-2.y r.k+1.y)) relaxed!203))
(assert (or (and (= r.k-2.x r.k+2.x) (= r.k-2.y r.k+2.y)) relaxed!208))
(assert (or (and (= r.k-2.x r.k+3.x) (= r.k-2.y r.k+3.y)) relaxed!213))
(assert (or (and (= r.k-2.x r.k+4.x) (= r.k-2.y r.k+4.y)) relaxed!218))
(assert (or (and (= r.k-2.x r.t.x) (= r.k-2.y r.t.y)) relaxed!223))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!228))
(assert (or (and (= r.k-3.x r.k+1.x) (= r.k-3.y r.k+1.y)) relaxed!233))
(assert (or (and (= r.k-3.x r.k+2.x) (= r.k-3.y r.k+2.y)) relaxed!238))
(assert (or (and (= r.k-3.x r.k+3.x) (= r.k-3.y r.k+3.y)) relaxed!243))
(assert (or (and (= r.k-3.x r.k+4.x) (= r.k-3.y r.k+4.y)) relaxed!248))
(assert (or (and (= r.k-3.x r.t.x) (= r.k-3.y r.t.y)) relaxed!253))
(assert (or (and (= r.k-4.x r.k+1.x) (= r.k-4.y r.k+1.y)) relaxed!258))
(assert (or (and (= r.k-4.x r.k+2.x) (= r.k-4.y r.k+2.y)) relaxed!263))
(assert (or (and (= r.k-4.x r.k+3.x) (= r.k-4.y r.k+3.y)) relaxed!268))
(assert (or (and (= r.k-4.x r.k+4.x) (= r.k-4.y r.k+4.y)) relaxed!273))
(assert (or (and (= r.k-4.x r.t.x) (= r.k-4.y r.t.y)) relaxed!278))
(assert (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) relaxed!283))
(assert (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) relaxed!288))
(assert (or (and (= r.k+1.x r.k+4.x) (= r.k+1.y r.k+4.y)) relaxed!293))
(assert (or (and (= r.k+1.x r.t.x) (= r.k+1.y r.t.y)) relaxed!298))
(assert (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) relaxed!303))
(assert (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) relaxed!308))
(assert (or (and (= r.k+2.x r.t.x) (= r.k+2.y r.t.y)) relaxed!313))
(assert (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) relaxed!318))
(assert (or (and (= r.k+3.x r.t.x) (= r.k+3.y r.t.y)) relaxed!323))
(assert (or (and (= r.k+4.x r.t.x) (= r.k+4.y r.t.y)) relaxed!328))
(assert (let ((a!1 (and (> (- r.w.x 0.0) (- 2.0)) (> 2.0 (- r.w.x 0.0))))
      (a!2 (and (> (- r.w.y 0.0) (- 2.0)) (> 2.0 (- r.w.y 0.0))))
      (a!7 (and (> (- (- r.c.x 0.0) (- r.w.x 0.0)) (- 2.0))
                (> 2.0 (- (- r.c.x 0.0) (- r.w.x 0.0)))))
      (a!8 (and (> (- r.c.y 0.0) (- 2.0)) (> 2.0 (- r.c.y 0.0))))
      (a!9 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                relaxed!367
                relaxed!368))
      (a!10 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 relaxed!374
                 relaxed!375))
      (a!11 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                 relaxed!381
                 relaxed!382))
      (a!12 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                 relaxed!388
                 relaxed!389))
      (a!13 (and (not (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y)))
                 relaxed!393
                 relaxed!394))
      (a!14 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                 relaxed!398
                 relaxed!399))
      (a!15 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                 relaxed!403
                 relaxed!404))
      (a!16 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)))
                 relaxed!408
                 relaxed!409))
      (a!17 (and (> (- r.t.x 0.0) (- 2.0)) (> 2.0 (- r.t.x 0.0))))
      (a!18 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!26 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))))
      (a!32 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))))
      (a!35 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!45 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!46 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!54 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))))
      (a!57 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!58 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!66 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))))
      (a!69 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!70 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!78 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))))
      (a!81 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!82 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!90 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))))
      (a!93 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!94 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!102 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))))
      (a!105 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!106 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!114 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))))
      (a!117 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!118 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!126 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))))
      (a!129 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!130 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!138 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))))
      (a!141 (and (> (- r.t.y 0.0) (- 2.0)) (> 2.0 (- r.t.y 0.0))))
      (a!149 (and (> (- (- r.t.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.t.x 0.0) (- r.w.x 0.0))))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!19 (or (and a!18 (< 0.0 (- 0.0 0.0))) (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!21 (not (and a!18 (> 0.0 (- 0.0 0.0)))))
      (a!27 (=> (and a!18 (> 0.0 (- 0.0 0.0))) (<= (- 0.0 0.0) (- r.t.y 0.0))))
      (a!30 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!33 (=> (and a!1 (> 0.0 (- r.w.y 0.0)))
                (<= (- r.w.y 0.0) (- r.t.y 0.0))))
      (a!36 (or (and a!35 (< 0.0 (- r.c.y 0.0)))
                (and a!35 (> 0.0 (- r.c.y 0.0)))
                (and a!8 (< 0.0 (- r.c.x 0.0)))
                (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!38 (not (and a!8 (> 0.0 (- r.c.x 0.0)))))
      (a!43 (=> (and a!35 (> 0.0 (- r.c.y 0.0)))
                (<= (- r.c.y 0.0) (- r.t.y 0.0))))
      (a!47 (or (and a!45 (< 0.0 (- r.k-1.y 0.0)))
                (and a!45 (> 0.0 (- r.k-1.y 0.0)))
                (and a!46 (< 0.0 (- r.k-1.x 0.0)))
                (and a!46 (> 0.0 (- r.k-1.x 0.0)))))
      (a!49 (not (and a!46 (> 0.0 (- r.k-1.x 0.0)))))
      (a!55 (=> (and a!45 (> 0.0 (- r.k-1.y 0.0)))
                (<= (- r.k-1.y 0.0) (- r.t.y 0.0))))
      (a!59 (or (and a!57 (< 0.0 (- r.k-2.y 0.0)))
                (and a!57 (> 0.0 (- r.k-2.y 0.0)))
                (and a!58 (< 0.0 (- r.k-2.x 0.0)))
                (and a!58 (> 0.0 (- r.k-2.x 0.0)))))
      (a!61 (not (and a!58 (> 0.0 (- r.k-2.x 0.0)))))
      (a!67 (=> (and a!57 (> 0.0 (- r.k-2.y 0.0)))
                (<= (- r.k-2.y 0.0) (- r.t.y 0.0))))
      (a!71 (or (and a!69 (< 0.0 (- r.k-3.y 0.0)))
                (and a!69 (> 0.0 (- r.k-3.y 0.0)))
                (and a!70 (< 0.0 (- r.k-3.x 0.0)))
                (and a!70 (> 0.0 (- r.k-3.x 0.0)))))
      (a!73 (not (and a!70 (> 0.0 (- r.k-3.x 0.0)))))
      (a!79 (=> (and a!69 (> 0.0 (- r.k-3.y 0.0)))
                (<= (- r.k-3.y 0.0) (- r.t.y 0.0))))
      (a!83 (or (and a!81 (< 0.0 (- r.k-4.y 0.0)))
                (and a!81 (> 0.0 (- r.k-4.y 0.0)))
                (and a!82 (< 0.0 (- r.k-4.x 0.0)))
                (and a!82 (> 0.0 (- r.k-4.x 0.0)))))
      (a!85 (not (and a!82 (> 0.0 (- r.k-4.x 0.0)))))
      (a!91 (=> (and a!81 (> 0.0 (- r.k-4.y 0.0)))
                (<= (- r.k-4.y 0.0) (- r.t.y 0.0))))
      (a!95 (or (and a!93 (< 0.0 (- r.k+1.y 0.0)))
                (and a!93 (> 0.0 (- r.k+1.y 0.0)))
                (and a!94 (< 0.0 (- r.k+1.x 0.0)))
                (and a!94 (> 0.0 (- r.k+1.x 0.0)))))
      (a!97 (not (and a!94 (> 0.0 (- r.k+1.x 0.0)))))
      (a!103 (=> (and a!93 (> 0.0 (- r.k+1.y 0.0)))
                 (<= (- r.k+1.y 0.0) (- r.t.y 0.0))))
      (a!107 (or (and a!105 (< 0.0 (- r.k+2.y 0.0)))
                 (and a!105 (> 0.0 (- r.k+2.y 0.0)))
                 (and a!106 (< 0.0 (- r.k+2.x 0.0)))
                 (and a!106 (> 0.0 (- r.k+2.x 0.0)))))
      (a!109 (not (and a!106 (> 0.0 (- r.k+2.x 0.0)))))
      (a!115 (=> (and a!105 (> 0.0 (- r.k+2.y 0.0)))
                 (<= (- r.k+2.y 0.0) (- r.t.y 0.0))))
      (a!119 (or (and a!117 (< 0.0 (- r.k+3.y 0.0)))
                 (and a!117 (> 0.0 (- r.k+3.y 0.0)))
                 (and a!118 (< 0.0 (- r.k+3.x 0.0)))
                 (and a!118 (> 0.0 (- r.k+3.x 0.0)))))
      (a!121 (not (and a!118 (> 0.0 (- r.k+3.x 0.0)))))
      (a!127 (=> (and a!117 (> 0.0 (- r.k+3.y 0.0)))
                 (<= (- r.k+3.y 0.0) (- r.t.y 0.0))))
      (a!131 (or (and a!129 (< 0.0 (- r.k+4.y 0.0)))
                 (and a!129 (> 0.0 (- r.k+4.y 0.0)))
                 (and a!130 (< 0.0 (- r.k+4.x 0.0)))
                 (and a!130 (> 0.0 (- r.k+4.x 0.0)))))
      (a!133 (not (and a!130 (> 0.0 (- r.k+4.x 0.0)))))
      (a!139 (=> (and a!129 (> 0.0 (- r.k+4.y 0.0)))
                 (<= (- r.k+4.y 0.0) (- r.t.y 0.0))))
      (a!142 (or (and a!17 (< 0.0 (- r.t.y 0.0)))
                 (and a!17 (> 0.0 (- r.t.y 0.0)))
                 (and a!141 (< 0.0 (- r.t.x 0.0)))
                 (and a!141 (> 0.0 (- r.t.x 0.0)))))
      (a!144 (not (and a!141 (> 0.0 (- r.t.x 0.0)))))
      (a!150 (=> (and a!17 (> 0.0 (- r.t.y 0.0)))
                 (<= (- r.t.y 0.0) (- r.t.y 0.0)))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!5 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0))))
      (a!20 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!22 (not (and (not (or a!19 a!19))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!23 (and (not (or a!19 a!19)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!24 (and (not (or a!19 a!19)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0))))
      (a!29 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!31 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!37 (not (and (not a!36) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!39 (not (and (not a!36) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!40 (and (not a!36) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!41 (and (not a!36) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0))))
      (a!48 (not (and (not a!47)
                      (> 0.0 (- r.k-1.x 0.0))
                      (< 0.0 (- r.k-1.y 0.0)))))
      (a!50 (not (and (not a!47)
                      (> 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!51 (and (not a!47) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!52 (and (not a!47) (< 0.0 (- r.k-1.x 0.0)) (> 0.0 (- r.k-1.y 0.0))))
      (a!60 (not (and (not a!59)
                      (> 0.0 (- r.k-2.x 0.0))
                      (< 0.0 (- r.k-2.y 0.0)))))
      (a!62 (not (and (not a!59)
                      (> 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!63 (and (not a!59) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!64 (and (not a!59) (< 0.0 (- r.k-2.x 0.0)) (> 0.0 (- r.k-2.y 0.0))))
      (a!72 (not (and (not a!71)
                      (> 0.0 (- r.k-3.x 0.0))
                      (< 0.0 (- r.k-3.y 0.0)))))
      (a!74 (not (and (not a!71)
                      (> 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!75 (and (not a!71) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0))))
      (a!76 (and (not a!71) (< 0.0 (- r.k-3.x 0.0)) (> 0.0 (- r.k-3.y 0.0))))
      (a!84 (not (and (not a!83)
                      (> 0.0 (- r.k-4.x 0.0))
                      (< 0.0 (- r.k-4.y 0.0)))))
      (a!86 (not (and (not a!83)
                      (> 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!87 (and (not a!83) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0))))
      (a!88 (and (not a!83) (< 0.0 (- r.k-4.x 0.0)) (> 0.0 (- r.k-4.y 0.0))))
      (a!96 (not (and (not a!95)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!98 (not (and (not a!95)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!99 (and (not a!95) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!100 (and (not a!95) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0))))
      (a!108 (not (and (not a!107)
                       (> 0.0 (- r.k+2.x 0.0))
                       (< 0.0 (- r.k+2.y 0.0)))))
      (a!110 (not (and (not a!107)
                       (> 0.0 (- r.k+2.x 0.0))
                       (> 0.0 (- r.k+2.y 0.0)))))
      (a!111 (and (not a!107) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!112 (and (not a!107) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0))))
      (a!120 (not (and (not a!119)
                       (> 0.0 (- r.k+3.x 0.0))
                       (< 0.0 (- r.k+3.y 0.0)))))
      (a!122 (not (and (not a!119)
                       (> 0.0 (- r.k+3.x 0.0))
                       (> 0.0 (- r.k+3.y 0.0)))))
      (a!123 (and (not a!119) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!124 (and (not a!119) (< 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0))))
      (a!132 (not (and (not a!131)
                       (> 0.0 (- r.k+4.x 0.0))
                       (< 0.0 (- r.k+4.y 0.0)))))
      (a!134 (not (and (not a!131)
                       (> 0.0 (- r.k+4.x 0.0))
                       (> 0.0 (- r.k+4.y 0.0)))))
      (a!135 (and (not a!131) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!136 (and (not a!131) (< 0.0 (- r.k+4.x 0.0)) (> 0.0 (- r.k+4.y 0.0))))
      (a!143 (not (and (not a!142) (> 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))))
      (a!145 (not (and (not a!142) (> 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!146 (and (not a!142) (< 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0))))
      (a!147 (and (not a!142) (< 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
(let ((a!6 (or a!4 (and a!2 (< 0.0 (- r.w.x 0.0))) a!5))
      (a!25 (or a!23 (and a!18 (< 0.0 (- 0.0 0.0))) a!24))
      (a!42 (or a!40 (and a!8 (< 0.0 (- r.c.x 0.0))) a!41))
      (a!53 (or a!51 (and a!46 (< 0.0 (- r.k-1.x 0.0))) a!52))
      (a!65 (or a!63 (and a!58 (< 0.0 (- r.k-2.x 0.0))) a!64))
      (a!77 (or a!75 (and a!70 (< 0.0 (- r.k-3.x 0.0))) a!76))
      (a!89 (or a!87 (and a!82 (< 0.0 (- r.k-4.x 0.0))) a!88))
      (a!101 (or a!99 (and a!94 (< 0.0 (- r.k+1.x 0.0))) a!100))
      (a!113 (or a!111 (and a!106 (< 0.0 (- r.k+2.x 0.0))) a!112))
      (a!125 (or a!123 (and a!118 (< 0.0 (- r.k+3.x 0.0))) a!124))
      (a!137 (or a!135 (and a!130 (< 0.0 (- r.k+4.x 0.0))) a!136))
      (a!148 (or a!146 (and a!141 (< 0.0 (- r.t.x 0.0))) a!147)))
(let ((a!28 (and a!20
                 a!21
                 a!22
                 (=> a!25 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not (and a!26 a!23))
                 (not (and a!26 a!24))
                 a!27))
      (a!34 (and a!29
                 a!30
                 a!31
                 (=> a!6 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not (and a!32 a!4))
                 (not (and a!32 a!5))
                 a!33))
      (a!44 (and a!37
                 a!38
                 a!39
                 (=> a!42 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!7 a!40))
                 (not (and a!7 a!41))
                 a!43))
      (a!56 (and a!48
                 a!49
                 a!50
                 (=> a!53 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not (and a!54 a!51))
                 (not (and a!54 a!52))
                 a!55))
      (a!68 (and a!60
                 a!61
                 a!62
                 (=> a!65 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not (and a!66 a!63))
                 (not (and a!66 a!64))
                 a!67))
      (a!80 (and a!72
                 a!73
                 a!74
                 (=> a!77 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not (and a!78 a!75))
                 (not (and a!78 a!76))
                 a!79))
      (a!92 (and a!84
                 a!85
                 a!86
                 (=> a!89 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not (and a!90 a!87))
                 (not (and a!90 a!88))
                 a!91))
      (a!104 (and a!96
                  a!97
                  a!98
                  (=> a!101 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                  (not (and a!102 a!99))
                  (not (and a!102 a!100))
                  a!103))
      (a!116 (and a!108
                  a!109
                  a!110
                  (=> a!113 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                  (not (and a!114 a!111))
                  (not (and a!114 a!112))
                  a!115))
      (a!128 (and a!120
                  a!121
                  a!122
                  (=> a!125 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                  (not (and a!126 a!123))
                  (not (and a!126 a!124))
                  a!127))
      (a!140 (and a!132
                  a!133
                  a!134
                  (=> a!137 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                  (not (and a!138 a!135))
                  (not (and a!138 a!136))
                  a!139))
      (a!151 (and a!143
                  a!144
                  a!145
                  (=> a!148 (>= (- r.t.x 0.0) (- r.w.x 0.0)))
                  (not (and a!149 a!146))
                  (not (and a!149 a!147))
                  a!150)))
(let ((a!152 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!332
                  a!6
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!355
                  a!7
                  (and a!8 (< 0.0 (- r.c.x 0.0)))
                  (or (not relaxed!364) a!9)
                  (or (not relaxed!371) a!10)
                  (or (not relaxed!378) a!11)
                  (or (not relaxed!385) a!12)
                  (or (not relaxed!364) a!13)
                  (or (not relaxed!371) a!14)
                  (or (not relaxed!378) a!15)
                  (or (not relaxed!385) a!16)
                  (not (and (= 0.0 r.t.x) (= 0.0 r.t.y)))
                  relaxed!413
                  (and a!17 (> 0.0 (- r.t.y 0.0)))
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!28))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!332 a!34))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!355 a!44))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!367 a!56))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!374 a!68))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!381 a!80))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!388 a!92))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                      (=> relaxed!393 a!104))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                      (=> relaxed!398 a!116))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))
                      (=> relaxed!403 a!128))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))
                      (=> relaxed!408 a!140))
                  (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) (=> relaxed!413 a!151)))))
  (=> r.case0 a!152))))))))
(assert (or r.case0))
(assert (and (>= 0.0 r.w.x)
     (>= 0.0 r.c.x)
     (>= 0.0 r.k-1.x)
     (>= 0.0 r.k-2.x)
     (>= 0.0 r.k-3.x)
     (>= 0.0 r.k-4.x)
     (>= 0.0 r.k+1.x)
     (>= 0.0 r.k+2.x)
     (>= 0.0 r.k+3.x)
     (>= 0.0 r.k+4.x)
     (>= 0.0 r.t.x)
     (distinct 0.0 (+ 0.0 0.0))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* 1.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* (- 1.0) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) 2.0))) (=> (not relaxed!43) a!1)))
; cut relaxed!43
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 9.0 5.0) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 8.0 5.0) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!43)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* 1.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* (- 1.0) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 9.0 5.0) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 8.0 5.0) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* 1.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* (- 1.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 9.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 8.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* 1.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* (- 1.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 9.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 8.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* 1.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* (- 1.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 9.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 8.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* 1.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* (- 1.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 9.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 8.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* 1.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* (- 1.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 9.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 8.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* 1.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* (- 1.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 9.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 8.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* 1.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* (- 1.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 9.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 8.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* 1.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* (- 1.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 9.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 8.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* 1.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+1.x)) (* 0.0 (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+1.x)) (* (- 1.0) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+2.x)) (* 0.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+2.x)) (* 1.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+2.x)) (* 0.0 (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+2.x)) (* (- 1.0) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+3.x)) (* 0.0 (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+3.x)) (* 1.0 (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+3.x)) (* 0.0 (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+3.x)) (* (- 1.0) (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k+4.x)) (* 0.0 (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+4.x)) (* 1.0 (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k+4.x)) (* 0.0 (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k+4.x)) (* (- 1.0) (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!183)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.t.x)) (* 0.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.t.x)) (* (/ 4.0 5.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.t.x)) (* 1.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 3.0 5.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.t.x)) (* 0.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.t.x)) (* (- 1.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.t.x)) (* (/ 4.0 5.0) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.t.x)) (* (/ 9.0 5.0) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 8.0 5.0) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 3.0 5.0) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!188)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!193)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!198)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* 1.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+1.x)) (* 0.0 (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+1.x)) (* (- 1.0) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!203)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+2.x)) (* 0.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+2.x)) (* 1.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+2.x)) (* 0.0 (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+2.x)) (* (- 1.0) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+2.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!208)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+3.x)) (* 0.0 (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+3.x)) (* 1.0 (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+3.x)) (* 0.0 (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+3.x)) (* (- 1.0) (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+3.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!213)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k+4.x)) (* 0.0 (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+4.x)) (* 1.0 (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k+4.x)) (* 0.0 (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k+4.x)) (* (- 1.0) (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+4.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!218)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.t.x)) (* 0.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.t.x)) (* (/ 4.0 5.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.t.x)) (* 1.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 3.0 5.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.t.x)) (* 0.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.t.x)) (* (- 1.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.t.x)) (* (/ 4.0 5.0) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.t.x)) (* (/ 9.0 5.0) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 8.0 5.0) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 3.0 5.0) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!223)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!228)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* 1.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+1.x)) (* 0.0 (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+1.x)) (* (- 1.0) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!233)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+2.x)) (* 0.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+2.x)) (* 1.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+2.x)) (* 0.0 (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+2.x)) (* (- 1.0) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+2.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!238)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+3.x)) (* 0.0 (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+3.x)) (* 1.0 (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+3.x)) (* 0.0 (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+3.x)) (* (- 1.0) (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+3.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!243)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k+4.x)) (* 0.0 (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+4.x)) (* 1.0 (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k+4.x)) (* 0.0 (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k+4.x)) (* (- 1.0) (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+4.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!248)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.t.x)) (* 0.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.t.x)) (* (/ 4.0 5.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.t.x)) (* 1.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 3.0 5.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.t.x)) (* 0.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.t.x)) (* (- 1.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.t.x)) (* (/ 4.0 5.0) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.t.x)) (* (/ 9.0 5.0) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 8.0 5.0) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 3.0 5.0) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!253)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* 1.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+1.x)) (* 0.0 (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+1.x)) (* (- 1.0) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+1.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+1.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!258)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+2.x)) (* 0.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+2.x)) (* 1.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+2.x)) (* 0.0 (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+2.x)) (* (- 1.0) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+2.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!263)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+3.x)) (* 0.0 (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+3.x)) (* 1.0 (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+3.x)) (* 0.0 (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+3.x)) (* (- 1.0) (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+3.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!268)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k+4.x)) (* 0.0 (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+4.x)) (* 1.0 (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k+4.x)) (* 0.0 (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k+4.x)) (* (- 1.0) (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+4.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!273)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.t.x)) (* 0.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.t.x)) (* (/ 4.0 5.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.t.x)) (* 1.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 3.0 5.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.t.x)) (* 0.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.t.x)) (* (- 1.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.t.x)) (* (/ 4.0 5.0) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.t.x)) (* (/ 9.0 5.0) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 8.0 5.0) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 3.0 5.0) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!278)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* 1.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* (- 1.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!283)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* 1.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* (- 1.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!288)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* 1.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* (- 1.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!293)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.t.x)) (* 0.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.t.x)) (* (/ 4.0 5.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.t.x)) (* 1.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 3.0 5.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.t.x)) (* 0.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.t.x)) (* (- 1.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.t.x)) (* (/ 4.0 5.0) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.t.x)) (* (/ 9.0 5.0) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 8.0 5.0) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 3.0 5.0) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!298)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* 1.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* (- 1.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!303)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* 1.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* (- 1.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!308)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.t.x)) (* 0.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.t.x)) (* (/ 4.0 5.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.t.x)) (* 1.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 3.0 5.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.t.x)) (* 0.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.t.x)) (* (- 1.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.t.x)) (* (/ 4.0 5.0) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.t.x)) (* (/ 9.0 5.0) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 8.0 5.0) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 3.0 5.0) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!313)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* 1.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* (- 1.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!318)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.t.x)) (* 0.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.t.x)) (* (/ 4.0 5.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.t.x)) (* 1.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 3.0 5.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.t.x)) (* 0.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.t.x)) (* (- 1.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.t.x)) (* (/ 4.0 5.0) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.t.x)) (* (/ 9.0 5.0) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 8.0 5.0) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 3.0 5.0) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!323)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.t.x)) (* 0.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.t.x)) (* (/ 4.0 5.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.t.x)) (* 1.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 3.0 5.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.t.x)) (* 0.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.t.x)) (* (- 1.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.t.x)) (* (/ 4.0 5.0) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.t.x)) (* (/ 9.0 5.0) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 8.0 5.0) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 3.0 5.0) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!328)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!332 a!1)))
; cut relaxed!332
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!332) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!355 a!1)))
; cut relaxed!355
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!355) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!364 a!1)))
; cut relaxed!364
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0)))) (=> (not relaxed!364) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!367 a!1)))
; cut relaxed!367
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!367) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!368
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!368 (<= a!1 2.0))))
; cut relaxed!368
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!368) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!371 a!1)))
; cut relaxed!371
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0)))) (=> (not relaxed!371) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!374 a!1)))
; cut relaxed!374
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!374) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!375
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!375 (<= a!1 2.0))))
; cut relaxed!375
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!375) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!378 a!1)))
; cut relaxed!378
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!378) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!381 a!1)))
; cut relaxed!381
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!381) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!382 (<= a!1 2.0))))
; cut relaxed!382
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!382) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!385
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) 0.0))) (=> relaxed!385 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!388 a!1)))
; cut relaxed!388
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!388) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!389
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!389 (<= a!1 2.0))))
; cut relaxed!389
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!389) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!393 a!1)))
; cut relaxed!393
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!393) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!394
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!394 (<= a!1 2.0))))
; cut relaxed!394
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!394) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!398 a!1)))
; cut relaxed!398
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0)))) (=> (not relaxed!398) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!399
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!399 (<= a!1 2.0))))
; cut relaxed!399
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> (not relaxed!399) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* 1.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* (- 1.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 9.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 8.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0)))) (=> (not relaxed!403) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> (not relaxed!404) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* 1.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* (- 1.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!408 a!1)))
; cut relaxed!408
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 9.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 8.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0)))) (=> (not relaxed!408) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!409 (<= a!1 2.0))))
; cut relaxed!409
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> (not relaxed!409) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!413 a!1)))
; cut relaxed!413
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0)))) (=> (not relaxed!413) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
(check-sat)
