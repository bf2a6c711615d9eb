"""A rule set of one's own, in one file: step one radius right when a robot is seen at least ``reach``
radii right (3 unless the model's ``[rules]`` table sets it), and nothing is within two radii of the
path (touching allowed).

Registered by the entry point ``toy-step = toy_fatline_plugin`` of the group ``fatline.plugins``
(``toy_fatline_plugin-0.1.dist-info/entry_points.txt``, as pip lays out an installed package).
"""

from fatline_verify.model.seams import Param
from fatline_verify.rules.paper.algorithm import Decision
from fatline_verify.rules.registry import RuleSet, register


def _clear(c, rho):
    """Whether the disc at ``c`` keeps clear of the robot's path from (0, 0) to (rho, 0)."""
    x, y = c
    px = min(max(x, 0), rho)
    return (x - px) ** 2 + y * y >= 4 * rho * rho


def decide(snapshot, model):
    """Step right by one radius, or stay."""
    rho = model.radius
    reach = model.setting("rules")["reach"] * rho
    if any(c[0] >= reach for c in snapshot) and all(_clear(c, rho) for c in snapshot):
        return Decision("toy-step", (rho, 0), ((0, 0), (rho, 0)), ())
    return Decision("toy-stay", (0, 0), ((0, 0),), ())


REACH = Param(3, "how many radii right a robot must be seen for a step", minimum=1, values=(3, 4))

register(
    RuleSet(
        "toy-step",
        decide,
        "A toy: one radius right when a robot is reach (3) radii right and the way is clear.",
        parameters={"reach": REACH},
    )
)
