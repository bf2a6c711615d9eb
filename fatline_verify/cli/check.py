"""``fatline check``: every lemma on every small swarm and every activation set, within stated bounds."""

from __future__ import annotations

import argparse
import contextlib
from pathlib import Path
from typing import Any

from ..errors import InvalidInput
from ..junit import check_suites, claim_junit, write_junit
from ..model.config import parse_robots, parse_window
from ..outputs import Kind, Output, claim_dir, claim_file, claim_files, distinct_outputs, write_json
from ..progress import Progress
from ..resources import parse_size
from ..schedulers.base import ENGINES
from ..text import check_lines
from .common import (
    EXIT_FOUND,
    EXIT_INCONCLUSIVE,
    EXIT_INTERRUPTED,
    EXIT_OK,
    add_bounds,
    add_command,
    add_force,
    add_model_argument,
    check_workers,
    emit,
    exit_codes,
    integer,
    model_arg,
    nonempty,
)

MAX_Q = 1000
MAX_STATES_LIMIT = 10**10


def cmd_check(args: argparse.Namespace) -> int:
    from ..check.checker import CheckPlan, check_to_json, witness_path, witness_paths, write_witnesses
    from ..locks import holding

    model = model_arg(args.model)
    robots = parse_robots(args.robots, error=InvalidInput) if args.robots is not None else None
    window = parse_window(args.window, error=InvalidInput) if args.window is not None else None
    if args.q is not None:
        model = model.with_q(args.q)
    traces_dir = claim_dir(args.traces, name="traces")
    json_path = claim_file(args.json, name="json", kind=Kind.CHECK, force=args.force) if args.json else None
    junit_path = claim_junit(args.junit, force=args.force) if args.junit else None
    bound = parse_window(args.bound, error=InvalidInput, name="bound") if args.bound is not None else None
    max_memory = parse_size(args.max_memory) if args.max_memory is not None else None
    checkpoint = Path(args.checkpoint) if args.checkpoint is not None else None
    distinct_outputs(
        [
            Output("json", json_path),
            Output("junit", junit_path),
            Output("traces", traces_dir, directory=True),
            Output("checkpoint", checkpoint, directory=True),
        ],
        [("model", args.model)],
    )
    check_workers(args.workers, args.cluster)
    plan = CheckPlan.of(
        model,
        robots,
        window,
        args.max_states,
        args.engine,
        args.after_violation,
        bound=bound,
        max_memory=max_memory,
        workers=args.workers,
        cluster=args.cluster,
        checkpoint=checkpoint,
    )
    claim_files(witness_paths(plan, traces_dir, f"{model.name}-"), name="traces", kind=Kind.TRACE, force=args.force)

    done = []
    interrupted = False
    with contextlib.ExitStack() as held:
        if checkpoint is not None:  # one run at a time per checkpoint: a second is refused here, before any work
            held.enter_context(holding(checkpoint, name="checkpoint"))
        with Progress(enabled=not args.quiet, unit="states") as bar:
            try:
                for search in plan.searches(bar.follow):
                    done.append(search)
            except KeyboardInterrupt:
                interrupted = True
    result = plan.result(done)
    prefix = f"{model.name}-"
    paths = {
        (r.lemma.value, r.robots): witness_path(traces_dir, prefix, r.lemma, r.robots).as_posix()
        for r in result.results
        if r.witness is not None
    }
    lines = check_lines(result, paths)
    if interrupted:
        finished = ", ".join(str(s.robots) for s in result.stats) or "none"
        lines.append(f"INTERRUPTED: robot counts finished: {finished}; the rest was not searched")
    emit(lines)  # the verdicts before any file: a full disk does not hide them
    write_witnesses(result, traces_dir, prefix)
    if json_path is not None and (done or not interrupted):
        write_json(json_path, check_to_json(result, paths))
        emit([f"results written to {json_path}"])
    if junit_path is not None and (done or not interrupted):
        write_junit(junit_path, check_suites(result, paths), name=f"fatline check {model.name}")
        emit([f"JUnit XML written to {junit_path}"])
    if interrupted:
        return EXIT_INTERRUPTED
    if result.any_violated:
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if result.any_inconclusive else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "check",
        "check every lemma on every small swarm and every activation set (bounded)",
        exit_codes(
            "every lemma HOLDS_WITHIN_BOUNDS",
            "a lemma is VIOLATED (a witness trace for each)",
            "nothing violated, but some verdict is INCONCLUSIVE (a bound was hit)",
            kept=True,
        ),
    )
    add_model_argument(p)
    add_bounds(p)
    p.add_argument("--q", type=integer("q", 1, MAX_Q), help="lattice points per radius (default: the model's q)")
    p.add_argument(
        "--max-states",
        type=integer("max-states", 1, MAX_STATES_LIMIT),
        help="stop a search after this many states (default: the model's)",
    )
    p.add_argument(
        "--bound",
        help="WIDTHxHEIGHT lattice points that bound the exploration (default: the window); successors outside "
        "are counted as escaped",
    )
    p.add_argument(
        "--max-memory",
        help="memory the search's arrays may use, e.g. 4G (default: half of this machine's); the search stops "
        "cleanly before a level that would need more",
    )
    p.add_argument(
        "--engine",
        choices=list(ENGINES),
        default=None,
        help="exploration engine (default: compiled)",
    )
    p.add_argument(
        "--workers",
        type=integer("workers", 1, 1024),
        default=1,
        help="share the search among N worker processes on this machine (Dask; default 1: in this process)",
    )
    p.add_argument("--cluster", help="share the search among the workers of the Dask scheduler at tcp://HOST:PORT")
    p.add_argument(
        "--checkpoint",
        help="save the search to DIR after every level; the same command resumes from it",
    )
    p.add_argument(
        "--after-violation",
        choices=["stop", "continue"],
        default="stop",
        help="explore states reached through a violating round (default: stop)",
    )
    p.add_argument(
        "--json", type=nonempty("json", "a file name for the JSON results"), help="write the results as JSON"
    )
    p.add_argument(
        "--junit",
        metavar="FILE",
        type=nonempty("junit", "a file name for the JUnit XML report"),
        help="also write a JUnit XML report: one test case per lemma and robot count (VIOLATED a failure, "
        "INCONCLUSIVE skipped with its reason)",
    )
    p.add_argument(
        "--traces",
        default="traces",
        type=nonempty("traces", "a directory for witness traces"),
        help="directory for witness traces (default: traces)",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    add_force(p)
    p.set_defaults(handler=cmd_check)
