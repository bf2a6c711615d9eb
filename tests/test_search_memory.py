"""What keeps a search's memory low without changing what it finds (issue: memory below SPIN's): the
shard's seed is held as given (the store's first level, not a copy), a level gathers only successors
not yet visited, and freed buffers leave the process."""

from __future__ import annotations

import os

import numpy as np
import pytest

from fatline_verify.check.checker import initial_keys_for
from fatline_verify.check.engines import engine_for
from fatline_verify.check.shard import Shard, followed
from fatline_verify.model.config import load_model
from fatline_verify.resources import return_freed_memory
from fatline_verify.schedulers.systems import system_for


@pytest.fixture(scope="module")
def seeded():
    system = system_for(load_model("paper"))
    codec = system.codec(4, (9, 9))
    start = initial_keys_for(system, 4, (9, 9), codec)
    shard = Shard(system, 4, (9, 9), engine_for(system, "compiled"))
    shard.seed(start, None, np.arange(len(start), dtype=np.int32))
    return shard, start


def test_a_level_gathers_only_unvisited_successors_and_the_seed_is_not_copied(seeded):
    shard, start = seeded
    every = shard.transitions(start, np.arange(len(start)))
    follow = followed(every.fits, every.flags, "stop")
    assert len(every.key) == int(follow.sum()) > 0
    successors = np.unique(every.key)
    unvisited = successors[~np.isin(successors, start)]
    assert 0 < len(unvisited) < len(successors)  # some successors were visited: the filter has work
    level = shard.expand(batch=500)
    ((keys, src, action),) = level.routed
    assert np.array_equal(keys, unvisited)  # exactly the unvisited ones, sorted, each once
    # each with its least (source, action) among the followed transitions reaching it
    pairs = sorted(zip(every.src[follow].tolist(), every.action[follow].tolist(), every.key.tolist(), strict=True))
    least = {}
    for s, a, k in pairs:
        least.setdefault(k, (s, a))
    assert [least[k] for k in keys.tolist()] == list(zip(src.tolist(), action.tolist(), strict=True))
    assert np.array_equal(level.ids, np.arange(len(start)))
    new, _, _ = shard.merge(level.routed)
    assert shard.base is start  # held as given, never merged into
    assert np.array_equal(shard.visited, new) and shard.known() == len(start) + len(new)
    assert shard.visited_bytes() == start.nbytes + new.nbytes + shard.frontier_ids.nbytes


def test_freed_buffers_leave_the_process():
    """On glibc the allocator is told to map large buffers on their own (and so unmap them when freed);
    asking twice is answered the same, and elsewhere it says it could not."""
    glibc = bool(os.confstr("CS_GNU_LIBC_VERSION")) if "CS_GNU_LIBC_VERSION" in os.confstr_names else False
    assert return_freed_memory() is glibc
    assert return_freed_memory() is glibc
