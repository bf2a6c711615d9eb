"""The published rule sets' decisions (fatline_verify/rules/published): each against the formula it
quotes, computed independently (floats for the published square roots, away from ties), and the exact
geometry they share against a brute-force reference."""

from __future__ import annotations

import math
from fractions import Fraction
from itertools import combinations

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from fatline_verify.model.config import model_from_mapping
from fatline_verify.rules.published import ando, gravity, universal
from fatline_verify.rules.published.exact import (
    dist2,
    exact_root,
    farthest_on_segment,
    lattice_farthest,
    lattice_steps,
    smallest_enclosing_circle,
)

coords = st.integers(min_value=-4, max_value=4)
points = st.tuples(coords, coords)


def _model(rules: str, **own: object):
    """A model of ``rules`` with its own parameters ``own`` (rad_v 4, q 1)."""
    return model_from_mapping(
        {"rules": {"name": rules, **own}, "parameters": {"rad_v": 4, "q": 1}, "options": {"scheduler": "ssync"}},
        source="<test>",
        default_name=rules,
    )


@settings(max_examples=200, deadline=None)
@given(st.lists(points, min_size=1, max_size=5, unique=True))
def test_smallest_enclosing_circle_is_the_smallest_of_every_candidate(pts):
    centre, r2 = smallest_enclosing_circle(pts)
    exact = [(Fraction(x), Fraction(y)) for x, y in pts]
    assert all(dist2(p, centre) <= r2 for p in exact)
    # brute force: no circle through two or three of the points that encloses them all is smaller
    for a, b in combinations(exact, 2):
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        if all(dist2(p, mid) <= dist2(a, mid) for p in exact):
            assert r2 <= dist2(a, mid)


def test_exact_root_only_for_squares():
    assert exact_root(Fraction(9, 4)) == Fraction(3, 2)
    assert exact_root(Fraction(2)) is None and exact_root(Fraction(-1)) is None


def test_lattice_steps_of_a_segment():
    assert lattice_steps((Fraction(4), Fraction(2))) == ((2, 1), 2)
    assert lattice_steps((Fraction(3, 2), Fraction(1))) == ((3, 2), 0)  # only the origin is a lattice point


def _published_move(centre, seen, view):
    """Ando et al.'s ``min(|Rc|, min_j limit_j)`` in floats, as the implementations quoted compute it."""
    cx, cy = float(centre[0]), float(centre[1])
    goal = math.hypot(cx, cy)
    limits = []
    for x, y in seen:
        d = math.hypot(x, y)
        cos = (cx * x + cy * y) / (goal * d)
        sin2 = max(0.0, 1 - cos * cos)
        limits.append(d / 2 * cos + math.sqrt((view / 2) ** 2 - (d / 2) ** 2 * sin2))
    return min([goal, *limits])


@settings(max_examples=150, deadline=None)
@given(st.lists(points, min_size=1, max_size=4, unique=True))
def test_ando_rational_reading_under_approximates_the_published_move_by_at_most_one_grid_step(seen):
    model = _model("ando", destination="rational", grid=16)
    seen = [p for p in seen if p != (0, 0) and model.sees(p[0] ** 2 + p[1] ** 2)]
    assume(seen)
    decision = ando.decide(seen, model)
    centre, _ = smallest_enclosing_circle([*seen, (0, 0)])
    published = _published_move(centre, seen, model.view) if centre != (0, 0) else 0.0
    moved = math.hypot(float(decision.destination[0]), float(decision.destination[1]))
    assert moved <= published + 1e-9  # never beyond the published point
    assert moved >= published - math.hypot(float(centre[0]), float(centre[1])) / 16 - 1e-9
    half = Fraction(model.view, 2)
    dest = (Fraction(decision.destination[0]), Fraction(decision.destination[1]))
    assert all(dist2(dest, (Fraction(x, 2), Fraction(y, 2))) <= half * half for x, y in seen)  # in every D(j)


@settings(max_examples=150, deadline=None)
@given(st.lists(points, min_size=1, max_size=4, unique=True))
def test_ando_lattice_reading_stays_on_the_segment_inside_every_disc(seen):
    model = _model("ando")
    seen = [p for p in seen if p != (0, 0) and model.sees(p[0] ** 2 + p[1] ** 2)]
    assume(seen)
    decision = ando.decide(seen, model)
    x, y = decision.destination
    assert isinstance(x, int) and isinstance(y, int)
    centre, _ = smallest_enclosing_circle([*seen, (0, 0)])
    assert x * centre[1] == y * centre[0]  # on the line to the centre ...
    assert x * centre[0] + y * centre[1] >= 0 and dist2((Fraction(x), Fraction(y)), (0, 0)) <= dist2(centre, (0, 0))
    assert all(4 * ((x - a / 2) ** 2 + (y - b / 2) ** 2) <= model.view**2 for a, b in seen)


def test_ando_readings_named_in_the_model_file():
    two = [(4, 0)]
    assert ando.decide(two, _model("ando")).destination == (2, 0)  # the midpoint: no disc limits it
    assert ando.decide([], _model("ando")).rule == "alone"
    # sec=others leaves the robot itself out of the circle: alone with one other robot it goes to it
    assert ando.decide(two, _model("ando", sec="others")).destination == (4, 0)


def test_ando_limited_by_a_disc_stops_short_of_the_centre():
    model = _model("ando", destination="rational")
    d = ando.decide([(4, 0), (-2, 3)], model)
    centre, _ = smallest_enclosing_circle([(4, 0), (-2, 3), (0, 0)])
    assert d.rule in {"to-centre", "limited"}
    if d.rule == "limited":
        assert dist2((Fraction(d.destination[0]), Fraction(d.destination[1])), (0, 0)) < dist2(centre, (0, 0))


def test_farthest_on_segment_is_exact_when_the_root_is_rational():
    # the disc of radius 5 around (0, 0) holds t * (8, 6) up to t = 1/2 exactly
    disc = [((Fraction(0), Fraction(0)), Fraction(25))]
    assert farthest_on_segment((Fraction(8), Fraction(6)), disc, 3) == Fraction(1, 2)
    assert lattice_farthest((Fraction(8), Fraction(6)), disc) == (4, 3)


def test_gravity_weights_reading():
    seen = [(3, 0), (3, 0), (0, 3)]  # two robots on one point
    multiset = gravity.decide(seen, _model("gravity"))
    assert multiset.destination == (Fraction(3, 2), Fraction(3, 4))
    as_set = gravity.decide(seen, _model("gravity", weights="set"))
    assert as_set.destination == (1, 1)
    # barycentre (2, 2/3) of (0, 0), (3, 0), (3, 2): the way to it passes (3/2, 1/2) only ... no lattice point
    assert gravity.decide([(3, 0), (3, 2)], _model("gravity", destination="lattice")).rule == "held"
    # barycentre (2, 0) of (0, 0), (3, 0), (3, 0): a lattice point, reached under both readings
    assert gravity.decide([(3, 0), (3, 0)], _model("gravity", destination="lattice")).destination == (2, 0)


def test_universal_targets():
    tri = universal.target_triangle
    a, b, c = (Fraction(0), Fraction(0)), (Fraction(4), Fraction(0)), (Fraction(2), Fraction(3))
    assert tri(a, b, c) == c  # isosceles: the apex between the equal sides
    # scalene: the vertex opposite the longest side
    far = (Fraction(1), Fraction(3))
    sides = {a: dist2(b, far), b: dist2(a, far), far: dist2(a, b)}
    assert tri(a, b, far) == max(sides, key=sides.__getitem__)


def test_universal_majority_and_dirty_cases():
    model = _model("universal-gathering")
    # a tower of two at (2, 0): the only point of greatest multiplicity
    assert universal.decide([(2, 0), (2, 0), (0, 2)], model).destination == (2, 0)
    assert universal.decide([(2, 0), (2, 0), (0, 2)], model).rule == "majority"
    # the robot inside the circle of an isosceles triangle: not clean, so it goes to the apex (0, 3)
    inner = universal.decide([(-2, -2), (2, -2), (0, 3)], model)
    assert (inner.rule, inner.destination) == ("dirty", (0, 3))
    # the circle's diameter from the robot to (4, 0), (2, 1) inside it: not clean, the robot is on the circle
    assert universal.decide([(2, 1), (4, 0)], model).rule == "dirty-on-sect"
    # a square: four on the circle, clean, every robot goes to the centre
    assert universal.decide([(4, 0), (0, 4), (4, 4)], model).destination == (2, 2)
