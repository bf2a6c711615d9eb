"""The vectorised ASYNC engine against the scalar one (the executable model): same explorations, same
expansions, same verdicts."""

from __future__ import annotations

import numpy as np
import pytest

from fatline_verify.check.checker import check
from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.systems import system_for
from tests.async_engines import (
    assert_explores_alike,
    assert_same,
    assert_wide_swarm_explores_alike,
    asynchronous,
    reading_cases,
)
from tests.conftest import make_model


@pytest.mark.parametrize(("readings", "K"), list(reading_cases((1, 2))))
def test_fast_async_engine_equals_scalar_engine(readings, K):
    assert_explores_alike(readings, K, ["scalar", "fast"])


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
    assert_same(engine_for(system, "scalar").expand(batch), fast, dtypes=False)
    assert (~fast.exact).any() and (fast.flags != 0).any() and fast.goal.any()
    assert ((fast.action >> 3) & 1).any() == (readings.get("motion") == "non-rigid")
    assert len(engine_for(system, "fast").expand(batch[:0]).src) == 0


def test_wide_snapshots_use_byte_keys():
    """Eight robots seeing 12 units of 1/3 each way: a snapshot's cell codes do not pack into 63 bits."""
    engine = assert_wide_swarm_explores_alike(lambda system: engine_for(system, "fast"))
    assert engine.cell_bits * 7 > 63


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
