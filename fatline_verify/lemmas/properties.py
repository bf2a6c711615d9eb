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
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # the registry imports this module
    from .registry import StepLemma


class Judged(StrEnum):
    """Where a lemma is decided: on one step of the transition system, on one state, or on the
    explored graph (reachable terminal states and fair cycles)."""

    STEP = "step"
    STATE = "state"
    GRAPH = "graph"


class Lemma(StrEnum):
    """The lemmas, checked ones in report order (:data:`CHECKED`), then the proof-only refinement.

    Everything else about a lemma — where it is judged, its violation bit, the paper's words — is
    in :data:`SPECS`; no lemma name is spelled as a string anywhere else.
    """

    CONNECTIVITY = "connectivity"
    NO_COLLISION = "no-collision"
    PROGRESS = "progress"
    RMA_FIXED = "rma-fixed"
    APPROACH = "approach"
    TERMINATION = "termination"
    CONNECTIVITY_EDGE = "connectivity-edge"

    @property
    def spec(self) -> LemmaSpec:
        """This lemma's row of :data:`SPECS`."""
        return SPECS[self]

    @property
    def judged(self) -> Judged:
        return SPECS[self].judged

    @property
    def flag(self) -> int:
        """The bit of a step lemma in a transition's violation flags (0 for the others)."""
        return SPECS[self].flag


@dataclass(frozen=True, slots=True)
class LemmaSpec:
    """One row of the lemma table."""

    judged: Judged
    flag: int
    paper: str
    checked: bool = True
    """Whether ``fatline check`` gives it a verdict (``connectivity-edge`` is the prover's refinement)."""


SPECS: dict[Lemma, LemmaSpec] = {
    Lemma.CONNECTIVITY: LemmaSpec(Judged.STEP, 2, "Lemma 1: The connectivity graph G remains connected."),
    Lemma.NO_COLLISION: LemmaSpec(Judged.STEP, 1, "Lemma 4: The robots never collide."),
    Lemma.PROGRESS: LemmaSpec(
        Judged.STATE,
        0,
        "Lemma 2: There exists always a robot which will move unless the robots in R forms a straight line.",
    ),
    Lemma.RMA_FIXED: LemmaSpec(Judged.STEP, 4, "Lemma 3: None of the robots ever crosses the RMA of the set of robot."),
    Lemma.APPROACH: LemmaSpec(Judged.GRAPH, 0, "Lemma 5: Each robot will move closer to RMA in finite time interval."),
    Lemma.TERMINATION: LemmaSpec(
        Judged.GRAPH, 0, "Lemma 6 + Theorem: All the robots in R will be on the RMA in finite time."
    ),
    Lemma.CONNECTIVITY_EDGE: LemmaSpec(
        Judged.STEP,
        0,
        "Proof of Lemma 1: every robot a mover saw before its move still sees it after (an edge is lost "
        "while G stays connected: the proof's claim fails, the lemma may not).",
        checked=False,
    ),
}

CHECKED: tuple[Lemma, ...] = tuple(lemma for lemma in Lemma if SPECS[lemma].checked)
"""The lemmas the checker gives verdicts, in report order."""

SAFETY: tuple[Lemma, ...] = tuple(lemma for lemma in CHECKED if SPECS[lemma].judged is Judged.STEP)
"""Lemmas about a single step; a violating step carries the witness."""

PROVED_LEMMAS: tuple[Lemma, ...] = (
    Lemma.NO_COLLISION,
    Lemma.CONNECTIVITY,
    Lemma.RMA_FIXED,
    Lemma.APPROACH,
    Lemma.PROGRESS,
    Lemma.TERMINATION,
)
"""The lemmas the prover has obligations for, in its results order (progress and termination: the
liveness obligations, for a rule set that declares them): named here, without z3, for the prover
(:data:`fatline_verify.prove.tasks.LEMMAS`), ``fatline prove --lemma`` and the report's columns."""

FLAG = {lemma: SPECS[lemma].flag for lemma in SAFETY}
"""Bit of each step lemma in a transition's violation flags."""


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
    MAX_MEMORY = "max-memory"
    CYCLE_NOT_DECISIVE = "cycle-not-decisive"

    def describe(self, detail: str = "") -> str:
        """A sentence for the report."""
        text = {
            StopReason.WINDOW: "executions leave the window (bounding box outgrew the bound)",
            StopReason.MAX_STATES: "the state bound was reached before the search finished",
            StopReason.MAX_MEMORY: "the memory bound (--max-memory) was reached before the search finished",
            StopReason.CYCLE_NOT_DECISIVE: "a fair cycle was found on which every robot off the RMA still moves right",
        }[self]
        return f"{text}{': ' + detail if detail else ''}"


@dataclass(frozen=True, slots=True)
class LemmaResult:
    """One lemma's verdict for one robot count, with the bounds and counts behind it."""

    lemma: Lemma | StepLemma
    verdict: Verdict
    robots: int
    window: tuple[int, int]
    reason: str = ""
    witness_rounds: int | None = None
    witness: dict[str, Any] | None = field(default=None, repr=False, compare=False)
    """The witness trace document (replayed before it is attached)."""
