"""Goals and point robots through a real installed plug-in package (``tests/plugins/gather``): a rule set
of point robots that gathers, checked against the ``point`` goal it declares under SSYNC and ASYNC with
the same verdicts from every engine; goals of the plug-in's own (one with an exact check only, one with
a parameter and a vectorised check); the initial condition of point robots."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).parent
SITE = HERE / "gather"
ENGINES = ("scalar", "fast", "compiled")


def fatline(*argv: str, cwd: Path | None = None, site: bool = True) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter, with the plug-in package installed (on its path) unless ``site`` is false."""
    path = [str(SITE)] if site else []
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([*path, os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


def _checked(tmp_path: Path, model: Path | str, engine: str, *more: str) -> tuple[dict, str]:
    out = tmp_path / f"{Path(model).stem}-{engine}.json"
    run = fatline("check", str(model), "--engine", engine, "--json", str(out), "--traces", str(tmp_path / "t"), *more)
    assert run.returncode in (0, 1), run.stderr
    assert "internal error" not in run.stderr
    return json.loads(out.read_text()), run.stdout


def _rows(doc: dict) -> tuple[list[tuple[str, int, str]], list[tuple[int, int, int]]]:
    """Verdicts per lemma and robot count, and the searches' sizes: what every engine must agree on."""
    lemmas = [(r["lemma"], r["robots"], r["verdict"]) for r in doc["lemmas"]]
    searches = [(s["robots"], s["states"], s["transitions"]) for s in doc["searches"]]
    return lemmas, searches


@pytest.mark.parametrize(("model", "window"), [("step-to-corner.toml", "7x7"), ("step-to-corner-async.toml", "5x5")])
def test_point_robots_gather_with_the_same_verdicts_from_every_engine(tmp_path: Path, model: str, window: str) -> None:
    """step-to-corner declares robots="points" and goal="point": no-collision is not judged (robots may share
    a point), the goal is the rule set's (the model file sets none), every engine gives the same verdicts:
    it gathers within bounds (progress, termination hold), and a robot stepping away splits 3 robots."""
    got = {}
    for engine in ENGINES:
        doc, _ = _checked(tmp_path, SITE / model, engine, "--window", window)
        assert doc["model"]["options"]["goal"] == "point"
        got[engine] = _rows(doc)
    assert got["scalar"] == got["fast"] == got["compiled"]
    verdicts = {(lemma, n): v for lemma, n, v in got["scalar"][0]}
    assert {lemma for lemma, _ in verdicts} == {"connectivity", "progress", "termination"}
    assert verdicts[("progress", 2)] == verdicts[("termination", 2)] == "HOLDS_WITHIN_BOUNDS"
    assert verdicts[("progress", 3)] == verdicts[("termination", 3)] == "HOLDS_WITHIN_BOUNDS"
    assert verdicts[("connectivity", 3)] == "VIOLATED"


def test_point_robots_start_at_distinct_positions_not_delta_apart(tmp_path: Path) -> None:
    """Points: any distinct positions (1 apart, below delta); two robots at one point are refused in one line.
    The paper's discs refuse the same start (they overlap). The initial configurations differ accordingly."""
    model = str(SITE / "step-to-corner.toml")
    run = fatline("simulate", model, "--init", "0,0 1,0 1,1", "--schedule", "1,2;2")
    assert run.returncode == 0, run.stderr
    assert "r0 (0, 0)  r1 (0, 0)  r2 (0, 0)" in run.stdout  # three robots at one point: no collision
    assert "goal reached: the robots are at the goal (point)" in run.stdout
    same = fatline("simulate", model, "--init", "0,0 0,0")
    assert same.returncode == 2 and same.stderr.count("\n") == 1
    assert "share a point (point robots start at distinct positions); expected distinct positions" in same.stderr
    discs = fatline("simulate", "paper", "--init", "0,0 1,0")
    assert discs.returncode == 2 and "overlap" in discs.stderr
    points, _ = _checked(tmp_path, model, "fast", "--robots", "2")
    paper, _ = _checked(tmp_path, "paper", "fast", "--robots", "2", "--window", "7x7")
    # 2 robots up to translation within view 4 in 7x7: 24 offsets, of which 6 are closer than delta = 2.1
    assert [s["initial"] for s in points["searches"]] == [24] and [s["initial"] for s in paper["searches"]] == [18]


def test_a_plugin_goal_with_an_exact_check_only_is_judged_by_every_engine(tmp_path: Path) -> None:
    """same-row has no vectorised check: the packed engines judge it by the exact one, say so in one line,
    and agree with the scalar engine; its witness records the goal's package, and replay without the
    package says what to install."""
    model = tmp_path / "row.toml"
    model.write_text('name = "row"\nrules = "step-to-corner-row"\n[bounds]\nrobots = "2..3"\nwindow = "7x7"\n')
    got = {}
    for engine in ENGINES:
        doc, text = _checked(tmp_path, model, engine)
        assert doc["model"]["options"]["goal"] == "same-row"
        got[engine] = _rows(doc)
        notes = [line for line in text.splitlines() if line.startswith("goal 'same-row' has no")]
        assert len(notes) == (0 if engine == "scalar" else 1), text
    assert got["scalar"] == got["fast"] == got["compiled"]
    verdicts = {(lemma, n): v for lemma, n, v in got["scalar"][0]}
    assert verdicts[("progress", 2)] == "HOLDS_WITHIN_BOUNDS" and "VIOLATED" in verdicts.values()
    trace = tmp_path / "t" / "row-connectivity-n3.json"
    doc = json.loads(trace.read_text())
    assert {"kind": "goal", "name": "same-row", "distribution": "gather-fatline-plugin", "version": "0.1"} in doc[
        "plugins"
    ]
    assert fatline("replay", str(trace)).returncode == 0
    missing = fatline("replay", str(trace), site=False)
    assert missing.returncode == 2 and missing.stderr.count("\n") == 1
    assert "is a plug-in that is not installed; expected its package installed: pip install" in missing.stderr


def test_a_plugin_goal_takes_its_parameter_from_the_model_file(tmp_path: Path) -> None:
    """row-band's height, set in [goal], on the paper's rules: its deadlocks are within 6 rows but not within
    2 (progress VIOLATED at 2, holds at 6); a key the goal does not declare is one line, exit 2, before any work."""
    base = 'name = "band"\n[options]\ngoal = "row-band"\n[bounds]\nrobots = "2..3"\nwindow = "7x7"\n'
    found = {}
    for height in (2, 6):
        model = tmp_path / f"band{height}.toml"
        model.write_text(base + f"[goal]\nheight = {height}\n")
        rows = {engine: _rows(_checked(tmp_path, model, engine)[0]) for engine in ENGINES}
        assert rows["scalar"] == rows["fast"] == rows["compiled"]
        found[height] = {lemma: v for lemma, n, v in rows["scalar"][0] if n == 3}
        assert _checked(tmp_path, model, "fast")[0]["model"]["goal"] == {"height": height}
    assert (found[2]["progress"], found[6]["progress"]) == ("VIOLATED", "HOLDS_WITHIN_BOUNDS")
    bad = tmp_path / "bad.toml"
    bad.write_text(base + "[goal]\nwidth = 2\n")
    run = fatline("check", str(bad), "--traces", str(tmp_path / "never"))
    assert run.returncode == 2 and run.stdout == "" and run.stderr.count("\n") == 1
    assert "goal.width=2: unknown key; expected one of height" in run.stderr
    assert not (tmp_path / "never").exists()


def test_no_collision_is_refused_for_point_robots() -> None:
    from fatline_verify.rules.registry import RuleSet

    def stay(snapshot: object, model: object) -> object:  # pragma: no cover - never called
        raise AssertionError

    with pytest.raises(ValueError, match="lemmas names 'no-collision' with robots='points'"):
        RuleSet("pts", stay, "x", lemmas=("no-collision",), robots="points").check_setting()
    with pytest.raises(ValueError, match=r"robots='blobs': expected 'discs' or 'points'"):
        RuleSet("pts", stay, "x", robots="blobs").check_setting()
    judged = RuleSet("pts", stay, "x", robots="points").applies()
    assert "no-collision" not in {lemma.value for lemma in judged} and len(judged) == 5
