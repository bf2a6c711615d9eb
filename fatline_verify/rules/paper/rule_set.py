"""The paper rule set's registration: its options, decision function and prover encoding."""

from ..registry import Encoding, Liveness, RuleSet, register, register_encoding
from .algorithm import decide
from .options import READINGS

CASES = register_encoding(Encoding("paper", "the paper's decision cases", decide))
"""The prover's encoding of the paper's rules: obligations per decision case (:mod:`fatline_verify.prove.smt.cases`)."""

PAPER = register(
    RuleSet(
        "paper",
        decide,
        "The paper's LineForm(): NoMovement, then getDestination (Scenarios 1-4), under the model's readings.",
        options=READINGS,
        prover=CASES,
        bands=True,
        liveness=Liveness(
            "fatline_verify.prove.smt.live_rules:paper_cases",
            ((-1, 0), (0, 1)),
            "lexicographic (sum of -x, sum of y) over the robots: a move goes right, or stays on its vertical "
            "and goes down",
            "sum of -x: bounded below while no robot moves right of every robot it sees (rma-fixed's `seen` "
            "obligations: the right-most vertical never moves right); sum of y: NOT argued (nothing in the "
            "paper's rules bounds how far Scenario 4 moves down), so these rows prove the fall only",
        ),
    )
)
