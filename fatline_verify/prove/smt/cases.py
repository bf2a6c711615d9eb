"""The decision cases of :mod:`fatline_verify.rules.paper.cases` as z3 constraints, over the reals or a lattice.

A decider at a symbolic point makes the decision of one :class:`~fatline_verify.rules.paper.cases.Case` (or of
one of a group of cases) when

- each of its *witnesses* (named roles: ``w`` the psi_right robot, ``b``/``c``/``d`` for R_psi n B/C/D,
  ``k-1``, ``k+3`` ... one blocker per blocked candidate, ``t`` the top of I, ``p`` a robot on a blocked
  Scenario-4 path, ``f``/``e``/``a`` for NoMovement) is visible and where the case needs it, and
- every robot of the *universe* (every robot the obligation names: deciders, witnesses, the violated
  robot) meets the case's universal conditions if the decider sees it.

The destination is then a known term (no search left in the formula). Roles may coincide: two
names are the same robot exactly when their centres are equal, since distinct robots are disjoint
discs. Everything mirrors :mod:`fatline_verify.rules.paper.algorithm` reading by reading; tests compare the two.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TypeAlias

import z3

from ...model.config import Model
from ...model.numbers import Number
from ...model.options import Contact, Visibility
from ...rules.paper.algorithm import Band, Rule
from ...rules.paper.cases import Branch, Case, candidates
from ...rules.paper.options import (
    BandOverlap,
    Bands,
    PathShape,
    PsiRight,
    Quadrants,
    RPsi,
    Scenario4Drop,
    Scenario4FreePath,
    SearchBound,
    Vacant,
)

Term: TypeAlias = z3.ArithRef
Pt = tuple[Term, Term]


class Arith:
    """Where coordinates live: the reals (one radius = 1) or a lattice ``x = X / q`` of integers
    (one radius = ``q``). Each instance has its own z3 context, so an answer never depends on terms
    another search created."""

    def __init__(self, q: int | None = None) -> None:
        self.ctx = z3.Context()
        self.q = q
        self.unit = q or 1
        self.rlimit_seen = 0
        """z3's resource count of this context after its last check (counts are cumulative per context)."""

    @property
    def lattice(self) -> bool:
        return self.q is not None

    def var(self, name: str) -> Term:
        return z3.Int(name, self.ctx) if self.q else z3.Real(name, self.ctx)

    def num(self, radii: Number) -> Term:
        """A length given in radii, in this domain's units (exact; integral on a lattice)."""
        v = Fraction(radii) * self.unit
        if self.q:
            if v.denominator != 1:
                raise ValueError(f"{radii} radii is not on the lattice q={self.q}")
            return z3.IntVal(int(v), self.ctx)
        return z3.RealVal(f"{v.numerator}/{v.denominator}", self.ctx)

    def cmp2(self, e: Term, op: str, radii: Number) -> z3.BoolRef:
        """``e op (radii * unit)^2`` with integer coefficients only (``e`` a squared length)."""
        v = (Fraction(radii) * self.unit) ** 2
        lhs = e * v.denominator if v.denominator != 1 else e
        rhs = z3.IntVal(v.numerator, self.ctx) if self.q else z3.RealVal(v.numerator, self.ctx)
        return {"<": lhs < rhs, "<=": lhs <= rhs, ">": lhs > rhs, ">=": lhs >= rhs}[op]

    def true(self) -> z3.BoolRef:
        return z3.BoolVal(True, self.ctx)

    def false(self) -> z3.BoolRef:
        return z3.BoolVal(False, self.ctx)

    def all(self, terms: Sequence[z3.BoolRef]) -> z3.BoolRef:
        return z3.And(*terms) if terms else self.true()

    def any(self, terms: Sequence[z3.BoolRef]) -> z3.BoolRef:
        return z3.Or(*terms) if terms else self.false()

    def point(self, name: str) -> Pt:
        return (self.var(f"{name}.x"), self.var(f"{name}.y"))

    def origin(self) -> Pt:
        return (self.num(0), self.num(0))


def d2(a: Pt, b: Pt) -> Term:
    dx, dy = a[0] - b[0], a[1] - b[1]
    return dx * dx + dy * dy


def same(a: Pt, b: Pt) -> z3.BoolRef:
    return z3.And(a[0] == b[0], a[1] == b[1])


def view_reach(model: Model) -> Fraction:
    """The visibility distance of the ``visibility`` option, in radii."""
    extra = {Visibility.CENTRE: 0, Visibility.ANY_PART: 1, Visibility.WHOLE_DISC: -1}[model.options.visibility]
    return Fraction(model.parameters.rad_v) + extra


def sees(ar: Arith, model: Model, a: Pt, b: Pt) -> z3.BoolRef:
    """``a`` sees ``b`` (and ``b`` sees ``a``)."""
    return ar.cmp2(d2(a, b), "<=", view_reach(model))


def apart(ar: Arith, model: Model, a: Pt, b: Pt) -> z3.BoolRef:
    """Two robots' discs do not overlap (touching allowed unless ``contact=strict``)."""
    return ar.cmp2(d2(a, b), ">" if model.options.contact is Contact.STRICT else ">=", 2)


def close(ar: Arith, model: Model, e: Term) -> z3.BoolRef:
    """A squared centre distance at which two discs collide, per ``contact``."""
    return ar.cmp2(e, "<=" if model.options.contact is Contact.STRICT else "<", 2)


def _strip(ar: Arith, offset: Term, disc: bool) -> z3.BoolRef:
    if disc:
        return z3.And(offset > -ar.num(2), offset < ar.num(2))
    return z3.And(offset >= -ar.num(1), offset <= ar.num(1))


def bands(ar: Arith, model: Model, rel: Pt) -> dict[Band, z3.BoolRef]:
    """Band membership of a robot at ``rel`` from the decider (visibility not included), as
    :func:`fatline_verify.rules.paper.algorithm.classify`."""
    opts = model.options
    x, y = rel
    disc = opts.bands is Bands.DISC
    in_v, in_h = _strip(ar, x, disc), _strip(ar, y, disc)
    zero = ar.num(0)
    va, vi = z3.And(in_v, y > zero), z3.And(in_v, y < zero)
    hc, hf = z3.And(in_h, x > zero), z3.And(in_h, x < zero)
    vert, hor = z3.Or(va, vi), z3.Or(hc, hf)
    if opts.band_overlap is BandOverlap.VERTICAL_FIRST:
        hc, hf = z3.And(hc, z3.Not(vert)), z3.And(hf, z3.Not(vert))
    elif opts.band_overlap is BandOverlap.HORIZONTAL_FIRST:
        va, vi = z3.And(va, z3.Not(hor)), z3.And(vi, z3.Not(hor))
    none = z3.Not(z3.Or(vert, hor))
    q1, q2 = z3.And(none, x > zero, y > zero), z3.And(none, x < zero, y > zero)
    q3, q4 = z3.And(none, x < zero, y < zero), z3.And(none, x > zero, y < zero)
    if opts.quadrants is Quadrants.LOWER_RIGHT:
        b, d, e, g = q1, q4, q2, q3
    else:
        b, d, e, g = q1, q2, q3, q4
    return {Band.A: va, Band.B: b, Band.C: hc, Band.D: d, Band.E: e, Band.F: hf, Band.G: g, Band.I: vi}


def role_names(case: Case, model: Model) -> list[str]:
    """The witnesses a decider in ``case`` needs (see the module docstring)."""
    rule = case.rule
    if case.branch is None:
        return {Rule.ALONE: [], Rule.F_NONEMPTY: ["f"], Rule.EFG_NONEMPTY: ["e"], Rule.ONLY_AI: ["a"]}[rule]
    names = ["w"] + {
        Branch.S1: [],
        Branch.S2: ["b", "c"],
        Branch.S3: ["c", "d"],
        Branch.NEITHER: ["c"],
        Branch.BOTH: ["b", "c", "d"],
    }[case.branch]
    n = candidates(model)
    for direction in case.failed:
        names += [blocker(direction, i) for i in range(1, n + 1)]
    if case.found is not None:
        direction, i = case.found
        names += [blocker(direction, j) for j in range(1, i)]
    if rule is Rule.SCENARIO_4_I_NONEMPTY or (rule is Rule.SCENARIO_4_PATH_BLOCKED and not case.i_empty):
        names.append("t")
    if rule is Rule.SCENARIO_4_PATH_BLOCKED:
        names.append("p")
    return names


def blocker(direction: int, i: int) -> str:
    """The role name of the robot blocking candidate ``i`` in ``direction``."""
    return f"k{'-' if direction < 0 else '+'}{i}"


@dataclass
class Decided:
    """A decider's encoded decision: constraints, destination and path corner (absolute)."""

    constraints: list[z3.BoolRef]
    dest: Pt
    corner: Pt | None
    selectors: list[z3.BoolRef] = field(default_factory=list)

    def pieces(self, start: Pt) -> list[tuple[Pt, Pt]]:
        if self.corner is None:
            return [(start, self.dest)]
        return [(start, self.corner), (self.corner, self.dest)]


def decide_case(
    ar: Arith,
    model: Model,
    case: Case,
    me: Pt,
    roles: dict[str, Pt],
    universe: Sequence[Pt],
    universals: bool = True,
) -> tuple[list[z3.BoolRef], Pt]:
    """Constraints under which the robot at ``me`` makes ``case``'s decision, and its destination
    (relative to ``me``). ``roles`` must hold every name of :func:`role_names`; ``universe`` is every
    robot of the obligation (``me`` may be in it: it is skipped by position). ``universals=False``
    leaves out the case's universal conditions (over every robot seen): only the witnesses and how the
    destination is built from them remain (:mod:`fatline_verify.prove.basis`: an *immediate* claim)."""
    opts = model.options
    u = ar.num
    zero = u(0)
    out: list[z3.BoolRef] = []

    def rel(p: Pt) -> Pt:
        return (p[0] - me[0], p[1] - me[1])

    def visible(p: Pt) -> z3.BoolRef:
        return sees(ar, model, me, p)

    def witness(name: str, *conds: z3.BoolRef) -> Pt:
        p = roles[name]
        out.extend([z3.Not(same(p, me)), visible(p), *conds])
        return rel(p)

    def universal(cond: object) -> None:
        if not universals:
            return
        for p in universe:
            out.append(z3.Or(same(p, me), z3.Implies(visible(p), cond(rel(p), bands(ar, model, rel(p))))))  # type: ignore[operator]

    rule = case.rule
    if case.branch is None:  # NoMovement
        if rule is Rule.ALONE:
            for p in universe if universals else ():
                out.append(z3.Or(same(p, me), z3.Not(visible(p))))
        elif rule is Rule.F_NONEMPTY:
            p = rel(roles["f"])
            witness("f", bands(ar, model, p)[Band.F])
        elif rule is Rule.EFG_NONEMPTY:
            p = rel(roles["e"])
            bs = bands(ar, model, p)
            witness("e", z3.Or(bs[Band.E], bs[Band.G]))
            universal(lambda r, b: z3.Not(b[Band.F]))
        else:
            p = rel(roles["a"])
            bs = bands(ar, model, p)
            witness("a", z3.Or(bs[Band.A], bs[Band.I]))
            universal(lambda r, b: z3.Not(z3.Or(*[b[k] for k in (Band.B, Band.C, Band.D, Band.E, Band.F, Band.G)])))
        return out, (zero, zero)

    # getDestination: psi_right, R_psi and the branch
    w_rel = rel(roles["w"])
    wb = bands(ar, model, w_rel)
    witness("w", z3.Or(wb[Band.B], wb[Band.C], wb[Band.D]))
    psi0 = w_rel[0]
    psi = psi0 if opts.psi_right is PsiRight.CENTRE_LINE else psi0 - u(1)
    rpsi_disc = opts.r_psi is RPsi.DISC or (opts.r_psi is RPsi.FOLLOWS_BANDS and opts.bands is Bands.DISC)

    def in_r(p: Pt) -> z3.BoolRef:
        return _strip(ar, p[0] - psi, rpsi_disc)

    for name, band in (("b", Band.B), ("c", Band.C), ("d", Band.D)):
        if name in roles and name in role_names(case, model):
            p = rel(roles[name])
            witness(name, in_r(p), bands(ar, model, p)[band])
    excluded = {
        Branch.S1: [Band.C],
        Branch.S2: [Band.D],
        Branch.S3: [Band.B],
        Branch.NEITHER: [Band.B, Band.D],
        Branch.BOTH: [],
    }[case.branch]

    strict_vacant = opts.vacant is Vacant.STRICT

    def blocks(p: Pt, cand: Pt) -> z3.BoolRef:
        return ar.cmp2(d2(p, cand), "<=" if strict_vacant else "<", 2)

    def in_view(i: int) -> z3.BoolRef:
        if opts.search_bound is not SearchBound.WITHIN_VIEW:
            return ar.true()
        return ar.cmp2(psi * psi + u(i) * u(i), "<=", Fraction(model.parameters.rad_v))

    for direction in case.failed:
        for i in range(1, candidates(model) + 1):
            cand = (psi, u(direction * i))
            k = rel(roles[blocker(direction, i)])
            p = roles[blocker(direction, i)]
            out.append(z3.Or(z3.Not(in_view(i)), z3.And(z3.Not(same(p, me)), visible(p), blocks(k, cand))))
    vacant_at: Pt | None = None
    if case.found is not None:
        direction, i = case.found
        for j in range(1, i):
            witness(blocker(direction, j), blocks(rel(roles[blocker(direction, j)]), (psi, u(direction * j))))
        out.append(in_view(i))
        vacant_at = (psi, u(direction * i))

    top: Term | None = None
    if "t" in role_names(case, model):
        t_rel = rel(roles["t"])
        witness("t", bands(ar, model, t_rel)[Band.I])
        top = t_rel[1]

    def cond(p: Pt, b: dict[Band, z3.BoolRef]) -> z3.BoolRef:
        terms = [z3.Not(b[Band.E]), z3.Not(b[Band.F]), z3.Not(b[Band.G])]
        terms.append(z3.Implies(z3.Or(b[Band.B], b[Band.C], b[Band.D]), p[0] >= psi0))
        terms += [z3.Not(z3.And(in_r(p), b[band])) for band in excluded]
        if vacant_at is not None:
            terms.append(z3.Not(blocks(p, vacant_at)))
        if case.i_empty is True:
            terms.append(z3.Not(b[Band.I]))
        elif top is not None:
            terms.append(z3.Implies(b[Band.I], p[1] <= top))
        return z3.And(*terms)

    universal(cond)

    if rule is Rule.SCENARIO_4_GUARD_FAILS or rule is Rule.UNCOVERED_STAY:
        return out, (zero, zero)
    if case.found is not None:
        return out, vacant_at  # type: ignore[return-value]
    if rule is Rule.SCENARIO_1:
        return out, (psi, zero)
    # Scenario 4
    rad_v = Fraction(model.parameters.rad_v)
    drop = opts.scenario4_drop
    if case.i_empty:
        y: Term = u(-rad_v if drop is Scenario4Drop.PROOFS else -rad_v + 1)
    else:
        assert top is not None
        d = -top
        y = {
            Scenario4Drop.LITERAL: -d + u(1),
            Scenario4Drop.TOUCH: -d + u(2),
            Scenario4Drop.GAP: -(d - u(2)) + u(1),
            Scenario4Drop.PROOFS: -d + u(2),
        }[drop]
    if opts.scenario4_free_path is Scenario4FreePath.ON:
        on_path = _on_path(ar, model, y)
        if rule is Rule.SCENARIO_4_PATH_BLOCKED:
            witness("p", on_path(rel(roles["p"])))
            return out, (zero, zero)
        universal(lambda p, b: z3.Not(on_path(p)))
    return out, (zero, y)


def _on_path(ar: Arith, model: Model, y: Term) -> Callable[[Pt], z3.BoolRef]:
    """Whether a robot at ``p`` meets the width-2 rectangle from the decider down to ``(0, y)``
    (:func:`fatline_verify.rules.paper.algorithm.free_path`): its centre within one radius of it."""
    strict = model.options.vacant is Vacant.STRICT
    zero = ar.num(0)
    lo_y, hi_y = z3.If(y < zero, y, zero), z3.If(y < zero, zero, y)

    def near(p: Pt) -> z3.BoolRef:
        x, py = p
        one = ar.num(1)
        ex = z3.If(x < -one, -one - x, z3.If(x > one, x - one, zero))
        ey = z3.If(py < lo_y, lo_y - py, z3.If(py > hi_y, py - hi_y, zero))
        return ar.cmp2(ex * ex + ey * ey, "<=" if strict else "<", 1)

    return near


def decide_group(
    ar: Arith,
    model: Model,
    cases: Sequence[Case],
    me: Pt,
    roles: dict[str, Pt],
    universe: Sequence[Pt],
    tag: str,
    universals: bool = True,
) -> Decided:
    """The decider makes the decision of one of ``cases`` (a disjunction; the cases of one model
    are disjoint, so at most one holds). The destination and corner are absolute."""
    constraints: list[z3.BoolRef] = []
    selectors = [z3.Bool(f"{tag}.case{i}", ar.ctx) for i in range(len(cases))]
    dests: list[Pt] = []
    for sel, case in zip(selectors, cases, strict=True):
        cs, dest = decide_case(ar, model, case, me, roles, universe, universals)
        constraints.append(z3.Implies(sel, z3.And(*cs)))
        dests.append(dest)
    constraints.append(ar.any(selectors))
    dx, dy = dests[-1]
    for sel, (x, y) in zip(reversed(selectors[:-1]), reversed(dests[:-1]), strict=True):
        dx, dy = z3.If(sel, x, dx), z3.If(sel, y, dy)
    dest = (me[0] + dx, me[1] + dy)
    corner: Pt | None = None
    if model.options.path is PathShape.HORIZONTAL_THEN_VERTICAL:
        corner = (dest[0], me[1])
    elif model.options.path is PathShape.VERTICAL_THEN_HORIZONTAL:
        corner = (me[0], dest[1])
    return Decided(constraints, dest, corner, selectors)


def roles_for(ar: Arith, cases: Sequence[Case], model: Model, prefix: str) -> dict[str, Pt]:
    """Fresh points for every witness any of ``cases`` needs, named ``PREFIX.ROLE``."""
    names = dict.fromkeys(n for c in cases for n in role_names(c, model))
    return {n: ar.point(f"{prefix}.{n}") for n in names}


__all__ = [
    "Arith",
    "Decided",
    "apart",
    "bands",
    "close",
    "d2",
    "decide_case",
    "decide_group",
    "role_names",
    "roles_for",
    "same",
    "sees",
    "view_reach",
]
