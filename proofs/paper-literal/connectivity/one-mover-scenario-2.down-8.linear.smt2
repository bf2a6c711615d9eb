; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 69; cuts: 865
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!8 (<= 4.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!13 (<= 4.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!18 (<= 4.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!23 (<= 4.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!28 (<= 4.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!33 (<= 4.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!38 (<= 4.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!43 (<= 4.0 (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x)) (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y))))
; atom relaxed!48 (<= 4.0 (+ (* (- 0.0 r.k-7.x) (- 0.0 r.k-7.x)) (* (- 0.0 r.k-7.y) (- 0.0 r.k-7.y))))
; atom relaxed!50 (<= 4.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y))))
; atom relaxed!54 (<= 4.0 (+ (* (- r.w.x r.b.x) (- r.w.x r.b.x)) (* (- r.w.y r.b.y) (- r.w.y r.b.y))))
; atom relaxed!59 (<= 4.0 (+ (* (- r.w.x r.c.x) (- r.w.x r.c.x)) (* (- r.w.y r.c.y) (- r.w.y r.c.y))))
; atom relaxed!64 (<= 4.0 (+ (* (- r.w.x r.k-1.x) (- r.w.x r.k-1.x)) (* (- r.w.y r.k-1.y) (- r.w.y r.k-1.y))))
; atom relaxed!69 (<= 4.0 (+ (* (- r.w.x r.k-2.x) (- r.w.x r.k-2.x)) (* (- r.w.y r.k-2.y) (- r.w.y r.k-2.y))))
; atom relaxed!74 (<= 4.0 (+ (* (- r.w.x r.k-3.x) (- r.w.x r.k-3.x)) (* (- r.w.y r.k-3.y) (- r.w.y r.k-3.y))))
; atom relaxed!79 (<= 4.0 (+ (* (- r.w.x r.k-4.x) (- r.w.x r.k-4.x)) (* (- r.w.y r.k-4.y) (- r.w.y r.k-4.y))))
; atom relaxed!84 (<= 4.0 (+ (* (- r.w.x r.k-5.x) (- r.w.x r.k-5.x)) (* (- r.w.y r.k-5.y) (- r.w.y r.k-5.y))))
; atom relaxed!89 (<= 4.0 (+ (* (- r.w.x r.k-6.x) (- r.w.x r.k-6.x)) (* (- r.w.y r.k-6.y) (- r.w.y r.k-6.y))))
; atom relaxed!94 (<= 4.0 (+ (* (- r.w.x r.k-7.x) (- r.w.x r.k-7.x)) (* (- r.w.y r.k-7.y) (- r.w.y r.k-7.y))))
; atom relaxed!99 (<= 4.0 (+ (* (- r.w.x o.x) (- r.w.x o.x)) (* (- r.w.y o.y) (- r.w.y o.y))))
; atom relaxed!104 (<= 4.0 (+ (* (- r.b.x r.c.x) (- r.b.x r.c.x)) (* (- r.b.y r.c.y) (- r.b.y r.c.y))))
; atom relaxed!109 (<= 4.0 (+ (* (- r.b.x r.k-1.x) (- r.b.x r.k-1.x)) (* (- r.b.y r.k-1.y) (- r.b.y r.k-1.y))))
; atom relaxed!114 (<= 4.0 (+ (* (- r.b.x r.k-2.x) (- r.b.x r.k-2.x)) (* (- r.b.y r.k-2.y) (- r.b.y r.k-2.y))))
; atom relaxed!119 (<= 4.0 (+ (* (- r.b.x r.k-3.x) (- r.b.x r.k-3.x)) (* (- r.b.y r.k-3.y) (- r.b.y r.k-3.y))))
; atom relaxed!124 (<= 4.0 (+ (* (- r.b.x r.k-4.x) (- r.b.x r.k-4.x)) (* (- r.b.y r.k-4.y) (- r.b.y r.k-4.y))))
; atom relaxed!129 (<= 4.0 (+ (* (- r.b.x r.k-5.x) (- r.b.x r.k-5.x)) (* (- r.b.y r.k-5.y) (- r.b.y r.k-5.y))))
; atom relaxed!134 (<= 4.0 (+ (* (- r.b.x r.k-6.x) (- r.b.x r.k-6.x)) (* (- r.b.y r.k-6.y) (- r.b.y r.k-6.y))))
; atom relaxed!139 (<= 4.0 (+ (* (- r.b.x r.k-7.x) (- r.b.x r.k-7.x)) (* (- r.b.y r.k-7.y) (- r.b.y r.k-7.y))))
; atom relaxed!144 (<= 4.0 (+ (* (- r.b.x o.x) (- r.b.x o.x)) (* (- r.b.y o.y) (- r.b.y o.y))))
; atom relaxed!149 (<= 4.0 (+ (* (- r.c.x r.k-1.x) (- r.c.x r.k-1.x)) (* (- r.c.y r.k-1.y) (- r.c.y r.k-1.y))))
; atom relaxed!154 (<= 4.0 (+ (* (- r.c.x r.k-2.x) (- r.c.x r.k-2.x)) (* (- r.c.y r.k-2.y) (- r.c.y r.k-2.y))))
; atom relaxed!159 (<= 4.0 (+ (* (- r.c.x r.k-3.x) (- r.c.x r.k-3.x)) (* (- r.c.y r.k-3.y) (- r.c.y r.k-3.y))))
; atom relaxed!164 (<= 4.0 (+ (* (- r.c.x r.k-4.x) (- r.c.x r.k-4.x)) (* (- r.c.y r.k-4.y) (- r.c.y r.k-4.y))))
; atom relaxed!169 (<= 4.0 (+ (* (- r.c.x r.k-5.x) (- r.c.x r.k-5.x)) (* (- r.c.y r.k-5.y) (- r.c.y r.k-5.y))))
; atom relaxed!174 (<= 4.0 (+ (* (- r.c.x r.k-6.x) (- r.c.x r.k-6.x)) (* (- r.c.y r.k-6.y) (- r.c.y r.k-6.y))))
; atom relaxed!179 (<= 4.0 (+ (* (- r.c.x r.k-7.x) (- r.c.x r.k-7.x)) (* (- r.c.y r.k-7.y) (- r.c.y r.k-7.y))))
; atom relaxed!184 (<= 4.0 (+ (* (- r.c.x o.x) (- r.c.x o.x)) (* (- r.c.y o.y) (- r.c.y o.y))))
; atom relaxed!189 (<= 4.0 (+ (* (- r.k-1.x r.k-2.x) (- r.k-1.x r.k-2.x)) (* (- r.k-1.y r.k-2.y) (- r.k-1.y r.k-2.y))))
; atom relaxed!194 (<= 4.0 (+ (* (- r.k-1.x r.k-3.x) (- r.k-1.x r.k-3.x)) (* (- r.k-1.y r.k-3.y) (- r.k-1.y r.k-3.y))))
; atom relaxed!199 (<= 4.0 (+ (* (- r.k-1.x r.k-4.x) (- r.k-1.x r.k-4.x)) (* (- r.k-1.y r.k-4.y) (- r.k-1.y r.k-4.y))))
; atom relaxed!204 (<= 4.0 (+ (* (- r.k-1.x r.k-5.x) (- r.k-1.x r.k-5.x)) (* (- r.k-1.y r.k-5.y) (- r.k-1.y r.k-5.y))))
; atom relaxed!209 (<= 4.0 (+ (* (- r.k-1.x r.k-6.x) (- r.k-1.x r.k-6.x)) (* (- r.k-1.y r.k-6.y) (- r.k-1.y r.k-6.y))))
; atom relaxed!214 (<= 4.0 (+ (* (- r.k-1.x r.k-7.x) (- r.k-1.x r.k-7.x)) (* (- r.k-1.y r.k-7.y) (- r.k-1.y r.k-7.y))))
; atom relaxed!219 (<= 4.0 (+ (* (- r.k-1.x o.x) (- r.k-1.x o.x)) (* (- r.k-1.y o.y) (- r.k-1.y o.y))))
; atom relaxed!224 (<= 4.0 (+ (* (- r.k-2.x r.k-3.x) (- r.k-2.x r.k-3.x)) (* (- r.k-2.y r.k-3.y) (- r.k-2.y r.k-3.y))))
; atom relaxed!229 (<= 4.0 (+ (* (- r.k-2.x r.k-4.x) (- r.k-2.x r.k-4.x)) (* (- r.k-2.y r.k-4.y) (- r.k-2.y r.k-4.y))))
; atom relaxed!234 (<= 4.0 (+ (* (- r.k-2.x r.k-5.x) (- r.k-2.x r.k-5.x)) (* (- r.k-2.y r.k-5.y) (- r.k-2.y r.k-5.y))))
; atom relaxed!239 (<= 4.0 (+ (* (- r.k-2.x r.k-6.x) (- r.k-2.x r.k-6.x)) (* (- r.k-2.y r.k-6.y) (- r.k-2.y r.k-6.y))))
; atom relaxed!244 (<= 4.0 (+ (* (- r.k-2.x r.k-7.x) (- r.k-2.x r.k-7.x)) (* (- r.k-2.y r.k-7.y) (- r.k-2.y r.k-7.y))))
; atom relaxed!249 (<= 4.0 (+ (* (- r.k-2.x o.x) (- r.k-2.x o.x)) (* (- r.k-2.y o.y) (- r.k-2.y o.y))))
; atom relaxed!254 (<= 4.0 (+ (* (- r.k-3.x r.k-4.x) (- r.k-3.x r.k-4.x)) (* (- r.k-3.y r.k-4.y) (- r.k-3.y r.k-4.y))))
; atom relaxed!259 (<= 4.0 (+ (* (- r.k-3.x r.k-5.x) (- r.k-3.x r.k-5.x)) (* (- r.k-3.y r.k-5.y) (- r.k-3.y r.k-5.y))))
; atom relaxed!264 (<= 4.0 (+ (* (- r.k-3.x r.k-6.x) (- r.k-3.x r.k-6.x)) (* (- r.k-3.y r.k-6.y) (- r.k-3.y r.k-6.y))))
; atom relaxed!269 (<= 4.0 (+ (* (- r.k-3.x r.k-7.x) (- r.k-3.x r.k-7.x)) (* (- r.k-3.y r.k-7.y) (- r.k-3.y r.k-7.y))))
; atom relaxed!274 (<= 4.0 (+ (* (- r.k-3.x o.x) (- r.k-3.x o.x)) (* (- r.k-3.y o.y) (- r.k-3.y o.y))))
; atom relaxed!279 (<= 4.0 (+ (* (- r.k-4.x r.k-5.x) (- r.k-4.x r.k-5.x)) (* (- r.k-4.y r.k-5.y) (- r.k-4.y r.k-5.y))))
; atom relaxed!284 (<= 4.0 (+ (* (- r.k-4.x r.k-6.x) (- r.k-4.x r.k-6.x)) (* (- r.k-4.y r.k-6.y) (- r.k-4.y r.k-6.y))))
; atom relaxed!289 (<= 4.0 (+ (* (- r.k-4.x r.k-7.x) (- r.k-4.x r.k-7.x)) (* (- r.k-4.y r.k-7.y) (- r.k-4.y r.k-7.y))))
; atom relaxed!294 (<= 4.0 (+ (* (- r.k-4.x o.x) (- r.k-4.x o.x)) (* (- r.k-4.y o.y) (- r.k-4.y o.y))))
; atom relaxed!299 (<= 4.0 (+ (* (- r.k-5.x r.k-6.x) (- r.k-5.x r.k-6.x)) (* (- r.k-5.y r.k-6.y) (- r.k-5.y r.k-6.y))))
; atom relaxed!304 (<= 4.0 (+ (* (- r.k-5.x r.k-7.x) (- r.k-5.x r.k-7.x)) (* (- r.k-5.y r.k-7.y) (- r.k-5.y r.k-7.y))))
; atom relaxed!309 (<= 4.0 (+ (* (- r.k-5.x o.x) (- r.k-5.x o.x)) (* (- r.k-5.y o.y) (- r.k-5.y o.y))))
; atom relaxed!314 (<= 4.0 (+ (* (- r.k-6.x r.k-7.x) (- r.k-6.x r.k-7.x)) (* (- r.k-6.y r.k-7.y) (- r.k-6.y r.k-7.y))))
; atom relaxed!319 (<= 4.0 (+ (* (- r.k-6.x o.x) (- r.k-6.x o.x)) (* (- r.k-6.y o.y) (- r.k-6.y o.y))))
; atom relaxed!324 (<= 4.0 (+ (* (- r.k-7.x o.x) (- r.k-7.x o.x)) (* (- r.k-7.y o.y) (- r.k-7.y o.y))))
; atom relaxed!328 (>= 16.0 (+ (* (- 0.0 r.w.x) (- 0.0 r.w.x)) (* (- 0.0 r.w.y) (- 0.0 r.w.y))))
; atom relaxed!353 (>= 16.0 (+ (* (- 0.0 r.b.x) (- 0.0 r.b.x)) (* (- 0.0 r.b.y) (- 0.0 r.b.y))))
; atom relaxed!377 (>= 16.0 (+ (* (- 0.0 r.c.x) (- 0.0 r.c.x)) (* (- 0.0 r.c.y) (- 0.0 r.c.y))))
; atom relaxed!397 (>= 16.0 (+ (* (- 0.0 r.k-1.x) (- 0.0 r.k-1.x)) (* (- 0.0 r.k-1.y) (- 0.0 r.k-1.y))))
; atom relaxed!398 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 1.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (> 4.0 a!1))
; atom relaxed!400 (>= 16.0 (+ (* (- 0.0 r.k-2.x) (- 0.0 r.k-2.x)) (* (- 0.0 r.k-2.y) (- 0.0 r.k-2.y))))
; atom relaxed!401 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 2.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (> 4.0 a!1))
; atom relaxed!403 (>= 16.0 (+ (* (- 0.0 r.k-3.x) (- 0.0 r.k-3.x)) (* (- 0.0 r.k-3.y) (- 0.0 r.k-3.y))))
; atom relaxed!404 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 3.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (> 4.0 a!1))
; atom relaxed!406 (>= 16.0 (+ (* (- 0.0 r.k-4.x) (- 0.0 r.k-4.x)) (* (- 0.0 r.k-4.y) (- 0.0 r.k-4.y))))
; atom relaxed!407 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 4.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (> 4.0 a!1))
; atom relaxed!409 (>= 16.0 (+ (* (- 0.0 r.k-5.x) (- 0.0 r.k-5.x)) (* (- 0.0 r.k-5.y) (- 0.0 r.k-5.y))))
; atom relaxed!410 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (> 4.0 a!1))
; atom relaxed!412 (>= 16.0 (+ (* (- 0.0 r.k-6.x) (- 0.0 r.k-6.x)) (* (- 0.0 r.k-6.y) (- 0.0 r.k-6.y))))
; atom relaxed!413 (let ((a!1 (+ (* (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-6.y 0.0) (- 6.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (> 4.0 a!1))
; atom relaxed!415 (>= 16.0 (+ (* (- 0.0 r.k-7.x) (- 0.0 r.k-7.x)) (* (- 0.0 r.k-7.y) (- 0.0 r.k-7.y))))
; atom relaxed!416 (let ((a!1 (+ (* (- (- r.k-7.x 0.0) (- r.w.x 0.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-7.y 0.0) (- 7.0)) (- (- r.k-7.y 0.0) (- 7.0)))))) (> 4.0 a!1))
; atom relaxed!449 (let ((a!1 (+ (* (- (- 0.0 0.0) (- r.w.x 0.0)) (- (- 0.0 0.0) (- r.w.x 0.0))) (* (- (- 0.0 0.0) (- 8.0)) (- (- 0.0 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!467 (let ((a!1 (+ (* (- (- r.w.x 0.0) (- r.w.x 0.0)) (- (- r.w.x 0.0) (- r.w.x 0.0))) (* (- (- r.w.y 0.0) (- 8.0)) (- (- r.w.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!486 (let ((a!1 (+ (* (- (- r.b.x 0.0) (- r.w.x 0.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (- r.b.y 0.0) (- 8.0)) (- (- r.b.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!509 (let ((a!1 (+ (* (- (- r.c.x 0.0) (- r.w.x 0.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (- r.c.y 0.0) (- 8.0)) (- (- r.c.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!550 (let ((a!1 (+ (* (- (- r.k-1.x 0.0) (- r.w.x 0.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-1.y 0.0) (- 8.0)) (- (- r.k-1.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!591 (let ((a!1 (+ (* (- (- r.k-2.x 0.0) (- r.w.x 0.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-2.y 0.0) (- 8.0)) (- (- r.k-2.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!632 (let ((a!1 (+ (* (- (- r.k-3.x 0.0) (- r.w.x 0.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-3.y 0.0) (- 8.0)) (- (- r.k-3.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!673 (let ((a!1 (+ (* (- (- r.k-4.x 0.0) (- r.w.x 0.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-4.y 0.0) (- 8.0)) (- (- r.k-4.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!714 (let ((a!1 (+ (* (- (- r.k-5.x 0.0) (- r.w.x 0.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-5.y 0.0) (- 8.0)) (- (- r.k-5.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!755 (let ((a!1 (+ (* (- (- r.k-6.x 0.0) (- r.w.x 0.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-6.y 0.0) (- 8.0)) (- (- r.k-6.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!796 (let ((a!1 (+ (* (- (- r.k-7.x 0.0) (- r.w.x 0.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (- r.k-7.y 0.0) (- 8.0)) (- (- r.k-7.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!804 (>= 16.0 (+ (* (- 0.0 o.x) (- 0.0 o.x)) (* (- 0.0 o.y) (- 0.0 o.y))))
; atom relaxed!841 (let ((a!1 (+ (* (- (- o.x 0.0) (- r.w.x 0.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (- o.y 0.0) (- 8.0)) (- (- o.y 0.0) (- 8.0)))))) (> 4.0 a!1))
; atom relaxed!849 (let ((a!1 (* (- (+ 0.0 (- r.w.x 0.0)) o.x) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (- (+ 0.0 (- 8.0)) o.y) (- (+ 0.0 (- 8.0)) o.y))))) (>= 16.0 a!2)))
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
(declare-fun r.k-7.y () Real)
(declare-fun r.k-7.x () Real)
(declare-fun relaxed!50 () Bool)
(declare-fun relaxed!54 () Bool)
(declare-fun relaxed!59 () Bool)
(declare-fun relaxed!64 () Bool)
(declare-fun relaxed!69 () Bool)
(declare-fun relaxed!74 () Bool)
(declare-fun relaxed!79 () Bool)
(declare-fun relaxed!84 () Bool)
(declare-fun relaxed!89 () Bool)
(declare-fun relaxed!94 () Bool)
(declare-fun relaxed!99 () Bool)
(declare-fun o.y () Real)
(declare-fun o.x () Real)
(declare-fun relaxed!104 () Bool)
(declare-fun relaxed!109 () Bool)
(declare-fun relaxed!114 () Bool)
(declare-fun relaxed!119 () Bool)
(declare-fun relaxed!124 () Bool)
(declare-fun relaxed!129 () Bool)
(declare-fun relaxed!134 () Bool)
(declare-fun relaxed!139 () Bool)
(declare-fun relaxed!144 () Bool)
(declare-fun relaxed!149 () Bool)
(declare-fun relaxed!154 () Bool)
(declare-fun relaxed!159 () Bool)
(declare-fun relaxed!164 () Bool)
(declare-fun relaxed!169 () Bool)
(declare-fun relaxed!174 () Bool)
(declare-fun relaxed!179 () Bool)
(declare-fun relaxed!184 () Bool)
(declare-fun relaxed!189 () Bool)
(declare-fun relaxed!194 () Bool)
(declare-fun relaxed!199 () Bool)
(declare-fun relaxed!204 () Bool)
(declare-fun relaxed!209 () Bool)
(declare-fun relaxed!214 () Bool)
(declare-fun relaxed!219 () Bool)
(declare-fun relaxed!224 () Bool)
(declare-fun relaxed!229 () Bool)
(declare-fun relaxed!234 () Bool)
(declare-fun relaxed!239 () Bool)
(declare-fun relaxed!244 () Bool)
(declare-fun relaxed!249 () Bool)
(declare-fun relaxed!254 () Bool)
(declare-fun relaxed!259 () Bool)
(declare-fun relaxed!264 () Bool)
(declare-fun relaxed!269 () Bool)
(declare-fun relaxed!274 () Bool)
(declare-fun relaxed!279 () Bool)
(declare-fun relaxed!284 () Bool)
(declare-fun relaxed!289 () Bool)
(declare-fun relaxed!294 () Bool)
(declare-fun relaxed!299 () Bool)
(declare-fun relaxed!304 () Bool)
(declare-fun relaxed!309 () Bool)
(declare-fun relaxed!314 () Bool)
(declare-fun relaxed!319 () Bool)
(declare-fun relaxed!324 () Bool)
(declare-fun relaxed!841 () Bool)
(declare-fun relaxed!804 () Bool)
(declare-fun relaxed!796 () Bool)
(declare-fun relaxed!415 () Bool)
(declare-fun relaxed!755 () Bool)
(declare-fun relaxed!412 () Bool)
(declare-fun relaxed!714 () Bool)
(declare-fun relaxed!409 () Bool)
(declare-fun relaxed!673 () Bool)
(declare-fun relaxed!406 () Bool)
(declare-fun relaxed!632 () Bool)
(declare-fun relaxed!403 () Bool)
(declare-fun relaxed!591 () Bool)
(declare-fun relaxed!400 () Bool)
(declare-fun relaxed!550 () Bool)
(declare-fun relaxed!397 () Bool)
(declare-fun relaxed!509 () Bool)
(declare-fun relaxed!377 () Bool)
(declare-fun relaxed!486 () Bool)
(declare-fun relaxed!353 () Bool)
(declare-fun relaxed!467 () Bool)
(declare-fun relaxed!328 () Bool)
(declare-fun relaxed!449 () Bool)
(declare-fun relaxed!416 () Bool)
(declare-fun relaxed!413 () Bool)
(declare-fun relaxed!410 () Bool)
(declare-fun relaxed!407 () Bool)
(declare-fun relaxed!404 () Bool)
(declare-fun relaxed!401 () Bool)
(declare-fun relaxed!398 () Bool)
(declare-fun r.case0 () Bool)
(declare-fun relaxed!849 () Bool)
(assert (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) relaxed!3))
(assert (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) relaxed!8))
(assert (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) relaxed!13))
(assert (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)) relaxed!18))
(assert (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)) relaxed!23))
(assert (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)) relaxed!28))
(assert (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)) relaxed!33))
(assert (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)) relaxed!38))
(assert (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)) relaxed!43))
(assert (or (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y)) relaxed!48))
(assert relaxed!50)
(assert (or (and (= r.w.x r.b.x) (= r.w.y r.b.y)) relaxed!54))
(assert (or (and (= r.w.x r.c.x) (= r.w.y r.c.y)) relaxed!59))
(assert (or (and (= r.w.x r.k-1.x) (= r.w.y r.k-1.y)) relaxed!64))
(assert (or (and (= r.w.x r.k-2.x) (= r.w.y r.k-2.y)) relaxed!69))
(assert (or (and (= r.w.x r.k-3.x) (= r.w.y r.k-3.y)) relaxed!74))
(assert (or (and (= r.w.x r.k-4.x) (= r.w.y r.k-4.y)) relaxed!79))
(assert (or (and (= r.w.x r.k-5.x) (= r.w.y r.k-5.y)) relaxed!84))
(assert (or (and (= r.w.x r.k-6.x) (= r.w.y r.k-6.y)) relaxed!89))
(assert (or (and (= r.w.x r.k-7.x) (= r.w.y r.k-7.y)) relaxed!94))
(assert (or (and (= r.w.x o.x) (= r.w.y o.y)) relaxed!99))
(assert (or (and (= r.b.x r.c.x) (= r.b.y r.c.y)) relaxed!104))
(assert (or (and (= r.b.x r.k-1.x) (= r.b.y r.k-1.y)) relaxed!109))
(assert (or (and (= r.b.x r.k-2.x) (= r.b.y r.k-2.y)) relaxed!114))
(assert (or (and (= r.b.x r.k-3.x) (= r.b.y r.k-3.y)) relaxed!119))
(assert (or (and (= r.b.x r.k-4.x) (= r.b.y r.k-4.y)) relaxed!124))
(assert (or (and (= r.b.x r.k-5.x) (= r.b.y r.k-5.y)) relaxed!129))
(assert (or (and (= r.b.x r.k-6.x) (= r.b.y r.k-6.y)) relaxed!134))
(assert (or (and (= r.b.x r.k-7.x) (= r.b.y r.k-7.y)) relaxed!139))
(assert (or (and (= r.b.x o.x) (= r.b.y o.y)) relaxed!144))
(assert (or (and (= r.c.x r.k-1.x) (= r.c.y r.k-1.y)) relaxed!149))
(assert (or (and (= r.c.x r.k-2.x) (= r.c.y r.k-2.y)) relaxed!154))
(assert (or (and (= r.c.x r.k-3.x) (= r.c.y r.k-3.y)) relaxed!159))
(assert (or (and (= r.c.x r.k-4.x) (= r.c.y r.k-4.y)) relaxed!164))
(assert (or (and (= r.c.x r.k-5.x) (= r.c.y r.k-5.y)) relaxed!169))
(assert (or (and (= r.c.x r.k-6.x) (= r.c.y r.k-6.y)) relaxed!174))
(assert (or (and (= r.c.x r.k-7.x) (= r.c.y r.k-7.y)) relaxed!179))
(assert (or (and (= r.c.x o.x) (= r.c.y o.y)) relaxed!184))
(assert (or (and (= r.k-1.x r.k-2.x) (= r.k-1.y r.k-2.y)) relaxed!189))
(assert (or (and (= r.k-1.x r.k-3.x) (= r.k-1.y r.k-3.y)) relaxed!194))
(assert (or (and (= r.k-1.x r.k-4.x) (= r.k-1.y r.k-4.y)) relaxed!199))
(assert (or (and (= r.k-1.x r.k-5.x) (= r.k-1.y r.k-5.y)) relaxed!204))
(assert (or (and (= r.k-1.x r.k-6.x) (= r.k-1.y r.k-6.y)) relaxed!209))
(assert (or (and (= r.k-1.x r.k-7.x) (= r.k-1.y r.k-7.y)) relaxed!214))
(assert (or (and (= r.k-1.x o.x) (= r.k-1.y o.y)) relaxed!219))
(assert (or (and (= r.k-2.x r.k-3.x) (= r.k-2.y r.k-3.y)) relaxed!224))
(assert (or (and (= r.k-2.x r.k-4.x) (= r.k-2.y r.k-4.y)) relaxed!229))
(assert (or (and (= r.k-2.x r.k-5.x) (= r.k-2.y r.k-5.y)) relaxed!234))
(assert (or (and (= r.k-2.x r.k-6.x) (= r.k-2.y r.k-6.y)) relaxed!239))
(assert (or (and (= r.k-2.x r.k-7.x) (= r.k-2.y r.k-7.y)) relaxed!244))
(assert (or (and (= r.k-2.x o.x) (= r.k-2.y o.y)) relaxed!249))
(assert (or (and (= r.k-3.x r.k-4.x) (= r.k-3.y r.k-4.y)) relaxed!254))
(assert (or (and (= r.k-3.x r.k-5.x) (= r.k-3.y r.k-5.y)) relaxed!259))
(assert (or (and (= r.k-3.x r.k-6.x) (= r.k-3.y r.k-6.y)) relaxed!264))
(assert (or (and (= r.k-3.x r.k-7.x) (= r.k-3.y r.k-7.y)) relaxed!269))
(assert (or (and (= r.k-3.x o.x) (= r.k-3.y o.y)) relaxed!274))
(assert (or (and (= r.k-4.x r.k-5.x) (= r.k-4.y r.k-5.y)) relaxed!279))
(assert (or (and (= r.k-4.x r.k-6.x) (= r.k-4.y r.k-6.y)) relaxed!284))
(assert (or (and (= r.k-4.x r.k-7.x) (= r.k-4.y r.k-7.y)) relaxed!289))
(assert (or (and (= r.k-4.x o.x) (= r.k-4.y o.y)) relaxed!294))
(assert (or (and (= r.k-5.x r.k-6.x) (= r.k-5.y r.k-6.y)) relaxed!299))
(assert (or (and (= r.k-5.x r.k-7.x) (= r.k-5.y r.k-7.y)) relaxed!304))
(assert (or (and (= r.k-5.x o.x) (= r.k-5.y o.y)) relaxed!309))
(assert (or (and (= r.k-6.x r.k-7.x) (= r.k-6.y r.k-7.y)) relaxed!314))
(assert (or (and (= r.k-6.x o.x) (= r.k-6.y o.y)) relaxed!319))
(assert (or (and (= r.k-7.x o.x) (= r.k-7.y o.y)) relaxed!324))
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
      (a!109 (and (> (- r.k-6.y 0.0) (- 2.0)) (> 2.0 (- r.k-6.y 0.0))))
      (a!119 (and (> (- r.k-7.x 0.0) (- 2.0)) (> 2.0 (- r.k-7.x 0.0))))
      (a!121 (and (> (- r.k-7.y 0.0) (- 2.0)) (> 2.0 (- r.k-7.y 0.0))))
      (a!131 (and (> (- o.x 0.0) (- 2.0)) (> 2.0 (- o.x 0.0))))
      (a!133 (and (> (- o.y 0.0) (- 2.0)) (> 2.0 (- o.y 0.0)))))
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
                 (and a!107 (> 0.0 (- r.k-6.y 0.0)))))
      (a!120 (or (and a!119 (< 0.0 (- r.k-7.y 0.0)))
                 (and a!119 (> 0.0 (- r.k-7.y 0.0)))))
      (a!132 (or (and a!131 (< 0.0 (- o.y 0.0)))
                 (and a!131 (> 0.0 (- o.y 0.0))))))
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
      (a!114 (and (and a!109 (< 0.0 (- r.k-6.x 0.0))) (not a!108)))
      (a!122 (or a!120
                 (and a!121 (< 0.0 (- r.k-7.x 0.0)))
                 (and a!121 (> 0.0 (- r.k-7.x 0.0)))))
      (a!124 (and (and a!121 (> 0.0 (- r.k-7.x 0.0))) (not a!120)))
      (a!126 (and (and a!121 (< 0.0 (- r.k-7.x 0.0))) (not a!120)))
      (a!134 (or a!132
                 (and a!133 (< 0.0 (- o.x 0.0)))
                 (and a!133 (> 0.0 (- o.x 0.0)))))
      (a!136 (and (and a!133 (> 0.0 (- o.x 0.0))) (not a!132)))
      (a!138 (and (and a!133 (< 0.0 (- o.x 0.0))) (not a!132))))
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
      (a!115 (and (not a!110) (> 0.0 (- r.k-6.x 0.0)) (< 0.0 (- r.k-6.y 0.0))))
      (a!123 (not (and (not a!122)
                       (> 0.0 (- r.k-7.x 0.0))
                       (> 0.0 (- r.k-7.y 0.0)))))
      (a!125 (not (and (not a!122)
                       (< 0.0 (- r.k-7.x 0.0))
                       (> 0.0 (- r.k-7.y 0.0)))))
      (a!127 (and (not a!122) (> 0.0 (- r.k-7.x 0.0)) (< 0.0 (- r.k-7.y 0.0))))
      (a!135 (not (and (not a!134) (> 0.0 (- o.x 0.0)) (> 0.0 (- o.y 0.0)))))
      (a!137 (not (and (not a!134) (< 0.0 (- o.x 0.0)) (> 0.0 (- o.y 0.0)))))
      (a!139 (and (not a!134) (> 0.0 (- o.x 0.0)) (< 0.0 (- o.y 0.0)))))
(let ((a!7 (or (and (not a!4) (< 0.0 (- r.w.x 0.0)) (< 0.0 (- r.w.y 0.0)))
               a!5
               a!6))
      (a!28 (and a!21
                 (not a!22)
                 a!23
                 (=> a!26 (>= (- 0.0 0.0) (- r.w.x 0.0)))
                 (not a!27)
                 (not relaxed!449)))
      (a!32 (and (> (- (- r.w.x 0.0) (- r.w.x 0.0)) (- 2.0))
                 (> 2.0 (- (- r.w.x 0.0) (- r.w.x 0.0)))
                 a!6))
      (a!39 (and a!34
                 (not a!35)
                 a!36
                 (=> (or a!13 a!37 a!38) (>= (- r.b.x 0.0) (- r.w.x 0.0)))
                 (not (and a!8 a!38))
                 (not relaxed!486)))
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
                  a!115))
      (a!128 (or (and (not a!122)
                      (< 0.0 (- r.k-7.x 0.0))
                      (< 0.0 (- r.k-7.y 0.0)))
                 a!126
                 a!127))
      (a!129 (and (> (- (- r.k-7.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0)))
                  a!127))
      (a!140 (or (and (not a!134) (< 0.0 (- o.x 0.0)) (< 0.0 (- o.y 0.0)))
                 a!138
                 a!139))
      (a!141 (and (> (- (- o.x 0.0) (- r.w.x 0.0)) (- 2.0))
                  (> 2.0 (- (- o.x 0.0) (- r.w.x 0.0)))
                  a!139)))
(let ((a!33 (and a!29
                 (not a!30)
                 a!31
                 (=> a!7 (>= (- r.w.x 0.0) (- r.w.x 0.0)))
                 (not a!32)
                 (not relaxed!467)))
      (a!46 (and a!41
                 (not a!42)
                 a!43
                 (=> a!45 (>= (- r.c.x 0.0) (- r.w.x 0.0)))
                 (not (and a!14 a!44))
                 (not relaxed!509)))
      (a!58 (and a!51
                 (not a!52)
                 a!53
                 (=> a!56 (>= (- r.k-1.x 0.0) (- r.w.x 0.0)))
                 (not a!57)
                 (not relaxed!550)))
      (a!70 (and a!63
                 (not a!64)
                 a!65
                 (=> a!68 (>= (- r.k-2.x 0.0) (- r.w.x 0.0)))
                 (not a!69)
                 (not relaxed!591)))
      (a!82 (and a!75
                 (not a!76)
                 a!77
                 (=> a!80 (>= (- r.k-3.x 0.0) (- r.w.x 0.0)))
                 (not a!81)
                 (not relaxed!632)))
      (a!94 (and a!87
                 (not a!88)
                 a!89
                 (=> a!92 (>= (- r.k-4.x 0.0) (- r.w.x 0.0)))
                 (not a!93)
                 (not relaxed!673)))
      (a!106 (and a!99
                  (not a!100)
                  a!101
                  (=> a!104 (>= (- r.k-5.x 0.0) (- r.w.x 0.0)))
                  (not a!105)
                  (not relaxed!714)))
      (a!118 (and a!111
                  (not a!112)
                  a!113
                  (=> a!116 (>= (- r.k-6.x 0.0) (- r.w.x 0.0)))
                  (not a!117)
                  (not relaxed!755)))
      (a!130 (and a!123
                  (not a!124)
                  a!125
                  (=> a!128 (>= (- r.k-7.x 0.0) (- r.w.x 0.0)))
                  (not a!129)
                  (not relaxed!796)))
      (a!142 (and a!135
                  (not a!136)
                  a!137
                  (=> a!140 (>= (- o.x 0.0) (- r.w.x 0.0)))
                  (not a!141)
                  (not relaxed!841))))
(let ((a!143 (and (not (and (= 0.0 r.w.x) (= 0.0 r.w.y)))
                  relaxed!328
                  a!7
                  (not (and (= 0.0 r.b.x) (= 0.0 r.b.y)))
                  relaxed!353
                  a!8
                  a!13
                  (not (and (= 0.0 r.c.x) (= 0.0 r.c.y)))
                  relaxed!377
                  a!14
                  a!18
                  (not (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y)))
                  relaxed!397
                  relaxed!398
                  (not (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y)))
                  relaxed!400
                  relaxed!401
                  (not (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y)))
                  relaxed!403
                  relaxed!404
                  (not (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y)))
                  relaxed!406
                  relaxed!407
                  (not (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y)))
                  relaxed!409
                  relaxed!410
                  (not (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y)))
                  relaxed!412
                  relaxed!413
                  (not (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y)))
                  relaxed!415
                  relaxed!416
                  true
                  (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true a!28))
                  (or (and (= 0.0 r.w.x) (= 0.0 r.w.y)) (=> relaxed!328 a!33))
                  (or (and (= 0.0 r.b.x) (= 0.0 r.b.y)) (=> relaxed!353 a!39))
                  (or (and (= 0.0 r.c.x) (= 0.0 r.c.y)) (=> relaxed!377 a!46))
                  (or (and (= 0.0 r.k-1.x) (= 0.0 r.k-1.y))
                      (=> relaxed!397 a!58))
                  (or (and (= 0.0 r.k-2.x) (= 0.0 r.k-2.y))
                      (=> relaxed!400 a!70))
                  (or (and (= 0.0 r.k-3.x) (= 0.0 r.k-3.y))
                      (=> relaxed!403 a!82))
                  (or (and (= 0.0 r.k-4.x) (= 0.0 r.k-4.y))
                      (=> relaxed!406 a!94))
                  (or (and (= 0.0 r.k-5.x) (= 0.0 r.k-5.y))
                      (=> relaxed!409 a!106))
                  (or (and (= 0.0 r.k-6.x) (= 0.0 r.k-6.y))
                      (=> relaxed!412 a!118))
                  (or (and (= 0.0 r.k-7.x) (= 0.0 r.k-7.y))
                      (=> relaxed!415 a!130))
                  (or (and (= 0.0 o.x) (= 0.0 o.y)) (=> relaxed!804 a!142)))))
  (=> r.case0 a!143)))))))))
(assert (or r.case0))
(assert (and relaxed!804 (not relaxed!849)))
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
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-7.x)) (* 0.0 (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-7.x)) (* (/ 4.0 5.0) (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-7.x)) (* 1.0 (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 3.0 5.0) (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-7.x)) (* 0.0 (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-7.x)) (* (- 1.0) (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.y))) 2.0))) (=> (not relaxed!48) a!1)))
; cut relaxed!48
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-7.x)) (* (/ 4.0 5.0) (- 0.0 r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-7.x)) (* (/ 9.0 5.0) (- 0.0 r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 8.0 5.0) (- 0.0 r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 3.0 5.0) (- 0.0 r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!48)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 o.x)) (* 0.0 (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 o.x)) (* (/ 4.0 5.0) (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 o.x)) (* 1.0 (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 o.x)) (* (/ 3.0 5.0) (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 o.x)) (* 0.0 (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 o.x)) (* (- (/ 4.0 5.0)) (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 o.x)) (* (- 1.0) (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 o.x)) (* (- (/ 3.0 5.0)) (- 0.0 o.y))) 2.0))) (=> (not relaxed!50) a!1)))
; cut relaxed!50
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 o.x)) (* (/ 4.0 5.0) (- 0.0 o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 o.x)) (* (/ 9.0 5.0) (- 0.0 o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 o.x)) (* (/ 8.0 5.0) (- 0.0 o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 o.x)) (* (/ 3.0 5.0) (- 0.0 o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 o.x)) (* (- (/ 4.0 5.0)) (- 0.0 o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 o.x)) (* (- (/ 9.0 5.0)) (- 0.0 o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 o.x)) (* (- (/ 8.0 5.0)) (- 0.0 o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 o.x)) (* (- (/ 3.0 5.0)) (- 0.0 o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!50)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* 1.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.b.x)) (* 0.0 (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.b.x)) (* (- 1.0) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) 2.0))) (=> (not relaxed!54) a!1)))
; cut relaxed!54
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.b.x)) (* (/ 4.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.b.x)) (* (/ 9.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.b.x)) (* (/ 8.0 5.0) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.b.x)) (* (/ 3.0 5.0) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.b.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.b.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.b.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.b.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.b.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!54)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* 1.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.c.x)) (* 0.0 (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.c.x)) (* (- 1.0) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) 2.0))) (=> (not relaxed!59) a!1)))
; cut relaxed!59
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.c.x)) (* (/ 4.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.c.x)) (* (/ 9.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.c.x)) (* (/ 8.0 5.0) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.c.x)) (* (/ 3.0 5.0) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!59)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* 1.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-1.x)) (* 0.0 (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-1.x)) (* (- 1.0) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) 2.0))) (=> (not relaxed!64) a!1)))
; cut relaxed!64
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-1.x)) (* (/ 4.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-1.x)) (* (/ 9.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 8.0 5.0) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-1.x)) (* (/ 3.0 5.0) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!64)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* 1.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-2.x)) (* 0.0 (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-2.x)) (* (- 1.0) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) 2.0))) (=> (not relaxed!69) a!1)))
; cut relaxed!69
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-2.x)) (* (/ 4.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-2.x)) (* (/ 9.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 8.0 5.0) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-2.x)) (* (/ 3.0 5.0) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!69)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* 1.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-3.x)) (* 0.0 (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-3.x)) (* (- 1.0) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) 2.0))) (=> (not relaxed!74) a!1)))
; cut relaxed!74
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-3.x)) (* (/ 4.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-3.x)) (* (/ 9.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 8.0 5.0) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-3.x)) (* (/ 3.0 5.0) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!74)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* 1.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-4.x)) (* 0.0 (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-4.x)) (* (- 1.0) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) 2.0))) (=> (not relaxed!79) a!1)))
; cut relaxed!79
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-4.x)) (* (/ 4.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-4.x)) (* (/ 9.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 8.0 5.0) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-4.x)) (* (/ 3.0 5.0) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!79)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* 1.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-5.x)) (* 0.0 (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-5.x)) (* (- 1.0) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) 2.0))) (=> (not relaxed!84) a!1)))
; cut relaxed!84
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-5.x)) (* (/ 4.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-5.x)) (* (/ 9.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 8.0 5.0) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-5.x)) (* (/ 3.0 5.0) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!84)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-6.x)) (* 0.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-6.x)) (* (/ 4.0 5.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-6.x)) (* 1.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 3.0 5.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-6.x)) (* 0.0 (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-6.x)) (* (- 1.0) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-6.y))) 2.0))) (=> (not relaxed!89) a!1)))
; cut relaxed!89
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-6.x)) (* (/ 4.0 5.0) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-6.x)) (* (/ 9.0 5.0) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 8.0 5.0) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-6.x)) (* (/ 3.0 5.0) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!89)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x r.k-7.x)) (* 0.0 (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x r.k-7.x)) (* (/ 4.0 5.0) (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-7.x)) (* 1.0 (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-7.x)) (* (/ 3.0 5.0) (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x r.k-7.x)) (* 0.0 (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x r.k-7.x)) (* (- 1.0) (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-7.y))) 2.0))) (=> (not relaxed!94) a!1)))
; cut relaxed!94
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x r.k-7.x)) (* (/ 4.0 5.0) (- r.w.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x r.k-7.x)) (* (/ 9.0 5.0) (- r.w.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x r.k-7.x)) (* (/ 8.0 5.0) (- r.w.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x r.k-7.x)) (* (/ 3.0 5.0) (- r.w.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.w.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.w.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.w.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.w.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!94)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* 1.0 (- r.w.x o.x)) (* 0.0 (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.w.x o.x)) (* (/ 4.0 5.0) (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x o.x)) (* 1.0 (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.w.x o.x)) (* (/ 3.0 5.0) (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.w.x o.x)) (* 0.0 (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.w.x o.x)) (* (- (/ 4.0 5.0)) (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* 0.0 (- r.w.x o.x)) (* (- 1.0) (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.w.x o.x)) (* (- (/ 3.0 5.0)) (- r.w.y o.y))) 2.0))) (=> (not relaxed!99) a!1)))
; cut relaxed!99
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.w.x o.x)) (* (/ 4.0 5.0) (- r.w.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.w.x o.x)) (* (/ 9.0 5.0) (- r.w.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.w.x o.x)) (* (/ 8.0 5.0) (- r.w.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.w.x o.x)) (* (/ 3.0 5.0) (- r.w.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.w.x o.x)) (* (- (/ 4.0 5.0)) (- r.w.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.w.x o.x)) (* (- (/ 9.0 5.0)) (- r.w.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.w.x o.x)) (* (- (/ 8.0 5.0)) (- r.w.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.w.x o.x)) (* (- (/ 3.0 5.0)) (- r.w.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!99)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* 1.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.c.x)) (* 0.0 (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.c.x)) (* (- 1.0) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) 2.0))) (=> (not relaxed!104) a!1)))
; cut relaxed!104
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.c.x)) (* (/ 4.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.c.x)) (* (/ 9.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.c.x)) (* (/ 8.0 5.0) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.c.x)) (* (/ 3.0 5.0) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.c.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.c.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.c.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.c.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.c.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!104)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* 1.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-1.x)) (* 0.0 (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-1.x)) (* (- 1.0) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) 2.0))) (=> (not relaxed!109) a!1)))
; cut relaxed!109
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-1.x)) (* (/ 4.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-1.x)) (* (/ 9.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 8.0 5.0) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-1.x)) (* (/ 3.0 5.0) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!109)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* 1.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-2.x)) (* 0.0 (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-2.x)) (* (- 1.0) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) 2.0))) (=> (not relaxed!114) a!1)))
; cut relaxed!114
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-2.x)) (* (/ 4.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-2.x)) (* (/ 9.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 8.0 5.0) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-2.x)) (* (/ 3.0 5.0) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!114)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* 1.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-3.x)) (* 0.0 (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-3.x)) (* (- 1.0) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) 2.0))) (=> (not relaxed!119) a!1)))
; cut relaxed!119
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-3.x)) (* (/ 4.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-3.x)) (* (/ 9.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 8.0 5.0) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-3.x)) (* (/ 3.0 5.0) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!119)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* 1.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-4.x)) (* 0.0 (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-4.x)) (* (- 1.0) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) 2.0))) (=> (not relaxed!124) a!1)))
; cut relaxed!124
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-4.x)) (* (/ 4.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-4.x)) (* (/ 9.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 8.0 5.0) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-4.x)) (* (/ 3.0 5.0) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!124)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* 1.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-5.x)) (* 0.0 (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-5.x)) (* (- 1.0) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) 2.0))) (=> (not relaxed!129) a!1)))
; cut relaxed!129
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-5.x)) (* (/ 4.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-5.x)) (* (/ 9.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 8.0 5.0) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-5.x)) (* (/ 3.0 5.0) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!129)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-6.x)) (* 0.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-6.x)) (* (/ 4.0 5.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-6.x)) (* 1.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 3.0 5.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-6.x)) (* 0.0 (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-6.x)) (* (- 1.0) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-6.y))) 2.0))) (=> (not relaxed!134) a!1)))
; cut relaxed!134
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-6.x)) (* (/ 4.0 5.0) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-6.x)) (* (/ 9.0 5.0) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 8.0 5.0) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-6.x)) (* (/ 3.0 5.0) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!134)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x r.k-7.x)) (* 0.0 (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x r.k-7.x)) (* (/ 4.0 5.0) (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-7.x)) (* 1.0 (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-7.x)) (* (/ 3.0 5.0) (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x r.k-7.x)) (* 0.0 (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x r.k-7.x)) (* (- 1.0) (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-7.y))) 2.0))) (=> (not relaxed!139) a!1)))
; cut relaxed!139
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x r.k-7.x)) (* (/ 4.0 5.0) (- r.b.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x r.k-7.x)) (* (/ 9.0 5.0) (- r.b.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x r.k-7.x)) (* (/ 8.0 5.0) (- r.b.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x r.k-7.x)) (* (/ 3.0 5.0) (- r.b.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.b.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.b.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.b.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.b.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!139)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* 1.0 (- r.b.x o.x)) (* 0.0 (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.b.x o.x)) (* (/ 4.0 5.0) (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x o.x)) (* 1.0 (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.b.x o.x)) (* (/ 3.0 5.0) (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.b.x o.x)) (* 0.0 (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.b.x o.x)) (* (- (/ 4.0 5.0)) (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* 0.0 (- r.b.x o.x)) (* (- 1.0) (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.b.x o.x)) (* (- (/ 3.0 5.0)) (- r.b.y o.y))) 2.0))) (=> (not relaxed!144) a!1)))
; cut relaxed!144
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.b.x o.x)) (* (/ 4.0 5.0) (- r.b.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.b.x o.x)) (* (/ 9.0 5.0) (- r.b.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.b.x o.x)) (* (/ 8.0 5.0) (- r.b.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.b.x o.x)) (* (/ 3.0 5.0) (- r.b.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.b.x o.x)) (* (- (/ 4.0 5.0)) (- r.b.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.b.x o.x)) (* (- (/ 9.0 5.0)) (- r.b.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.b.x o.x)) (* (- (/ 8.0 5.0)) (- r.b.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.b.x o.x)) (* (- (/ 3.0 5.0)) (- r.b.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!144)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* 1.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-1.x)) (* 0.0 (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-1.x)) (* (- 1.0) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) 2.0))) (=> (not relaxed!149) a!1)))
; cut relaxed!149
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-1.x)) (* (/ 4.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-1.x)) (* (/ 9.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 8.0 5.0) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-1.x)) (* (/ 3.0 5.0) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-1.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-1.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-1.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-1.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!149)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* 1.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-2.x)) (* 0.0 (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-2.x)) (* (- 1.0) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) 2.0))) (=> (not relaxed!154) a!1)))
; cut relaxed!154
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-2.x)) (* (/ 4.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-2.x)) (* (/ 9.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 8.0 5.0) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-2.x)) (* (/ 3.0 5.0) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!154)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* 1.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-3.x)) (* 0.0 (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-3.x)) (* (- 1.0) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) 2.0))) (=> (not relaxed!159) a!1)))
; cut relaxed!159
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-3.x)) (* (/ 4.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-3.x)) (* (/ 9.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 8.0 5.0) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-3.x)) (* (/ 3.0 5.0) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!159)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* 1.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-4.x)) (* 0.0 (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-4.x)) (* (- 1.0) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) 2.0))) (=> (not relaxed!164) a!1)))
; cut relaxed!164
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-4.x)) (* (/ 4.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-4.x)) (* (/ 9.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 8.0 5.0) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-4.x)) (* (/ 3.0 5.0) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!164)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* 1.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-5.x)) (* 0.0 (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-5.x)) (* (- 1.0) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) 2.0))) (=> (not relaxed!169) a!1)))
; cut relaxed!169
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-5.x)) (* (/ 4.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-5.x)) (* (/ 9.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 8.0 5.0) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-5.x)) (* (/ 3.0 5.0) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!169)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-6.x)) (* 0.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-6.x)) (* (/ 4.0 5.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-6.x)) (* 1.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 3.0 5.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-6.x)) (* 0.0 (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-6.x)) (* (- 1.0) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-6.y))) 2.0))) (=> (not relaxed!174) a!1)))
; cut relaxed!174
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-6.x)) (* (/ 4.0 5.0) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-6.x)) (* (/ 9.0 5.0) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 8.0 5.0) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-6.x)) (* (/ 3.0 5.0) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!174)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x r.k-7.x)) (* 0.0 (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x r.k-7.x)) (* (/ 4.0 5.0) (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-7.x)) (* 1.0 (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-7.x)) (* (/ 3.0 5.0) (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x r.k-7.x)) (* 0.0 (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x r.k-7.x)) (* (- 1.0) (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-7.y))) 2.0))) (=> (not relaxed!179) a!1)))
; cut relaxed!179
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x r.k-7.x)) (* (/ 4.0 5.0) (- r.c.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x r.k-7.x)) (* (/ 9.0 5.0) (- r.c.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x r.k-7.x)) (* (/ 8.0 5.0) (- r.c.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x r.k-7.x)) (* (/ 3.0 5.0) (- r.c.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.c.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.c.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.c.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.c.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!179)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* 1.0 (- r.c.x o.x)) (* 0.0 (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.c.x o.x)) (* (/ 4.0 5.0) (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x o.x)) (* 1.0 (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.c.x o.x)) (* (/ 3.0 5.0) (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.c.x o.x)) (* 0.0 (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.c.x o.x)) (* (- (/ 4.0 5.0)) (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* 0.0 (- r.c.x o.x)) (* (- 1.0) (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.c.x o.x)) (* (- (/ 3.0 5.0)) (- r.c.y o.y))) 2.0))) (=> (not relaxed!184) a!1)))
; cut relaxed!184
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.c.x o.x)) (* (/ 4.0 5.0) (- r.c.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.c.x o.x)) (* (/ 9.0 5.0) (- r.c.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.c.x o.x)) (* (/ 8.0 5.0) (- r.c.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.c.x o.x)) (* (/ 3.0 5.0) (- r.c.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.c.x o.x)) (* (- (/ 4.0 5.0)) (- r.c.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.c.x o.x)) (* (- (/ 9.0 5.0)) (- r.c.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.c.x o.x)) (* (- (/ 8.0 5.0)) (- r.c.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.c.x o.x)) (* (- (/ 3.0 5.0)) (- r.c.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!184)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* 1.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-2.x)) (* 0.0 (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-2.x)) (* (- 1.0) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) 2.0))) (=> (not relaxed!189) a!1)))
; cut relaxed!189
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-2.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-2.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-2.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-2.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-2.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!189)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* 1.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-3.x)) (* 0.0 (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-3.x)) (* (- 1.0) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) 2.0))) (=> (not relaxed!194) a!1)))
; cut relaxed!194
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!194)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* 1.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-4.x)) (* 0.0 (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-4.x)) (* (- 1.0) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) 2.0))) (=> (not relaxed!199) a!1)))
; cut relaxed!199
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!199)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* 1.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-5.x)) (* 0.0 (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-5.x)) (* (- 1.0) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) 2.0))) (=> (not relaxed!204) a!1)))
; cut relaxed!204
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!204)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-6.x)) (* 0.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-6.x)) (* 1.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-6.x)) (* 0.0 (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-6.x)) (* (- 1.0) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-6.y))) 2.0))) (=> (not relaxed!209) a!1)))
; cut relaxed!209
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!209)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x r.k-7.x)) (* 0.0 (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-7.x)) (* 1.0 (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x r.k-7.x)) (* 0.0 (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x r.k-7.x)) (* (- 1.0) (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-7.y))) 2.0))) (=> (not relaxed!214) a!1)))
; cut relaxed!214
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-1.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-1.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-1.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-1.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!214)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-1.x o.x)) (* 0.0 (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-1.x o.x)) (* (/ 4.0 5.0) (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x o.x)) (* 1.0 (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x o.x)) (* (/ 3.0 5.0) (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-1.x o.x)) (* 0.0 (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-1.x o.x)) (* (- 1.0) (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-1.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y o.y))) 2.0))) (=> (not relaxed!219) a!1)))
; cut relaxed!219
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-1.x o.x)) (* (/ 4.0 5.0) (- r.k-1.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-1.x o.x)) (* (/ 9.0 5.0) (- r.k-1.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-1.x o.x)) (* (/ 8.0 5.0) (- r.k-1.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-1.x o.x)) (* (/ 3.0 5.0) (- r.k-1.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-1.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-1.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-1.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-1.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-1.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-1.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-1.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-1.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!219)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* 1.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-3.x)) (* 0.0 (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-3.x)) (* (- 1.0) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) 2.0))) (=> (not relaxed!224) a!1)))
; cut relaxed!224
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-3.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-3.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-3.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-3.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-3.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!224)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* 1.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-4.x)) (* 0.0 (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-4.x)) (* (- 1.0) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) 2.0))) (=> (not relaxed!229) a!1)))
; cut relaxed!229
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!229)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* 1.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-5.x)) (* 0.0 (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-5.x)) (* (- 1.0) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) 2.0))) (=> (not relaxed!234) a!1)))
; cut relaxed!234
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!234)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-6.x)) (* 0.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-6.x)) (* 1.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-6.x)) (* 0.0 (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-6.x)) (* (- 1.0) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-6.y))) 2.0))) (=> (not relaxed!239) a!1)))
; cut relaxed!239
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!239)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x r.k-7.x)) (* 0.0 (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-7.x)) (* 1.0 (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x r.k-7.x)) (* 0.0 (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x r.k-7.x)) (* (- 1.0) (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-7.y))) 2.0))) (=> (not relaxed!244) a!1)))
; cut relaxed!244
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-2.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-2.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-2.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-2.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!244)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-2.x o.x)) (* 0.0 (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-2.x o.x)) (* (/ 4.0 5.0) (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x o.x)) (* 1.0 (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x o.x)) (* (/ 3.0 5.0) (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-2.x o.x)) (* 0.0 (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-2.x o.x)) (* (- 1.0) (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-2.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y o.y))) 2.0))) (=> (not relaxed!249) a!1)))
; cut relaxed!249
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-2.x o.x)) (* (/ 4.0 5.0) (- r.k-2.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-2.x o.x)) (* (/ 9.0 5.0) (- r.k-2.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-2.x o.x)) (* (/ 8.0 5.0) (- r.k-2.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-2.x o.x)) (* (/ 3.0 5.0) (- r.k-2.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-2.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-2.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-2.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-2.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-2.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-2.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-2.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-2.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!249)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* 1.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-4.x)) (* 0.0 (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-4.x)) (* (- 1.0) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) 2.0))) (=> (not relaxed!254) a!1)))
; cut relaxed!254
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-4.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-4.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-4.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-4.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-4.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!254)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* 1.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-5.x)) (* 0.0 (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-5.x)) (* (- 1.0) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) 2.0))) (=> (not relaxed!259) a!1)))
; cut relaxed!259
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!259)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-6.x)) (* 0.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-6.x)) (* 1.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-6.x)) (* 0.0 (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-6.x)) (* (- 1.0) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-6.y))) 2.0))) (=> (not relaxed!264) a!1)))
; cut relaxed!264
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!264)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x r.k-7.x)) (* 0.0 (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-7.x)) (* 1.0 (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x r.k-7.x)) (* 0.0 (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x r.k-7.x)) (* (- 1.0) (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-7.y))) 2.0))) (=> (not relaxed!269) a!1)))
; cut relaxed!269
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-3.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-3.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-3.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-3.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!269)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-3.x o.x)) (* 0.0 (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-3.x o.x)) (* (/ 4.0 5.0) (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x o.x)) (* 1.0 (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x o.x)) (* (/ 3.0 5.0) (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-3.x o.x)) (* 0.0 (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-3.x o.x)) (* (- 1.0) (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-3.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y o.y))) 2.0))) (=> (not relaxed!274) a!1)))
; cut relaxed!274
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-3.x o.x)) (* (/ 4.0 5.0) (- r.k-3.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-3.x o.x)) (* (/ 9.0 5.0) (- r.k-3.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-3.x o.x)) (* (/ 8.0 5.0) (- r.k-3.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-3.x o.x)) (* (/ 3.0 5.0) (- r.k-3.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-3.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-3.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-3.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-3.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-3.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-3.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-3.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-3.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!274)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* 1.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-5.x)) (* 0.0 (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-5.x)) (* (- 1.0) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) 2.0))) (=> (not relaxed!279) a!1)))
; cut relaxed!279
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-5.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-5.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-5.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-5.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-5.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!279)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-6.x)) (* 0.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-6.x)) (* 1.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-6.x)) (* 0.0 (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-6.x)) (* (- 1.0) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-6.y))) 2.0))) (=> (not relaxed!284) a!1)))
; cut relaxed!284
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!284)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x r.k-7.x)) (* 0.0 (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-7.x)) (* 1.0 (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x r.k-7.x)) (* 0.0 (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x r.k-7.x)) (* (- 1.0) (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-7.y))) 2.0))) (=> (not relaxed!289) a!1)))
; cut relaxed!289
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-4.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-4.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-4.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-4.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!289)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-4.x o.x)) (* 0.0 (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-4.x o.x)) (* (/ 4.0 5.0) (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x o.x)) (* 1.0 (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x o.x)) (* (/ 3.0 5.0) (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-4.x o.x)) (* 0.0 (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-4.x o.x)) (* (- 1.0) (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-4.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y o.y))) 2.0))) (=> (not relaxed!294) a!1)))
; cut relaxed!294
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-4.x o.x)) (* (/ 4.0 5.0) (- r.k-4.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-4.x o.x)) (* (/ 9.0 5.0) (- r.k-4.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-4.x o.x)) (* (/ 8.0 5.0) (- r.k-4.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-4.x o.x)) (* (/ 3.0 5.0) (- r.k-4.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-4.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-4.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-4.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-4.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-4.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-4.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-4.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-4.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!294)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-5.x r.k-6.x)) (* 0.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-6.x)) (* 1.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-5.x r.k-6.x)) (* 0.0 (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-6.x)) (* (- 1.0) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-6.y))) 2.0))) (=> (not relaxed!299) a!1)))
; cut relaxed!299
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-6.x)) (* (/ 9.0 5.0) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 8.0 5.0) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-5.x r.k-6.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-6.x)) (* (- (/ 9.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 8.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-5.x r.k-6.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-6.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!299)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-5.x r.k-7.x)) (* 0.0 (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-7.x)) (* 1.0 (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-5.x r.k-7.x)) (* 0.0 (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x r.k-7.x)) (* (- 1.0) (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-7.y))) 2.0))) (=> (not relaxed!304) a!1)))
; cut relaxed!304
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-5.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-5.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-5.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-5.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-5.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-5.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-5.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-5.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-5.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-5.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-5.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-5.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!304)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-5.x o.x)) (* 0.0 (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-5.x o.x)) (* (/ 4.0 5.0) (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x o.x)) (* 1.0 (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x o.x)) (* (/ 3.0 5.0) (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-5.x o.x)) (* 0.0 (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-5.x o.x)) (* (- 1.0) (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-5.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y o.y))) 2.0))) (=> (not relaxed!309) a!1)))
; cut relaxed!309
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-5.x o.x)) (* (/ 4.0 5.0) (- r.k-5.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-5.x o.x)) (* (/ 9.0 5.0) (- r.k-5.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-5.x o.x)) (* (/ 8.0 5.0) (- r.k-5.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-5.x o.x)) (* (/ 3.0 5.0) (- r.k-5.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-5.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-5.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-5.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-5.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-5.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-5.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-5.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-5.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!309)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-6.x r.k-7.x)) (* 0.0 (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-6.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-6.x r.k-7.x)) (* 1.0 (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-6.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-6.x r.k-7.x)) (* 0.0 (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-6.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-6.x r.k-7.x)) (* (- 1.0) (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-6.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-6.y r.k-7.y))) 2.0))) (=> (not relaxed!314) a!1)))
; cut relaxed!314
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-6.x r.k-7.x)) (* (/ 4.0 5.0) (- r.k-6.y r.k-7.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-6.x r.k-7.x)) (* (/ 9.0 5.0) (- r.k-6.y r.k-7.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-6.x r.k-7.x)) (* (/ 8.0 5.0) (- r.k-6.y r.k-7.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-6.x r.k-7.x)) (* (/ 3.0 5.0) (- r.k-6.y r.k-7.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-6.x r.k-7.x)) (* (- (/ 4.0 5.0)) (- r.k-6.y r.k-7.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-6.x r.k-7.x)) (* (- (/ 9.0 5.0)) (- r.k-6.y r.k-7.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-6.x r.k-7.x)) (* (- (/ 8.0 5.0)) (- r.k-6.y r.k-7.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-6.x r.k-7.x)) (* (- (/ 3.0 5.0)) (- r.k-6.y r.k-7.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!314)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-6.x o.x)) (* 0.0 (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-6.x o.x)) (* (/ 4.0 5.0) (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-6.x o.x)) (* 1.0 (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-6.x o.x)) (* (/ 3.0 5.0) (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-6.x o.x)) (* 0.0 (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-6.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-6.x o.x)) (* (- 1.0) (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-6.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-6.y o.y))) 2.0))) (=> (not relaxed!319) a!1)))
; cut relaxed!319
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-6.x o.x)) (* (/ 4.0 5.0) (- r.k-6.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-6.x o.x)) (* (/ 9.0 5.0) (- r.k-6.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-6.x o.x)) (* (/ 8.0 5.0) (- r.k-6.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-6.x o.x)) (* (/ 3.0 5.0) (- r.k-6.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-6.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-6.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-6.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-6.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-6.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-6.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-6.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-6.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!319)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 1.0 (- r.k-7.x o.x)) (* 0.0 (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- r.k-7.x o.x)) (* (/ 4.0 5.0) (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-7.x o.x)) (* 1.0 (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- r.k-7.x o.x)) (* (/ 3.0 5.0) (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- 1.0) (- r.k-7.x o.x)) (* 0.0 (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- r.k-7.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* 0.0 (- r.k-7.x o.x)) (* (- 1.0) (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- r.k-7.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-7.y o.y))) 2.0))) (=> (not relaxed!324) a!1)))
; cut relaxed!324
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- r.k-7.x o.x)) (* (/ 4.0 5.0) (- r.k-7.y o.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- r.k-7.x o.x)) (* (/ 9.0 5.0) (- r.k-7.y o.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- r.k-7.x o.x)) (* (/ 8.0 5.0) (- r.k-7.y o.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- r.k-7.x o.x)) (* (/ 3.0 5.0) (- r.k-7.y o.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- r.k-7.x o.x)) (* (- (/ 4.0 5.0)) (- r.k-7.y o.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- r.k-7.x o.x)) (* (- (/ 9.0 5.0)) (- r.k-7.y o.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- r.k-7.x o.x)) (* (- (/ 8.0 5.0)) (- r.k-7.y o.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- r.k-7.x o.x)) (* (- (/ 3.0 5.0)) (- r.k-7.y o.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!324)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* 1.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.w.x)) (* 0.0 (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.w.x)) (* (- 1.0) (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) 4.0))) (=> relaxed!328 a!1)))
; cut relaxed!328
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.w.x)) (* (/ 4.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.w.x)) (* (/ 9.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.w.x)) (* (/ 8.0 5.0) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.w.x)) (* (/ 3.0 5.0) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.w.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.w.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.w.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.w.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.w.y))) (/ 36.0 5.0)))) (=> (not relaxed!328) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* 1.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.b.x)) (* 0.0 (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.b.x)) (* (- 1.0) (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) 4.0))) (=> relaxed!353 a!1)))
; cut relaxed!353
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.b.x)) (* (/ 4.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.b.x)) (* (/ 9.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.b.x)) (* (/ 8.0 5.0) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.b.x)) (* (/ 3.0 5.0) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.b.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.b.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.b.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.b.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.b.y))) (/ 36.0 5.0)))) (=> (not relaxed!353) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* 1.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.c.x)) (* 0.0 (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.c.x)) (* (- 1.0) (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) 4.0))) (=> relaxed!377 a!1)))
; cut relaxed!377
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.c.x)) (* (/ 4.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.c.x)) (* (/ 9.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.c.x)) (* (/ 8.0 5.0) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.c.x)) (* (/ 3.0 5.0) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.c.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.c.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.c.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.c.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.c.y))) (/ 36.0 5.0)))) (=> (not relaxed!377) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* 1.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-1.x)) (* 0.0 (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-1.x)) (* (- 1.0) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) 4.0))) (=> relaxed!397 a!1)))
; cut relaxed!397
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-1.x)) (* (/ 4.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-1.x)) (* (/ 9.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 8.0 5.0) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.x)) (* (/ 3.0 5.0) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-1.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-1.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-1.y))) (/ 36.0 5.0)))) (=> (not relaxed!397) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> relaxed!398 (<= a!1 2.0))))
; cut relaxed!398
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 1.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 1.0)))))) (=> (not relaxed!398) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* 1.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-2.x)) (* 0.0 (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-2.x)) (* (- 1.0) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) 4.0))) (=> relaxed!400 a!1)))
; cut relaxed!400
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-2.x)) (* (/ 4.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-2.x)) (* (/ 9.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 8.0 5.0) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.x)) (* (/ 3.0 5.0) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-2.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-2.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-2.y))) (/ 36.0 5.0)))) (=> (not relaxed!400) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!401
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> relaxed!401 (<= a!1 2.0))))
; cut relaxed!401
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 2.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 2.0)))))) (=> (not relaxed!401) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* 1.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-3.x)) (* 0.0 (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-3.x)) (* (- 1.0) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) 4.0))) (=> relaxed!403 a!1)))
; cut relaxed!403
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-3.x)) (* (/ 4.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-3.x)) (* (/ 9.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 8.0 5.0) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.x)) (* (/ 3.0 5.0) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-3.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-3.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-3.y))) (/ 36.0 5.0)))) (=> (not relaxed!403) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> relaxed!404 (<= a!1 2.0))))
; cut relaxed!404
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 3.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 3.0)))))) (=> (not relaxed!404) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* 1.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-4.x)) (* 0.0 (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-4.x)) (* (- 1.0) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) 4.0))) (=> relaxed!406 a!1)))
; cut relaxed!406
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-4.x)) (* (/ 4.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-4.x)) (* (/ 9.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 8.0 5.0) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.x)) (* (/ 3.0 5.0) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-4.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-4.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-4.y))) (/ 36.0 5.0)))) (=> (not relaxed!406) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!407
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> relaxed!407 (<= a!1 2.0))))
; cut relaxed!407
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 4.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 4.0)))))) (=> (not relaxed!407) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* 1.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-5.x)) (* 0.0 (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-5.x)) (* (- 1.0) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) 4.0))) (=> relaxed!409 a!1)))
; cut relaxed!409
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-5.x)) (* (/ 4.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-5.x)) (* (/ 9.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 8.0 5.0) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.x)) (* (/ 3.0 5.0) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-5.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-5.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-5.y))) (/ 36.0 5.0)))) (=> (not relaxed!409) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!410
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> relaxed!410 (<= a!1 2.0))))
; cut relaxed!410
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 5.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 5.0)))))) (=> (not relaxed!410) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* 1.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-6.x)) (* 0.0 (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-6.x)) (* (- 1.0) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) 4.0))) (=> relaxed!412 a!1)))
; cut relaxed!412
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-6.x)) (* (/ 4.0 5.0) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-6.x)) (* (/ 9.0 5.0) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 8.0 5.0) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.x)) (* (/ 3.0 5.0) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-6.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-6.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-6.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-6.y))) (/ 36.0 5.0)))) (=> (not relaxed!412) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!413
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> relaxed!413 (<= a!1 2.0))))
; cut relaxed!413
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 6.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 6.0)))))) (=> (not relaxed!413) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.k-7.x)) (* 0.0 (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.k-7.x)) (* (/ 4.0 5.0) (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-7.x)) (* 1.0 (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 3.0 5.0) (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.k-7.x)) (* 0.0 (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.k-7.x)) (* (- 1.0) (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.y))) 4.0))) (=> relaxed!415 a!1)))
; cut relaxed!415
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.k-7.x)) (* (/ 4.0 5.0) (- 0.0 r.k-7.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.k-7.x)) (* (/ 9.0 5.0) (- 0.0 r.k-7.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 8.0 5.0) (- 0.0 r.k-7.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.k-7.x)) (* (/ 3.0 5.0) (- 0.0 r.k-7.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.k-7.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.k-7.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.k-7.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.k-7.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.k-7.y))) (/ 36.0 5.0)))) (=> (not relaxed!415) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!416
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> relaxed!416 (<= a!1 2.0))))
; cut relaxed!416
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-7.y 0.0) (- 7.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-7.y 0.0) (- 7.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-7.y 0.0) (- 7.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-7.y 0.0) (- 7.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-7.y 0.0) (- 7.0)))))) (=> (not relaxed!416) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!449
(assert (not relaxed!449))
; cut relaxed!467
(assert (let ((a!1 (+ (* 1.0 (- (- r.w.y 0.0) (- 8.0))) (* 0.0 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (/ 4.0 5.0) 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 8.0))) (* 1.0 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (/ 3.0 5.0) 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.w.y 0.0) (- 8.0))) (* 0.0 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 4.0 5.0)) 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* 0.0 (- (- r.w.y 0.0) (- 8.0))) (* (- 1.0) 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> relaxed!467 (<= a!1 2.0))))
; cut relaxed!467
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (/ 4.0 5.0) 0.0))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (/ 9.0 5.0) 0.0))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (/ 8.0 5.0) 0.0))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (/ 3.0 5.0) 0.0))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 4.0 5.0)) 0.0))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 9.0 5.0)) 0.0))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 8.0 5.0)) 0.0))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.w.y 0.0) (- 8.0))) (* (- (/ 3.0 5.0)) 0.0)))) (=> (not relaxed!467) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!486
(assert (let ((a!1 (+ (* 1.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* 0.0 (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 8.0)))))) (=> relaxed!486 (<= a!1 2.0))))
; cut relaxed!486
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.b.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.b.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.b.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.b.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.b.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.b.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.b.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.b.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.b.y 0.0) (- 8.0)))))) (=> (not relaxed!486) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!509
(assert (let ((a!1 (+ (* 1.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* 0.0 (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 8.0)))))) (=> relaxed!509 (<= a!1 2.0))))
; cut relaxed!509
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.c.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.c.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.c.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.c.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.c.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.c.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.c.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.c.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.c.y 0.0) (- 8.0)))))) (=> (not relaxed!509) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!550
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> relaxed!550 (<= a!1 2.0))))
; cut relaxed!550
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-1.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-1.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-1.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-1.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-1.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-1.y 0.0) (- 8.0)))))) (=> (not relaxed!550) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!591
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> relaxed!591 (<= a!1 2.0))))
; cut relaxed!591
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-2.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-2.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-2.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-2.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-2.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-2.y 0.0) (- 8.0)))))) (=> (not relaxed!591) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!632
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> relaxed!632 (<= a!1 2.0))))
; cut relaxed!632
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-3.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-3.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-3.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-3.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-3.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-3.y 0.0) (- 8.0)))))) (=> (not relaxed!632) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!673
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> relaxed!673 (<= a!1 2.0))))
; cut relaxed!673
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-4.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-4.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-4.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-4.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-4.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-4.y 0.0) (- 8.0)))))) (=> (not relaxed!673) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!714
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> relaxed!714 (<= a!1 2.0))))
; cut relaxed!714
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-5.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-5.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-5.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-5.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-5.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-5.y 0.0) (- 8.0)))))) (=> (not relaxed!714) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!755
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> relaxed!755 (<= a!1 2.0))))
; cut relaxed!755
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-6.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-6.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-6.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-6.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-6.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-6.y 0.0) (- 8.0)))))) (=> (not relaxed!755) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!796
(assert (let ((a!1 (+ (* 1.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (- 1.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* 0.0 (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> relaxed!796 (<= a!1 2.0))))
; cut relaxed!796
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- r.k-7.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- r.k-7.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- r.k-7.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- r.k-7.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- r.k-7.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- r.k-7.y 0.0) (- 8.0)))))) (=> (not relaxed!796) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 o.x)) (* 0.0 (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 o.x)) (* (/ 4.0 5.0) (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 o.x)) (* 1.0 (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 o.x)) (* (/ 3.0 5.0) (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 o.x)) (* 0.0 (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 o.x)) (* (- (/ 4.0 5.0)) (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 o.x)) (* (- 1.0) (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 o.x)) (* (- (/ 3.0 5.0)) (- 0.0 o.y))) 4.0))) (=> relaxed!804 a!1)))
; cut relaxed!804
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 o.x)) (* (/ 4.0 5.0) (- 0.0 o.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 o.x)) (* (/ 9.0 5.0) (- 0.0 o.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 o.x)) (* (/ 8.0 5.0) (- 0.0 o.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 o.x)) (* (/ 3.0 5.0) (- 0.0 o.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 o.x)) (* (- (/ 4.0 5.0)) (- 0.0 o.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 o.x)) (* (- (/ 9.0 5.0)) (- 0.0 o.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 o.x)) (* (- (/ 8.0 5.0)) (- 0.0 o.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 o.x)) (* (- (/ 3.0 5.0)) (- 0.0 o.y))) (/ 36.0 5.0)))) (=> (not relaxed!804) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!841
(assert (let ((a!1 (+ (* 1.0 (- (- o.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (/ 3.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* 0.0 (- (- o.x 0.0) (- r.w.x 0.0))) (* 1.0 (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (- (/ 4.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (- 1.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* 0.0 (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (- (/ 3.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* 0.0 (- (- o.x 0.0) (- r.w.x 0.0))) (* (- 1.0) (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (/ 4.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- o.y 0.0) (- 8.0)))))) (=> relaxed!841 (<= a!1 2.0))))
; cut relaxed!841
(assert (let ((a!1 (+ (* (/ 8.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 4.0 5.0) (- (- o.y 0.0) (- 8.0))))) (a!2 (+ (* (/ 3.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 9.0 5.0) (- (- o.y 0.0) (- 8.0))))) (a!3 (+ (* (- (/ 4.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 8.0 5.0) (- (- o.y 0.0) (- 8.0))))) (a!4 (+ (* (- (/ 9.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (/ 3.0 5.0) (- (- o.y 0.0) (- 8.0))))) (a!5 (+ (* (- (/ 8.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 4.0 5.0)) (- (- o.y 0.0) (- 8.0))))) (a!6 (+ (* (- (/ 3.0 5.0)) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 9.0 5.0)) (- (- o.y 0.0) (- 8.0))))) (a!7 (+ (* (/ 4.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 8.0 5.0)) (- (- o.y 0.0) (- 8.0))))) (a!8 (+ (* (/ 9.0 5.0) (- (- o.x 0.0) (- r.w.x 0.0))) (* (- (/ 3.0 5.0)) (- (- o.y 0.0) (- 8.0)))))) (=> (not relaxed!841) (or (>= a!1 (/ 16.0 5.0)) (>= a!2 (/ 18.0 5.0)) (>= a!3 (/ 16.0 5.0)) (>= a!4 (/ 18.0 5.0)) (>= a!5 (/ 16.0 5.0)) (>= a!6 (/ 18.0 5.0)) (>= a!7 (/ 16.0 5.0)) (>= a!8 (/ 18.0 5.0))))))
; cut relaxed!849
(assert (let ((a!1 (* 1.0 (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* 0.0 (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (/ 3.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (/ 4.0 5.0) (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* 0.0 (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* 1.0 (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (- (/ 4.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (/ 3.0 5.0) (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (- 1.0) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* 0.0 (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (- (/ 3.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (- (/ 4.0 5.0)) (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* 0.0 (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (- 1.0) (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (/ 4.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (- (/ 3.0 5.0)) (- (+ 0.0 (- 8.0)) o.y))))) (=> relaxed!849 (<= a!2 4.0)))))
; cut relaxed!849
(assert (let ((a!1 (* (/ 8.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!3 (* (/ 3.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!5 (* (- (/ 4.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!7 (* (- (/ 9.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!9 (* (- (/ 8.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!11 (* (- (/ 3.0 5.0)) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!13 (* (/ 4.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x))) (a!15 (* (/ 9.0 5.0) (- (+ 0.0 (- r.w.x 0.0)) o.x)))) (let ((a!2 (+ a!1 (* (/ 4.0 5.0) (- (+ 0.0 (- 8.0)) o.y)))) (a!4 (+ a!3 (* (/ 9.0 5.0) (- (+ 0.0 (- 8.0)) o.y)))) (a!6 (+ a!5 (* (/ 8.0 5.0) (- (+ 0.0 (- 8.0)) o.y)))) (a!8 (+ a!7 (* (/ 3.0 5.0) (- (+ 0.0 (- 8.0)) o.y)))) (a!10 (+ a!9 (* (- (/ 4.0 5.0)) (- (+ 0.0 (- 8.0)) o.y)))) (a!12 (+ a!11 (* (- (/ 9.0 5.0)) (- (+ 0.0 (- 8.0)) o.y)))) (a!14 (+ a!13 (* (- (/ 8.0 5.0)) (- (+ 0.0 (- 8.0)) o.y)))) (a!16 (+ a!15 (* (- (/ 3.0 5.0)) (- (+ 0.0 (- 8.0)) o.y))))) (=> (not relaxed!849) (or (>= a!2 (/ 32.0 5.0)) (>= a!4 (/ 36.0 5.0)) (>= a!6 (/ 32.0 5.0)) (>= a!8 (/ 36.0 5.0)) (>= a!10 (/ 32.0 5.0)) (>= a!12 (/ 36.0 5.0)) (>= a!14 (/ 32.0 5.0)) (>= a!16 (/ 36.0 5.0)))))))
(check-sat)
