"""The certified rule set's registration: its decision function and labels (no prover encoding yet)."""

from ..registry import RuleSet, register
from .algorithm import LABELS, decide

CERTIFIED = register(
    RuleSet(
        "certified",
        decide,
        "Not the paper: moves right, diagonally right or vertically, checked against every move a robot in "
        "view might make (issue 32); safe by a local argument, live within the checker's bounds up to 4 "
        "robots at q = 1 and 3 at q = 2.",
        prover=None,
        labels=dict(LABELS),
    )
)
"""The certified rule set (:mod:`.algorithm`); ``fatline prove`` refuses it until an encoding exists."""
