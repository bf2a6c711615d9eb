"""Benchmark the prover: seconds per obligation for a model (default: paper).

python bench/prove.py [MODEL] [--timeout S] [--slots K] [--jobs J]
"""

from __future__ import annotations

import argparse
import time

from fatline_verify.config import load_model
from fatline_verify.prover import prove
from fatline_verify.text import table


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("model", nargs="?", default="paper")
    parser.add_argument("--timeout", type=float, default=10.0)
    parser.add_argument("--slots", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=None)
    args = parser.parse_args()
    model = load_model(args.model)
    t0 = time.perf_counter()
    results = prove(model, slots=args.slots, timeout=args.timeout, jobs=args.jobs)
    wall = time.perf_counter() - t0
    rows = [[r.lemma, r.form, r.rule, r.verdict.value, str(r.slots), f"{r.seconds:.2f}"] for r in results]
    print("\n".join(table(["lemma", "form", "rule", "verdict", "slots", "solver s"], rows)))
    total = sum(r.seconds for r in results)
    print(f"\n{len(results)} obligations, {total:.1f} solver seconds, {wall:.1f} s wall")


if __name__ == "__main__":
    main()
