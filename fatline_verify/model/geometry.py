"""Exact 2-D geometry on ``int`` and ``Fraction``: squared distances only, never a square root.

Robots are discs; two discs of radius ``rho`` overlap iff their centres are closer than ``2 rho``,
so every predicate of the model compares a *squared* distance with a squared threshold. The
functions here return exact squared distances and leave the comparison (strict or not, per the
model's ``contact`` and ``vacant`` options) to the caller.

A *path* is a tuple of waypoints ``(s, ..., t)`` followed at constant speed; a path of one point
is a robot at rest. Rigid moves in this model are straight segments or axis-parallel L shapes.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from itertools import pairwise

from .numbers import Number, Point, normalize

Path = tuple[Point, ...]


def sub(a: Point, b: Point) -> Point:
    """``a - b``."""
    return (a[0] - b[0], a[1] - b[1])


def dot(a: Point, b: Point) -> Number:
    """Dot product."""
    return a[0] * b[0] + a[1] * b[1]


def cross(a: Point, b: Point) -> Number:
    """z-component of the cross product ``a x b``."""
    return a[0] * b[1] - a[1] * b[0]


def norm2(a: Point) -> Number:
    """Squared length."""
    return a[0] * a[0] + a[1] * a[1]


def dist2(a: Point, b: Point) -> Number:
    """Squared distance between two points."""
    dx = a[0] - b[0]
    dy = a[1] - b[1]
    return dx * dx + dy * dy


def _closest_on_unit(d0: Point, v: Point) -> Number:
    """``min over s in [0, 1] of |d0 + s v|^2``, exactly.

    The minimiser of the convex quadratic is ``s* = -d0.v / |v|^2`` clamped to ``[0, 1]``.
    """
    vv = norm2(v)
    if vv == 0:
        return norm2(d0)
    num = -dot(d0, v)
    if num <= 0:
        return norm2(d0)
    if num >= vv:
        return norm2((d0[0] + v[0], d0[1] + v[1]))
    s = Fraction(num) / vv
    return normalize(norm2((d0[0] + s * v[0], d0[1] + s * v[1])))


def point_segment_dist2(p: Point, a: Point, b: Point) -> Number:
    """Squared distance from point ``p`` to the closed segment ``ab`` (a point when ``a == b``)."""
    return _closest_on_unit(sub(a, p), sub(b, a))


def _orientation(a: Point, b: Point, c: Point) -> int:
    value = cross(sub(b, a), sub(c, a))
    return (value > 0) - (value < 0)


def _on_segment(p: Point, a: Point, b: Point) -> bool:
    """``p`` collinear with ``ab`` lies within its bounding box."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_intersect(a: Point, b: Point, c: Point, d: Point) -> bool:
    """Whether the closed segments ``ab`` and ``cd`` share a point (exact orientation tests)."""
    o1, o2 = _orientation(a, b, c), _orientation(a, b, d)
    o3, o4 = _orientation(c, d, a), _orientation(c, d, b)
    if o1 != o2 and o3 != o4 and o1 * o2 <= 0 and o3 * o4 <= 0:
        return True
    return (
        (o1 == 0 and _on_segment(c, a, b))
        or (o2 == 0 and _on_segment(d, a, b))
        or (o3 == 0 and _on_segment(a, c, d))
        or (o4 == 0 and _on_segment(b, c, d))
    )


def segment_segment_dist2(a: Point, b: Point, c: Point, d: Point) -> Number:
    """Squared distance between closed segments ``ab`` and ``cd``.

    Zero when they intersect; otherwise the minimum is attained at an endpoint of one of them.
    """
    if segments_intersect(a, b, c, d):
        return 0
    return min(
        point_segment_dist2(a, c, d),
        point_segment_dist2(b, c, d),
        point_segment_dist2(c, a, b),
        point_segment_dist2(d, a, b),
    )


def pieces(path: Path) -> list[tuple[Point, Point]]:
    """The segments of a path; a path of one point is one degenerate segment."""
    if len(path) == 1:
        return [(path[0], path[0])]
    return [(path[k], path[k + 1]) for k in range(len(path) - 1)]


def path_point_dist2(path: Path, c: Point) -> Number:
    """Closest squared distance between a disc centre at rest at ``c`` and a mover along ``path``.

    This is the swept-disc test of a mover against a resting robot: they come within ``2 rho``
    iff this value is below ``(2 rho)^2``.
    """
    return min(point_segment_dist2(c, a, b) for a, b in pieces(path))


def paths_any_speed_dist2(p: Path, q: Path) -> Number:
    """Closest squared distance two movers *can* reach when speeds are arbitrary (``timing=any-speed``).

    With rigid but otherwise arbitrary speed profiles, every pair of points (one on each path) is
    occupied at a common instant by some schedule, so the answer is the distance of the two swept
    centre-lines: the minimum segment-segment distance over their pieces.
    """
    return min(segment_segment_dist2(a, b, c, d) for a, b in pieces(p) for c, d in pieces(q))


def timeline(path: Path) -> list[tuple[Fraction, Point]]:
    """Breakpoints ``(time, position)`` of a constant-speed traversal of ``path`` in time ``[0, 1]``.

    A one-piece path needs no length. A path of several pieces must be axis-parallel (the L-shaped
    moves of the ``path`` option), so its piece lengths ``|dx| + |dy|`` are exact.
    """
    segs = [(a, b) for a, b in pieces(path) if a != b]
    if not segs:
        return [(Fraction(0), path[0]), (Fraction(1), path[0])]
    if len(segs) == 1:
        return [(Fraction(0), segs[0][0]), (Fraction(1), segs[0][1])]
    lengths: list[Number] = []
    for a, b in segs:
        if a[0] != b[0] and a[1] != b[1]:
            raise ValueError(f"path piece {a}->{b}: a path of several pieces must be axis-parallel")
        dx, dy = b[0] - a[0], b[1] - a[1]
        lengths.append((dx if dx >= 0 else -dx) + (dy if dy >= 0 else -dy))
    total: Number = 0
    for length in lengths:
        total += length
    out = [(Fraction(0), segs[0][0])]
    run: Number = 0
    for (_, b), length in zip(segs, lengths, strict=True):
        run += length
        out.append((Fraction(run) / total, b))
    return out


def _position_at(line: Sequence[tuple[Fraction, Point]], t: Fraction) -> Point:
    for (t0, p0), (t1, p1) in pairwise(line):
        if t0 <= t <= t1:
            if t1 == t0:
                return p0
            s = (t - t0) / (t1 - t0)
            return (normalize(p0[0] + s * (p1[0] - p0[0])), normalize(p0[1] + s * (p1[1] - p0[1])))
    return line[-1][1]


def point_at(path: Path, t: Fraction) -> Point:
    """Where a constant-speed traversal of ``path`` (time ``[0, 1]``) is at time ``t``, exactly."""
    return _position_at(timeline(path), t)


def subpath(path: Path, t0: Fraction, t1: Fraction) -> Path:
    """The part of ``path`` traversed between times ``t0 <= t1`` at constant speed: its end points and
    every corner strictly between them (a move step of the asynchronous scheduler sweeps exactly this)."""
    line = timeline(path)
    inner = [p for t, p in line if t0 < t < t1]
    out = [point_at(path, t0), *inner, point_at(path, t1)]
    return tuple(p for k, p in enumerate(out) if k == 0 or p != out[k - 1]) if len(out) > 1 else tuple(out)


def paths_lockstep_dist2(p: Path, q: Path) -> Number:
    """Closest squared distance of two movers that start together, move at constant speed along
    their paths and arrive together (``timing=lockstep``).

    Between consecutive breakpoints of either timeline both centres move linearly, so the relative
    position is linear there and its minimum norm is the clamped quadratic minimum.
    """
    lp, lq = timeline(p), timeline(q)
    times = sorted({t for t, _ in lp} | {t for t, _ in lq})
    best: Number | None = None
    for t0, t1 in pairwise(times):
        d0 = sub(_position_at(lp, t0), _position_at(lq, t0))
        d1 = sub(_position_at(lp, t1), _position_at(lq, t1))
        value = _closest_on_unit(d0, sub(d1, d0))
        best = value if best is None or value < best else best
    assert best is not None
    return best


def point_rect_dist2(p: Point, lo: Point, hi: Point) -> Number:
    """Squared distance from ``p`` to the closed axis-parallel rectangle ``[lo, hi]``."""
    dx = max(lo[0] - p[0], 0, p[0] - hi[0])
    dy = max(lo[1] - p[1], 0, p[1] - hi[1])
    return dx * dx + dy * dy


def collinear(points: Sequence[Point]) -> bool:
    """Whether all points lie on one straight line (fewer than three always do)."""
    distinct = list(dict.fromkeys(points))
    if len(distinct) < 3:
        return True
    a, b = distinct[0], distinct[1]
    return all(cross(sub(b, a), sub(c, a)) == 0 for c in distinct[2:])


def width_at_most(points: Sequence[Point], w: Number) -> bool:
    """Whether some straight line has every point within distance ``w / 2``, i.e. the point set's
    width is at most ``w``.

    The minimum width of a finite set is attained perpendicular to an edge of its convex hull, and
    a hull edge joins two of the points with every other point on one side of it. So trying every
    pair ``ab`` is exact when the test is one-sided: all ``cross(b - a, c - a)`` of one sign and
    ``cross^2 <= w^2 |b - a|^2``. Then all points lie in a strip of width ``w`` and within ``w / 2``
    of its middle line.
    """
    distinct = list(dict.fromkeys(points))
    if len(distinct) < 3:
        return True
    for i, a in enumerate(distinct):
        for b in distinct[i + 1 :]:
            ab = sub(b, a)
            limit = w * w * norm2(ab)
            sides = [cross(ab, sub(c, a)) for c in distinct]
            one_side = all(v >= 0 for v in sides) or all(v <= 0 for v in sides)
            if one_side and all(v * v <= limit for v in sides):
                return True
    return False
