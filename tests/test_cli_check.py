"""``fatline check`` through the command line."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fatline_verify.cli import main
from tests.test_cli import assert_one_line_error, run_cli

TABLE_MODEL = Path(__file__).resolve().parents[1] / "bench" / "table-q1-7x7-ssync.toml"


def test_check_default_model_writes_replayable_traces_and_json(capsys, tmp_path):
    traces = tmp_path / "traces"
    out_json = tmp_path / "r.json"
    code, out, _ = run_cli(
        capsys, "check", "--robots", "2..3", "--window", "7x7", "--traces", str(traces), "--json", str(out_json), "-q"
    )
    assert code == 1
    assert "VIOLATED" in out
    data = json.loads(out_json.read_text())
    assert {x["lemma"] for x in data["lemmas"]} == {
        "connectivity",
        "no-collision",
        "progress",
        "rma-fixed",
        "approach",
        "termination",
    }
    assert [s["robots"] for s in data["searches"]] == [2, 3]
    written = sorted(traces.glob("*.json"))
    assert written
    assert all(x["trace"] for x in data["lemmas"] if x["verdict"] == "VIOLATED")
    code, out, _ = run_cli(capsys, "replay", *map(str, written))
    assert code == 0
    assert out.count("reproduces") == len(written)


def test_check_says_one_round_and_what_truncated_means(capsys, tmp_path):
    code, out, _ = run_cli(capsys, "check", "--robots", "2", "--window", "7x7", "--traces", str(tmp_path), "-q")
    assert code == 1
    row = next(line for line in out.splitlines() if line.startswith("connectivity "))
    assert " 1 round " in row and "1 rounds" not in out
    assert "truncated = the search stopped at --max-states or --max-memory" in out


def test_a_first_run_says_it_is_compiling_the_kernels_not_0_states(monkeypatch):
    """While numba compiles (a first run), the stage says so; a warm run goes straight to the search."""
    from fatline_verify.check import checker
    from fatline_verify.model.config import load_model

    plan = checker.CheckPlan.of(load_model("paper"), (2, 2), (7, 7))
    seen: list[tuple[str, int, int]] = []
    checker.explore_robots(plan, 2, None, lambda label, done, total, note: None)  # compiles them if need be
    if checker.kernels_cached(plan.engine):  # a warm run goes straight to the search
        checker.explore_robots(plan, 2, None, lambda label, done, total, note: seen.append((label, done, total)))
        assert seen[0] == ("n=2: enumerating initial configurations in 7x7", 0, 0)
    monkeypatch.setattr(checker, "kernels_cached", lambda engine, family="rounds": False)
    seen.clear()
    checker.explore_robots(plan, 2, None, lambda label, done, total, note: seen.append((label, done, total)))
    assert seen[0] == ("n=2: compiling kernels, first run only", 0, 0)
    assert not any("initial configurations" in label for label, _, _ in seen)  # the compile stage stands
    assert seen[1][0].startswith("n=2: level ")


def test_check_exit_0_when_everything_holds(capsys, tmp_path):
    # One robot: alone, already a line.
    code, out, _ = run_cli(capsys, "check", "--robots", "1", "--window", "3x3", "--traces", str(tmp_path), "-q")
    assert code == 0
    assert out.count("HOLDS_WITHIN_BOUNDS") == 6


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["--robots", "0"], "robots='0'"),
        (["--robots", "4..2"], "robots='4..2'"),
        (["--robots", "x"], "robots='x'"),
        (["--window", "9"], "window='9'"),
        (["--window", "0x5"], "window='0x5'"),
        (["--robots", "5", "--window", "200x200", "--engine", "scalar"], "does not pack or rank into 63 bits"),
        (["--robots", "3", "--window", "2x2"], "window=2x2: no two robots fit"),
        (["--robots", "4", "--window", "3x4"], "no initial configuration fits"),
        (["--max-states", "0"], "max-states='0': expected a whole number"),
        (["--robots", "2", "--window", "200x3"], "at most 128x128"),
        (["nope.toml"], "model='nope.toml'"),
    ],
)
def test_check_bad_bounds(capsys, tmp_path, args, fragment):
    code, _, err = run_cli(capsys, "check", *args, "--traces", str(tmp_path / "t"), "-q")
    assert_one_line_error(code, err, fragment)


def test_check_refuses_a_file_as_traces_dir(capsys, tmp_path):
    f = tmp_path / "file"
    f.write_text("keep")
    code, _, err = run_cli(capsys, "check", "--robots", "2", "--traces", str(f), "-q")
    assert_one_line_error(code, err, "not a directory")
    assert f.read_text() == "keep"


def test_help_states_exit_codes(capsys):
    assert main(["check", "--help"]) == 0
    out = capsys.readouterr().out
    assert "exit codes" in out and "INCONCLUSIVE" in out


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["--timeout", "0"], "timeout='0': expected a positive, finite number"),
        (["--slots", "0"], "slots='0': expected a whole number"),
        (
            ["--lemma", "happiness"],
            "lemma='happiness': expected one of no-collision, connectivity, rma-fixed, approach, progress, "
            "termination, liveness, all",
        ),
    ],
)
def test_prove_bad_input(capsys, tmp_path, args, fragment):
    code, _, err = run_cli(capsys, "prove", *args, "--out", str(tmp_path / "p"), "-q")
    assert code == 2
    assert fragment in err
    assert "Traceback" not in err


def test_prove_refuses_a_file_as_out_dir(capsys, tmp_path):
    f = tmp_path / "p"
    f.mkdir()
    (f / "paper").write_text("keep")
    code, _, err = run_cli(capsys, "prove", "--out", str(f), "-q")
    assert_one_line_error(code, err, "not a directory")
    assert (f / "paper").read_text() == "keep"


def test_prove_refuses_a_lemma_the_model_has_no_obligation_for(capsys, tmp_path):
    """A move family's model proves no-collision and connectivity only: asking it for rma-fixed is refused in one
    line naming what it has, rather than an empty table and exit 0 (which reads as "everything asked holds")."""
    code, _, err = run_cli(capsys, "prove", str(TABLE_MODEL), "--lemma", "rma-fixed", "--out", str(tmp_path))
    assert_one_line_error(code, err, "has no obligation for it; expected one of connectivity, no-collision")
    assert not any(tmp_path.iterdir())


@pytest.mark.slow
def test_prove_whole_model_through_the_cli(capsys, tmp_path):
    code, _, _ = run_cli(
        capsys, "prove", "--timeout", "4", "--out", str(tmp_path / "p"), "--traces", str(tmp_path / "t"), "-q"
    )
    assert code in (1, 3)
    data = json.loads((tmp_path / "p" / "paper" / "results.json").read_text())
    from fatline_verify.model.config import load_model
    from fatline_verify.prove.prover import task_key, tasks_for
    from fatline_verify.prove.tasks import row_key

    # one row per obligation of the model, each under its own key (the count grew with the obligation forms)
    keys = sorted(row_key(r) for r in data["obligations"])
    assert keys == sorted(task_key(t) for t in tasks_for(load_model("paper")))
    for row in data["obligations"]:
        assert Path(row["smt2"]).exists()
        if row["verdict"] == "VIOLATED":
            assert row["trace"]
    code, _, _ = run_cli(capsys, "replay", *map(str, (tmp_path / "t").glob("*.json")))
    assert code == 0
