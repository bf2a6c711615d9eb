#!/usr/bin/env python
"""The pocket certificate (fatline_verify/repair/pocket.py), checked exactly under every shipped model that
reads repair_lock = left-first, and what the repaired rules do there at q = 2.

Usage: python bench/pocket.py (from the repository root)."""

from __future__ import annotations

from fatline_verify.model.config import load_model, shipped_models
from fatline_verify.model.numbers import show_point
from fatline_verify.repair.pocket import POCKET, check
from fatline_verify.rules.repaired.options import RepairLock
from fatline_verify.schedulers.round import decide_all


def main() -> None:
    r, *blockers = POCKET.robots
    x_r, x_s, y_lo, y_hi = POCKET.box
    print(f"pocket: r at {show_point(r)}, blockers at {', '.join(show_point(b) for b in blockers)}")
    print(f"box: x in [{x_r}, {x_s}], y in [{y_lo}, {y_hi}]; {len(POCKET.cover)} covering segments")
    for path in shipped_models():
        model = load_model(path)
        if model.options.repair_lock is not RepairLock.LEFT_FIRST:
            continue
        problems = check(POCKET, model)
        print(f"{model.name}: {'a certificate' if not problems else '; '.join(problems)}")
        at2 = model.with_q(2)
        state = tuple(at2.to_lattice(p) for p in POCKET.robots)
        for i, d in decide_all(state, at2).items():
            print(f"  q=2 robot {i} {show_point(POCKET.robots[i])}: {d.rule.value} -> {show_point(d.destination)}")


if __name__ == "__main__":
    main()
