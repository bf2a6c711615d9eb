"""Liveness obligations: Lemma 2's enabledness and a ranking measure, one per decision case of a
rule set that declares them (:class:`~fatline_verify.rules.registry.Liveness`).

- ``progress/enabled-CASE``, one per case: a robot ``r`` (at the origin) sees no robot left of it and
  sees a robot ``g`` right of it (``g.x > 0``), and decides ``CASE`` and stays (a staying case; a
  moving case whose destination is r's own centre). The named
  witness is a robot of the swarm's left-most vertical that sees a robot off it: every connected swarm
  that is not a goal (``goal = vertical-line``: not every centre on one vertical) has one (some robot
  is off the left-most vertical, and a path of edges leads to it from that vertical; its first edge
  leaving the vertical starts at such a robot). ``unsat`` for every case means that robot
  moves: in every connected non-goal swarm of any size some robot is enabled.
- ``termination/measure-CASE``, one per *moving* case, on the model's lattice (``x = X / q``): r moves
  (its destination is not its centre) and the mover's own term of the declared lexicographic measure
  (a sum over the robots of ``a * X + b * Y`` per component) does not fall by at least one lattice
  unit. ``unsat`` means every move of the case makes the mover's term fall lexicographically by a unit
  or more.

Why ``unsat`` covers swarms of every size (written in each header): the case's conditions, and the
named robot's (nothing seen to its left; ``g`` seen), are universal over the robots ``r`` sees or name
a witness; any swarm in which the claim fails gives, by its robots playing the roles, a solution.
Names may denote one robot (equal centres); distinct names are disjoint discs (no collision, the
lemma proved on its own). The converse (a solution's robots make the same decision) is what the
executable model's replay decides before anything is called a counterexample.
"""

from __future__ import annotations

from dataclasses import dataclass

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...rules import registry
from ..goals import goal_problem
from .cases import Arith, Pt, apart, same, sees
from .claims import Built
from .live_rules import LiveCase

ENABLED = "enabled"
MEASURE = "measure"

CLAIM = {
    ENABLED: "a robot of the left-most vertical that sees a robot right of it moves (so some robot is enabled)",
    MEASURE: "every move makes the mover's term of the measure fall lexicographically by a lattice unit or more",
}


@dataclass(frozen=True, slots=True)
class LiveSpec:
    """One liveness obligation: its form (:data:`ENABLED` or :data:`MEASURE`) and r's case."""

    lemma: Lemma
    form: str
    case: str

    @property
    def name(self) -> str:
        return self.case

    @property
    def other(self) -> str:
        return ""

    @property
    def key(self) -> str:
        return f"{self.lemma}/{self.form}-{self.case}"

    @property
    def claim(self) -> str:
        return CLAIM[self.form]


def live_specs(model: Model, cases: list[LiveCase], lemmas: tuple[Lemma, ...]) -> list[LiveSpec]:
    """The obligations of ``lemmas`` (progress, termination) for ``cases``, in case order."""
    out: list[LiveSpec] = []
    if Lemma.PROGRESS in lemmas:
        out += [LiveSpec(Lemma.PROGRESS, ENABLED, c.name) for c in cases]
    if Lemma.TERMINATION in lemmas:
        out += [LiveSpec(Lemma.TERMINATION, MEASURE, c.name) for c in cases if c.moves]
    return out


def _named(
    ar: Arith, model: Model, case: LiveCase, extra: tuple[str, ...], initial: bool
) -> tuple[dict[str, Pt], list[z3.BoolRef]]:
    """r at the origin, the case's witnesses and ``extra`` robots; pairwise the same robot or disjoint
    discs (``initial``: or at least ``delta`` apart, the initial condition's pairs)."""
    bodies: dict[str, Pt] = {"r": ar.origin()}
    bodies.update({name: ar.point(f"r.{name}") for name in case.roles})
    bodies.update({name: ar.point(name) for name in extra})
    names = list(bodies)
    out: list[z3.BoolRef] = []
    delta = model.parameters.delta
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            pa, pb = bodies[a], bodies[b]
            far = (
                ar.cmp2((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2, ">=", delta)
                if initial
                else apart(ar, model, pa, pb)
            )
            out.append(z3.Or(same(pa, pb), far))
    return bodies, out


def build_enabled(ar: Arith, model: Model, case: LiveCase, *, initial: bool = False) -> Built:
    """``progress/enabled-CASE``: r sees nothing to its left, sees ``g`` right of it, and stays in ``case``."""
    bodies, asserts = _named(ar, model, case, ("g",), initial)
    r, g = bodies["r"], bodies["g"]
    roles = {n: p for n, p in bodies.items() if n not in ("r", "g")}
    universe = [p for n, p in bodies.items() if n != "r"]
    cs, dest = case.encode(ar, model, r, roles, universe)
    asserts += cs
    if case.moves:  # a moving case stays when its destination is r's own centre
        asserts += [dest[0] == ar.num(0), dest[1] == ar.num(0)]
    asserts += [sees(ar, model, r, g), g[0] > r[0]]
    asserts += [z3.Or(same(p, r), z3.Implies(sees(ar, model, r, p), p[0] >= r[0])) for p in universe]
    return Built(ar, asserts, bodies, "g")


def build_measure(ar: Arith, model: Model, case: LiveCase, *, initial: bool = False) -> Built:
    """``termination/measure-CASE``: r moves in ``case`` and its term of the measure does not fall by a unit."""
    declared = registry.of(model).liveness
    assert declared is not None
    bodies, asserts = _named(ar, model, case, (), initial)
    r = bodies["r"]
    roles = {n: p for n, p in bodies.items() if n != "r"}
    cs, dest = case.encode(ar, model, r, roles, list(roles.values()))
    asserts += cs
    asserts.append(z3.Or(dest[0] != ar.num(0), dest[1] != ar.num(0)))  # a move (a null one is a stay)
    deltas = [a * dest[0] + b * dest[1] for a, b in declared.measure]
    falls = []
    for k, d in enumerate(deltas):
        falls.append(z3.And(*[e == 0 for e in deltas[:k]], d <= z3.IntVal(-1, ar.ctx) if ar.lattice else d <= -1))
    asserts.append(z3.Not(z3.Or(*falls)))
    built = Built(ar, asserts, bodies, "")
    built.bodies["r'"] = (r[0] + dest[0], r[1] + dest[1])
    return built


def header(model: Model, spec: LiveSpec, case: LiveCase, built: Built, *, lattice: int | None) -> str:
    """The obligation's argument: the claim, the named robots, why unsat covers every swarm size."""
    declared = registry.of(model).liveness
    assert declared is not None
    named = ", ".join(n for n in built.bodies if not n.endswith("'"))
    lines = [
        f"Obligation: {spec.lemma}, form {spec.form}, r's case {case.name}; model {model.name} (rule set "
        f"{model.rules}), scheduler {model.options.scheduler}, motion {model.options.motion}.",
        f"Claim: {spec.claim}.",
        f"Named robots: {named} (r at the origin); two names are one robot (equal centres) or disjoint discs.",
    ]
    if spec.form == ENABLED:
        lines += [
            "Negated: r sees no robot left of it (universal over the robots it sees), sees g with g.x > r.x, and "
            f"decides {case.name} and stays" + (" (its destination is its own centre)." if case.moves else "."),
            "Why unsat covers swarms of every size: a connected swarm that is not a goal (not every centre on one "
            "vertical) has a robot r on its left-most vertical seeing a robot g off it (a path of edges leads from "
            "that vertical to a robot off it; take its first edge that leaves it). Nothing r sees is left of it. If "
            "r stayed in this case, its witnesses and g would be a solution (the case's other conditions are "
            "universal over the robots r sees). Unsat for every case: r moves, so some robot is enabled, "
            "in every connected non-goal swarm of any size (connectivity is its own lemma).",
            "Over the reals (one radius = 1).",
        ]
    else:
        lines += [
            f"Measure: {declared.words}; components (a, b) per robot a*X + b*Y: {list(declared.measure)}.",
            "Negated: r moves in this case (its destination is not its centre) and its own term does not fall "
            "lexicographically by at least one lattice unit.",
            f"On the model's lattice q = {lattice} (integer coordinates, one radius = q): a fall is at least one "
            "lattice unit (the fixed epsilon).",
            "Why unsat covers swarms of every size: the case's conditions are universal over the robots r sees "
            "or name a witness, and r's term depends on r's own move only. Any set of movers the scheduler "
            "allows (one: centralized; any non-empty set: ssync; every enabled robot: fsync) changes the sum by "
            "the sum of the movers' falls, and the lexicographic order of integer vectors is compatible with "
            "addition, so every round with a mover makes the measure fall by a unit or more (rigid moves: each "
            "mover reaches its destination).",
            f"Bounded below: {declared.bounded}.",
            "Termination for every n, with a fair scheduler: every enabledness obligation PROVED (a non-goal "
            "connected swarm has an enabled robot, which stays enabled until it moves, since nothing moves before), "
            "every measure obligation PROVED, the bound argued, and connectivity and no-collision PROVED.",
        ]
    lines.append("Assumptions: exact arithmetic; unit discs; one shared snapshot per round.")
    return "\n".join(lines)


__all__ = [
    "CLAIM",
    "ENABLED",
    "MEASURE",
    "LiveSpec",
    "build_enabled",
    "build_measure",
    "goal_problem",
    "header",
    "live_specs",
]
