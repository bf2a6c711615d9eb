"""A rule set of one's own, from an installed package: found through the ``fatline.plugins`` entry
point, used by every command, refused by ``prove`` (which has no encoding of it)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from fatline_verify.errors import InvalidModel
from fatline_verify.model.config import load_model, model_from_mapping, model_to_mapping
from fatline_verify.rules import registry

HERE = Path(__file__).parent
SITE = HERE / "site"
"""Where the toy plug-in package is installed (its code and its ``.dist-info`` with the entry point)."""
MODEL = HERE / "toy-step.toml"
LEMMAS = ("connectivity", "no-collision", "progress", "rma-fixed", "approach", "termination")


def fatline(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter that has the plug-in package installed (on its path)."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(SITE), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


@pytest.fixture
def toy(monkeypatch: pytest.MonkeyPatch) -> registry.RuleSet:
    """The toy rule set, found by its entry point."""
    monkeypatch.syspath_prepend(str(SITE))
    registry.load_plugins()
    return registry.get("toy-step")


def test_the_entry_point_registers_the_rule_set(toy: registry.RuleSet) -> None:
    assert toy.name == "toy-step"
    assert "toy-step" in registry.names()
    assert toy.prover is None and not toy.bands
    assert not toy.accepts("quadrants") and toy.accepts("scheduler")


def test_the_toy_decides_as_its_file_says(toy: registry.RuleSet) -> None:
    model = load_model(MODEL)
    assert model.rules == "toy-step"
    step = registry.decide([(3, 0)], model)
    assert (str(step.rule), step.destination) == ("toy-step", (1, 0))
    # a robot within two radii of the swept path blocks it; touching (exactly 2) does not
    assert not registry.decide([(4, 0), (1, 1)], model).moves
    assert registry.decide([(4, 0), (1, 2)], model).moves
    assert not registry.decide([(2, 0)], model).moves  # nothing 3 radii right


def test_a_model_of_the_toy_carries_its_rule_set_and_no_paper_reading(toy: registry.RuleSet) -> None:
    model = load_model(MODEL)
    data = model_to_mapping(model)
    assert data["rules"] == "toy-step"
    assert set(data["options"]) <= registry.MODEL_OPTIONS  # type: ignore[arg-type]
    back = model_from_mapping(data)
    assert (back.rules, back.options, back.parameters) == (model.rules, model.options, model.parameters)


def test_a_paper_reading_in_a_toy_model_is_refused(toy: registry.RuleSet) -> None:
    with pytest.raises(InvalidModel, match=r"options.quadrants='literal': not an option of rule set 'toy-step'"):
        model_from_mapping({"name": "t", "rules": "toy-step", "options": {"quadrants": "literal"}})
    with pytest.raises(InvalidModel, match=r"rules='nope': unknown rule set; expected one of .*paper"):
        model_from_mapping({"name": "t", "rules": "nope"})


def test_a_repair_in_a_paper_model_is_refused() -> None:
    with pytest.raises(InvalidModel, match=r"options.repair_lock='left-first': not an option of rule set 'paper'"):
        model_from_mapping({"name": "t", "rules": "paper", "options": {"repair_lock": "left-first"}})


def test_the_paper_models_name_no_rule_set_in_their_data() -> None:
    """The paper's and the repaired rule sets follow from the options: their traces, fingerprints and
    caches are as before rule sets were named."""
    for name in ("paper", "repaired"):
        model = load_model(name)
        assert model.rules == name
        assert "rules" not in model_to_mapping(model)


@pytest.mark.parametrize("engine", ["compiled", "fast", "scalar"])
def test_check_runs_the_toy_and_every_engine_agrees(engine: str, tmp_path: Path) -> None:
    out = tmp_path / "check.json"
    got = fatline("check", str(MODEL), "--engine", engine, "--json", str(out), "--traces", str(tmp_path / "t"), "-q")
    assert got.returncode == 1, got.stderr  # the toy deadlocks and splits the swarm
    data = json.loads(out.read_text())
    verdicts = {(r["lemma"], r["robots"]): (r["verdict"], r["witness_rounds"]) for r in data["lemmas"]}
    assert {lemma for lemma, _ in verdicts} == set(LEMMAS)
    assert verdicts[("connectivity", 3)] == ("VIOLATED", 1)
    assert verdicts[("progress", 2)] == ("VIOLATED", 0)
    assert verdicts[("no-collision", 3)][0] == "HOLDS_WITHIN_BOUNDS"
    states = {s["robots"]: (s["states"], s["transitions"]) for s in data["searches"]}
    assert states == {2: (19, 6), 3: (439, 318)}


def test_simulate_replay_and_report_use_the_toy(tmp_path: Path) -> None:
    trace = tmp_path / "split.json"
    sim = fatline("simulate", str(MODEL), "--init", "0,0 0,4 3,0", "--schedule", "0", "--trace", str(trace))
    assert sim.returncode == 1, sim.stderr
    assert "r0 toy-step -> (1, 0)" in sim.stdout
    doc = json.loads(trace.read_text())
    assert doc["model"]["rules"] == "toy-step"
    assert doc["violation"]["property"] == "connectivity"
    rep = fatline("replay", str(trace))
    assert rep.returncode == 0 and "reproduces" in rep.stdout, rep.stdout + rep.stderr
    # a trace whose recorded rule the toy would not choose does not reproduce
    doc["rounds"][0]["decisions"][0]["rule"] = "toy-stay"
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(doc))
    bad = fatline("replay", str(tampered))
    assert bad.returncode == 1 and "toy-st" in bad.stdout + bad.stderr
    report = fatline("report", str(MODEL), "--out", str(tmp_path / "reports"))
    assert report.returncode in (0, 1), report.stderr
    page = (tmp_path / "reports" / "toy-step" / "README.md").read_text()
    assert "connectivity" in page and "VIOLATED" in page
    assert any((tmp_path / "reports" / "traces").glob("toy-step-*.json"))


def test_prove_refuses_the_toy_in_one_line(tmp_path: Path) -> None:
    got = fatline("prove", str(MODEL), "--out", str(tmp_path / "proofs"))
    assert got.returncode == 2
    assert got.stderr.count("\n") == 1
    assert got.stderr.startswith("fatline: error: rules='toy-step': fatline prove has no encoding of this rule set")
    assert not (tmp_path / "proofs").exists()


def test_without_the_package_the_toy_is_an_unknown_rule_set() -> None:
    got = subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", "check", str(MODEL)],
        capture_output=True,
        text=True,
        env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"},
        cwd=HERE.parent.parent,
    )
    assert got.returncode == 2
    assert "rules='toy-step': unknown rule set; expected one of paper, repaired" in got.stderr
