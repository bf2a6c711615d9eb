"""Rule sets with a move family, through a real installed plug-in package (``tests/plugins/careful``).

The example of ``docs/plugins.md`` (``careful-right``) is proved safe for every swarm size from its own
file; a family whose guard forgets the swept path (``careless-right``) gets its failing obligation
replayed into a real collision; a policy that leaves its family once (``cheat-right``) is caught by the
checker's ``in-family`` lemma, with a trace that replays."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent
SITE = HERE / "careful"
DOCS = HERE.parent.parent / "docs" / "plugins.md"


def fatline(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter with the plug-in package installed (on its path)."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(SITE), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


def _rows(out: Path, name: str) -> list[dict]:
    return json.loads((out / name / "results.json").read_text())["obligations"]


def test_the_docs_example_is_the_installed_plugin_and_is_proved_safe(tmp_path: Path) -> None:
    """docs/plugins.md's rule set, word for word the plug-in's module, gets no-collision and connectivity
    PROVED for every swarm size (its family's obligations and every view of the lattice), and nothing else."""
    text = DOCS.read_text()
    block = re.search(r"```python\n# careful_fatline_plugin/careful.py\n(.*?)```", text, re.S)
    assert block, "docs/plugins.md shows careful_fatline_plugin/careful.py"
    assert block.group(1) == (SITE / "careful_fatline_plugin" / "careful.py").read_text()
    got = fatline("prove", str(SITE / "careful-right.toml"), "--out", str(tmp_path))
    assert got.returncode == 0, got.stderr
    assert "no-collision: PROVED" in got.stdout and "connectivity: PROVED" in got.stdout, got.stdout
    rows = _rows(tmp_path, "careful-right")
    assert rows and all(r["verdict"] == "PROVED" for r in rows)
    assert {r["form"] for r in rows} == {"leg", "kept", "in-family-views"}


def test_a_wrong_guard_is_refuted_by_a_replayed_collision(tmp_path: Path) -> None:
    got = fatline("prove", str(SITE / "careless-right.toml"), "--lemma", "no-collision", "--out", str(tmp_path))
    assert got.returncode == 1, got.stdout + got.stderr
    assert "no-collision: VIOLATED" in got.stdout, got.stdout
    (row,) = [r for r in _rows(tmp_path, "careless-right") if r["verdict"] == "VIOLATED"]
    assert row["form"] == "leg" and "replayed" in row["reason"]
    (trace,) = (tmp_path / "careless-right" / "traces").glob("*.json")
    again = fatline("replay", str(trace))
    assert again.returncode == 0 and "reproduces" in again.stdout and "no-collision" in again.stdout, again.stdout


def test_a_policy_that_leaves_its_family_is_a_checker_violation(tmp_path: Path) -> None:
    """cheat-right steps left on one view: the in-family lemma is VIOLATED, its witness replays; the
    prover's views row is VIOLATED too, so nothing is PROVED of the rule set."""
    out = tmp_path / "check.json"
    got = fatline(
        "check", str(SITE / "cheat-right.toml"), "--robots", "2", "--traces", str(tmp_path / "t"), "--json", str(out)
    )
    assert got.returncode == 1, got.stderr
    results = [r for r in json.loads(out.read_text())["lemmas"] if r["lemma"] == "in-family"]
    assert results and results[0]["verdict"] == "VIOLATED", results
    trace = Path(results[0]["trace"])
    assert trace.exists()
    again = fatline("replay", str(trace))
    assert again.returncode == 0 and "in-family" in again.stdout, again.stdout
    proof = fatline("prove", str(SITE / "cheat-right.toml"), "--lemma", "no-collision", "--out", str(tmp_path / "p"))
    assert "no-collision: NOT PROVED" in proof.stdout and "in-family: 1 of 1 not PROVED" in proof.stdout, proof.stdout


def test_a_rule_set_without_a_family_is_not_judged_in_family(tmp_path: Path) -> None:
    out = tmp_path / "check.json"
    fatline("check", "paper", "--robots", "2", "--json", str(out), "--traces", str(tmp_path / "t"))
    assert "in-family" not in {r["lemma"] for r in json.loads(out.read_text())["lemmas"]}


def test_simulate_stops_where_a_decision_leaves_the_family(tmp_path: Path) -> None:
    """Every run judges the registered step lemmas its model has: simulate too, with a trace that replays."""
    trace = tmp_path / "cheat.json"
    got = fatline(
        "simulate", str(SITE / "cheat-right.toml"), "--init", "0,0 3,0", "--schedule", "0;0;0", "--trace", str(trace)
    )
    assert got.returncode == 1, got.stdout + got.stderr
    assert "witnesses in-family: r0" in got.stdout and "the remaining 1 scheduled round were not played" in got.stdout
    again = fatline("replay", str(trace))
    assert again.returncode == 0 and "in-family in round 2" in again.stdout, again.stdout
