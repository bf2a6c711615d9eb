"""Move families: the moves a rule set may make and the guard each must pass, in a small language read by
a concrete interpreter (the engines) and a symbolic one (the prover)."""

from .family import REST, FamilyOf, LegClass, MoveFamily, family_of
from .held import HELD, Held, held
from .lang import (
    FALSE,
    TRUE,
    Cond,
    all_of,
    any_of,
    chain,
    clear,
    clear_of,
    distinct,
    end,
    exists,
    forall,
    implies,
    me,
    sees,
)

__all__ = [
    "FALSE",
    "HELD",
    "REST",
    "TRUE",
    "Cond",
    "FamilyOf",
    "Held",
    "LegClass",
    "MoveFamily",
    "all_of",
    "any_of",
    "chain",
    "clear",
    "clear_of",
    "distinct",
    "end",
    "exists",
    "family_of",
    "forall",
    "held",
    "implies",
    "me",
    "sees",
]
