"""``fatline replay``: recompute traces from their initial positions and compare every recorded value.

Under the trace's own model (or ``--model`` with the same rule set, readings and parameters) any difference
means the file was changed: "recorded value differs". Under another model ``M`` a difference is a
finding about ``M``: "the counterexample is gone under M" when the recorded violation (or, for a
trace without one, the recorded outcome) no longer happens, else "still VIOLATED (lemma) under M;
recorded values differ: ...". Both are exit 1, and so is a trace the model cannot play (an asynchronous
schedule under a round scheduler): a line naming its file, "COULD NOT BE REPLAYED", after which the other
traces are still replayed. A file that is not a trace is bad input (exit 2), refused before any line is
printed; so is, under its own model, a trace whose model is no longer valid or a round its own scheduler
never plays (three robots under a scheduler of at most ``k = 2``).
"""

from __future__ import annotations

import argparse
from enum import StrEnum
from pathlib import Path
from typing import Any

from ..errors import FatlineError, ForbiddenRound
from ..model.config import Model
from ..model.seams import SEAMS
from ..outputs import Kind, claim_dir, claim_files, write_text
from ..text import plural, trace_lines
from ..trace.simulate import Run
from ..trace.traces import differences, load_trace, replay, run_to_json, trace_model
from .common import EXIT_FOUND, EXIT_OK, add_command, add_force, emit, exit_codes, model_arg


def _same_model(doc: dict[str, Any], model: Model) -> bool:
    """Whether ``model`` has the trace's own rule set, readings and parameters, its scheduler's and rule
    set's own included (its name may differ)."""
    try:
        own = trace_model(doc)
    except FatlineError:
        return False
    same = own.rules == model.rules and own.options == model.options and own.parameters == model.parameters
    return same and all(own.setting(seam) == model.setting(seam) for seam in SEAMS)


def _first(diffs: list[str]) -> str:
    more = f" (and {len(diffs) - 1} more)" if len(diffs) > 1 else ""
    return f"{diffs[0]}{more}"


def _word(doc: dict[str, Any]) -> str:
    """What a step of this trace is called: "event" for asynchronous traces, else "round"."""
    return "event" if any("event" in r for r in doc["rounds"]) else "round"


def _what_happens(again: dict[str, Any]) -> str:
    """The replayed outcome and every step that violates a lemma, for the "gone" message."""
    word = _word(again)
    violating = [
        f"{word} {k} violates {', '.join(dict.fromkeys(v['property'] for v in r['violations']))}"
        for k, r in enumerate(again["rounds"], start=1)
        if r["violations"]
    ]
    return f"replayed outcome {again['outcome']}; " + (
        "; ".join(violating) if violating else f"no {word} violates a lemma"
    )


class Change(StrEnum):
    """How a trace that did not reproduce differs (the summary of many traces counts each)."""

    CHANGED = "with a recorded value changed"
    """Under its own model: the file was changed."""
    GONE = "with the counterexample or recorded outcome gone"
    STILL = "with it still there, other values differing"


def _change(doc: dict[str, Any], run: Run, diffs: list[str], other: Model | None) -> tuple[Change, str]:
    """Why the trace did not reproduce, and which kind of difference that is: a changed value under its own
    model (``other`` is ``None``), or under another model whether its counterexample (or outcome) is gone
    or still there."""
    if other is None:
        return Change.CHANGED, _first(diffs)
    name = other.name
    recorded = doc.get("violation")
    again = run_to_json(run, focus=recorded["property"] if recorded else None)
    if recorded:
        if again["violation"] is None:
            k = recorded.get("round")
            where = "" if k is None else f" in {_word(doc)} {k}" if k else " in the initial configuration"
            return Change.GONE, (
                f"the counterexample is gone under {name}: {recorded['property']} is no longer violated{where} "
                f"({_what_happens(again)})"
            )
        return Change.STILL, (
            f"still VIOLATED ({recorded['property']}) under {name}; recorded values differ: {_first(diffs)}"
        )
    if again["outcome"] != doc["outcome"]:
        return Change.GONE, f"the recorded outcome {doc['outcome']} is gone under {name} ({_what_happens(again)})"
    return Change.STILL, f"still {doc['outcome']} under {name}; recorded values differ: {_first(diffs)}"


def not_reproduced(doc: dict[str, Any], run: Run, diffs: list[str], other: Model | None) -> str:
    """Why the trace did not reproduce (:func:`_change`'s text)."""
    return _change(doc, run, diffs, other)[1]


NOT_PLAYED = "could not be replayed"
"""A trace whose recorded steps the model refuses to play (an ASYNC schedule under a round scheduler)."""


def summary_line(total: int, counts: dict[str, int], under: str) -> str:
    """``392 traces replayed under certified: 0 reproduce; 387 did not (364 counterexample ... gone, 23
    still violated ...); 5 could not be replayed``."""
    differ = [f"{counts[c]} {c.value}" for c in Change if counts.get(c)]
    line = f"{plural(total, 'trace')} replayed{under}: {counts.get('reproduce', 0)} reproduce"
    if differ:
        line += f"; {sum(counts.get(c, 0) for c in Change)} did not ({', '.join(differ)})"
    if counts.get(NOT_PLAYED):
        line += f"; {counts[NOT_PLAYED]} {NOT_PLAYED}"
    return line


def cmd_replay(args: argparse.Namespace) -> int:
    """Every trace loaded and checked first (a bad file: one line, exit 2, before any replay); then each
    replayed, one line per trace naming its file: reproduces, did not reproduce, or could not be replayed
    under the model (exit 1 for either of the last two); a summary line after more than one."""
    override = model_arg(args.model) if args.model is not None else None
    picture = claim_dir(args.picture, name="picture") if args.picture is not None else None
    docs = [(name, load_trace(name)) for name in args.traces]
    played: dict[int, Run | FatlineError] = {}
    if override is None:  # each trace replays under its own model: a model no longer valid is bad input,
        for k, (name, doc) in enumerate(docs):  # and so is a round its own scheduler never plays
            try:
                trace_model(doc)
            except FatlineError as exc:
                raise type(exc)(f"{name}: {exc}") from None
            try:
                played[k] = replay(doc)
            except ForbiddenRound as exc:
                raise ForbiddenRound(f"{name}: {exc}") from None
            except FatlineError as exc:  # said in its line below, as under another model
                played[k] = exc
    under = f" under {override.name}" if override is not None else ""
    counts: dict[str, int] = {}
    for k, (name, doc) in enumerate(docs):
        try:
            done = played[k] if k in played else replay(doc, override)
            if isinstance(done, FatlineError):
                raise done
            run = done
            diffs = differences(doc, run)
        except FatlineError as exc:
            emit([f"{name}: {NOT_PLAYED.upper()}{under}: {exc}"])
            counts[NOT_PLAYED] = counts.get(NOT_PLAYED, 0) + 1
            continue
        other = override if override is not None and not _same_model(doc, override) else None
        if diffs:
            change, why = _change(doc, run, diffs, other)
            emit([f"{name}: DID NOT REPRODUCE: {why}"])
            counts[change] = counts.get(change, 0) + 1
            continue
        counts["reproduce"] = counts.get("reproduce", 0) + 1
        v = doc["violation"]
        word = _word(doc)
        what = f"{doc['outcome']}" + (f" ({v['property']} in {word} {v['round']})" if v else "")
        lines = [f"{name}: reproduces{under}: {plural(len(run.rounds), word)}, {what}"]
        if args.verbose:
            lines += ["  " + line for line in trace_lines(doc, override)]
        if picture is not None:
            from ..report.pictures import frames

            svgs = frames(run, doc)
            files = [picture / f"{Path(name).stem}-{k}.svg" for k in range(len(svgs))]
            claim_files(files, name="picture", kind=Kind.PAGE, force=args.force)
            for file, svg in zip(files, svgs, strict=True):
                write_text(file, svg)
            lines.append(f"  pictures written to {picture}")
        emit(lines)
    if len(docs) > 1:
        emit([summary_line(len(docs), counts, under)])
    return EXIT_OK if counts.get("reproduce", 0) == len(docs) else EXIT_FOUND


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "replay",
        "recompute traces from their initial positions and compare every recorded value",
        exit_codes("every trace reproduces", "a trace did not reproduce, or could not be replayed under --model"),
    )
    p.add_argument("traces", nargs="+", metavar="TRACE")
    p.add_argument(
        "--model",
        help="replay under this model instead of the trace's own: a trace that does not reproduce says whether "
        "its counterexample is gone under it or still there with other values",
    )
    p.add_argument("-v", "--verbose", action="store_true", help="print every round (or event)")
    p.add_argument("--picture", metavar="DIR", help="write one SVG picture per round (or event) of each trace into DIR")
    add_force(p)
    p.set_defaults(handler=cmd_replay)
