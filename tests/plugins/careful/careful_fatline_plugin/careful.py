from fatline_verify.rules.decision import stay, step
from fatline_verify.rules.family import LegClass, MoveFamily, clear, end, forall, me, sees
from fatline_verify.rules.registry import RuleSet, register

RIGHT = LegClass(
    "right",
    shape=(end.y == me.y) & (end.x > me.x) & (end.x <= me.x + 1),  # at most one radius, to the right
    guard=forall(lambda c: clear(c) & sees(end, c)),  # the way clear of every robot seen, each still in view
    says="one radius or less right, the way clear, every robot seen still in view",
)

FAMILY = MoveFamily(
    "careful-right",
    classes=(RIGHT,),
    max_step=1,
    at_rest=~forall(lambda c: c.x >= me.x),  # a robot that sees one strictly left of it stays
    says="one radius right at a time, never while a robot is seen to the left",
)


def decide(snapshot, model):
    """The policy (any Python): one radius right when a robot is seen right and the family admits it."""
    ahead = (model.radius, 0)
    if any(x > 0 for x, _ in snapshot) and FAMILY.classify(snapshot, ahead, model) == "right":
        return step("right", ahead)
    return stay("wait")


register(RuleSet("careful-right", decide, "One radius right when the way is clear.", family=FAMILY))
