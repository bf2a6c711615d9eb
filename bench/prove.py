"""Benchmark the prover from its saved results: verdicts, seconds per obligation and encoding sizes.

python bench/prove.py [MODEL ...] [--proofs proofs]

Reads ``proofs/MODEL/results.json`` (written by ``fatline prove MODEL``) and the ``.smt2`` files it
names; prints per model the verdict counts, the median and maximum solver seconds, and the sizes of
the written obligations (bytes, assertions). To measure afresh: ``fatline prove MODEL --out DIR``
first, then this script with ``--proofs DIR``.
"""

from __future__ import annotations

import argparse
import json
import statistics
from collections import Counter
from pathlib import Path

from fatline_verify.text import table


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("models", nargs="*")
    parser.add_argument("--proofs", default="proofs")
    args = parser.parse_args()
    root = Path(args.proofs)
    names = args.models or sorted(p.parent.name for p in root.glob("*/results.json"))
    rows = []
    for name in names:
        data = json.loads((root / name / "results.json").read_text())
        obligations = data["obligations"]
        counts = Counter(r["verdict"] for r in obligations)
        seconds = [r["seconds"] for r in obligations]
        files = [Path(r["smt2"]) for r in obligations if r.get("smt2") and Path(r["smt2"]).is_file()]
        sizes = [f.stat().st_size for f in files]
        asserts = [f.read_text().count("(assert ") for f in files]
        rows.append(
            [
                name,
                str(len(obligations)),
                str(counts["PROVED"]),
                str(counts["VIOLATED"]),
                str(counts["HOLDS_WITHIN_BOUNDS"]),
                str(counts["INCONCLUSIVE"]),
                f"{statistics.median(seconds):.2f}",
                f"{max(seconds):.2f}",
                f"{statistics.median(sizes) / 1024:.0f}" if sizes else "-",
                f"{max(sizes) / 1024:.0f}" if sizes else "-",
                f"{statistics.median(asserts):.0f}" if asserts else "-",
            ]
        )
    head = [
        "model",
        "obligations",
        "PROVED",
        "VIOLATED",
        "HOLDS",
        "INCONCL.",
        "median s",
        "max s",
        "median KB",
        "max KB",
        "median asserts",
    ]
    print("\n".join(table(head, rows)))


if __name__ == "__main__":
    main()
