"""Move families: the moves a rule set may make and the guard each must pass, in a small language read by
a concrete interpreter (the engines) and a symbolic one (the prover)."""

from .family import REST, FamilyOf, LegClass, MoveFamily, family_of
from .lang import (
    FALSE,
    TRUE,
    Cond,
    all_of,
    any_of,
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
    "REST",
    "TRUE",
    "Cond",
    "FamilyOf",
    "LegClass",
    "MoveFamily",
    "all_of",
    "any_of",
    "clear",
    "clear_of",
    "distinct",
    "end",
    "exists",
    "family_of",
    "forall",
    "implies",
    "me",
    "sees",
]
