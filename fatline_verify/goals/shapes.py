"""Exact tests of the shapes a swarm may have to form beyond a line: one point, a small disc, a circle,
discs that hold together.

Each test comes twice: on the executable model's positions (``int`` or :class:`~fractions.Fraction`,
one state) and vectorised over ``(m, n, 2)`` integer arrays (any unit: every length a test takes is
given in that unit). Both use the same integer identities, so no float decides anything; a
differential test holds the two to the same answers.

- **Point**: every centre equal.
- **Disc of diameter d**: some disc of diameter ``d`` holds every centre, i.e. the smallest enclosing
  circle has radius at most ``d / 2``. That circle passes through two points as a diameter or three as a
  circumcircle, so it is enough to try those circles: one holds every point and has radius at most
  ``d / 2`` exactly when the smallest does.
- **Circle**: every distinct centre on one circle (of radius ``r``, or of any radius when ``r`` is 0):
  two distinct points always are (with radius ``r`` when they are at most ``2 r`` apart); three or more
  are when they are not collinear and every other point passes the four-point determinant test against
  the circle of three non-collinear ones.
- **Discs that hold together**: the union of the closed discs of radius ``r`` about the centres is
  connected, i.e. the graph joining two centres at most ``2 r`` apart (their discs touch or overlap)
  is connected; compared as squared distances, ``reach2 = (2 r)^2``.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations
from typing import Any

import numpy as np

Point = tuple[Any, Any]


def _distinct(points: Sequence[Point]) -> list[Point]:
    return list(dict.fromkeys(points))


def at_one_point(points: Sequence[Point]) -> bool:
    """Whether every point is the same point."""
    return len(set(points)) <= 1


def in_disc(points: Sequence[Point], diameter: Any) -> bool:
    """Whether some closed disc of diameter ``diameter`` holds every point (exact)."""
    pts = _distinct(points)
    if len(pts) <= 1:
        return diameter >= 0
    d2 = diameter * diameter
    for a, b in combinations(pts, 2):  # a diameter ab: centre (a + b) / 2
        ab2 = (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
        if ab2 <= d2 and all((2 * p[0] - a[0] - b[0]) ** 2 + (2 * p[1] - a[1] - b[1]) ** 2 <= ab2 for p in pts):
            return True
    for a, b, c in combinations(pts, 3):  # a circumcircle: centre U / D relative to a
        bx, by, cx, cy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
        den = 2 * (bx * cy - by * cx)
        if den == 0:
            continue
        b2, c2 = bx * bx + by * by, cx * cx + cy * cy
        ux, uy = cy * b2 - by * c2, bx * c2 - cx * b2
        r2 = ux * ux + uy * uy  # the radius squared, times den^2
        if 4 * r2 <= d2 * den * den and all(
            (den * (p[0] - a[0]) - ux) ** 2 + (den * (p[1] - a[1]) - uy) ** 2 <= r2 for p in pts
        ):
            return True
    return False


def _concyclic4(a: Point, b: Point, c: Point, d: Point) -> bool:
    """Whether ``d`` is on the circle through ``a``, ``b``, ``c`` (or the line, if they are collinear)."""
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (x1, y1), (x2, y2), (x3, y3) = rows
    n1, n2, n3 = x1 * x1 + y1 * y1, x2 * x2 + y2 * y2, x3 * x3 + y3 * y3
    det = x1 * (y2 * n3 - n2 * y3) - y1 * (x2 * n3 - n2 * x3) + n1 * (x2 * y3 - y2 * x3)
    return det == 0


def on_circle(points: Sequence[Point], radius: Any = 0) -> bool:
    """Whether every point lies on one circle, of radius ``radius`` (``0``: any radius), exactly."""
    pts = _distinct(points)
    if len(pts) <= 1:
        return True
    if len(pts) == 2:
        a, b = pts
        return radius == 0 or (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 <= 4 * radius * radius
    a, b = pts[0], pts[1]
    third = next((c for c in pts[2:] if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) != 0), None)
    if third is None:
        return False  # three or more distinct points on a line are on no circle
    if not all(_concyclic4(a, b, third, d) for d in pts[2:]):
        return False
    if radius == 0:
        return True
    ab2 = (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
    bc2 = (b[0] - third[0]) ** 2 + (b[1] - third[1]) ** 2
    ca2 = (third[0] - a[0]) ** 2 + (third[1] - a[1]) ** 2
    cr = (b[0] - a[0]) * (third[1] - a[1]) - (b[1] - a[1]) * (third[0] - a[0])
    return ab2 * bc2 * ca2 == 4 * cr * cr * radius * radius  # R = |ab||bc||ca| / (2 |cross|)


def discs_connected(points: Sequence[Point], reach2: Any) -> bool:
    """Whether the graph joining two points at squared distance at most ``reach2`` is connected (exact):
    for discs of radius ``r`` and ``reach2 = (2 r)^2``, whether the union of the discs is connected."""
    if len(points) <= 1:
        return True
    seen, todo = {0}, [0]
    while todo:
        a = points[todo.pop()]
        for k, b in enumerate(points):
            if k not in seen and (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 <= reach2:
                seen.add(k)
                todo.append(k)
    return len(seen) == len(points)


# --- vectorised: (m, n, 2) int64 ----------------------------------------------------------------------
def _distinct_count(pos: np.ndarray) -> np.ndarray:
    """Per state, how many distinct points it holds."""
    span = int(np.abs(pos).max()) * 2 + 1 if pos.size else 1
    codes = np.sort((pos[..., 0] + span) * (2 * span + 1) + pos[..., 1] + span, axis=1)
    return (np.diff(codes, axis=1) != 0).sum(axis=1) + 1  # type: ignore[no-any-return]


def at_one_point_batch(pos: np.ndarray) -> np.ndarray:
    """:func:`at_one_point` per state."""
    return (pos == pos[:, :1, :]).all(axis=(1, 2))  # type: ignore[no-any-return]


def in_disc_batch(pos: np.ndarray, diameter: int) -> np.ndarray:
    """:func:`in_disc` per state (``diameter`` in the positions' unit)."""
    n = pos.shape[1]
    out = _distinct_count(pos) <= 1
    d2 = diameter * diameter
    px, py = pos[..., 0], pos[..., 1]
    for i, j in combinations(range(n), 2):
        a, b = pos[:, i], pos[:, j]
        ab2 = ((a - b) ** 2).sum(axis=1)
        cx, cy = a[:, 0] + b[:, 0], a[:, 1] + b[:, 1]
        inside = ((2 * px - cx[:, None]) ** 2 + (2 * py - cy[:, None]) ** 2 <= ab2[:, None]).all(axis=1)
        out |= (ab2 > 0) & (ab2 <= d2) & inside
    for i, j, k in combinations(range(n), 3):
        a = pos[:, i]
        bx, by = pos[:, j, 0] - a[:, 0], pos[:, j, 1] - a[:, 1]
        cx, cy = pos[:, k, 0] - a[:, 0], pos[:, k, 1] - a[:, 1]
        den = 2 * (bx * cy - by * cx)
        b2, c2 = bx * bx + by * by, cx * cx + cy * cy
        ux, uy = cy * b2 - by * c2, bx * c2 - cx * b2
        r2 = ux * ux + uy * uy
        rx, ry = px - a[:, 0:1], py - a[:, 1:2]
        inside = ((den[:, None] * rx - ux[:, None]) ** 2 + (den[:, None] * ry - uy[:, None]) ** 2 <= r2[:, None]).all(
            axis=1
        )
        out |= (den != 0) & (4 * r2 <= d2 * den * den) & inside
    return out  # type: ignore[no-any-return]


def on_circle_batch(pos: np.ndarray, radius: int = 0) -> np.ndarray:
    """:func:`on_circle` per state (``radius`` in the positions' unit; ``0``: any)."""
    m, n, _ = pos.shape
    count = _distinct_count(pos)
    out = count <= 1
    if n >= 2:
        far2 = ((pos[:, :, None, :] - pos[:, None, :, :]) ** 2).sum(axis=-1).max(axis=(1, 2))
        out |= (count == 2) & ((radius == 0) | (far2 <= 4 * radius * radius))
    px, py = pos[..., 0], pos[..., 1]
    found = np.zeros(m, dtype=bool)
    for i, j, k in combinations(range(n), 3):
        a, b, c = pos[:, i], pos[:, j], pos[:, k]
        cr = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        rows = [(p[:, 0:1] - px, p[:, 1:2] - py) for p in (a, b, c)]  # each (m, n): p - d for every d
        (x1, y1), (x2, y2), (x3, y3) = rows
        n1, n2, n3 = x1 * x1 + y1 * y1, x2 * x2 + y2 * y2, x3 * x3 + y3 * y3
        det = x1 * (y2 * n3 - n2 * y3) - y1 * (x2 * n3 - n2 * x3) + n1 * (x2 * y3 - y2 * x3)
        fits = (cr != 0) & (det == 0).all(axis=1)
        if radius:
            ab2 = ((a - b) ** 2).sum(axis=1)
            bc2 = ((b - c) ** 2).sum(axis=1)
            ca2 = ((c - a) ** 2).sum(axis=1)
            fits &= ab2 * bc2 * ca2 == 4 * cr * cr * radius * radius
        found |= fits
    return out | ((count >= 3) & found)  # type: ignore[no-any-return]


def discs_connected_batch(pos: np.ndarray, reach2: int) -> np.ndarray:
    """:func:`discs_connected` per state (``reach2`` in the positions' unit, squared): the closure of the
    adjacency matrix, one robot's row grown ``n - 1`` times."""
    m, n, _ = pos.shape
    if n <= 1:
        return np.ones(m, dtype=bool)
    near = ((pos[:, :, None, :] - pos[:, None, :, :]) ** 2).sum(axis=-1) <= reach2
    reached = near[:, 0, :].copy()
    for _ in range(n - 2):
        reached |= (reached[:, :, None] & near).any(axis=1)
    return reached.all(axis=1)  # type: ignore[no-any-return]


__all__ = [
    "at_one_point",
    "at_one_point_batch",
    "discs_connected",
    "discs_connected_batch",
    "in_disc",
    "in_disc_batch",
    "on_circle",
    "on_circle_batch",
]
