"""The shipped tables' registration: ``table-<file stem>`` for each file of ``tables/`` (no prover encoding:
``fatline prove`` refuses them; what backs them is ``fatline synth``'s replay and ``fatline check``)."""

from ..registry import RuleSet, register
from .algorithm import LABELS, TABLES, decider, load

TABLE_RULE_SETS = tuple(
    register(RuleSet(s.name, decider(s), s.summary, prover=None, labels=dict(LABELS)))
    for s in (load(p) for p in sorted(TABLES.glob("*.json")))
)
"""One rule set per shipped table."""
