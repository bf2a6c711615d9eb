"""The repaired rule set's registration: its options, decision function and prover encoding."""

from collections.abc import Sequence
from typing import Any

from ...model.options import CATALOGUE
from ..paper.algorithm import Decision, paper_decide
from ..paper.rule_set import READINGS
from ..registry import RuleSet, register
from .algorithm import repair

REPAIRS = frozenset(name for name, spec in CATALOGUE.items() if spec.repair)
"""The repair options."""


def decide(snapshot: Sequence[Any], model: Any) -> Decision:
    """The paper's decision, then the model's repairs (each ``off`` leaves it as it is)."""
    return repair(paper_decide(snapshot, model), snapshot, model)


REPAIRED = register(
    RuleSet(
        "repaired",
        decide,
        "Not the paper: its LineForm() with the named repairs of the model's repair_* options.",
        options=READINGS | REPAIRS,
        prover="legs",
        bands=True,
    )
)
