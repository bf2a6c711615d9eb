"""``fatline report``: per-model pages with pictures, the regression corpus and the readings x lemmas matrix."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from ..errors import InvalidInput
from ..model.config import shipped_models
from ..outputs import Output, claim_dir, distinct_outputs
from ..progress import Progress
from .common import EXIT_OK, add_command, add_force, emit, exit_codes, integer, model_arg, nonempty, seconds
from .prove import DEFAULT_SLOTS, DEFAULT_TIMEOUT, MAX_SLOTS

STEPS = ("check", "prove", "pictures")


def cmd_report(args: argparse.Namespace) -> int:
    from ..locks import holding
    from ..report.build import build_report

    specs = args.models or [p.stem for p in shipped_models()]
    models = [model_arg(s) for s in specs]
    names = [m.name for m in models]
    if len(set(names)) != len(names):
        raise InvalidInput(f"models={specs}: two models share a name; expected distinct model names")
    out = Path(args.out)
    claim_dir(out, name="out")
    distinct_outputs(
        [Output("out", out, directory=True), Output("proofs", args.proofs, directory=True)],
        [("models", spec) for spec in specs],
    )
    with holding(out, name="out"), Progress(enabled=not args.quiet, unit="steps") as bar:  # one run per --out
        bar.stage("report", total=len(models) * len(STEPS))
        reports = build_report(
            models,
            out,
            proofs=Path(args.proofs),
            slots=args.slots,
            timeout=args.timeout,
            refresh=args.refresh,
            force=args.force,
            progress=bar.step,
        )
    asked = set(names)
    lines = [
        f"{out / r.model.name / 'README.md'}: {len(r.traces)} counterexample traces"
        for r in reports
        if r.model.name in asked
    ]
    kept = [r.model.name for r in reports if r.model.name not in asked]
    if kept:
        lines.append(f"kept from earlier runs in the matrix: {', '.join(kept)}")
    lines.append(f"{out / 'index.html'} and {out / 'README.md'}: the readings x lemmas matrix")
    emit(lines)
    return EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "report",
        "write per-model reports with pictures, the regression corpus and the readings x lemmas matrix",
        exit_codes("the pages are written"),
    )
    p.add_argument("models", nargs="*", metavar="MODEL", help="model files or names (default: every shipped model)")
    p.add_argument(
        "--out",
        default="reports",
        type=nonempty("out", "a report directory"),
        help="report directory (default: reports)",
    )
    p.add_argument(
        "--proofs",
        default="proofs",
        type=nonempty("proofs", "a directory for prover artefacts"),
        help="prover artefacts directory (default: proofs)",
    )
    p.add_argument(
        "--slots",
        type=integer("slots", 1, MAX_SLOTS),
        default=DEFAULT_SLOTS,
        help=f"prover slot robots (default {DEFAULT_SLOTS})",
    )
    p.add_argument(
        "--timeout",
        type=seconds("timeout"),
        default=DEFAULT_TIMEOUT,
        help=f"prover budget per obligation in seconds (default {DEFAULT_TIMEOUT:g})",
    )
    p.add_argument("--refresh", action="store_true", help="recompute results even when the cached ones are up to date")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    add_force(p)
    p.set_defaults(handler=cmd_report)
