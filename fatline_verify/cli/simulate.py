"""``fatline simulate``: one swarm under a seeded, fair random scheduler."""

from __future__ import annotations

import argparse
from typing import Any

from ..options import Scheduler
from ..outputs import Kind, claim_file
from ..simulate import Outcome, simulate
from ..text import trace_lines
from ..trace import run_to_json, write_trace
from .common import (
    EXIT_FOUND,
    EXIT_OK,
    add_command,
    add_force,
    add_model_argument,
    emit,
    integer,
    model_arg,
    parse_init,
)

MAX_ROUNDS = 1_000_000


def cmd_simulate(args: argparse.Namespace) -> int:
    trace = claim_file(args.trace, name="trace", kind=Kind.TRACE, force=args.force) if args.trace is not None else None
    model = model_arg(args.model)
    initial = parse_init(args.init, model)
    scheduler = Scheduler(args.scheduler) if args.scheduler else model.options.scheduler
    run = simulate(initial, model, scheduler=scheduler, seed=args.seed, max_rounds=args.rounds)
    doc = run_to_json(run, {"tool": "fatline simulate", "scheduler": str(scheduler), "seed": args.seed})
    lines = [f"model {model.describe()}", f"scheduler {scheduler}, seed {args.seed}, at most {args.rounds} rounds"]
    lines += trace_lines(doc)
    if trace is not None:
        write_trace(doc, trace)
        lines.append(f"trace written to {trace}")
    emit(lines)
    return EXIT_FOUND if run.outcome in (Outcome.VIOLATION, Outcome.DEADLOCK) else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(sub, "simulate", "run one swarm under a seeded, fair random scheduler")
    add_model_argument(p)
    p.add_argument(
        "--init", required=True, help='initial centres in robot radii, e.g. "0,0 3,0 5/2,3" or "0,0 3.3,-2.2"'
    )
    p.add_argument("--scheduler", choices=[s.value for s in Scheduler], help="override the model's scheduler")
    p.add_argument("--seed", type=integer("seed", 0, 2**63 - 1), default=0, help="random seed (default 0)")
    p.add_argument(
        "--rounds",
        type=integer("rounds", 0, MAX_ROUNDS),
        default=100,
        help="stop after this many rounds (default 100)",
    )
    p.add_argument("--trace", help="write the run as a trace JSON file")
    add_force(p)
    p.set_defaults(handler=cmd_simulate)
