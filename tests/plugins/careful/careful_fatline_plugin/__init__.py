"""Rule sets with a move family, as a user writes them (``docs/plugins.md``, "A rule set proved safe"):

- ``careful-right``: its family (the example of the docs, :mod:`.careful`): proved safe for every swarm size;
- ``careless-right``: the careful policy under a guard that forgets the swept path: its no-collision
  obligation fails, and the counterexample is replayed (a real collision of the rule set);
- ``cheat-right``: the careful family, but a policy that leaves it once (a robot that sees exactly one
  robot, two radii right of it, steps left): the checker's ``in-family`` lemma catches it.

Registered by the entry point ``careful = careful_fatline_plugin`` (``fatline.plugins``).
"""

from fatline_verify.rules.decision import stay, step
from fatline_verify.rules.family import LegClass, MoveFamily, end, forall, sees
from fatline_verify.rules.registry import RuleSet, register

from . import careful
from .careful import RIGHT, decide

CARELESS = MoveFamily(
    "careless-right",
    (LegClass("right", RIGHT.shape, forall(lambda c: sees(end, c)), "one radius right, robots seen kept in view"),),
    max_step=1,
    at_rest=careful.FAMILY.at_rest,
)


def careless(snapshot, model):
    """One radius right when a robot is seen right and the family admits it (it does not look at the way)."""
    ahead = (model.radius, 0)
    if any(x > 0 for x, _ in snapshot) and CARELESS.classify(snapshot, ahead, model) == "right":
        return step("right", (model.radius, 0))
    return stay("wait")


def cheat(snapshot, model):
    """The careful policy, but a robot seeing exactly one robot, two radii right of it, steps left."""
    if list(snapshot) == [(2 * model.radius, 0)]:
        return step("cheat", (-model.radius, 0))
    return decide(snapshot, model)


register(
    RuleSet(
        "careless-right",
        careless,
        "Right when every robot seen stays in view, whatever is in the way.",
        family=CARELESS,
    )
)
register(RuleSet("cheat-right", cheat, "careful-right, but one view steps left.", family=careful.FAMILY))
__all__ = ["CARELESS", "careful", "careless", "cheat"]
