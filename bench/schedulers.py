"""States and seconds per scheduler: the round schedulers and ASYNC (async_steps K = 1, 2, 3) on the
same initial configurations, with the fast engine.

    python bench/schedulers.py [--model paper] [--robots 3..4] [--window 9x9]
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace

from fatline_verify.check.checker import check
from fatline_verify.model.config import load_model, parse_robots, parse_window
from fatline_verify.text import table

SETTINGS = [("ssync", None), ("centralized", None), ("fsync", None), ("async", 1), ("async", 2), ("async", 3)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--model", default="paper")
    parser.add_argument("--robots", default="3..4")
    parser.add_argument("--window", default="9x9")
    args = parser.parse_args()
    base = load_model(args.model)
    robots, window = parse_robots(args.robots), parse_window(args.window)
    rows = []
    for n in range(robots[0], robots[1] + 1):
        for scheduler, steps in SETTINGS:
            model = replace(base, options=base.options.with_(scheduler=scheduler))
            if steps is not None:
                model = replace(model, parameters=replace(model.parameters, async_steps=steps))
            t0 = time.perf_counter()
            result = check(model, (n, n), window, max_states=50_000_000)
            seconds = time.perf_counter() - t0
            s = result.stats[0]
            violated = sum(r.verdict.value == "VIOLATED" for r in result.results)
            rows.append(
                [
                    str(n),
                    scheduler + (f" K={steps}" if steps else ""),
                    f"{s.initial:,}",
                    f"{s.states:,}",
                    f"{s.transitions:,}",
                    f"{s.off_lattice:,}",
                    f"{seconds:.2f}",
                    f"{violated}/6",
                ]
            )
            print(" ".join(rows[-1]), flush=True)
    print()
    heads = ["robots", "scheduler", "initial", "states", "transitions", "off-lattice", "seconds", "violated"]
    print("\n".join(table(heads, rows)))


if __name__ == "__main__":
    main()
