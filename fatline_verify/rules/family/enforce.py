"""The step lemma ``in-family``: every decision of a rule set that declares a move family lies in it.

What ``fatline prove`` proves of a family (:mod:`fatline_verify.prove.smt.family`) is what runs only if
every decision the rule set makes is one the family admits. This lemma holds the rule set to that as
it runs: on every step the checker explores (and every round ``simulate`` and ``replay`` play), each
robot that moved is asked again what it decided on the configuration before the step, and a decision
the family does not admit (:meth:`~fatline_verify.rules.family.family.MoveFamily.admit`) is a violation
— a witness trace, replayed like any other, never a silent skip. It is judged only for a rule set that
declares a family (for the model's options), so it changes nothing for any other.

In a round (SSYNC, FSYNC, centralized) every robot that moves decided on the configuration before the
round, which is what this lemma asks. Under ASYNC a robot decides at its look, on a configuration that
may have changed by the time it moves, and a step of positions does not say what it saw: the lemma is
not judged there (its verdict is absent, not HOLDS). The family's proof is a proof about rounds too:
``fatline prove`` refuses ASYNC.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ...lemmas.registry import Points, StepLemma, register
from ...model.numbers import Point

NAME = "in-family"


def _family(model: Any) -> Any:
    from .. import registry

    if model.algorithm is not None:  # a seeded-bug replacement of decide is not held to the rule set's family
        return None
    return registry.family(model)


def applies(model: Any) -> bool:
    """Whether ``model``'s rule set declares a family for its options, under a round scheduler."""
    from ...model.options import Scheduler

    return model.options.scheduler is not Scheduler.ASYNC and _family(model) is not None


def _view(before: Sequence[Point], i: int, model: Any) -> tuple[Point, ...]:
    ox, oy = before[i]
    out = []
    for j, (x, y) in enumerate(before):
        if j != i:
            dx, dy = x - ox, y - oy
            if model.sees(dx * dx + dy * dy):
                out.append((dx, dy))
    return tuple(sorted(out))


_CACHE: dict[tuple[Any, tuple[Point, ...]], str | None] = {}
"""``(model, view) -> why``: each view's decision judged once per model (the engines revisit views)."""


def why_not(view: tuple[Point, ...], model: Any) -> str | None:
    """Why the decision on ``view`` leaves the model's family (``None``: admitted)."""
    from .. import registry

    key = (model, view)
    if key not in _CACHE:
        family = _family(model)
        decision = registry.decider(model)(view, model)
        _CACHE[key] = None if family is None else family.admit(view, decision, model)
    return _CACHE[key]


def violators(before: Points, after: Points, model: Any) -> list[int]:
    """The robots that moved in the step though their decision on ``before`` leaves the family."""
    if _family(model) is None:
        return []
    return [
        i for i in range(len(before)) if tuple(before[i]) != tuple(after[i]) and why_not(_view(before, i, model), model)
    ]


def batch(before: np.ndarray, after: np.ndarray, model: Any) -> np.ndarray:
    """:func:`violators` on ``(t, n, 2)`` lattice arrays, one bool per step."""
    out = np.zeros(len(before), dtype=bool)
    if _family(model) is None or not len(before):
        return out
    moved = (before != after).any(axis=2)
    for k in np.flatnonzero(moved.any(axis=1)):
        b = [tuple(int(v) for v in p) for p in before[k]]
        out[k] = any(why_not(_view(b, i, model), model) for i in np.flatnonzero(moved[k]))
    return out


IN_FAMILY = register(
    StepLemma(
        NAME,
        "Every decision lies in the rule set's declared move family (what fatline prove proves is what runs).",
        violators,
        batch,
        applies=applies,
    )
)

__all__ = ["IN_FAMILY", "NAME", "applies", "batch", "violators", "why_not"]
