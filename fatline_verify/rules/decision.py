"""What Compute returns, for every rule set: a :class:`Decision`, relative to the deciding robot.

Neutral ground between the rule sets and everything that runs them (schedulers, traces, synthesis,
plug-ins): a decision is a label, a destination and the path to it, all relative to the robot, which
sits at :data:`ORIGIN`, in lattice units. The paper's rule set annotates its decisions with the bands
and the search that led to them (``classification``, ``psi``, ``candidates``, ``case``); any other rule
set leaves them empty.
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, field
from typing import Any

from ..model.geometry import Path
from ..model.numbers import Number, Point

ORIGIN: Point = (0, 0)
"""The deciding robot's own position in its snapshot."""


@dataclass(frozen=True, slots=True)
class Decision:
    """The outcome of Compute for one robot, relative to that robot (it sits at the origin).

    ``rule`` is a label (the paper's :class:`~fatline_verify.rules.paper.algorithm.Rule`, or any string a
    rule set of one's own chooses), shown in traces and pictures; ``destination`` is where the robot goes
    (``(0, 0)`` is a stay); ``path`` is the polyline it moves along from the origin to the destination:
    collisions are judged along it."""

    rule: Hashable
    destination: Point
    path: Path
    classification: tuple[tuple[Point, frozenset[Any]], ...] = field(default=(), repr=False)
    """The paper's bands of each robot seen (empty for a rule set without bands)."""
    psi: Number | None = None
    """The paper's psi_right, when its search ran."""
    r_psi: tuple[Point, ...] = field(default=(), repr=False)
    candidates: tuple[Any, ...] = field(default=(), repr=False)
    """The paper's vacancy search: each point it tried."""
    case: Any = None
    """The paper's case (Scenario 2, 3 or uncovered) whose search found nothing, when Scenario 4 or a stay followed."""

    @property
    def moves(self) -> bool:
        """Whether the destination differs from the current position (the robot is *enabled*)."""
        return self.destination != ORIGIN

    def members(self, band: Any) -> tuple[Point, ...]:
        """The visible robots the paper's rules put in ``band``."""
        return tuple(c for c, m in self.classification if band in m)


def stay(rule: Hashable) -> Decision:
    """A decision to stay, labelled ``rule``."""
    return Decision(rule, ORIGIN, (ORIGIN,))


def step(rule: Hashable, end: Point) -> Decision:
    """A straight move to ``end`` (relative), labelled ``rule``."""
    return Decision(rule, end, (ORIGIN, end))


__all__ = ["ORIGIN", "Decision", "stay", "step"]
