"""Rule sets written as a new user might, some asking for a verdict they have not earned:

- ``rush-right``: one radius right whenever a robot is seen right of it, whatever is in the way, with
  liveness cases and a measure that really falls, and ``bounded_proved=True``: its liveness rows prove,
  but it collides (2 robots, one round), so termination must not be PROVED.
- ``rush-borrow``: the same rules claiming the paper's encoding by name (``prover="paper"``).
- ``rush-borrow-object``: the same rules carrying the paper's encoding object itself.
- ``half-step``: half a radius right when a robot is seen at least 3 radii right and the way is clear:
  its moves leave the lattice q = 1 (every engine must still check it, with the same verdicts).

Registered by the entry point ``users = users_fatline_plugin`` (``fatline.plugins``).
"""

from fractions import Fraction

import z3

from fatline_verify.prove.smt.cases import same, sees
from fatline_verify.prove.smt.live_rules import LiveCase
from fatline_verify.rules.decision import Decision
from fatline_verify.rules.paper.rule_set import CASES
from fatline_verify.rules.registry import Liveness, RuleSet, register


def decide(snapshot, model):
    """One radius right when a robot is seen right of it; otherwise stay."""
    rho = model.radius
    if any(x > 0 for x, _ in snapshot):
        return Decision("rush", (rho, 0), ((0, 0), (rho, 0)), ())
    return Decision("wait", (0, 0), ((0, 0),), ())


def _wait(ar, model, me, roles, universe):
    cs = [z3.Or(same(p, me), z3.Implies(sees(ar, model, me, p), p[0] <= me[0])) for p in universe]
    return cs, (ar.num(0), ar.num(0))


def _rush(ar, model, me, roles, universe):
    m = roles["m"]
    return [z3.Not(same(m, me)), sees(ar, model, me, m), m[0] > me[0]], (ar.num(1), ar.num(0))


def cases(model):
    """Both decisions: wait (nothing seen right), rush (some robot ``m`` seen right)."""
    return [LiveCase("wait", (), False, _wait), LiveCase("rush", ("m",), True, _rush)]


LIVENESS = Liveness(cases, ((-1, 0),), "sum of -x", "x is bounded (the author says so)", bounded_proved=True)

register(
    RuleSet("rush-right", decide, "Right whenever a robot is seen right, whatever is in the way.", liveness=LIVENESS)
)
register(RuleSet("rush-borrow", decide, "rush-right claiming the paper's encoding by name.", prover="paper"))
register(RuleSet("rush-borrow-object", decide, "rush-right carrying the paper's encoding.", prover=CASES))


def half_step(snapshot, model):
    """Half a radius right when a robot is seen 3 radii right and nothing comes within 2 of the path."""
    rho = model.radius
    half = Fraction(rho, 2)
    clear = all((x - min(max(x, 0), half)) ** 2 + y * y >= 4 * rho * rho for x, y in snapshot)
    if clear and any(x >= 3 * rho for x, _ in snapshot):
        return Decision("half", (half, 0), ((0, 0), (half, 0)), ())
    return Decision("wait", (0, 0), ((0, 0),), ())


register(RuleSet("half-step", half_step, "Half a radius right when the way is clear (off the lattice q = 1)."))


def step_left(snapshot, model):
    """One radius left when a robot is seen at least 3 radii left and nothing comes within 2 of the path."""
    rho = model.radius
    clear = all((x - min(max(x, -rho), 0)) ** 2 + y * y >= 4 * rho * rho for x, y in snapshot)
    if clear and any(x <= -3 * rho for x, _ in snapshot):
        return Decision("left", (-rho, 0), ((0, 0), (-rho, 0)), ())
    return Decision("wait", (0, 0), ((0, 0),), ())


OWN_SETTING = ("no-collision", "connectivity", "progress", "termination")
"""Lemmas step-left claims: Lemma 3 (the right-most axis stays) is not one of them; its moves shift that axis."""

register(RuleSet("step-left", step_left, "One radius left toward a robot 3 radii left.", lemmas=OWN_SETTING))
register(RuleSet("step-left-paper", step_left, "step-left judged by the paper's six lemmas."))
