"""The centre-of-gravity ("gravitational") algorithm: every robot moves to the barycentre of what it sees.

Sources. The rule and its claims for robots that see everything: R. Cohen, D. Peleg, "Convergence
properties of the gravitational algorithm in asynchronous robot systems", SIAM J. Computing 34(6),
2005 (convergence under SSYNC and ASYNC), and its mechanised form in the Pactole Coq library
(Balabonski, Courtieu, Rieg, Urbain; ``CaseStudies/Gathering/InR2/Peleg.v``), which proves that under
FSYNC it gathers the robots in finite time. Its robogram, quoted:

    (** The robogram solving the gathering problem in R². *)
    Definition ffgatherR2_pgm (s : observation) : @path location location_Setoid :=
      paths_in_R2 (barycenter (List.map (fun xn => (fst xn, INR (snd xn))) (elements s))).

(the observation ``s`` a multiset: a point seen with multiplicity ``k`` weighs ``k``); its sibling
``FSyncFlexNoMultAlgorithm.v`` observes a set and moves to ``isobarycenter (elements s)``, each
occupied point weighing one. With limited visibility the same rule, applied to the robots a robot sees,
is the naive algorithm Ando, Oasa, Suzuki and Yamashita (1999) set out to improve on, since moving to
the centre of gravity of one's neighbours can take a robot out of another's sight: the claim that the
tool tests there is theirs, that visibility is not preserved.

Readings (``[rules]`` in a model file):

- ``weights``: ``multiset`` (default; ``Peleg.v``: every robot seen weighs one, coinciding robots
  count) or ``set`` (``FSyncFlexNoMultAlgorithm.v``: every occupied point weighs one).
- ``destination``: ``rational`` (default; the barycentre itself, exactly: a rational point, off the
  lattice when the weights do not divide, a successor the checker judges on its step and does not
  explore) or ``lattice`` (the lattice point of the segment toward the barycentre nearest to it, an
  under-approximation that keeps runs on the lattice; the barycentre itself whenever it is a lattice
  point).

Not expressed: Pactole's flexible motion (the demon stops a robot anywhere after ``delta``; here motion
is rigid) and convergence itself (what a finite search can decide about it is in the docs page).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

from ...lemmas.properties import Lemma
from ...model.seams import Param
from ..decision import Decision, stay
from ..registry import RuleSet, register
from .exact import frac, lattice_farthest, point

PARAMETERS = {
    "weights": Param(
        "multiset",
        "what the barycentre weighs: every robot seen (multiset, Peleg.v) or every occupied point (set)",
        choices=("multiset", "set"),
    ),
    "destination": Param(
        "rational",
        "the barycentre itself (rational) or the lattice point of the way to it nearest to it (lattice)",
        choices=("rational", "lattice"),
    ),
}

LABELS = {
    "at-barycentre": "is at the barycentre of what it sees (itself included): stays",
    "to-barycentre": "moves to the barycentre of the robots it sees and itself",
    "toward-barycentre": "moves to the lattice point of the way to the barycentre nearest to it",
    "held": "no lattice point of the way to the barycentre but its own (destination = lattice): stays",
}


def barycentre(snapshot: Sequence[tuple[Any, Any]], weights: str) -> tuple[Fraction, Fraction]:
    """The barycentre of the robot at the origin and those it sees, weighted per the ``weights`` reading."""
    points = [(Fraction(0), Fraction(0)), *(frac(p) for p in snapshot)]
    counts = Counter(points) if weights == "multiset" else Counter(set(points))
    total = sum(counts.values())
    return (
        sum((p[0] * k for p, k in counts.items()), Fraction(0)) / total,
        sum((p[1] * k for p, k in counts.items()), Fraction(0)) / total,
    )


def decide(snapshot: Sequence[tuple[Any, Any]], model: Any) -> Decision:
    """The centre-of-gravity rule for the robot at the origin (the module's docstring quotes it)."""
    own = model.setting("rules")
    target = barycentre(snapshot, str(own["weights"]))
    if target == (0, 0):
        return stay("at-barycentre")
    if own["destination"] == "rational" or all(v.denominator == 1 for v in target):
        end = point(target)
        return Decision("to-barycentre", end, ((0, 0), end))
    near = lattice_farthest(target, [])
    if near == (0, 0):
        return stay("held")
    return Decision("toward-barycentre", near, ((0, 0), near))


LEMMAS = tuple(lemma.value for lemma in (Lemma.CONNECTIVITY, Lemma.PROGRESS, Lemma.TERMINATION))
"""The claims in the checker's terms: the swarm stays connected (trivially with full visibility; the
claim Ando et al. deny with limited visibility) and the robots gather (progress and termination)."""

GRAVITY = register(
    RuleSet(
        "gravity",
        decide,
        "The centre-of-gravity algorithm (Cohen and Peleg 2005; Pactole's Peleg.v): every robot moves to the "
        "barycentre of the robots it sees and itself.",
        labels=dict(LABELS),
        lemmas=LEMMAS,
        robots="points",
        goal="point",
        parameters=PARAMETERS,
    )
)

__all__ = ["GRAVITY", "LABELS", "PARAMETERS", "barycentre", "decide"]
