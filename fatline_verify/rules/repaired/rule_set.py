"""The repaired rule set's registration: its options, decision function and prover encoding."""

from collections.abc import Sequence
from typing import Any

from ..decision import Decision
from ..paper.algorithm import paper_decide
from ..paper.options import READINGS
from ..registry import Encoding, RuleSet, register, register_encoding
from .algorithm import repair
from .family import family
from .options import REPAIR_SPECS

OPTIONS = (*(entry if isinstance(entry, str) else entry.name for entry in READINGS), *REPAIR_SPECS)
"""What it reads: the paper's readings and the model layer's options, by name (the paper's rule set
declares them), then the repairs, which it declares."""


def decide(snapshot: Sequence[Any], model: Any) -> Decision:
    """The paper's decision, then the model's repairs (each ``off`` leaves it as it is)."""
    return repair(paper_decide(snapshot, model), snapshot, model)


LEGS = register_encoding(Encoding("legs", "the repaired rules' legs", decide))
"""The prover's encoding of the repaired rules: each leg class against rest and every other class
(:mod:`.family`, :mod:`fatline_verify.prove.smt.family`); with every repair off the rules decide as the paper's, and the
paper's case table is used (:func:`fatline_verify.prove.coverage.encoding_name`)."""

REPAIRED = register(
    RuleSet(
        "repaired",
        decide,
        "Not the paper: its LineForm() with the named repairs of the model's repair_* options.",
        options=OPTIONS,
        prover=LEGS,
        bands=True,
        family=family,
    )
)
