#!/usr/bin/env python
"""Figures of ``fatline synth`` (docs/synth.md): per leg family, lattice, robot count and scheduler, the answer
(SAT: one safe, live table for every count from 2 robots to that one; UNSAT: none exists), the size of the
search and the seconds; then the last formula of one search solved again from scratch by each python-sat
solver and by z3, in-solver seconds only.

Usage: python bench/synth.py [--quick]   (from the repository root; --quick: the 7x7 rows and the comparison)."""

from __future__ import annotations

import sys
import time

from fatline_verify.model.config import load_model
from fatline_verify.model.options import Scheduler
from fatline_verify.repair.reach import PROVED, Kind, starts
from fatline_verify.synth.encode import SOLVERS, Encoder, Stats, search, synthesise

LEFT_CORNER = PROVED | {Kind.LEFT, Kind.CORNER}
FAMILIES = {
    "right, vertical": PROVED,
    "+ left, corner": LEFT_CORNER,
    "+ left-alone, corner": PROVED | {Kind.LEFT_ALONE, Kind.CORNER},
}
C, S = Scheduler.CENTRALIZED, Scheduler.SSYNC


def rows(quick: bool) -> list[tuple[str, int, int, int, Scheduler]]:
    out = [("+ left, corner", 1, n, 7, sch) for sch in (C, S) for n in (2, 3, 4)]
    if quick:
        return out
    out += [(fam, 1, n, 9, sch) for fam in FAMILIES for sch in (C, S) for n in (2, 3, 4)]
    out += [(fam, 2, n, 9, sch) for fam in FAMILIES for sch in (C, S) for n in (2, 3)]
    return out


def compare(model, kinds, n, window, scheduler) -> str:  # type: ignore[no-untyped-def]
    """The search's last formula (every clause it added, the initial configurations assumed), solved afresh."""
    import z3
    from pysat.solvers import Solver

    enc = Encoder(model, kinds, scheduler)
    enc.keep = []
    first = starts(model, n, window)
    table, *_ = search(enc, first, Stats())
    assumptions = [enc.reach[s] for s in first]
    cells = [f"{'SAT' if table is not None else 'UNSAT'}, {enc.top:,} variables, {len(enc.keep):,} clauses"]
    for name in SOLVERS:
        with Solver(name=name, bootstrap_with=enc.keep) as solver:
            t = time.perf_counter()
            solver.solve(assumptions=assumptions)
            cells.append(f"{name} {time.perf_counter() - t:.2f} s")
    z = z3.Solver()
    xs = [z3.Bool(f"v{i}") for i in range(enc.top + 1)]
    z.add([z3.Or([xs[x] if x > 0 else z3.Not(xs[-x]) for x in c]) for c in enc.keep])
    t = time.perf_counter()
    z.check([xs[a] for a in assumptions])
    cells.append(f"z3 {time.perf_counter() - t:.2f} s")
    return "; ".join(cells)


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    base = load_model("repaired")
    print(
        "| legs | q | robots | window | scheduler | answer | initial | states | views | variables | clauses "
        "| refinements | core | seconds |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for fam, q, n, w, sch in rows(quick):
        r = synthesise(base.with_q(q), n, (w, w), FAMILIES[fam], scheduler=sch, smallest=2)
        s = r.stats
        print(
            f"| {fam} | {q} | 2..{n} | {w}x{w} | {sch.value} | {'SAT' if r.sat else 'UNSAT'} | {r.initial:,} | "
            f"{s.states:,} | {s.views:,} | {s.variables:,} | {s.clauses:,} | {s.refinements:,} | "
            f"{len(r.core) if not r.sat else ''} | {s.seconds:.1f} |",
            flush=True,
        )
    print()
    print(
        "7x7, 4 robots, + left, corner, centralized, the last formula solved afresh:",
        compare(base, LEFT_CORNER, 4, (7, 7), C),
    )


if __name__ == "__main__":
    main()
