"""initial_keys (the numba Redelmeier kernel) against the three other enumerations of initial configurations:
the Python Redelmeier generator, the numpy level-by-level reference and brute force over all n-subsets."""

from __future__ import annotations

import threading
from math import comb
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.check import initial
from fatline_verify.check.initial import (
    count_by_brute_force,
    initial_array,
    initial_array_by_levels,
    initial_configurations,
    initial_keys,
)
from fatline_verify.model.config import load_model
from fatline_verify.model.lattice import KeyCodec
from tests.conftest import make_model

SPIN = Path(__file__).resolve().parents[2] / "shared" / "anchors" / "spin" / "spin-reading.toml"


def _spin_model():
    """The SPIN-anchor reading if the shared checkout is there, else the shipped paper model: both have
    rad_v = 4, q = 1, delta = 21/10 and centre visibility, so the same initial configurations."""
    return load_model(SPIN) if SPIN.is_file() else load_model("paper")


def _encode(states, codec: KeyCodec) -> np.ndarray:
    """Sorted keys of canonical states (an array (m, n, 2) or a list of tuples)."""
    arr = np.asarray(states, dtype=np.int64).reshape(-1, codec.n, 2)
    return np.sort(codec.encode(arr)) if len(arr) else np.zeros(0, dtype=np.int64)


def _keys(n, window, model, codec=None) -> np.ndarray:
    return initial_keys(n, window, model, codec or KeyCodec(n, window))


READINGS = [
    pytest.param({}, [(5, 5), (4, 6), (6, 4)], id="default"),
    pytest.param({"visibility": "any-part"}, [(5, 5), (3, 6)], id="any-part"),
    pytest.param({"visibility": "whole-disc"}, [(5, 5)], id="whole-disc"),
    pytest.param({"q": 2}, [(6, 6), (7, 5), (9, 7)], id="q2"),
]


@pytest.mark.parametrize(("readings", "windows"), READINGS)
@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_initial_keys_four_ways(n, readings, windows):
    q = readings.get("q", 1)
    model = make_model(q=q, **{k: v for k, v in readings.items() if k != "q"})
    for window in windows:
        codec = KeyCodec(n, window)
        keys = _keys(n, window, model, codec)
        assert keys.dtype == np.int64
        assert np.array_equal(keys, _encode(initial_array_by_levels(n, window, model), codec))
        assert np.array_equal(keys, _encode(list(initial_configurations(n, window, model)), codec))
        if comb(window[0] * window[1], n) <= 200_000:
            assert len(keys) == count_by_brute_force(n, window, model)


@pytest.mark.parametrize(("n", "window"), [(3, (7, 7)), (4, (6, 8)), (5, (7, 6))])
def test_initial_keys_in_a_larger_codec(n, window):
    model = make_model()
    big = KeyCodec(n, (window[0] + 3, window[1] + 2))
    keys = _keys(n, window, model, big)
    assert np.array_equal(keys, _encode(initial_array_by_levels(n, window, model), big))
    # the same configurations as in the window's own codec, re-encoded
    small = KeyCodec(n, window)
    assert np.array_equal(keys, _encode(small.decode(_keys(n, window, model, small)), big))


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_initial_keys_sorted_unique_canonical_in_window(n):
    window = (7, 6)
    codec = KeyCodec(n, window)
    keys = _keys(n, window, make_model(), codec)
    assert len(keys) and np.all(np.diff(keys) > 0)
    states = codec.decode(keys)
    assert (states.min(axis=1) == 0).all()
    assert (states.max(axis=1) < np.array(window)).all()
    assert np.array_equal(codec.encode(states), keys)


def test_initial_keys_large_window_small_n():
    """The lattice is cropped to what a connected set can reach; a large window must still be exact."""
    model = make_model()
    for n, window in [(2, (40, 40)), (3, (25, 30)), (2, (1, 40)), (3, (40, 1))]:
        codec = KeyCodec(n, window)
        assert np.array_equal(_keys(n, window, model, codec), _encode(initial_array_by_levels(n, window, model), codec))


def test_initial_keys_edge_cases():
    model = make_model()
    assert _keys(1, (9, 9), model).tolist() == [0]
    assert _keys(1, (1, 1), model).tolist() == [0]
    assert _keys(2, (1, 1), model).tolist() == []
    assert _keys(2, (1, 2), model).tolist() == []  # too close to be apart
    assert _keys(3, (2, 2), model).tolist() == []
    assert _keys(2, (1, 3), model).tolist() == []  # (0, 0) and (0, 2): squared distance 4 < delta^2
    assert _keys(2, (1, 4), model).tolist() == KeyCodec(2, (1, 4)).encode(np.array([[[0, 0], [0, 3]]])).tolist()
    assert initial_array(2, (1, 1), model).shape == (0, 2, 2)
    assert initial_array(1, (3, 3), model).tolist() == [[[0, 0]]]


def test_initial_keys_rejects_a_codec_that_cannot_hold_the_window():
    model = make_model()
    with pytest.raises(ValueError, match="cannot hold window 9x9"):
        initial_keys(3, (9, 9), model, KeyCodec(3, (9, 8)))
    with pytest.raises(ValueError, match="cannot hold window 6x7"):
        initial_keys(3, (6, 7), model, KeyCodec(3, (5, 9)))
    with pytest.raises(ValueError, match="packs 4 robots, not 3"):
        initial_keys(3, (6, 6), model, KeyCodec(4, (6, 6)))
    with pytest.raises(ValueError, match="at least 1 robot"):
        initial_keys(0, (6, 6), model, KeyCodec(1, (6, 6)))


def test_initial_array_is_decoded_keys_sorted_by_key():
    model = make_model(visibility="any-part")
    window = (6, 7)
    arr = initial_array(4, window, model)
    codec = KeyCodec(4, window)
    assert arr.dtype == np.int64 and arr.shape[1:] == (4, 2)
    keys = codec.encode(arr)
    assert np.all(np.diff(keys) > 0)
    assert np.array_equal(arr, initial_array_by_levels(4, window, model))
    assert np.array_equal(arr, codec.decode(_keys(4, window, model, codec)))


def test_initial_keys_paper_model_matches_levels():
    model = load_model("paper")
    for n in (3, 4):
        codec = KeyCodec(n, (9, 9))
        assert np.array_equal(_keys(n, (9, 9), model, codec), _encode(initial_array_by_levels(n, (9, 9), model), codec))


def test_initial_keys_n5_9x9_matches_levels():
    model = _spin_model()
    codec = KeyCodec(5, (9, 9))
    keys = _keys(5, (9, 9), model, codec)
    assert np.array_equal(keys, _encode(initial_array_by_levels(5, (9, 9), model), codec))
    assert len(keys) == len(initial_array(5, (9, 9), model))


def test_initial_keys_concurrent_calls_agree():
    """Parallel kernels launched from several Python threads at once (serialised by a lock)."""
    model = make_model()
    want = _keys(5, (8, 8), model)
    got: list[np.ndarray] = []

    def run() -> None:
        got.append(_keys(5, (8, 8), model))

    threads = [threading.Thread(target=run) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(got) == 3 and all(np.array_equal(g, want) for g in got)


def test_initial_keys_without_numba_falls_back(monkeypatch):
    model = make_model()
    want = _keys(4, (6, 6), model)
    monkeypatch.setattr(initial, "HAVE_NUMBA", False)
    assert np.array_equal(_keys(4, (6, 6), model), want)


def test_initial_keys_is_deterministic_across_thread_counts():
    numba = pytest.importorskip("numba")
    model = make_model()
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = _keys(6, (8, 8), model)
    finally:
        numba.set_num_threads(before)
    assert np.array_equal(one, _keys(6, (8, 8), model))


@pytest.mark.slow
def test_initial_keys_n6_9x9_matches_levels():
    """2,380,968 configurations under spin-reading.toml; the level-by-level reference takes ~15 s and ~4 GB."""
    model = _spin_model()
    codec = KeyCodec(6, (9, 9))
    keys = _keys(6, (9, 9), model, codec)
    assert np.array_equal(keys, _encode(initial_array_by_levels(6, (9, 9), model), codec))
