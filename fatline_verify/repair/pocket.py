"""Pockets: a limit of every repair that keeps the lock and moves robots only rightwards, shown exactly.

``repair_lock = left-first`` ("a robot moves only if it sees no robot strictly left of it") is what the
leg obligations need to prove the repaired rule set safe for every swarm size, and every rule of the
paper moves a robot in the +X direction (Lemma: "it will leave its Y axis after a finite time and move
in the +X direction"; the prover's ``x-nondecreasing`` claims). Together they leave some initial
configurations with no way to the line, *whatever the rules decide*: r, the only robot the lock lets
move, sits in a **pocket** that two robots right of it close with their discs, and those two stay
locked because they see r to their left wherever it goes in the pocket.

A :class:`Pocket` is the certificate, checked exactly (:func:`check`): a box ``[x_r, x_s] x [y_lo,
y_hi]`` holding r, whose bottom, top and right sides are each cut into segments that lie inside one
blocker's disc of radius 2 (a segment is inside a disc when both its ends are: the disc is convex).
A path of r's centre that never goes left of ``x_r`` and never comes within 2 of a blocker (no
collision) cannot cross those sides, so r stays in the box: its x never exceeds ``x_s``, which is left
of every blocker. Every blocker sees each corner of the box (so every point of it: distance is convex)
strictly to its left, so it is locked as long as r is in the box; the blockers are not on one vertical,
so the swarm never forms the vertical line. r moves in no direction but right, up and down, and there
is no way out of the box that way.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.swarm import initial_problems

Segment = tuple[Point, Point]


@dataclass(frozen=True, slots=True)
class Pocket:
    """An initial configuration ``robots`` (radii; r first, then the blockers), the box that holds r,
    and the segments covering the box's bottom, top and right sides, each with the blocker whose disc
    holds it."""

    robots: tuple[Point, ...]
    box: tuple[Fraction, Fraction, Fraction, Fraction]
    """``(x_r, x_s, y_lo, y_hi)``: r's own x on the left."""
    cover: tuple[tuple[Segment, int], ...]
    """Each segment and the index (in ``robots``) of the blocker whose open disc of radius 2 holds it."""


def _inside(p: Point, c: Point) -> bool:
    """``p`` strictly within 2 of ``c``: a centre there would collide (distance 2 is contact, allowed)."""
    return (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 < 4


def _covers(segments: Sequence[Segment], a: Point, b: Point) -> bool:
    """Whether ``segments``, laid end to end along one axis, cover the segment ``a``-``b`` exactly."""
    axis = 0 if a[1] == b[1] else 1
    fixed = 1 - axis
    lo, hi = sorted((a[axis], b[axis]))
    spans = []
    for s, t in segments:
        if s[fixed] != a[fixed] or t[fixed] != a[fixed]:
            continue
        spans.append(tuple(sorted((s[axis], t[axis]))))
    reach = lo
    for s_lo, s_hi in sorted(spans):
        if s_lo > reach:
            return False
        reach = max(reach, s_hi)
    return reach >= hi


def check(pocket: Pocket, model: Model) -> list[str]:
    """Why ``pocket`` is not a certificate under ``model`` (nothing: it is one); see the module docstring."""
    problems: list[str] = []
    robots = pocket.robots
    r, blockers = robots[0], robots[1:]
    x_r, x_s, y_lo, y_hi = pocket.box
    lattice = tuple(model.to_lattice(p) for p in robots)
    problems += [f"not initial: {p}" for p in initial_problems(lattice, model)]
    if x_r != r[0] or not (x_r < x_s and y_lo < r[1] < y_hi):
        problems.append(f"the box {pocket.box} does not hold r at {show_point(r)} with r's x on its left")
    for segment, k in pocket.cover:
        if not 1 <= k < len(robots) or not all(_inside(end, robots[k]) for end in segment):
            problems.append(f"segment {segment} is not inside the disc of robot {k}")
    sides = {
        "bottom": ((x_r, y_lo), (x_s, y_lo)),
        "top": ((x_r, y_hi), (x_s, y_hi)),
        "right": ((x_s, y_lo), (x_s, y_hi)),
    }
    for name, (start, end) in sides.items():
        if not _covers([s for s, _ in pocket.cover], start, end):
            problems.append(f"the {name} side is not covered")
    corners = [(x, y) for x in (x_r, x_s) for y in (y_lo, y_hi)]
    view2 = Fraction(model.parameters.rad_v) ** 2
    for k, b in enumerate(blockers, 1):
        if not all(p[0] < b[0] and (p[0] - b[0]) ** 2 + (p[1] - b[1]) ** 2 <= view2 for p in corners):
            problems.append(f"robot {k} at {show_point(b)} does not see every point of the box strictly to its left")
    if len({b[0] for b in blockers}) < 2 and len(blockers) > 1:
        problems.append("the blockers share a vertical")
    return problems


POCKET = Pocket(
    robots=((Fraction(0), Fraction(3, 2)), (Fraction(1), Fraction(7, 2)), (Fraction(3, 2), Fraction(0))),
    box=(Fraction(0), Fraction(1, 2), Fraction(13, 10), Fraction(177, 100)),
    cover=(
        (((Fraction(0), Fraction(13, 10)), (Fraction(1, 2), Fraction(13, 10))), 2),
        (((Fraction(0), Fraction(177, 100)), (Fraction(1, 2), Fraction(177, 100))), 1),
        (((Fraction(1, 2), Fraction(13, 10)), (Fraction(1, 2), Fraction(8, 5))), 2),
        (((Fraction(1, 2), Fraction(8, 5)), (Fraction(1, 2), Fraction(177, 100))), 1),
    ),
)
"""The smallest pocket the checker meets (``repaired`` with ``repair_progress = corner`` at q = 2, 3
robots, an initial configuration): r at (0, 3/2) between (1, 7/2) and (3/2, 0), whose discs overlap
right of r; r cannot get right of x = 1/2 without first moving left."""


__all__ = ["POCKET", "Pocket", "check"]
