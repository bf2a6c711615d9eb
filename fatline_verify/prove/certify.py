"""``python -m fatline_verify.prove.certify [--jobs N] [DIR...]`` (``--help``: the usage).

First every linear certificate a ``results.json`` under the directories (default ``proofs``) records:
one that is missing is regenerated (:mod:`fatline_verify.prove.regenerate`: its obligation solved
again, both files held to the row's digests), one that is there is held to its row's digest. Then every
linear certificate (``*.linear.smt2``) under the directories is checked against the obligation file
beside it, from the two files alone (:mod:`fatline_verify.prove.smt.certificates`): the relaxed part is
the obligation, every cut is implied by the atom its Boolean stands for, and cvc5 finds the linear
problem unsat. Prints one line per certificate that fails and a count, and on stderr a progress line
every 10 seconds; ``--jobs N`` checks (and solves) N at once (each is independent). Exit 0 if every
one passed, 1 if one failed, 2 for a bad argument (a directory that does not exist, a bad ``--jobs``),
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


DESCRIPTION = """Regenerate the linear certificates the results.json files under the directories record and
that are missing (each obligation solved again; both files must match the digests its row recorded),
then check every linear certificate (*.linear.smt2) under the directories against the obligation
file beside it, from the two files alone: the relaxed part is the obligation, every cut is implied
by the atom its Boolean stands for, and cvc5 finds the linear problem unsat. Prints one line per
certificate that fails, then a count; on stderr a progress line every 10 s."""

EPILOG = """exit codes:
  0    every certificate checks from its own files (and every one the rows record is there, as recorded)
  1    a certificate failed, or is not as its row recorded (a line FAILED PATH: why for each)
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
    unmatched = _regenerated(dirs, jobs)
    failed, done, start, last = 0, 0, time.monotonic(), time.monotonic()
    files = sorted(p for d in dirs for p in d.rglob("*.linear.smt2"))
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
    return 1 if failed or unmatched else 0


def _regenerated(dirs: list[Path], jobs: int) -> int:
    """Every certificate the rows under ``dirs`` record: one that is there held to its row's digest, one
    that is missing regenerated (:func:`fatline_verify.prove.regenerate.regenerate`). Prints a line per
    failure (and returns how many); on stderr how many were regenerated."""
    from .digests import file_sha256
    from .regenerate import regenerate, wanted

    failures = 0

    def failed(path: Path, why: str) -> None:
        nonlocal failures
        failures += 1
        print(f"FAILED {path.as_posix()}: {why}", flush=True)

    rows = [w for d in dirs for results in sorted(d.rglob("results.json")) for w in wanted(results)]
    missing = [w for w in rows if not w.certificate.exists()]
    for w in rows:
        if w not in missing and file_sha256(w.certificate) != w.certificate_sha256:
            failed(w.certificate, f"not the certificate its row recorded ({w.key}): regenerate it (move it away)")
    if missing:
        print(f"certify: regenerating {len(missing)} certificates (each obligation solved again)", file=sys.stderr)
        placed = regenerate(missing, jobs, failed)
        print(f"certify: {placed} of {len(missing)} regenerated byte for byte", file=sys.stderr, flush=True)
    return failures


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
