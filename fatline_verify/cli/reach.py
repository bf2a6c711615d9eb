"""``fatline reach``: whether *any* rule set of the repaired family could bring each small swarm to a line."""

from __future__ import annotations

import argparse
from typing import Any

from ..errors import InvalidInput
from ..model.config import parse_robots, parse_window
from ..outputs import Kind, claim_file, write_json
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
    integer,
    model_arg,
    nonempty,
)

MAX_Q = 8
"""The search is in Python and every state of every initial configuration is kept: finer lattices
than this are out of reach of one machine at the robot counts that matter."""
BYTES_PER_START = 2048
"""Memory the search holds per initial configuration (Python states, their successors and distances:
about 1.5 KB measured at 5 robots in 9x9), for the guard before any work."""

DEFAULT_MODEL = "repaired"
"""The family's legs are the repaired rule set's (the paper's rules have no repairs: ``reach paper`` is refused)."""
SHOWN = 10
"""Stuck configurations listed per robot count (``--json`` has them all)."""


def _kinds(text: str | None) -> frozenset[Any]:
    from ..repair.reach import PROVED, WHAT_IF, Kind

    if text is None:
        return PROVED
    names = [t.strip() for t in text.split(",")]
    allowed = [k.value for k in WHAT_IF]
    bad = [t for t in names if t not in allowed]
    if bad or not names:
        raise InvalidInput(f"with={text!r}: expected what-if leg kinds from {', '.join(allowed)}, comma-separated")
    return PROVED | frozenset(Kind(t) for t in names)



def refuse_unpacked(lo: int, hi: int, window: tuple[int, int]) -> None:
    """Refuse, before any work, a robot count whose states do not pack into 63 bits in ``window`` (the
    initial configurations are enumerated as the checker's keys): ``reach`` and ``synth`` alike."""
    from ..model.lattice import KeyCodec

    for n in range(lo, hi + 1):
        try:
            KeyCodec(n, window)
        except ValueError:
            raise InvalidInput(
                f"window={window[0]}x{window[1]} with robots={n}: a state does not pack into 63 bits; expected a "
                "smaller window or fewer robots"
            ) from None

def cmd_reach(args: argparse.Namespace) -> int:
    from ..check.checker import guard_starts, validate_resources
    from ..repair.reach import reach, refuse, starts
    from ..repair.reach_text import reach_lines, reach_to_json
    from ..resources import default_max_memory

    model = model_arg(args.model)
    kinds = _kinds(args.with_)
    if args.q is not None:
        model = model.with_q(args.q)
    refuse(model)
    lo, hi = parse_robots(args.robots, error=InvalidInput) if args.robots is not None else model.bounds.robots
    window = parse_window(args.window, error=InvalidInput) if args.window is not None else model.bounds.window
    refuse_unpacked(lo, hi, window)
    validate_resources(model, (lo, hi), window)
    guard_starts(model, (lo, hi), window, default_max_memory(), BYTES_PER_START, "half this machine's memory")
    empty = [n for n in range(lo, hi + 1) if not starts(model, n, window)]
    if empty:
        raise InvalidInput(
            f"window={window[0]}x{window[1]}: no initial configuration of {empty[0]} robots fits it at "
            f"q={model.parameters.q} (lattice points, {model.parameters.q} per radius); expected a larger --window"
        )
    json_path = claim_file(args.json, name="json", kind=Kind.REACH, force=args.force) if args.json else None

    results = []
    interrupted = False
    with Progress(enabled=not args.quiet, unit="robot counts") as bar:
        bar.stage(f"{model.name}: reaching a line", total=hi - lo + 1)
        try:
            for n in range(lo, hi + 1):
                results.append(reach(model, n, window, kinds, witnesses=args.verify))
                bar.step(f"{n} robots: {len(results[-1].stuck):,} stuck")
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
    )
    add_model_argument(p, default=DEFAULT_MODEL)
    add_bounds(p)
    p.add_argument("--q", type=integer("q", 1, MAX_Q), help="lattice points per radius (default: the model's q)")
    p.add_argument(
        "--with",
        dest="with_",
        metavar="KINDS",
        help="also what-if legs no proof covers: left, corner (comma-separated)",
    )
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
