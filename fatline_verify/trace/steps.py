"""One step of a run as trace JSON: a round or an asynchronous event, each decision and violation.

The transition systems write their steps through these (``step_to_json``); the trace document
around them is :mod:`fatline_verify.trace.traces`. Numbers are exact (``"p/q"`` strings), in radii.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..model.config import Model
from ..model.numbers import Number, Point, format_number
from ..model.swarm import State
from ..rules.decision import Decision
from ..schedulers.round import Collision, Disconnection, RmaMoved, RoundResult, Violation


def _point(model: Model, p: Point) -> list[int | str]:
    x, y = model.from_lattice(p)
    return [format_number(x), format_number(y)]


def _area(model: Model, d2: Number) -> int | str:
    """A squared lattice distance in squared radii."""
    return format_number(Fraction(d2) / (model.radius * model.radius))


def violation_to_json(v: Violation, model: Model, after: State) -> dict[str, Any]:
    """One violation with its measured quantity, in radius units."""
    if isinstance(v, Collision):
        return {
            "property": v.lemma.value,
            "robots": list(v.robots),
            "closest_distance2": _area(model, v.closest_dist2),
            "both_moved": v.both_moved,
        }
    if isinstance(v, Disconnection):
        robots = sorted({i for e in v.lost_edges for i in e})
        d2 = [
            _area(model, (after[i][0] - after[j][0]) ** 2 + (after[i][1] - after[j][1]) ** 2) for i, j in v.lost_edges
        ]
        return {
            "property": v.lemma.value,
            "robots": robots,
            "components": [list(c) for c in v.components],
            "lost_edges": [list(e) for e in v.lost_edges],
            "distance2_after": d2,
        }
    assert isinstance(v, RmaMoved)
    return {
        "property": v.lemma.value,
        "robots": [v.robot],
        "rma_x": format_number(Fraction(v.rma_x) / model.radius),
        "x_after": format_number(Fraction(v.x_after) / model.radius),
    }


def decision_to_json(i: int, d: Decision, origin: Point, model: Model) -> dict[str, Any]:
    """Robot ``i``'s decision, taken at ``origin``: rule, case, psi_right and destination (global)."""
    ox, oy = origin
    dest = (ox + d.destination[0], oy + d.destination[1])
    return {
        "robot": i,
        "rule": str(d.rule),
        "case": str(d.case) if d.case else None,
        "psi": None if d.psi is None else format_number(Fraction(ox + d.psi) / model.radius),
        "destination": _point(model, dest),
    }


def round_to_json(r: RoundResult, model: Model) -> dict[str, Any]:
    """One round: active set, each active robot's decision, positions after, violations."""
    return {
        "active": list(r.active),
        "decisions": [decision_to_json(i, r.decisions[i], r.before[i], model) for i in r.active],
        "positions": [_point(model, p) for p in r.after],
        "violations": [violation_to_json(v, model, r.after) for v in r.violations],
    }


def event_to_json(e: Any, system: Any) -> dict[str, Any]:
    """One asynchronous event (an :class:`~fatline_verify.schedulers.asynchronous.EventResult`): which robot did
    what, its decision when it looked, positions after, every robot still moving (path, steps done,
    and the positions it decided on), violations."""
    model = system.model
    i = e.event.robot
    moving = [
        {
            "robot": j,
            "path": [_point(model, p) for p in r.path],
            "step": r.k,
            "of": system.K,
            "seen": None if r.seen is None else [_point(model, p) for p in r.seen],
        }
        for j, r in enumerate(e.target)
        if r.moving
    ]
    return {
        "event": e.event.kind.value,
        "robot": i,
        "active": [i],
        "decisions": [decision_to_json(i, d, e.before[i], model) for i, d in e.decisions.items()],
        "positions": [_point(model, p) for p in e.after],
        "moving": moving,
        "violations": [violation_to_json(v, model, e.after) for v in e.violations],
    }
