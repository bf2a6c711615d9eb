"""Property tests of the executable model over random configurations and random readings."""

from __future__ import annotations

import json
from fractions import Fraction as Fr

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from fatline_verify.model.options import CATALOGUE
from fatline_verify.model.swarm import initial_problems
from fatline_verify.rules.paper.algorithm import Band, decide
from fatline_verify.schedulers.round import decide_all
from fatline_verify.trace.simulate import simulate
from fatline_verify.trace.traces import check_replay, run_to_json, validate
from tests.conftest import make_model

ALGORITHM_OPTIONS = [n for n, spec in CATALOGUE.items() if n != "scheduler" and not spec.repair]
"""The readings of the paper (the repairs change the algorithm: tests/test_repairs.py)."""


def readings(fixed: dict[str, str] | None = None) -> st.SearchStrategy[dict[str, str]]:
    """A random reading for every option (the scheduler stays runnable)."""
    fixed = fixed or {}
    table = {
        name: st.just(fixed[name]) if name in fixed else st.sampled_from(sorted(CATALOGUE[name].readings))
        for name in ALGORITHM_OPTIONS
    }
    table["scheduler"] = st.sampled_from(["ssync", "fsync", "centralized"])
    return st.fixed_dictionaries(table)


VISIBLE = [(x, y) for x in range(-4, 5) for y in range(-4, 5) if 4 <= x * x + y * y <= 16]


@st.composite
def lattice_snapshots(draw, max_size: int = 6):
    """Visible, pairwise non-overlapping lattice robots around r (q = 1, rad_v = 4)."""
    chosen: list[tuple[int, int]] = []
    for p in draw(st.lists(st.sampled_from(VISIBLE), max_size=max_size, unique=True)):
        if all((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 >= 4 for c in chosen):
            chosen.append(p)
    return chosen


@st.composite
def initial_states(draw, max_n: int = 4, window: int = 7):
    n = draw(st.integers(2, max_n))
    points = draw(
        st.lists(st.tuples(st.integers(0, window - 1), st.integers(0, window - 1)), min_size=n, max_size=n, unique=True)
    )
    return tuple(points)


@given(lattice_snapshots(), readings())
def test_lattice_in_lattice_out(snapshot, opts):
    d = decide(snapshot, make_model(**opts))
    assert all(isinstance(v, int) for v in d.destination)
    assert all(isinstance(v, int) for p in d.path for v in p)


@given(lattice_snapshots(), readings())
def test_a_robot_that_sees_E_F_or_G_never_moves(snapshot, opts):
    d = decide(snapshot, make_model(**opts))
    if any(m & {Band.E, Band.F, Band.G} for _, m in d.classification):
        assert not d.moves


@given(lattice_snapshots(), readings({"quadrants": "lower-right"}))
def test_no_rule_decreases_x_on_the_lattice(snapshot, opts):
    """Holds for every reading but quadrants=literal, on the q = 1 lattice (see the pinned exceptions)."""
    d = decide(snapshot, make_model(**opts))
    assert d.destination[0] >= 0
    assert all(p[0] >= 0 for p in d.path)


def test_x_decreases_under_literal_quadrants():
    # (-2,3) is in the second quadrant: D under the literal reading, and psi_right = -2.
    assert decide([(-2, 3)], make_model(quadrants="literal")).destination == (-2, 0)


def test_x_decreases_under_touch_line_off_the_lattice():
    # (1/2, 39/20) meets the A and the C strip and is about 2.01 from r: psi = 1/2 - 1 = -1/2. It is
    # R_psi's only robot, an uncovered case; search-both finds (-1/2, -1) vacant, left of r.
    d = decide([(Fr(1, 2), Fr(39, 20))], make_model(psi_right="touch-line", uncovered="search-both"))
    assert d.destination == (Fr(-1, 2), -1)
    # With the default uncovered=scenario-4 the same robot sends r straight down instead.
    assert decide([(Fr(1, 2), Fr(39, 20))], make_model(psi_right="touch-line")).destination == (0, -3)


@given(initial_states(), st.tuples(st.integers(-50, 50), st.integers(-50, 50)), readings())
def test_decisions_are_invariant_under_translation(state, shift, opts):
    model = make_model(**opts)
    moved = tuple((x + shift[0], y + shift[1]) for x, y in state)
    a, b = decide_all(state, model), decide_all(moved, model)
    for i in a:
        assert (a[i].rule, a[i].destination, a[i].psi, a[i].path) == (b[i].rule, b[i].destination, b[i].psi, b[i].path)


@settings(max_examples=60, deadline=None)
@given(initial_states(), st.integers(0, 2**16), readings())
def test_a_simulated_run_replays_exactly(state, seed, opts):
    model = make_model(**opts)
    assume(not initial_problems(state, model))
    run = simulate(state, model, seed=seed, max_rounds=25)
    doc = json.loads(json.dumps(run_to_json(run)))
    validate(doc)
    again = check_replay(doc)
    assert again.outcome is run.outcome
    assert again.final == run.final
