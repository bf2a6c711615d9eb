"""The paper rule set's registration: its options, decision function and prover encoding."""


from ...model.options import CATALOGUE
from ..registry import MODEL_OPTIONS, RuleSet, register
from .algorithm import decide

READINGS = frozenset(name for name, spec in CATALOGUE.items() if not spec.repair) - MODEL_OPTIONS
"""The paper's open points (``fatline explain``): the options this rule set reads."""

PAPER = register(
    RuleSet(
        "paper",
        decide,
        "The paper's LineForm(): NoMovement, then getDestination (Scenarios 1-4), under the model's readings.",
        options=READINGS,
        prover="paper",
        bands=True,
    )
)
