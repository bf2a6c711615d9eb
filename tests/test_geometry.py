"""Exact geometry: pinned ties, and agreement with an independent float computation away from ties."""

from __future__ import annotations

from fractions import Fraction as Fr

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from fatline_verify.model.geometry import (
    collinear,
    dist2,
    path_point_dist2,
    paths_any_speed_dist2,
    paths_lockstep_dist2,
    point_rect_dist2,
    point_segment_dist2,
    segment_segment_dist2,
    segments_intersect,
    timeline,
    width_at_most,
)

coord = st.fractions(min_value=-8, max_value=8, max_denominator=7)
point = st.tuples(coord, coord)


def test_squared_distance_is_exact_on_int_and_fraction():
    assert dist2((0, 0), (3, 4)) == 25
    assert isinstance(dist2((0, 0), (3, 4)), int)
    assert dist2((0, 0), (Fr(1, 3), 0)) == Fr(1, 9)


def test_point_segment_ties():
    # Exactly 2 from the segment's interior, and from an endpoint.
    assert point_segment_dist2((1, 2), (0, 0), (3, 0)) == 4
    assert point_segment_dist2((5, 0), (0, 0), (3, 0)) == 4
    assert point_segment_dist2((2, 2), (0, 0), (0, 0)) == 8


def test_point_segment_interior_projection_is_fraction():
    # From (3,0) to the segment (0,0)-(2,-2): closest at (3/2,-3/2), squared distance 9/2.
    assert point_segment_dist2((3, 0), (0, 0), (2, -2)) == Fr(9, 2)


def test_segment_segment():
    assert segment_segment_dist2((0, 0), (6, 0), (6, -6), (6, 6)) == 0
    assert segment_segment_dist2((0, 0), (2, 0), (0, 2), (2, 2)) == 4
    assert segments_intersect((0, 0), (2, 2), (2, 2), (3, 0))  # shared endpoint
    assert segments_intersect((0, 0), (4, 0), (1, 0), (2, 0))  # collinear overlap
    assert not segments_intersect((0, 0), (1, 0), (2, 0), (3, 0))  # collinear apart


def test_lockstep_vs_any_speed():
    # Paths cross at (6,0), but r1 reaches it at t = 1 and r2 at t = 1/2: closest approach 36/5 at t = 3/5.
    a, b = ((0, 0), (6, 0)), ((6, -6), (6, 6))
    assert paths_any_speed_dist2(a, b) == 0
    assert paths_lockstep_dist2(a, b) == Fr(36, 5)


def test_lockstep_with_l_shaped_paths():
    # r1: (0,0)->(2,0)->(2,2) (length 4, corner at t=1/2); r2 rests at (4,0): closest 4 at t = 1/2.
    assert timeline(((0, 0), (2, 0), (2, 2))) == [(0, (0, 0)), (Fr(1, 2), (2, 0)), (1, (2, 2))]
    assert paths_lockstep_dist2(((0, 0), (2, 0), (2, 2)), ((4, 0),)) == 4
    assert path_point_dist2(((0, 0), (2, 0), (2, 2)), (4, 0)) == 4


def test_several_pieces_must_be_axis_parallel():
    with pytest.raises(ValueError):
        timeline(((0, 0), (1, 1), (2, 0)))


def test_point_rect():
    assert point_rect_dist2((1, -3), (-1, -2), (1, 0)) == 1
    assert point_rect_dist2((0, -1), (-1, -2), (1, 0)) == 0
    assert point_rect_dist2((3, 3), (-1, -2), (1, 0)) == 13


def test_collinear_and_width():
    assert collinear([(0, 0), (3, 3), (6, 6)])
    assert not collinear([(0, 0), (3, 1), (6, 0)])
    assert width_at_most([(0, 0), (3, 1), (6, 0)], 2)  # width 1
    assert width_at_most([(0, 0), (3, 2), (6, 0)], 2)  # width exactly 2: tangent line meets
    assert not width_at_most([(0, 0), (3, 3), (6, 0)], 2)
    # A pair that is not a hull edge must not count: points 1 either side of the line y=0.
    assert not width_at_most([(0, 0), (4, 0), (2, 2), (2, -2)], 2)


# --- independent float computations, compared away from ties ---------------------------------------


def _f(p):
    return np.array([float(p[0]), float(p[1])])


def float_point_segment(p, a, b):
    p, a, b = _f(p), _f(a), _f(b)
    v = b - a
    vv = float(v @ v)
    t = 0.0 if vv == 0 else min(1.0, max(0.0, float((p - a) @ v) / vv))
    d = a + t * v - p
    return float(d @ d)


def float_lockstep(a, b, samples=20001):
    t = np.linspace(0.0, 1.0, samples)[:, None]
    pa = _f(a[0]) + t * (_f(a[-1]) - _f(a[0]))
    pb = _f(b[0]) + t * (_f(b[-1]) - _f(b[0]))
    d = pa - pb
    return float(np.min(np.sum(d * d, axis=1)))


@given(point, point, point)
def test_point_segment_agrees_with_float(p, a, b):
    exact = point_segment_dist2(p, a, b)
    assert abs(float(exact) - float_point_segment(p, a, b)) < 1e-9
    if abs(float(exact) - 4) > 1e-6:  # away from the tie, the collision predicate agrees
        assert (exact < 4) == (float_point_segment(p, a, b) < 4)


@given(point, point, point, point)
def test_segment_segment_agrees_with_float(a, b, c, d):
    exact = segment_segment_dist2(a, b, c, d)
    approx = min(
        float_point_segment(a, c, d),
        float_point_segment(b, c, d),
        float_point_segment(c, a, b),
        float_point_segment(d, a, b),
    )
    if exact != 0:
        assert abs(float(exact) - approx) < 1e-9
    else:  # intersecting: the sampled closest approach of the two lines is near zero
        ts = np.linspace(0, 1, 401)[:, None]
        s1 = _f(a) + ts * (_f(b) - _f(a))
        s2 = _f(c) + ts * (_f(d) - _f(c))
        gaps = ((s1[:, None, :] - s2[None, :, :]) ** 2).sum(axis=2)
        assert gaps.min() < 0.2


@given(point, point, point, point)
def test_lockstep_agrees_with_sampling(a, b, c, d):
    exact = paths_lockstep_dist2((a, b), (c, d))
    sampled = float_lockstep((a, b), (c, d))
    assert float(exact) <= sampled + 1e-9
    assert sampled - float(exact) < 0.02  # the grid step bounds how far sampling can overshoot
