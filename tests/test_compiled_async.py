"""The compiled ASYNC engine against the fast and scalar ones: expansions field by field, keys against
decode + expand + canonical + encode (one- and two-word keys), whole explorations, check JSON byte for
byte; and the multi-word key-set kernels of ``check/keys.py`` against numpy."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.check import keys as keyset
from fatline_verify.check.checker import check, check_to_json
from fatline_verify.check.compiled_async import CompiledAsyncEngine
from fatline_verify.check.engines import engine_for
from fatline_verify.check.fast_async import FastAsyncEngine
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.base import KeyExpansion
from fatline_verify.schedulers.systems import system_for
from tests.async_engines import (
    assert_explores_alike,
    assert_same,
    assert_wide_swarm_explores_alike,
    asynchronous,
    reading_cases,
)
from tests.conftest import make_model


def composed(system, engine, keys, codec) -> KeyExpansion:
    """What ``expand_keys`` must equal: decode, expand, canonicalise, bound check, encode."""
    ex = engine.expand(codec.decode(keys))
    canon, _ = system.canonical(ex.after)
    fits = codec.fits(canon) & ex.exact
    key = np.zeros(len(canon), dtype=codec.dtype)
    if fits.any():
        key[fits] = codec.encode(canon[fits])
    return KeyExpansion(ex.enabled, ex.goal, ex.src, ex.action, key, ex.flags, fits, ex.exact)


@pytest.mark.parametrize(("readings", "K"), list(reading_cases((2,))))
def test_compiled_async_explores_like_fast_and_scalar(readings, K):
    assert_explores_alike(readings, K, ["scalar", "fast", "compiled"])


@pytest.mark.parametrize(("K", "readings"), [(2, {}), (3, {"motion": "non-rigid", "path": "horizontal-then-vertical"})])
def test_expand_and_expand_keys_equal_fast_on_reachable_states(K, readings):
    """Past violations too (overlapping robots, lost views, off-lattice steps), in a one-word codec (3
    robots) and a two-word one (4 robots)."""
    model = asynchronous(make_model(**readings), K)
    system = system_for(model)
    fast, compiled = FastAsyncEngine(system), CompiledAsyncEngine(system)
    off_lattice = 0
    for n, w, max_states in [(3, 6, 100_000), (4, 7, 20_000)]:
        init = system.initial(initial_array(n, (w, w), model))
        ex = explore(system, init, (w, w), fast, after_violation="continue", max_states=max_states)
        rng = np.random.default_rng(n)
        ids = rng.choice(ex.n_states, min(ex.n_states, 1500), replace=False)
        line = system.initial(np.array([[(0, 2 * i) for i in range(n)]], dtype=np.int64))  # a goal state
        batch = np.concatenate([ex.state_array(ids), line])
        a = fast.expand(batch)
        assert_same(a, compiled.expand(batch))
        assert (a.flags != 0).any() and a.goal.any()
        off_lattice += int((~a.exact).sum())
        codec = system.codec(n, (w, w))
        assert codec.words == (1 if n == 3 else 2)
        keys = codec.encode(batch)
        got = compiled.expand_keys(keys, codec)
        assert_same(composed(system, fast, keys, codec), got)
        assert got.fits.any() and (~got.fits).any()
        assert len(compiled.expand(batch[:0]).src) == 0
    assert off_lattice > 0


@pytest.mark.parametrize(("other", "robots"), [("fast", (2, 4)), ("scalar", (2, 3))])
def test_compiled_async_gives_the_other_engines_check_json_byte_for_byte(other, robots):
    model = load_model("paper-async")

    def data(engine: str) -> str:
        result = check(model, robots, (7, 7), engine=engine)
        out = check_to_json(result, {})
        for s in out["searches"]:
            assert s["engine"] == engine
            s["seconds"], s["engine"] = 0, ""
        witnesses = [r.witness for r in result.results if r.witness is not None]
        for w in witnesses:
            assert w["origin"]["engine"] == engine
            w["origin"]["engine"] = ""
        return json.dumps([out, witnesses], sort_keys=True)

    compiled = data("compiled")
    assert compiled == data(other)
    assert '"VIOLATED"' in compiled and '"origin"' in compiled


def test_compiled_is_the_async_default_engine():
    assert system_for(load_model("paper-async")).default_engine == "compiled"
    assert engine_for(system_for(load_model("paper-async")), "compiled").name == "compiled"


def test_wide_snapshots_are_delegated_to_the_fast_engine():
    """Eight robots seeing 12 units of 1/3 each way: a snapshot does not pack into 63 bits; the compiled
    engine hands the batch to the fast engine, which packs it in bytes."""
    engine = assert_wide_swarm_explores_alike(CompiledAsyncEngine)
    assert not engine.packs(8) and engine.packs(4)


def test_a_sweep_past_its_packing_is_the_fast_engines_error():
    model = asynchronous(make_model(), 2)
    system = system_for(model)
    far = np.zeros((1, 2, 6), dtype=np.int64)
    far[0, 0] = (0, 0, 9000, 0, 0, 1)  # moving 9000 units of 1/2, past the 14-bit sweep fields
    far[0, 1] = (4, 0, 4, 0, 0, 0)
    with pytest.raises(ValueError, match="exceeds 8191 units of 1/2") as fast_error:
        FastAsyncEngine(system).expand(far)
    with pytest.raises(ValueError) as compiled_error:
        CompiledAsyncEngine(system).expand(far)
    assert str(compiled_error.value) == str(fast_error.value)


# --- multi-word key sets ---------------------------------------------------------------------------


def _void(rows: list[tuple[int, ...]], w: int) -> np.ndarray:
    words = np.array(rows, dtype=np.uint64).reshape(len(rows), w)
    return np.ascontiguousarray(words.astype(">u8")).view(np.dtype((np.void, 8 * w))).ravel()


_word = st.one_of(st.integers(0, 3), st.integers(0, 2**64 - 1), st.sampled_from([2**63, 2**63 - 1, 2**11, 2**22]))


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 3).flatmap(lambda w: st.tuples(st.just(w), st.lists(st.tuples(*[_word] * w), max_size=60))))
def test_key_set_kernels_equal_numpy(case):
    w, rows = case
    keys = _void(rows, w)
    assert np.array_equal(keyset.argsort(keys), np.argsort(keys, kind="stable"))
    assert np.array_equal(keyset.sort(keys), np.sort(keys))
    got, want = keyset.unique_first(keys), np.unique(keys, return_index=True)
    assert np.array_equal(got[0], want[0]) and np.array_equal(got[1], want[1])
    s = np.sort(keys)
    for q in (keys, keys[: len(keys) // 9], s, s[::2]):
        assert np.array_equal(keyset.searchsorted(s, q), np.searchsorted(s, q))
    half = len(keys) // 2
    a, b = np.sort(keys[:half]), np.sort(keys[half:])
    assert np.array_equal(keyset.merge_sorted(a, b), np.sort(np.concatenate([a, b])))


def test_key_set_functions_pass_int64_keys_to_numpy():
    keys = np.array([5, 3, 5, 1, 9], dtype=np.int64)
    assert np.array_equal(keyset.argsort(keys), np.argsort(keys, kind="stable"))
    assert np.array_equal(keyset.unique_first(keys)[1], np.unique(keys, return_index=True)[1])
    assert np.array_equal(keyset.merge_sorted(np.array([1, 4]), np.array([2, 3])), [1, 2, 3, 4])
