"""``fatline sweep``: each lemma over the whole product of readings, covered by counterexamples."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ..errors import InvalidInput
from ..lemmas.properties import CHECKED, Lemma
from ..model.config import parse_robots, parse_window
from ..outputs import child, claim_dir
from ..schedulers.base import ENGINES
from .check import MAX_Q
from .common import (
    EXIT_FOUND,
    EXIT_INCONCLUSIVE,
    EXIT_INTERRUPTED,
    EXIT_OK,
    add_command,
    add_model_argument,
    check_workers,
    emit,
    integer,
    model_arg,
    nonempty,
)

DEFAULT_ROBOTS = (2, 3)
DEFAULT_WINDOW = (7, 7)


def cmd_sweep(args: argparse.Namespace) -> int:
    from ..check.checker import CheckPlan
    from ..check.workers import require_dask
    from ..locks import holding
    from ..sweep.run import Sweep, SweepBounds
    from ..sweep.space import Space, parse_vary

    model = model_arg(args.model)
    if args.q is not None:
        model = model.with_q(args.q)
    vary = parse_vary(args.vary, model)
    lemmas = parse_lemmas(args.lemma)
    robots = parse_robots(args.robots, error=InvalidInput) if args.robots is not None else DEFAULT_ROBOTS
    window = parse_window(args.window, error=InvalidInput) if args.window is not None else DEFAULT_WINDOW
    bound = parse_window(args.bound, error=InvalidInput, name="bound") if args.bound is not None else None
    CheckPlan.of(model, robots, window, args.max_states, args.engine, bound=bound)  # refused now, not per check
    check_workers(args.workers, args.cluster)
    if args.cluster is not None or args.workers > 1:
        require_dask(f"workers={args.workers}" if args.cluster is None else f"cluster={args.cluster!r}")
    root = claim_dir(args.out, name="out")
    sweep = Sweep(
        Space(model, vary),
        SweepBounds(robots, window, args.engine, args.max_states, bound),
        child(root, model.name),
        lemmas,
    )
    with holding(sweep.out, name="out"):  # one run at a time per sweep: a second is refused, before any work
        return _run(args, model.name, sweep)


def _run(args: argparse.Namespace, name: str, sweep: Any) -> int:
    """Resume, run, save and report ``sweep`` (its directory held)."""
    from ..sweep.page import claim_pages, page_files, write_pages
    from ..sweep.run import INCONCLUSIVE, sweep_lines

    resumed = sweep.resume()  # refuses another sweep's directory, or files changed since, before any work
    claim_pages(sweep.out)

    def say(line: str) -> None:
        if not args.quiet:
            print(line, file=sys.stderr, flush=True)

    if resumed:
        say(f"resuming: {len(sweep.checks)} checks done, {sweep.open_count():,} combinations open")
    interrupted = False
    try:
        if args.max_checks != 0:
            sweep.run(args.max_checks, args.workers, args.cluster, say)
    except KeyboardInterrupt:
        interrupted = True
    lines = [*sweep_lines(sweep), f"report page: {page_files(sweep.out)[0]}"]
    if interrupted:
        lines.append(f"INTERRUPTED: {len(sweep.checks)} checks finished and saved in {sweep.json_path}; "
                     "the same command resumes")  # fmt: skip
    emit(lines)  # the verdicts before any file: a full disk does not hide them
    sweep.save()
    write_pages(sweep, _command(args, name))
    if interrupted:
        return EXIT_INTERRUPTED
    if sweep.open_count():
        return EXIT_INCONCLUSIVE
    if sweep.witnesses:
        return EXIT_FOUND
    # nothing refuted: INCONCLUSIVE anywhere is exit 3, as for check
    return EXIT_INCONCLUSIVE if any((s == INCONCLUSIVE).any() for s in sweep.status.values()) else EXIT_OK


def _command(args: argparse.Namespace, name: str) -> str:
    """The command that resumes this sweep and rewrites its page (the settings that name the sweep)."""
    parts = ["fatline sweep", args.model or name]
    for flag in ("vary", "lemma", "robots", "window", "bound", "q", "max_states", "out"):
        value = getattr(args, flag)
        if value is not None and not (flag == "out" and str(value) == "sweeps"):
            parts.append(f"--{flag.replace('_', '-')} {value}")
    return " ".join(str(p) for p in parts)


def parse_lemmas(text: str | None) -> tuple[Lemma, ...]:
    """``--lemma a,b`` as checked lemmas in table order (default: every one)."""
    if text is None:
        return CHECKED
    names = [t.strip() for t in text.split(",") if t.strip()]
    known = {lemma.value: lemma for lemma in CHECKED}
    for name in names or [text]:
        if name not in known:
            raise InvalidInput(f"lemma={name!r}: expected a comma-separated list of {', '.join(known)}")
    if len(set(names)) != len(names):
        raise InvalidInput(f"lemma={text!r}: expected each lemma once")
    return tuple(lemma for lemma in CHECKED if lemma.value in names)


def register(sub: Any) -> None:
    p = add_command(sub, "sweep", "each lemma over the whole product of readings, covered by counterexamples")
    add_model_argument(p)
    p.add_argument(
        "--vary",
        help="comma-separated options to vary (default: every option but the scheduler; the others as in the model)",
    )
    p.add_argument("--lemma", help="comma-separated lemmas to sweep (default: every lemma the checker decides)")
    p.add_argument(
        "--robots",
        help=f"robot count or range checked per combination (default {DEFAULT_ROBOTS[0]}..{DEFAULT_ROBOTS[1]})",
    )
    p.add_argument("--window", help=f"WIDTHxHEIGHT lattice points (default {DEFAULT_WINDOW[0]}x{DEFAULT_WINDOW[1]})")
    p.add_argument(
        "--bound",
        help="WIDTHxHEIGHT lattice points that bound each exploration (default: the window); a liveness lemma "
        "whose search lets a successor escape is INCONCLUSIVE there, so a bound nothing escapes from decides it",
    )
    p.add_argument("--q", type=integer("q", 1, MAX_Q), help="lattice points per radius (default: the model's q)")
    p.add_argument("--max-states", type=integer("max-states", 1, 10**10), help="stop a search after this many states")
    p.add_argument("--engine", choices=list(ENGINES), default=None, help="exploration engine")
    p.add_argument(
        "--max-checks",
        type=integer("max-checks", 0),
        default=None,
        help="stop after this many checks (default: until every combination is judged); rerun to go on; "
        "0: no check, only the report page from what is saved",
    )
    p.add_argument(
        "--workers", type=integer("workers", 1, 1024), default=1, help="checks at once, on a local Dask cluster"
    )
    p.add_argument("--cluster", help="run the checks on the Dask scheduler at tcp://HOST:PORT")
    p.add_argument(
        "--out",
        default="sweeps",
        type=nonempty("out", "a directory for sweep results"),
        help="directory for OUT/MODEL/sweep.json, status.npz and the witnesses (default: sweeps); a rerun with the "
        "same settings resumes",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    p.set_defaults(handler=cmd_sweep)
