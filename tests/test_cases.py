"""Decision cases: the witness argument the prover's any-size claims rest on, and the z3 encoding of
each case against the executable ``decide``."""

from __future__ import annotations

from fractions import Fraction as Fr

import pytest
import z3
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.model.geometry import dist2, path_point_dist2
from fatline_verify.prove.smt.cases import Arith, decide_case, role_names, same
from fatline_verify.rules.paper.cases import case_of, cases_for, witnesses
from fatline_verify.rules.registry import decide
from tests.conftest import make_model
from tests.test_properties import readings

coord = st.one_of(st.integers(-9, 9).map(Fr), st.fractions(min_value=-9, max_value=9, max_denominator=2))


@st.composite
def swarms(draw, crowded: bool = False):
    """Non-overlapping robots around r at the origin, visible or not. ``crowded``: many robots
    packed near r's view, where blockers and witnesses compete."""
    span = 6 if crowded else 9
    size = 24 if crowded else 10
    points = draw(
        st.lists(
            st.tuples(
                st.fractions(min_value=-span, max_value=span, max_denominator=2),
                st.fractions(min_value=-span, max_value=span, max_denominator=2),
            ),
            max_size=size,
        )
    )
    out: list[tuple[Fr, Fr]] = []
    for p in points:
        if dist2(p, (0, 0)) >= 4 and all(dist2(p, c) >= 4 for c in out):
            out.append(p)
    return out


def _visible(model, points):
    return [p for p in points if model.sees(dist2(p, (0, 0)))]


def _witness_argument(opts, swarm, pick):
    """r's witnesses and any one other robot, taken out of the swarm, give the same case and
    destination, and that robot's distance to r's path is the same (so is any violation at it)."""
    model = make_model(**opts)
    full = decide(_visible(model, swarm), model)
    case = case_of(full, model)
    assert case in cases_for(model)
    kept = witnesses(full, _visible(model, swarm), model)
    o = swarm[pick % len(swarm)] if swarm else None
    sub = list(dict.fromkeys([*kept, *([o] if o is not None else [])]))
    again = decide(_visible(model, sub), model)
    assert case_of(again, model) == case
    assert (again.rule, again.destination, again.path) == (full.rule, full.destination, full.path)
    if o is not None:
        assert path_point_dist2(again.path, o) == path_point_dist2(full.path, o)


@settings(max_examples=300, deadline=None)
@given(readings(), swarms(), st.integers(0, 100))
def test_witnesses_make_the_same_decision_on_random_swarms(opts, swarm, pick):
    _witness_argument(opts, swarm, pick)


@settings(max_examples=300, deadline=None)
@given(readings(), swarms(crowded=True), st.integers(0, 100))
def test_witnesses_make_the_same_decision_on_crowded_swarms(opts, swarm, pick):
    _witness_argument(opts, swarm, pick)


def test_every_case_is_met_on_some_crowded_lattice_swarm():
    """The cases are not just names: a seeded sweep of lattice swarms meets most of the paper's."""
    import random

    model = make_model()
    rng = random.Random(7)
    seen = set()
    for _ in range(4000):
        pts: list[tuple[int, int]] = []
        for _ in range(rng.randint(1, 12)):
            p = (rng.randint(-6, 6), rng.randint(-6, 6))
            if dist2(p, (0, 0)) >= 4 and all(dist2(p, c) >= 4 for c in pts):
                pts.append(p)
        seen.add(case_of(decide(_visible(model, pts), model), model))
    assert len(seen) >= 18  # of 29; four can never fire (candidate 4 within view needs x_psi = 0)
    assert seen <= set(cases_for(model))


def _encoded_case(model, case, points):
    """Whether the z3 encoding of ``case`` holds with every robot fixed at ``points`` (roles must be
    robots of the swarm) and, if so, its destination."""
    ar = Arith(None)
    universe = [(ar.num(x), ar.num(y)) for x, y in points]
    me = ar.origin()
    roles = {n: ar.point(n) for n in role_names(case, model)}
    solver = z3.Solver(ctx=ar.ctx)
    for p in roles.values():
        solver.add(z3.Or(*[same(p, u) for u in universe]) if universe else ar.false())
    constraints, dest = decide_case(ar, model, case, me, roles, universe)
    solver.add(*constraints)
    if solver.check() != z3.sat:
        return None
    m = solver.model()

    def value(e):
        v = m.eval(e, model_completion=True)
        return Fr(v.numerator_as_long(), v.denominator_as_long())

    return (value(dest[0]), value(dest[1]))


@pytest.mark.slow  # 40 crowded swarms, each encoded for every case; the default tier draws 10 (below)
@settings(max_examples=40, deadline=None)
@given(readings(), swarms(crowded=True))
def test_the_encoding_of_each_case_agrees_with_decide(opts, swarm):
    """Exactly the case ``decide`` falls in is satisfiable with the swarm fixed, with the same destination."""
    _encoding_agrees(opts, swarm)


@settings(max_examples=10, deadline=None)
@given(readings(), swarms(crowded=True))
def test_the_encoding_of_each_case_agrees_with_decide_on_a_few_swarms(opts, swarm):
    """The fast representative of the above: the same check on 10 random swarms."""
    _encoding_agrees(opts, swarm)


def _encoding_agrees(opts, swarm) -> None:
    model = make_model(**opts)
    decision = decide(_visible(model, swarm), model)
    expected = case_of(decision, model)
    for case in cases_for(model):
        got = _encoded_case(model, case, swarm)
        if case == expected:
            assert got == tuple(Fr(v) for v in decision.destination), case.name
        else:
            assert got is None, f"{case.name} encoded on a swarm that decides {expected.name}"
