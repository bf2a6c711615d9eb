"""``fatline sweep``: each lemma over the whole product of readings, covered by counterexamples."""

from __future__ import annotations

import argparse
import math
import re
import shlex
import time
from typing import Any

from ..errors import InvalidInput
from ..lemmas.properties import CHECKED, Lemma
from ..model.config import parse_robots, parse_window
from ..outputs import Output, child, claim_dir, distinct_outputs
from ..progress import Progress
from ..resources import default_max_memory, format_size, parse_size
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
    exit_codes,
    integer,
    model_arg,
    nonempty,
)

DEFAULT_ROBOTS = (2, 3)
DEFAULT_WINDOW = (7, 7)
DEFAULT_MAX_TIME = "10m"
FIRST = 0.5
"""Seconds before the first progress line off a terminal (the plan line comes at once)."""
EVERY = 10.0


def cmd_sweep(args: argparse.Namespace) -> int:
    from ..check.checker import CheckPlan
    from ..check.workers import require_dask
    from ..locks import holding
    from ..sweep.params import combinations, label, model_at, split_vary
    from ..sweep.run import CHECK_SHARE, WORK, Sweep, SweepBounds
    from ..sweep.space import Space, parse_vary

    model = model_arg(args.model)
    if args.q is not None:
        model = model.with_q(args.q)
    options_text, swept = split_vary(args.vary, model)
    vary = () if options_text == "" else parse_vary(options_text, model)
    lemmas = parse_lemmas(args.lemma)
    robots = parse_robots(args.robots, error=InvalidInput) if args.robots is not None else DEFAULT_ROBOTS
    window = parse_window(args.window, error=InvalidInput) if args.window is not None else DEFAULT_WINDOW
    bound = parse_window(args.bound, error=InvalidInput, name="bound") if args.bound is not None else None
    max_memory = parse_size(args.max_memory) if args.max_memory is not None else default_max_memory()
    max_time = parse_duration(args.max_time)
    # refused now, not per check
    CheckPlan.of(model, robots, window, args.max_states, args.engine, bound=bound, max_memory=max_memory // CHECK_SHARE)
    check_workers(args.workers, args.cluster)
    if args.cluster is not None or args.workers > 1:
        require_dask(f"workers={args.workers}" if args.cluster is None else f"cluster={args.cluster!r}")
    root = claim_dir(args.out, name="out")
    distinct_outputs([Output("out", child(root, model.name), directory=True)], [("model", args.model)])
    combos = combinations(swept)
    sweeps = []
    for combo in combos:  # every combination's model and directory made (and checked) before any work
        at = model_at(model, combo)
        out = child(child(root, model.name), label(combo)) if combo else child(root, model.name)
        bounds = SweepBounds(robots, window, args.engine, args.max_states, bound)
        work = 0 if max_time is None else WORK  # a run with a time limit keeps each step to minutes
        sweeps.append((combo, Sweep(Space(at, vary), bounds, out, lemmas, max_memory, work)))
    deadline = None if max_time is None else time.monotonic() + max_time
    codes = []
    for combo, sweep in sweeps:
        left = None if deadline is None else deadline - time.monotonic()
        if left is not None and left <= 0:
            emit([f"{label(combo)}: not started (--max-time {args.max_time} spent); the same command resumes"])
            codes.append(EXIT_INCONCLUSIVE)
            continue
        if combo:
            emit([f"{label(combo)}: {', '.join(f'{k}={v!r}' for k, v in combo.items())}"])
        with holding(sweep.out, name="out"):  # one run at a time per sweep: a second is refused, before any work
            codes.append(_run(args, model.name, sweep, left))
        if codes[-1] == EXIT_INTERRUPTED:
            return EXIT_INTERRUPTED
    return worst_exit(codes)


def worst_exit(codes: list[int]) -> int:
    """The exit code of several sweeps (one per combination of parameter values): a refutation anywhere
    (1), else anything open or INCONCLUSIVE (3), else every lemma holds within bounds (0)."""
    if EXIT_FOUND in codes:
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if EXIT_INCONCLUSIVE in codes else EXIT_OK


def _run(args: argparse.Namespace, name: str, sweep: Any, max_time: float | None) -> int:
    """Resume, run, save and report ``sweep`` (its directory held): progress from the first second,
    every step saved as it finishes, a stop after ``max_time`` seconds (between two steps)."""
    from ..sweep.page import claim_pages, page_files, write_pages
    from ..sweep.run import INCONCLUSIVE, Sweep, sweep_lines

    started = time.monotonic()
    deadline = None if max_time is None else started + max_time
    interrupted = False
    resumed = sweep.resume()  # refuses another sweep's directory, or files changed since, before any work
    claim_pages(sweep.out)
    with Progress(enabled=not args.quiet, unit="judgements", first=FIRST, every=EVERY) as bar:
        bar.say(_plan_line(sweep, max_time))
        if resumed:
            bar.say(
                f"resuming: {len(sweep.checks)} checks done, {sweep.open_count():,} judgements open"
                + (f", a check under way ({len(sweep.absorbed)} lemmas closed from it)" if sweep.pending else "")
            )
        opened = sweep.open_count()
        bar.stage("judging", total=opened or None, live=lambda: str(sweep.doing))

        def say(line: str) -> None:
            bar.update(opened - sweep.open_count())
            bar.say(line)

        try:
            if args.max_checks != 0:
                sweep.run(args.max_checks, args.workers, args.cluster, say, deadline)
        except KeyboardInterrupt:
            interrupted = True
    if interrupted:  # the step under way is dropped: what is reported and kept is what was saved
        sweep = Sweep(sweep.space, sweep.bounds, sweep.out, sweep.lemmas, sweep.max_memory, sweep.work)
        sweep.resume()
    lines = [*sweep_lines(sweep), f"report page: {page_files(sweep.out)[0]}"]
    timed_out = deadline is not None and time.monotonic() >= deadline and sweep.open_count() > 0
    if interrupted:
        under_way = f" and {len(sweep.absorbed)} lemmas closed from the next" if sweep.absorbed else ""
        lines.append(f"INTERRUPTED: {len(sweep.checks)} checks{under_way} finished and saved in {sweep.json_path}; "
                     "the same command resumes")  # fmt: skip
    elif timed_out:
        lines.append(f"stopped after --max-time {args.max_time}: {len(sweep.checks)} checks saved in "
                     f"{sweep.json_path}; the same command resumes")  # fmt: skip
    emit(lines)  # the verdicts before any file: a full disk does not hide them
    if not interrupted:
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


def _plan_line(sweep: Any, max_time: float | None) -> str:
    """The first line: what is swept, what a check costs, when the run stops."""
    b = sweep.bounds
    lo, hi = b.robots
    robots = str(lo) if lo == hi else f"{lo}..{hi}"
    stop = "no time limit" if max_time is None else f"stops after {_duration_text(max_time)} (--max-time)"
    return (
        f"sweep of {sweep.space.base.name}: {len(sweep.space.names)} options varied, {sweep.judgements():,} "
        f"judgements ({len(sweep.lemmas)} lemmas); each check explores robots {robots} in "
        f"{b.window[0]}x{b.window[1]}; memory up to {format_size(sweep.max_memory)}; {stop}; every step saved "
        f"in {sweep.out}"
    )


def parse_duration(text: str) -> float | None:
    """``--max-time``: ``90``, ``90s``, ``10m``, ``1.5h`` -> seconds; ``none``: no limit."""
    if text.strip().lower() == "none":
        return None
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([smh]?)\s*", text.lower())
    value = float(m.group(1)) * {"": 1, "s": 1, "m": 60, "h": 3600}[m.group(2)] if m else math.nan
    if not (math.isfinite(value) and 0 < value <= 7 * 86_400):
        raise InvalidInput(f"max-time={text!r}: expected a duration such as 90s, 10m or 2h (at most a week), or none")
    return value


def _duration_text(seconds: float) -> str:
    if seconds >= 3600 and seconds % 3600 == 0:
        return f"{seconds / 3600:g} h"
    if seconds >= 60 and seconds % 60 == 0:
        return f"{seconds / 60:g} min"
    return f"{seconds:g} s"


def _command(args: argparse.Namespace, name: str) -> str:
    """The command that resumes this sweep and rewrites its page (the settings that name the sweep)."""
    parts = ["fatline sweep", shlex.quote(str(args.model or name))]
    for flag in ("vary", "lemma", "robots", "window", "bound", "q", "max_states", "out"):
        value = getattr(args, flag)
        if value is not None and not (flag == "out" and str(value) == "sweeps"):
            parts.append(f"--{flag.replace('_', '-')} {shlex.quote(str(value))}")
    return " ".join(parts)


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
    p = add_command(
        sub,
        "sweep",
        "each lemma over the whole product of readings, covered by counterexamples",
        exit_codes(
            "every lemma holds within bounds under every reading",
            "a lemma is refuted under some reading (covering counterexamples)",
            "readings still open (--max-time, --max-checks) or some verdict INCONCLUSIVE",
            kept=True,
        ),
    )
    add_model_argument(p)
    p.add_argument(
        "--vary",
        help="comma-separated options to vary (default: every option but the scheduler; the others as in the model), "
        "and parameters the model's scheduler or rule set declares, as SEAM.NAME (scheduler.k; default: those that "
        "declare their values): each combination of their values is a sweep of its own, in OUT/MODEL/SEAM.NAME-VALUE",
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
        help="stop after this many checks (default: until every combination is judged or --max-time); rerun "
        "to go on; 0: no check, only the report page from what is saved. A check is not cheap: at the default "
        "bounds (robots 2..3, window 7x7) its searches take about 20 s, and closing what it decides over the "
        "other readings (replaying its counterexamples, spreading what holds) from seconds to minutes",
    )
    p.add_argument(
        "--max-time",
        default=DEFAULT_MAX_TIME,
        help=f"stop after this long, between two steps (a step is one lemma closed from one check, saved as it "
        f"finishes), e.g. 90s, 30m, 2h, or none (default {DEFAULT_MAX_TIME}: a first answer, every lemma's "
        "counts so far); the same command resumes. With a limit, each closure is bounded too (20,000 replays: "
        "the readings it has not shown alike stay open for later checks); with none, closures run to the end "
        "and close far more per check (the shipped sweeps)",
    )
    p.add_argument(
        "--max-memory",
        help="memory the run may use, e.g. 4G (default: half of this machine's): a check's search gets half, "
        "the remembered replays and a closure's sets of readings a quarter each (a closure that would need "
        "more leaves those readings open for later checks)",
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
