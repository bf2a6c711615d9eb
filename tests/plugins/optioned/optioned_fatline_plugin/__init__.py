"""A rule set with an option of its own: a robot steps one radius toward a robot it sees at least three
radii away, right or left as the option ``turn`` reads, when nothing comes within two radii of its path.

Its text ("each robot moves towards its far neighbour") leaves open which way; the option names both
readings. A model file sets it (``[options] turn = "left"``), ``fatline explain`` lists it, ``fatline
sweep`` takes a model through its readings, and a trace records it.
"""

from enum import StrEnum

from fatline_verify.model.option_spec import spec
from fatline_verify.rules.decision import stay, step
from fatline_verify.rules.registry import RuleSet, register


class Turn(StrEnum):
    """Which way a robot steps."""

    RIGHT = "right"
    LEFT = "left"


TURN = spec(
    "turn",
    Turn,
    "each robot moves towards its far neighbour",
    {
        "right": "toward a robot seen at least 3 radii right: the right-most robot never moves",
        "left": "toward a robot seen at least 3 radii left: the right-most robot may leave its vertical",
    },
    note="the rule set's own option (a plug-in's), not one of the paper's",
)


def _clear(c, end, rho):
    """Whether the disc at ``c`` keeps clear of the path from (0, 0) to ``(end, 0)`` (touching allowed)."""
    x, y = c
    px = min(max(x, min(0, end)), max(0, end))
    return (x - px) ** 2 + y * y >= 4 * rho * rho


def decide(snapshot, model):
    """One radius toward a robot seen 3 radii away on the side ``turn`` reads, the way clear; else stay."""
    rho = model.radius
    sign = 1 if model.options.turn is Turn.RIGHT else -1
    if any(sign * x >= 3 * rho for x, _ in snapshot) and all(_clear(c, sign * rho, rho) for c in snapshot):
        return step("turn-step", (sign * rho, 0))
    return stay("turn-stay")


register(
    RuleSet(
        "turn-step",
        decide,
        "One radius toward a robot 3 radii away, right or left as its option turn reads.",
        options=(TURN,),
    )
)
