"""Role-assigned obligations: one per lemma form and decision case, r's destination a known term.

An obligation asks z3 for a configuration in which r (at the origin) makes the decision of one
:class:`~fatline_verify.rules.paper.cases.Case` and a claim fails. The robots named are r, r's witnesses
(:mod:`fatline_verify.prove.smt.cases`), and per form:

- ``one-mover``: a robot ``o`` at rest (visible to r or not). Claims: ``no-collision`` (r's swept
  disc meets o), ``connectivity`` (r saw o and does not after its move). Under ``fsync``, o is at
  rest because it decides to stay: o and its witnesses are encoded too.
- ``two-movers`` (ssync, fsync): a second robot ``s`` that moves in the same round, deciding one of
  the cases of one rule from the same snapshot, with its own witnesses. Claims: ``no-collision``
  (the two movers come within 2, per ``timing``), ``connectivity`` (they saw each other and do not).
- ``seen`` (``rma-fixed``): r's destination is right of r and of every robot r sees.
- ``on-rma`` (``rma-fixed``, the other half of Lemma 3: "a robot on the RMA never leaves it"): no
  named robot is right of r (r is on the right-most axis of any swarm they are part of), and r's
  destination has another x.
- ``x-nondecreasing`` (``approach``): r's destination has a smaller x.
- ``closer`` (``connectivity``, Lemma 1's argument): some robot of B u C u D that r sees is not
  closer to r's destination than to r.

Why ``unsat`` covers swarms of every size (written in each obligation's header): take any swarm in
which the claim fails, with r in the case. Name r's witnesses in it (they exist: the case's
existential conditions), s's and o's likewise, and the violated robot. Every robot of the swarm meets
the case's universal conditions, in particular the named ones; the named robots are distinct discs
or the same robot (equal centres). So the named robots are a solution of the obligation, and an
obligation without solution means no swarm of any size breaks the claim in this case. Conversely,
a solution's named robots form a swarm in which r makes the same decision (the witness argument of
:mod:`fatline_verify.rules.paper.cases`); the prover still replays it before calling it a counterexample.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from math import ceil

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Scheduler, Timing
from ...rules.paper.algorithm import Band
from ...rules.paper.cases import Case
from ...rules.paper.options import PathShape
from .cases import Arith, Decided, Pt, apart, bands, close, d2, decide_group, roles_for, same, sees, view_reach


class NotEncoded(Exception):
    """A form this encoding does not cover, with the reason."""


ONE_MOVER = "one-mover"
TWO_MOVERS = "two-movers"
SEEN = "seen"
ON_RMA = "on-rma"
X_NONDECREASING = "x-nondecreasing"
CLOSER = "closer"
GLOBAL = "global"

CLAIM = {
    (Lemma.NO_COLLISION, ONE_MOVER): "no robot o at rest comes within distance 2 of r's path",
    (Lemma.CONNECTIVITY, ONE_MOVER): "every robot o at rest that r saw before the round is still visible after it",
    (Lemma.NO_COLLISION, TWO_MOVERS): "a robot s moving in the same round never comes within distance 2 of r",
    (Lemma.CONNECTIVITY, TWO_MOVERS): "a robot s moving in the same round that r saw stays visible to r",
    (Lemma.RMA_FIXED, SEEN): "r does not move right of every robot it sees (and of itself)",
    (Lemma.RMA_FIXED, ON_RMA): "r, on the right-most axis (no robot right of it), keeps its x (never leaves the axis)",
    (Lemma.APPROACH, X_NONDECREASING): "r's move does not decrease its x",
    (Lemma.CONNECTIVITY, CLOSER): "after the move r is strictly closer to every robot of B u C u D it sees (Lemma 1)",
}
"""Each (lemma, form) and the claim its obligations negate."""


@dataclass(frozen=True, slots=True)
class Spec:
    """One obligation: a lemma form, r's case (or, for two movers, the cases of one rule), and the
    other robot's cases (two movers: the cases of one rule; fsync one-mover: o's staying cases)."""

    lemma: Lemma
    form: str
    mine: tuple[Case, ...]
    other: tuple[Case, ...] = ()
    other_name: str = ""
    repair: str = ""
    """A repaired rule set's own destination in r's case (:data:`REPAIRS`), or ``""``: the paper's."""

    @classmethod
    def of(cls, lemma: Lemma, form: str, case: Case, other: tuple[Case, ...] = (), other_name: str = "") -> Spec:
        return cls(lemma, form, (case,), other, other_name)

    @property
    def name(self) -> str:
        """r's case name, or its rule for a group; ``repair-NAME.CASE`` for a repair's destination."""
        base = self.mine[0].name if len(self.mine) == 1 else self.mine[0].rule.value
        return f"repair-{self.repair}.{base}" if self.repair else base

    @property
    def key(self) -> str:
        """``lemma/form-case[.and.other]``: how result rows and files name the obligation."""
        tail = f".and.{self.other_name}" if self.other_name else ""
        return f"{self.lemma}/{self.form}-{self.name}{tail}"

    @property
    def claim(self) -> str:
        return CLAIM[(self.lemma, self.form)]


REPAIRS = {
    "align": "repair_stack = align: r, seeing only A u I, moves to the greatest x it sees, if right of r",
    "approach": "repair_approach = on: in Scenario 4, r moves to 2 radii short of psi_right, if right of r",
    "contract": "repair_stack = align: the top or bottom of a vertical, seeing only A u I, moves along its vertical",
}
"""The repaired rule set's own destinations (:mod:`fatline_verify.rules.repaired.algorithm`), each encoded in
the paper case it replaces (only-AI, Scenario 4), so that the facts the leg argument and Lemma 3 take from
the destinations (``x-nondecreasing``, ``seen``, ``on-rma``) are obligations for them too."""


@dataclass
class Built:
    """An encoded obligation: its assertions and the named robots (absolute, r first)."""

    ar: Arith
    assertions: list[z3.BoolRef]
    bodies: dict[str, Pt]
    focus: str
    """The robot the claim is about besides r: ``o``, ``s``, or ``""``."""
    comment: str = ""
    bounds: list[z3.BoolRef] = field(default_factory=list)


def segment_close(ar: Arith, model: Model, p: Pt, a: Pt, b: Pt) -> z3.BoolRef:
    """Closed form: the point ``p`` comes within 2 of the segment ``ab`` (per ``contact``)."""
    vx, vy = b[0] - a[0], b[1] - a[1]
    wx, wy = p[0] - a[0], p[1] - a[1]
    dot = wx * vx + wy * vy
    vv = vx * vx + vy * vy
    zero = ar.num(0)
    four = ar.num(2) * ar.num(2)
    inner = (wx * wx + wy * wy) * vv - dot * dot
    from ...model.options import Contact

    mid = inner <= four * vv if model.options.contact is Contact.STRICT else inner < four * vv
    return z3.Or(
        z3.And(dot <= zero, close(ar, model, d2(p, a))),
        z3.And(dot >= vv, close(ar, model, d2(p, b))),
        z3.And(dot > zero, dot < vv, mid),
    )


def _orient(a: Pt, b: Pt, c: Pt) -> z3.ArithRef:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def capsules_close(ar: Arith, model: Model, ab: tuple[Pt, Pt], cd: tuple[Pt, Pt]) -> z3.BoolRef:
    """Closed form: two segments come within 2 (they cross, or an end point is within 2 of the other)."""
    (a, b), (c, d) = ab, cd
    zero = ar.num(0)
    crosses = z3.And(_orient(a, b, c) * _orient(a, b, d) < zero, _orient(c, d, a) * _orient(c, d, b) < zero)
    return z3.Or(
        crosses,
        segment_close(ar, model, a, c, d),
        segment_close(ar, model, b, c, d),
        segment_close(ar, model, c, a, b),
        segment_close(ar, model, d, a, b),
    )


def _movers_close(ar: Arith, model: Model, r: Pt, dr: Decided, s: Pt, ds: Decided) -> z3.BoolRef:
    mine, theirs = dr.pieces(r), ds.pieces(s)
    if model.options.timing is Timing.ANY_SPEED:
        return ar.any([capsules_close(ar, model, p, q) for p in mine for q in theirs])
    if model.options.path is not PathShape.STRAIGHT:
        return _lockstep_l(ar, model, r, dr, s, ds)
    # lockstep on straight segments: the relative position moves on a segment; its distance to 0
    d0 = (r[0] - s[0], r[1] - s[1])
    d1 = (dr.dest[0] - ds.dest[0], dr.dest[1] - ds.dest[1])
    return segment_close(ar, model, ar.origin(), d0, d1)


def _lockstep_l(ar: Arith, model: Model, r: Pt, dr: Decided, s: Pt, ds: Decided) -> z3.BoolRef:
    """Lockstep timing with L-shaped paths: both centres at constant speed along their pieces,
    starting and arriving together, at a common time ``t`` in [0, 1] (one parameter; the corner
    times are the first piece's share of the path's length)."""
    if ar.lattice:
        raise NotEncoded("lockstep timing with L-shaped paths is searched over the reals only")
    t = z3.Real("t", ar.ctx)
    zero, one = ar.num(0), ar.num(1)

    def position(start: Pt, dec: Decided, tag: str) -> tuple[Pt, list[z3.BoolRef]]:
        assert dec.corner is not None
        c, e = dec.corner, dec.dest
        l1 = _abs(c[0] - start[0]) + _abs(c[1] - start[1])
        l2 = _abs(e[0] - c[0]) + _abs(e[1] - c[1])
        total = l1 + l2
        x, y = z3.Real(f"{tag}.tx", ar.ctx), z3.Real(f"{tag}.ty", ar.ctx)
        run = t * total  # arc length travelled; on the first piece while it is at most l1
        cons = [
            z3.Implies(
                run <= l1,
                z3.And(
                    x * l1 == start[0] * l1 + run * (c[0] - start[0]), y * l1 == start[1] * l1 + run * (c[1] - start[1])
                ),
            ),
            z3.Implies(
                run > l1,
                z3.And(
                    x * l2 == c[0] * l2 + (run - l1) * (e[0] - c[0]), y * l2 == c[1] * l2 + (run - l1) * (e[1] - c[1])
                ),
            ),
        ]
        return (x, y), cons

    pr, cr = position(r, dr, "r")
    ps, cs = position(s, ds, "s")
    return z3.And(t >= zero, t <= one, *cr, *cs, close(ar, model, d2(pr, ps)))


def _abs(e: z3.ArithRef) -> z3.ArithRef:
    return z3.If(e < 0, -e, e)


def lattice_extent(model: Model) -> Fraction:
    """How far (radii) from r a named robot can be: o up to a view plus a path plus a diameter from
    r, witnesses a view from their decider."""
    return 3 * view_reach(model) + 6


def build(
    ar: Arith, model: Model, spec: Spec, *, initial: bool = False, vacuity: bool = False, immediate: bool = False
) -> Built:
    """The obligation ``spec`` over ``ar``'s domain. ``initial`` (lattice searches) adds the paper's
    initial condition on the named robots (pairwise distance >= delta, connected); the replay checks
    it again. ``vacuity`` keeps only "r (and s) make their decisions": unsat means the case never fires.
    ``immediate`` leaves out every decider's universal conditions (the claim's premises only: the
    witnesses, the destination built from them, disjoint discs): unsat means the claim follows from
    the rule's construction (:mod:`fatline_verify.prove.basis`)."""
    scheduler = model.options.scheduler
    form = spec.form
    r = ar.origin()
    r_roles = roles_for(ar, spec.mine, model, "r")
    if spec.repair == "align":
        r_roles["m"] = ar.point("r.m")  # the robot of greatest x that r sees
    bodies: dict[str, Pt] = {"r": r, **{f"r.{k}": v for k, v in r_roles.items()}}
    groups: list[tuple[Pt, dict[str, Pt]]] = [(r, r_roles)]
    must_differ = set()
    s = o = None
    other_roles: dict[str, Pt] = {}
    if form == TWO_MOVERS:
        s = ar.point("s")
        other_roles = roles_for(ar, spec.other, model, "s")
        bodies["s"] = s
        bodies.update({f"s.{k}": v for k, v in other_roles.items()})
        groups.append((s, other_roles))
        must_differ.add(("r", "s"))
    elif form in (ONE_MOVER, CLOSER):
        o = ar.point("o")
        bodies["o"] = o
        must_differ.add(("r", "o"))
        if form == ONE_MOVER and scheduler is Scheduler.FSYNC:
            other_roles = roles_for(ar, spec.other, model, "o")
            bodies.update({f"o.{k}": v for k, v in other_roles.items()})
            groups.append((o, other_roles))
    universe = list(bodies.values())
    names = list(bodies)
    asserts: list[z3.BoolRef] = []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            sep = apart(ar, model, bodies[a], bodies[b])
            asserts.append(sep if (a, b) in must_differ else z3.Or(same(bodies[a], bodies[b]), sep))
    dr = decide_group(ar, model, spec.mine, r, r_roles, universe, "r", not immediate)
    if spec.repair:
        dr = _repaired(ar, model, spec.repair, r, r_roles, universe, dr, not immediate)
    asserts += dr.constraints
    ds: Decided | None = None
    if s is not None:
        ds = decide_group(ar, model, spec.other, s, other_roles, universe, "s", not immediate)
        asserts += ds.constraints
    elif o is not None and form == ONE_MOVER and scheduler is Scheduler.FSYNC:
        asserts += decide_group(ar, model, spec.other, o, other_roles, universe, "o", not immediate).constraints
    focus = "s" if s is not None else "o" if o is not None else ""
    bounds: list[z3.BoolRef] = []
    if ar.lattice:
        extent = ar.num(Fraction(ceil(lattice_extent(model))))
        for name, (x, y) in bodies.items():
            if name != "r":
                bounds += [x >= -extent, x <= extent, y >= -extent, y <= extent]
    if initial:
        asserts += _initial(ar, model, bodies, groups)
    if vacuity:
        return Built(ar, asserts, bodies, focus, bounds=bounds)
    asserts.append(_violation(ar, model, spec, r, dr, s, ds, o, bodies))
    return Built(ar, asserts, bodies, focus, bounds=bounds)


def _repaired(
    ar: Arith, model: Model, repair: str, r: Pt, roles: dict[str, Pt], universe: list[Pt], dr: Decided, universals: bool
) -> Decided:
    """r's paper decision ``dr`` replaced by the repair's destination (:data:`REPAIRS`), with the repair's
    own conditions: ``align``: a witness m that r sees, right of r, and (universal) no robot r sees right
    of m; ``approach``: psi_right (from the case's witness w) more than 2 radii right of r; ``contract``:
    any step along r's vertical of at most one radius."""
    from ...rules.paper.options import PsiRight

    zero = ar.num(0)
    cons = list(dr.constraints)
    if repair == "align":
        m = roles["m"]
        cons += [z3.Not(same(m, r)), sees(ar, model, r, m), m[0] > r[0]]
        if universals:
            cons += [z3.Or(same(p, r), z3.Not(sees(ar, model, r, p)), p[0] <= m[0]) for p in universe]
        dest = (m[0], r[1])
    elif repair == "approach":
        psi = roles["w"][0] - r[0]
        if model.options.psi_right is not PsiRight.CENTRE_LINE:
            psi = psi - ar.num(1)
        x = psi - ar.num(2)
        cons.append(x > zero)
        dest = (r[0] + x, r[1])
    elif repair == "contract":
        step = ar.var("r.contract")
        cons += [step != zero, step <= ar.num(1), step >= -ar.num(1)]
        dest = (r[0], r[1] + step)
    else:
        raise NotEncoded(f"repair {repair!r}: expected one of {', '.join(REPAIRS)}")
    corner: Pt | None = None
    if model.options.path is PathShape.HORIZONTAL_THEN_VERTICAL:
        corner = (dest[0], r[1])
    elif model.options.path is PathShape.VERTICAL_THEN_HORIZONTAL:
        corner = (r[0], dest[1])
    return Decided(cons, dest, corner, dr.selectors)


def _violation(
    ar: Arith,
    model: Model,
    spec: Spec,
    r: Pt,
    dr: Decided,
    s: Pt | None,
    ds: Decided | None,
    o: Pt | None,
    bodies: dict[str, Pt],
) -> z3.BoolRef:
    lemma, form = spec.lemma, spec.form
    if form == ONE_MOVER:
        assert o is not None
        if lemma is Lemma.NO_COLLISION:
            return ar.any([segment_close(ar, model, o, a, b) for a, b in dr.pieces(r)])
        return z3.And(sees(ar, model, r, o), z3.Not(sees(ar, model, dr.dest, o)))
    if form == TWO_MOVERS:
        assert s is not None and ds is not None
        if lemma is Lemma.NO_COLLISION:
            return _movers_close(ar, model, r, dr, s, ds)
        return z3.And(sees(ar, model, r, s), z3.Not(sees(ar, model, dr.dest, ds.dest)))
    if form == SEEN:
        others = [p for name, p in bodies.items() if name != "r"]
        right = [z3.Or(same(p, r), z3.Not(sees(ar, model, r, p)), p[0] < dr.dest[0]) for p in others]
        return z3.And(dr.dest[0] > r[0], *right)
    if form == ON_RMA:
        others = [p for name, p in bodies.items() if name != "r"]
        return z3.And(*[p[0] <= r[0] for p in others], dr.dest[0] != r[0])
    if form == X_NONDECREASING:
        return dr.dest[0] < r[0]
    if form == CLOSER:
        assert o is not None
        b = bands(ar, model, o)
        return z3.And(sees(ar, model, r, o), z3.Or(b[Band.B], b[Band.C], b[Band.D]), d2(o, dr.dest) >= d2(o, r))
    raise ValueError(f"unknown form {form}")


def _initial(
    ar: Arith, model: Model, bodies: dict[str, Pt], groups: list[tuple[Pt, dict[str, Pt]]]
) -> list[z3.BoolRef]:
    """The paper's initial condition on the named robots: distinct ones at least delta apart, and a
    connected visibility graph (each witness seen by its decider, each decider reached from r)."""
    delta = Fraction(model.parameters.delta)
    names = list(bodies)
    out: list[z3.BoolRef] = []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            pa, pb = bodies[a], bodies[b]
            out.append(z3.Or(same(pa, pb), ar.cmp2(d2(pa, pb), ">=", delta)))
    reached = [groups[0][0], *groups[0][1].values()]
    for who, roles in groups:
        out += [sees(ar, model, who, p) for p in roles.values()]
        if who is not groups[0][0]:
            mine = [who, *roles.values()]
            out.append(ar.any([sees(ar, model, a, b) for a in mine for b in reached]))
            reached += mine
    if "o" in bodies and not any(who is bodies["o"] for who, _ in groups):
        o = bodies["o"]
        out.append(ar.any([sees(ar, model, o, p) for name, p in bodies.items() if name != "o"]))
    return out


__all__ = ["Built", "NotEncoded", "Spec", "build", "capsules_close", "segment_close"]


def argument(model: Model, spec: Spec, built: Built) -> str:
    """The obligation's header: what it claims, the case, and why ``unsat`` covers every swarm size."""
    from ...rules.paper.cases import describe

    lines = [
        f"Obligation: {spec.lemma}, form {spec.form}, r's case {spec.name}"
        + (f", the other robot's cases: {spec.other_name}" if spec.other_name else "")
        + f"; model {model.name}, scheduler {model.options.scheduler}.",
        f"Claim: whenever r decides this case, {spec.claim}.",
    ]
    if spec.repair:
        lines.append(
            f"r's destination is the repaired rule set's own, in place of the case's: {REPAIRS[spec.repair]} "
            "(fatline_verify/rules/repaired/algorithm.py); its conditions are asserted with the case's."
        )
    if len(spec.mine) == 1:
        lines.append("r's case: " + "; ".join(describe(spec.mine[0], model)) + ".")
    else:
        lines.append(
            f"r decides one of {len(spec.mine)} cases of {spec.name}, each with its witnesses and universal "
            "conditions (a disjunction)."
        )
    if spec.form == TWO_MOVERS:
        lines.append(
            f"s: a robot moving in the same round, deciding one of {len(spec.other)} cases of "
            f"{spec.other_name}, "
            "each with its own witnesses and universal conditions."
        )
    if spec.form == ONE_MOVER and spec.other:
        lines.append(f"o stays (fsync: every enabled robot moves): o decides one of {len(spec.other)} staying cases.")
    lines += [
        f"Named robots: {', '.join(built.bodies)} (r at the origin). Two names are one robot iff their centres "
        "are equal; distinct robots are disjoint discs. Universal conditions are asserted for every named robot "
        "the decider sees.",
        "Why unsat covers swarms of every size: in any swarm where the claim fails with r in this case, the robots "
        "playing the named roles (they exist: the case's witnesses, the robot the claim is about) satisfy every "
        "constraint here, because the universal conditions hold for every robot of the swarm. So unsat means no swarm, "
        "of any size, breaks the claim in this case. (Conversely a solution's named robots make the same decisions: "
        "universal conditions hold in every sub-swarm; tests/test_cases.py checks this on random and crowded swarms.)",
        "How unsat may be shown: on the obligation's linearization (every comparison that multiplies two "
        "non-constant terms replaced by a Boolean; where it compares a squared distance with a constant, the "
        "Boolean implies exact linear cuts: tangent lines inside the disc, one of a grid's sector half-planes "
        "outside it), which every solution of the obligation also solves; an unsat linearization is an unsat "
        "obligation.",
        "Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.",
    ]
    return "\n".join(lines)
