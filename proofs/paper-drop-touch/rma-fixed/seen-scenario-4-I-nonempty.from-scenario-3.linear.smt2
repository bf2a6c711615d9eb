; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 81; cuts: 917
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!53 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!58 (<= 4.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
; atom relaxed!63 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!68 (<= 4.0 (+ (* (- r.w.x r.d.x) (- r.w.x r.d.x)) (* (- r.w.y r.d.y) (- r.w.y r.d.y))))
; atom relaxed!73 (<= 4.0 (+ (* (- r.w.x r.k+1.x) (- r.w.x r.k+1.x)) (* (- r.w.y r.k+1.y) (- r.w.y r.k+1.y))))
; atom relaxed!78 (<= 4.0 (+ (* (- r.w.x r.k+2.x) (- r.w.x r.k+2.x)) (* (- r.w.y r.k+2.y) (- r.w.y r.k+2.y))))
; atom relaxed!83 (<= 4.0 (+ (* (- r.w.x r.k+3.x) (- r.w.x r.k+3.x)) (* (- r.w.y r.k+3.y) (- r.w.y r.k+3.y))))
; atom relaxed!88 (<= 4.0 (+ (* (- r.w.x r.k+4.x) (- r.w.x r.k+4.x)) (* (- r.w.y r.k+4.y) (- r.w.y r.k+4.y))))
; atom relaxed!93 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!98 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!103 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!108 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!113 (<= 4.0 (+ (* (- r.w.x r.t.x) (- r.w.x r.t.x)) (* (- r.w.y r.t.y) (- r.w.y r.t.y))))
; atom relaxed!118 (<= 4.0 (+ (* (- r.c.x r.d.x) (- r.c.x r.d.x)) (* (- r.c.y r.d.y) (- r.c.y r.d.y))))
; atom relaxed!123 (<= 4.0 (+ (* (- r.c.x r.k+1.x) (- r.c.x r.k+1.x)) (* (- r.c.y r.k+1.y) (- r.c.y r.k+1.y))))
; atom relaxed!128 (<= 4.0 (+ (* (- r.c.x r.k+2.x) (- r.c.x r.k+2.x)) (* (- r.c.y r.k+2.y) (- r.c.y r.k+2.y))))
; atom relaxed!133 (<= 4.0 (+ (* (- r.c.x r.k+3.x) (- r.c.x r.k+3.x)) (* (- r.c.y r.k+3.y) (- r.c.y r.k+3.y))))
; atom relaxed!138 (<= 4.0 (+ (* (- r.c.x r.k+4.x) (- r.c.x r.k+4.x)) (* (- r.c.y r.k+4.y) (- r.c.y r.k+4.y))))
; atom relaxed!143 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!148 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!153 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!158 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!163 (<= 4.0 (+ (* (- r.c.x r.t.x) (- r.c.x r.t.x)) (* (- r.c.y r.t.y) (- r.c.y r.t.y))))
; atom relaxed!168 (<= 4.0 (+ (* (- r.d.x r.k+1.x) (- r.d.x r.k+1.x)) (* (- r.d.y r.k+1.y) (- r.d.y r.k+1.y))))
; atom relaxed!173 (<= 4.0 (+ (* (- r.d.x r.k+2.x) (- r.d.x r.k+2.x)) (* (- r.d.y r.k+2.y) (- r.d.y r.k+2.y))))
; atom relaxed!178 (<= 4.0 (+ (* (- r.d.x r.k+3.x) (- r.d.x r.k+3.x)) (* (- r.d.y r.k+3.y) (- r.d.y r.k+3.y))))
; atom relaxed!183 (<= 4.0 (+ (* (- r.d.x r.k+4.x) (- r.d.x r.k+4.x)) (* (- r.d.y r.k+4.y) (- r.d.y r.k+4.y))))
; atom relaxed!188 (<= 4.0 (+ (* (- r.d.x r.k-1.x) (- r.d.x r.k-1.x)) (* (- r.d.y r.k-1.y) (- r.d.y r.k-1.y))))
; atom relaxed!193 (<= 4.0 (+ (* (- r.d.x r.k-2.x) (- r.d.x r.k-2.x)) (* (- r.d.y r.k-2.y) (- r.d.y r.k-2.y))))
; atom relaxed!198 (<= 4.0 (+ (* (- r.d.x r.k-3.x) (- r.d.x r.k-3.x)) (* (- r.d.y r.k-3.y) (- r.d.y r.k-3.y))))
; atom relaxed!203 (<= 4.0 (+ (* (- r.d.x r.k-4.x) (- r.d.x r.k-4.x)) (* (- r.d.y r.k-4.y) (- r.d.y r.k-4.y))))
; atom relaxed!208 (<= 4.0 (+ (* (- r.d.x r.t.x) (- r.d.x r.t.x)) (* (- r.d.y r.t.y) (- r.d.y r.t.y))))
; atom relaxed!213 (<= 4.0 (+ (* (- r.k+1.x r.k+2.x) (- r.k+1.x r.k+2.x)) (* (- r.k+1.y r.k+2.y) (- r.k+1.y r.k+2.y))))
; atom relaxed!218 (<= 4.0 (+ (* (- r.k+1.x r.k+3.x) (- r.k+1.x r.k+3.x)) (* (- r.k+1.y r.k+3.y) (- r.k+1.y r.k+3.y))))
; atom relaxed!223 (<= 4.0 (+ (* (- r.k+1.x r.k+4.x) (- r.k+1.x r.k+4.x)) (* (- r.k+1.y r.k+4.y) (- r.k+1.y r.k+4.y))))
; atom relaxed!228 (<= 4.0 (+ (* (- r.k+1.x r.k-1.x) (- r.k+1.x r.k-1.x)) (* (- r.k+1.y r.k-1.y) (- r.k+1.y r.k-1.y))))
; atom relaxed!233 (<= 4.0 (+ (* (- r.k+1.x r.k-2.x) (- r.k+1.x r.k-2.x)) (* (- r.k+1.y r.k-2.y) (- r.k+1.y r.k-2.y))))
; atom relaxed!238 (<= 4.0 (+ (* (- r.k+1.x r.k-3.x) (- r.k+1.x r.k-3.x)) (* (- r.k+1.y r.k-3.y) (- r.k+1.y r.k-3.y))))
; atom relaxed!243 (<= 4.0 (+ (* (- r.k+1.x r.k-4.x) (- r.k+1.x r.k-4.x)) (* (- r.k+1.y r.k-4.y) (- r.k+1.y r.k-4.y))))
; atom relaxed!248 (<= 4.0 (+ (* (- r.k+1.x r.t.x) (- r.k+1.x r.t.x)) (* (- r.k+1.y r.t.y) (- r.k+1.y r.t.y))))
; atom relaxed!253 (<= 4.0 (+ (* (- r.k+2.x r.k+3.x) (- r.k+2.x r.k+3.x)) (* (- r.k+2.y r.k+3.y) (- r.k+2.y r.k+3.y))))
; atom relaxed!258 (<= 4.0 (+ (* (- r.k+2.x r.k+4.x) (- r.k+2.x r.k+4.x)) (* (- r.k+2.y r.k+4.y) (- r.k+2.y r.k+4.y))))
; atom relaxed!263 (<= 4.0 (+ (* (- r.k+2.x r.k-1.x) (- r.k+2.x r.k-1.x)) (* (- r.k+2.y r.k-1.y) (- r.k+2.y r.k-1.y))))
; atom relaxed!268 (<= 4.0 (+ (* (- r.k+2.x r.k-2.x) (- r.k+2.x r.k-2.x)) (* (- r.k+2.y r.k-2.y) (- r.k+2.y r.k-2.y))))
; atom relaxed!273 (<= 4.0 (+ (* (- r.k+2.x r.k-3.x) (- r.k+2.x r.k-3.x)) (* (- r.k+2.y r.k-3.y) (- r.k+2.y r.k-3.y))))
; atom relaxed!278 (<= 4.0 (+ (* (- r.k+2.x r.k-4.x) (- r.k+2.x r.k-4.x)) (* (- r.k+2.y r.k-4.y) (- r.k+2.y r.k-4.y))))
; atom relaxed!283 (<= 4.0 (+ (* (- r.k+2.x r.t.x) (- r.k+2.x r.t.x)) (* (- r.k+2.y r.t.y) (- r.k+2.y r.t.y))))
; atom relaxed!288 (<= 4.0 (+ (* (- r.k+3.x r.k+4.x) (- r.k+3.x r.k+4.x)) (* (- r.k+3.y r.k+4.y) (- r.k+3.y r.k+4.y))))
; atom relaxed!293 (<= 4.0 (+ (* (- r.k+3.x r.k-1.x) (- r.k+3.x r.k-1.x)) (* (- r.k+3.y r.k-1.y) (- r.k+3.y r.k-1.y))))
; atom relaxed!298 (<= 4.0 (+ (* (- r.k+3.x r.k-2.x) (- r.k+3.x r.k-2.x)) (* (- r.k+3.y r.k-2.y) (- r.k+3.y r.k-2.y))))
; atom relaxed!303 (<= 4.0 (+ (* (- r.k+3.x r.k-3.x) (- r.k+3.x r.k-3.x)) (* (- r.k+3.y r.k-3.y) (- r.k+3.y r.k-3.y))))
; atom relaxed!308 (<= 4.0 (+ (* (- r.k+3.x r.k-4.x) (- r.k+3.x r.k-4.x)) (* (- r.k+3.y r.k-4.y) (- r.k+3.y r.k-4.y))))
; atom relaxed!313 (<= 4.0 (+ (* (- r.k+3.x r.t.x) (- r.k+3.x r.t.x)) (* (- r.k+3.y r.t.y) (- r.k+3.y r.t.y))))
; atom relaxed!318 (<= 4.0 (+ (* (- r.k+4.x r.k-1.x) (- r.k+4.x r.k-1.x)) (* (- r.k+4.y r.k-1.y) (- r.k+4.y r.k-1.y))))
; atom relaxed!323 (<= 4.0 (+ (* (- r.k+4.x r.k-2.x) (- r.k+4.x r.k-2.x)) (* (- r.k+4.y r.k-2.y) (- r.k+4.y r.k-2.y))))
; atom relaxed!328 (<= 4.0 (+ (* (- r.k+4.x r.k-3.x) (- r.k+4.x r.k-3.x)) (* (- r.k+4.y r.k-3.y) (- r.k+4.y r.k-3.y))))
; atom relaxed!333 (<= 4.0 (+ (* (- r.k+4.x r.k-4.x) (- r.k+4.x r.k-4.x)) (* (- r.k+4.y r.k-4.y) (- r.k+4.y r.k-4.y))))
; atom relaxed!338 (<= 4.0 (+ (* (- r.k+4.x r.t.x) (- r.k+4.x r.t.x)) (* (- r.k+4.y r.t.y) (- r.k+4.y r.t.y))))
; atom relaxed!343 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!348 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!353 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!358 (<= 4.0 (+ (* (- r.k-1.x r.t.x) (- r.k-1.x r.t.x)) (* (- r.k-1.y r.t.y) (- r.k-1.y r.t.y))))
; atom relaxed!363 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!368 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!373 (<= 4.0 (+ (* (- r.k-2.x r.t.x) (- r.k-2.x r.t.x)) (* (- r.k-2.y r.t.y) (- r.k-2.y r.t.y))))
; atom relaxed!378 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!383 (<= 4.0 (+ (* (- r.k-3.x r.t.x) (- r.k-3.x r.t.x)) (* (- r.k-3.y r.t.y) (- r.k-3.y r.t.y))))
; atom relaxed!388 (<= 4.0 (+ (* (- r.k-4.x r.t.x) (- r.k-4.x r.t.x)) (* (- r.k-4.y r.t.y) (- r.k-4.y r.t.y))))
; atom relaxed!392 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!415 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!425 (>= 16.0 (+ (* (- 0.0 r.d.x) (- 0.0 r.d.x)) (* (- 0.0 r.d.y) (- 0.0 r.d.y))))
; atom relaxed!448 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 1.0 1.0)))
; atom relaxed!451 (>= 16.0 (+ (* (- 0.0 r.k+1.x) (- 0.0 r.k+1.x)) (* (- 0.0 r.k+1.y) (- 0.0 r.k+1.y))))
; atom relaxed!452 (let ((a!1 (+ (* (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+1.y 0.0) 1.0) (- (- r.k+1.y 0.0) 1.0))))) (> 4.0 a!1))
; atom relaxed!455 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 2.0 2.0)))
; atom relaxed!458 (>= 16.0 (+ (* (- 0.0 r.k+2.x) (- 0.0 r.k+2.x)) (* (- 0.0 r.k+2.y) (- 0.0 r.k+2.y))))
; atom relaxed!459 (let ((a!1 (+ (* (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+2.y 0.0) 2.0) (- (- r.k+2.y 0.0) 2.0))))) (> 4.0 a!1))
; atom relaxed!462 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 3.0 3.0)))
; atom relaxed!465 (>= 16.0 (+ (* (- 0.0 r.k+3.x) (- 0.0 r.k+3.x)) (* (- 0.0 r.k+3.y) (- 0.0 r.k+3.y))))
; atom relaxed!466 (let ((a!1 (+ (* (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+3.y 0.0) 3.0) (- (- r.k+3.y 0.0) 3.0))))) (> 4.0 a!1))
; atom relaxed!469 (>= 16.0 (+ (* (- r.w.x 0.0) (- r.w.x 0.0)) (* 4.0 4.0)))
; atom relaxed!472 (>= 16.0 (+ (* (- 0.0 r.k+4.x) (- 0.0 r.k+4.x)) (* (- 0.0 r.k+4.y) (- 0.0 r.k+4.y))))
; atom relaxed!473 (let ((a!1 (+ (* (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k+4.y 0.0) 4.0) (- (- r.k+4.y 0.0) 4.0))))) (> 4.0 a!1))
; atom relaxed!477 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!478 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!482 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!483 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!487 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!488 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!492 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!493 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!497 (>= 16.0 (+ (* (- 0.0 r.t.x) (- 0.0 r.t.x)) (* (- 0.0 r.t.y) (- 0.0 r.t.y))))
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
(declare-fun r.k-3.y () Real)
(declare-fun r.k-3.x () Real)
(declare-fun relaxed!53 () Bool)
(declare-fun r.k-4.y () Real)
(declare-fun r.k-4.x () Real)
(declare-fun relaxed!58 () Bool)
(declare-fun r.t.y () Real)
(declare-fun r.t.x () Real)
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
(declare-fun relaxed!333 () Bool)
(declare-fun relaxed!338 () Bool)
(declare-fun relaxed!343 () Bool)
(declare-fun relaxed!348 () Bool)
(declare-fun relaxed!353 () Bool)
(declare-fun relaxed!358 () Bool)
(declare-fun relaxed!363 () Bool)
(declare-fun relaxed!368 () Bool)
(declare-fun relaxed!373 () Bool)
(declare-fun relaxed!378 () Bool)
(declare-fun relaxed!383 () Bool)
(declare-fun relaxed!388 () Bool)
(declare-fun relaxed!497 () Bool)
(declare-fun relaxed!492 () Bool)
(declare-fun relaxed!487 () Bool)
(declare-fun relaxed!482 () Bool)
(declare-fun relaxed!477 () Bool)
(declare-fun relaxed!472 () Bool)
(declare-fun relaxed!465 () Bool)
(declare-fun relaxed!458 () Bool)
(declare-fun relaxed!451 () Bool)
(declare-fun relaxed!425 () Bool)
(declare-fun relaxed!415 () Bool)
(declare-fun relaxed!392 () Bool)
(declare-fun relaxed!493 () Bool)
(declare-fun relaxed!469 () Bool)
(declare-fun relaxed!488 () Bool)
(declare-fun relaxed!462 () Bool)
(declare-fun relaxed!483 () Bool)
(declare-fun relaxed!455 () Bool)
(declare-fun relaxed!478 () Bool)
(declare-fun relaxed!448 () Bool)
(declare-fun relaxed!473 () Bool)
(declare-fun relaxed!466 () Bool)
(declare-fun relaxed!459 () Bool)
(declare-fun relaxed!452 () Bool)
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
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!48))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!53))
(assert (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) relaxed!58))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!63))
(assert (or (and (= r.w.x r.d.x) (= r.w.y r.d.y)) relaxed!68))
(assert (or (and (= r.w.x r.k+1.x) (= r.w.y r.k+1.y)) relaxed!73))
(assert (or (and (= r.w.x r.k+2.x) (= r.w.y r.k+2.y)) relaxed!78))
(assert (or (and (= r.w.x r.k+3.x) (= r.w.y r.k+3.y)) relaxed!83))
(assert (or (and (= r.w.x r.k+4.x) (= r.w.y r.k+4.y)) relaxed!88))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!93))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!98))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!103))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!108))
(assert (or (and (= r.w.x r.t.x) (= r.w.y r.t.y)) relaxed!113))
(assert (or (and (= r.c.x r.d.x) (= r.c.y r.d.y)) relaxed!118))
(assert (or (and (= r.c.x r.k+1.x) (= r.c.y r.k+1.y)) relaxed!123))
(assert (or (and (= r.c.x r.k+2.x) (= r.c.y r.k+2.y)) relaxed!128))
(assert (or (and (= r.c.x r.k+3.x) (= r.c.y r.k+3.y)) relaxed!133))
(assert (or (and (= r.c.x r.k+4.x) (= r.c.y r.k+4.y)) relaxed!138))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!143))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!148))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!153))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!158))
(assert (or (and (= r.c.x r.t.x) (= r.c.y r.t.y)) relaxed!163))
(assert (or (and (= r.d.x r.k+1.x) (= r.d.y r.k+1.y)) relaxed!168))
(assert (or (and (= r.d.x r.k+2.x) (= r.d.y r.k+2.y)) relaxed!173))
(assert (or (and (= r.d.x r.k+3.x) (= r.d.y r.k+3.y)) relaxed!178))
(assert (or (and (= r.d.x r.k+4.x) (= r.d.y r.k+4.y)) relaxed!183))
(assert (or (and (= r.d.x r.k-1.x) (= r.d.y r.k-1.y)) relaxed!188))
(assert (or (and (= r.d.x r.k-2.x) (= r.d.y r.k-2.y)) relaxed!193))
(assert (or (and (= r.d.x r.k-3.x) (= r.d.y r.k-3.y)) relaxed!198))
(assert (or (and (= r.d.x r.k-4.x) (= r.d.y r.k-4.y)) relaxed!203))
(assert (or (and (= r.d.x r.t.x) (= r.d.y r.t.y)) relaxed!208))
(assert (or (and (= r.k+1.x r.k+2.x) (= r.k+1.y r.k+2.y)) relaxed!213))
(assert (or (and (= r.k+1.x r.k+3.x) (= r.k+1.y r.k+3.y)) relaxed!218))
(assert (or (and (= r.k+1.x r.k+4.x) (= r.k+1.y r.k+4.y)) relaxed!223))
(assert (or (and (= r.k+1.x r.k-1.x) (= r.k+1.y r.k-1.y)) relaxed!228))
(assert (or (and (= r.k+1.x r.k-2.x) (= r.k+1.y r.k-2.y)) relaxed!233))
(assert (or (and (= r.k+1.x r.k-3.x) (= r.k+1.y r.k-3.y)) relaxed!238))
(assert (or (and (= r.k+1.x r.k-4.x) (= r.k+1.y r.k-4.y)) relaxed!243))
(assert (or (and (= r.k+1.x r.t.x) (= r.k+1.y r.t.y)) relaxed!248))
(assert (or (and (= r.k+2.x r.k+3.x) (= r.k+2.y r.k+3.y)) relaxed!253))
(assert (or (and (= r.k+2.x r.k+4.x) (= r.k+2.y r.k+4.y)) relaxed!258))
(assert (or (and (= r.k+2.x r.k-1.x) (= r.k+2.y r.k-1.y)) relaxed!263))
(assert (or (and (= r.k+2.x r.k-2.x) (= r.k+2.y r.k-2.y)) relaxed!268))
(assert (or (and (= r.k+2.x r.k-3.x) (= r.k+2.y r.k-3.y)) relaxed!273))
(assert (or (and (= r.k+2.x r.k-4.x) (= r.k+2.y r.k-4.y)) relaxed!278))
(assert (or (and (= r.k+2.x r.t.x) (= r.k+2.y r.t.y)) relaxed!283))
(assert (or (and (= r.k+3.x r.k+4.x) (= r.k+3.y r.k+4.y)) relaxed!288))
(assert (or (and (= r.k+3.x r.k-1.x) (= r.k+3.y r.k-1.y)) relaxed!293))
(assert (or (and (= r.k+3.x r.k-2.x) (= r.k+3.y r.k-2.y)) relaxed!298))
(assert (or (and (= r.k+3.x r.k-3.x) (= r.k+3.y r.k-3.y)) relaxed!303))
(assert (or (and (= r.k+3.x r.k-4.x) (= r.k+3.y r.k-4.y)) relaxed!308))
(assert (or (and (= r.k+3.x r.t.x) (= r.k+3.y r.t.y)) relaxed!313))
(assert (or (and (= r.k+4.x r.k-1.x) (= r.k+4.y r.k-1.y)) relaxed!318))
(assert (or (and (= r.k+4.x r.k-2.x) (= r.k+4.y r.k-2.y)) relaxed!323))
(assert (or (and (= r.k+4.x r.k-3.x) (= r.k+4.y r.k-3.y)) relaxed!328))
(assert (or (and (= r.k+4.x r.k-4.x) (= r.k+4.y r.k-4.y)) relaxed!333))
(assert (or (and (= r.k+4.x r.t.x) (= r.k+4.y r.t.y)) relaxed!338))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!343))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!348))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!353))
(assert (or (and (= r.k-1.x r.t.x) (= r.k-1.y r.t.y)) relaxed!358))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!363))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!368))
(assert (or (and (= r.k-2.x r.t.x) (= r.k-2.y r.t.y)) relaxed!373))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!378))
(assert (or (and (= r.k-3.x r.t.x) (= r.k-3.y r.t.y)) relaxed!383))
(assert (or (and (= r.k-4.x r.t.x) (= r.k-4.y r.t.y)) relaxed!388))
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
                 relaxed!451
                 relaxed!452))
      (a!14 (and (not (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y)))
                 relaxed!458
                 relaxed!459))
      (a!15 (and (not (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y)))
                 relaxed!465
                 relaxed!466))
      (a!16 (and (not (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y)))
                 relaxed!472
                 relaxed!473))
      (a!17 (and (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                 relaxed!477
                 relaxed!478))
      (a!18 (and (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                 relaxed!482
                 relaxed!483))
      (a!19 (and (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                 relaxed!487
                 relaxed!488))
      (a!20 (and (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                 relaxed!492
                 relaxed!493))
      (a!21 (and (> (- r.t.x 0.0) (- 2.0)) (> 2.0 (- r.t.x 0.0))))
      (a!22 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!38 (and (> (- r.c.x 0.0) (- 2.0)) (> 2.0 (- r.c.x 0.0))))
      (a!54 (and (> (- r.k+1.x 0.0) (- 2.0)) (> 2.0 (- r.k+1.x 0.0))))
      (a!55 (and (> (- r.k+1.y 0.0) (- 2.0)) (> 2.0 (- r.k+1.y 0.0))))
      (a!65 (and (> (- r.k+2.x 0.0) (- 2.0)) (> 2.0 (- r.k+2.x 0.0))))
      (a!66 (and (> (- r.k+2.y 0.0) (- 2.0)) (> 2.0 (- r.k+2.y 0.0))))
      (a!76 (and (> (- r.k+3.x 0.0) (- 2.0)) (> 2.0 (- r.k+3.x 0.0))))
      (a!77 (and (> (- r.k+3.y 0.0) (- 2.0)) (> 2.0 (- r.k+3.y 0.0))))
      (a!87 (and (> (- r.k+4.x 0.0) (- 2.0)) (> 2.0 (- r.k+4.x 0.0))))
      (a!88 (and (> (- r.k+4.y 0.0) (- 2.0)) (> 2.0 (- r.k+4.y 0.0))))
      (a!98 (and (> (- r.k-1.x 0.0) (- 2.0)) (> 2.0 (- r.k-1.x 0.0))))
      (a!99 (and (> (- r.k-1.y 0.0) (- 2.0)) (> 2.0 (- r.k-1.y 0.0))))
      (a!109 (and (> (- r.k-2.x 0.0) (- 2.0)) (> 2.0 (- r.k-2.x 0.0))))
      (a!110 (and (> (- r.k-2.y 0.0) (- 2.0)) (> 2.0 (- r.k-2.y 0.0))))
      (a!120 (and (> (- r.k-3.x 0.0) (- 2.0)) (> 2.0 (- r.k-3.x 0.0))))
      (a!121 (and (> (- r.k-3.y 0.0) (- 2.0)) (> 2.0 (- r.k-3.y 0.0))))
      (a!131 (and (> (- r.k-4.x 0.0) (- 2.0)) (> 2.0 (- r.k-4.x 0.0))))
      (a!132 (and (> (- r.k-4.y 0.0) (- 2.0)) (> 2.0 (- r.k-4.y 0.0))))
      (a!142 (and (> (- r.t.y 0.0) (- 2.0)) (> 2.0 (- r.t.y 0.0)))))
(let ((a!3 (or (and a!1 (< 0.0 (- r.w.y 0.0)))
               (and a!1 (> 0.0 (- r.w.y 0.0)))
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!11 (or (and a!9 (< 0.0 (- r.d.y 0.0)))
                (and a!9 (> 0.0 (- r.d.y 0.0)))
                (and a!10 (< 0.0 (- r.d.x 0.0)))
                (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!23 (or (and a!22 (< 0.0 (- 0.0 0.0))) (and a!22 (> 0.0 (- 0.0 0.0)))))
      (a!25 (not (and a!22 (> 0.0 (- 0.0 0.0)))))
      (a!30 (=> (and a!22 (> 0.0 (- 0.0 0.0))) (<= (- 0.0 0.0) (- r.t.y 0.0))))
      (a!33 (not (and a!2 (> 0.0 (- r.w.x 0.0)))))
      (a!36 (=> (and a!1 (> 0.0 (- r.w.y 0.0)))
                (<= (- r.w.y 0.0) (- r.t.y 0.0))))
      (a!39 (or (and a!38 (< 0.0 (- r.c.y 0.0)))
                (and a!38 (> 0.0 (- r.c.y 0.0)))
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!41 (not (and a!7 (> 0.0 (- r.c.x 0.0)))))
      (a!45 (=> (and a!38 (> 0.0 (- r.c.y 0.0)))
                (<= (- r.c.y 0.0) (- r.t.y 0.0))))
      (a!48 (not (and a!10 (> 0.0 (- r.d.x 0.0)))))
      (a!52 (=> (and a!9 (> 0.0 (- r.d.y 0.0)))
                (<= (- r.d.y 0.0) (- r.t.y 0.0))))
      (a!56 (or (and a!54 (< 0.0 (- r.k+1.y 0.0)))
                (and a!54 (> 0.0 (- r.k+1.y 0.0)))
                (and a!55 (< 0.0 (- r.k+1.x 0.0)))
                (and a!55 (> 0.0 (- r.k+1.x 0.0)))))
      (a!58 (not (and a!55 (> 0.0 (- r.k+1.x 0.0)))))
      (a!63 (=> (and a!54 (> 0.0 (- r.k+1.y 0.0)))
                (<= (- r.k+1.y 0.0) (- r.t.y 0.0))))
      (a!67 (or (and a!65 (< 0.0 (- r.k+2.y 0.0)))
                (and a!65 (> 0.0 (- r.k+2.y 0.0)))
                (and a!66 (< 0.0 (- r.k+2.x 0.0)))
                (and a!66 (> 0.0 (- r.k+2.x 0.0)))))
      (a!69 (not (and a!66 (> 0.0 (- r.k+2.x 0.0)))))
      (a!74 (=> (and a!65 (> 0.0 (- r.k+2.y 0.0)))
                (<= (- r.k+2.y 0.0) (- r.t.y 0.0))))
      (a!78 (or (and a!76 (< 0.0 (- r.k+3.y 0.0)))
                (and a!76 (> 0.0 (- r.k+3.y 0.0)))
                (and a!77 (< 0.0 (- r.k+3.x 0.0)))
                (and a!77 (> 0.0 (- r.k+3.x 0.0)))))
      (a!80 (not (and a!77 (> 0.0 (- r.k+3.x 0.0)))))
      (a!85 (=> (and a!76 (> 0.0 (- r.k+3.y 0.0)))
                (<= (- r.k+3.y 0.0) (- r.t.y 0.0))))
      (a!89 (or (and a!87 (< 0.0 (- r.k+4.y 0.0)))
                (and a!87 (> 0.0 (- r.k+4.y 0.0)))
                (and a!88 (< 0.0 (- r.k+4.x 0.0)))
                (and a!88 (> 0.0 (- r.k+4.x 0.0)))))
      (a!91 (not (and a!88 (> 0.0 (- r.k+4.x 0.0)))))
      (a!96 (=> (and a!87 (> 0.0 (- r.k+4.y 0.0)))
                (<= (- r.k+4.y 0.0) (- r.t.y 0.0))))
      (a!100 (or (and a!98 (< 0.0 (- r.k-1.y 0.0)))
                 (and a!98 (> 0.0 (- r.k-1.y 0.0)))
                 (and a!99 (< 0.0 (- r.k-1.x 0.0)))
                 (and a!99 (> 0.0 (- r.k-1.x 0.0)))))
      (a!102 (not (and a!99 (> 0.0 (- r.k-1.x 0.0)))))
      (a!107 (=> (and a!98 (> 0.0 (- r.k-1.y 0.0)))
                 (<= (- r.k-1.y 0.0) (- r.t.y 0.0))))
      (a!111 (or (and a!109 (< 0.0 (- r.k-2.y 0.0)))
                 (and a!109 (> 0.0 (- r.k-2.y 0.0)))
                 (and a!110 (< 0.0 (- r.k-2.x 0.0)))
                 (and a!110 (> 0.0 (- r.k-2.x 0.0)))))
      (a!113 (not (and a!110 (> 0.0 (- r.k-2.x 0.0)))))
      (a!118 (=> (and a!109 (> 0.0 (- r.k-2.y 0.0)))
                 (<= (- r.k-2.y 0.0) (- r.t.y 0.0))))
      (a!122 (or (and a!120 (< 0.0 (- r.k-3.y 0.0)))
                 (and a!120 (> 0.0 (- r.k-3.y 0.0)))
                 (and a!121 (< 0.0 (- r.k-3.x 0.0)))
                 (and a!121 (> 0.0 (- r.k-3.x 0.0)))))
      (a!124 (not (and a!121 (> 0.0 (- r.k-3.x 0.0)))))
      (a!129 (=> (and a!120 (> 0.0 (- r.k-3.y 0.0)))
                 (<= (- r.k-3.y 0.0) (- r.t.y 0.0))))
      (a!133 (or (and a!131 (< 0.0 (- r.k-4.y 0.0)))
                 (and a!131 (> 0.0 (- r.k-4.y 0.0)))
                 (and a!132 (< 0.0 (- r.k-4.x 0.0)))
                 (and a!132 (> 0.0 (- r.k-4.x 0.0)))))
      (a!135 (not (and a!132 (> 0.0 (- r.k-4.x 0.0)))))
      (a!140 (=> (and a!131 (> 0.0 (- r.k-4.y 0.0)))
                 (<= (- r.k-4.y 0.0) (- r.t.y 0.0))))
      (a!143 (or (and a!21 (< 0.0 (- r.t.y 0.0)))
                 (and a!21 (> 0.0 (- r.t.y 0.0)))
                 (and a!142 (< 0.0 (- r.t.x 0.0)))
                 (and a!142 (> 0.0 (- r.t.x 0.0)))))
      (a!145 (not (and a!142 (> 0.0 (- r.t.x 0.0)))))
      (a!150 (=> (and a!21 (> 0.0 (- r.t.y 0.0)))
                 (<= (- r.t.y 0.0) (- r.t.y 0.0)))))
(let ((a!4 (and (not a!3) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0))))
      (a!12 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0))))
      (a!24 (not (and (not (or a!23 a!23))
                      (> 0.0 (- 0.0 0.0))
                      (< 0.0 (- 0.0 0.0)))))
      (a!26 (not (and (not (or a!23 a!23))
                      (> 0.0 (- 0.0 0.0))
                      (> 0.0 (- 0.0 0.0)))))
      (a!27 (and (not (or a!23 a!23)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0))))
      (a!32 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))))
      (a!34 (not (and (not a!3) (> 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!40 (not (and (not a!39) (> 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0)))))
      (a!42 (not (and (not a!39) (> 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!43 (and (not a!39) (< 0.0 (- r.c.x 0.0)) (< 0.0 (- r.c.y 0.0))))
      (a!47 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0)))))
      (a!49 (not (and (not a!11) (> 0.0 (- r.d.x 0.0)) (> 0.0 (- r.d.y 0.0)))))
      (a!50 (and (not a!11) (< 0.0 (- r.d.x 0.0)) (< 0.0 (- r.d.y 0.0))))
      (a!57 (not (and (not a!56)
                      (> 0.0 (- r.k+1.x 0.0))
                      (< 0.0 (- r.k+1.y 0.0)))))
      (a!59 (not (and (not a!56)
                      (> 0.0 (- r.k+1.x 0.0))
                      (> 0.0 (- r.k+1.y 0.0)))))
      (a!60 (and (not a!56) (< 0.0 (- r.k+1.x 0.0)) (< 0.0 (- r.k+1.y 0.0))))
      (a!68 (not (and (not a!67)
                      (> 0.0 (- r.k+2.x 0.0))
                      (< 0.0 (- r.k+2.y 0.0)))))
      (a!70 (not (and (not a!67)
                      (> 0.0 (- r.k+2.x 0.0))
                      (> 0.0 (- r.k+2.y 0.0)))))
      (a!71 (and (not a!67) (< 0.0 (- r.k+2.x 0.0)) (< 0.0 (- r.k+2.y 0.0))))
      (a!79 (not (and (not a!78)
                      (> 0.0 (- r.k+3.x 0.0))
                      (< 0.0 (- r.k+3.y 0.0)))))
      (a!81 (not (and (not a!78)
                      (> 0.0 (- r.k+3.x 0.0))
                      (> 0.0 (- r.k+3.y 0.0)))))
      (a!82 (and (not a!78) (< 0.0 (- r.k+3.x 0.0)) (< 0.0 (- r.k+3.y 0.0))))
      (a!90 (not (and (not a!89)
                      (> 0.0 (- r.k+4.x 0.0))
                      (< 0.0 (- r.k+4.y 0.0)))))
      (a!92 (not (and (not a!89)
                      (> 0.0 (- r.k+4.x 0.0))
                      (> 0.0 (- r.k+4.y 0.0)))))
      (a!93 (and (not a!89) (< 0.0 (- r.k+4.x 0.0)) (< 0.0 (- r.k+4.y 0.0))))
      (a!101 (not (and (not a!100)
                       (> 0.0 (- r.k-1.x 0.0))
                       (< 0.0 (- r.k-1.y 0.0)))))
      (a!103 (not (and (not a!100)
                       (> 0.0 (- r.k-1.x 0.0))
                       (> 0.0 (- r.k-1.y 0.0)))))
      (a!104 (and (not a!100) (< 0.0 (- r.k-1.x 0.0)) (< 0.0 (- r.k-1.y 0.0))))
      (a!112 (not (and (not a!111)
                       (> 0.0 (- r.k-2.x 0.0))
                       (< 0.0 (- r.k-2.y 0.0)))))
      (a!114 (not (and (not a!111)
                       (> 0.0 (- r.k-2.x 0.0))
                       (> 0.0 (- r.k-2.y 0.0)))))
      (a!115 (and (not a!111) (< 0.0 (- r.k-2.x 0.0)) (< 0.0 (- r.k-2.y 0.0))))
      (a!123 (not (and (not a!122)
                       (> 0.0 (- r.k-3.x 0.0))
                       (< 0.0 (- r.k-3.y 0.0)))))
      (a!125 (not (and (not a!122)
                       (> 0.0 (- r.k-3.x 0.0))
                       (> 0.0 (- r.k-3.y 0.0)))))
      (a!126 (and (not a!122) (< 0.0 (- r.k-3.x 0.0)) (< 0.0 (- r.k-3.y 0.0))))
      (a!134 (not (and (not a!133)
                       (> 0.0 (- r.k-4.x 0.0))
                       (< 0.0 (- r.k-4.y 0.0)))))
      (a!136 (not (and (not a!133)
                       (> 0.0 (- r.k-4.x 0.0))
                       (> 0.0 (- r.k-4.y 0.0)))))
      (a!137 (and (not a!133) (< 0.0 (- r.k-4.x 0.0)) (< 0.0 (- r.k-4.y 0.0))))
      (a!144 (not (and (not a!143) (> 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))))
      (a!146 (not (and (not a!143) (> 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!147 (and (not a!143) (< 0.0 (- r.t.x 0.0)) (< 0.0 (- r.t.y 0.0)))))
(let ((a!5 (or a!4
               (and a!2 (< 0.0 (- r.w.x 0.0)))
               (and (not a!3) (< 0.0 (- r.w.x 0.0)) (> 0.0 (- r.w.y 0.0)))))
      (a!28 (or a!27
                (and a!22 (< 0.0 (- 0.0 0.0)))
                (and (not (or a!23 a!23))
                     (< 0.0 (- 0.0 0.0))
                     (> 0.0 (- 0.0 0.0)))))
      (a!29 (and (> (- (- 0.0 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- 0.0 0.0) (- r.w.x 0.0)))
                 a!27))
      (a!35 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!4))
      (a!44 (or a!43
                (and a!7 (< 0.0 (- r.c.x 0.0)))
                (and (not a!39) (< 0.0 (- r.c.x 0.0)) (> 0.0 (- r.c.y 0.0)))))
      (a!51 (or a!50 (and a!10 (< 0.0 (- r.d.x 0.0))) a!12))
      (a!61 (or a!60
                (and a!55 (< 0.0 (- r.k+1.x 0.0)))
                (and (not a!56) (< 0.0 (- r.k+1.x 0.0)) (> 0.0 (- r.k+1.y 0.0)))))
      (a!62 (and (> (- (- r.k+1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 a!60))
      (a!72 (or a!71
                (and a!66 (< 0.0 (- r.k+2.x 0.0)))
                (and (not a!67) (< 0.0 (- r.k+2.x 0.0)) (> 0.0 (- r.k+2.y 0.0)))))
      (a!73 (and (> (- (- r.k+2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 a!71))
      (a!83 (or a!82
                (and a!77 (< 0.0 (- r.k+3.x 0.0)))
                (and (not a!78) (< 0.0 (- r.k+3.x 0.0)) (> 0.0 (- r.k+3.y 0.0)))))
      (a!84 (and (> (- (- r.k+3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 a!82))
      (a!94 (or a!93
                (and a!88 (< 0.0 (- r.k+4.x 0.0)))
                (and (not a!89) (< 0.0 (- r.k+4.x 0.0)) (> 0.0 (- r.k+4.y 0.0)))))
      (a!95 (and (> (- (- r.k+4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 a!93))
      (a!105 (or a!104
                 (and a!99 (< 0.0 (- r.k-1.x 0.0)))
                 (and (not a!100)
                      (< 0.0 (- r.k-1.x 0.0))
                      (> 0.0 (- r.k-1.y 0.0)))))
      (a!106 (and (> (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  a!104))
      (a!116 (or a!115
                 (and a!110 (< 0.0 (- r.k-2.x 0.0)))
                 (and (not a!111)
                      (< 0.0 (- r.k-2.x 0.0))
                      (> 0.0 (- r.k-2.y 0.0)))))
      (a!117 (and (> (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  a!115))
      (a!127 (or a!126
                 (and a!121 (< 0.0 (- r.k-3.x 0.0)))
                 (and (not a!122)
                      (< 0.0 (- r.k-3.x 0.0))
                      (> 0.0 (- r.k-3.y 0.0)))))
      (a!128 (and (> (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  a!126))
      (a!138 (or a!137
                 (and a!132 (< 0.0 (- r.k-4.x 0.0)))
                 (and (not a!133)
                      (< 0.0 (- r.k-4.x 0.0))
                      (> 0.0 (- r.k-4.y 0.0)))))
      (a!139 (and (> (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0)))
                  a!137))
      (a!148 (or a!147
                 (and a!142 (< 0.0 (- r.t.x 0.0)))
                 (and (not a!143) (< 0.0 (- r.t.x 0.0)) (> 0.0 (- r.t.y 0.0)))))
      (a!149 (and (> (- (- r.t.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.t.x 0.0) (- r.w.x 0.0)))
                  a!147)))
(let ((a!31 (and a!24
                 a!25
                 a!26
                 (=> a!28 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!29)
                 a!30))
      (a!37 (and a!32
                 a!33
                 a!34
                 (=> a!5 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!35)
                 a!36))
      (a!46 (and a!40
                 a!41
                 a!42
                 (=> a!44 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!6 a!43))
                 a!45))
      (a!53 (and a!47
                 a!48
                 a!49
                 (=> a!51 (>= (- r.d.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!50))
                 a!52))
      (a!64 (and a!57
                 a!58
                 a!59
                 (=> a!61 (>= (- r.k+1.x 0.0) (- r.w.x 0.0)))
                 (not a!62)
                 a!63))
      (a!75 (and a!68
                 a!69
                 a!70
                 (=> a!72 (>= (- r.k+2.x 0.0) (- r.w.x 0.0)))
                 (not a!73)
                 a!74))
      (a!86 (and a!79
                 a!80
                 a!81
                 (=> a!83 (>= (- r.k+3.x 0.0) (- r.w.x 0.0)))
                 (not a!84)
                 a!85))
      (a!97 (and a!90
                 a!91
                 a!92
                 (=> a!94 (>= (- r.k+4.x 0.0) (- r.w.x 0.0)))
                 (not a!95)
                 a!96))
      (a!108 (and a!101
                  a!102
                  a!103
                  (=> a!105 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                  (not a!106)
                  a!107))
      (a!119 (and a!112
                  a!113
                  a!114
                  (=> a!116 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                  (not a!117)
                  a!118))
      (a!130 (and a!123
                  a!124
                  a!125
                  (=> a!127 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                  (not a!128)
                  a!129))
      (a!141 (and a!134
                  a!135
                  a!136
                  (=> a!138 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                  (not a!139)
                  a!140))
      (a!151 (and a!144
                  a!145
                  a!146
                  (=> a!148 (>= (- r.t.x 0.0) (- r.w.x 0.0)))
                  (not a!149)
                  a!150)))
(let ((a!152 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!392
                  a!5
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!415
                  a!6
                  (and a!7 (< 0.0 (- r.c.x 0.0)))
                  (not (and (= 0.0 r.d.x) (= 0.0 r.d.y)))
                  relaxed!425
                  a!8
                  a!12
                  (or (not relaxed!448) a!13)
                  (or (not relaxed!455) a!14)
                  (or (not relaxed!462) a!15)
                  (or (not relaxed!469) a!16)
                  (or (not relaxed!448) a!17)
                  (or (not relaxed!455) a!18)
                  (or (not relaxed!462) a!19)
                  (or (not relaxed!469) a!20)
                  (not (and (= 0.0 r.t.x) (= 0.0 r.t.y)))
                  relaxed!497
                  (and a!21 (> 0.0 (- r.t.y 0.0)))
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!31))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!392 a!37))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!415 a!46))
                  (or (and (= 0.0 r.d.x) (= 0.0 r.d.y)) (=> relaxed!425 a!53))
                  (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
                      (=> relaxed!451 a!64))
                  (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
                      (=> relaxed!458 a!75))
                  (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))
                      (=> relaxed!465 a!86))
                  (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))
                      (=> relaxed!472 a!97))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!477 a!108))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!482 a!119))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!487 a!130))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!492 a!141))
                  (or (and (= 0.0 r.t.x) (= 0.0 r.t.y)) (=> relaxed!497 a!151)))))
  (=> r.case0 a!152))))))))
(assert (or r.case0))
(assert (and (< 0.0 (+ 0.0 0.0))
     (or (and (= 0.0 r.w.x) (= 0.0 r.w.y))
         (not relaxed!392)
         (< r.w.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.c.x) (= 0.0 r.c.y))
         (not relaxed!415)
         (< r.c.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.d.x) (= 0.0 r.d.y))
         (not relaxed!425)
         (< r.d.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k+1.x) (= 0.0 r.k+1.y))
         (not relaxed!451)
         (< r.k+1.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k+2.x) (= 0.0 r.k+2.y))
         (not relaxed!458)
         (< r.k+2.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k+3.x) (= 0.0 r.k+3.y))
         (not relaxed!465)
         (< r.k+3.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k+4.x) (= 0.0 r.k+4.y))
         (not relaxed!472)
         (< r.k+4.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
         (not relaxed!477)
         (< r.k-1.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
         (not relaxed!482)
         (< r.k-2.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
         (not relaxed!487)
         (< r.k-3.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
         (not relaxed!492)
         (< r.k-4.x (+ 0.0 0.0)))
     (or (and (= 0.0 r.t.x) (= 0.0 r.t.y))
         (not relaxed!497)
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 2.0))) (=> (not relaxed!53) a!1)))
; cut relaxed!53
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!53)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 2.0))) (=> (not relaxed!58) a!1)))
; cut relaxed!58
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!58)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!63) a!1)))
; cut relaxed!63
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!63)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* 1.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.d.x)) (* 0.0 (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.d.x)) (* (- 1.0) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) 2.0))) (=> (not relaxed!68) a!1)))
; cut relaxed!68
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.d.x)) (* (/ 4.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.d.x)) (* (/ 9.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.d.x)) (* (/ 8.0 5.0) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.d.x)) (* (/ 3.0 5.0) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!68)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* 1.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+1.x)) (* 0.0 (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+1.x)) (* (- 1.0) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) 2.0))) (=> (not relaxed!73) a!1)))
; cut relaxed!73
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+1.x)) (* (/ 4.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+1.x)) (* (/ 9.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 8.0 5.0) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+1.x)) (* (/ 3.0 5.0) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!73)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* 1.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+2.x)) (* 0.0 (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+2.x)) (* (- 1.0) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) 2.0))) (=> (not relaxed!78) a!1)))
; cut relaxed!78
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+2.x)) (* (/ 4.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+2.x)) (* (/ 9.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 8.0 5.0) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+2.x)) (* (/ 3.0 5.0) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!78)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* 1.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+3.x)) (* 0.0 (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+3.x)) (* (- 1.0) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) 2.0))) (=> (not relaxed!83) a!1)))
; cut relaxed!83
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+3.x)) (* (/ 4.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+3.x)) (* (/ 9.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 8.0 5.0) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+3.x)) (* (/ 3.0 5.0) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!83)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* 1.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k+4.x)) (* 0.0 (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k+4.x)) (* (- 1.0) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) 2.0))) (=> (not relaxed!88) a!1)))
; cut relaxed!88
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k+4.x)) (* (/ 4.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k+4.x)) (* (/ 9.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 8.0 5.0) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k+4.x)) (* (/ 3.0 5.0) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!88)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!93) a!1)))
; cut relaxed!93
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!93)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!98) a!1)))
; cut relaxed!98
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!98)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!103) a!1)))
; cut relaxed!103
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!103)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!108) a!1)))
; cut relaxed!108
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!108)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* 1.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.t.x)) (* 0.0 (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.t.x)) (* (- 1.0) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) 2.0))) (=> (not relaxed!113) a!1)))
; cut relaxed!113
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.t.x)) (* (/ 4.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.t.x)) (* (/ 9.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.t.x)) (* (/ 8.0 5.0) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.t.x)) (* (/ 3.0 5.0) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!113)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* 1.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.d.x)) (* 0.0 (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.d.x)) (* (- 1.0) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) 2.0))) (=> (not relaxed!118) a!1)))
; cut relaxed!118
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.d.x)) (* (/ 4.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.d.x)) (* (/ 9.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.d.x)) (* (/ 8.0 5.0) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.d.x)) (* (/ 3.0 5.0) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.d.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.d.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.d.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.d.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.d.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!118)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* 1.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+1.x)) (* 0.0 (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+1.x)) (* (- 1.0) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) 2.0))) (=> (not relaxed!123) a!1)))
; cut relaxed!123
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+1.x)) (* (/ 4.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+1.x)) (* (/ 9.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 8.0 5.0) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+1.x)) (* (/ 3.0 5.0) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!123)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* 1.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+2.x)) (* 0.0 (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+2.x)) (* (- 1.0) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) 2.0))) (=> (not relaxed!128) a!1)))
; cut relaxed!128
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+2.x)) (* (/ 4.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+2.x)) (* (/ 9.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 8.0 5.0) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+2.x)) (* (/ 3.0 5.0) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!128)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* 1.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+3.x)) (* 0.0 (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+3.x)) (* (- 1.0) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) 2.0))) (=> (not relaxed!133) a!1)))
; cut relaxed!133
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+3.x)) (* (/ 4.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+3.x)) (* (/ 9.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 8.0 5.0) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+3.x)) (* (/ 3.0 5.0) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!133)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* 1.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k+4.x)) (* 0.0 (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k+4.x)) (* (- 1.0) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) 2.0))) (=> (not relaxed!138) a!1)))
; cut relaxed!138
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k+4.x)) (* (/ 4.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k+4.x)) (* (/ 9.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 8.0 5.0) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k+4.x)) (* (/ 3.0 5.0) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!138)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!143) a!1)))
; cut relaxed!143
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!143)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!148) a!1)))
; cut relaxed!148
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!148)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!153) a!1)))
; cut relaxed!153
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!153)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!158) a!1)))
; cut relaxed!158
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!158)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* 1.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.t.x)) (* 0.0 (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.t.x)) (* (- 1.0) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) 2.0))) (=> (not relaxed!163) a!1)))
; cut relaxed!163
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.t.x)) (* (/ 4.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.t.x)) (* (/ 9.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.t.x)) (* (/ 8.0 5.0) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.t.x)) (* (/ 3.0 5.0) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!163)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* 1.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+1.x)) (* 0.0 (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+1.x)) (* (- 1.0) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) 2.0))) (=> (not relaxed!168) a!1)))
; cut relaxed!168
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+1.x)) (* (/ 4.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+1.x)) (* (/ 9.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 8.0 5.0) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+1.x)) (* (/ 3.0 5.0) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!168)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* 1.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+2.x)) (* 0.0 (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+2.x)) (* (- 1.0) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) 2.0))) (=> (not relaxed!173) a!1)))
; cut relaxed!173
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+2.x)) (* (/ 4.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+2.x)) (* (/ 9.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 8.0 5.0) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+2.x)) (* (/ 3.0 5.0) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!173)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+3.x)) (* 0.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+3.x)) (* (/ 4.0 5.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+3.x)) (* 1.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 3.0 5.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+3.x)) (* 0.0 (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+3.x)) (* (- 1.0) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+3.y))) 2.0))) (=> (not relaxed!178) a!1)))
; cut relaxed!178
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+3.x)) (* (/ 4.0 5.0) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+3.x)) (* (/ 9.0 5.0) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 8.0 5.0) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+3.x)) (* (/ 3.0 5.0) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!178)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k+4.x)) (* 0.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k+4.x)) (* (/ 4.0 5.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+4.x)) (* 1.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 3.0 5.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k+4.x)) (* 0.0 (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k+4.x)) (* (- 1.0) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+4.y))) 2.0))) (=> (not relaxed!183) a!1)))
; cut relaxed!183
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k+4.x)) (* (/ 4.0 5.0) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k+4.x)) (* (/ 9.0 5.0) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 8.0 5.0) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k+4.x)) (* (/ 3.0 5.0) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!183)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* 1.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-1.x)) (* 0.0 (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-1.x)) (* (- 1.0) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) 2.0))) (=> (not relaxed!188) a!1)))
; cut relaxed!188
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-1.x)) (* (/ 4.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-1.x)) (* (/ 9.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 8.0 5.0) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-1.x)) (* (/ 3.0 5.0) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!188)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* 1.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-2.x)) (* 0.0 (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-2.x)) (* (- 1.0) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) 2.0))) (=> (not relaxed!193) a!1)))
; cut relaxed!193
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-2.x)) (* (/ 4.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-2.x)) (* (/ 9.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 8.0 5.0) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-2.x)) (* (/ 3.0 5.0) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!193)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-3.x)) (* 0.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-3.x)) (* (/ 4.0 5.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-3.x)) (* 1.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 3.0 5.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-3.x)) (* 0.0 (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-3.x)) (* (- 1.0) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-3.y))) 2.0))) (=> (not relaxed!198) a!1)))
; cut relaxed!198
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-3.x)) (* (/ 4.0 5.0) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-3.x)) (* (/ 9.0 5.0) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 8.0 5.0) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-3.x)) (* (/ 3.0 5.0) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!198)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.k-4.x)) (* 0.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.k-4.x)) (* (/ 4.0 5.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-4.x)) (* 1.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 3.0 5.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.k-4.x)) (* 0.0 (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.k-4.x)) (* (- 1.0) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-4.y))) 2.0))) (=> (not relaxed!203) a!1)))
; cut relaxed!203
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.k-4.x)) (* (/ 4.0 5.0) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.k-4.x)) (* (/ 9.0 5.0) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 8.0 5.0) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.k-4.x)) (* (/ 3.0 5.0) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!203)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 1.0 (- r.d.x r.t.x)) (* 0.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.d.x r.t.x)) (* (/ 4.0 5.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.t.x)) (* 1.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.t.x)) (* (/ 3.0 5.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.d.x r.t.x)) (* 0.0 (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* 0.0 (- r.d.x r.t.x)) (* (- 1.0) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.d.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.t.y))) 2.0))) (=> (not relaxed!208) a!1)))
; cut relaxed!208
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.d.x r.t.x)) (* (/ 4.0 5.0) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.d.x r.t.x)) (* (/ 9.0 5.0) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.d.x r.t.x)) (* (/ 8.0 5.0) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.d.x r.t.x)) (* (/ 3.0 5.0) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.d.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.d.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.d.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.d.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.d.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.d.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!208)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* 1.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+2.x)) (* 0.0 (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+2.x)) (* (- 1.0) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) 2.0))) (=> (not relaxed!213) a!1)))
; cut relaxed!213
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!213)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* 1.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+3.x)) (* 0.0 (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+3.x)) (* (- 1.0) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) 2.0))) (=> (not relaxed!218) a!1)))
; cut relaxed!218
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!218)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* 1.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k+4.x)) (* 0.0 (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k+4.x)) (* (- 1.0) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) 2.0))) (=> (not relaxed!223) a!1)))
; cut relaxed!223
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!223)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-1.x)) (* 0.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-1.x)) (* 1.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-1.x)) (* 0.0 (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-1.x)) (* (- 1.0) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-1.y))) 2.0))) (=> (not relaxed!228) a!1)))
; cut relaxed!228
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!228)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-2.x)) (* 0.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-2.x)) (* 1.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-2.x)) (* 0.0 (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-2.x)) (* (- 1.0) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-2.y))) 2.0))) (=> (not relaxed!233) a!1)))
; cut relaxed!233
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!233)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-3.x)) (* 0.0 (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-3.x)) (* 1.0 (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-3.x)) (* 0.0 (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-3.x)) (* (- 1.0) (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-3.y))) 2.0))) (=> (not relaxed!238) a!1)))
; cut relaxed!238
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!238)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.k-4.x)) (* 0.0 (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-4.x)) (* 1.0 (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.k-4.x)) (* 0.0 (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.k-4.x)) (* (- 1.0) (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-4.y))) 2.0))) (=> (not relaxed!243) a!1)))
; cut relaxed!243
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k+1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k+1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!243)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+1.x r.t.x)) (* 0.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+1.x r.t.x)) (* (/ 4.0 5.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.t.x)) (* 1.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 3.0 5.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+1.x r.t.x)) (* 0.0 (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+1.x r.t.x)) (* (- 1.0) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.t.y))) 2.0))) (=> (not relaxed!248) a!1)))
; cut relaxed!248
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+1.x r.t.x)) (* (/ 4.0 5.0) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+1.x r.t.x)) (* (/ 9.0 5.0) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 8.0 5.0) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+1.x r.t.x)) (* (/ 3.0 5.0) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+1.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+1.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+1.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+1.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!248)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* 1.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+3.x)) (* 0.0 (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+3.x)) (* (- 1.0) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) 2.0))) (=> (not relaxed!253) a!1)))
; cut relaxed!253
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+3.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+3.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!253)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* 1.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k+4.x)) (* 0.0 (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k+4.x)) (* (- 1.0) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) 2.0))) (=> (not relaxed!258) a!1)))
; cut relaxed!258
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!258)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-1.x)) (* 0.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-1.x)) (* 1.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-1.x)) (* 0.0 (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-1.x)) (* (- 1.0) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-1.y))) 2.0))) (=> (not relaxed!263) a!1)))
; cut relaxed!263
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!263)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-2.x)) (* 0.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-2.x)) (* 1.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-2.x)) (* 0.0 (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-2.x)) (* (- 1.0) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-2.y))) 2.0))) (=> (not relaxed!268) a!1)))
; cut relaxed!268
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!268)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-3.x)) (* 0.0 (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-3.x)) (* 1.0 (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-3.x)) (* 0.0 (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-3.x)) (* (- 1.0) (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-3.y))) 2.0))) (=> (not relaxed!273) a!1)))
; cut relaxed!273
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!273)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.k-4.x)) (* 0.0 (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-4.x)) (* 1.0 (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.k-4.x)) (* 0.0 (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.k-4.x)) (* (- 1.0) (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-4.y))) 2.0))) (=> (not relaxed!278) a!1)))
; cut relaxed!278
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k+2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k+2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!278)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+2.x r.t.x)) (* 0.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+2.x r.t.x)) (* (/ 4.0 5.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.t.x)) (* 1.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 3.0 5.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+2.x r.t.x)) (* 0.0 (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+2.x r.t.x)) (* (- 1.0) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.t.y))) 2.0))) (=> (not relaxed!283) a!1)))
; cut relaxed!283
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+2.x r.t.x)) (* (/ 4.0 5.0) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+2.x r.t.x)) (* (/ 9.0 5.0) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 8.0 5.0) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+2.x r.t.x)) (* (/ 3.0 5.0) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+2.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+2.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+2.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+2.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!283)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* 1.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k+4.x)) (* 0.0 (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k+4.x)) (* (- 1.0) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) 2.0))) (=> (not relaxed!288) a!1)))
; cut relaxed!288
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k+4.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k+4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k+4.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k+4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k+4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!288)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-1.x)) (* 0.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-1.x)) (* 1.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-1.x)) (* 0.0 (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-1.x)) (* (- 1.0) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-1.y))) 2.0))) (=> (not relaxed!293) a!1)))
; cut relaxed!293
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!293)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-2.x)) (* 0.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-2.x)) (* 1.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-2.x)) (* 0.0 (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-2.x)) (* (- 1.0) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-2.y))) 2.0))) (=> (not relaxed!298) a!1)))
; cut relaxed!298
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!298)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-3.x)) (* 0.0 (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-3.x)) (* 1.0 (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-3.x)) (* 0.0 (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-3.x)) (* (- 1.0) (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-3.y))) 2.0))) (=> (not relaxed!303) a!1)))
; cut relaxed!303
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!303)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.k-4.x)) (* 0.0 (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-4.x)) (* 1.0 (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.k-4.x)) (* 0.0 (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.k-4.x)) (* (- 1.0) (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-4.y))) 2.0))) (=> (not relaxed!308) a!1)))
; cut relaxed!308
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k+3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k+3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!308)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+3.x r.t.x)) (* 0.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+3.x r.t.x)) (* (/ 4.0 5.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.t.x)) (* 1.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 3.0 5.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+3.x r.t.x)) (* 0.0 (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+3.x r.t.x)) (* (- 1.0) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.t.y))) 2.0))) (=> (not relaxed!313) a!1)))
; cut relaxed!313
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+3.x r.t.x)) (* (/ 4.0 5.0) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+3.x r.t.x)) (* (/ 9.0 5.0) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 8.0 5.0) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+3.x r.t.x)) (* (/ 3.0 5.0) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+3.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+3.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+3.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+3.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!313)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-1.x)) (* 0.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-1.x)) (* 1.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-1.x)) (* 0.0 (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-1.x)) (* (- 1.0) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-1.y))) 2.0))) (=> (not relaxed!318) a!1)))
; cut relaxed!318
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-1.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-1.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!318)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-2.x)) (* 0.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-2.x)) (* 1.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-2.x)) (* 0.0 (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-2.x)) (* (- 1.0) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-2.y))) 2.0))) (=> (not relaxed!323) a!1)))
; cut relaxed!323
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!323)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-3.x)) (* 0.0 (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-3.x)) (* 1.0 (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-3.x)) (* 0.0 (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-3.x)) (* (- 1.0) (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-3.y))) 2.0))) (=> (not relaxed!328) a!1)))
; cut relaxed!328
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!328)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.k-4.x)) (* 0.0 (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-4.x)) (* 1.0 (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.k-4.x)) (* 0.0 (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.k-4.x)) (* (- 1.0) (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-4.y))) 2.0))) (=> (not relaxed!333) a!1)))
; cut relaxed!333
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k+4.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k+4.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k+4.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k+4.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!333)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k+4.x r.t.x)) (* 0.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k+4.x r.t.x)) (* (/ 4.0 5.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.t.x)) (* 1.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 3.0 5.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k+4.x r.t.x)) (* 0.0 (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k+4.x r.t.x)) (* (- 1.0) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.t.y))) 2.0))) (=> (not relaxed!338) a!1)))
; cut relaxed!338
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k+4.x r.t.x)) (* (/ 4.0 5.0) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k+4.x r.t.x)) (* (/ 9.0 5.0) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 8.0 5.0) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k+4.x r.t.x)) (* (/ 3.0 5.0) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k+4.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k+4.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k+4.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k+4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k+4.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!338)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!343) a!1)))
; cut relaxed!343
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!343)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!348) a!1)))
; cut relaxed!348
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!348)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!353) a!1)))
; cut relaxed!353
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!353)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.t.x)) (* 0.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.t.x)) (* (/ 4.0 5.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.t.x)) (* 1.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 3.0 5.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.t.x)) (* 0.0 (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.t.x)) (* (- 1.0) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.t.y))) 2.0))) (=> (not relaxed!358) a!1)))
; cut relaxed!358
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.t.x)) (* (/ 4.0 5.0) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.t.x)) (* (/ 9.0 5.0) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 8.0 5.0) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.t.x)) (* (/ 3.0 5.0) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!358)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!363) a!1)))
; cut relaxed!363
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!363)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!368) a!1)))
; cut relaxed!368
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!368)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.t.x)) (* 0.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.t.x)) (* (/ 4.0 5.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.t.x)) (* 1.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 3.0 5.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.t.x)) (* 0.0 (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.t.x)) (* (- 1.0) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.t.y))) 2.0))) (=> (not relaxed!373) a!1)))
; cut relaxed!373
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.t.x)) (* (/ 4.0 5.0) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.t.x)) (* (/ 9.0 5.0) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 8.0 5.0) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.t.x)) (* (/ 3.0 5.0) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!373)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!378) a!1)))
; cut relaxed!378
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!378)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.t.x)) (* 0.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.t.x)) (* (/ 4.0 5.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.t.x)) (* 1.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 3.0 5.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.t.x)) (* 0.0 (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.t.x)) (* (- 1.0) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.t.y))) 2.0))) (=> (not relaxed!383) a!1)))
; cut relaxed!383
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.t.x)) (* (/ 4.0 5.0) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.t.x)) (* (/ 9.0 5.0) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 8.0 5.0) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.t.x)) (* (/ 3.0 5.0) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!383)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.t.x)) (* 0.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.t.x)) (* (/ 4.0 5.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.t.x)) (* 1.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 3.0 5.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.t.x)) (* 0.0 (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.t.x)) (* (- 1.0) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.t.y))) 2.0))) (=> (not relaxed!388) a!1)))
; cut relaxed!388
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.t.x)) (* (/ 4.0 5.0) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.t.x)) (* (/ 9.0 5.0) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 8.0 5.0) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.t.x)) (* (/ 3.0 5.0) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.t.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.t.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.t.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.t.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.t.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!388)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!392 a!1)))
; cut relaxed!392
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!392) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!415) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* 1.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.d.x)) (* 0.0 (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.d.x)) (* (- 1.0) (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) 4.0))) (=> relaxed!425 a!1)))
; cut relaxed!425
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.d.x)) (* (/ 4.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.d.x)) (* (/ 9.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.d.x)) (* (/ 8.0 5.0) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.d.x)) (* (/ 3.0 5.0) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.d.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.d.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.d.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.d.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.d.y))) (/ 36.0 5.0)))) (=> (not relaxed!425) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 3872983347.0 1000000000.0)))) (=> relaxed!448 a!1)))
; cut relaxed!448
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 1936491673.0 312500000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 17428425057.0 2500000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 1936491673.0 312500000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 17428425057.0 2500000000.0)))) (=> (not relaxed!448) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* 1.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+1.x)) (* 0.0 (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+1.x)) (* (- 1.0) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) 4.0))) (=> relaxed!451 a!1)))
; cut relaxed!451
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+1.x)) (* (/ 4.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+1.x)) (* (/ 9.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 8.0 5.0) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.x)) (* (/ 3.0 5.0) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+1.y))) (/ 36.0 5.0)))) (=> (not relaxed!451) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!452
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> relaxed!452 (<= a!1 2.0))))
; cut relaxed!452
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+1.y 0.0) 1.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+1.y 0.0) 1.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+1.y 0.0) 1.0))))) (=> (not relaxed!452) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 216506351.0 62500000.0)))) (=> relaxed!455 a!1)))
; cut relaxed!455
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 692820323.0 125000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 6235382907.0 1000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 692820323.0 125000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 6235382907.0 1000000000.0)))) (=> (not relaxed!455) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* 1.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+2.x)) (* 0.0 (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+2.x)) (* (- 1.0) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) 4.0))) (=> relaxed!458 a!1)))
; cut relaxed!458
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+2.x)) (* (/ 4.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+2.x)) (* (/ 9.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 8.0 5.0) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.x)) (* (/ 3.0 5.0) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+2.y))) (/ 36.0 5.0)))) (=> (not relaxed!458) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!459
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> relaxed!459 (<= a!1 2.0))))
; cut relaxed!459
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+2.y 0.0) 2.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+2.y 0.0) 2.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+2.y 0.0) 2.0))))) (=> (not relaxed!459) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 165359457.0 62500000.0)))) (=> relaxed!462 a!1)))
; cut relaxed!462
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 9.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 8.0 5.0) 0.0)) (/ 2645751311.0 625000000.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) (/ 23811761799.0 5000000000.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 9.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 8.0 5.0)) 0.0)) (/ 2645751311.0 625000000.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) (/ 23811761799.0 5000000000.0)))) (=> (not relaxed!462) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* 1.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+3.x)) (* 0.0 (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+3.x)) (* (- 1.0) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) 4.0))) (=> relaxed!465 a!1)))
; cut relaxed!465
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+3.x)) (* (/ 4.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+3.x)) (* (/ 9.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 8.0 5.0) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.x)) (* (/ 3.0 5.0) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+3.y))) (/ 36.0 5.0)))) (=> (not relaxed!465) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!466
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> relaxed!466 (<= a!1 2.0))))
; cut relaxed!466
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+3.y 0.0) 3.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+3.y 0.0) 3.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+3.y 0.0) 3.0))))) (=> (not relaxed!466) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x 0.0)) (* (/ 4.0 5.0) 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* 1.0 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x 0.0)) (* (/ 3.0 5.0) 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x 0.0)) (* 0.0 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x 0.0)) (* (- (/ 4.0 5.0)) 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x 0.0)) (* (- 1.0) 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!469
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x 0.0)) (* (- (/ 3.0 5.0)) 0.0)) 0.0))) (=> relaxed!469 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* 1.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k+4.x)) (* 0.0 (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k+4.x)) (* (- 1.0) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) 4.0))) (=> relaxed!472 a!1)))
; cut relaxed!472
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k+4.x)) (* (/ 4.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k+4.x)) (* (/ 9.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 8.0 5.0) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.x)) (* (/ 3.0 5.0) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k+4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k+4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k+4.y))) (/ 36.0 5.0)))) (=> (not relaxed!472) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!473
(assert (let ((a!1 (+ (* 1.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* 0.0 (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> relaxed!473 (<= a!1 2.0))))
; cut relaxed!473
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k+4.y 0.0) 4.0)))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k+4.y 0.0) 4.0)))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k+4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k+4.y 0.0) 4.0))))) (=> (not relaxed!473) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!477 a!1)))
; cut relaxed!477
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!477) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!478
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!478 (<= a!1 2.0))))
; cut relaxed!478
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!478) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!482 a!1)))
; cut relaxed!482
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!482) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!483
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!483 (<= a!1 2.0))))
; cut relaxed!483
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!483) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!487 a!1)))
; cut relaxed!487
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!487) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!488
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!488 (<= a!1 2.0))))
; cut relaxed!488
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!488) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!492 a!1)))
; cut relaxed!492
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!492) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!493
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!493 (<= a!1 2.0))))
; cut relaxed!493
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!493) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* 1.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.t.x)) (* 0.0 (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.t.x)) (* (- 1.0) (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) 4.0))) (=> relaxed!497 a!1)))
; cut relaxed!497
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.t.x)) (* (/ 4.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.t.x)) (* (/ 9.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.t.x)) (* (/ 8.0 5.0) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.t.x)) (* (/ 3.0 5.0) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.t.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.t.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.t.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.t.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.t.y))) (/ 36.0 5.0)))) (=> (not relaxed!497) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
(check-sat)
