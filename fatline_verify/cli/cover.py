"""``fatline cover``: are a rule set's declared liveness cases every decision its ``decide`` makes?

The liveness obligations of ``fatline prove`` speak of the declared cases only; this command holds
the cases to ``decide`` on the views a robot can have (:mod:`fatline_verify.prove.refine`): a random
sample by default, every view with ``--all``. Exit 1 with the first uncovered view named, 0 when
every view checked is covered (a sample says so and proves nothing), 2 on bad input.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..errors import InvalidInput
from ..lemmas.properties import Verdict
from ..rules import registry
from .common import (
    EXIT_FOUND,
    EXIT_OK,
    add_command,
    add_model_argument,
    check_cores,
    emit,
    exit_codes,
    integer,
    model_arg,
)


def cmd_cover(args: argparse.Namespace) -> int:
    from ..prove.refine import prove_coverage
    from ..prove.views import count_views

    model = model_arg(args.model)
    if registry.of(model).liveness is None:
        raise InvalidInput(f"rules={model.rules!r}: the rule set declares no liveness cases; expected one that does")
    check_cores("jobs", args.jobs, "each process checks a share of the views")
    if args.all:
        emit([f"{model.name}: {count_views(model)} views at q={model.parameters.q}, rad_v={model.parameters.rad_v}"])
    row = prove_coverage(model, exhaustive=args.all, sample=args.sample, processes=args.jobs)
    emit([f"{row.key}: {row.verdict}", f"  {row.reason}"])
    return EXIT_FOUND if row.verdict is Verdict.VIOLATED else EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "cover",
        "check that a rule set's liveness cases cover every decision of its decide",
        exit_codes(
            "every view checked is in a declared case with decide's destination",
            "a view is in no declared case (it is named)",
        ),
    )
    add_model_argument(p)
    p.add_argument("--all", action="store_true", help="every view a robot can have (default: a random sample)")
    p.add_argument(
        "--sample", type=integer("sample", 1), default=2000, help="random views without --all (default: 2000)"
    )
    p.add_argument("--jobs", type=integer("jobs", 1, 64), default=1, help="processes for --all (default: 1)")
    p.set_defaults(handler=cmd_cover)
