"""Scale: the exploration bound, shards and Dask workers, checkpoints, the memory guard."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.check.checker import CheckPlan, check, check_robots, check_to_json
from fatline_verify.check.checkpoint import Checkpoint
from fatline_verify.check.initial import initial_keys
from fatline_verify.check.search import Limit, LocalShards, explore_keys
from fatline_verify.check.shard import Shard, owners
from fatline_verify.errors import InvalidInput
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.systems import system_for
from tests.conftest import make_model
from tests.test_cli import assert_one_line_error, run_cli

ROOT = Path(__file__).resolve().parent.parent
SPIN_READING = ROOT.parent / "shared" / "anchors" / "spin" / "spin-reading.toml"
FIELDS = [
    "keys",
    "parent",
    "parent_action",
    "depth",
    "expanded",
    "enabled",
    "goal",
    "edge_src",
    "edge_dst",
    "edge_action",
    "edge_flags",
    "edge_fits",
    "edge_exact",
]


def _same(a, b) -> None:
    for f in FIELDS:
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    assert (a.limit, a.n_initial) == (b.limit, b.n_initial)


def _keys(model, n, window, bound):
    system = system_for(model)
    return system, initial_keys(n, window, model, system.codec(n, bound))


def _spin_model():
    if SPIN_READING.exists():
        return load_model(str(SPIN_READING))
    return make_model(band_overlap="vertical-first", uncovered="search-both")


# --- the exploration bound ---------------------------------------------------------------------------


@pytest.mark.parametrize(("n", "initial", "states", "edges"), [(3, 410, 461, 494), (4, 9_501, 11_220, 17_730)])
def test_a_bound_nothing_escapes_from_gives_the_spin_anchor_counts(n, initial, states, edges):
    """The SPIN anchor's figures (three independent implementations agree on them for n = 3..5)."""
    result = check(_spin_model(), (n, n), (9, 9), bound=(16, 16))
    s = result.stats[0]
    assert (s.initial, s.states, s.transitions, s.escaped) == (initial, states, edges, 0)
    wider = check(_spin_model(), (n, n), (9, 9), bound=(20, 20)).stats[0]
    assert (wider.states, wider.transitions) == (s.states, s.transitions)


def test_the_window_as_bound_counts_escapes_and_a_larger_bound_explores_them():
    model = make_model()
    tight = check(model, (4, 4), (9, 9)).stats[0]
    loose = check(model, (4, 4), (9, 9), bound=(16, 16)).stats[0]
    assert tight.escaped > 0 and loose.escaped == 0
    assert loose.initial == tight.initial and loose.states > tight.states


def test_verdicts_and_witnesses_name_the_bound(tmp_path):
    result = check(make_model(), (3, 3), (7, 7), bound=(12, 12))
    held = [r for r in result.results if r.reason.startswith("3 robots")]
    assert held and all("window 7x7, bound 12x12" in r.reason for r in held)
    witness = next(r.witness for r in result.results if r.witness is not None)
    assert witness["origin"]["window"] == [7, 7] and witness["origin"]["bound"] == [12, 12]
    same = check(make_model(), (3, 3), (7, 7), bound=(7, 7))
    assert same.bound is None
    assert "bound" not in next(r.witness for r in same.results if r.witness is not None)["origin"]


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["--bound", "5x5"], "bound=5x5: expected at least the window 9x9"),
        (["--bound", "x"], "bound='x': expected WIDTHxHEIGHT"),
        (["--robots", "7", "--bound", "60x60"], "bound=60x60 with robots=7: a state does not pack or rank"),
        (["--max-memory", "lots"], "max-memory='lots': expected a size"),
        (["--max-memory", "100T"], "max-memory='100T': expected at most this machine's memory"),
        (["--workers", "0"], "workers='0'"),
        (["--engine", "turbo"], "engine='turbo'"),
        (["--cluster", "nonsense"], "cluster='nonsense': expected a Dask scheduler address"),
        (["--cluster", "foo://bar:1"], "cluster='foo://bar:1'"),
        (["--checkpoint", "/proc/nope/ck"], "checkpoint='/proc/nope/ck': cannot write there"),
    ],
)
def test_bad_scale_flags_are_one_line_errors(capsys, tmp_path, args, fragment):
    code, _, err = run_cli(capsys, "check", *args, "--traces", str(tmp_path / "t"), "-q")
    assert_one_line_error(code, err, fragment)


def test_async_runs_the_compiled_engine(capsys, tmp_path):
    out = tmp_path / "check.json"
    args = ["paper-async", "--robots", "2", "--window", "6x6", "--engine", "compiled", "--json", str(out)]
    code, _, err = run_cli(capsys, "check", *args, "--traces", str(tmp_path / "t"), "-q")
    assert code in (0, 1) and not err
    assert [s["engine"] for s in json.loads(out.read_text())["searches"]] == ["compiled"]


def test_a_system_without_an_engine_refuses_it():
    from types import SimpleNamespace

    from fatline_verify.check.engines import engine_for
    from fatline_verify.model.options import Scheduler

    other = SimpleNamespace(family="other", kind=Scheduler.ASYNC)
    with pytest.raises(
        InvalidInput, match="engine='compiled': scheduler=async has no compiled engine; expected scalar"
    ):
        engine_for(other, "compiled")  # type: ignore[arg-type]


# --- shards and workers ------------------------------------------------------------------------------


@pytest.mark.parametrize("readings", [{}, {"scheduler": "centralized"}, {"scheduler": "async"}])
def test_any_number_of_shards_gives_the_same_search(readings):
    model = make_model(**readings)
    system = system_for(model)
    codec = system.codec(3, (8, 8))
    from fatline_verify.check.initial import initial_array

    init = np.sort(codec.encode(system.initial(initial_array(3, (6, 6), model))))
    one = explore_keys(system, 3, init, (8, 8), "fast")
    for count in (2, 3):
        shards = [Shard(system, 3, (8, 8), "fast", i, count) for i in range(count)]
        many = explore_keys(system, 3, init, (8, 8), "fast", pool=LocalShards(shards))
        _same(one, many)


def test_shards_elsewhere_name_the_level_they_expand_before_it_returns():
    """Shards that report nothing while they run (Dask workers) still have the progress line name their
    level as it starts (nothing done of its frontier), then the level done, as one process does."""
    model = make_model()
    system = system_for(model)
    codec = system.codec(3, (8, 8))
    from fatline_verify.check.initial import initial_array

    init = np.sort(codec.encode(system.initial(initial_array(3, (6, 6), model))))
    calls: list[tuple[int, int, int, int]] = []
    shards = [Shard(system, 3, (8, 8), "fast", i, 2) for i in range(2)]
    ex = explore_keys(system, 3, init, (8, 8), "fast", pool=LocalShards(shards), progress=lambda *a: calls.append(a))
    starts = [c for c in calls if c[1] == 0 and c[2]]  # (an empty last level reports 0 of 0 when done)
    sizes = [int(s) for s in ex.level_sizes]
    assert [(level, frontier) for level, _, frontier, _ in starts] == [(i, sizes[i]) for i in range(len(starts))]
    assert len(starts) == sum(1 for s in sizes if s)  # every level with a frontier, once, before it ran
    assert starts[0] == (0, 0, len(init), len(init))


@pytest.mark.parametrize("motion", ["rigid", "non-rigid"])
def test_shards_agree_on_async_byte_keys(motion):
    """Four async robots need two-word keys; a shard with nothing to route must not break the level."""
    model = make_model(scheduler="async", motion=motion)
    system = system_for(model)
    from fatline_verify.check.initial import initial_array

    codec = system.codec(4, (7, 7))
    assert codec.dtype != np.int64
    init = np.sort(codec.encode(system.initial(initial_array(4, (5, 5), model))))
    one = explore_keys(system, 4, init, (7, 7), "fast", after_violation="continue")
    shards = [Shard(system, 4, (7, 7), "fast", i, 3, "continue") for i in range(3)]
    _same(one, explore_keys(system, 4, init, (7, 7), "fast", pool=LocalShards(shards), after_violation="continue"))
    assert len(owners(np.zeros(0, dtype=codec.dtype), 2)) == 0


def test_transitions_are_in_source_then_action_order_for_every_engine():
    model = make_model(scheduler="async", motion="non-rigid")
    system = system_for(model)
    from fatline_verify.check.initial import initial_array

    init = system.initial(initial_array(3, (6, 6), model))
    for engine in ("fast", "scalar"):
        ex = explore_keys(system, 3, np.sort(system.codec(3, (8, 8)).encode(init)), (8, 8), engine)
        order = np.lexsort((ex.edge_action, ex.edge_src))
        assert np.array_equal(order, np.arange(ex.n_transitions)), engine


def test_owners_spread_keys_and_are_stable():
    keys = np.arange(0, 10_000, 7, dtype=np.int64)
    got = owners(keys, 4)
    assert np.array_equal(got, owners(keys.copy(), 4))
    assert set(np.bincount(got, minlength=4)) and min(np.bincount(got, minlength=4)) > len(keys) // 8


def _normalised(data: dict) -> dict:
    for s in data["searches"]:
        s["seconds"] = 0
    return data


def test_two_dask_workers_give_byte_identical_results(tmp_path):
    model = make_model()
    one = check(model, (2, 4), (9, 9))
    two = check(model, (2, 4), (9, 9), workers=2)
    assert _normalised(check_to_json(one, {})) == _normalised(check_to_json(two, {}))
    for a, b in zip(one.results, two.results, strict=True):
        assert json.dumps(a.witness, sort_keys=True) == json.dumps(b.witness, sort_keys=True)


# --- checkpoints -------------------------------------------------------------------------------------


class _Kill(Exception):
    pass


def _explore(model, n, checkpoint=None, kill_at=None, **kw):
    system, init = _keys(model, n, (9, 9), (12, 12))

    def tick(level, done, frontier, states):
        if kill_at is not None and level == kill_at:
            raise _Kill

    return explore_keys(system, n, init, (12, 12), "fast", checkpoint=checkpoint, progress=tick, **kw)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_killed_at_a_random_level_resumes_to_the_identical_search(tmp_path, seed):
    model = make_model()
    whole = _explore(model, 4)
    levels = int(whole.depth.max())
    kill_at = int(np.random.default_rng(seed).integers(1, levels + 1))
    with pytest.raises(_Kill):
        _explore(model, 4, tmp_path / "ck", kill_at=kill_at)
    manifest = json.loads((tmp_path / "ck" / "manifest.json").read_text())
    assert 0 <= manifest["levels"] <= kill_at
    _same(whole, _explore(model, 4, tmp_path / "ck"))
    _same(whole, _explore(model, 4, tmp_path / "ck"))  # a finished checkpoint resumes to the same end


def test_a_level_file_larger_than_other_files_read_back_resumes(tmp_path, monkeypatch):
    """A level file is as large as its level (n = 8's initial level: 1.8 GB): the bound on files read
    back (256 MiB) does not refuse it; the digest the manifest records still guards it."""
    from fatline_verify.check import checkpoint

    model = make_model()
    whole = _explore(model, 4)
    with pytest.raises(_Kill):
        _explore(model, 4, tmp_path / "ck", kill_at=2)
    assert max(p.stat().st_size for p in (tmp_path / "ck").glob("level-*.npz")) > 1000
    monkeypatch.setattr(checkpoint, "MAX_READ", 1000)
    _same(whole, _explore(model, 4, tmp_path / "ck"))


def test_a_level_file_beyond_the_manifest_is_written_again(tmp_path):
    model = make_model()
    whole = _explore(model, 4)
    with pytest.raises(_Kill):
        _explore(model, 4, tmp_path / "ck", kill_at=3)
    ck = tmp_path / "ck"
    levels = json.loads((ck / "manifest.json").read_text())["levels"]
    (ck / f"level-{levels + 1:05d}.npz").write_bytes(b"half a file")  # a write the kill interrupted
    (ck / f".level-{levels + 2:05d}.npz.tmp").write_bytes(b"")
    _same(whole, _explore(model, 4, ck))


def test_a_state_capped_run_resumes_further_with_a_larger_cap(tmp_path):
    model = make_model()
    capped = _explore(model, 4, tmp_path / "ck", max_states=9_600)
    assert capped.limit is Limit.MAX_STATES
    _same(_explore(model, 4), _explore(model, 4, tmp_path / "ck", max_states=10**6))


def test_a_checkpoint_of_another_search_is_refused(tmp_path):
    _explore(make_model(), 3, tmp_path / "ck")
    with pytest.raises(InvalidInput, match="holds another search"):
        _explore(make_model(), 4, tmp_path / "ck")
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "manifest.json").write_text('{"mine": true}')
    with pytest.raises(InvalidInput, match="not written by fatline check"):
        _explore(make_model(), 3, tmp_path / "other")
    assert (tmp_path / "other" / "manifest.json").read_text() == '{"mine": true}'


def test_checkpoint_flag_refuses_a_file(capsys, tmp_path):
    f = tmp_path / "ck"
    f.write_text("keep")
    code, _, err = run_cli(capsys, "check", "--checkpoint", str(f), "--traces", str(tmp_path / "t"), "-q")
    assert_one_line_error(code, err, "checkpoint=", "is a file")
    assert f.read_text() == "keep"


def test_checkpoint_refuses_foreign_files_before_any_work(capsys, tmp_path):
    ck = tmp_path / "ck"
    (ck / "n2").mkdir(parents=True)
    (ck / "n2" / "data.csv").write_text("mine")
    code, _, err = run_cli(capsys, "check", "--robots", "2", "--checkpoint", str(ck), "--traces", str(tmp_path), "-q")
    assert_one_line_error(code, err, "n2/data.csv is not a checkpoint file")
    (ck / "notes.txt").write_text("mine")
    code, _, err = run_cli(capsys, "check", "--robots", "2", "--checkpoint", str(ck), "--traces", str(tmp_path), "-q")
    assert_one_line_error(code, err, "holds 'notes.txt'")
    assert (ck / "notes.txt").read_text() == "mine" and (ck / "n2" / "data.csv").read_text() == "mine"


def test_a_checkpoint_with_a_missing_level_is_refused(tmp_path):
    _explore(make_model(), 3, tmp_path / "ck")
    (tmp_path / "ck" / "level-00001.npz").unlink()
    with pytest.raises(InvalidInput, match=r"level-00001\.npz is missing"):
        _explore(make_model(), 3, tmp_path / "ck")


def test_checkpoint_names_the_run():
    model = make_model()
    a = Checkpoint(None, model, 3, (9, 9), np.arange(3), "stop").run
    assert a != Checkpoint(None, model, 3, (9, 9), np.arange(4), "stop").run
    assert a != Checkpoint(None, model, 3, (10, 9), np.arange(3), "stop").run
    assert a == Checkpoint(None, model, 3, (9, 9), np.arange(3), "stop").run


@pytest.mark.slow  # three CLI processes on 5 robots in a 14x14 bound; the resume logic itself is
# checked in the default tier in process (killed at a random level, a level file beyond the manifest)
def test_sigkill_then_the_same_command_gives_the_identical_json(tmp_path):
    """A real kill -9 while the search writes its checkpoint, then the same command again."""
    args = [sys.executable, "-m", "fatline_verify.cli", "check", "--robots", "5", "--bound", "14x14", "--engine"]
    args += ["fast", "--checkpoint", str(tmp_path / "ck"), "--traces", str(tmp_path / "t"), "-q", "--force"]
    manifest = tmp_path / "ck" / "n5" / "manifest.json"
    proc = subprocess.Popen([*args, "--json", str(tmp_path / "a.json")], cwd=tmp_path)
    t0 = time.monotonic()
    while time.monotonic() - t0 < 60:
        try:
            if json.loads(manifest.read_text())["levels"] >= 2:
                break
        except (OSError, ValueError):
            pass
        time.sleep(0.02)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    assert json.loads(manifest.read_text())["levels"] >= 2
    resumed = subprocess.run([*args, "--json", str(tmp_path / "a.json")], cwd=tmp_path, capture_output=True)
    fresh = subprocess.run([*args[:-6], "--traces", str(tmp_path / "u"), "-q", "--json", str(tmp_path / "b.json")])
    assert resumed.returncode == fresh.returncode == 1, resumed.stderr
    a = _normalised(json.loads((tmp_path / "a.json").read_text()))
    b = _normalised(json.loads((tmp_path / "b.json").read_text()))
    for row in a["lemmas"] + b["lemmas"]:
        row["trace"] = Path(row["trace"]).name if row["trace"] else None
    assert a == b


# --- memory ------------------------------------------------------------------------------------------


def test_the_memory_guard_stops_cleanly_and_names_the_flag():
    result = check(make_model(), (5, 5), (9, 9), max_memory=2 * 2**20)
    stopped = [r for r in result.results if r.verdict.value == "INCONCLUSIVE"]
    assert stopped and all("--max-memory" in r.reason for r in stopped)
    assert result.stats[0].truncated


def test_without_max_states_the_memory_budget_is_the_only_limit():
    plan = CheckPlan.of(make_model(), (6, 6), (9, 9), max_memory=64 * 2**20)
    assert plan.max_states is None and plan.max_memory == 64 * 2**20
    assert CheckPlan.of(make_model(), (6, 6), (9, 9), max_states=5).max_states == 5
    capped = check(make_model(), (4, 4), (9, 9), max_states=10_000)
    held = [r for r in capped.results if r.verdict.value == "INCONCLUSIVE"]
    assert capped.stats[0].truncated and held and all("--max-states" in r.reason for r in held)


def test_the_first_level_is_guarded_too():
    """The initial configurations' expansion is usually the largest level; it is estimated, not run blind."""
    result = check(make_model(), (5, 5), (9, 9), max_memory=8 * 2**20)
    assert result.stats[0].truncated and result.stats[0].states == result.stats[0].initial


def test_a_search_holds_compact_columns():
    stats, _ = check_robots(CheckPlan.of(make_model(), (5, 5), (9, 9)), 5)
    assert stats.nbytes / stats.states < 100  # keys, parents and transitions only
