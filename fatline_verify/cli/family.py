"""What ``fatline reach`` and ``fatline synth`` share: the family's legs (``--with``), the lattice
(``--q``), the memory budget (``--max-memory``) and the checks of their bounds before any work."""

from __future__ import annotations

import argparse
from typing import Any

from ..errors import InvalidInput
from ..model.config import Model, parse_robots, parse_window
from .common import integer

MAX_Q = 8
"""The searches are in Python and every state of every initial configuration is kept: finer lattices
than this are out of reach of one machine at the robot counts that matter."""
DEFAULT_MODEL = "repaired"
"""The family's legs are the repaired rule set's (the paper's rules have no repairs: ``reach paper`` and
``synth paper`` are refused)."""


def add_family_arguments(p: argparse.ArgumentParser) -> None:
    """``--q``, ``--with`` and ``--max-memory``, as ``reach`` and ``synth`` read them."""
    p.add_argument("--q", type=integer("q", 1, MAX_Q), help="lattice points per radius (default: the model's q)")
    p.add_argument(
        "--with",
        dest="with_",
        metavar="KINDS",
        help="also legs beyond right and vertical, comma-separated: left-alone (the left leg guarded) and corner, "
        "their no-collision and connectivity obligations PROVED for every swarm size at q = 1 and 2 (fatline prove "
        "repaired --with left-alone,corner --q Q: 390 of 390), or left (unguarded: obligations VIOLATED, a what-if)",
    )
    p.add_argument(
        "--max-memory",
        help="memory the search may hold, e.g. 4G (default: half of this machine's); robot counts whose initial "
        "configurations alone would need more are refused before any work",
    )


def leg_kinds(text: str | None) -> frozenset[Any]:
    """The legs of ``--with``: the proved ones (right, vertical) and the what-if kinds named."""
    from ..repair.reach import PROVED, WHAT_IF, Kind, check_kinds

    if text is None:
        return PROVED
    names = [t.strip() for t in text.split(",")]
    allowed = [k.value for k in WHAT_IF]
    bad = [t for t in names if t not in allowed]
    if bad or not names:
        raise InvalidInput(f"with={text!r}: expected what-if leg kinds from {', '.join(allowed)}, comma-separated")
    check_kinds(names)
    return PROVED | frozenset(Kind(t) for t in names)


def refuse_unpacked(lo: int, hi: int, window: tuple[int, int]) -> None:
    """Refuse, before any work, a robot count whose states do not pack into 63 bits in ``window`` (the
    initial configurations are enumerated as the checker's keys)."""
    from ..model.lattice import KeyCodec

    for n in range(lo, hi + 1):
        try:
            KeyCodec(n, window)
        except ValueError:
            raise InvalidInput(
                f"window={window[0]}x{window[1]} with robots={n}: a state does not pack into 63 bits; expected a "
                "smaller window or fewer robots"
            ) from None


def family_bounds(
    args: argparse.Namespace, model: Model, per_start: int, most: tuple[int, str] | None = None
) -> tuple[int, int, tuple[int, int]]:
    """The robot counts and window of ``args`` (the model's bounds by default), refused before any work
    as one-line errors: more robots than ``most`` allows (the limit and why); states that do not pack; a
    lattice or window the checker refuses (:func:`~fatline_verify.check.checker.validate_resources`);
    initial configurations beyond ``--max-memory`` at ``per_start`` bytes each; a robot count with no
    initial configuration."""
    from ..check.checker import guard_starts, validate_resources
    from ..repair.reach import starts
    from ..resources import default_max_memory, parse_size

    budget = parse_size(args.max_memory) if args.max_memory is not None else default_max_memory()
    lo, hi = parse_robots(args.robots, error=InvalidInput) if args.robots is not None else model.bounds.robots
    if most is not None and hi > most[0]:
        raise InvalidInput(f"robots={hi}: expected at most {most[0]} ({most[1]})")
    window = parse_window(args.window, error=InvalidInput) if args.window is not None else model.bounds.window
    refuse_unpacked(lo, hi, window)
    validate_resources(model, (lo, hi), window)
    name = "--max-memory" if args.max_memory is not None else "half this machine's memory"
    guard_starts(model, (lo, hi), window, budget, per_start, name)
    empty = [n for n in range(lo, hi + 1) if not starts(model, n, window)]
    if empty:
        raise InvalidInput(
            f"window={window[0]}x{window[1]}: no initial configuration of {empty[0]} robots fits it at "
            f"q={model.parameters.q} (lattice points, {model.parameters.q} per radius); expected a larger --window"
        )
    return lo, hi, window


__all__ = ["DEFAULT_MODEL", "MAX_Q", "add_family_arguments", "family_bounds", "leg_kinds", "refuse_unpacked"]
