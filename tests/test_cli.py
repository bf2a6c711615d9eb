"""The command line: shipped examples work; every bad input is one line on stderr and exit 2."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.errors import InvalidModel
from fatline_verify.model.config import load_model, shipped_models
from fatline_verify.model.options import CATALOGUE

ROOT = Path(__file__).resolve().parent.parent


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code, err, *fragments):
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    for f in fragments:
        assert f in lines[0], lines[0]


def test_explain_lists_every_option_and_reading(capsys):
    code, out, _ = run_cli(capsys, "explain")
    assert code == 0
    for name, spec in CATALOGUE.items():
        assert f"\n{name}\n" in f"\n{out}"
        for reading in spec.readings:
            assert f" {reading}" in out
    assert out.count("[default") == len(CATALOGUE)


def test_explain_marks_the_models_reading(capsys):
    code, out, _ = run_cli(capsys, "explain", "quadrants", "--model", "models/paper-literal.toml")
    assert code == 0
    assert "* literal [model paper-literal]" in out
    assert "  lower-right [default]" in out


def test_models_lists_shipped(capsys):
    code, out, _ = run_cli(capsys, "models")
    assert code == 0
    assert "paper:" in out and "paper-literal:" in out


def test_shipped_models_load_and_differ_as_documented():
    paper = load_model(ROOT / "models" / "paper.toml")
    literal = load_model(ROOT / "models" / "paper-literal.toml")
    assert paper.options.differences() == {}
    assert literal.options.differences() == {
        "quadrants": "literal",
        "band_overlap": "vertical-first",
        "path": "horizontal-then-vertical",
        "search_bound": "unbounded",
        "scenario4_guard": "all-three-full",
        "goal": "any-line",
    }
    stems = [p.stem for p in shipped_models()]
    assert stems == sorted(stems) and {"paper", "paper-literal"} <= set(stems)
    for stem in set(stems) - {"paper", "paper-literal", "repaired"}:  # the variants differ from paper in one reading
        model = load_model(ROOT / "models" / f"{stem}.toml")
        if model.rules != "paper":  # a rule set of its own reads none of the paper's readings
            # (its scheduler aside, and its own goal: a published algorithm's point, near-gathering)
            assert set(model.options.differences()) <= {"scheduler", "goal"}, stem
            continue
        assert len(model.options.differences()) == 1, stem
    repaired = load_model(ROOT / "models" / "repaired.toml").options.differences()  # repairs and one reading
    assert {k for k in repaired if not k.startswith("repair_")} == {"uncovered"} and len(repaired) > 1


def test_simulate_writes_a_trace_that_replays(capsys, tmp_path):
    trace = tmp_path / "run.json"
    code, out, _ = run_cli(capsys, "simulate", "models/paper.toml", "--init", "0,0 3,0 3,3", "--trace", str(trace))
    assert code == 1  # the default readings disconnect this swarm in round 1
    assert "VIOLATED connectivity" in out
    assert json.loads(trace.read_text())["violation"]["property"] == "connectivity"
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 0 and "reproduces" in out


def test_simulate_goal_exit_0(capsys):
    code, out, _ = run_cli(capsys, "simulate", "paper", "--init", "0,0 2,3", "--scheduler", "centralized")
    assert code == 0
    assert "goal reached" in out


def test_replay_reports_a_tampered_trace_with_exit_1(capsys, tmp_path):
    trace = tmp_path / "run.json"
    run_cli(capsys, "simulate", "--init", "0,0 3,0", "--trace", str(trace))
    doc = json.loads(trace.read_text())
    doc["rounds"][0]["positions"][0] = [0, -2]
    trace.write_text(json.dumps(doc))
    code, out, _ = run_cli(capsys, "replay", str(trace))
    assert code == 1
    assert "DID NOT REPRODUCE: rounds[0].positions[0][1]: recorded -2, replayed -3" in out


BAD_INIT = [
    ("0,0 1,0", "overlap"),
    ("0,0 2,0", "closer than delta"),
    ("0,0 209/100,0", "closer than delta"),
    ("0,0 2.09,0", "closer than delta"),
    ("0,0 10,0", "not connected"),
    ("0,0 a,b", "init='a,b'"),
    ("0,0 3", "init='3'"),
    ("0,0 1/0,0", "init='1/0,0'"),
    ("", "init=''"),
]


@pytest.mark.parametrize(("init", "fragment"), BAD_INIT)
def test_bad_init(capsys, tmp_path, init, fragment):
    trace = tmp_path / "run.json"
    code, _, err = run_cli(capsys, "simulate", "--init", init, "--trace", str(trace))
    assert_one_line_error(code, err, fragment)
    assert list(tmp_path.iterdir()) == []  # nothing written


BAD_MODELS = [
    ('name = "x"\ncolour = 1\n', "colour=1: unknown key"),
    (
        '[options]\nvacant = "maybe"\n',
        "option vacant='maybe': unknown reading; expected one of touching-allowed, strict",
    ),
    ('[options]\nspeed = "fast"\n', "option speed='fast': unknown option"),
    ("[parameters]\nrad_v = 2\n", "rad_v=2: expected a visibility radius above 2"),
    ('[parameters]\nrad_v = "9/2"\nq = 1\n', "rad_v=9/2 with q=1: expected rad_v * q to be an integer"),
    ("[parameters]\ndelta = 2\n", "delta=2: expected delta > 2"),
    ('[parameters]\ndelta = "1.9"\n', "delta=19/10: expected delta > 2"),
    ("[parameters]\nq = 0\n", "q=0: expected a whole number"),
    ('[parameters]\nrad_v = "four"\n', "rad_v='four': expected"),
    ("[parameters]\nsize = 3\n", "parameters.size=3: unknown key"),
    ('[bounds]\nwindow = "9by9"\n', "window='9by9'"),
    ('[bounds]\nrobots = "5..2"\n', "robots='5..2'"),
    ("name = \n", "not valid TOML"),
    ("options = 3\n", "options=3: expected a table"),
]


@pytest.mark.parametrize(("text", "fragment"), BAD_MODELS)
def test_bad_model_files(capsys, tmp_path, text, fragment):
    path = tmp_path / "m.toml"
    path.write_text(text)
    with pytest.raises(InvalidModel):
        load_model(path)
    code, _, err = run_cli(capsys, "simulate", str(path), "--init", "0,0 3,0")
    assert_one_line_error(code, err, fragment)


def test_missing_model_file(capsys):
    code, _, err = run_cli(capsys, "simulate", "nope.toml", "--init", "0,0 3,0")
    assert_one_line_error(code, err, "model='nope.toml': no such file")


def test_unknown_explain_option(capsys):
    code, _, err = run_cli(capsys, "explain", "colour")
    assert_one_line_error(code, err, "option='colour': unknown option")


def test_bad_traces_exit_2(capsys, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "fatline-trace"}')
    code, _, err = run_cli(capsys, "replay", str(bad))
    assert_one_line_error(code, err, "'version' is a required property")
    code, _, err = run_cli(capsys, "replay", str(tmp_path / "missing.json"))
    assert_one_line_error(code, err, "no such file")


def test_async_simulate_runs_events(capsys):
    code, out, err = run_cli(capsys, "simulate", "--init", "0,0 2,3", "--scheduler", "async", "--seed", "4")
    assert code in (0, 1) and err == ""
    assert "scheduler async, seed 4, at most 100 events" in out


def test_console_script_runs(tmp_path):
    result = subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", "simulate", "--init", "0,0 1,0"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "overlap" in result.stderr


def test_bad_expected_verdicts(capsys, tmp_path):
    path = tmp_path / "m.toml"
    path.write_text('[expected]\nprogress = "MAYBE"\n')
    code, _, err = run_cli(capsys, "check", str(path), "-q")
    assert_one_line_error(code, err, "expected.progress='MAYBE': unknown verdict")
    path.write_text('[expected]\nhappiness = "VIOLATED"\n')
    code, _, err = run_cli(capsys, "check", str(path), "-q")
    assert_one_line_error(code, err, "expected.happiness='VIOLATED': unknown key")


def _subcommands():
    import argparse

    from fatline_verify.cli import build_parser

    action = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return action.choices


@pytest.mark.parametrize("name", sorted(_subcommands()))
def test_each_help_lists_only_the_exit_codes_its_command_returns(name):
    """A command's epilog lists 0, 2 and 130 (every command: main's) and 1 and 3 exactly when its handler's
    module returns them, with no line for another command."""
    import inspect
    import re

    parser = _subcommands()[name]
    handler = parser.get_default("handler")
    source = inspect.getsource(inspect.getmodule(handler))
    expected = {0, 2, 130} | ({1} if "EXIT_FOUND" in source else set())
    expected |= {3} if "EXIT_INCONCLUSIVE" in source else set()
    epilog = parser.epilog or ""
    listed = {int(m[1]) for m in re.finditer(r"^  (\d+) ", epilog, re.MULTILINE)}
    assert listed == expected, epilog
    others = set(_subcommands()) - {name}
    assert not any(re.search(rf"\b{other}\b[,:]", epilog) for other in others), epilog
