"""A policy held to its move family by construction: it proposes decisions in order of preference, and the first
the family admits is the decision.

A rule set's ``decide`` is free Python, so that every decision lies in the family is a fact to check: as it runs
(the step lemma ``in-family``) and, for a proof, on every view of the lattice (the row ``in-family-views-any``:
one ``decide`` and one ``admit`` per view, 1,624,375 views at q = 1, rad_v = 4). A rule set whose ``decide`` is a
:class:`Held` needs neither: :meth:`Held.__call__` returns a proposal only after :meth:`MoveFamily.admit` admits
it (a stay always is), so no decision leaves the family, whatever ``propose`` does; the views row says so without
reading a view. The price is paid as it runs: one ``admit`` per proposed move.

``propose(snapshot, model)`` yields decisions, best first (a generator: the later ones are not computed once
one is admitted); when none is admitted, the robot stays, with the rule :data:`HELD`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from ...model.numbers import Point
from ..decision import ORIGIN, Decision
from .family import FamilyOf, family_of

HELD = "held"
"""The rule of a stay :class:`Held` makes when no proposal is admitted (a rule set's labels should say it)."""


@dataclass(frozen=True)
class Held:
    """``decide`` of a rule set: the first of ``propose``'s decisions that ``family`` admits (or a stay)."""

    propose: Callable[[Sequence[Point], Any], Iterable[Decision]]
    family: FamilyOf

    def __call__(self, snapshot: Sequence[Point], model: Any) -> Decision:
        fam = family_of(self.family, model)
        for decision in self.propose(snapshot, model):
            if not decision.moves or fam is None or fam.admit(snapshot, decision, model) is None:
                return decision
        return Decision(HELD, ORIGIN, (ORIGIN,), ())  # type: ignore[arg-type]

    def holds_to(self, family: FamilyOf | None, model: Any) -> bool:
        """Whether every decision is in ``family`` on ``model`` by construction: the family it holds to is that one."""
        return family is not None and family_of(self.family, model) is family_of(family, model)


def held(propose: Callable[[Sequence[Point], Any], Iterable[Decision]], family: FamilyOf) -> Held:
    """``decide`` for ``RuleSet(..., decide=held(propose, FAMILY), family=FAMILY)``: every decision in the family by
    construction (the views row then reads no view)."""
    return Held(propose, family)


__all__ = ["HELD", "Held", "held"]
