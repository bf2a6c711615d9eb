"""This package's goals, registered on import: the paper's three readings of "form a straight line"
(the ``goal`` option's readings) and the goals of other published algorithms (gathering at a point,
near-gathering / epsilon-convergence, a circle, fat robots' gathering: discs that touch and hold
together). What each means exactly is its ``says``; docs/plugins.md lists them ("Goals").

Lengths a goal takes as parameters (``eps``, ``radius``) are whole **lattice units**, as everything a
rule set's ``decide`` sees (one robot radius is ``q`` of them): exact on the lattice the search explores.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..model.geometry import collinear, width_at_most
from ..model.options import Goal as Reading
from ..model.seams import Param
from .registry import KERNELS, Goal, register_goal
from .shapes import (
    at_one_point,
    at_one_point_batch,
    discs_connected,
    discs_connected_batch,
    in_disc,
    in_disc_batch,
    on_circle,
    on_circle_batch,
)

Point = tuple[Any, Any]


def _line_batch(reading: Reading) -> Any:
    """The lattice's vectorised line test for ``reading`` (positions in ``1/unit`` lattice units)."""

    def positions(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
        from ..model.lattice import goal_positions

        return goal_positions(pos, reading, 2 * model.radius * unit)

    positions.__name__ = positions.__qualname__ = f"{reading.name.lower()}_positions"
    return positions


def _vertical(state: Sequence[Point], model: Any) -> bool:
    return len({p[0] for p in state}) <= 1


def _any_line(state: Sequence[Point], model: Any) -> bool:
    return collinear(state)


def _meets_discs(state: Sequence[Point], model: Any) -> bool:
    return width_at_most(state, 2 * model.radius)


def _line(reading: Reading, says: str, exact: Any) -> Goal:
    """Register one of the paper's readings of "form a straight line", with its compiled kernel."""
    return register_goal(
        Goal(reading.value, says, exact, _line_batch(reading), kernel=KERNELS[reading.value], scaled=True)
    )


VERTICAL_LINE = _line(
    Reading.VERTICAL_LINE,
    "every centre has the same x (the paper's proof puts every robot on the right-most vertical)",
    _vertical,
)
ANY_LINE = _line(
    Reading.ANY_LINE, "every centre is on one straight line, of any direction (two centres always are)", _any_line
)
LINE_MEETS_DISCS = _line(
    Reading.LINE_MEETS_DISCS,
    "some straight line meets every disc: the centres lie in a strip of width 2 radii",
    _meets_discs,
)


def _point(state: Sequence[Point], model: Any) -> bool:
    return at_one_point(state)


def _point_batch(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
    return at_one_point_batch(pos)


POINT = register_goal(
    Goal(
        "point",
        "exact gathering: every robot at one and the same point (point robots only: discs there would overlap)",
        _point,
        _point_batch,
        kernel=KERNELS["point"],
        robots=("points",),
        scaled=True,
    )
)


def _sized(name: str, says: str, key: str, param: Param, exact: Any, batch: Any) -> Goal:
    """Register a goal whose shape test takes one length, the goal's parameter ``key`` (lattice units):
    ``exact(points, length)`` and ``batch(pos, length)`` (positions in ``1/unit`` lattice units, the
    length scaled alike)."""

    def holds(state: Sequence[Point], model: Any) -> bool:
        return bool(exact(state, model.setting("goal")[key]))

    def positions(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
        return batch(pos, int(model.setting("goal")[key]) * unit)  # type: ignore[no-any-return]

    return register_goal(Goal(name, says, holds, positions, parameters={key: param}, scaled=True))


EPS = Param(2, "the diameter of the disc every robot must be in, in lattice units (a robot radius is q)", minimum=0)
"""The parameter of the near-gathering goals."""

NEAR = (
    "every centre in one closed disc of diameter eps ([goal] eps, lattice units): the smallest enclosing "
    "circle has diameter at most eps"
)
NEAR_GATHERING = _sized("near-gathering", NEAR, "eps", EPS, in_disc, in_disc_batch)
EPS_CONVERGENCE = _sized(
    "eps-convergence",
    NEAR + "; a finite search decides whether every fair run reaches such a state, not convergence in the "
    "limit (docs/plugins.md, Goals)",
    "eps",
    EPS,
    in_disc,
    in_disc_batch,
)

RADIUS = Param(0, "the circle's radius in lattice units (a robot radius is q); 0: a circle of any radius", minimum=0)
"""The parameter of the circle goal."""

CIRCLE = _sized(
    "circle",
    "every centre on the circumference of one circle, of radius [goal] radius (lattice units; 0, the "
    "default: any radius): two distinct centres always are, three or more when not collinear and "
    "concyclic (the four-point determinant, in integers)",
    "radius",
    RADIUS,
    on_circle,
    on_circle_batch,
)


def _touching(state: Sequence[Point], model: Any) -> bool:
    return discs_connected(state, model.contact2)


def _touching_batch(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
    return discs_connected_batch(pos, model.contact2 * unit * unit)


TOUCHING = register_goal(
    Goal(
        "touching",
        "gathering of fat robots: the union of the discs is connected, i.e. the graph joining two robots whose "
        "discs touch (centres at most 2 radii apart) is connected, so every robot touches another (Czyzowicz, "
        "Gasieniec, Pelc 2009; Agathangelou, Georgiou, Mavronicolas 2013; discs only)",
        _touching,
        _touching_batch,
        robots=("discs",),
        scaled=True,
    )
)
"""Fat robots' gathering, as the fat-robot gathering papers define it: Czyzowicz, Gasieniec and Pelc,
"Gathering few fat mobile robots in the plane" (Theoretical Computer Science 410, 2009), abstract:
"Gathering such robots means forming a configuration for which the union of all discs representing them
is connected"; Agathangelou, Georgiou and Mavronicolas, "A distributed algorithm for gathering many fat
mobile robots in the plane" (PODC 2013; arXiv:1209.3904), abstract, condition (c): "The configuration is
connected, that is, every robot touches another robot and all robots together form a connected
formation" (their conditions (a), a convex hull with every robot on it, and (b), every robot seeing every
other past the discs in between, are theirs alone and not part of this goal). Closed discs of one radius
touch when their centres are at most 2 radii apart: ``model.contact2``, compared squared."""

__all__ = [
    "ANY_LINE",
    "CIRCLE",
    "EPS_CONVERGENCE",
    "LINE_MEETS_DISCS",
    "NEAR_GATHERING",
    "POINT",
    "TOUCHING",
    "VERTICAL_LINE",
]
