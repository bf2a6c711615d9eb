"""Explicit schedules (``simulate --schedule``) and replay under another model ("gone under M")."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from fatline_verify.errors import InvalidInput
from fatline_verify.model.config import load_model
from fatline_verify.model.options import Scheduler
from fatline_verify.trace.simulate import Outcome, parse_schedule, play_schedule
from fatline_verify.trace.traces import load_trace, replay
from tests.test_cli import assert_one_line_error, run_cli

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "reports" / "traces"


def simulate_to(capsys, tmp_path, *argv, name="t.json"):
    trace = tmp_path / name
    code, out, err = run_cli(capsys, "simulate", *argv, "--trace", str(trace))
    return code, out, err, trace


# --- parsing --------------------------------------------------------------------------------------------


def test_parse_schedule_reads_rounds_robots_and_all():
    assert parse_schedule("0;1,2;all", 3, Scheduler.SSYNC) == [(0,), (1, 2), (0, 1, 2)]
    assert parse_schedule(" 2 , 0 ; ALL ", 3, Scheduler.SSYNC) == [(0, 2), (0, 1, 2)]
    assert parse_schedule("1;0;1", 2, Scheduler.CENTRALIZED) == [(1,), (0,), (1,)]
    assert parse_schedule("all;0,1", 2, Scheduler.FSYNC) == [(0, 1), (0, 1)]
    assert parse_schedule("all", 1, Scheduler.CENTRALIZED) == [(0,)]


@pytest.mark.parametrize(
    ("text", "scheduler", "fragment"),
    [
        ("0;;1", Scheduler.SSYNC, "schedule='0;;1': round 2 is empty; expected"),
        ("0,1", Scheduler.CENTRALIZED, "round 1 activates 2 robots (0,1); expected exactly one robot per round"),
        ("all;0", Scheduler.FSYNC, "round 2 activates robots 0 of 2; expected every robot"),
        ("2", Scheduler.SSYNC, "round 1: robot 2 does not exist"),
    ],
)
def test_parse_schedule_rejects(text, scheduler, fragment):
    with pytest.raises(InvalidInput) as exc:
        parse_schedule(text, 2, scheduler)
    assert fragment in str(exc.value)


def test_parse_schedule_reads_async_events():
    events = parse_schedule(" L0 ; M0;l1;m1 ", 2, Scheduler.ASYNC)
    assert [str(e) for e in events] == ["L0", "M0", "L1", "M1"]


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("0", "event 1 '0' is not an event; expected events separated by ';'"),
        ("L0;;M0", "event 2 '' is not an event"),
        ("L2", "event 1: robot 2 does not exist (there are 2 robots)"),
        ("L0;S0", "event 2 'S0': S<i> needs motion=non-rigid"),
        ("X0", "event 1 'X0' is not an event"),
    ],
)
def test_parse_schedule_rejects_bad_events(text, fragment):
    with pytest.raises(InvalidInput) as exc:
        parse_schedule(text, 2, Scheduler.ASYNC)
    assert fragment in str(exc.value)


# --- round trip through replay -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("init", "schedule", "played", "outcome", "exit_code"),
    [
        # a move, then the goal, and the rounds after the goal are still played
        ("0,0 2,3", "0;1;all;0,1", [[0], [1], [0, 1], [0, 1]], "goal", 0),
        # a round of a robot that stays, then two robots in one round: the run ends at the violation
        ("0,0 3,0 3,3", "2;0,1;all", [[2], [0, 1]], "violation", 1),
    ],
)
def test_schedule_round_trips_through_replay(capsys, tmp_path, init, schedule, played, outcome, exit_code):
    code, out, err, trace = simulate_to(capsys, tmp_path, "--init", init, "--schedule", schedule)
    assert (code, err) == (exit_code, "")
    doc = load_trace(trace)
    assert [r["active"] for r in doc["rounds"]] == played
    assert doc["outcome"] == outcome
    assert doc["origin"] == {"tool": "fatline simulate", "scheduler": "ssync", "schedule": schedule}
    assert f"schedule {schedule!r}" in out
    code, out, err = run_cli(capsys, "replay", str(trace))
    assert (code, err) == (0, "")
    assert f"reproduces: {len(played)} rounds, {outcome}" in out
    assert [list(r.active) for r in replay(doc).rounds] == played


def test_schedule_stops_early_only_at_a_violation(capsys, tmp_path):
    code, out, _, trace = simulate_to(capsys, tmp_path, "--init", "0,0 3,0 3,3", "--schedule", "2;0,1;all")
    assert code == 1
    assert len(load_trace(trace)["rounds"]) == 2
    assert "the remaining 1 scheduled round were not played" in out


def test_schedule_plays_on_past_a_deadlock(capsys, tmp_path):
    # (0,0), (0,3), (1,5): the deadlock of docs/findings.md; every round is still played, nothing moves
    code, _, _, trace = simulate_to(capsys, tmp_path, "--init", "0,0 0,3 1,5", "--schedule", "all;0;1;2")
    doc = load_trace(trace)
    assert code == 1
    assert doc["outcome"] == "deadlock"
    assert [r["active"] for r in doc["rounds"]] == [[0, 1, 2], [0], [1], [2]]
    assert all(r["positions"] == doc["initial"] for r in doc["rounds"])


def test_activating_a_robot_that_would_not_move_is_legal(capsys, tmp_path):
    # r1 at (2,1) is not enabled (NoMovement); activating it first changes nothing, then r0 moves
    code, _, err, trace = simulate_to(capsys, tmp_path, "--init", "0,0 2,1", "--schedule", "1;0")
    assert err == ""
    doc = load_trace(trace)
    first = doc["rounds"][0]
    assert first["active"] == [1]
    assert first["decisions"] == [
        {"robot": 1, "rule": "nomovement-2-F", "case": None, "psi": None, "destination": [2, 1]}
    ]
    assert first["positions"] == doc["initial"] and first["violations"] == []
    assert doc["rounds"][1]["active"] == [0]
    assert doc["violation"]["round"] == 2
    assert code == 1
    # the same through the library
    model = load_model("paper")
    run = play_schedule(((0, 0), (2, 1)), model, [(1,), (1,), (1,)])
    assert run.outcome is Outcome.ROUND_LIMIT
    assert [r.after for r in run.rounds] == [((0, 0), (2, 1))] * 3


def test_schedule_reproduces_the_readme_disconnection(capsys, tmp_path):
    """README: with (0,0), (2,1) the left robot drops rad_v - 1 = 3 and the squared distance becomes 20."""
    code, out, _, trace = simulate_to(capsys, tmp_path, "--init", "0,0 2,1", "--schedule", "0")
    assert code == 1
    doc = load_trace(trace)
    assert doc["outcome"] == "violation"
    assert doc["rounds"][0]["positions"] == [[0, -3], [2, 1]]
    assert doc["violation"] == {
        "property": "connectivity",
        "robots": [0, 1],
        "components": [[0], [1]],
        "lost_edges": [[0, 1]],
        "distance2_after": [20],
        "round": 1,
    }
    assert "lost r0-r1 (distance^2 20)" in out
    corpus = load_trace(CORPUS / "paper-check-connectivity-n2.json")
    assert doc["rounds"] == corpus["rounds"] and doc["violation"] == corpus["violation"]


def test_schedule_is_checked_against_the_models_scheduler(capsys, tmp_path):
    code, _, err, trace = simulate_to(capsys, tmp_path, "paper-centralized", "--init", "0,0 2,3", "--schedule", "0;1")
    assert code == 0 and err == ""
    code, _, err, trace = simulate_to(
        capsys, tmp_path, "paper-centralized", "--init", "0,0 2,3", "--schedule", "0;0,1", name="u.json"
    )
    assert_one_line_error(code, err, "schedule='0;0,1': round 2 activates 2 robots (0,1)", "scheduler=centralized")
    assert not trace.exists()


# --- bad schedules: one line, exit 2, nothing written -----------------------------------------------------


@pytest.mark.parametrize(
    ("extra", "fragment"),
    [
        (["--schedule", ""], "schedule='': no rounds; expected"),
        (["--schedule", "  "], "': no rounds; expected"),
        (["--schedule", "0;;1"], "schedule='0;;1': round 2 is empty; expected rounds separated by ';'"),
        (["--schedule", "0;"], "schedule='0;': round 2 is empty"),
        (["--schedule", "0,,1"], "round 1 has an empty robot index"),
        (["--schedule", "3"], "schedule='3': round 1: robot 3 does not exist (there are 3 robots)"),
        (["--schedule", "0;1;99"], "round 3: robot 99 does not exist"),
        (["--schedule", "-1"], "round 1: '-1' is not a robot index"),
        (["--schedule", "1.0"], "round 1: '1.0' is not a robot index"),
        (["--schedule", "zero"], "round 1: 'zero' is not a robot index"),
        (["--schedule", "0 1"], "round 1: '0 1' is not a robot index"),
        (["--schedule", "1,0,1"], "round 1 names robot 1 twice"),
        (["--schedule", "all,1"], "round 1 mixes 'all' with other robots"),
        (["--schedule", "0;1,2", "--scheduler", "centralized"], "round 2 activates 2 robots (1,2)"),
        (["--schedule", "all", "--scheduler", "centralized"], "round 1 activates 3 robots (0,1,2)"),
        (["--schedule", "all;0,1", "--scheduler", "fsync"], "round 2 activates robots 0,1 of 3; expected every"),
        (["--schedule", "0", "--scheduler", "async"], "event 1 '0' is not an event"),
        (["--schedule", "M0", "--scheduler", "async"], "event 1 M0: robot 0 is idle; expected L0 first"),
        (["--schedule", "L0;L0", "--scheduler", "async"], "event 2 L0: robot 0 is moving (0 of 2 steps done)"),
        (["--schedule", "0", "--seed", "7"], "seed='7': has no effect with --schedule"),
        (["--schedule", "0", "--rounds", "5"], "rounds='5': has no effect with --schedule"),
    ],
)
def test_bad_schedule_is_one_line_and_writes_nothing(capsys, tmp_path, extra, fragment):
    code, out, err, trace = simulate_to(capsys, tmp_path, "--init", "0,0 3,0 3,3", *extra)
    assert_one_line_error(code, err, fragment)
    assert out == ""
    assert not trace.exists()
    assert list(tmp_path.iterdir()) == []


def test_schedule_checks_the_initial_condition_first(capsys, tmp_path):
    code, _, err, trace = simulate_to(capsys, tmp_path, "--init", "0,0 1,0", "--schedule", "0")
    assert_one_line_error(code, err, "overlap")
    assert not trace.exists()


# --- replay under another model ----------------------------------------------------------------------------


def test_corpus_counterexample_is_gone_under_uncovered_stay(capsys):
    trace = CORPUS / "paper-check-connectivity-n2.json"
    code, out, err = run_cli(capsys, "replay", str(trace), "--model", "paper-uncovered-stay")
    assert (code, err) == (1, "")
    assert (
        f"{trace}: DID NOT REPRODUCE: the counterexample is gone under paper-uncovered-stay: connectivity is no "
        "longer violated in round 1" in out
    )
    assert "recorded" not in out
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 0 and "reproduces" in out


def test_deadlock_is_gone_under_a_model_file_with_another_goal(capsys, tmp_path):
    model = tmp_path / "meets.toml"
    model.write_text('name = "meets"\n[options]\ngoal = "line-meets-discs"\n')
    trace = CORPUS / "paper-check-progress-n3.json"
    code, out, _ = run_cli(capsys, "replay", str(trace), "--model", str(model))
    assert code == 1
    assert "the counterexample is gone under meets: progress is no longer violated" in out
    assert "replayed outcome goal" in out


def test_violation_still_there_under_another_model_is_worded_apart(capsys):
    trace = CORPUS / "paper-check-approach-n2.json"
    code, out, _ = run_cli(capsys, "replay", str(trace), "--model", "paper-literal")
    assert code == 1
    assert "DID NOT REPRODUCE: still VIOLATED (approach) under paper-literal; recorded values differ: outcome:" in out
    assert "gone" not in out


def test_counterexample_that_stays_reproduces_under_another_model(capsys):
    trace = CORPUS / "paper-check-connectivity-n2.json"
    code, out, _ = run_cli(capsys, "replay", str(trace), "--model", "paper-drop-touch")
    assert code == 0
    assert "reproduces under paper-drop-touch: 1 round, violation (connectivity in round 1)" in out


@pytest.mark.parametrize("model", [None, "paper"])
def test_tampered_trace_says_recorded_value_differs(capsys, tmp_path, model):
    trace = tmp_path / "t.json"
    shutil.copy(CORPUS / "paper-check-connectivity-n2.json", trace)
    doc = json.loads(trace.read_text())
    doc["violation"]["distance2_after"] = [17]
    trace.write_text(json.dumps(doc))
    argv = ["replay", str(trace)] + (["--model", model] if model else [])
    code, out, err = run_cli(capsys, *argv)
    assert (code, err) == (1, "")
    assert "DID NOT REPRODUCE: violation.distance2_after[0]: recorded 17, replayed 20" in out
    assert "gone" not in out and "still" not in out


def test_tampered_schedule_trace_says_recorded_value_differs(capsys, tmp_path):
    _, _, _, trace = simulate_to(capsys, tmp_path, "--init", "0,0 2,3", "--schedule", "0;1")
    doc = json.loads(trace.read_text())
    doc["rounds"][0]["positions"][0] = [2, 1]
    trace.write_text(json.dumps(doc))
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 1
    assert "DID NOT REPRODUCE: rounds[0].positions[0][1]: recorded 1, replayed 0" in out


def test_replay_of_many_traces_names_each_one_that_cannot_be_played_and_exits_1(capsys):
    """An ASYNC trace under a round model cannot be played: a line naming its file, the other traces still
    replayed, a summary counting each kind, exit 1 (a trace did not reproduce), not 2 (bad input)."""
    traces = [
        CORPUS / "paper-check-connectivity-n2.json",  # gone under certified
        CORPUS / "paper-async-check-connectivity-n2.json",  # events: not played by an SSYNC model
        CORPUS / "paper-check-connectivity-n2.json",
    ]
    code, out, err = run_cli(capsys, "replay", *map(str, traces), "--model", "certified")
    assert (code, err) == (1, "")
    lines = out.strip().splitlines()
    assert len(lines) == 4
    assert lines[1].startswith(f"{traces[1]}: COULD NOT BE REPLAYED under certified: rounds/0: an asynchronous event")
    assert lines[0].startswith(f"{traces[0]}: DID NOT REPRODUCE: the counterexample is gone under certified")
    assert lines[3] == (
        "3 traces replayed under certified: 0 reproduce; 2 did not (2 with the counterexample or recorded outcome "
        "gone); 1 could not be replayed"
    )


def test_replay_refuses_a_bad_file_before_replaying_any(capsys, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    code, out, err = run_cli(capsys, "replay", str(CORPUS / "paper-check-connectivity-n2.json"), str(bad))
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "bad.json" in err
