"""The linearization's cuts are consequences of the comparisons they stand for (exact, on rational
points), and the refinement loop decides what the plain relaxation cannot."""

from __future__ import annotations

from fractions import Fraction

import pytest
import z3
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.prove.smt.cases import Arith
from fatline_verify.prove.smt.claims import Built
from fatline_verify.prove.smt.linearize import (
    FIRST_GRID,
    Linearization,
    cover,
    direction,
    disc,
    sector,
    sqrt_down,
    sqrt_up,
)
from fatline_verify.prove.smt.solving import relaxation, solver_for

rationals = st.fractions(min_value=-6, max_value=6, max_denominator=1000)
radii2 = st.fractions(min_value=Fraction(1, 100), max_value=36, max_denominator=100)
params = st.fractions(min_value=0, max_value=Fraction(255, 64), max_denominator=64)


@given(st.fractions(min_value=0, max_value=100, max_denominator=10**6))
def test_square_roots_are_rounded_the_right_way(x):
    assert sqrt_down(x) ** 2 <= x <= sqrt_up(x) ** 2
    assert sqrt_up(x) - sqrt_down(x) <= Fraction(1, 10**9)


@given(params)
def test_grid_directions_are_exact_unit_vectors_in_angle_order(s):
    x, y = direction(s)
    assert x * x + y * y == 1
    later = direction(min(s + Fraction(1, 128), Fraction(4) - Fraction(1, 10**6)))
    if later != (x, y):
        assert x * later[1] - y * later[0] > 0  # counter-clockwise, less than half a turn


@settings(max_examples=300)
@given(rationals, rationals, radii2, st.lists(params, max_size=6))
def test_a_point_outside_a_disc_satisfies_one_sector_half_plane(px, py, r2, extra):
    if px * px + py * py < r2:
        return
    planes = cover([*FIRST_GRID, *extra], r2)
    assert any(w[0] * px + w[1] * py >= h for w, h in planes)


widths = st.fractions(min_value=Fraction(1, 4096), max_value=1, max_denominator=4096)
weights = st.fractions(min_value=0, max_value=8, max_denominator=1000)


@settings(max_examples=300)
@given(weights, weights, radii2, params, widths)
def test_a_point_outside_a_disc_between_a_gaps_directions_satisfies_its_sector_cut(a, b, r2, lo, width):
    """The local cut a refinement adds: a point ``a u + b v`` (``a, b >= 0``: between the gap's two
    directions, the gap wrapping past a full turn too) outside the disc has ``w . l >= h``."""
    u, v, w, h = sector(lo, lo + width, r2)
    px, py = a * u[0] + b * v[0], a * u[1] + b * v[1]
    if px * px + py * py < r2:
        return
    assert w[0] * px + w[1] * py >= h


def _outside_disc(ctx):
    x, y = z3.Real("x", ctx), z3.Real("y", ctx)
    boolean = z3.Bool("b", ctx)
    d = disc(x * x + y * y >= 4, boolean)
    assert d is not None and not d.inside_when_true
    return d, x, y, boolean


def _holds(cuts, ctx, x, y, boolean, p) -> bool:
    """Whether the cuts allow the Boolean to say "outside" at the point ``p``."""
    solver = z3.Solver(ctx=ctx)
    solver.add(*cuts, boolean, x == z3.RealVal(p[0], ctx), y == z3.RealVal(p[1], ctx))
    return solver.check() == z3.sat


near_one = st.fractions(min_value=Fraction(1, 10), max_value=Fraction(99999, 100000), max_denominator=10**6)
angles = st.fractions(min_value=0, max_value=Fraction(3999, 1000), max_denominator=10**6)


@settings(max_examples=150, deadline=None)
@given(near_one, angles)
def test_a_refinement_excludes_a_point_wrongly_put_outside(scale, s):
    """A point strictly inside the disc that the Boolean calls outside gets cuts that exclude it (z3,
    given the point and the outside literal, finds them unsatisfiable), however close to the circle
    (several subdivisions) and whatever its angle (not only on the grid's rays), unless the refinement
    says it cannot (no cuts)."""
    ctx = z3.Context()
    d, x, y, boolean = _outside_disc(ctx)
    u = direction(s)
    p = (2 * scale * u[0], 2 * scale * u[1])
    cuts = d.refine(p, False, ctx)
    assert cuts or scale > Fraction(9999, 10000)
    if cuts:
        assert not _holds(cuts, ctx, x, y, boolean, p)


@settings(max_examples=100, deadline=None)
@given(near_one, angles, st.fractions(min_value=1, max_value=3, max_denominator=1000), angles)
def test_refinement_cuts_never_exclude_a_point_outside_the_disc(scale, s, far, t):
    """The cuts, as z3 formulas, are consequences of "outside": after refining around an inside point,
    any point outside the disc (here at distance 2 to 6, any angle) still satisfies all of them."""
    ctx = z3.Context()
    d, x, y, boolean = _outside_disc(ctx)
    u, v = direction(s), direction(t)
    cuts = d.refine((2 * scale * u[0], 2 * scale * u[1]), False, ctx) + d.cuts(ctx)
    assert _holds(cuts, ctx, x, y, boolean, (2 * far * v[0], 2 * far * v[1]))
    assert _holds(cuts, ctx, x, y, boolean, (2 * u[0], 2 * u[1]))  # on the circle, at the refined angle


@settings(max_examples=300)
@given(rationals, rationals, radii2, params)
def test_a_point_inside_a_disc_satisfies_every_tangent(px, py, r2, s):
    if px * px + py * py > r2:
        return
    u = direction(s)
    assert u[0] * px + u[1] * py <= sqrt_up(r2)


def test_a_sector_half_plane_excludes_points_well_inside():
    """The cover is not vacuous: a point within R cos(gap/2) of the centre satisfies none (8 directions:
    cos 22.5 degrees > 0.92, so a point at 0.9 R is excluded)."""
    planes = cover(list(FIRST_GRID), Fraction(4))
    assert all(h > 0 for _, h in planes)
    for p in [(Fraction(9, 5), Fraction(0)), (Fraction(0), Fraction(-9, 5)), (Fraction(-127, 100), Fraction(127, 100))]:
        assert not any(w[0] * p[0] + w[1] * p[1] >= h for w, h in planes), p


def test_comparisons_are_read_as_discs():
    ctx = z3.Context()
    a, b, c, d = (z3.Real(n, ctx) for n in "abcd")
    boolean = z3.Bool("b", ctx)
    got = disc(z3.RealVal(4, ctx) <= (a - b) * (a - b) + (c - d) * (c - d), boolean)  # constant first
    assert got is not None and got.r2 == 4 and not got.inside_when_true and not got.strict
    got = disc((a * a + c * c) * 100 < 441, boolean)
    assert got is not None and got.r2 == Fraction(441, 100) and got.inside_when_true and got.strict
    got = disc((a - b) * (a - b) + 1 * 1 <= 16, boolean)
    assert got is not None and got.r2 == 15  # one squared term and a constant
    assert disc(a * b <= 1, boolean) is None
    assert disc(a * a + 2 * c * c <= 1, boolean) is None  # an ellipse: left a free Boolean


def _built(assertions, ar: Arith, bodies) -> Built:
    return Built(ar, assertions, bodies, "")


def test_the_linearization_proves_what_the_relaxation_cannot():
    """x^2 + y^2 <= 1 and x + y >= 1.45: unsat (the most x + y is sqrt 2), but not linearly."""
    ar = Arith(None)
    x, y = z3.Real("p.x", ar.ctx), z3.Real("p.y", ar.ctx)
    built = _built([x * x + y * y <= 1, x + y >= Fraction(145, 100)], ar, {"p": (x, y)})
    loose = relaxation(built)
    assert solver_for(loose, 5).check() == z3.sat
    lin = Linearization(built)
    answer = lin.check(5)
    assert answer.status == "unsat" and lin.refinements >= 1


def test_the_linearization_finds_a_solution_and_polishes_it_to_the_circle():
    """On the circle of radius 5 with x = 3: the linear problem's points miss the circle, the polish
    solves for the point over the reals (y = 4 or -4), exactly."""
    ar = Arith(None)
    x, y = z3.Real("p.x", ar.ctx), z3.Real("p.y", ar.ctx)
    built = _built([x * x + y * y >= 25, x * x + y * y <= 25, x == 3], ar, {"p": (x, y)})
    answer = Linearization(built).check(5)
    assert answer.status == "sat" and not answer.rounded
    px, py = answer.positions["p"]
    assert px == 3 and py * py == 16


@pytest.mark.parametrize("bound", [Fraction(141, 100), Fraction(3, 2)])
def test_near_the_boundary_the_answer_follows_the_exact_geometry(bound):
    """x + y >= bound on the unit disc: sat below sqrt 2 (a solution of the obligation itself), unsat above."""
    ar = Arith(None)
    x, y = z3.Real("p.x", ar.ctx), z3.Real("p.y", ar.ctx)
    built = _built([x * x + y * y <= 1, x + y >= bound], ar, {"p": (x, y)})
    answer = Linearization(built).check(10)
    expected = "sat" if bound * bound < 2 else "unsat"
    assert answer.status == expected
    if expected == "sat":
        px, py = answer.positions["p"]
        assert px * px + py * py <= 1 and px + py >= bound
