"""Incremental linearization of an obligation over the reals: decide it with linear arithmetic where
the nonlinear search runs out of budget.

Every comparison that multiplies two unknowns becomes a Boolean, as in
:func:`~fatline_verify.prove.smt.solving.relaxation`. Most of them compare a squared distance with a
constant, ``a * (l1^2 + l2^2) + c  <=  K`` for linear terms ``l1, l2`` (visibility, contact, the
search's reach): their Booleans get exact linear consequences (:class:`Disc`), which every solution
of the obligation satisfies:

* a point **inside** the disc ``l1^2 + l2^2 <= R^2`` has ``u . l <= R`` for every unit vector ``u``
  (a tangent line; ``u`` rational, ``R`` rounded up);
* a point **outside** it lies in one of the sectors between consecutive directions ``u``, ``v`` of a
  grid, and there ``(u + v) . l >= R (1 + u . v)`` (the bisector's half-plane: ``|u + v| cos(gap/2)``
  is exactly ``1 + u . v``; ``R`` rounded down).

The linear problem is asked; ``unsat`` means the obligation is unsat. A solution is checked against
the real comparisons: where a Boolean disagrees with its comparison at the solution, the disc gets a
tangent line through that point (inside) or, outside, sector cuts of its own between directions ever
closer around the point, each asserted only where a point lies between its two directions (a local
cut: rebuilding the whole cover on a finer grid made the Python side, not z3, take most of the time),
and the problem is asked again. A solution that disagrees nowhere solves the obligation; one that disagrees only in a
few robots' coordinates is *polished*: every other coordinate fixed at its value, the obligation
asked over the reals for those few (a small nonlinear problem). Directions are rational points of the
unit circle with small denominators, so the linear problems stay cheap.
"""

from __future__ import annotations

import functools
import itertools
import math
import time
from dataclasses import dataclass, field
from fractions import Fraction
from math import isqrt
from pathlib import Path

import z3

from .cases import Arith
from .claims import Built
from .solving import Answer, decode, exact_value, relaxed_atoms, rlimit, spent, unknown_reason, wall_ms

Vec = tuple[Fraction, Fraction]

PRECISION = 10**9
"""Square roots are rounded to this many parts of a radius (up for tangents, down for sectors)."""

FIRST_GRID = tuple(Fraction(k, 2) for k in range(8))
"""The sector grid every disc starts with (:func:`direction` parameters: 8 directions, 0 to 315 degrees)."""

TANGENT_DENOMINATORS = (4, 16, 64, 256, 1024, 4096, 1 << 14, 1 << 16, 1 << 20)
"""Tangent directions are tried with these denominators of ``tan(angle/2)``, the smallest first."""

LINEAR_RATE = 3
"""z3 spends its resource units this many times faster on the linear problems than on the nonlinear
ones, per second; a linearization's budget is counted at this rate. Measured with the sector cuts of
:meth:`Disc.refine` on ``paper``'s Scenario 2 and 3 cases (68 linear checks, 170 million units in
29.9 s: 5.7 million a second against :data:`~fatline_verify.prove.smt.solving.RLIMIT_PER_SECOND`'s 2)."""

SUBDIVISIONS = 12
"""How many times a sector around a wrongly-outside point is split in quarters, at most, until its cut
excludes the point (a gap of a quarter turn, split 12 times, is under 2e-7 turns wide)."""

POLISH_COORDINATES = 8
"""A solution is polished when its disagreements involve at most this many unknowns."""

POLISH_REPEATS = 3
"""Polishes per set of free unknowns: the coordinates a polish fixes are at new values each time, but
one that failed three times rarely succeeds (and nlsat runs slower than the budget assumes: a polish
that fails costs up to :data:`~fatline_verify.prove.smt.solving.WALL` times its budget in time)."""

POLISH_BUDGET = 1.0
"""Seconds of budget a polish may take (at most what is left)."""

STUCK = "the linearization cannot separate its solution from the obligation's comparisons"
"""Why a linearization stops before its budget: the comparisons its solution breaks are not distances
(or lie on their circles too closely for a tangent), and too many unknowns to polish."""


def sqrt_down(x: Fraction) -> Fraction:
    """A rational at most ``sqrt(x)``, within ``1/PRECISION``."""
    return Fraction(isqrt(int(x * PRECISION * PRECISION)), PRECISION) if x > 0 else Fraction(0)


def sqrt_up(x: Fraction) -> Fraction:
    """A rational at least ``sqrt(x)``, within ``1/PRECISION``."""
    low = sqrt_down(x)
    return low if low * low >= x else low + Fraction(1, PRECISION)


@functools.cache
def direction(s: Fraction) -> Vec:
    """The exact rational unit vector at grid parameter ``s`` in [0, 4): quarter turn ``floor(s)``,
    then ``((1 - t^2), 2t) / (1 + t^2)`` for ``t = s - floor(s)`` (angle ``2 atan t``, monotone in s)."""
    q = math.floor(s)
    t = s - q
    x, y = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    for _ in range(q % 4):
        x, y = -y, x
    return x, y


def parameter(angle: float) -> float:
    """The grid parameter of an angle (used only to choose where to refine, never to decide)."""
    angle %= 2 * math.pi
    q = min(3, int(angle // (math.pi / 2)))
    return q + math.tan((angle - q * math.pi / 2) / 2)


def tangent(angle: float, den: int) -> Vec:
    """A rational unit vector near ``angle`` (``tan`` of its half-angle to ``1/den``)."""
    s = parameter(angle)
    return direction(Fraction(math.floor(s)) + Fraction(round((s - math.floor(s)) * den), den))


def cover(grid: list[Fraction], r2: Fraction) -> list[tuple[Vec, Fraction]]:
    """Half-planes ``w . l >= h`` of which every point with ``|l|^2 >= r2`` satisfies one: per gap
    between consecutive directions ``u``, ``v`` of ``grid`` (each gap under half a turn),
    ``w = u + v`` and ``h = R (1 + u . v)`` with ``R`` at most ``sqrt(r2)``."""
    params = sorted(set(grid))
    return [sector(s, params[(i + 1) % len(params)], r2)[2:] for i, s in enumerate(params)]


def sector(lo: Fraction, hi: Fraction, r2: Fraction) -> tuple[Vec, Vec, Vec, Fraction]:
    """The cut of one gap of a grid, from parameter ``lo`` to ``hi`` (under half a turn): ``(u, v, w,
    h)`` such that every point ``l`` with ``|l|^2 >= r2`` between the directions ``u`` and ``v``
    (``u x l >= 0`` and ``l x v >= 0``) has ``w . l >= h`` (``w = u + v``, ``h = R (1 + u . v)`` with
    ``R`` at most ``sqrt(r2)``: the bisector's half-plane, as in :func:`cover`)."""
    u, v = direction(lo), direction(hi)
    if u[0] * v[1] - u[1] * v[0] <= 0:
        raise ValueError("a grid gap of half a turn or more")
    return u, v, (u[0] + v[0], u[1] + v[1]), sqrt_down(r2) * (1 + u[0] * v[0] + u[1] * v[1])


@dataclass
class Disc:
    """A comparison ``l1^2 + l2^2  (<=, <, >=, >)  r2`` of linear terms with a constant, and its Boolean."""

    boolean: z3.BoolRef
    terms: tuple[z3.ArithRef, z3.ArithRef]
    r2: Fraction
    inside_when_true: bool
    """Whether the comparison says "inside" (``<=``, ``<``) or "outside" (``>=``, ``>``)."""
    strict: bool
    grid: list[Fraction] = field(default_factory=lambda: list(FIRST_GRID))

    def inside(self) -> z3.BoolRef:
        """The literal saying the point is inside the disc."""
        return self.boolean if self.inside_when_true else z3.Not(self.boolean)

    def is_inside(self, p: Vec) -> bool:
        """Whether ``p`` lies on the inside literal's side, boundary per the comparison."""
        s = p[0] * p[0] + p[1] * p[1]
        boundary_inside = not self.strict if self.inside_when_true else self.strict
        return s < self.r2 or (s == self.r2 and boundary_inside)

    def line(self, u: Vec, ctx: z3.Context) -> z3.ArithRef:
        return z3.RealVal(u[0], ctx) * self.terms[0] + z3.RealVal(u[1], ctx) * self.terms[1]

    def cuts(self, ctx: z3.Context) -> list[z3.BoolRef]:
        """The first cuts: inside, ``|l_i| <= R`` and the grid's tangents; outside, the grid's sectors."""
        inside = self.inside()
        if self.r2 < 0 or (self.r2 == 0 and self.inside_when_true == self.strict):
            return [z3.Not(inside)]
        r = sqrt_up(self.r2)
        out = [z3.Implies(inside, self.line(direction(s), ctx) <= r) for s in self.grid]
        return out + self.sectors(ctx)

    def sectors(self, ctx: z3.Context) -> list[z3.BoolRef]:
        if self.r2 <= 0:
            return []
        half_planes = [self.line(w, ctx) >= h for w, h in cover(self.grid, self.r2)]
        return [z3.Implies(z3.Not(self.inside()), z3.Or(*half_planes))]

    def refine(self, p: Vec, inside: bool, ctx: z3.Context) -> list[z3.BoolRef]:
        """Cuts excluding ``p``, at which the Boolean says ``inside`` and the point is not there (or the
        reverse); none when ``p`` lies on the circle too closely for any tangent to separate it."""
        angle = math.atan2(float(p[1]), float(p[0]))
        if inside:
            r = sqrt_up(self.r2)
            for den in TANGENT_DENOMINATORS:
                u = tangent(angle, den)
                if u[0] * p[0] + u[1] * p[1] > r:
                    line = self.line(u, ctx)
                    return [z3.Implies(self.inside(), line < r if self.inside_when_true and self.strict else line <= r)]
            return []
        return self._subdivide(p, ctx)

    def _subdivide(self, p: Vec, ctx: z3.Context) -> list[z3.BoolRef]:
        """Cuts for a point ``p`` the Boolean puts outside though it is inside: the grid's gap holding
        ``p`` is split in quarters, each quarter getting its own sector cut (:func:`sector`, asserted
        where a point lies between its two directions), and the quarter holding ``p`` again until its
        cut excludes ``p``; none when ``p`` lies on the circle too closely (or is the centre). Which gap
        holds ``p`` is decided exactly (cross products), so a returned set of cuts excludes ``p``."""
        if p[0] == 0 and p[1] == 0:
            return []
        params = sorted(set(self.grid))
        gaps = [(lo, params[i + 1] if i + 1 < len(params) else params[0] + 4) for i, lo in enumerate(params)]
        lo, hi = next(g for g in gaps if _between(direction(g[0]), direction(g[1]), p))
        outside = z3.Not(self.inside())
        out: list[z3.BoolRef] = []
        for _ in range(SUBDIVISIONS):
            points = [lo + (hi - lo) * k / 4 for k in range(5)]
            self.grid += [s - 4 if s >= 4 else s for s in points[1:4]]
            quarters = [((a, b), sector(a, b, self.r2)) for a, b in itertools.pairwise(points)]
            for _, (u, v, w, h) in quarters:
                between = [self._cross(u, ctx) >= 0, -self._cross(v, ctx) >= 0]
                out.append(z3.Implies(z3.And(outside, *between), self.line(w, ctx) >= h))
            (lo, hi), (u, v, w, h) = next(q for q in quarters if _between(q[1][0], q[1][1], p))
            if w[0] * p[0] + w[1] * p[1] < h:
                return out
        return []

    def _cross(self, u: Vec, ctx: z3.Context) -> z3.ArithRef:
        """``u x l``: non-negative when ``l`` is counter-clockwise of ``u`` (within half a turn)."""
        return z3.RealVal(u[0], ctx) * self.terms[1] - z3.RealVal(u[1], ctx) * self.terms[0]


def _between(u: Vec, v: Vec, p: Vec) -> bool:
    """Whether ``p`` lies between the directions ``u`` and ``v`` (counter-clockwise from ``u``, at most
    to ``v``; the gap under half a turn), exactly."""
    return u[0] * p[1] - u[1] * p[0] >= 0 and p[0] * v[1] - p[1] * v[0] >= 0


def _number(e: z3.ExprRef) -> Fraction | None:
    s = z3.simplify(e)
    if z3.is_rational_value(s):
        return Fraction(s.numerator_as_long(), s.denominator_as_long())
    if z3.is_int_value(s):
        return Fraction(s.as_long())
    return None


def _squares(e: z3.ExprRef) -> tuple[list[tuple[Fraction, z3.ArithRef]], Fraction] | None:
    """``e`` as ``sum c_i * l_i^2 + c0`` (each ``l_i`` linear), or None."""
    if z3.is_add(e):
        terms: list[tuple[Fraction, z3.ArithRef]] = []
        const = Fraction(0)
        for child in e.children():
            got = _squares(child)
            if got is None:
                return None
            terms += got[0]
            const += got[1]
        return terms, const
    value = _number(e)
    if value is not None:
        return [], value
    if z3.is_mul(e) and e.num_args() == 2:
        a, b = e.children()
        if a.eq(b) and _linear(a):
            return [(Fraction(1), a)], Fraction(0)
        for k, x in ((_number(a), b), (_number(b), a)):
            if k is not None:
                got = _squares(x)
                return None if got is None else ([(k * c, t) for c, t in got[0]], k * got[1])
    return None


def _linear(e: z3.ExprRef) -> bool:
    if z3.is_mul(e):
        return sum(_number(c) is None for c in e.children()) <= 1 and all(_linear(c) for c in e.children())
    return all(_linear(c) for c in e.children())


FLIP = {z3.Z3_OP_LE: z3.Z3_OP_GE, z3.Z3_OP_GE: z3.Z3_OP_LE, z3.Z3_OP_LT: z3.Z3_OP_GT, z3.Z3_OP_GT: z3.Z3_OP_LT}


def disc(atom: z3.BoolRef, boolean: z3.BoolRef) -> Disc | None:
    """The comparison as a :class:`Disc` (a squared distance against a constant), or None."""
    if atom.num_args() != 2 or atom.decl().kind() not in FLIP:
        return None
    kind = atom.decl().kind()
    lhs, rhs = atom.children()
    k, s = _number(rhs), _squares(lhs)
    if k is None or s is None:
        k, s, kind = _number(lhs), _squares(rhs), FLIP[kind]
        if k is None or s is None:
            return None
    terms, const = s
    coefs = {c for c, _ in terms}
    if len(terms) not in (1, 2) or len(coefs) != 1 or (a := coefs.pop()) <= 0:
        return None
    pair = (terms[0][1], terms[1][1] if len(terms) == 2 else z3.RealVal(0, atom.ctx))
    return Disc(boolean, pair, (k - const) / a, kind in (z3.Z3_OP_LE, z3.Z3_OP_LT), kind in (z3.Z3_OP_LT, z3.Z3_OP_GT))


class Linearization:
    """One obligation's linearization, kept across rounds (its cuts only grow)."""

    def __init__(self, built: Built) -> None:
        self.built = built
        ctx = built.ar.ctx
        relaxed, self.atoms = relaxed_atoms(built)
        self.solver = z3.Solver(ctx=ctx)
        self.solver.add(*relaxed)
        self.relaxed = relaxed
        self.discs = [d for atom, b in self.atoms if (d := disc(atom, b)) is not None]
        self.cut_log: list[tuple[z3.BoolRef, z3.BoolRef]] = []
        """Every cut asserted so far, with the relaxed Boolean whose disc it bounds (the certificate's marks)."""
        for d in self.discs:
            self._cut(d, d.cuts(ctx))
        self.refinements = 0
        self._names: dict[int, frozenset[str]] = {}
        self._polished: dict[frozenset[str], int] = {}
        """How many polishes solved for each set of unknowns (at most :data:`POLISH_REPEATS`)."""

    def _cut(self, d: Disc, cuts: list[z3.BoolRef]) -> None:
        self.solver.add(*cuts)
        self.cut_log += [(d.boolean, c) for c in cuts]

    def script(self) -> str:
        """The linear problem as it stands (the relaxed obligation and every cut so far), as SMT-LIB2:
        after ``unsat``, the certificate another solver confirms. It records, beside every relaxed
        Boolean, the atom it stands for (``; atom NAME SEXPR``), and marks each cut with the Boolean whose
        disc it bounds (``; cut NAME`` before its ``assert``), so that
        :mod:`fatline_verify.prove.smt.certificates` re-derives from the obligation's file alone that every
        cut is implied (:data:`CERTIFICATE_FORMAT`)."""
        plain = z3.Solver(ctx=self.built.ar.ctx)
        plain.add(*self.relaxed)
        header = (
            "; The linearization of the obligation in the file of the same name without '.linear': each nonlinear\n"
            "; comparison a Boolean, each squared distance's Boolean implying exact tangent lines (inside) or one of\n"
            "; a grid's sector half-planes (outside), which every solution of the obligation satisfies. Unsat here\n"
            "; is unsat there. Check it from the two files alone: python -m fatline_verify.prove.certify DIR\n"
            f"; {CERTIFICATE_FORMAT}\n"
            f"; relaxed assertions: {len(self.relaxed)}; cuts: {len(self.cut_log)}\n"
        )
        atoms = "".join(f"; atom {b.decl().name()} {_one_line(atom)}\n" for atom, b in self.atoms)
        cuts = "".join(f"; cut {b.decl().name()}\n(assert {_one_line(c)})\n" for b, c in self.cut_log)
        return f"{header}{atoms}(set-logic QF_LRA)\n{plain.sexpr()}{cuts}(check-sat)\n"

    def check(self, seconds: float) -> Answer:
        """Refine until ``unsat``, a solution of the obligation, or ``seconds`` of budget are spent."""
        ctx = self.built.ar.ctx
        t0 = time.perf_counter()
        spent(self.solver, self.built)  # what other checks in this context used is not ours
        left = seconds
        while left >= 0.01:
            self.solver.set("rlimit", rlimit(left * LINEAR_RATE))
            self.solver.set("timeout", wall_ms(left))
            res = self.solver.check()
            left -= spent(self.solver, self.built) / LINEAR_RATE
            if res == z3.unsat:
                return Answer("unsat", time.perf_counter() - t0, budget=min(seconds, seconds - left))
            if res == z3.unknown:
                return Answer("unknown", time.perf_counter() - t0, unknown_reason(self.solver, seconds), budget=seconds)
            m = self.solver.model()
            wrong = [
                (atom, b)
                for atom, b in self.atoms
                if z3.is_true(m.eval(atom, model_completion=True)) != z3.is_true(m.eval(b, model_completion=True))
            ]
            if not wrong:
                return decode(m, self.built, time.perf_counter() - t0, min(seconds, seconds - left))
            polished = self._polish(m, wrong, min(left, POLISH_BUDGET))
            left -= spent(self.solver, self.built)
            if polished is not None:
                return decode(polished, self.built, time.perf_counter() - t0, min(seconds, seconds - left))
            cuts: list[tuple[Disc, list[z3.BoolRef]]] = []
            for d in self.discs:
                p = (exact_value(m.eval(d.terms[0], True))[0], exact_value(m.eval(d.terms[1], True))[0])
                said = z3.is_true(m.eval(d.inside(), True))
                if said != d.is_inside(p):
                    more = d.refine(p, said, ctx)
                    if more:
                        cuts.append((d, more))
            if not cuts:
                return Answer("unknown", time.perf_counter() - t0, STUCK, budget=seconds - left)
            self.refinements += 1
            for d, more in cuts:
                self._cut(d, more)
        return Answer("unknown", time.perf_counter() - t0, unknown_reason(self.solver, seconds), budget=seconds)

    def _unknowns(self, e: z3.ExprRef) -> frozenset[str]:
        """The names of the unknowns in ``e`` (memoised by term: atoms share most of their terms)."""
        key = e.get_id()
        got = self._names.get(key)
        if got is None:
            if z3.is_const(e):
                value = z3.is_rational_value(e) or z3.is_int_value(e) or z3.is_true(e) or z3.is_false(e)
                got = frozenset() if value else frozenset({e.decl().name()})
            else:
                got = frozenset().union(*(self._unknowns(c) for c in e.children()))
            self._names[key] = got
        return got

    def _polish(self, m: z3.ModelRef, wrong: list[tuple[z3.BoolRef, z3.BoolRef]], seconds: float) -> z3.ModelRef | None:
        """The obligation over the reals with every unknown fixed at ``m``'s value but those of the
        comparisons ``m`` gets wrong (at most :data:`POLISH_COORDINATES` of them): its model, or None."""
        free: set[str] = set()
        for atom, _ in wrong:
            free |= self._unknowns(atom)
        key = frozenset(free)
        if len(free) > POLISH_COORDINATES or seconds < 0.01 or self._polished.get(key, 0) >= POLISH_REPEATS:
            return None
        self._polished[key] = self._polished.get(key, 0) + 1
        ctx = self.built.ar.ctx
        solver = z3.Solver(ctx=ctx)
        solver.set("rlimit", rlimit(seconds))
        solver.set("timeout", wall_ms(seconds))
        solver.add(*self.built.assertions, *self.built.bounds)
        for x, y in self.built.bodies.values():
            for v in (x, y):
                if z3.is_const(v) and v.decl().name() not in free and not z3.is_rational_value(v):
                    solver.add(v == m.eval(v, model_completion=True))
        return solver.model() if solver.check() == z3.sat else None


CERTIFICATE_FORMAT = (
    "format fatline-certificate 1: '; atom NAME SEXPR' gives the comparison the Boolean NAME stands for; the first "
    "'relaxed assertions' asserts are the obligation's, each comparison by its Boolean; each later assert, after "
    "'; cut NAME', is a cut implied by NAME's comparison"
)
"""The header line that says how a ``.linear.smt2`` file records its atoms and cuts."""


def _one_line(e: z3.ExprRef) -> str:
    return " ".join(e.sexpr().split())


def certificate(path: Path, seconds: float = 30.0) -> str | None:
    """The linearization of a written obligation (the ``.smt2`` file alone), run until it answers: when
    unsat, the linear problem it ended with, as SMT-LIB2 (linear arithmetic with Booleans), for another
    solver to confirm; else None. With the cuts' soundness (``tests/test_linearize.py``), an unsat
    certificate is an unsat obligation."""
    ar = Arith(None)
    built = Built(ar, list(z3.parse_smt2_file(str(path), ctx=ar.ctx)), {}, "")
    lin = Linearization(built)
    if lin.check(seconds).status != "unsat":
        return None
    return lin.script()


__all__ = ["Disc", "Linearization", "certificate", "cover", "direction", "disc", "sqrt_down", "sqrt_up"]
