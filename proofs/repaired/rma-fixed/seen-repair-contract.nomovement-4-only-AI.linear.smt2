; The linearization of the obligation in the file of the same name without '.linear': each nonlinear
; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of
; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here
; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR
; format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first 'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after '; cut NAME', is a cut implied by NAME's comparison
; relaxed assertions: 7; cuts: 18
; atom relaxed!3 (<= 4.0 (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x)) (* (- 0.0 r.a.y) (- 0.0 r.a.y))))
; atom relaxed!7 (>= 16.0 (+ (* (- 0.0 r.a.x) (- 0.0 r.a.x)) (* (- 0.0 r.a.y) (- 0.0 r.a.y))))
(set-logic QF_LRA)
(declare-fun relaxed!3 () Bool)
(declare-fun r.a.y () Real)
(declare-fun r.a.x () Real)
(declare-fun relaxed!7 () Bool)
(declare-fun r.case0 () Bool)
(declare-fun r.contract () Real)
(assert (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) relaxed!3))
(assert (let ((a!1 (and (> (- r.a.x 0.0) (- 2.0)) (> 2.0 (- r.a.x 0.0))))
      (a!3 (and (> (- 0.0 0.0) (- 2.0)) (> 2.0 (- 0.0 0.0))))
      (a!6 (and (> (- r.a.y 0.0) (- 2.0)) (> 2.0 (- r.a.y 0.0)))))
(let ((a!2 (or (and a!1 (< 0.0 (- r.a.y 0.0))) (and a!1 (> 0.0 (- r.a.y 0.0)))))
      (a!4 (or (and a!3 (< 0.0 (- 0.0 0.0))) (and a!3 (> 0.0 (- 0.0 0.0))))))
(let ((a!5 (or (and (not (or a!4 a!4)) (< 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))
               (and a!3 (< 0.0 (- 0.0 0.0)))
               (and (not (or a!4 a!4)) (< 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0)))
               (and (not (or a!4 a!4)) (> 0.0 (- 0.0 0.0)) (< 0.0 (- 0.0 0.0)))
               (and a!3 (> 0.0 (- 0.0 0.0)))
               (and (not (or a!4 a!4)) (> 0.0 (- 0.0 0.0)) (> 0.0 (- 0.0 0.0)))))
      (a!7 (or a!2
               (and a!6 (< 0.0 (- r.a.x 0.0)))
               (and a!6 (> 0.0 (- r.a.x 0.0))))))
(let ((a!8 (or (and (not a!7) (< 0.0 (- r.a.x 0.0)) (< 0.0 (- r.a.y 0.0)))
               (and a!6 (< 0.0 (- r.a.x 0.0)))
               (and (not a!7) (< 0.0 (- r.a.x 0.0)) (> 0.0 (- r.a.y 0.0)))
               (and (not a!7) (> 0.0 (- r.a.x 0.0)) (< 0.0 (- r.a.y 0.0)))
               (and a!6 (> 0.0 (- r.a.x 0.0)))
               (and (not a!7) (> 0.0 (- r.a.x 0.0)) (> 0.0 (- r.a.y 0.0))))))
(let ((a!9 (and (not (and (= 0.0 r.a.x) (= 0.0 r.a.y)))
                relaxed!7
                a!2
                (or (and (= 0.0 0.0) (= 0.0 0.0)) (=> true (not a!5)))
                (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) (=> relaxed!7 (not a!8))))))
  (=> r.case0 a!9)))))))
(assert (or r.case0))
(assert (distinct 0.0 r.contract))
(assert (>= 1.0 r.contract))
(assert (>= r.contract (- 1.0)))
(assert (and (> 0.0 0.0)
     (or (and (= 0.0 r.a.x) (= 0.0 r.a.y)) (not relaxed!7) (> 0.0 r.a.x))))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.a.x)) (* 0.0 (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.a.x)) (* (/ 4.0 5.0) (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.a.x)) (* 1.0 (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.a.x)) (* (/ 3.0 5.0) (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.a.x)) (* 0.0 (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.a.x)) (* (- 1.0) (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.a.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.a.y))) 2.0))) (=> (not relaxed!3) a!1)))
; cut relaxed!3
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.a.x)) (* (/ 4.0 5.0) (- 0.0 r.a.y))) (/ 16.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.a.x)) (* (/ 9.0 5.0) (- 0.0 r.a.y))) (/ 18.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.a.x)) (* (/ 8.0 5.0) (- 0.0 r.a.y))) (/ 16.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.a.x)) (* (/ 3.0 5.0) (- 0.0 r.a.y))) (/ 18.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.a.y))) (/ 16.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.a.y))) (/ 18.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.a.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.a.y))) (/ 16.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.a.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.a.y))) (/ 18.0 5.0)))) (=> (not (not relaxed!3)) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* 1.0 (- 0.0 r.a.x)) (* 0.0 (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* (/ 3.0 5.0) (- 0.0 r.a.x)) (* (/ 4.0 5.0) (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.a.x)) (* 1.0 (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.a.x)) (* (/ 3.0 5.0) (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* (- 1.0) (- 0.0 r.a.x)) (* 0.0 (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* 0.0 (- 0.0 r.a.x)) (* (- 1.0) (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (<= (+ (* (/ 4.0 5.0) (- 0.0 r.a.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.a.y))) 4.0))) (=> relaxed!7 a!1)))
; cut relaxed!7
(assert (let ((a!1 (>= (+ (* (/ 8.0 5.0) (- 0.0 r.a.x)) (* (/ 4.0 5.0) (- 0.0 r.a.y))) (/ 32.0 5.0))) (a!2 (>= (+ (* (/ 3.0 5.0) (- 0.0 r.a.x)) (* (/ 9.0 5.0) (- 0.0 r.a.y))) (/ 36.0 5.0))) (a!3 (>= (+ (* (- (/ 4.0 5.0)) (- 0.0 r.a.x)) (* (/ 8.0 5.0) (- 0.0 r.a.y))) (/ 32.0 5.0))) (a!4 (>= (+ (* (- (/ 9.0 5.0)) (- 0.0 r.a.x)) (* (/ 3.0 5.0) (- 0.0 r.a.y))) (/ 36.0 5.0))) (a!5 (>= (+ (* (- (/ 8.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 4.0 5.0)) (- 0.0 r.a.y))) (/ 32.0 5.0))) (a!6 (>= (+ (* (- (/ 3.0 5.0)) (- 0.0 r.a.x)) (* (- (/ 9.0 5.0)) (- 0.0 r.a.y))) (/ 36.0 5.0))) (a!7 (>= (+ (* (/ 4.0 5.0) (- 0.0 r.a.x)) (* (- (/ 8.0 5.0)) (- 0.0 r.a.y))) (/ 32.0 5.0))) (a!8 (>= (+ (* (/ 9.0 5.0) (- 0.0 r.a.x)) (* (- (/ 3.0 5.0)) (- 0.0 r.a.y))) (/ 36.0 5.0)))) (=> (not relaxed!7) (or a!1 a!2 a!3 a!4 a!5 a!6 a!7 a!8))))
(check-sat)
