#!/usr/bin/env python
"""Usage: python bench/no_leg_states.py MODEL N  (PYTHONPATH at the repository).

Inherent deadlocks: states where no robot has ANY leg of the three classes that passes repairs.allowed
(lock, clearance, edges kept/bridged; bottom: none below, ends >= 3 below each above; horizontal: rightward
and only if r sees a robot strictly right of it, so it cannot leave the RMA)."""

import sys

from fatline_verify.check.checker import CheckPlan, explore_robots
from fatline_verify.model.config import load_model
from fatline_verify.rules.repaired.algorithm import allowed, locked
from fatline_verify.schedulers.round import snapshot


def admissible(state, i, model):
    S = snapshot(state, i, model)
    rho = model.radius
    if not S or locked(S):
        return []
    out = []
    right = max(c[0] for c in S)
    for s in range(1, rho + 1):
        if s <= right:
            out.append(((s, 0), False))
    above = [c[1] for c in S if c[0] == 0 and c[1] > 0]
    below = [c[1] for c in S if c[0] == 0 and c[1] < 0]
    if not above:
        out += [((0, s), False) for s in range(-rho, rho + 1) if s]
    elif not below:
        out += [((0, s), True) for s in range(1, rho + 1) if s <= min(above) - 3 * rho]
    return [(e, b) for e, b in out if allowed(e, ((0, 0), e), S, model, bottom_up=b)]


def goal(state):
    return len({p[0] for p in state}) == 1


if __name__ == "__main__":
    model = load_model(sys.argv[1])
    n = int(sys.argv[2])
    plan = CheckPlan.of(model, (n, n), (9, 9), None)
    ex = explore_robots(plan, n)
    dead = []
    for sid in range(ex.n_states):
        if not ex.expanded[sid]:
            continue
        st = ex.system.from_array(ex.state_array(sid))
        pts = [tuple(int(v) for v in p) for p in st]
        if goal(pts):
            continue
        if not any(admissible(pts, i, model) for i in range(n)):
            dead.append((int(ex.depth[sid]), pts))
    zero = sum(d == 0 for d, _ in dead)
    print(f"n={n}: {ex.n_states} states, {len(dead)} with no admissible leg for any robot; depth-0: {zero}")
    for d, pts in sorted(dead)[:10]:
        print("  depth", d, pts)
