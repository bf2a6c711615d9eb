"""Each round scheduler says the same thing through each of its faces: the checker's activation sets
(scalar and vectorised), the check of an explicit schedule, and the fair random choice."""

from __future__ import annotations

import random

import numpy as np
import pytest

from fatline_verify.errors import Unsupported
from fatline_verify.model.options import Scheduler
from fatline_verify.schedulers.activation import ROUND_SCHEDULERS, round_scheduler


def _robots(mask: int, n: int) -> tuple[int, ...]:
    return tuple(i for i in range(n) if mask >> i & 1)


@pytest.mark.parametrize("kind", [s.kind for s in ROUND_SCHEDULERS.values()])
@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_faces_agree(kind, n):
    s = round_scheduler(kind)
    all_masks = np.arange(1, 1 << n, dtype=np.int64)
    enabled = np.arange(0, 1 << n, dtype=np.int64)
    table = s.valid(all_masks, enabled)
    for en in range(1 << n):
        offered = s.masks(en, n)
        assert offered == sorted(offered)
        assert offered == [int(m) for m, ok in zip(all_masks, table[en], strict=True) if ok]
        for mask in offered:
            assert mask & ~en == 0  # only enabled robots (others would be a self-loop)
            if kind is not Scheduler.FSYNC:  # fsync activates everyone; its offered set is the enabled ones
                assert s.forbids(_robots(mask, n), n) is None


def test_offered_sets_per_scheduler():
    assert round_scheduler(Scheduler.SSYNC).masks(0b101, 3) == [0b001, 0b100, 0b101]
    assert round_scheduler(Scheduler.FSYNC).masks(0b101, 3) == [0b101]
    assert round_scheduler(Scheduler.CENTRALIZED).masks(0b101, 3) == [0b001, 0b100]
    assert round_scheduler(Scheduler.CENTRALIZED).forbids((0, 1), 3) is not None
    assert round_scheduler(Scheduler.FSYNC).forbids((0, 1), 3) is not None
    assert round_scheduler(Scheduler.FSYNC).forbids((0, 1, 2), 3) is None


@pytest.mark.parametrize("kind", [s.kind for s in ROUND_SCHEDULERS.values()])
def test_fair_choice_is_legal_and_serves_the_starved(kind):
    s = round_scheduler(kind)
    rng = random.Random(7)
    n = 4
    for _ in range(200):
        candidates = tuple(sorted(rng.sample(range(n), rng.randint(1, n))))
        waiting = [rng.randint(0, n) for _ in range(n)]
        chosen = s.choose(rng, candidates, waiting, n)
        assert chosen and s.forbids(tuple(sorted(chosen)), n) is None
        if kind is not Scheduler.FSYNC:
            assert chosen <= set(candidates)
        starved = [i for i in candidates if waiting[i] >= n]
        if starved and kind is Scheduler.SSYNC:
            assert set(starved) <= chosen


def test_async_is_not_a_round_scheduler():
    with pytest.raises(Unsupported, match="scheduler='async': not implemented yet"):
        round_scheduler(Scheduler.ASYNC)
