"""``fatline synth`` (fatline_verify/synth/): tables found are replayed through the executable model, unsat
answers carry a core that is replayed and solved again, and the table rule set plays a shipped table."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fatline_verify.model.config import load_model
from fatline_verify.model.options import Scheduler
from fatline_verify.model.swarm import is_goal
from fatline_verify.repair.pocket import POCKET
from fatline_verify.repair.reach import PROVED, Family, Kind, canonical, family_legs, starts
from fatline_verify.repair.search import reach
from fatline_verify.rules import registry
from fatline_verify.rules.table.algorithm import TABLES, load
from fatline_verify.schedulers.round import decide_all
from fatline_verify.synth.certificate import certify
from fatline_verify.synth.encode import find_cycles, synthesise
from fatline_verify.synth.replay import replay
from fatline_verify.synth.table import Table, parse_view, view_of, view_text
from tests.test_cli import assert_one_line_error, run_cli

LEFT_CORNER = PROVED | {Kind.LEFT, Kind.CORNER}
ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def repaired():
    return load_model("repaired")


@pytest.mark.parametrize("scheduler", [Scheduler.CENTRALIZED, Scheduler.SSYNC])
@pytest.mark.parametrize("kinds", [PROVED, LEFT_CORNER], ids=["proved", "left-corner"])
def test_a_small_sat_table_replays_through_the_executable_model(repaired, scheduler, kinds):
    r = synthesise(repaired, 3, (7, 7), kinds, scheduler=scheduler, smallest=2)
    assert r.sat and r.core == ()
    assert r.initial == len(starts(repaired, 2, (7, 7))) + len(starts(repaired, 3, (7, 7)))
    got = replay(r.table, repaired, range(2, 4), (7, 7), kinds, scheduler)
    assert got.problems == []
    assert got.initial == r.initial and got.rounds == r.rounds >= 1
    # every leg the table takes is one the family offers its view
    fam = Family(repaired, kinds)
    for view, end in r.table.legs.items():
        if end != (0, 0):
            assert end in {e for e, _ in family_legs(view, fam.model, kinds)}


def test_the_replay_catches_a_broken_table(repaired):
    """The replay can fail: a table with its moves taken away is stuck; one with a move no leg allows is named."""
    r = synthesise(repaired, 2, (7, 7), PROVED, scheduler=Scheduler.SSYNC)
    assert r.sat
    still = Table(r.table.q, r.table.rad_v, {})
    got = replay(still, repaired, 2, (7, 7), PROVED, Scheduler.SSYNC)
    assert got.problems and "stuck" in got.problems[0]
    wrong = Table(r.table.q, r.table.rad_v, {v: (-1, 0) for v in r.table.legs})
    assert any("not a leg" in p for p in replay(wrong, repaired, 2, (7, 7), PROVED, Scheduler.SSYNC).problems)


def test_the_replay_catches_a_cycle(repaired):
    """Two robots side by side: a table that moves the lower one up and then down again cycles."""
    start = canonical(((0, 0), (3, 0)))
    fam = Family(repaired, PROVED)
    left = view_of(start, 0, fam.model)
    legs = {e for e, _ in family_legs(left, fam.model, PROVED)}
    assert (0, 1) in legs and (0, -1) in legs
    up = canonical(((0, 1), (3, 0)))
    table = Table(1, 4, {left: (0, 1), view_of(up, 0, fam.model): (0, -1)})
    got = replay(table, repaired, 2, (7, 7), PROVED, Scheduler.CENTRALIZED, only=[start])
    assert got.problems and "cycle" in got.problems[0]
    assert not is_goal(start, repaired)


def test_find_cycles_finds_one_per_component():
    a, b, c, d = ((0,),), ((1,),), ((2,),), ((3,),)
    edges = {a: [(b, ())], b: [(a, ()), (c, ())], c: [(c, ())], d: [(a, ())]}
    cycles = find_cycles(edges)
    got = sorted(sorted(s for s, _ in cyc) for cyc in cycles)
    assert got == [[a, b], [c]]
    assert find_cycles({a: [(b, ())], b: []}) == []


def test_the_pocket_at_q2_is_unsat_with_right_and_vertical_legs(repaired):
    """The smallest unsat case: the pocket (fatline_verify/repair/pocket.py) at q = 2 alone; the core is the
    pocket, no round of the family reaches a line from it, and another solver agrees from scratch."""
    m2 = repaired.with_q(2)
    pocket = canonical(m2.to_lattice(p) for p in POCKET.robots)
    r = synthesise(m2, 3, (9, 9), PROVED, scheduler=Scheduler.CENTRALIZED, only=[pocket])
    assert not r.sat and r.core == (pocket,)
    cert = certify(m2, r)
    assert cert.again == "glucose4"
    assert [(c.state, c.planner, c.alone) for c in cert.core] == [(pocket, None, False)]
    # the same configuration with the what-if legs: a table exists
    assert synthesise(m2, 3, (9, 9), LEFT_CORNER, scheduler=Scheduler.CENTRALIZED, only=[pocket]).sat


def test_an_unsat_core_of_3_robots_at_q2_is_what_reach_calls_stuck(repaired):
    """With right and vertical legs at q = 2 no table is live for 3 robots in 9x9: the core's configuration is
    one ``fatline reach`` finds no line from."""
    m2 = repaired.with_q(2)
    r = synthesise(m2, 3, (9, 9), PROVED, scheduler=Scheduler.CENTRALIZED)
    assert not r.sat and len(r.core) == 1
    assert set(r.core) <= set(reach(m2, 3, (9, 9), PROVED).stuck)


def test_a_core_is_deletion_minimal_and_replayed(repaired):
    """A hand-made set: two configurations each fine alone; the core keeps only what is needed, and each of
    its configurations reaches a line by the family's rounds (replayed), so a planner could."""
    m2 = repaired.with_q(2)
    pocket = canonical(m2.to_lattice(p) for p in POCKET.robots)
    easy = canonical(((0, 0), (4, 0), (8, 0)))
    r = synthesise(m2, 3, (9, 9), PROVED, scheduler=Scheduler.SSYNC, only=[easy, pocket])
    assert not r.sat and r.core == (pocket,)


def _tables():
    """Each shipped table; those searched for more than 3 robots replay in the slow tier (minutes in Python)."""
    out = []
    for path in sorted(TABLES.glob("*.json")):
        hi = json.loads(path.read_text())["searches"][-1]["robots"][1]
        out.append(pytest.param(path, id=path.stem, marks=[pytest.mark.slow] if hi > 3 else []))
    return out


def test_there_is_a_shipped_table_replayed_in_the_default_tier():
    assert any(not p.marks for p in _tables())


@pytest.mark.parametrize("path", _tables())
def test_the_shipped_table_replays_and_the_rule_set_plays_it(repaired, path):
    """A shipped table is replayed through the executable model at the bounds it names, and its rule set
    (and its model in bench/) decides as the table does."""
    shipped = load(path)
    data = json.loads(path.read_text())
    kinds = frozenset(Kind(k) for k in data["legs"])
    lo, hi = data["searches"][-1]["robots"]
    window = tuple(data["window"])
    model = repaired.with_q(shipped.table.q)
    got = replay(shipped.table, model, range(lo, hi + 1), window, kinds, Scheduler(data["scheduler"]))
    assert got.problems == [], (path, got.problems[:3])
    table_model = load_model(ROOT / "bench" / f"{shipped.name}.toml")
    assert registry.of(table_model).name == shipped.name
    assert table_model.bounds.robots == (lo, hi) and table_model.bounds.window == window
    for start in starts(model, hi, window)[:50]:
        for i, d in decide_all(start, table_model).items():
            assert d.destination == shipped.table.action(view_of(start, i, model))


def test_view_text_round_trips():
    for v in [(), ((0, -4),), ((-1, 2), (0, -4), (3, 3))]:
        assert parse_view(view_text(v)) == v


def test_cli_sat_writes_a_sealed_table(capsys, tmp_path):
    out = tmp_path / "t.json"
    code, stdout, _ = run_cli(
        capsys, "synth", "--robots", "2..3", "--window", "7x7", "--scheduler", "ssync", "-q", "--json", str(out)
    )
    assert code == 0, stdout
    assert "2..3" in stdout and "SAT" in stdout and "replayed" in stdout
    data = json.loads(out.read_text())
    assert data["format"] == "fatline-synth" and data["digest"].startswith("sha256:")
    assert [s["answer"] for s in data["searches"]] == ["sat", "sat"]
    assert data["searches"][-1]["replay"]["problems"] == []
    # a second run does not overwrite a file fatline did not write
    foreign = tmp_path / "mine.json"
    foreign.write_text("{}")
    code, _, _ = run_cli(capsys, "synth", "--robots", "2", "--window", "7x7", "-q", "--json", str(foreign))
    assert code == 2 and foreign.read_text() == "{}"


def test_cli_unsat_exits_1_and_names_the_core(capsys):
    code, stdout, _ = run_cli(
        capsys, "synth", "--q", "2", "--robots", "3", "--window", "9x9", "--scheduler", "centralized", "-q"
    )
    assert code == 1
    assert "UNSAT" in stdout and '--init "0,3/2 1,7/2 3/2,0"' in stdout and "glucose4: UNSAT" in stdout


@pytest.mark.parametrize(
    ("argv", "fragment"),
    [
        (["--scheduler", "async"], "scheduler='async'"),
        (["--scheduler", "fsync"], "scheduler='fsync'"),
        (["--solver", "z9"], "solver='z9'"),
        (["--robots", "2..9"], "robots=9"),
        (["--with", "diagonal"], "with='diagonal'"),
        (["paper"], "paper"),
        (["--max-memory", "lots"], "max-memory='lots'"),
        (["--window", "3x3", "--robots", "3"], "no initial configuration of 3 robots fits"),
        (["--window", "99999x99999", "--robots", "2"], "does not pack into 63 bits"),
        (["--robots", "2..4", "--window", "9x9", "--max-memory", "1M"], "robots=3 window=9x9: more than"),
    ],
)
def test_cli_bad_input_is_one_line(capsys, argv, fragment):
    code, _, err = run_cli(capsys, "synth", *argv, "-q")
    assert_one_line_error(code, err, fragment)


@pytest.mark.slow
@pytest.mark.parametrize("scheduler", [Scheduler.CENTRALIZED, Scheduler.SSYNC])
def test_no_table_of_left_and_corner_legs_is_live_for_4_robots_at_q1(repaired, scheduler):
    """The impossibility: no oblivious table of right, vertical, left and corner legs is safe and live for 4
    robots at q = 1 in 9x9; from each core configuration a line is reachable (a planner could), each is
    needed, and another solver agrees from the core alone."""
    r = synthesise(repaired, 4, (9, 9), LEFT_CORNER, scheduler=scheduler)
    assert not r.sat and 1 <= len(r.core) <= 10
    cert = certify(repaired, r)
    assert all(c.planner is not None for c in cert.core)
    for c in r.core:  # deletion-minimal: without any one of them, a table exists
        rest = [s for s in r.core if s != c]
        assert synthesise(repaired, 4, (9, 9), LEFT_CORNER, scheduler=scheduler, only=rest, minimise=False).sat


@pytest.mark.slow
def test_4_robots_at_q1_with_proved_legs_is_unsat_at_a_stuck_configuration(repaired):
    r = synthesise(repaired, 4, (9, 9), PROVED, scheduler=Scheduler.CENTRALIZED)
    assert not r.sat and set(r.core) <= set(reach(repaired, 4, (9, 9), PROVED).stuck)


def test_a_changed_table_file_is_refused(tmp_path):
    """A shipped table carries its digest: an edited leg is refused, naming the file, not played."""
    from fatline_verify.errors import OutputFailed

    src = sorted(TABLES.glob("*.json"))[0]
    data = json.loads(src.read_text())
    rows = data["searches"][-1]["table"]
    view = next(iter(rows))
    rows[view] = "0,-1" if rows[view] != "0,-1" else "0,1"
    bad = tmp_path / src.name
    bad.write_text(json.dumps(data))
    with pytest.raises(OutputFailed, match=src.name):
        load(bad)


def test_a_table_rule_set_refuses_another_lattice(repaired):
    from fatline_verify.errors import InvalidModel

    model = load_model(ROOT / "bench" / "table-q1-9x9-ssync.toml").with_q(2)
    with pytest.raises(InvalidModel, match="q=2"):
        decide_all(((0, 0), (4, 0)), model)
