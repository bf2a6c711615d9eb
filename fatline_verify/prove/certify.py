"""``python -m fatline_verify.prove.certify [--jobs N] [DIR...]`` (``--help``: the usage): check every linear
certificate (``*.linear.smt2``) under the directories (default ``proofs``) against the obligation file beside it,
from the two files alone (:mod:`fatline_verify.prove.smt.certificates`): the relaxed part is the
obligation, every cut is implied by the atom its Boolean stands for, and cvc5 finds the linear problem
unsat. Prints one line per certificate that fails and a count, and on stderr a progress line every 10
seconds; ``--jobs N`` checks N certificates at once (each check is independent). Exit 0 if every one
passed, 1 if one failed, 2 for a bad argument (a directory that does not exist, a bad ``--jobs``),
before any work."""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import NoReturn, TypeVar

T = TypeVar("T")
R = TypeVar("R")

PROGRESS_EVERY = 10.0
"""Seconds between progress lines on stderr."""


def _check(path: Path) -> tuple[str, bool, str]:
    from .smt.certificates import check_certificate

    got = check_certificate(path)
    return got.path, got.ok, got.why


def _usage(message: str) -> int:
    print(f"fatline: certify: {message}", file=sys.stderr)
    return 2


class _BadArgument(Exception):
    """An argument argparse refused: one line, exit 2 (no usage text but with ``--help``)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        raise _BadArgument(message)


DESCRIPTION = """Check every linear certificate (*.linear.smt2) under the directories against the obligation
file beside it, from the two files alone: the relaxed part is the obligation, every cut is implied
by the atom its Boolean stands for, and cvc5 finds the linear problem unsat. Prints one line per
certificate that fails, then a count; on stderr a progress line every 10 s."""

EPILOG = """exit codes:
  0    every certificate checks from its own files
  1    a certificate failed (a line FAILED PATH: why for each)
  2    a bad argument (a directory that does not exist, a bad --jobs), before any work
"""


def build_parser() -> argparse.ArgumentParser:
    """The command line: ``[--jobs N] [DIR...]``, with ``--help``."""
    p = _Parser(
        prog="python -m fatline_verify.prove.certify",
        description=DESCRIPTION,
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("dirs", nargs="*", metavar="DIR", help="directories searched recursively (default: proofs)")
    p.add_argument("--jobs", default="1", metavar="N", help="certificates checked at once (default 1)")
    return p


def main(argv: list[str] | None = None) -> int:
    try:
        parsed = build_parser().parse_args(sys.argv[1:] if argv is None else argv)
    except _BadArgument as exc:
        return _usage(str(exc))
    except SystemExit as exc:  # --help
        return int(exc.code or 0)
    value = parsed.jobs
    if not value.isdigit() or int(value) < 1:
        return _usage(f"--jobs {value or '(missing)'}: expected a positive whole number of processes")
    jobs = int(value)
    dirs = [Path(a) for a in parsed.dirs] or [Path("proofs")]
    for d in dirs:
        if not d.is_dir():
            return _usage(f"{d.as_posix()}: no such directory; expected a directory of proofs")
    files = sorted(p for d in dirs for p in d.rglob("*.linear.smt2"))
    failed, done, start, last = 0, 0, time.monotonic(), time.monotonic()
    with ProcessPoolExecutor(jobs) if jobs > 1 else _Inline() as pool:
        for where, ok, why in pool.map(_check, files):
            done += 1
            if not ok:
                failed += 1
                print(f"FAILED {where}: {why}", flush=True)
            if time.monotonic() - last >= PROGRESS_EVERY:
                last = time.monotonic()
                print(
                    f"certify: {done} of {len(files)} checked, {failed} failed, {last - start:.0f} s",
                    file=sys.stderr,
                    flush=True,
                )
    print(f"{len(files) - failed} of {len(files)} certificates check from their own files (atoms, cuts, cvc5)")
    return 1 if failed else 0


class _Inline:
    """``map`` in this process (``--jobs 1``): no pool to start."""

    def __enter__(self) -> _Inline:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def map(self, fn: Callable[[T], R], items: Iterable[T]) -> Iterator[R]:
        return (fn(x) for x in items)


if __name__ == "__main__":
    sys.exit(main())
