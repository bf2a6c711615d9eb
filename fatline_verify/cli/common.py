"""What every command shares: exit codes, one-line argument errors, value types, ``--init``.

Every value is checked here, at the boundary, before any work starts: a bad one is one line
``fatline: error: name='value': expected ...`` and exit 2.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import sys
import textwrap
from collections.abc import Callable, Sequence
from typing import Any, NoReturn

from ..errors import InvalidInput
from ..model.config import Model, load_model
from ..model.numbers import parse_number
from ..model.swarm import State

EXIT_OK, EXIT_FOUND, EXIT_BAD, EXIT_INCONCLUSIVE, EXIT_INTERRUPTED = 0, 1, 2, 3, 130

EPILOG = """exit codes:
  0    everything asked holds (check: every lemma HOLDS_WITHIN_BOUNDS; simulate: no violation and no
       deadlock; replay, regress: every trace reproduces)
  1    a violation or deadlock was found, or a trace did not reproduce (replay, regress: or could not be
       replayed under --model)
  2    bad input (malformed model, trace or argument) or an internal error
  3    check, prove and sweep: nothing violated, but some verdict is INCONCLUSIVE (a bound was hit)
  130  interrupted (Ctrl-C); what was finished is kept
"""


class ArgumentError(Exception):
    """A command-line error argparse found; rendered as one line."""


_REWRITES: list[tuple[re.Pattern[str], Callable[[re.Match[str]], str]]] = [
    (  # an option (--engine) or a positional (COMMAND) with a choice it does not offer
        re.compile(r"^argument (?:-\w, )?-{0,2}([\w-]+)(?:/[^:]*)?: invalid choice: '(.*)' \(choose from (.*)\)$"),
        lambda m: f"{m[1]}={m[2]!r}: expected one of {m[3].replace(chr(39), '')}",
    ),
    (
        re.compile(r"^argument (?:-\w, )?--?([\w-]+)(?:/[^:]*)?: invalid \w+ value: '(.*)'$"),
        lambda m: f"{m[1]}={m[2]!r}: expected a number",
    ),
    (re.compile(r"^argument (?:-\w, )?--?[\w-]+(?:/[^:]*)?: (\S+=.*)$"), lambda m: m[1]),
    (
        re.compile(r"^argument (?:-\w, )?--?([\w-]+)(?:/[^:]*)?: expected one argument$"),
        lambda m: f"{m[1]}: no value given; expected one after --{m[1]}",
    ),
    (
        re.compile(r"^the following arguments are required: (.*)$"),
        lambda m: f"{m[1].split(',')[0].lstrip('-')}: missing; expected {m[1]}",
    ),
    (
        re.compile(r"^unrecognized arguments: (.*)$"),
        lambda m: f"argument={m[1].split()[0]!r}: unknown; expected an option listed by --help",
    ),
]


ECHO = 200
"""The most characters of one value an error line repeats."""
LINE = 1000
"""The most characters of one error line."""


def error_line(message: str) -> str:
    """The one line every error is printed as (a value longer than :data:`ECHO` characters cut short)."""
    words = [
        w if len(w) <= ECHO else f"{w[: ECHO - 20]}...({len(w):,} characters)...{w[-20:]}" for w in message.split()
    ]
    line = f"fatline: error: {' '.join(words)}"
    return line if len(line) <= LINE else f"{line[:LINE]}...(+{len(line) - LINE:,} characters)"


def cores() -> int:
    """The processor cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def check_cores(name: str, value: int, why: str, instead: str = "") -> None:
    """Refuse (not cap), before any work, ``--NAME VALUE`` processes or solvers at once above this machine's
    cores: they would only share the cores; ``why`` says what that costs, ``instead`` what to do for more."""
    if value > cores():
        raise InvalidInput(
            f"{name}={value}: expected at most {cores()}, the cores of this machine ({why})"
            + (f"; {instead}" if instead else "")
        )


def check_workers(workers: int, cluster: str | None) -> None:
    """``--workers`` of ``check`` and ``sweep``: local worker processes, each holding its own copy of the
    search (a ``--cluster`` brings its own machines)."""
    if cluster is None:
        check_cores(
            "workers",
            workers,
            "more processes than cores only share them",
            "for more, --cluster with the workers of several machines",
        )


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors (usage only with ``--help``) and the exit codes in the epilog."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", argparse.RawDescriptionHelpFormatter)
        kwargs.setdefault("epilog", EPILOG)
        super().__init__(*args, **kwargs)

    def error(self, message: str) -> NoReturn:
        for pattern, rewrite in _REWRITES:
            m = pattern.match(message)
            if m:
                raise ArgumentError(rewrite(m))
        raise ArgumentError(message)


def exit_codes(ok: str, found: str | None = None, inconclusive: str | None = None, kept: bool = False) -> str:
    """One command's ``--help`` epilog: the exit codes it can return, each said for it (``found``: exit 1,
    ``inconclusive``: exit 3; ``kept``: an interrupt keeps what was finished). Exit 2 and 130 come from
    :func:`fatline_verify.cli.main` for every command."""
    rows = [(EXIT_OK, ok), (EXIT_FOUND, found)]
    rows += [(EXIT_BAD, "bad input (model, trace or argument: one line, before any work) or an internal error")]
    rows += [(EXIT_INCONCLUSIVE, inconclusive)]
    rows += [(EXIT_INTERRUPTED, "interrupted (Ctrl-C)" + ("; what was finished is kept" if kept else ""))]
    lines = ["exit codes:"]
    for code, text in rows:
        if text is not None:
            lines.append(textwrap.fill(text, 100, initial_indent=f"  {code:<5}", subsequent_indent=" " * 7))
    return "\n".join(lines) + "\n"


def add_command(sub: Any, name: str, help_text: str, exits: str) -> Parser:
    """A subcommand whose description is its help line and whose epilog is its own exit codes (``exits``:
    :func:`exit_codes`)."""
    return sub.add_parser(name, help=help_text, description=help_text, epilog=exits)  # type: ignore[no-any-return]


def add_model_argument(p: argparse.ArgumentParser, default: str = "paper") -> None:
    p.add_argument("model", nargs="?", default=default, help=f"model file or shipped model name (default: {default})")


def add_bounds(p: argparse.ArgumentParser) -> None:
    """``--robots`` and ``--window``, defaulting to the model's bounds (``check``, ``reach``)."""
    p.add_argument("--robots", help="robot count or range, e.g. 3 or 2..4 (default: the model's bounds)")
    p.add_argument("--window", help="WIDTHxHEIGHT lattice points, e.g. 9x9 (default: the model's bounds)")


def add_force(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--force", action="store_true", help="overwrite output files that are not earlier outputs of this tool"
    )


# --- value types: each names the flag and what was expected ----------------------------------------------


def integer(name: str, low: int, high: int | None = None, what: str = "") -> Callable[[str], int]:
    """An argparse type: a whole number in ``[low, high]``."""

    def parse(text: str) -> int:
        try:
            value = int(text.strip())
        except ValueError:
            value = None
        if value is None or value < low or (high is not None and value > high):
            span = f"from {low} to {high}" if high is not None else f"at least {low}"
            raise argparse.ArgumentTypeError(f"{name}={text!r}: expected a whole number {span}{what}")
        return value

    return parse


def seconds(name: str, high: float = 86_400.0) -> Callable[[str], float]:
    """An argparse type: a positive, finite number of seconds (at most a day)."""

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not (math.isfinite(value) and 0 < value <= high):
            raise argparse.ArgumentTypeError(
                f"{name}={text!r}: expected a positive, finite number of seconds up to {high:g}"
            )
        return value

    return parse


def nonempty(name: str, what: str) -> Callable[[str], str]:
    """An argparse type: any text but empty or blank."""

    def parse(text: str) -> str:
        if not text.strip():
            raise argparse.ArgumentTypeError(f"{name}={text!r}: expected {what}")
        return text

    return parse


# --- output ------------------------------------------------------------------------------------------------


def emit(lines: Sequence[str]) -> None:
    """Print result lines on stdout."""
    sys.stdout.write("\n".join(lines) + ("\n" if lines else ""))
    sys.stdout.flush()


def model_arg(spec: str) -> Model:
    """The model a command names (a file or a shipped model); bad ones are one line."""
    if not str(spec).strip():
        raise InvalidInput("model='': expected a model file or a shipped model name")
    return load_model(spec)


def parse_init(text: str, model: Model) -> State:
    """``"0,0 3.3,-2.2 5/2,3"`` (robot radii; integers, fractions or decimals, exactly) to lattice positions."""
    points = []
    for token in text.split():
        parts = token.split(",")
        if len(parts) != 2:
            raise InvalidInput(f"init={token!r}: expected a position x,y such as 3,0 or 5/2,-1 or 3.3,-2.2")
        try:
            x = parse_number(parts[0], name="init x", allow_decimal=True)
            y = parse_number(parts[1], name="init y", allow_decimal=True)
        except ValueError:
            raise InvalidInput(
                f"init={token!r}: expected a position x,y of integers, fractions or decimals such as 3,0 or "
                "5/2,-1 or 3.3,-2.2"
            ) from None
        points.append(model.to_lattice((x, y)))
    if not points:
        raise InvalidInput(f"init={text!r}: expected at least one position x,y")
    return tuple(points)
