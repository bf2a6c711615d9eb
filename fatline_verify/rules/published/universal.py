"""Certified universal gathering in R² (Courtieu, Rieg, Tixeuil, Urbain, DISC 2016), as Pactole states it.

Source: P. Courtieu, L. Rieg, S. Tixeuil, X. Urbain, "Certified universal gathering in R² for oblivious
mobile robots", DISC 2016, LNCS 9888, and its Coq development in the Pactole library
(``CaseStudies/Gathering/InR2/Algorithm.v``), where the algorithm is proved to gather every configuration
that is not bivalent, for ``n >= 3`` robots, under a fair SSYNC demon, with rigid moves, unlimited
visibility and strong multiplicity detection (a robot sees how many robots stand on each point). Its
robogram, quoted:

    Function target_triangle (pt1 pt2 pt3 : R2) : R2 :=
      match classify_triangle pt1 pt2 pt3 with
        | Equilateral => barycenter_3_pts pt1 pt2 pt3
        | Isosceles p => p
        | Scalene => opposite_of_max_side pt1 pt2 pt3
      end.

    Function target (s : spectrum) : R2 :=
      let l := support s in
      match on_SEC l with
        | nil => (0, 0) (* no robot *)
        | pt :: nil => pt (* gathered *)
        | pt1 :: pt2 :: pt3 :: nil => target_triangle pt1 pt2 pt3 (* triangle cases *)
        | _ => R2.center (SEC l) (* general case *)
      end.

    Definition SECT (s : spectrum) : list R2 := target s :: on_SEC (support s).
    Definition is_clean (s : spectrum) : bool :=
      if inclA_bool _ equiv_dec (support s) (SECT s) then true else false.

    Definition gatherR2_pgm (s : spectrum) : R2 :=
      match support (max s) with
        | nil => origin (* no robot *)
        | pt :: nil => pt (* majority *)
        | _ :: _ :: _ =>
          if is_clean s then target s (* clean case *)
          else if mem equiv_dec origin (SECT s) then origin else target s (* dirty case *)
      end.

``max s`` is the points of greatest multiplicity, ``on_SEC l`` the points of ``l`` on the smallest
enclosing circle, ``Isosceles p`` names the apex ``p`` (the vertex between the two equal sides). Every
target is exact here: a robot's position, a vertex, or the centre of a smallest enclosing circle
(rational; off the lattice when its coordinates are not whole, a successor the checker judges on its
step and does not explore). An equilateral triangle has no lattice vertices, so that case never fires on
the lattice (its barycentre is computed all the same).

Not expressed: nothing of the rule itself; the claim's fairness is the checker's (a fair cycle that
never gathers refutes termination). Unlimited visibility is a model whose ``rad_v`` sees across its window.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

from ...lemmas.properties import Lemma
from ..decision import Decision, stay
from ..registry import RuleSet, register
from .exact import Pt, dist2, frac, point, smallest_enclosing_circle

LABELS = {
    "majority": "one point holds more robots than any other: goes there",
    "clean": "every occupied point is the target or on the smallest enclosing circle: goes to the target",
    "dirty-on-sect": "the configuration is not clean and it stands on the target or the circle: stays",
    "dirty": "the configuration is not clean: goes to the target",
    "at-target": "stands on the point it would go to: stays",
}


def target_triangle(a: Pt, b: Pt, c: Pt) -> Pt:
    """Pactole's ``target_triangle``: the barycentre of an equilateral triangle, the apex of an isosceles
    one, the vertex opposite the longest side of a scalene one (squared lengths, exactly)."""
    ab, bc, ca = dist2(a, b), dist2(b, c), dist2(c, a)
    if ab == bc == ca:
        return (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3
    if ab == bc:
        return b  # the vertex between the equal sides ab and bc
    if bc == ca:
        return c
    if ca == ab:
        return a
    longest = max((ab, c), (bc, a), (ca, b), key=lambda side: side[0])
    return longest[1]


def target(support: Sequence[Pt]) -> Pt:
    """Pactole's ``target``: the triangle target when three occupied points lie on the smallest enclosing
    circle, its centre otherwise (two, or four and more, on it)."""
    centre, r2 = smallest_enclosing_circle(support)
    on_sec = sorted(p for p in support if dist2(p, centre) == r2)
    if len(on_sec) == 1:
        return on_sec[0]
    if len(on_sec) == 3:
        return target_triangle(*on_sec)
    return centre


def decide(snapshot: Sequence[tuple[Any, Any]], model: Any) -> Decision:
    """``gatherR2_pgm`` for the robot at the origin, which sees every robot with its multiplicity."""
    origin: Pt = (Fraction(0), Fraction(0))
    counts = Counter([origin, *(frac(p) for p in snapshot)])
    most = max(counts.values())
    towers = [p for p, k in counts.items() if k == most]
    if len(towers) == 1:
        rule, goal = "majority", towers[0]
    else:
        support = sorted(counts)
        goal = target(support)
        centre, r2 = smallest_enclosing_circle(support)
        sect = {goal, *(p for p in support if dist2(p, centre) == r2)}
        if all(p in sect for p in support):
            rule = "clean"
        elif origin in sect:
            return stay("dirty-on-sect")
        else:
            rule = "dirty"
    if goal == origin:
        return stay("at-target")
    end = point(goal)
    return Decision(rule, end, ((0, 0), end))


LEMMAS = tuple(lemma.value for lemma in (Lemma.PROGRESS, Lemma.TERMINATION))
"""The claim in the checker's terms: the robots gather (exact gathering) under a fair SSYNC scheduler.
Connectivity means nothing with unlimited visibility; no-collision nothing for points."""

UNIVERSAL = register(
    RuleSet(
        "universal-gathering",
        decide,
        "Certified universal gathering in R2 (Courtieu, Rieg, Tixeuil, Urbain, DISC 2016; Pactole's "
        "gatherR2): to the majority tower, else to the target of the smallest enclosing circle.",
        labels=dict(LABELS),
        lemmas=LEMMAS,
        robots="points",
        goal="point",
    )
)

__all__ = ["LABELS", "UNIVERSAL", "decide", "target", "target_triangle"]
