"""``fatline synth``: search for an oblivious rule table of the family's legs that is safe and live, or prove
that none exists (fatline_verify/synth/)."""

from __future__ import annotations

import argparse
from typing import Any

from ..errors import InvalidInput
from ..outputs import Kind, Output, claim_file, distinct_outputs, write_json
from ..progress import Progress
from .common import (
    EXIT_FOUND,
    EXIT_INTERRUPTED,
    EXIT_OK,
    add_bounds,
    add_command,
    add_force,
    add_model_argument,
    emit,
    exit_codes,
    model_arg,
    nonempty,
)
from .family import DEFAULT_MODEL, add_family_arguments, family_bounds, leg_kinds

MAX_ROBOTS = 5
"""Every configuration the table may meet is a state of the search, in Python: 4 robots in 9x9 take minutes;
beyond 5 the formula outgrows one machine."""
BYTES_PER_START = 16384
"""Memory the synthesis holds per initial configuration (its states, views, clauses and the replay: about 12 KB
measured at 2..4 robots in 9x9 with left and corner legs, 9,929 initial configurations, 115 MB above the
interpreter's), for the guard before any work."""


def _scheduler(text: str | None, model: Any) -> Any:
    from ..model.options import Scheduler
    from ..synth.encode import SCHEDULERS, schedulers_text

    name = text if text is not None else model.options.scheduler.value
    if name not in {s.value for s in SCHEDULERS}:
        where = f"scheduler={name!r}" + ("" if text is not None else f" (model {model.name})")
        raise InvalidInput(
            f"{where}: the encoding covers schedulers that may activate one robot alone; expected one of "
            f"{schedulers_text()} (--scheduler)"
        )
    return Scheduler(name)


def cmd_synth(args: argparse.Namespace) -> int:
    from ..repair.reach import refuse
    from ..synth.certificate import certify
    from ..synth.encode import SOLVERS, synthesise
    from ..synth.text import synth_lines, synth_to_json

    model = model_arg(args.model)
    kinds = leg_kinds(args.with_)
    if args.q is not None:
        model = model.with_q(args.q)
    scheduler = _scheduler(args.scheduler, model)
    refuse(model)
    if args.solver not in SOLVERS:
        raise InvalidInput(f"solver={args.solver!r}: expected one of {', '.join(SOLVERS)}")
    most = (MAX_ROBOTS, "every reachable configuration is in the formula")
    lo, hi, window = family_bounds(args, model, BYTES_PER_START, most)
    json_path = claim_file(args.json, name="json", kind=Kind.SYNTH, force=args.force) if args.json else None
    distinct_outputs([Output("json", json_path)], [("model", args.model)])

    results = []
    interrupted = False
    with Progress(enabled=not args.quiet, unit="configurations") as bar:
        try:
            for n in range(lo, hi + 1):  # progress per initial configuration and solve: not per robot count
                r = synthesise(
                    model, n, window, kinds, scheduler=scheduler, solver=args.solver, smallest=lo, progress=bar.follow
                )
                answer = "SAT" if r.sat else "UNSAT"
                bar.stage(f"{lo}..{n} robots: {answer}; checking the answer (replayed, solved again)", timer=True)
                results.append((r, certify(model, r, again=not args.no_again)))
                if not r.sat:  # more robots only add initial configurations: unsat stays unsat
                    break
        except KeyboardInterrupt:
            interrupted = True
    lines = synth_lines(model, args.model, results)
    if interrupted:
        done = ", ".join(str(r.n) for r, _ in results) or "none"
        lines.append(f"INTERRUPTED: robot counts finished: {done}; the rest was not searched")
    emit(lines)
    if json_path is not None and results:
        write_json(json_path, synth_to_json(model, results))
        emit([f"results written to {json_path}"])
    if interrupted:
        return EXIT_INTERRUPTED
    bad = [c.problems[0] for _, c in results if c.problems]
    if bad:  # pragma: no cover - a table that fails its replay is a bug of the encoding
        raise AssertionError(f"a synthesised table fails its replay: {bad[0]}")
    return EXIT_FOUND if any(not r.sat for r, _ in results) else EXIT_OK


def register(sub: Any) -> None:
    from ..synth.encode import SOLVERS

    p = add_command(
        sub,
        "synth",
        "search for an oblivious rule table of the family's legs that is safe and live for small swarms, or prove "
        "that none is (exit 1: some robot count is unsat)",
        exit_codes(
            "a table exists for every robot count asked (SAT)",
            "some robot count is UNSAT (no such table; a replayed core)",
            kept=True,
        ),
    )
    add_model_argument(p, default=DEFAULT_MODEL)
    add_bounds(p)
    add_family_arguments(p)
    p.add_argument("--scheduler", help="centralized or ssync (default: the model's scheduler)")
    p.add_argument(
        "--solver", default=SOLVERS[0], help=f"python-sat solver, one of {', '.join(SOLVERS)} (default: {SOLVERS[0]})"
    )
    p.add_argument("--no-again", action="store_true", help="do not solve an unsat core again with another solver")
    p.add_argument(
        "--json",
        type=nonempty("json", "a file name for the JSON results"),
        help="write the results (tables, cores) as JSON",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    add_force(p)
    p.set_defaults(handler=cmd_synth)
