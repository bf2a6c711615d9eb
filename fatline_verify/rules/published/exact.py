"""Exact geometry the published rule sets share: smallest enclosing circles, the lattice points of a
segment, and the largest step along a segment that stays inside a family of discs, all on rationals.

No float decides anything here: a point is a pair of ``int`` or :class:`~fractions.Fraction`, a length
is kept squared, and where a published rule asks for a square root (a move limit, a point on a circle)
the callers choose between the exact rational value (when the root is rational) and a rational or
lattice under-approximation that stays inside the published feasible region, each a named reading.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction
from itertools import combinations
from math import gcd, isqrt, lcm

from ...model.numbers import normalize

Q = Fraction
Pt = tuple[Fraction, Fraction]


def frac(p: tuple[object, object]) -> Pt:
    """``p`` with exact rational coordinates."""
    return Fraction(p[0]), Fraction(p[1])  # type: ignore[arg-type]


def norm2(p: Pt) -> Fraction:
    """The squared length of ``p``."""
    return p[0] * p[0] + p[1] * p[1]


def dist2(a: Pt, b: Pt) -> Fraction:
    """The squared distance between ``a`` and ``b``."""
    return norm2((a[0] - b[0], a[1] - b[1]))


def dot(a: Pt, b: Pt) -> Fraction:
    return a[0] * b[0] + a[1] * b[1]


def _circumcentre(a: Pt, b: Pt, c: Pt) -> Pt | None:
    """The centre of the circle through ``a``, ``b``, ``c`` (``None`` when they are collinear)."""
    bx, by = b[0] - a[0], b[1] - a[1]
    cx, cy = c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    if d == 0:
        return None
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    return a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d


def smallest_enclosing_circle(points: Iterable[tuple[object, object]]) -> tuple[Pt, Fraction]:
    """The centre and squared radius of the smallest circle enclosing ``points`` (at least one), exactly.

    The swarms here are small (a robot sees a handful of others), so every circle a smallest enclosing
    circle can be is tried: the one point, a diameter circle of two points, the circumcircle of three;
    the smallest that encloses every point is the answer (it is unique, so ties cannot disagree)."""
    pts = sorted({frac(p) for p in points})
    if not pts:
        raise ValueError("smallest_enclosing_circle: expected at least one point")
    if len(pts) == 1:
        return pts[0], Fraction(0)
    best: tuple[Pt, Fraction] | None = None
    candidates: list[Pt] = [((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) for a, b in combinations(pts, 2)]
    candidates += [c for t in combinations(pts, 3) if (c := _circumcentre(*t)) is not None]
    for centre in candidates:
        r2 = max(dist2(centre, p) for p in pts)
        if best is None or r2 < best[1]:
            best = (centre, r2)
    assert best is not None
    return best


def exact_root(x: Fraction) -> Fraction | None:
    """``sqrt(x)`` when it is rational, else ``None`` (``x >= 0``)."""
    if x < 0:
        return None
    n, d = x.numerator, x.denominator
    rn, rd = isqrt(n), isqrt(d)
    return Fraction(rn, rd) if rn * rn == n and rd * rd == d else None


def inside_all(point: Pt, discs: Sequence[tuple[Pt, Fraction]]) -> bool:
    """Whether ``point`` lies in every closed disc ``(centre, squared radius)``."""
    return all(dist2(point, c) <= r2 for c, r2 in discs)


def on_segment(d: Pt, t: Fraction) -> Pt:
    """The point ``t * d`` (the segment from the origin to ``d`` at parameter ``t``)."""
    return d[0] * t, d[1] * t


def exact_limits(d: Pt, discs: Sequence[tuple[Pt, Fraction]]) -> list[Fraction]:
    """For each disc holding the origin, the largest ``t`` with ``t * d`` in it, where that ``t`` is
    rational (the root of ``t^2 |d|^2 - 2 t d.c + |c|^2 - r^2 = 0``); an irrational one is left out."""
    a = norm2(d)
    out = []
    for c, r2 in discs:
        b = dot(d, c)
        root = exact_root(b * b - a * (norm2(c) - r2))
        if root is not None:
            out.append((b + root) / a)
    return out


def farthest_on_segment(d: Pt, discs: Sequence[tuple[Pt, Fraction]], grid: int) -> Fraction:
    """The largest ``t`` in ``[0, 1]`` with ``t * d`` inside every disc, among ``1``, every rational
    exact limit and the multiples of ``1/grid``: the published farthest point where it is rational, a
    rational under-approximation (within ``1/grid`` of the segment) where it is not. The discs all hold
    the origin, so the feasible ``t`` form an interval from 0 and a candidate that is inside is below the
    true limit: the answer is never beyond the published feasible region."""
    candidates = {Fraction(1), *exact_limits(d, discs), *(Fraction(k, grid) for k in range(grid + 1))}
    return max(t for t in candidates if 0 <= t <= 1 and inside_all(on_segment(d, t), discs))


def lattice_steps(d: Pt) -> tuple[tuple[int, int], int]:
    """The lattice points on the segment from the origin to ``d``: ``(w, m)`` with ``w`` the primitive
    integer step along ``d`` and ``m`` the number of whole steps that fit (``k * w`` for ``0 <= k <= m``)."""
    den = lcm(d[0].denominator, d[1].denominator)
    dx, dy = int(d[0] * den), int(d[1] * den)
    g = gcd(dx, dy)
    if g == 0:
        return (0, 0), 0
    w = (dx // g, dy // g)
    return w, g // den  # d = (g / den) * w


def lattice_farthest(d: Pt, discs: Sequence[tuple[Pt, Fraction]]) -> tuple[int, int]:
    """The lattice point of the segment from the origin to ``d`` farthest from the origin inside every
    disc (the origin itself when no other is)."""
    w, m = lattice_steps(d)
    for k in range(m, 0, -1):
        p = (Fraction(k * w[0]), Fraction(k * w[1]))
        if inside_all(p, discs):
            return k * w[0], k * w[1]
    return 0, 0


def point(p: Pt) -> tuple[object, object]:
    """``p`` as the executable model keeps points (a whole number as an ``int``)."""
    return normalize(p[0]), normalize(p[1])


__all__ = [
    "dist2",
    "dot",
    "exact_limits",
    "exact_root",
    "farthest_on_segment",
    "frac",
    "inside_all",
    "lattice_farthest",
    "lattice_steps",
    "norm2",
    "on_segment",
    "point",
    "smallest_enclosing_circle",
]
