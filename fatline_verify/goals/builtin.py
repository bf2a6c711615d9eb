"""This package's goals, registered on import: the paper's three readings of "form a straight line"
(the ``goal`` option's readings) and the goals of other published algorithms (gathering at a point,
near-gathering / epsilon-convergence, a circle). What each means exactly is its ``says``; docs/plugins.md
lists them ("Goals").

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
from .registry import Goal, register_goal
from .shapes import at_one_point, at_one_point_batch, in_disc, in_disc_batch, on_circle, on_circle_batch

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


VERTICAL_LINE = register_goal(
    Goal(
        Reading.VERTICAL_LINE.value,
        "every centre has the same x (the paper's proof puts every robot on the right-most vertical)",
        _vertical,
        _line_batch(Reading.VERTICAL_LINE),
        kernel=0,
        scaled=True,
    )
)
ANY_LINE = register_goal(
    Goal(
        Reading.ANY_LINE.value,
        "every centre is on one straight line, of any direction (two centres always are)",
        _any_line,
        _line_batch(Reading.ANY_LINE),
        kernel=1,
        scaled=True,
    )
)
LINE_MEETS_DISCS = register_goal(
    Goal(
        Reading.LINE_MEETS_DISCS.value,
        "some straight line meets every disc: the centres lie in a strip of width 2 radii",
        _meets_discs,
        _line_batch(Reading.LINE_MEETS_DISCS),
        kernel=2,
        scaled=True,
    )
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
        kernel=3,
        robots=("points",),
        scaled=True,
    )
)

EPS = {
    "eps": Param(
        2, "the diameter of the disc every robot must be in, in lattice units (a robot radius is q)", minimum=0
    )
}
"""The parameter of the near-gathering goals."""


def _near(state: Sequence[Point], model: Any) -> bool:
    return in_disc(state, model.setting("goal")["eps"])


def _near_batch(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
    return in_disc_batch(pos, int(model.setting("goal")["eps"]) * unit)


NEAR = (
    "every centre in one closed disc of diameter eps ([goal] eps, lattice units): the smallest enclosing "
    "circle has diameter at most eps"
)
NEAR_GATHERING = register_goal(Goal("near-gathering", NEAR, _near, _near_batch, parameters=EPS, scaled=True))
EPS_CONVERGENCE = register_goal(
    Goal(
        "eps-convergence",
        NEAR + "; a finite search decides whether every fair run reaches such a state, not convergence in the "
        "limit (docs/plugins.md, Goals)",
        _near,
        _near_batch,
        parameters=EPS,
        scaled=True,
    )
)

RADIUS = {
    "radius": Param(
        0, "the circle's radius in lattice units (a robot radius is q); 0: a circle of any radius", minimum=0
    )
}
"""The parameter of the circle goal."""


def _circle(state: Sequence[Point], model: Any) -> bool:
    return on_circle(state, model.setting("goal")["radius"])


def _circle_batch(pos: np.ndarray, model: Any, unit: int = 1) -> np.ndarray:
    return on_circle_batch(pos, int(model.setting("goal")["radius"]) * unit)


CIRCLE = register_goal(
    Goal(
        "circle",
        "every centre on the circumference of one circle, of radius [goal] radius (lattice units; 0, the "
        "default: any radius): two distinct centres always are, three or more when not collinear and "
        "concyclic (the four-point determinant, in integers)",
        _circle,
        _circle_batch,
        parameters=RADIUS,
        scaled=True,
    )
)

__all__ = [
    "ANY_LINE",
    "CIRCLE",
    "EPS_CONVERGENCE",
    "LINE_MEETS_DISCS",
    "NEAR_GATHERING",
    "POINT",
    "VERTICAL_LINE",
]
