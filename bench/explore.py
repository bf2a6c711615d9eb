"""Benchmark the exploration engines on the paper's default model.

Prints, for each bound, initial configurations, states, transitions, wall seconds and states per
second for the scalar reference engine and the fast engine side by side, and the speed-up.

    python bench/explore.py                # every bound, both engines
    python bench/explore.py --fast-only    # skip the (slow) scalar engine
"""

from __future__ import annotations

import argparse
import time

from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.systems import system_for
from fatline_verify.text import table

BOUNDS = [(3, 9), (4, 9), (4, 12), (5, 9)]


def measure(model, n: int, w: int, engine: str) -> tuple[int, int, int, float]:
    t0 = time.perf_counter()
    system = system_for(model)
    initial = initial_array(n, (w, w), model)
    ex = explore(system, system.initial(initial), (w, w), engine_for(system, engine))
    return len(initial), ex.n_states, ex.n_transitions, time.perf_counter() - t0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--fast-only", action="store_true")
    parser.add_argument("--model", default="paper")
    args = parser.parse_args()
    model = load_model(args.model)
    rows = []
    for n, w in BOUNDS:
        init, states, trans, fast_s = measure(model, n, w, "fast")
        row = [f"n={n}, {w}x{w}", str(init), str(states), str(trans), f"{fast_s:.2f}", f"{states / fast_s:,.0f}"]
        if args.fast_only:
            row += ["-", "-", "-"]
        else:
            _, s_states, _, scalar_s = measure(model, n, w, "scalar")
            assert s_states == states, "engines disagree"
            row += [f"{scalar_s:.2f}", f"{states / scalar_s:,.0f}", f"{scalar_s / fast_s:.1f}x"]
        rows.append(row)
        print("\n".join(table(HEADERS, rows)[-1:]), flush=True)
    print()
    print("\n".join(table(HEADERS, rows)))


HEADERS = [
    "bound",
    "initial",
    "states",
    "transitions",
    "fast s",
    "fast states/s",
    "scalar s",
    "scalar states/s",
    "speed-up",
]

if __name__ == "__main__":
    main()
