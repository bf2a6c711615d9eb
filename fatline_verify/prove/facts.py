"""The facts about the repaired rules' code that their leg obligations rest on, checked on views.

The leg obligations (:mod:`fatline_verify.prove.smt.legs`) prove safety "whatever rule chose the move",
from two facts about ``decide`` that no obligation states (:data:`fatline_verify.prove.rests.LEGS_FACTS`):

- **legs**: every move is one leg (:func:`~fatline_verify.rules.repaired.algorithm.leg_of`: horizontal
  right, top, bottom) whose conditions hold for every robot the mover sees
  (:func:`~fatline_verify.prove.smt.legs.conditions`), each edge kept or bridged by a robot it sees
  (:func:`~fatline_verify.prove.smt.legs.kept`, :func:`~fatline_verify.prove.smt.legs.bridged`);
- **lock**: a robot that sees a robot strictly left of it stays (the bridge robot ``b``, which sees the
  mover strictly left of it, is at rest).

Both read only what one robot sees, so they are facts about ``decide`` on a *view*
(:func:`fatline_verify.prove.views.all_views`: every input ``decide`` can get on the model's lattice).
:func:`check_facts` checks them on every view (exhaustive at q = 1: the slow tier) or on a sample.
The z3 terms of the leg conditions are evaluated on the view's numbers (``z3.simplify`` of ground terms).
"""

from __future__ import annotations

import time
from collections.abc import Iterable
from dataclasses import dataclass, field
from fractions import Fraction

import z3

from ..model.config import Model
from ..model.numbers import show_point
from ..rules import registry
from ..rules.decision import Decision
from ..rules.repaired.algorithm import Leg, leg_of
from .smt.cases import Arith, Pt
from .smt.legs import Mover, bridged, conditions, kept
from .views import View, all_views, random_views

SHOWN = 5
"""Counterexamples kept per fact (the first ones, in enumeration order)."""


@dataclass
class FactCheck:
    """What :func:`check_facts` found: views checked, views where ``decide`` moved, and the views that
    break each fact (each with why)."""

    views: int = 0
    moving: int = 0
    seconds: float = 0.0
    broken: dict[str, list[str]] = field(default_factory=lambda: {"legs": [], "lock": []})
    counts: dict[str, int] = field(default_factory=lambda: {"legs": 0, "lock": 0})

    @property
    def holds(self) -> bool:
        return not any(self.counts.values())

    def text(self) -> str:
        what = f"{self.views:,} views, {self.moving:,} with a move, {self.seconds:.1f} s"
        if self.holds:
            return f"legs and lock hold on {what}"
        bad = "; ".join(f"{name}: {n:,} views, first {self.broken[name][0]}" for name, n in self.counts.items() if n)
        return f"{bad} ({what})"


def _pt(ar: Arith, model: Model, p: tuple[int, int]) -> Pt:
    x, y = model.from_lattice(p)
    return (ar.num(Fraction(x)), ar.num(Fraction(y)))


def _true(e: z3.BoolRef) -> bool:
    value = z3.simplify(e)
    if not (z3.is_true(value) or z3.is_false(value)):  # pragma: no cover - ground terms always simplify
        raise ValueError(f"not a ground truth value: {value}")
    return z3.is_true(value)


def _shown(view: View, model: Model) -> str:
    return "{" + ", ".join(show_point(model.from_lattice(p)) for p in view) + "}"


def leg_problem(model: Model, view: View, d: Decision, ar: Arith | None = None) -> str | None:
    """Why the move ``d`` (``decide`` on ``view``) is not a leg the obligations cover, or ``None`` (no move,
    or a leg whose conditions hold for every robot of the view, each edge kept or bridged)."""
    if not d.moves:
        return None
    ar = ar or Arith(None)
    dx, dy = d.destination
    leg = leg_of(d.destination, view)
    if max(abs(dx), abs(dy)) > model.radius:
        return f"{d.rule} moves {d.destination}, longer than one radius"
    if leg is Leg.HORIZONTAL and not dx > 0:
        return f"{d.rule} moves {d.destination}: a horizontal leg not to the right"
    if leg is not Leg.HORIZONTAL and (dx != 0 or dy == 0):
        return f"{d.rule} moves {d.destination}: not along one axis"
    if leg is Leg.BOTTOM and not dy > 0:
        return f"{d.rule} moves {d.destination}: a bottom leg not upward"
    if leg not in (Leg.HORIZONTAL, Leg.TOP, Leg.BOTTOM):
        return f"{d.rule} moves {d.destination}: a {leg} leg, which no obligation covers"
    m = Mover(_pt(ar, model, (0, 0)), _pt(ar, model, (dx, dy)), leg)  # type: ignore[arg-type]
    points = {c: _pt(ar, model, c) for c in view}
    for c, cz in points.items():
        if not _true(conditions(ar, model, m, cz)):
            return f"{d.rule} moves {d.destination} ({leg}): a condition fails for the robot at {c}"
        if _true(kept(ar, model, m, cz)):
            continue
        if not any(b != c and _true(bridged(ar, model, m, cz, bz)) for b, bz in points.items()):
            return f"{d.rule} moves {d.destination} ({leg}): the edge to {c} is neither kept nor bridged"
    return None


def lock_problem(view: View, d: Decision) -> str | None:
    """Why the decision ``d`` on ``view`` breaks the lock (a robot strictly left is seen, yet it moves), or ``None``."""
    if not d.moves or not any(x < 0 for x, _ in view):
        return None
    return f"{d.rule} moves {d.destination} though it sees a robot strictly left"


def check_facts(model: Model, views: Iterable[View] | None = None) -> FactCheck:
    """The legs and lock facts on ``views`` (default: every view on ``model``'s lattice)."""
    out = FactCheck()
    ar = Arith(None)
    started = time.perf_counter()
    for view in all_views(model) if views is None else views:
        out.views += 1
        d = registry.decide(view, model)
        out.moving += bool(d.moves)
        for name, problem in (("lock", lock_problem(view, d)), ("legs", leg_problem(model, view, d, ar))):
            if problem is None:
                continue
            out.counts[name] += 1
            if len(out.broken[name]) < SHOWN:
                out.broken[name].append(f"{_shown(view, model)}: {problem}")
    out.seconds = time.perf_counter() - started
    return out


def sampled_facts(model: Model, n: int = 2000, seed: int = 0) -> FactCheck:
    """:func:`check_facts` on ``n`` random views (the default test tier)."""
    return check_facts(model, random_views(model, n, seed))


__all__ = ["FactCheck", "check_facts", "leg_problem", "lock_problem", "sampled_facts"]
