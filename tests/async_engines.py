"""What the ASYNC engine tests share (``test_fast_async.py``, ``test_compiled_async.py``): the readings
and step counts they run, and the comparisons of one engine with another."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import fields as dataclass_fields
from dataclasses import replace
from typing import Any

import numpy as np
import pytest

from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.model.config import Model
from fatline_verify.schedulers.base import Expansion, KeyExpansion
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
MOST_CHANGED = ({}, {"motion": "non-rigid"})
"""The default readings and non-rigid motion: the readings the step count changes most."""
WIDE = [(0, 0), (0, 3), (0, 6), (3, 1), (3, 4), (6, 0), (6, 3), (6, 6)]
"""Eight robots seeing 12 units of 1/3 each way: a snapshot's cell codes do not pack into 63 bits."""


def asynchronous(model: Model, K: int) -> Model:
    return replace(
        model,
        parameters=replace(model.parameters, async_steps=K),
        options=model.options.with_(scheduler="async"),
    )


def reading_cases(default_tier_k: tuple[int, ...]) -> Iterator[object]:
    """Every reading at K = 1, 2, 3: in the default tier the step counts ``default_tier_k`` for every
    reading and every K for :data:`MOST_CHANGED`; the rest in the slow tier."""
    for readings in READINGS:
        name = ",".join(f"{k}={v}" for k, v in readings.items()) or "default"
        for K in (1, 2, 3):
            slow = K not in default_tier_k and readings not in MOST_CHANGED
            yield pytest.param(readings, K, id=f"{name}-{K}", marks=[pytest.mark.slow] if slow else [])


def assert_same(a: Expansion | KeyExpansion, b: Expansion | KeyExpansion, dtypes: bool = True) -> None:
    """Field by field: equal arrays of equal shapes (and dtypes, unless ``dtypes`` is false)."""
    for f in dataclass_fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        assert x.shape == y.shape and (not dtypes or x.dtype == y.dtype), f.name
        assert np.array_equal(x, y), f.name


def assert_explores_alike(readings: dict[str, str], K: int, engines: list[str]) -> None:
    """Every engine of ``engines`` explores 2 and 3 robots in 6x6 as the first one does, field by field."""
    model = asynchronous(make_model(**readings), K)
    system = system_for(model)
    for n, w in [(2, 6), (3, 6)]:
        init = system.initial(initial_array(n, (w, w), model))
        first, *others = [explore(system, init, (w, w), engine_for(system, e)) for e in engines]
        assert first.n_states > 10
        for name, other in zip(engines[1:], others, strict=True):
            assert other.engine == name
            for f in FIELDS:
                assert np.array_equal(getattr(first, f), getattr(other, f)), (name, f)


def assert_wide_swarm_explores_alike(make: Callable[[Any], Any]) -> Any:
    """The :data:`WIDE` swarm at K = 3, explored by the engine ``make`` builds on the system as by the
    scalar engine, to 150 states past violations; returns that engine."""
    system = system_for(asynchronous(make_model(), 3))
    engine = make(system)
    init = system.initial(np.array([sorted(WIDE)], dtype=np.int64))
    a = explore(system, init, (9, 9), engine_for(system, "scalar"), max_states=150, after_violation="continue")
    b = explore(system, init, (9, 9), engine, max_states=150, after_violation="continue")
    assert a.n_states > 150 and a.truncated
    for f in FIELDS:
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    return engine
