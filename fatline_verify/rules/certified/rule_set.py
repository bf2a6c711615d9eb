"""The certified rule set's registration: its decision function, labels and move family (what ``fatline prove``
proves no-collision and connectivity from; it has no case encoding of its own)."""

from ..registry import RuleSet, register
from .algorithm import LABELS
from .family import decide, family

CERTIFIED = register(
    RuleSet(
        "certified",
        decide,
        "Not the paper: moves right, diagonally right or vertically, checked against every move a robot in "
        "view might make (issue 32); safe by a local argument, live within the checker's bounds up to 4 "
        "robots at q = 1 and 3 at q = 2.",
        prover=None,
        labels=dict(LABELS),
        family=family,
    )
)
"""The certified rule set (:mod:`.algorithm`); ``fatline prove`` proves its safety from its move family
(:mod:`.family`)."""
