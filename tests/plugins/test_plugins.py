"""A rule set of one's own, from an installed package: found through the ``fatline.plugins`` entry
point, used by every command, refused by ``prove`` (which has no encoding of it); a step lemma and a
round scheduler of one's own likewise. (Issue 39's first-class plug-ins: ``test_first_class.py``; their
parameters: ``test_parameters.py``; report pages from anywhere: ``test_pages.py``.)"""

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
from tests.plugins.cli import LEMMAS, MODEL, PAIRS, ROOT, SITE, evidence_with_and_without, fatline


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
    assert data["rules"] == {"name": "toy-step", "reach": 3}  # its [rules] table: the name, its own parameter
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
    assert {lemma for lemma, _ in verdicts} == {*LEMMAS, "no-left", "no-down"}  # the plug-in's lemmas too
    assert verdicts[("no-left", 3)][0] == "HOLDS_WITHIN_BOUNDS"  # the toy only steps right
    assert verdicts[("no-down", 3)][0] == "HOLDS_WITHIN_BOUNDS"
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
    assert doc["model"]["rules"] == {"name": "toy-step", "reach": 3}
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
        cwd=ROOT,
    )
    assert got.returncode == 2
    assert "rules='toy-step': unknown rule set; expected one of " in got.stderr
    named = got.stderr.split("expected one of ", 1)[1].strip().split(", ")
    assert {"certified", "paper", "repaired"} <= set(named) and "toy-step" not in named


# --- a step lemma of one's own (toy_fatline_plugin/lemma.py: no robot ever moves left) -------------


def _left_step(snapshot, model):  # type: ignore[no-untyped-def]
    """A seeded rule: a robot that sees one to its right steps one radius left."""
    from fatline_verify.rules.paper.algorithm import Decision

    rho = model.radius
    if any(c[0] > 0 for c in snapshot):
        return Decision("left", (-rho, 0), ((0, 0), (-rho, 0)), ())
    return Decision("stay", (0, 0), ((0, 0),), ())


@pytest.mark.parametrize("engine", ["compiled", "fast", "scalar"])
def test_every_engine_judges_a_registered_lemma_and_its_witness_replays(no_left: object, engine: str) -> None:
    from dataclasses import replace

    from fatline_verify.check.checker import check
    from fatline_verify.lemmas.properties import Verdict
    from fatline_verify.trace.traces import check_replay
    from tests.conftest import make_model

    model = replace(make_model(), algorithm=_left_step)
    result = check(model, (2, 3), (7, 7), engine=engine)
    rows = {(r.lemma.value, r.robots): r for r in result.results}
    assert rows[("no-left", 2)].verdict is Verdict.VIOLATED
    doc = rows[("no-left", 2)].witness
    assert doc is not None and doc["violation"]["property"] == "no-left"
    assert doc["violation"]["robots"] and len(doc["rounds"]) == 1
    check_replay(doc, model)
    # the paper's rules never move left: the lemma holds there, within the bounds
    paper = check(make_model(), (2, 3), (7, 7), engine=engine)
    assert {r.verdict for r in paper.results if r.lemma.value == "no-left"} == {Verdict.HOLDS_WITHIN_BOUNDS}


def test_a_trace_of_the_registered_lemma_is_rejudged_on_replay(no_left: object) -> None:
    from dataclasses import replace

    from fatline_verify.check.checker import check
    from fatline_verify.errors import TraceDidNotReproduce
    from fatline_verify.trace.traces import check_replay
    from tests.conftest import make_model

    model = replace(make_model(), algorithm=_left_step)
    doc = next(r.witness for r in check(model, (2, 2), (7, 7)).results if r.lemma.value == "no-left")
    assert doc is not None
    doc["violation"]["robots"] = [5]
    with pytest.raises(TraceDidNotReproduce, match=r"violation\.robots"):
        check_replay(doc, model)


def test_adding_a_lemma_changes_no_other_lemma_s_evidence(tmp_path: Path) -> None:
    """``fatline check paper`` with and without the plug-in: the same states, transitions, verdicts and
    witnesses for every lemma of the paper; only the plug-in's row is new."""
    runs = evidence_with_and_without("paper", "2..3", tmp_path)
    (s0, r0, t0), (s1, r1, t1) = runs["without"], runs["with"]
    assert s0 == s1
    assert {k: v for k, v in r1.items() if k[0] not in ("no-left", "no-down")} == r0
    assert {k for k in r1 if k[0] == "no-left"} == {("no-left", 2), ("no-left", 3)}
    # the paper's rules never move left, but do step down: the only new traces are no-down's, and every
    # old one is byte-identical
    assert {k: v for k, v in t1.items() if "no-down" not in k} == t0
    assert sorted(k for k in t1 if "no-down" in k) == ["paper-no-down-n2.json", "paper-no-down-n3.json"]


def test_the_committed_corpus_replays_with_the_lemma_installed() -> None:
    corpus = sorted((ROOT / "reports" / "traces").glob("*.json"))
    sample = corpus[:: max(1, len(corpus) // 25)]
    env = {**os.environ, "PYTHONPATH": str(SITE)}
    got = subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", "replay", *map(str, sample)],
        capture_output=True,
        text=True,
        env=env,
        cwd=ROOT,
    )
    assert got.returncode == 0, got.stdout[-2000:] + got.stderr
    assert got.stdout.count("reproduces") == len(sample)


def test_the_registries_are_as_before_after_a_plug_in_test() -> None:
    """Runs after the tests above: nothing of the plug-in stays registered in this process."""
    from fatline_verify.lemmas import registry as lemmas

    assert "toy-step" not in registry.names()
    assert lemmas.find("no-left") is None


# --- a scheduler of one's own (toy_fatline_plugin/scheduler.py: one or two robots a round) ---------


@pytest.mark.parametrize("engine", ["compiled", "fast", "scalar"])
def test_check_runs_the_toy_scheduler_and_every_engine_agrees(engine: str, tmp_path: Path) -> None:
    out = tmp_path / "check.json"
    got = fatline("check", str(PAIRS), "--engine", engine, "--json", str(out), "--traces", str(tmp_path / "t"), "-q")
    assert got.returncode == 1, got.stderr
    data = json.loads(out.read_text())
    assert [(s["robots"], s["states"], s["transitions"]) for s in data["searches"]] == [
        (2, 19, 12),
        (3, 461, 494),
        (4, 11243, 17726),
    ]
    ssync = tmp_path / "ssync.json"
    traces = str(tmp_path / "t4")  # not tmp_path itself: the --json file would be inside it (refused)
    fatline("check", "paper", "--robots", "4", "--engine", engine, "--json", str(ssync), "--traces", traces)
    everyone = json.loads(ssync.read_text())["searches"][0]
    # the same states as SSYNC (one robot at a time reaches them), fewer transitions (no sets of 3 or 4)
    assert everyone["states"] == 11243 and everyone["transitions"] > 17726


def test_the_toy_scheduler_refuses_a_round_of_three_and_replays(tmp_path: Path) -> None:
    bad = fatline("simulate", str(PAIRS), "--init", "0,0 0,3 2,2 4,4", "--schedule", "0,1,2")
    assert bad.returncode == 2
    assert bad.stderr == (
        "fatline: error: schedule='0,1,2': round 1 activates 3 robots; expected one or two under scheduler=pairs\n"
    )
    trace = tmp_path / "t.json"
    sim = fatline("simulate", str(PAIRS), "--init", "0,0 0,3 2,2", "--schedule", "1", "--trace", str(trace))
    assert sim.returncode == 1 and json.loads(trace.read_text())["model"]["options"]["scheduler"] == "pairs"
    rep = fatline("replay", str(trace))
    assert rep.returncode == 0 and "reproduces" in rep.stdout


def test_prove_refuses_the_toy_scheduler_in_one_line(tmp_path: Path) -> None:
    got = fatline("prove", str(PAIRS), "--out", str(tmp_path / "proofs"))
    assert got.returncode == 2
    assert got.stderr.startswith("fatline: error: scheduler=pairs: fatline prove has no encoding of this scheduler")
    assert got.stderr.count("\n") == 1 and not (tmp_path / "proofs").exists()


def test_a_scheduler_of_one_s_own_cannot_claim_an_encoding() -> None:
    from fatline_verify.model.options import SchedulerName
    from fatline_verify.schedulers.activation import register

    class Claims:
        kind = SchedulerName("claims")
        alone = True
        encoded = True

    with pytest.raises(ValueError, match="encoded=True"):
        register(Claims())  # type: ignore[arg-type]


def test_an_unknown_scheduler_in_a_model_file_is_one_line(tmp_path: Path) -> None:
    model = tmp_path / "m.toml"
    model.write_text('name = "m"\n[options]\nscheduler = "pair"\n')
    got = fatline("check", str(model))
    assert got.returncode == 2
    assert got.stderr.startswith("fatline: error: options.scheduler='pair': unknown scheduler; expected one of ssync, ")
    assert "pairs" in got.stderr and "async" in got.stderr  # the plug-in's too


def test_a_deadlock_of_the_toy_says_whom_each_robot_sees() -> None:
    """The toy does not sort robots into the paper's sets: the text lists the robots each one sees."""
    got = fatline("simulate", str(MODEL), "--init", "0,0 4,0", "--rounds", "5")
    assert got.returncode == 1
    assert "r0: toy-stay (sees r1)" in got.stdout and "r1: toy-stay (sees r0)" in got.stdout
