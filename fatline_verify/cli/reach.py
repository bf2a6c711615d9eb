"""``fatline reach``: whether *any* rule set of the repaired family could bring each small swarm to a line."""

from __future__ import annotations

import argparse
from typing import Any

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

BYTES_PER_START = 2048
"""Memory the search holds per initial configuration (Python states, their successors and distances:
about 1.5 KB measured at 5 robots in 9x9), for the guard before any work."""
SHOWN = 10
"""Stuck configurations listed per robot count (``--json`` has them all)."""


def cmd_reach(args: argparse.Namespace) -> int:
    from ..repair.reach import refuse
    from ..repair.reach_text import reach_lines, reach_to_json
    from ..repair.search import reach

    model = model_arg(args.model)
    kinds = leg_kinds(args.with_)
    if args.q is not None:
        model = model.with_q(args.q)
    refuse(model)
    lo, hi, window = family_bounds(args, model, BYTES_PER_START)
    json_path = claim_file(args.json, name="json", kind=Kind.REACH, force=args.force) if args.json else None
    distinct_outputs([Output("json", json_path)], [("model", args.model)])

    results = []
    interrupted = False
    with Progress(enabled=not args.quiet, unit="states") as bar:
        try:
            for n in range(lo, hi + 1):  # progress per state expanded, per stuck configuration: not per count
                results.append(reach(model, n, window, kinds, witnesses=args.verify, progress=bar.follow))
        except KeyboardInterrupt:
            interrupted = True
    lines = reach_lines(model, args.model, kinds, window, results, shown=SHOWN)
    if interrupted:
        done = ", ".join(str(r.n) for r in results) or "none"
        lines.append(f"INTERRUPTED: robot counts finished: {done}; the rest was not searched")
    emit(lines)  # the verdicts first: a full disk does not hide them
    if json_path is not None and results:
        write_json(json_path, reach_to_json(model, kinds, window, results))
        emit([f"results written to {json_path}"])
    if interrupted:
        return EXIT_INTERRUPTED
    return EXIT_FOUND if any(r.stuck for r in results) else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "reach",
        "whether any rule set whose moves are the repaired family's legs could bring each small swarm to a line",
        exit_codes(
            "every initial configuration can be brought to a line",
            "some configuration cannot (listed as stuck)",
            kept=True,
        ),
    )
    add_model_argument(p, default=DEFAULT_MODEL)
    add_bounds(p)
    add_family_arguments(p)
    p.add_argument(
        "--verify",
        action="store_true",
        help="also replay a shortest way to a line from every configuration that has one, and search every stuck "
        "one again on its own (slower)",
    )
    p.add_argument(
        "--json", type=nonempty("json", "a file name for the JSON results"), help="write the results as JSON"
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    add_force(p)
    p.set_defaults(handler=cmd_reach)
