#!/usr/bin/env python
"""Which initial configurations no rule set of the repaired family brings to a line, and which leg
kinds would free them (``fatline reach``), as the table of docs/repaired.md: per family, the stuck
initial configurations, the seconds, and the rounds that failed the executable model's checks (not followed).

Usage: python bench/reach.py [--quick]   (from the repository root; --quick: 2-4 robots at q = 1)."""

from __future__ import annotations

import sys
import time

from fatline_verify.model.config import load_model
from fatline_verify.repair.reach import PROVED, Kind
from fatline_verify.repair.search import reach

FAMILIES = {
    "proved (right, vertical)": PROVED,
    "+ left": PROVED | {Kind.LEFT},
    "+ corner": PROVED | {Kind.CORNER},
    "+ left, corner": PROVED | {Kind.LEFT, Kind.CORNER},
    "+ left-alone, corner": PROVED | {Kind.LEFT_ALONE, Kind.CORNER},
}


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    base = load_model("repaired")
    rows = [(1, n) for n in range(2, 5 if quick else 6)] + ([] if quick else [(2, n) for n in range(2, 5)])
    print("| lattice, robots | initial | every algorithm | " + " | ".join(FAMILIES) + " |")
    print("|---|---|---|" + "---|" * len(FAMILIES))
    for q, n in rows:
        model = base.with_q(q)
        cells = []
        universal = initial = None
        for kinds in FAMILIES.values():
            t = time.perf_counter()
            r = reach(model, n, (9, 9), kinds)
            universal, initial = len(r.universal), r.initial
            failed = f", {r.unsafe:,} rounds failed the checks" if r.unsafe else ""
            cells.append(f"{len(r.stuck):,} ({time.perf_counter() - t:.0f} s{failed})")
        print(f"| q = {q}, {n} | {initial:,} | {universal:,} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
