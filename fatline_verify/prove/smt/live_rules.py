"""A rule set's decision cases as the liveness obligations read them (:mod:`.liveness`).

A :class:`LiveCase` is one decision case of a rule set: the witnesses it names, whether the decider
moves in it, and its encoding (the constraints under which the robot at ``me`` makes that decision,
with its destination relative to ``me``), in the convention of :mod:`.cases`: each witness a named
point, every other condition universal over the robots the obligation names that the decider sees.
A rule set declares where its cases come from in its
:attr:`~fatline_verify.rules.registry.Liveness.encoding`; :func:`paper_cases` gives the paper's
(:func:`fatline_verify.rules.paper.cases.cases_for`, encoded by :func:`.cases.decide_case`).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial

import z3

from ...model.config import Model
from ...rules import registry
from ...rules.paper.cases import Case, cases_for
from .cases import Arith, Pt, decide_case, role_names

Encode = Callable[[Arith, Model, Pt, dict[str, Pt], Sequence[Pt]], tuple[list[z3.BoolRef], Pt]]
"""``encode(ar, model, me, roles, universe) -> (constraints, destination relative to me)``."""


@dataclass(frozen=True)
class LiveCase:
    """One decision case: its name, its witnesses' role names, whether it moves, its encoding."""

    name: str
    roles: tuple[str, ...]
    moves: bool
    encode: Encode


def _paper(case: Case, ar: Arith, model: Model, me: Pt, roles: dict[str, Pt], universe: Sequence[Pt]):  # type: ignore[no-untyped-def]
    return decide_case(ar, model, case, me, roles, universe)


def paper_cases(model: Model) -> list[LiveCase]:
    """The paper's decision cases under ``model``'s readings (NoMovement bullets, then each branch)."""
    return [LiveCase(c.name, tuple(role_names(c, model)), c.moves, partial(_paper, c)) for c in cases_for(model)]


def live_cases(model: Model) -> list[LiveCase]:
    """The cases ``model``'s rule set declares for its liveness obligations (``[]`` without a declaration)."""
    declared = registry.of(model).liveness
    if declared is None:
        return []
    source = declared.encoding
    if isinstance(source, str):
        module, _, name = source.partition(":")
        source = getattr(importlib.import_module(module), name)
    return list(source(model))


__all__ = ["Encode", "LiveCase", "live_cases", "paper_cases"]
