"""The algorithm over the reals: ``decide`` for a robot at the origin and ``k`` symbolic slot robots.

Each slot robot has a centre ``(x, y)`` relative to the deciding robot and a ``present`` flag, so ``k``
slots stand for every configuration of at most ``k`` other robots. Everything mirrors
:mod:`fatline_verify.rules.paper.algorithm` reading by reading; unit = one radius. ``psi0`` (the least x in
B u C u D) and ``top`` (the highest y in I) are fresh variables pinned down by side constraints,
which every use must assert (``SymDecision.side``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from math import floor

import z3

from ...model.config import Model
from ...model.numbers import Number
from ...model.options import Visibility
from ...rules.paper.algorithm import Band, Rule
from ...rules.paper.options import (
    BandOverlap,
    Bands,
    PathShape,
    PsiRight,
    Quadrants,
    RPsi,
    Scenario4Drop,
    Scenario4FreePath,
    Scenario4Guard,
    SearchBound,
    SearchOrder,
    Uncovered,
    Vacant,
)

RULES = list(Rule)


def real(v: Number) -> z3.ArithRef:
    """An exact z3 rational."""
    f = Fraction(v)
    return z3.RealVal(f"{f.numerator}/{f.denominator}")


def any_(terms: list[z3.BoolRef]) -> z3.BoolRef:
    return z3.Or(*terms) if terms else z3.BoolVal(False)


def all_(terms: list[z3.BoolRef]) -> z3.BoolRef:
    return z3.And(*terms) if terms else z3.BoolVal(True)


def sq(e: z3.ArithRef) -> z3.ArithRef:
    return e * e


@dataclass
class Slot:
    """A symbolic robot: centre relative to the observer and whether it exists."""

    x: z3.ArithRef
    y: z3.ArithRef
    present: z3.BoolRef

    def minus(self, ox: z3.ArithRef, oy: z3.ArithRef) -> Slot:
        return Slot(self.x - ox, self.y - oy, self.present)


@dataclass
class SymDecision:
    """A symbolic decision: rule index, destination, path corner, and the side constraints."""

    rule: z3.ArithRef
    dx: z3.ArithRef
    dy: z3.ArithRef
    corner: tuple[z3.ArithRef, z3.ArithRef] | None
    side: list[z3.BoolRef] = field(default_factory=list)

    def is_rule(self, rule: Rule) -> z3.BoolRef:
        return self.rule == RULES.index(rule)

    @property
    def moves(self) -> z3.BoolRef:
        return z3.Or(self.dx != 0, self.dy != 0)


def view_reach(model: Model) -> Fraction:
    """The visibility distance of the ``visibility`` option, in radii."""
    extra = {Visibility.CENTRE: 0, Visibility.ANY_PART: 1, Visibility.WHOLE_DISC: -1}[model.options.visibility]
    return Fraction(model.parameters.rad_v) + extra


def candidates_per_direction(model: Model) -> int:
    """How many search candidates one direction can examine: within view, ``i <= rad_v``; unbounded,
    up to the first one more than 2 beyond every visible robot (which is always vacant)."""
    if model.options.search_bound is SearchBound.WITHIN_VIEW:
        return floor(Fraction(model.parameters.rad_v))
    return floor(view_reach(model)) + 3


def _strip(offset: z3.ArithRef, disc: bool) -> z3.BoolRef:
    return z3.And(offset > -2, offset < 2) if disc else z3.And(offset >= -1, offset <= 1)


def classify(c: Slot, model: Model, visible: z3.BoolRef) -> dict[Band, z3.BoolRef]:
    """Band membership of a slot (false when it is not visible), as :func:`algorithm.classify`."""
    opts = model.options
    disc = opts.bands is Bands.DISC
    in_v, in_h = _strip(c.x, disc), _strip(c.y, disc)
    va, vi = z3.And(in_v, c.y > 0), z3.And(in_v, c.y < 0)
    hc, hf = z3.And(in_h, c.x > 0), z3.And(in_h, c.x < 0)
    vert, hor = z3.Or(va, vi), z3.Or(hc, hf)
    if opts.band_overlap is BandOverlap.VERTICAL_FIRST:
        hc, hf = z3.And(hc, z3.Not(vert)), z3.And(hf, z3.Not(vert))
    elif opts.band_overlap is BandOverlap.HORIZONTAL_FIRST:
        va, vi = z3.And(va, z3.Not(hor)), z3.And(vi, z3.Not(hor))
    none = z3.Not(z3.Or(vert, hor))
    q1, q2 = z3.And(none, c.x > 0, c.y > 0), z3.And(none, c.x < 0, c.y > 0)
    q3, q4 = z3.And(none, c.x < 0, c.y < 0), z3.And(none, c.x > 0, c.y < 0)
    if opts.quadrants is Quadrants.LOWER_RIGHT:
        b, d, e, g = q1, q4, q2, q3
    else:
        b, d, e, g = q1, q2, q3, q4
    sets = {Band.A: va, Band.B: b, Band.C: hc, Band.D: d, Band.E: e, Band.F: hf, Band.G: g, Band.I: vi}
    return {k: z3.And(visible, v) for k, v in sets.items()}


def _extremum(var: z3.ArithRef, members: list[z3.BoolRef], values: list[z3.ArithRef], least: bool) -> z3.BoolRef:
    """``var`` is the least (or greatest) of ``values`` over the members, when there is a member."""
    bound = [z3.Implies(m, var <= v if least else v <= var) for m, v in zip(members, values, strict=True)]
    attained = [z3.And(m, var == v) for m, v in zip(members, values, strict=True)]
    return z3.Implies(any_(members), z3.And(any_(attained), all_(bound)))


def decide(slots: list[Slot], model: Model, tag: str) -> SymDecision:
    """``LineForm()`` for the robot at the origin seeing (some of) ``slots``."""
    opts = model.options
    reach2 = real(view_reach(model) ** 2)
    rad_v = real(model.parameters.rad_v)
    visible = [z3.And(c.present, sq(c.x) + sq(c.y) <= reach2) for c in slots]
    sets = [classify(c, model, v) for c, v in zip(slots, visible, strict=True)]
    side: list[z3.BoolRef] = []

    def some(band: Band) -> z3.BoolRef:
        return any_([s[band] for s in sets])

    right = [z3.Or(s[Band.B], s[Band.C], s[Band.D]) for s in sets]
    psi0 = z3.Real(f"psi0_{tag}")
    side.append(_extremum(psi0, right, [c.x for c in slots], least=True))
    psi = psi0 if opts.psi_right is PsiRight.CENTRE_LINE else psi0 - 1
    rpsi_disc = opts.r_psi is RPsi.DISC or (opts.r_psi is RPsi.FOLLOWS_BANDS and opts.bands is Bands.DISC)
    in_r = [z3.And(v, _strip(c.x - psi, rpsi_disc)) for c, v in zip(slots, visible, strict=True)]
    rb = any_([z3.And(r, s[Band.B]) for r, s in zip(in_r, sets, strict=True)])
    rc = any_([z3.And(r, s[Band.C]) for r, s in zip(in_r, sets, strict=True)])
    rd = any_([z3.And(r, s[Band.D]) for r, s in zip(in_r, sets, strict=True)])

    strict = opts.vacant is Vacant.STRICT

    def vacant(px: z3.ArithRef, py: z3.ArithRef) -> z3.BoolRef:
        far = [sq(c.x - px) + sq(c.y - py) > 4 if strict else sq(c.x - px) + sq(c.y - py) >= 4 for c in slots]
        return all_([z3.Implies(v, f) for v, f in zip(visible, far, strict=True)])

    n_cand = candidates_per_direction(model)
    bounded = opts.search_bound is SearchBound.WITHIN_VIEW

    def search(direction: int) -> tuple[z3.BoolRef, z3.ArithRef]:
        """(found, y of the found candidate) for one direction."""
        vac = [vacant(psi, real(direction * i)) for i in range(1, n_cand + 1)]
        inview = [sq(psi) + i * i <= sq(rad_v) if bounded else z3.BoolVal(True) for i in range(1, n_cand + 1)]
        found = [z3.And(inview[i], vac[i], *[z3.Not(vac[j]) for j in range(i)]) for i in range(n_cand)]
        y: z3.ArithRef = real(0)
        for i in reversed(range(n_cand)):
            y = z3.If(found[i], real(direction * (i + 1)), y)
        return any_(found), y

    # Scenario 4
    below = [s[Band.I] for s in sets]
    top = z3.Real(f"top_{tag}")
    side.append(_extremum(top, below, [c.y for c in slots], least=False))
    d = -top
    drop = opts.scenario4_drop
    y_empty = -rad_v if drop is Scenario4Drop.PROOFS else -rad_v + 1
    y_full = {
        Scenario4Drop.LITERAL: -d + 1,
        Scenario4Drop.TOUCH: -d + 2,
        Scenario4Drop.GAP: -(d - 2) + 1,
        Scenario4Drop.PROOFS: -d + 2,
    }[drop]
    i_empty = z3.Not(any_(below))
    y4 = z3.If(i_empty, y_empty, y_full)
    if opts.scenario4_free_path is Scenario4FreePath.ON:
        lo, hi = z3.If(y4 < 0, y4, real(0)), z3.If(y4 < 0, real(0), y4)
        hits = []
        for c, v in zip(slots, visible, strict=True):
            ex = z3.If(c.x < -1, -1 - c.x, z3.If(c.x > 1, c.x - 1, real(0)))
            ey = z3.If(c.y < lo, lo - c.y, z3.If(c.y > hi, c.y - hi, real(0)))
            near = sq(ex) + sq(ey) <= 1 if strict else sq(ex) + sq(ey) < 1
            hits.append(z3.And(v, near))
        blocked = any_(hits)
    else:
        blocked = z3.BoolVal(False)
    guard = z3.And(rb, rc, rd) if opts.scenario4_guard is Scenario4Guard.ALL_THREE_FULL else z3.BoolVal(True)

    def idx(rule: Rule) -> z3.ArithRef:
        return z3.IntVal(RULES.index(rule))

    def scenario4() -> tuple[z3.ArithRef, z3.ArithRef, z3.ArithRef]:
        rule = z3.If(
            z3.Not(guard),
            idx(Rule.SCENARIO_4_GUARD_FAILS),
            z3.If(
                blocked,
                idx(Rule.SCENARIO_4_PATH_BLOCKED),
                z3.If(i_empty, idx(Rule.SCENARIO_4_I_EMPTY), idx(Rule.SCENARIO_4_I_NONEMPTY)),
            ),
        )
        moving = z3.And(guard, z3.Not(blocked))
        return rule, real(0), z3.If(moving, y4, real(0))

    def searched(directions: list[int], found_rule: Rule) -> tuple[z3.ArithRef, z3.ArithRef, z3.ArithRef]:
        rule, dx, dy = scenario4()
        for direction in reversed(directions):
            found, y = search(direction)
            rule = z3.If(found, idx(found_rule), rule)
            dx = z3.If(found, psi, dx)
            dy = z3.If(found, y, dy)
        return rule, dx, dy

    both = opts.search_order is SearchOrder.PRIMARY_THEN_OPPOSITE
    s2 = searched([-1, 1] if both else [-1], Rule.SCENARIO_2)
    s3 = searched([1, -1] if both else [1], Rule.SCENARIO_3)
    if opts.uncovered is Uncovered.STAY:
        unc = (idx(Rule.UNCOVERED_STAY), real(0), real(0))
    elif opts.uncovered is Uncovered.SEARCH_BOTH:
        unc = searched([-1, 1], Rule.UNCOVERED_SEARCH)
    else:
        unc = scenario4()

    Triple = tuple[z3.ArithRef, z3.ArithRef, z3.ArithRef]

    def pick(cond: z3.BoolRef, a: Triple, b: Triple) -> Triple:
        return (z3.If(cond, a[0], b[0]), z3.If(cond, a[1], b[1]), z3.If(cond, a[2], b[2]))

    zero = (real(0), real(0))
    case = pick(z3.And(rb, z3.Not(rd)), s2, pick(z3.And(rd, z3.Not(rb)), s3, unc))
    case = pick(z3.Not(rc), (idx(Rule.SCENARIO_1), psi, real(0)), case)
    case = pick(z3.Not(any_(right)), (idx(Rule.ONLY_AI), *zero), case)
    case = pick(z3.Or(some(Band.E), some(Band.G)), (idx(Rule.EFG_NONEMPTY), *zero), case)
    case = pick(some(Band.F), (idx(Rule.F_NONEMPTY), *zero), case)
    case = pick(z3.Not(any_(visible)), (idx(Rule.ALONE), *zero), case)
    rule, dx, dy = case
    corner = None
    if opts.path is PathShape.HORIZONTAL_THEN_VERTICAL:
        corner = (dx, real(0))
    elif opts.path is PathShape.VERTICAL_THEN_HORIZONTAL:
        corner = (real(0), dy)
    return SymDecision(rule, dx, dy, corner, side)


def witness_bound(rule: Rule, model: Model) -> int:
    """How many robots besides the deciding one can be needed to make ``rule`` fire with its
    destination: the psi_right robot, one robot each for R n B, R n C, R n D, one blocker per
    blocked search candidate, the highest robot of I. Any violating swarm contains such a
    sub-swarm plus the violated robot, on which ``decide`` gives the same decision."""
    n = candidates_per_direction(model)
    both = model.options.search_order is SearchOrder.PRIMARY_THEN_OPPOSITE
    if rule is Rule.SCENARIO_1:
        return 1
    if rule in (Rule.SCENARIO_2, Rule.SCENARIO_3):
        return 3 + (2 * n - 1 if both else n - 1)
    if rule is Rule.UNCOVERED_SEARCH:
        return 4 + 2 * n - 1
    return 4 + 2 * n + 1


def make_slots(k: int, prefix: str = "") -> list[Slot]:
    """``k`` fresh symbolic robots."""
    return [Slot(z3.Real(f"{prefix}x{i}"), z3.Real(f"{prefix}y{i}"), z3.Bool(f"{prefix}p{i}")) for i in range(k)]


__all__ = ["RULES", "Slot", "SymDecision", "decide", "make_slots", "real", "witness_bound"]
