"""The vectorised ASYNC engine against the scalar one (the executable model): same explorations, same
expansions, same verdicts."""

from __future__ import annotations

from dataclasses import fields as dataclass_fields
from dataclasses import replace

import numpy as np
import pytest

from fatline_verify.check.checker import check
from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.model.config import Model, load_model
from fatline_verify.schedulers.base import Expansion
from fatline_verify.schedulers.systems import system_for
from tests.conftest import make_model
from tests.test_explore import FIELDS

READINGS = [
    {},
    {"path": "horizontal-then-vertical"},
    {"path": "vertical-then-horizontal"},
    {"contact": "strict", "vacant": "strict"},
    {"goal": "any-line"},
    {"goal": "line-meets-discs"},
    {"quadrants": "literal"},
    {"uncovered": "search-both"},
    {"visibility": "any-part"},
    {"motion": "non-rigid"},
]


def asynchronous(model: Model, K: int) -> Model:
    return replace(
        model,
        parameters=replace(model.parameters, async_steps=K),
        options=model.options.with_(scheduler="async"),
    )


def assert_same_expansion(a: Expansion, b: Expansion) -> None:
    for f in dataclass_fields(Expansion):
        x, y = getattr(a, f.name), getattr(b, f.name)
        assert x.shape == y.shape, f.name
        assert np.array_equal(x, y), f.name


def _engine_cases():
    """Every reading at K = 1, 2, 3; K = 3 (the most interleavings) is in the default tier for the
    default readings and non-rigid motion (the readings it changes most), in the slow tier otherwise."""
    for readings in READINGS:
        name = ",".join(f"{k}={v}" for k, v in readings.items()) or "default"
        for K in (1, 2, 3):
            slow = K == 3 and readings not in ({}, {"motion": "non-rigid"})
            yield pytest.param(readings, K, id=f"{name}-{K}", marks=[pytest.mark.slow] if slow else [])


@pytest.mark.parametrize(("readings", "K"), list(_engine_cases()))
def test_fast_async_engine_equals_scalar_engine(readings, K):
    model = asynchronous(make_model(**readings), K)
    system = system_for(model)
    for n, w in [(2, 6), (3, 6)]:
        init = system.initial(initial_array(n, (w, w), model))
        a = explore(system, init, (w, w), engine_for(system, "scalar"))
        b = explore(system, init, (w, w), engine_for(system, "fast"))
        assert b.engine == "fast"
        for f in FIELDS:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f


@pytest.mark.parametrize(("K", "readings"), [(2, {}), (3, {"motion": "non-rigid", "path": "horizontal-then-vertical"})])
def test_expand_equals_scalar_on_random_reachable_states(K, readings):
    """Past violations too (overlapping robots, lost views), with moving robots in every state of the batch."""
    model = asynchronous(make_model(**readings), K)
    system = system_for(model)
    init = system.initial(initial_array(3, (6, 6), model))
    ex = explore(system, init, (6, 6), engine_for(system, "fast"), after_violation="continue")
    moving = ((ex.states[..., 0:2] != ex.states[..., 2:4]).any(axis=-1)).any(axis=1)
    assert moving.sum() > 300
    rng = np.random.default_rng(7)
    batch = ex.states[rng.choice(np.nonzero(moving)[0], 300, replace=False)]
    others = rng.choice(len(ex.states), 100, replace=False)
    batch = np.concatenate([batch, ex.states[others], ex.states[ex.goal]])
    fast = engine_for(system, "fast").expand(batch)
    assert_same_expansion(engine_for(system, "scalar").expand(batch), fast)
    assert (~fast.exact).any() and (fast.flags != 0).any() and fast.goal.any()
    assert ((fast.action >> 3) & 1).any() == (readings.get("motion") == "non-rigid")
    assert len(engine_for(system, "fast").expand(batch[:0]).src) == 0


def test_wide_snapshots_use_byte_keys():
    """Eight robots seeing 12 units of 1/3 each way: a snapshot's cell codes do not pack into 63 bits."""
    model = asynchronous(make_model(), 3)
    system = system_for(model)
    engine = engine_for(system, "fast")
    assert engine.cell_bits * 7 > 63
    spots = [(0, 0), (0, 3), (0, 6), (3, 1), (3, 4), (6, 0), (6, 3), (6, 6)]
    init = system.initial(np.array([sorted(spots)], dtype=np.int64))
    a = explore(system, init, (9, 9), engine_for(system, "scalar"), max_states=150, after_violation="continue")
    b = explore(system, init, (9, 9), engine, max_states=150, after_violation="continue")
    assert a.n_states > 150 and a.truncated
    for f in FIELDS:
        assert np.array_equal(getattr(a, f), getattr(b, f)), f


def test_check_verdicts_agree_on_the_async_paper_model():
    model = asynchronous(load_model("paper"), 2)
    fast = check(model, (3, 3), (7, 7), engine="fast")
    scalar = check(model, (3, 3), (7, 7), engine="scalar")
    assert [(r.lemma, r.verdict, r.witness_rounds) for r in fast.results] == [
        (r.lemma, r.verdict, r.witness_rounds) for r in scalar.results
    ]
    assert [(s.states, s.transitions, s.off_lattice) for s in fast.stats] == [
        (s.states, s.transitions, s.off_lattice) for s in scalar.stats
    ]
