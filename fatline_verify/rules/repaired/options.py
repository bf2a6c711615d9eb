"""The repairs' options: changes to the paper's algorithm (:mod:`fatline_verify.rules.repaired.algorithm`), not readings
of its text. Each is ``off`` by default and left out of a model's data at ``off``, so the paper's
models keep their fingerprints. The repaired rule set declares them (:mod:`.rule_set`), and so
:data:`fatline_verify.model.options.CATALOGUE` lists them after the paper's open points."""

from __future__ import annotations

from enum import StrEnum
from typing import Any

from ...model.option_spec import OptionSpec
from ...model.option_spec import spec as _spec


def _repair(*args: Any, **kwargs: Any) -> OptionSpec:
    """A repair's catalogue entry."""
    return _spec(*args, **kwargs, repair=True)


class RepairLock(StrEnum):
    """Repair: which robots may move in the same round."""

    OFF = "off"
    LEFT_FIRST = "left-first"


class RepairStack(StrEnum):
    """Repair: what a robot that sees only A u I does."""

    OFF = "off"
    ALIGN = "align"


class RepairApproach(StrEnum):
    """Repair: what a robot does instead of Scenario 4's drop while psi_right is far."""

    OFF = "off"
    ON = "on"


class RepairStep(StrEnum):
    """Repair: how far a robot moves in one round."""

    OFF = "off"
    UNIT = "unit"


class RepairClear(StrEnum):
    """Repair: whether a move must keep clear of every robot r sees."""

    OFF = "off"
    ON = "on"


class RepairEdges(StrEnum):
    """Repair: whether a move must keep every robot r sees in view."""

    OFF = "off"
    ON = "on"


class RepairProgress(StrEnum):
    """Repair: what an unlocked robot does when every leg toward its destination is refused."""

    OFF = "off"
    DETOUR = "detour"
    CORNER = "corner"


REPAIR_SPECS: list[OptionSpec] = [
    _repair(
        "repair_lock",
        RepairLock,
        "(a repair, not the paper's) semi-synchronous scheduling where an arbitrary set of robots look, "
        "compute and move simultaneously",
        {
            "off": "the paper: every robot that decides to move may move in the same round",
            "left-first": "r moves only if it sees no robot strictly left of it, and vertically only if it sees "
            "none above it on its own vertical: two movers that see each other share a vertical, and only the "
            "upper one may move vertically",
        },
        note="removes: two movers colliding or losing their edge in one round",
    ),
    _repair(
        "repair_stack",
        RepairStack,
        "(a repair, not the paper's) If B u C u D u E u F u G is empty and A u I is not empty, r does not move",
        {
            "off": "the paper: r stays, though the A and I bands (|x| < 2 under bands=disc) hold robots right "
            "of r's vertical",
            "align": "r moves horizontally to the greatest x of the robots it sees (all in A u I), so the "
            "stack ends on one vertical; a robot on top of a vertical whose moves are all refused moves one "
            "radius down toward the robot below it",
        },
        note="removes: a deadlock of robots in each other's A/I bands but not on one vertical",
    ),
    _repair(
        "repair_approach",
        RepairApproach,
        "(a repair, not the paper's) If there is no vacant point ..., then r moves towards either -Y axis",
        {
            "off": "the paper: Scenario 4 drops r down its vertical",
            "on": "while psi_right is more than 2 radii right of r, r moves right to x_psi - 2 instead of dropping",
        },
        note="removes: Scenario 4's drop taking r out of the swarm's view when the line is forming to its right",
    ),
    _repair(
        "repair_step",
        RepairStep,
        "(a repair, not the paper's) its horizontal movement must be followed by a vertical movement",
        {
            "off": "the paper: r moves to its destination in one round",
            "unit": "r moves at most one radius a round along one axis: horizontally toward its destination "
            "(or vertically first under path=vertical-then-horizontal), else along the other axis if that "
            "leg is refused",
        },
        note="removes: a move whose path meets a robot r cannot see, and far movers meeting",
    ),
    _repair(
        "repair_clear",
        RepairClear,
        "(a repair, not the paper's) A path ... is called free path, if ... is not contained any part of another robot",
        {
            "off": "the paper: vacancy is tested at the destination only",
            "on": "a move is allowed only if no robot r sees comes within 2 of its path (per contact)",
        },
        note="removes: r's path crossing a robot it sees",
    ),
    _repair(
        "repair_edges",
        RepairEdges,
        "(a repair, not the paper's) the robots remain connected (Lemma 1)",
        {
            "off": "the paper: a move may take r out of a neighbour's view",
            "on": "a move is allowed only if it ends within rad_v of every robot r sees, or (with "
            "repair_lock) of a robot right of r, held by the lock, that sees that robot wherever it may move",
        },
        note="removes: r walking out of a neighbour's view",
    ),
    _repair(
        "repair_progress",
        RepairProgress,
        "(a repair, not the paper's) there exists always a robot which will move unless all the robots are "
        "on a straight line",
        {
            "off": "a robot whose every leg toward its destination is refused stays",
            "detour": "(with repair_lock, repair_step, repair_clear, repair_edges) an unlocked robot whose every "
            "leg toward its destination is refused tries, in a fixed order, other legs of the same three classes: "
            "right (at most to the greatest x it sees), along its vertical toward the nearest height from which "
            "right would pass, toward its destination, the top's contraction, up, then down",
            "corner": "detour, then a corner leg (one radius right and one vertically at once): the top of a "
            "vertical with a robot below it right and down, the bottom right and up, ending 3 below each robot "
            "above; each robot r sees on its vertical may also be on a corner leg",
        },
        note="removes: a deadlock where the one unlocked robot's legs toward its destination are all refused "
        "(detour); the square of side rad_v, where every one-axis leg loses an edge (corner)",
    ),
]
"""The catalogue entries of the repairs, in the order ``fatline explain`` lists them."""
