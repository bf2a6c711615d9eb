"""Ando, Oasa, Suzuki and Yamashita (1999): point convergence of oblivious robots with limited visibility.

Source: H. Ando, Y. Oasa, I. Suzuki, M. Yamashita, "Distributed memoryless point convergence algorithm
for mobile robots with limited visibility", IEEE Transactions on Robotics and Automation 15(5):818-828,
1999, doi:10.1109/70.795787, Section III ("A point convergence algorithm"). The paper's own text was not
in reach; its rule is quoted as two independent implementations that cite that section reproduce it (the
Sycamore simulator's ``GatheringAndoSuzuki`` plug-in, University of Pisa, and HengZ121's
``Distributed-Points-Convergence``, ``mobile_robot.py``):

    "If this robot does not see any robot other than itself, it does not move. Otherwise, find the
    center of the smallest enclosing circle of the set of all visible robots c(t) ... For every visible
    robot j, this robot's position lies in the disc D(j) whose center is the midpoint of this robot and
    robot j and whose radius is V/2."

    limit_j = (d_j / 2) cos(theta_j) + sqrt((V/2)^2 - ((d_j / 2) sin(theta_j))^2),
    move = min(|R c|, min_j limit_j), toward c,

with ``d_j`` the distance to robot ``j`` and ``theta_j`` the angle between the directions to ``c`` and to
``j``: ``limit_j`` is how far the robot can go toward ``c`` and stay in ``D(j)``. The claim (SSYNC, point
robots, visibility ``dist <= V``): robots that see each other keep seeing each other, and the robots
converge to one point. Under ASYNC the algorithm is not claimed; Kirkpatrick, Kostitsyna, Navarra,
Prencipe and Santoro (PODC 2021, Distributed Computing 2024) prove that with unbounded asynchrony no
algorithm converges cohesively (keeping the initial visibility edges).

Readings (the rule set's own parameters, ``[rules]`` in a model file):

- ``destination``: ``lattice`` (default) goes to the lattice point of the segment toward ``c`` farthest
  from the robot inside every ``D(j)``, an under-approximation of ``move`` that keeps every published
  constraint and makes runs stay on the lattice, so the checker explores them; ``rational`` goes to the
  published point ``min(|Rc|, limit)`` where it is rational and otherwise to the farthest multiple of
  ``1/grid`` of the segment inside every ``D(j)`` (``limit_j`` is a square root: never approximated from
  above), a successor off the lattice that the checker judges on its step but does not explore.
- ``sec``: ``with-self`` (default): the circle encloses the robot and the robots it sees (the paper's
  "set of all visible robots", the robot included, as HengZ121's ``getVisibleRobots`` has it);
  ``others``: only the robots it sees (as both implementations then compute it).
- ``grid``: the denominator of the rational under-approximation (``destination = rational`` only).

Not expressed: the paper's bound ``sigma`` on a move's length (moves here are unbounded, one of its
settings), its non-rigid motion, and convergence itself (an infinite approach, :mod:`..published`'s
docs say what a finite lattice search can decide about it). Robots are points: no-collision does not
apply, and two robots may share a position (they then behave as one).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import Any

from ...lemmas.properties import Lemma
from ...model.seams import Param
from ..decision import Decision, stay
from ..registry import RuleSet, register
from .exact import farthest_on_segment, frac, lattice_farthest, on_segment, point, smallest_enclosing_circle

PARAMETERS = {
    "destination": Param(
        "lattice",
        "where the robot stops on its way to the centre: lattice (the farthest lattice point inside every "
        "D(j)) or rational (the published point, under-approximated by 1/grid where it is irrational)",
        choices=("lattice", "rational"),
    ),
    "sec": Param(
        "with-self",
        "the smallest enclosing circle of the robot and those it sees (with-self) or of those it sees (others)",
        choices=("with-self", "others"),
    ),
    "grid": Param(16, "the denominator of the rational under-approximation of a move's limit", minimum=1, maximum=64),
}

LABELS = {
    "alone": "sees no other robot: stays (the paper: 'it does not move')",
    "at-centre": "is the centre of the smallest enclosing circle: stays",
    "to-centre": "goes to the centre c of the smallest enclosing circle (no D(j) limits it)",
    "limited": "goes toward c as far as every disc D(j) (midpoint of it and j, radius V/2) allows",
    "held": "no point of the segment toward c but its own is allowed (on the lattice): stays",
}


def decide(snapshot: Sequence[tuple[Any, Any]], model: Any) -> Decision:
    """Ando et al.'s rule for the robot at the origin (see the module's docstring for the text)."""
    if not snapshot:
        return stay("alone")
    own = model.setting("rules")
    seen = [frac(p) for p in snapshot]
    circle = [*seen, (Fraction(0), Fraction(0))] if own["sec"] == "with-self" else seen
    centre, _ = smallest_enclosing_circle(circle)
    if centre == (0, 0):
        return stay("at-centre")
    half = Fraction(model.view, 2)
    discs = [((p[0] / 2, p[1] / 2), half * half) for p in seen]  # D(j): midpoint, radius V/2
    if own["destination"] == "lattice":
        end: tuple[Any, Any] = lattice_farthest(centre, discs)
        if end == (0, 0):
            return stay("held")
    else:
        t = farthest_on_segment(centre, discs, int(own["grid"]))
        if t == 0:
            return stay("held")
        end = point(on_segment(centre, t))
    rule = "to-centre" if frac(end) == centre else "limited"
    return Decision(rule, end, ((0, 0), end))


LEMMAS = tuple(lemma.value for lemma in (Lemma.CONNECTIVITY, Lemma.PROGRESS, Lemma.TERMINATION))
"""What the paper claims, in the checker's terms: visibility kept (Lemma: mutually visible robots stay so,
so the visibility graph stays connected) and convergence (progress and termination against the goal)."""

ANDO = register(
    RuleSet(
        "ando",
        decide,
        "Ando, Oasa, Suzuki, Yamashita (1999): each robot moves toward the centre of the smallest circle "
        "enclosing what it sees, as far as keeps it within V/2 of the midpoint with every robot it sees.",
        labels=dict(LABELS),
        lemmas=LEMMAS,
        robots="points",
        goal="near-gathering",
        parameters=PARAMETERS,
    )
)

__all__ = ["ANDO", "LABELS", "PARAMETERS", "decide"]
