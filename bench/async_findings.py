"""What ASYNC adds: per model and lemma, the smallest swarm that violates the lemma under ``async`` but
not under the model's own round scheduler (``ssync`` for the paper's models).

For each shipped model (or ``--model``), the model is checked under its own scheduler and under
``scheduler = async`` (``async_steps`` from ``--steps``, default the model's) for ``--robots`` on
``--window``; a row is printed for every lemma whose verdict differs, with the ASYNC witness's length,
and every such witness is written under ``--traces`` (replayed before it is written, as every
witness). The table is docs/async.md ("What ASYNC adds").

    python bench/async_findings.py --robots 2..4 --window 9x9 --traces reports/traces
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from pathlib import Path

from fatline_verify.check.checker import check, write_witnesses
from fatline_verify.lemmas.properties import CHECKED, Verdict
from fatline_verify.model.config import load_model, parse_robots, parse_window, shipped_models
from fatline_verify.model.options import Scheduler
from fatline_verify.text import table


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--model", action="append", help="model file or name (default: every shipped model)")
    parser.add_argument("--robots", default="2..4")
    parser.add_argument("--window", default="9x9")
    parser.add_argument("--steps", type=int, default=None, help="async_steps (default: the model's)")
    parser.add_argument("--traces", default=None, help="write the ASYNC-only witnesses here")
    parser.add_argument("--max-states", type=int, default=None, help="state bound (default: the model's)")
    args = parser.parse_args()
    robots, window = parse_robots(args.robots), parse_window(args.window)
    names = args.model or [p.stem for p in shipped_models() if "async" not in p.stem]
    rows, found = [], 0
    for name in names:
        model = load_model(name)
        if model.options.scheduler is Scheduler.ASYNC:
            continue
        steps = args.steps or model.parameters.async_steps
        amodel = replace(
            model,
            name=f"{model.name}-as-async",
            options=model.options.with_(scheduler="async"),
            parameters=replace(model.parameters, async_steps=steps),
        )
        t0 = time.perf_counter()
        sync = check(model, robots, window, max_states=args.max_states)
        t1 = time.perf_counter()
        asyn = check(amodel, robots, window, max_states=args.max_states)
        t2 = time.perf_counter()
        cut = " (truncated)" if any(s.truncated for s in (*sync.stats, *asyn.stats)) else ""
        print(
            f"{name}: {model.options.scheduler} {sum(s.states for s in sync.stats):,} states {t1 - t0:.1f} s; "
            f"async (K={steps}) {sum(s.states for s in asyn.stats):,} states {t2 - t1:.1f} s{cut}",
            flush=True,
        )
        for lemma in CHECKED:
            for n in range(robots[0], robots[1] + 1):
                a = next(r for r in asyn.results if r.lemma is lemma and r.robots == n)
                s = next(r for r in sync.results if r.lemma is lemma and r.robots == n)
                if a.verdict is Verdict.VIOLATED and s.verdict is not Verdict.VIOLATED:
                    rows.append([name, lemma.value, str(n), s.verdict.value, f"{a.witness_rounds} events", a.reason])
                    found += 1
                    break
        if args.traces:
            only = replace(
                asyn,
                results=tuple(
                    r
                    for r in asyn.results
                    if r.verdict is Verdict.VIOLATED
                    and next(x for x in sync.results if x.lemma is r.lemma and x.robots == r.robots).verdict
                    is not Verdict.VIOLATED
                ),
            )
            Path(args.traces).mkdir(parents=True, exist_ok=True)
            for (lemma, n), path in write_witnesses(only, Path(args.traces), f"{amodel.name}-").items():
                print(f"  witness {lemma} n={n}: {path}")
    print()
    w, h = window
    print(f"robots {robots[0]}..{robots[1]}, window {w}x{h}: {found} lemma(s) violated under async only")
    print("\n".join(table(["model", "lemma", "smallest n", "own scheduler", "async witness", "detail"], rows)))


if __name__ == "__main__":
    main()
