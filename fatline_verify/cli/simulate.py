"""``fatline simulate``: one swarm under a seeded, fair random scheduler, or an explicit schedule."""

from __future__ import annotations

import argparse
from dataclasses import replace
from typing import Any

from ..errors import InvalidInput
from ..outputs import Kind, Output, claim_file, distinct_outputs
from ..schedulers.activation import scheduler_named
from ..schedulers.systems import system_for
from ..text import plural, trace_lines
from ..trace.simulate import Outcome, parse_schedule, play_schedule, registered_violation, simulate
from ..trace.traces import run_to_json, write_trace
from .common import (
    EXIT_FOUND,
    EXIT_OK,
    add_command,
    add_force,
    add_model_argument,
    emit,
    exit_codes,
    integer,
    model_arg,
    parse_init,
)

MAX_ROUNDS = 1_000_000
MAX_Q = 1000
DEFAULT_SEED = 0
DEFAULT_ROUNDS = 100


def _random_only(args: argparse.Namespace) -> None:
    """``--seed`` and ``--rounds`` steer the random scheduler; with ``--schedule`` they would be
    silently meaningless, so combining them is bad input."""
    for flag, value in (("seed", args.seed), ("rounds", args.rounds)):
        if value is not None:
            raise InvalidInput(
                f"{flag}='{value}': has no effect with --schedule (the schedule fixes every round); "
                f"expected --{flag} or --schedule, not both"
            )


def cmd_simulate(args: argparse.Namespace) -> int:
    if args.schedule is not None:
        _random_only(args)
    trace = claim_file(args.trace, name="trace", kind=Kind.TRACE, force=args.force) if args.trace is not None else None
    distinct_outputs([Output("trace", trace)], [("model", args.model)])
    model = model_arg(args.model)
    if args.q is not None:  # the lattice the repaired rules shorten their legs on (1/q radius)
        model = model.with_q(args.q)
    initial = parse_init(args.init, model)
    if args.scheduler:  # the trace records the scheduler it ran under, so replay runs it again
        named = scheduler_named(args.scheduler, where="scheduler")
        if named != model.options.scheduler:  # its own parameters at their defaults, not the model's scheduler's
            kept = tuple(seam for seam in model.settings if seam[0] != "scheduler")
            model = replace(model, options=model.options.with_(scheduler=named), settings=kept)
    scheduler = model.options.scheduler
    word = system_for(model).step_word
    lines = [f"model {model.describe()}"]
    if args.schedule is not None:
        rounds = parse_schedule(args.schedule, len(initial), scheduler, model)
        run = play_schedule(initial, model, rounds)
        origin = {"tool": "fatline simulate", "scheduler": str(scheduler), "schedule": args.schedule}
        lines.append(
            f"scheduler {scheduler}, schedule {args.schedule!r}: {len(rounds)} {word}{'s' if len(rounds) != 1 else ''}"
        )
    else:
        seed = DEFAULT_SEED if args.seed is None else args.seed
        max_rounds = DEFAULT_ROUNDS if args.rounds is None else args.rounds
        run = simulate(initial, model, seed=seed, max_rounds=max_rounds)
        origin = {"tool": "fatline simulate", "scheduler": str(scheduler), "seed": seed}
        lines.append(f"scheduler {scheduler}, seed {seed}, at most {plural(max_rounds, word)}")
    focus = None
    found = registered_violation(run)  # a registered step lemma (a plug-in's, in-family): the run up to it
    if found is not None and (run.outcome is not Outcome.VIOLATION or len(found[0].rounds) < len(run.rounds)):
        run, focus = found
    doc = run_to_json(run, origin, focus)
    lines += trace_lines(doc)
    if args.schedule is not None and len(run.rounds) < len(rounds):
        rest = len(rounds) - len(run.rounds)
        lines.append(f"the remaining {rest} scheduled {word}{'s' if rest != 1 else ''} were not played")
    emit(lines)  # the run first: a full disk does not hide it
    if trace is not None:
        write_trace(doc, trace)
        emit([f"trace written to {trace}"])
    return EXIT_FOUND if focus or run.outcome in (Outcome.VIOLATION, Outcome.DEADLOCK) else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "simulate",
        "run one swarm under a seeded, fair random scheduler, or play an explicit schedule",
        exit_codes("the run ends without a violation or a deadlock", "a violation or a deadlock"),
    )
    add_model_argument(p)
    p.add_argument(
        "--init", required=True, help='initial centres in robot radii, e.g. "0,0 3,0 5/2,3" or "0,0 3.3,-2.2"'
    )
    p.add_argument(
        "--scheduler",
        metavar="NAME",
        help="override the model's scheduler: ssync, fsync, centralized, async or a registered one (a plug-in's; "
        "with --schedule: the rule every round is checked against)",
    )
    p.add_argument(
        "--schedule",
        metavar="STEPS",
        help="play exactly these steps instead of the random scheduler, separated by ';'. Round schedulers: "
        "activation sets, robots (indices in --init order, from 0) separated by ',', 'all' for every robot, "
        'e.g. "0;1,2;all"; an activated robot that would not move stays; checked against the scheduler '
        "before anything runs: centralized one robot a round, fsync every robot, ssync any non-empty set. "
        'async: events, e.g. "L0;M0;L1;M0;M1": L<i> robot i looks and computes on the current positions, '
        "M<i> it takes one of async_steps move steps, S<i> it ends its move early (motion=non-rigid). The "
        "run stops early only at a violation; past the goal or a deadlock the remaining steps are still "
        "played. Not combinable with --seed or --rounds",
    )
    p.add_argument(
        "--seed",
        type=integer("seed", 0, 2**63 - 1),
        default=None,
        help=f"random seed (default {DEFAULT_SEED}; not with --schedule)",
    )
    p.add_argument(
        "--rounds",
        type=integer("rounds", 0, MAX_ROUNDS),
        default=None,
        help=f"stop after this many rounds, or events under async (default {DEFAULT_ROUNDS}; not with --schedule)",
    )
    p.add_argument(
        "--q",
        type=integer("q", 1, MAX_Q),
        help="lattice points per radius (default: the model's): what a move may be shortened to, as in fatline check "
        "--q (positions need not lie on it)",
    )
    p.add_argument("--trace", help="write the run as a trace JSON file")
    add_force(p)
    p.set_defaults(handler=cmd_simulate)
