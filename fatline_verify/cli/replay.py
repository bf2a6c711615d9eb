"""``fatline replay``: recompute traces from their initial positions and compare every recorded value.

Under the trace's own model (or ``--model`` with the same rule set, readings and parameters) any difference
means the file was changed: "recorded value differs". Under another model ``M`` a difference is a
finding about ``M``: "the counterexample is gone under M" when the recorded violation (or, for a
trace without one, the recorded outcome) no longer happens, else "still VIOLATED (lemma) under M;
recorded values differ: ...". Both are exit 1.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from ..errors import FatlineError
from ..model.config import Model
from ..model.seams import SEAMS
from ..outputs import Kind, claim_dir, claim_files, write_text
from ..text import plural, trace_lines
from ..trace.simulate import Run
from ..trace.traces import differences, load_trace, replay, run_to_json, trace_model
from .common import EXIT_BAD, EXIT_FOUND, EXIT_OK, add_command, add_force, emit, error_line, model_arg


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


def not_reproduced(doc: dict[str, Any], run: Run, diffs: list[str], other: Model | None) -> str:
    """Why the trace did not reproduce: a changed value under its own model (``other`` is ``None``),
    or under another model whether its counterexample (or outcome) is gone or still there."""
    if other is None:
        return _first(diffs)
    name = other.name
    recorded = doc.get("violation")
    again = run_to_json(run, focus=recorded["property"] if recorded else None)
    if recorded:
        if again["violation"] is None:
            k = recorded.get("round")
            where = "" if k is None else f" in {_word(doc)} {k}" if k else " in the initial configuration"
            return (
                f"the counterexample is gone under {name}: {recorded['property']} is no longer violated{where} "
                f"({_what_happens(again)})"
            )
        return f"still VIOLATED ({recorded['property']}) under {name}; recorded values differ: {_first(diffs)}"
    if again["outcome"] != doc["outcome"]:
        return f"the recorded outcome {doc['outcome']} is gone under {name} ({_what_happens(again)})"
    return f"still {doc['outcome']} under {name}; recorded values differ: {_first(diffs)}"


def cmd_replay(args: argparse.Namespace) -> int:
    override = model_arg(args.model) if args.model is not None else None
    picture = claim_dir(args.picture, name="picture") if args.picture is not None else None
    worst = EXIT_OK
    for name in args.traces:
        try:
            doc = load_trace(name)
            run = replay(doc, override)
            diffs = differences(doc, run)
        except FatlineError as exc:
            print(error_line(str(exc)), file=sys.stderr)
            worst = EXIT_BAD
            continue
        other = override if override is not None and not _same_model(doc, override) else None
        if diffs:
            emit([f"{name}: DID NOT REPRODUCE: {not_reproduced(doc, run, diffs, other)}"])
            worst = max(worst, EXIT_FOUND)
            continue
        v = doc["violation"]
        word = _word(doc)
        what = f"{doc['outcome']}" + (f" ({v['property']} in {word} {v['round']})" if v else "")
        under = f" under {override.name}" if override is not None else ""
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
    return worst


def register(sub: Any) -> None:
    p = add_command(sub, "replay", "recompute traces from their initial positions and compare every recorded value")
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
