"""Point robots and goals of one's own, written as a user might (``tests/plugins/test_goals_plugin.py``):

- ``step-to-corner``: point robots (``robots="points"``) that gather (``goal="point"``): a robot steps one
  lattice unit in x and in y (a king's move) toward the left-most, then lowest, robot it sees, itself
  included; it stays when that is itself. Every move goes left, or down on its vertical, and never past
  its target, so no run is infinite; whether the swarm stays connected is for the checker to say.
- ``same-row``: a goal with an exact check only (no vectorised one): every robot on one horizontal line.
  The packed engines judge it by that check, state by state, and say so in one line.
- ``row-band``: a goal with a parameter and a vectorised check: every robot's y within ``height`` lattice
  units of the lowest's (``[goal] height``, default 1).

Registered by the entry point ``gather = gather_fatline_plugin`` (``fatline.plugins``).
"""

import numpy as np

from fatline_verify.goals import Goal, register_goal
from fatline_verify.model.seams import Param
from fatline_verify.rules.decision import Decision
from fatline_verify.rules.registry import RuleSet, register


def _sign(v):
    return (v > 0) - (v < 0)


def step_to_corner(snapshot, model):
    """One king's step toward the left-most lowest robot seen (itself included), or stay."""
    tx, ty = min([(0, 0), *snapshot])
    if (tx, ty) == (0, 0):
        return Decision("corner", (0, 0), ((0, 0),), ())
    step = (_sign(tx), _sign(ty))
    return Decision("step", step, ((0, 0), step), ())


LABELS = {"step": "a king's step toward the left-most lowest robot seen", "corner": "it is that robot"}

for name, goal, summary in (
    ("step-to-corner", "point", "Point robots: one lattice step toward the left-most lowest robot seen."),
    ("step-to-corner-row", "same-row", "step-to-corner judged against the goal same-row (the plug-in's)."),
):
    register(
        RuleSet(
            name,
            step_to_corner,
            summary,
            lemmas=("connectivity", "progress", "termination"),
            goal=goal,
            robots="points",
            labels=LABELS,
        )
    )


def same_row(state, model):
    """Every robot on one horizontal line (exact: the y coordinates are equal)."""
    return len({y for _, y in state}) <= 1


register_goal(Goal("same-row", "every robot on one horizontal line", same_row))


def row_band(state, model):
    """Every robot's y within ``height`` of the lowest's."""
    ys = [y for _, y in state]
    return max(ys) - min(ys) <= model.setting("goal")["height"]


def row_band_positions(pos, model):
    """:func:`row_band` per state of an ``(m, n, 2)`` integer array."""
    y = pos[..., 1]
    return np.asarray(y.max(axis=1) - y.min(axis=1) <= model.setting("goal")["height"])


register_goal(
    Goal(
        "row-band",
        "every robot's y within [goal] height of the lowest's",
        row_band,
        row_band_positions,
        parameters={"height": Param(1, "how far above the lowest robot the others may be", minimum=0)},
    )
)
