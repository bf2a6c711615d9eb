"""The repaired rule set's obligations: every move is a *leg*, whatever rule chose it.

With ``repair_lock``, ``repair_step``, ``repair_clear`` and ``repair_edges`` on
(:mod:`fatline_verify.rules.repaired.algorithm`), a robot m that moves makes one leg that ``repairs.allowed``
passed, of one of three classes (:class:`~fatline_verify.rules.repaired.algorithm.Leg`,
:func:`~fatline_verify.rules.repaired.algorithm.leg_of`):

- ``horizontal``: to ``(dx, 0)``, ``0 < dx <= 1`` (:data:`RIGHTWARD`);
- ``top``: to ``(0, dy)``, ``0 < |dy| <= 1``, m seeing no robot above it on its vertical;
- ``bottom``: to ``(0, dy)``, ``0 < dy <= 1``, m seeing none below it on its vertical and ending at
  least 3 below each robot above it there (the bottom's contraction).

For every robot c that m sees, ``allowed`` says: c is not strictly left of m (the lock); c's disc
does not meet m's swept disc (``repair_clear``); and m's edge to c is **kept** (m ends within view
of c, and of c one radius right when m moves vertically and c is on its vertical), or **bridged** by
a robot b right of m that m sees, that sees m's end, and that sees c wherever c's move may take it
(``repairs._anywhere``). These are universal conditions over the robots m sees, so they hold for
whichever robots an obligation names. A robot b of a bridge sees m (visibility is symmetric) strictly
left of it: the lock holds b at rest.

The obligations (:data:`FORMS`), r a mover at the origin, its leg of one class, the other robot o at
rest or moving by a leg of one class, each mover's conditions asserted for every named robot:

- ``no-collision/leg``: r and o come within 2 during the round (r's swept disc against o at rest;
  two movers per ``timing``).
- ``connectivity/kept``: r sees o, each mover's test for the other passed by *kept*, and r and o do
  not see each other after the round.
- ``connectivity/bridged``: r sees o, r's test for o passed through b, and r-b or b-o is not an
  edge after the round (b at rest).

Why ``unsat`` covers every swarm size (each obligation's header says it): a collision in any round
is between a mover r and another robot, at rest or moving: its ``leg`` obligation names the two. An
edge r-c of the graph before the round with a mover at one end: if a mover's test for the other was
bridged through some b, name that mover r: its ``bridged`` obligation names r, c, b and says r-b and
b-c are edges after; otherwise each mover kept it, and its ``kept`` obligation says r-c is an edge
after. So every edge before is a path of at most two edges after, and a connected swarm stays
connected. The move classes and every asserted condition are checked against the repaired rules'
own decisions on random swarms (``tests/test_legs.py``).
"""

from __future__ import annotations

from dataclasses import dataclass

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Timing
from ...rules.repaired.algorithm import CORNERS, Leg
from ...rules.repaired.options import RepairClear, RepairEdges, RepairLock, RepairStep
from .cases import Arith, Pt, apart, sees
from .claims import Built, capsules_close, segment_close

RIGHTWARD = (
    "a horizontal leg goes right: it is one radius or less toward the paper's destination, whose x never "
    "decreases (the approach obligations of the same run: x-nondecreasing for every case of the paper's rules "
    "under these readings), or toward the repairs' own (repair-align: the greatest x r sees, right of r; "
    "repair-approach: 2 radii short of psi_right, used only if right of r: their x-nondecreasing-repair-* "
    "obligations; repair-detour, when on: toward a destination right of r, or at most to the greatest x r sees)"
)
"""Why the ``horizontal`` class has ``dx > 0``: the one fact the leg obligations take from the rules."""

CLASSES = tuple(leg for leg in Leg if leg not in CORNERS)
"""The leg classes the obligations cover: not the corner legs of ``repair_progress = corner``, which
``fatline prove`` refuses (:func:`fatline_verify.prove.tasks.check_encoded`)."""

REST = "rest"
"""The other robot does not move."""

LEG = "leg"
KEPT = "kept"
BRIDGED = "bridged"

FORMS = {Lemma.NO_COLLISION: (LEG,), Lemma.CONNECTIVITY: (KEPT, BRIDGED)}
"""The forms of each lemma the repaired rule set's obligations take."""

CLAIM = {
    (Lemma.NO_COLLISION, LEG): "r and the other robot o never come within distance 2 during the round",
    (Lemma.CONNECTIVITY, KEPT): "r and o, within view before the round, are within view after it",
    (Lemma.CONNECTIVITY, BRIDGED): "r-b and b-o are edges after the round, b at rest",
}

NEEDED = {
    "repair_lock": RepairLock.LEFT_FIRST,
    "repair_step": RepairStep.UNIT,
    "repair_clear": RepairClear.ON,
    "repair_edges": RepairEdges.ON,
}
"""The repairs the leg obligations rest on (the others only choose destinations)."""


def missing_repairs(model: Model) -> list[str]:
    """The repairs of :data:`NEEDED` the model does not have, as ``name=reading`` to set."""
    return [f"{name}={want}" for name, want in NEEDED.items() if getattr(model.options, name) is not want]


@dataclass(frozen=True, slots=True)
class LegSpec:
    """One obligation of the repaired rule set: a lemma form, r's leg class, the other robot's."""

    lemma: Lemma
    form: str
    mine: Leg
    other: str
    """A :class:`~fatline_verify.rules.repaired.algorithm.Leg` value, or :data:`REST`."""

    @property
    def name(self) -> str:
        return self.mine.value

    @property
    def other_name(self) -> str:
        return self.other

    @property
    def key(self) -> str:
        """``lemma/form-leg.and.other``: how result rows and files name the obligation."""
        return f"{self.lemma}/{self.form}-{self.mine}.and.{self.other}"

    @property
    def claim(self) -> str:
        return CLAIM[(self.lemma, self.form)]


def leg_specs(lemmas: tuple[Lemma, ...]) -> list[LegSpec]:
    """Every leg obligation of ``lemmas``: unordered pairs where the two robots play the same part
    (``leg``, ``kept``), every ordered pair for ``bridged`` (r is the robot whose test bridged)."""
    legs = list(CLASSES)
    specs: list[LegSpec] = []
    for lemma in lemmas:
        for form in FORMS.get(lemma, ()):
            for i, mine in enumerate(legs):
                others = [REST, *(leg.value for leg in (legs if form == BRIDGED else legs[i:]))]
                specs += [LegSpec(lemma, form, mine, other) for other in others]
    return specs


@dataclass(frozen=True)
class Mover:
    """A robot and its leg: start, end, class."""

    at: Pt
    end: Pt
    leg: Leg


def mover(ar: Arith, name: str, leg: Leg, at: Pt) -> tuple[Mover, list[z3.BoolRef]]:
    """A leg of class ``leg`` from ``at``: at most one radius along one axis (a free step variable),
    rightward if horizontal (:data:`RIGHTWARD`)."""
    step = ar.var(f"{name}.step")
    zero, one = ar.num(0), ar.num(1)
    end = (at[0] + step, at[1]) if leg is Leg.HORIZONTAL else (at[0], at[1] + step)
    shape = [step > zero] if leg is not Leg.TOP else [step != zero, step >= -one]
    return Mover(at, end, leg), [*shape, step <= one]


def conditions(ar: Arith, model: Model, m: Mover, c: Pt) -> z3.BoolRef:
    """What ``repairs.allowed`` (and the leg's class) says of a robot ``c`` that ``m`` sees: not
    strictly left of m, clear of m's swept disc, and the class's condition on m's vertical."""
    on_vertical = c[0] == m.at[0]
    facts = [c[0] >= m.at[0], z3.Not(segment_close(ar, model, c, m.at, m.end))]
    if m.leg is Leg.TOP:
        facts.append(z3.Not(z3.And(on_vertical, c[1] > m.at[1])))
    elif m.leg is Leg.BOTTOM:
        facts.append(z3.Implies(on_vertical, z3.And(c[1] > m.at[1], m.end[1] <= c[1] - ar.num(3))))
    return z3.Implies(sees(ar, model, m.at, c), z3.And(*facts))


def _right(ar: Arith, c: Pt) -> Pt:
    return (c[0] + ar.num(1), c[1])


def kept(ar: Arith, model: Model, m: Mover, c: Pt) -> z3.BoolRef:
    """``repairs._edge_kept``'s first test: m ends within view of ``c`` wherever ``repairs._wherever``
    puts it (at rest; also one radius right if m moves vertically and c is on m's vertical)."""
    at_rest = sees(ar, model, m.end, c)
    if m.leg is Leg.HORIZONTAL:
        return at_rest
    return z3.And(at_rest, z3.Implies(c[0] == m.at[0], sees(ar, model, m.end, _right(ar, c))))


def bridged(ar: Arith, model: Model, m: Mover, c: Pt, b: Pt) -> z3.BoolRef:
    """``repairs._edge_kept``'s second test: ``b`` right of m, seen by m, sees m's end and ``c``
    wherever ``repairs._anywhere`` puts it."""
    up, down = (c[0], c[1] + ar.num(1)), (c[0], c[1] - ar.num(1))
    vertical = z3.And(sees(ar, model, b, up), sees(ar, model, b, down))
    anywhere = z3.And(
        sees(ar, model, b, c),
        z3.Implies(c[0] == m.at[0], z3.And(sees(ar, model, b, _right(ar, c)), z3.Implies(c[1] > m.at[1], vertical))),
    )
    return z3.And(b[0] > m.at[0], sees(ar, model, m.at, b), sees(ar, model, m.end, b), anywhere)


def _movers_close(ar: Arith, model: Model, r: Mover, o: Mover) -> z3.BoolRef:
    if model.options.timing is Timing.ANY_SPEED:
        return capsules_close(ar, model, (r.at, r.end), (o.at, o.end))
    d0 = (r.at[0] - o.at[0], r.at[1] - o.at[1])
    d1 = (r.end[0] - o.end[0], r.end[1] - o.end[1])
    return segment_close(ar, model, ar.origin(), d0, d1)


def build(ar: Arith, model: Model, spec: LegSpec, *, vacuity: bool = False, immediate: bool = False) -> Built:
    """The obligation ``spec`` over ``ar``'s domain; ``vacuity`` keeps only "the legs occur together";
    ``immediate`` leaves out each mover's conditions on the robots it sees (``repairs.allowed``), keeping
    the legs' shapes and the form's own test (kept, bridged): unsat means the claim follows from the test
    that let the move be made (:mod:`fatline_verify.prove.basis`)."""
    r, asserts = mover(ar, "r", spec.mine, ar.origin())
    o_at = ar.point("o")
    bodies: dict[str, Pt] = {"r": r.at, "o": o_at}
    movers = [r]
    o_end = o_at
    if spec.other != REST:
        o, more = mover(ar, "o", Leg(spec.other), o_at)
        asserts += more
        movers.append(o)
        o_end = o.end
    if spec.form == BRIDGED:
        bodies["b"] = ar.point("b")
    names = list(bodies)
    for i, a in enumerate(names):
        asserts += [apart(ar, model, bodies[a], bodies[b]) for b in names[i + 1 :]]
    for m in movers if not immediate else ():
        asserts += [conditions(ar, model, m, p) for p in bodies.values() if p is not m.at]
    if spec.form == KEPT:
        asserts += [sees(ar, model, r.at, o_at), kept(ar, model, r, o_at)]
        asserts += [kept(ar, model, m, r.at) for m in movers[1:]]
    if spec.form == BRIDGED:
        asserts += [sees(ar, model, r.at, o_at), bridged(ar, model, r, o_at, bodies["b"])]
    for m in movers:
        bodies[f"{'r' if m is r else 'o'}'"] = m.end
    if not vacuity:
        asserts.append(_violation(ar, model, spec, movers, o_end, bodies.get("b")))
    return Built(ar, asserts, bodies, "o")


def _violation(ar: Arith, model: Model, spec: LegSpec, movers: list[Mover], o_end: Pt, b: Pt | None) -> z3.BoolRef:
    r = movers[0]
    if spec.form == LEG:
        if len(movers) == 1:
            return segment_close(ar, model, o_end, r.at, r.end)
        return _movers_close(ar, model, r, movers[1])
    if spec.form == KEPT:
        return z3.Not(sees(ar, model, r.end, o_end))
    assert b is not None
    return z3.Not(z3.And(sees(ar, model, r.end, b), sees(ar, model, b, o_end)))


def argument(model: Model, spec: LegSpec, built: Built) -> str:
    """The obligation's header: the claim, the legs, and why ``unsat`` covers every swarm size."""
    other = "at rest" if spec.other == REST else f"moving by a {spec.other} leg"
    return "\n".join(
        [
            f"Obligation: {spec.lemma}, form {spec.form}, r's leg {spec.mine}, the other robot o {other}; model "
            f"{model.name} (the repaired rule set), scheduler {model.options.scheduler}, "
            f"timing {model.options.timing}.",
            f"Claim: {spec.claim}.",
            "Legs: horizontal (dx, 0) with 0 < dx <= 1 ("
            + RIGHTWARD
            + "); top (0, dy) with 0 < |dy| <= 1 seeing no robot above on its "
            "vertical; bottom (0, dy) with 0 < dy <= 1 seeing none below on its vertical and ending >= 3 below each "
            "robot above it there. Whatever rule chose the move (fatline_verify/rules/repaired/algorithm.py, leg_of).",
            "Each mover's conditions for every named robot it sees (repairs.allowed): not strictly left of it (the "
            "lock), clear of its swept disc (repair_clear), its leg class's condition on its vertical. kept: the "
            "mover ends within view of the robot (and of it one radius right when the mover is vertical and the robot "
            "on its vertical). bridged: b right of r, seen by r, sees r's end and o wherever o may move; b sees r "
            "strictly left of it, so the lock holds b at rest.",
            f"Named robots: {', '.join(n for n in built.bodies if not n.endswith(chr(39)))} (r at the origin), "
            "pairwise disjoint discs.",
            "Why unsat covers swarms of every size: the conditions asserted are universal over the robots a mover "
            "sees (so they hold for the named ones in any swarm), and every collision, and every edge with a mover "
            "at one end, is an instance of one leg obligation "
            "(the module docstring of fatline_verify/prove/smt/legs.py); "
            "each edge before the round is then a path of at most two edges after it, and the swarm stays connected. "
            "tests/test_legs.py checks the leg classes and each condition on the repaired rules' own decisions.",
            "Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.",
        ]
    )


__all__ = ["FORMS", "LegSpec", "build", "leg_specs", "missing_repairs"]
