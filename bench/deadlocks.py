#!/usr/bin/env python
"""Deadlocks of a model within the checker's bounds: states where no robot moves and the robots are not
on one vertical, and how many of them are initial configurations.

Usage: python bench/deadlocks.py MODEL ROBOTS [--q Q] [--window W] [--show K]
(from the repository root). The "Toward liveness" table of docs/repaired.md is this script's output for
models/repaired.toml, bench/repaired-progress.toml and bench/repaired-corner.toml at q = 1 and 2."""

from __future__ import annotations

import argparse
from dataclasses import replace

from fatline_verify.check.checker import CheckPlan, explore_robots
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.round import decide_all, enabled


def deadlocks(model, robots: int, window: int) -> tuple[int, list[tuple[int, list[tuple[int, int]]]]]:
    """The explored state count and the deadlock states, each with its depth (0 = initial)."""
    plan = CheckPlan.of(model, (robots, robots), (window, window), None)
    ex = explore_robots(plan, robots)
    found = []
    for sid in range(ex.n_states):
        if not ex.expanded[sid]:
            continue
        state = [(int(x), int(y)) for x, y in ex.system.from_array(ex.state_array(sid))]
        if len({x for x, _ in state}) > 1 and not enabled(decide_all(state, model)):
            found.append((int(ex.depth[sid]), sorted(state)))
    return ex.n_states, sorted(found)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model")
    parser.add_argument("robots", type=int)
    parser.add_argument("--q", type=int, default=None, help="lattice points per radius (default: the model's)")
    parser.add_argument("--window", type=int, default=9)
    parser.add_argument("--show", type=int, default=5, help="deadlock states to print (shallowest first)")
    args = parser.parse_args()
    model = load_model(args.model)
    if args.q is not None:
        model = replace(model, parameters=replace(model.parameters, q=args.q))
    states, found = deadlocks(model, args.robots, args.window)
    initial = sum(depth == 0 for depth, _ in found)
    print(
        f"{model.name} q={model.parameters.q} robots={args.robots} window={args.window}x{args.window}: "
        f"{states:,} states, {len(found):,} deadlocks, {initial:,} of them initial"
    )
    for depth, state in found[: args.show]:
        print(f"  depth {depth}: {state}")
