"""The paper's lemmas as checkable properties, and the typed verdicts the checker gives them.

| id | paper |
|---|---|
| connectivity | Lemma 1: "The connectivity graph G remains connected." |
| no-collision | Lemma 4: "The robots never collide." |
| progress | Lemma 2: "There exists always a robot which will move unless the robots in R forms a straight line." |
| rma-fixed | Lemma 3: "None of the robots ever crosses the RMA of the set of robot." |
| approach | Lemma 5: "Each robot will move closer to RMA in finite time interval." |
| termination | Lemma 6 + Theorem: "All the robots in R will be on the RMA in finite time." |
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any


class Lemma(StrEnum):
    """The checked lemmas, in report order."""

    CONNECTIVITY = "connectivity"
    NO_COLLISION = "no-collision"
    PROGRESS = "progress"
    RMA_FIXED = "rma-fixed"
    APPROACH = "approach"
    TERMINATION = "termination"


SAFETY = (Lemma.CONNECTIVITY, Lemma.NO_COLLISION, Lemma.RMA_FIXED)
"""Lemmas about a single round; a violating round carries the witness."""

FLAG = {Lemma.NO_COLLISION: 1, Lemma.CONNECTIVITY: 2, Lemma.RMA_FIXED: 4}
"""Bit of each round-level lemma in a transition's violation flags."""


class Verdict(StrEnum):
    """What the checker or the prover concluded; never a bool."""

    VIOLATED = "VIOLATED"
    HOLDS_WITHIN_BOUNDS = "HOLDS_WITHIN_BOUNDS"
    PROVED = "PROVED"
    INCONCLUSIVE = "INCONCLUSIVE"


class StopReason(StrEnum):
    """Why a verdict is INCONCLUSIVE."""

    WINDOW = "window"
    MAX_STATES = "max-states"
    CYCLE_NOT_DECISIVE = "cycle-not-decisive"

    def describe(self, detail: str = "") -> str:
        """A sentence for the report."""
        text = {
            StopReason.WINDOW: "executions leave the window (bounding box outgrew the bound)",
            StopReason.MAX_STATES: "the state bound was reached before the search finished",
            StopReason.CYCLE_NOT_DECISIVE: "a fair cycle was found on which every robot off the RMA still moves right",
        }[self]
        return f"{text}{': ' + detail if detail else ''}"


@dataclass(frozen=True, slots=True)
class LemmaResult:
    """One lemma's verdict for one robot count, with the bounds and counts behind it."""

    lemma: Lemma
    verdict: Verdict
    robots: int
    window: tuple[int, int]
    reason: str = ""
    witness_rounds: int | None = None
    witness: dict[str, Any] | None = field(default=None, repr=False, compare=False)
    """The witness trace document (replayed before it is attached)."""
