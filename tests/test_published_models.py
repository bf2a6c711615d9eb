"""The published algorithms' models through the CLI: every counterexample the checker reports for them
replays (``fatline replay``), and the runs their pages cite do what the pages say. Their golden verdicts
(each model file's ``[expected]``) run in tests/test_golden.py with the other shipped models."""

from __future__ import annotations

import json
from pathlib import Path

from tests.test_cli import run_cli


def test_the_ando_deadlock_is_the_lattice_reading_s(capsys, tmp_path: Path) -> None:
    """ando's progress witness, (0,0) (1,2): held under destination = lattice (the midpoint (1/2, 1) has no
    lattice point on the way), and both robots move to it under destination = rational (ando-rational)."""
    code, out, _ = run_cli(capsys, "simulate", "ando", "--init", "0,0 1,2", "--schedule", "0,1")
    assert code == 1 and "deadlock" in out
    code, out, _ = run_cli(capsys, "simulate", "ando-rational", "--init", "0,0 1,2", "--schedule", "0,1")
    assert "r0 to-centre -> (1/2, 1)" in out and "r1 to-centre -> (1/2, 1)" in out


def test_universal_gathering_under_async_never_gathers_three_robots(capsys, tmp_path: Path) -> None:
    """The certified algorithm's claim is SSYNC's; under ASYNC the checker's witness is a fair cycle: a robot
    in the majority tower moves on a stale snapshot and the tower changes sides, forever (replayed)."""
    traces = tmp_path / "t"
    code, _, _ = run_cli(capsys, "check", "universal-async", "--traces", str(traces), "-q")
    assert code == 1
    (trace,) = traces.glob("*termination*.json")
    doc = json.loads(trace.read_text())
    assert doc["outcome"] == "cycle" and doc["initial"] == [[0, 2], [2, 0], [3, 2]]
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 0 and "reproduces" in out


def test_gravity_with_limited_visibility_loses_a_robot_in_one_round(capsys, tmp_path: Path) -> None:
    """The page's run: (0,0) (0,3) (2,1) (5,1), rad_v = 3; the robot at (2,1) sees the other three and
    moves to the barycentre of the four, (7/4, 5/4), away from (5,1), which sees nobody else and loses it."""
    trace = tmp_path / "split.json"
    code, out, _ = run_cli(
        capsys, "simulate", "gravity", "--init", "0,0 0,3 2,1 5,1", "--schedule", "2", "--trace", str(trace)
    )
    assert code == 1 and "VIOLATED connectivity" in out
    assert json.loads(trace.read_text())["violation"]["property"] == "connectivity"
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 0 and "reproduces" in out


def test_a_reading_the_rule_set_does_not_name_is_one_line_exit_2(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('[rules]\nname = "ando"\ndestination = "float"\n\n[options]\nscheduler = "ssync"\n')
    code, out, err = run_cli(capsys, "check", str(bad))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "rules.destination='float': expected one of lattice, rational" in err


def test_a_state_off_the_lattice_by_one_common_offset_is_its_lattice_translate() -> None:
    """Robots agree on axes, not on an origin: a successor whose robots share one rational offset is the
    lattice state it translates to (gravity-fsync's gathering at a rational barycentre is followed);
    robots off the lattice by different offsets are not (counted, not explored)."""
    from fractions import Fraction as F

    from fatline_verify.model.config import load_model
    from fatline_verify.schedulers.systems import system_for

    system = system_for(load_model("gravity-fsync"))
    third = F(1, 3)
    moved = system.exact_array(((F(7, 3), F(5, 3)), (F(7, 3), F(5, 3)), (F(7, 3), F(5, 3))))
    assert moved is not None and moved.tolist() == [[2, 1], [2, 1], [2, 1]]
    shifted = system.exact_array(((third, 0), (1 + third, 2)))
    assert shifted is not None and shifted.tolist() == [[0, 0], [1, 2]]
    assert system.exact_array(((F(1, 2), 0), (1, 0))) is None
    assert system.exact_array(((0, 0), (3, 4))).tolist() == [[0, 0], [3, 4]]
