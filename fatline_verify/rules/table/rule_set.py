"""The shipped tables' registration: ``table-<file stem>`` for each file of ``tables/``, each with the move family it
was searched in (``fatline prove`` proves its no-collision and connectivity from it; ``fatline synth``'s replay
and ``fatline check`` back the rest)."""

from ..registry import RuleSet, register
from .algorithm import LABELS, TABLES, decider, family, load

TABLE_RULE_SETS = tuple(
    register(RuleSet(s.name, decider(s), s.summary, prover=None, labels=dict(LABELS), family=family(s)))
    for s in (load(p) for p in sorted(TABLES.glob("*.json")))
)
"""One rule set per shipped table."""
