"""``fatline replay``: recompute traces from their initial positions and compare every recorded value."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from ..errors import FatlineError, TraceDidNotReproduce
from ..outputs import Kind, claim_dir, claim_files, write_text
from ..text import trace_lines
from ..trace import check_replay, load_trace
from .common import EXIT_BAD, EXIT_FOUND, EXIT_OK, add_command, add_force, emit, error_line, model_arg


def cmd_replay(args: argparse.Namespace) -> int:
    override = model_arg(args.model) if args.model is not None else None
    picture = claim_dir(args.picture, name="picture") if args.picture is not None else None
    worst = EXIT_OK
    for name in args.traces:
        try:
            doc = load_trace(name)
            run = check_replay(doc, override)
        except TraceDidNotReproduce as exc:
            emit([f"{name}: DID NOT REPRODUCE: {exc}"])
            worst = max(worst, EXIT_FOUND)
            continue
        except FatlineError as exc:
            print(error_line(str(exc)), file=sys.stderr)
            worst = EXIT_BAD
            continue
        v = doc["violation"]
        what = f"{doc['outcome']}" + (f" ({v['property']} in round {v['round']})" if v else "")
        lines = [f"{name}: reproduces: {len(run.rounds)} rounds, {what}"]
        if args.verbose:
            lines += ["  " + line for line in trace_lines(doc)]
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
    p.add_argument("--model", help="replay under this model instead of the trace's own")
    p.add_argument("-v", "--verbose", action="store_true", help="print every round")
    p.add_argument("--picture", metavar="DIR", help="write one SVG picture per round of each trace into DIR")
    add_force(p)
    p.set_defaults(handler=cmd_replay)
