"""Views: what a robot at the origin can see on a model's lattice, every one of them or a random sample.

A *view* is a set of lattice points ``p != 0`` of the model's own lattice that the robot sees
(``model.sees``), whose discs are pairwise disjoint and disjoint from its own
(:func:`fatline_verify.schedulers.round.collides` per ``contact``). ``decide`` reads nothing else, so the
views are every input ``decide`` can get on that lattice (at q = 1, rad_v = 4: 40 candidate points and
1,624,375 views, the empty one included). The coverage check (:mod:`.refine`) and the facts the repaired
legs rest on (:mod:`.facts`) are both checked on them.
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterator, Sequence

from ..model.config import Model
from ..schedulers.round import collides

View = tuple[tuple[int, int], ...]
"""A view: the robots the decider at the origin sees, lattice units, sorted."""


def view_points(model: Model) -> list[tuple[int, int]]:
    """The lattice points a robot at the origin can see another robot at, sorted."""
    reach = math.isqrt(model.view2)
    return sorted(
        (x, y)
        for x in range(-reach, reach + 1)
        for y in range(-reach, reach + 1)
        if (x, y) != (0, 0) and model.sees(x * x + y * y) and not collides(x * x + y * y, model)
    )


def _clashes(points: Sequence[tuple[int, int]], model: Model) -> list[int]:
    """Per point, the bit mask of the points whose discs overlap it."""
    out = []
    for a in points:
        mask = 0
        for j, b in enumerate(points):
            if b != a and collides((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2, model):
                mask |= 1 << j
        out.append(mask)
    return out


def all_views(model: Model) -> Iterator[View]:
    """Every view of ``model``'s lattice, the empty one first: each set of :func:`view_points` with
    pairwise disjoint discs exactly once (a recursive build over the points in order, each point taken
    or left, the points it overlaps struck out when it is taken)."""
    points = view_points(model)
    clash = _clashes(points, model)

    def build(free: int, chosen: tuple[tuple[int, int], ...]) -> Iterator[View]:
        if not free:
            yield chosen
            return
        i = (free & -free).bit_length() - 1
        rest = free & ~(1 << i)
        yield from build(rest, chosen)
        yield from build(rest & ~clash[i], (*chosen, points[i]))

    yield from build((1 << len(points)) - 1, ())


def count_views(model: Model) -> int:
    """How many views :func:`all_views` yields (counted, not built: the same recursion, memoized)."""
    points = view_points(model)
    clash = _clashes(points, model)
    memo: dict[int, int] = {}

    def count(free: int) -> int:
        if not free:
            return 1
        if free not in memo:
            i = (free & -free).bit_length() - 1
            rest = free & ~(1 << i)
            memo[free] = count(rest) + count(rest & ~clash[i])
        return memo[free]

    return count((1 << len(points)) - 1)


def largest_view(model: Model) -> int:
    """The most robots a view holds (the largest set of :func:`view_points` with disjoint discs)."""
    points = view_points(model)
    clash = _clashes(points, model)
    memo: dict[int, int] = {}

    def most(free: int) -> int:
        if not free:
            return 0
        if free not in memo:
            i = (free & -free).bit_length() - 1
            rest = free & ~(1 << i)
            memo[free] = max(most(rest), 1 + most(rest & ~clash[i]))
        return memo[free]

    return most((1 << len(points)) - 1)


def random_views(model: Model, n: int, seed: int = 0) -> Iterator[View]:
    """``n`` views drawn at random: a density drawn uniformly in [0, 1], the points in a random order,
    each taken with that probability if its disc is free (sparse and crowded views alike, the empty
    one among them). Every other view is drawn from the points with ``x >= 0`` only: what a robot of
    the left-most vertical sees, the robot the enabledness obligations are about (views drawn from
    every point mostly have a robot in F, E or G, and the decider stays)."""
    rng = random.Random(seed)
    points = view_points(model)
    right = [p for p in points if p[0] >= 0]
    for k in range(n):
        density = rng.random()
        order = (points if k % 2 == 0 else right)[:]
        rng.shuffle(order)
        chosen: list[tuple[int, int]] = []
        for p in order:
            if rng.random() < density and not any(
                collides((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2, model) for c in chosen
            ):
                chosen.append(p)
        yield tuple(sorted(chosen))


__all__ = ["View", "all_views", "count_views", "largest_view", "random_views", "view_points"]
