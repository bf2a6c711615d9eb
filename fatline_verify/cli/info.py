"""``fatline explain`` and ``fatline models``: the paper's open points and the shipped models."""

from __future__ import annotations

import argparse
from typing import Any

from ..errors import InvalidInput
from ..model.config import load_model, shipped_models
from ..model.options import CATALOGUE
from ..rules import registry
from ..text import explain_lines
from .common import EXIT_OK, add_command, emit, exit_codes, model_arg


def cmd_explain(args: argparse.Namespace) -> int:
    """The catalogue, an option of it, or a parameter a scheduler or rule set declares (``scheduler.k``)."""
    model = model_arg(args.model) if args.model is not None else None
    if args.option is not None and args.option not in CATALOGUE:
        registry.names()  # a plug-in's rule set declares its options when it loads
    if args.option is not None and args.option not in CATALOGUE and "." not in args.option:
        raise InvalidInput(f"option={args.option!r}: unknown option; expected one of {', '.join(CATALOGUE)}")
    emit(explain_lines(args.option, model))
    return EXIT_OK


def cmd_models(args: argparse.Namespace) -> int:
    lines = []
    for path in shipped_models():
        model = load_model(path)
        lines += [f"{path.stem}: {model.description}", f"  {model.describe()}"]
    emit(lines)
    return EXIT_OK


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "explain",
        "print the options (the paper's open points, the model's, a rule set's own: quote, readings, default) and the "
        "parameters schedulers and rule sets declare",
        exit_codes("printed"),
    )
    p.add_argument("option", nargs="?", help="one option, or a parameter as SEAM.NAME (scheduler.k; default: all)")
    p.add_argument(
        "--model",
        help="mark the readings and parameter values this model file selects (only the options its rule set reads)",
    )
    p.set_defaults(handler=cmd_explain)

    p = add_command(sub, "models", "list the shipped model files", exit_codes("listed"))
    p.set_defaults(handler=cmd_models)
