"""``fatline regress``: replay every trace of directories (the corpus, a user's own) for CI, with JUnit XML.

What ``fatline replay`` does for the files it is given, over whole directories, with a report CI
systems read: every ``*.json`` under each DIR (recursively, hidden paths left out) is a trace, except
files another fatline command wrote (a ``results.json``, a check's ``--json``: their ``"format"`` says
so), which are skipped and counted. Every trace is loaded and schema-checked, and its model resolved,
before the first replay: a directory that does not exist or holds no trace, a malformed trace, or a
``--junit`` path that cannot be written or holds a file this tool did not write is one line and exit 2
before any work.

Each trace is then replayed by :func:`fatline_verify.trace.check_replay` (under ``--model`` with other
readings, as ``fatline replay --model`` does: the counterexample gone, or still there with other
values); a trace that does not reproduce is a ``<failure>`` whose message is the first differing value
(the :class:`~fatline_verify.errors.TraceDidNotReproduce` message), one whose recorded step the model
refuses an ``<error>``. Exit 0 when every trace reproduces, 1 when some did not.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..errors import FatlineError, InvalidInput, TraceDidNotReproduce
from ..junit import Case, Outcome, Suite, claim_junit, totals, write_junit
from ..model.config import Model
from ..outputs import Kind, Output, distinct_outputs, read_json
from ..progress import Progress
from ..trace.traces import check_replay, differences, load_trace, replay, trace_model
from .common import EXIT_FOUND, EXIT_OK, add_command, add_force, emit, exit_codes, model_arg, nonempty
from .replay import _same_model, not_reproduced

OTHER_OUTPUTS = frozenset(k.value for k in Kind if k is not Kind.TRACE)
"""The ``"format"`` of JSON files other fatline commands write: not traces, skipped."""


class Entry:
    """One trace to replay: its file, its name in the report, its document."""

    __slots__ = ("doc", "name", "path")

    def __init__(self, path: Path, name: str, doc: dict[str, Any]) -> None:
        self.path, self.name, self.doc = path, name, doc


def _files(arg: str) -> list[tuple[Path, str]]:
    """The ``*.json`` files of one argument (a directory, or one trace file), with their report names."""
    path = Path(arg)
    if path.is_file():
        return [(path, path.name)]
    if not path.is_dir():
        raise InvalidInput(f"dir={arg!r}: no such directory; expected a directory of trace files (*.json)")
    try:
        found = [
            (f, f.relative_to(path).as_posix())
            for f in path.rglob("*.json")
            if not any(part.startswith(".") for part in f.relative_to(path).parts) and f.is_file()
        ]
    except OSError as exc:
        raise InvalidInput(f"dir={arg!r}: cannot be read ({exc.__class__.__name__}: {exc.strerror})") from None
    return sorted(found, key=lambda item: item[1])


def collect(
    arg: str, files: list[tuple[Path, str]], override: Model | None, loaded: Callable[[str], None] | None = None
) -> tuple[list[Entry], int]:
    """Every trace of ``files`` (:func:`_files` of ``arg``), loaded, schema-checked and its model resolved
    (a bad one: one line, exit 2), and how many other fatline outputs were skipped; ``loaded(name)`` as
    each file is taken up (the progress of a load that takes a minute for 10,000 traces)."""
    entries, skipped = [], 0
    directory = Path(arg).is_dir()
    for path, name in files:
        if loaded is not None:
            loaded(name)
        try:
            doc = load_trace(path)
        except FatlineError:
            data = read_json(path) if directory else None  # a file named on its own must be a trace
            if data is not None and data.get("format") in OTHER_OUTPUTS:
                skipped += 1
                continue
            raise
        if override is None:
            try:
                trace_model(doc)
            except FatlineError as exc:
                raise InvalidInput(f"trace={str(path)!r}: {exc}") from None
        entries.append(Entry(path, name, doc))
    if not entries:
        others = f" ({skipped} other fatline output{'s' * (skipped != 1)} skipped)" if skipped else ""
        raise InvalidInput(
            f"dir={arg!r}: no trace files in it{others}; expected a directory of fatline traces (*.json)"
        )
    return entries, skipped


def difference(doc: dict[str, Any], override: Model | None) -> str | None:
    """Why ``doc`` does not reproduce (``None``: it does): the first differing value under its own model
    (or one with its readings), whether the counterexample is gone or still there under another."""
    if override is None or _same_model(doc, override):
        try:
            check_replay(doc, override)
        except TraceDidNotReproduce as exc:
            return str(exc)
        return None
    run = replay(doc, override)
    diffs = differences(doc, run)
    return not_reproduced(doc, run, diffs, override) if diffs else None


def replay_case(entry: Entry, override: Model | None, model_flag: str | None) -> Case:
    """One trace replayed, as a test case: ``classname`` its model, ``name`` its file, its seconds."""
    again = f"fatline replay {entry.path} -v" + (f" --model {model_flag}" if model_flag else "")
    classname = str(entry.doc["model"].get("name", "trace"))
    started = time.perf_counter()
    try:
        message = difference(entry.doc, override)
    except FatlineError as exc:  # a recorded step the model refuses to play (InvalidTrace)
        seconds = time.perf_counter() - started
        return Case(classname, entry.name, seconds, Outcome.ERROR, str(exc), exc.__class__.__name__, again)
    seconds = time.perf_counter() - started
    if message is None:
        return Case(classname, entry.name, seconds)
    return Case(classname, entry.name, seconds, Outcome.FAILURE, message, TraceDidNotReproduce.__name__, again)


def cmd_regress(args: argparse.Namespace) -> int:
    override = model_arg(args.model) if args.model is not None else None
    junit = claim_junit(args.junit, force=args.force) if args.junit is not None else None
    listed = [(arg, _files(arg)) for arg in args.dirs]
    under = f" under {override.name}" if override is not None else ""
    suites: list[Suite] = []
    lines: list[str] = []
    with Progress(enabled=not args.quiet, unit="traces") as bar:
        bar.stage("loading and checking traces", total=sum(len(files) for _, files in listed))
        groups = [(arg, *collect(arg, files, override, bar.step)) for arg, files in listed]
        traces = [("dir", entry.path) for _, entries, _ in groups for entry in entries]
        distinct_outputs([Output("junit", junit)], [*traces, *([("model", args.model)] if args.model else [])])
        started = time.perf_counter()
        bar.stage("replaying traces", total=sum(len(entries) for _, entries, _ in groups))
        for arg, entries, _ in groups:
            cases = []
            for entry in entries:
                case = replay_case(entry, override, args.model)
                cases.append(case)
                bar.step(entry.name)
                if case.outcome is Outcome.FAILURE:
                    lines.append(f"{entry.path}: DID NOT REPRODUCE{under}: {case.message}")
                elif case.outcome is Outcome.ERROR:
                    lines.append(f"{entry.path}: ERROR{under}: {case.message}")
            props = (("directory", arg), *((("model", override.name),) if override is not None else ()))
            suites.append(Suite(f"fatline regress {arg}{under}", tuple(cases), properties=props))
    seconds = time.perf_counter() - started

    count = totals(suites)
    bad = count[Outcome.FAILURE] + count[Outcome.ERROR]
    total = sum(count.values())
    skipped = sum(s for _, _, s in groups)
    where = f"{len(groups)} director{'y' if len(groups) == 1 else 'ies'}"
    summary = f"{total} trace{'s' * (total != 1)} in {where} replayed{under} in {seconds:.1f} s: "
    summary += f"{total - bad} reproduce, {count[Outcome.FAILURE]} did not"
    if count[Outcome.ERROR]:
        summary += f", {count[Outcome.ERROR]} could not be replayed"
    if skipped:
        summary += f" ({skipped} other fatline output{'s' * (skipped != 1)} skipped)"
    lines.append(summary)
    if junit is not None:
        write_junit(junit, suites, name="fatline regress " + " ".join(args.dirs) + under)
        lines.append(f"JUnit XML written to {junit}")
    emit(lines)
    return EXIT_FOUND if bad else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "regress",
        "replay every trace of directories (e.g. reports/traces) for CI; --junit writes JUnit XML",
        exit_codes("every trace reproduces", "a trace did not reproduce, or could not be replayed"),
    )
    p.add_argument(
        "dirs",
        nargs="+",
        metavar="DIR",
        help="directory of trace files (*.json, searched recursively; other fatline outputs skipped), or a trace",
    )
    p.add_argument(
        "--model",
        help="replay under this model instead of each trace's own: a trace that does not reproduce says whether "
        "its counterexample is gone under it or still there with other values",
    )
    p.add_argument(
        "--junit",
        metavar="FILE",
        type=nonempty("junit", "a file name for the JUnit XML report"),
        help="write a JUnit XML report: one test case per trace (classname its model, name its file, its time), "
        "a failure naming the first differing value",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    add_force(p)
    p.set_defaults(handler=cmd_regress)
