"""Benchmark the prover: from its saved results, or afresh (wall clock against solver seconds).

python bench/prove.py [MODEL ...] [--proofs proofs]
python bench/prove.py --startup N
python bench/prove.py --run MODEL [--jobs J] [--lemma L] [--fresh]
python bench/prove.py MODEL ... --against OTHER/.venv/bin/python [--jobs J] [--lemma L]

The first form reads ``proofs/MODEL/results.json`` (written by ``fatline prove MODEL``) and the
``.smt2`` files it names where they are there (they are not in git: a ``fatline prove`` run writes
those it solves); prints per model the verdict counts, the median and maximum solver seconds, and the
sizes of the written obligations (bytes, assertions; ``-`` without the files).

``--startup N``: what an obligation costs before its solver starts. N calls, one after another, each
in its own process the way ``fatline prove`` runs an obligation (:func:`fatline_verify.fresh.run_fresh`),
each importing the prover and returning; prints the seconds per call.

``--run MODEL``: ``fatline prove MODEL`` into a temporary copy of ``--proofs`` (so every earlier
counterexample is replayed first, as in this repository: the solver's own work is small and the
start-up shows; ``fatline prove --fresh``: every obligation solved, none answered from its row), one
obligation at a time unless ``--jobs``; prints the wall clock per obligation,
the solver seconds per obligation (the rows' ``seconds``) and the difference, the cost of running an
obligation at all. ``--fresh``: into an empty directory instead (what a user gets: the shipped
counterexample corpus, ``fatline_verify/prove/corpus.json``, is replayed first, no earlier run's).

``MODEL ... --against OTHER/.venv/bin/python``: each model proved afresh by another checkout's
interpreter (its installed package: the code before a change) and then by this one, one after the
other on the same machine, with ``--jobs``; prints both wall clocks, their ratio over every model, and
every row whose verdict or PROVED basis differs.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from fatline_verify.text import table

PRELOAD = "import fatline_verify.prove.search, fatline_verify.prove.family, fatline_verify.prove.prover"
"""What a real obligation imports before it solves (``exec`` of it is a picklable call that returns None)."""


def startup(calls: int) -> None:
    from fatline_verify.fresh import run_fresh

    got: list[float] = []
    t0 = time.perf_counter()
    last = t0

    def done(_: int, __: object) -> None:
        nonlocal last
        now = time.perf_counter()
        got.append(now - last)
        last = now

    run_fresh([(exec, (PRELOAD,), {})] * calls, 1, done)
    total = time.perf_counter() - t0
    print(
        f"{calls} fresh processes, one at a time, each importing the prover: {total:.2f} s, "
        f"{total / calls:.3f} s per obligation (first {got[0]:.3f} s, median {statistics.median(got):.3f} s)"
    )


def run(
    model: str, proofs: Path, jobs: int, lemma: str | None, fresh: bool = False, python: str = sys.executable
) -> dict[str, tuple[str, str]]:
    """One timed ``fatline prove`` by the interpreter ``python`` (its installed package: this checkout's,
    or another's with ``--against``); the verdict and basis of each row, by key."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "proofs"
        if not fresh:
            shutil.copytree(proofs, out)
        argv = [
            python,
            "-m",
            "fatline_verify.cli",
            "prove",
            model,
            "--out",
            str(out),
            "--jobs",
            str(jobs),
            "-q",
        ]
        if not fresh:  # the copied rows are solved again (into an empty directory there are none)
            argv.append("--fresh")
        if lemma:
            argv += ["--lemma", lemma]
        t0 = time.perf_counter()
        # run from the temporary directory: ``python -m`` puts the working directory first on the path,
        # so from a checkout it would import that checkout's package, not the interpreter's own
        subprocess.run(argv, check=False, stdout=subprocess.DEVNULL, cwd=tmp)
        wall = time.perf_counter() - t0
        rows = json.loads((out / model / "results.json").read_text())["obligations"]
        ran = len(rows) if lemma is None else sum(1 for r in rows if r["lemma"] == lemma)
        solver = sum(r["seconds"] for r in rows if lemma is None or r["lemma"] == lemma)
    per = wall * jobs / ran
    who = "" if python == sys.executable else f" [{python}]"
    print(
        f"fatline prove {model}{f' --lemma {lemma}' if lemma else ''} --jobs {jobs}{' (fresh)' if fresh else ''}{who}: "
        f"{ran} obligations in {wall:.1f} s; "
        f"per obligation (x{jobs} jobs) {per:.2f} s of wall clock, {solver / ran:.2f} s solving, "
        f"{per - solver / ran:.2f} s the rest",
        flush=True,
    )
    return {
        f"{r['lemma']}/{r['form']}-{r.get('case', '')}.{r.get('other', '')}": (r["verdict"], r.get("basis", ""))
        for r in rows
        if lemma is None or r["lemma"] == lemma
    }


def side_by_side(models: list[str], against: str, jobs: int, lemma: str | None) -> None:
    """Each model proved afresh by the other checkout's interpreter, then by this one, one after the
    other on the same machine; the wall clocks side by side and every row whose verdict or basis differs."""
    total = {"then": 0.0, "now": 0.0}
    for model in models:
        for who, python in (("then", against), ("now", sys.executable)):
            t0 = time.perf_counter()
            got = run(model, Path("proofs"), jobs, lemma, True, python)
            total[who] += time.perf_counter() - t0
            if who == "then":
                then = got
        differ = sorted(k for k in set(then) | set(got) if then.get(k) != got.get(k))
        print(f"  {model}: {len(got)} rows, {len(differ)} differ in verdict or basis", flush=True)
        for k in differ:
            print(f"    {k}: {then.get(k)} -> {got.get(k)}")
    print(
        f"every model: {total['then']:.0f} s then, {total['now']:.0f} s now "
        f"({total['then'] / max(total['now'], 1e-9):.2f}x)"
    )


def saved(models: list[str], root: Path) -> None:
    names = models or sorted(p.parent.name for p in root.glob("*/results.json"))
    rows = []
    for name in names:
        data = json.loads((root / name / "results.json").read_text())
        obligations = data["obligations"]
        counts = Counter(r["verdict"] for r in obligations)
        bases = Counter(r.get("basis", "?") for r in obligations if r["verdict"] == "PROVED")
        seconds = [r["seconds"] for r in obligations]
        files = [Path(r["smt2"]) for r in obligations if r.get("smt2") and Path(r["smt2"]).is_file()]
        sizes = [f.stat().st_size for f in files]
        asserts = [f.read_text().count("(assert ") for f in files]
        rows.append(
            [
                name,
                str(len(obligations)),
                str(counts["PROVED"]),
                f"{bases['substantive']}/{bases['immediate']}/{bases['vacuous']}"
                + (f" ({bases['?']} ?)" if bases["?"] else ""),
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
        "subst./immed./vac.",
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("models", nargs="*")
    parser.add_argument("--proofs", default="proofs")
    parser.add_argument("--startup", type=int, metavar="N", help="time N fresh obligation processes doing nothing")
    parser.add_argument("--run", metavar="MODEL", help="time a fresh fatline prove MODEL (earlier results replayed)")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--lemma")
    parser.add_argument("--fresh", action="store_true", help="--run into an empty directory (no earlier results)")
    parser.add_argument(
        "--against",
        metavar="PYTHON",
        help="with MODELs: prove each afresh by this interpreter (another checkout's venv) and by this one, "
        "side by side",
    )
    args = parser.parse_args()
    if args.against:
        side_by_side(args.models, args.against, args.jobs, args.lemma)
    elif args.startup:
        startup(args.startup)
    elif args.run:
        run(args.run, Path(args.proofs), args.jobs, args.lemma, args.fresh)
    else:
        saved(args.models, Path(args.proofs))


if __name__ == "__main__":
    main()
