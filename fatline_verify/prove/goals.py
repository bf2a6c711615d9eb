"""Which goals the liveness obligations encode: a leaf module (no z3), read by the obligations
(:mod:`fatline_verify.prove.smt.liveness`), the task list (:mod:`fatline_verify.prove.tasks`) and the
lemma-level verdicts (:mod:`fatline_verify.prove.coverage`)."""

from __future__ import annotations

from ..model.config import Model
from ..model.options import Goal


def goal_problem(model: Model) -> str:
    """Why the enabledness obligations do not encode ``model``'s goal (empty when they do)."""
    if model.options.goal is Goal.VERTICAL_LINE:
        return ""
    return (
        f"goal={model.options.goal}: the enabledness obligations encode goal=vertical-line (a swarm that is not a "
        "goal has a robot off the left-most vertical); this goal is not encoded, so nothing is claimed"
    )


__all__ = ["goal_problem"]
