"""A rule set of one's own, from an installed package: found through the ``fatline.plugins`` entry
point, used by every command, refused by ``prove`` (which has no encoding of it)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import ClassVar

import pytest

from fatline_verify.errors import InvalidModel
from fatline_verify.model.config import load_model, model_from_mapping, model_to_mapping
from fatline_verify.rules import registry

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
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
def installed(install_site: Callable[[Path], None]) -> None:
    """The plug-in package installed for one test (tests/plugins/conftest.py: no other test sees the
    toy rule set, lemma or scheduler)."""
    install_site(SITE)


@pytest.fixture
def toy(installed: None) -> registry.RuleSet:
    """The toy rule set, found by its entry point."""
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
        cwd=HERE.parent.parent,
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


@pytest.fixture
def no_left(installed: None) -> object:
    """The toy lemma, registered through its entry point."""
    from fatline_verify.lemmas import registry as lemmas

    found = lemmas.find("no-left")
    assert found is not None
    return found


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
    runs = {}
    for name, env_path in (("without", ""), ("with", str(SITE))):
        out = tmp_path / f"{name}.json"
        env = {**os.environ, "PYTHONPATH": env_path}
        got = subprocess.run(
            [
                sys.executable,
                "-m",
                "fatline_verify.cli",
                "check",
                "paper",
                "--robots",
                "2..3",
                "--json",
                str(out),
                "--traces",
                str(tmp_path / name),
                "-q",
            ],
            capture_output=True,
            text=True,
            env=env,
            cwd=ROOT,
        )
        assert got.returncode == 1, got.stderr
        data = json.loads(out.read_text())
        searches = [{k: v for k, v in s.items() if k not in ("seconds", "bytes")} for s in data["searches"]]
        rows = {(r["lemma"], r["robots"]): (r["verdict"], r["reason"], r["witness_rounds"]) for r in data["lemmas"]}
        traces = {p.name: p.read_text() for p in (tmp_path / name).glob("*.json")}
        runs[name] = (searches, rows, traces)
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

PAIRS = HERE / "pairs.toml"


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


# --- issue 39: a plug-in's lemma, scheduler and traces are first-class -------------------------------

TOY_DIST = {"distribution": "toy-fatline-plugin", "version": "0.1"}
"""What ``importlib.metadata`` says of the toy package (its ``.dist-info``)."""


def without_plugin(*argv: str) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter without the plug-in package."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=ROOT
    )


def test_a_violated_plug_in_lemma_s_witness_is_written_loaded_and_replayed(tmp_path: Path) -> None:
    """The paper's robots step down: ``no-down`` is VIOLATED, its witness written (the trace schema takes
    a registered lemma's name), records the package that provides the lemma, and replays."""
    out, traces = tmp_path / "check.json", tmp_path / "t"
    got = fatline("check", "paper", "--robots", "2", "--json", str(out), "--traces", str(traces), "-q", cwd=ROOT)
    assert got.returncode == 1, got.stderr
    row = next(r for r in json.loads(out.read_text())["lemmas"] if r["lemma"] == "no-down")
    assert (row["verdict"], row["witness_rounds"]) == ("VIOLATED", 1)
    trace = traces / "paper-no-down-n2.json"
    assert row["trace"] == trace.as_posix()
    doc = json.loads(trace.read_text())
    assert doc["violation"]["property"] == "no-down" and doc["violation"]["robots"]
    assert doc["plugins"] == [{"kind": "lemma", "name": "no-down", **TOY_DIST}]
    rep = fatline("replay", str(trace))
    assert rep.returncode == 0 and "reproduces" in rep.stdout and "no-down" in rep.stdout, rep.stdout + rep.stderr
    # replay re-judges the lemma: a robot it did not break it for is a recorded value that differs
    doc["violation"]["robots"] = [1 - doc["violation"]["robots"][0]]
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(doc))
    bad = fatline("replay", str(tampered))
    assert bad.returncode == 1 and "violation.robots" in bad.stdout + bad.stderr
    # the traces of the paper's own lemmas need no plug-in and record none
    assert all("plugins" not in json.loads(p.read_text()) for p in traces.glob("paper-[!n]*.json"))


def test_without_the_package_replay_names_the_package_to_install(tmp_path: Path) -> None:
    trace = tmp_path / "down.json"
    assert fatline("check", "paper", "--robots", "2", "--traces", str(tmp_path), "-q", cwd=ROOT).returncode == 1
    (tmp_path / "paper-no-down-n2.json").rename(trace)
    got = without_plugin("replay", str(trace))
    assert got.returncode == 2 and got.stdout == ""
    assert got.stderr == (
        f"fatline: error: {trace}: lemma 'no-down' is a plug-in that is not installed; expected its package "
        "installed: pip install 'toy-fatline-plugin==0.1'\n"
    )
    # a trace of an unknown lemma that records no package: one line that lists the lemmas there are
    doc = json.loads(trace.read_text())
    del doc["plugins"]
    trace.write_text(json.dumps(doc))
    got = without_plugin("replay", str(trace))
    assert got.returncode == 2 and got.stderr.count("\n") == 1
    assert "violation.property='no-down': unknown lemma; expected one of connectivity, no-collision, " in got.stderr


def test_a_second_report_reads_its_own_check_json_and_writes_the_same(tmp_path: Path) -> None:
    """A model of a plug-in scheduler, with a plug-in lemma VIOLATED: the report works, and a second one
    reuses its cached check.json (no recomputation: the trace files are not rewritten) with the same
    output, byte for byte."""
    out = tmp_path / "reports"
    first = fatline("report", str(PAIRS), "--out", str(out))
    assert first.returncode == 0, first.stderr
    page = (out / "paper-pairs" / "README.md").read_text()
    assert "| no-down | 2 | VIOLATED |" in page and "| no-left | 4 | HOLDS_WITHIN_BOUNDS |" in page
    files = {p: (p.read_bytes(), p.stat().st_mtime_ns) for p in out.rglob("*") if p.is_file()}
    second = fatline("report", str(PAIRS), "--out", str(out))
    assert second.returncode == 0, second.stderr
    again = {p: (p.read_bytes(), p.stat().st_mtime_ns) for p in out.rglob("*") if p.is_file()}
    assert {p: b for p, (b, _) in again.items()} == {p: b for p, (b, _) in files.items()}
    traces = [p for p in files if p.parent.name == "traces"]
    assert traces and all(again[p][1] == files[p][1] for p in traces)  # the cache was used


def test_simulate_takes_a_registered_scheduler(tmp_path: Path) -> None:
    bad = fatline("simulate", "paper", "--init", "0,0 0,3 3,0", "--scheduler", "pair")
    assert bad.returncode == 2
    assert bad.stderr == (
        "fatline: error: scheduler='pair': unknown scheduler; expected one of ssync, fsync, centralized, pairs, async\n"
    )
    three = fatline("simulate", "paper", "--init", "0,0 0,3 2,2 4,4", "--scheduler", "pairs", "--schedule", "0,1,2")
    assert three.returncode == 2 and "expected one or two under scheduler=pairs" in three.stderr
    trace = tmp_path / "t.json"
    sim = fatline("simulate", "paper", "--init", "0,0 0,3 3,0", "--scheduler", "pairs", "--trace", str(trace))
    assert sim.returncode == 1, sim.stderr
    doc = json.loads(trace.read_text())
    assert doc["model"]["options"]["scheduler"] == "pairs"
    assert doc["plugins"] == [{"kind": "scheduler", "name": "pairs", **TOY_DIST}]
    assert "reproduces" in fatline("replay", str(trace)).stdout
    gone = without_plugin("replay", str(trace))
    assert gone.returncode == 2 and "scheduler 'pairs' is a plug-in that is not installed" in gone.stderr


# --- a step lemma under ASYNC: judged on the events the executable model plays ----------------------


@pytest.mark.parametrize(("K", "readings"), [(2, {}), (3, {"motion": "non-rigid", "path": "horizontal-then-vertical"})])
def test_async_step_positions_are_the_executable_model_s(K: int, readings: dict[str, str]) -> None:
    """Every event's positions before and after, as the engines give them to a registered lemma, are
    what :meth:`AsyncSystem.play` computes: looks and stops move no one, a move step its robot by one
    step, also to a point off the finer lattice (where the engines' successor is blank)."""
    from fractions import Fraction

    import numpy as np

    from fatline_verify.check.engines import engine_for
    from fatline_verify.check.initial import initial_array
    from fatline_verify.check.search import explore
    from fatline_verify.schedulers.systems import system_for
    from tests.async_engines import asynchronous
    from tests.conftest import make_model

    model = asynchronous(make_model(**readings), K)
    system = system_for(model)
    init = system.initial(initial_array(3, (6, 6), model))
    ex = explore(system, init, (6, 6), engine_for(system, "fast"), after_violation="continue")
    batch = ex.states[np.random.default_rng(3).choice(len(ex.states), 200, replace=False)]
    for engine in ("compiled", "fast", "scalar"):
        expansion = engine_for(system, engine).expand(batch)
        before, after, unit = system.step_positions(batch, expansion)
        assert unit == K * K and (~expansion.exact).any()
        played = []
        for row in range(len(batch)):
            _, steps = system.successors(system.from_array(batch[row]))
            played += [(row, code, step) for code, step in steps]
        assert [(r, c) for r, c, _ in played] == list(
            zip(expansion.src.tolist(), expansion.action.tolist(), strict=True)
        )
        for k, (_, _, step) in enumerate(played):
            assert [tuple(Fraction(int(v), unit) for v in p) for p in before[k]] == list(step.before)
            assert [tuple(Fraction(int(v), unit) for v in p) for p in after[k]] == list(step.after)


def _async_left(snapshot, model):  # type: ignore[no-untyped-def]
    """A seeded rule: a robot that sees one to its right steps one radius left (under K=2 its first move
    step ends halfway, between lattice points: judged by the lemma's scalar check on exact positions)."""
    from fatline_verify.rules.paper.algorithm import Decision

    rho = model.radius
    if any(c[0] > 0 for c in snapshot):
        return Decision("left", (-rho, 0), ((0, 0), (-rho, 0)), ())
    return Decision("stay", (0, 0), ((0, 0),), ())


@pytest.mark.parametrize("engine", ["compiled", "fast", "scalar"])
def test_every_async_engine_finds_a_real_left_move_and_its_witness_replays(no_left: object, engine: str) -> None:
    from dataclasses import replace
    from fractions import Fraction

    from fatline_verify.check.checker import check
    from fatline_verify.lemmas.properties import Verdict
    from fatline_verify.trace.traces import check_replay
    from tests.async_engines import asynchronous
    from tests.conftest import make_model

    model = asynchronous(replace(make_model(), algorithm=_async_left), 2)
    rows = {(r.lemma.value, r.robots): r for r in check(model, (2, 2), (7, 7), engine=engine).results}
    assert rows[("no-left", 2)].verdict is Verdict.VIOLATED
    doc = rows[("no-left", 2)].witness
    assert doc is not None and doc["violation"]["property"] == "no-left"
    # robot 0 looks, then its first move step takes it half a radius left
    assert [(e["event"], e["robot"]) for e in doc["rounds"]] == [("look", 0), ("move", 0)]
    last = check_replay(doc, model).rounds[-1]
    assert last.after[0][0] == last.before[0][0] - Fraction(1, 2)


def test_installing_the_toy_lemmas_leaves_paper_async_as_it_was(tmp_path: Path) -> None:
    """Under ASYNC a registered lemma is judged on each event's exact positions: ``fatline check
    paper-async`` with the plug-in installed gives the paper's lemmas the same searches, verdicts and
    traces as without it; no-left holds (no robot's x decreases in any event the model plays) and
    no-down has replayed witnesses."""
    runs = {}
    for name, env_path in (("without", ""), ("with", str(SITE))):
        out = tmp_path / f"{name}.json"
        env = {**os.environ, "PYTHONPATH": env_path}
        argv = ["check", "paper-async", "--robots", "2..3", "--json", str(out), "--traces", str(tmp_path / name), "-q"]
        got = subprocess.run(
            [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=ROOT
        )
        assert got.returncode == 1, got.stderr
        data = json.loads(out.read_text())
        searches = [{k: v for k, v in s.items() if k not in ("seconds", "bytes")} for s in data["searches"]]
        rows = {(r["lemma"], r["robots"]): (r["verdict"], r["reason"], r["witness_rounds"]) for r in data["lemmas"]}
        traces = {p.name: p.read_text() for p in (tmp_path / name).glob("*.json")}
        runs[name] = (searches, rows, traces)
    (s0, r0, t0), (s1, r1, t1) = runs["without"], runs["with"]
    assert s0 == s1
    assert {k: v for k, v in r1.items() if k[0] not in ("no-left", "no-down")} == r0
    assert {r1[("no-left", n)][0] for n in (2, 3)} == {"HOLDS_WITHIN_BOUNDS"}
    assert {r1[("no-down", n)][0] for n in (2, 3)} == {"VIOLATED"}
    assert {k: v for k, v in t1.items() if "no-down" not in k} == t0
    rep = fatline("replay", *(str(tmp_path / "with" / f"paper-async-no-down-n{n}.json") for n in (2, 3)))
    assert rep.returncode == 0 and rep.stdout.count("reproduces") == 2, rep.stdout + rep.stderr


# --- parameters of a scheduler's or rule set's own: [scheduler] and [rules] tables ------------------


def _pairs_model(tmp_path: Path, table: str, name: str = "pairs-k") -> Path:
    """``pairs.toml`` with a ``[scheduler]`` table (or any other text) appended."""
    path = tmp_path / f"{name}.toml"
    path.write_text(PAIRS.read_text().replace('name = "paper-pairs"', f'name = "{name}"') + "\n" + table)
    return path


def test_the_scheduler_s_k_is_set_in_the_model_file_and_changes_the_rounds(tmp_path: Path) -> None:
    """k = 1 plays exactly centralized's rounds, k = 2 (the default) the toy's as before, k >= n every
    set, as ssync: the same states, as many transitions."""
    searches = {}
    for k in (1, 2, 4):
        out = tmp_path / f"k{k}.json"
        model = _pairs_model(tmp_path, f"[scheduler]\nk = {k}\n", f"pairs-k{k}")
        traces = tmp_path / f"traces-k{k}"
        got = fatline("check", str(model), "--robots", "4", "--json", str(out), "--traces", str(traces), "-q")
        assert got.returncode == 1, got.stderr
        data = json.loads(out.read_text())
        assert data["model"]["scheduler"] == {"k": k}
        searches[k] = (data["searches"][0]["states"], data["searches"][0]["transitions"])
    for name in ("centralized", "ssync"):
        out = tmp_path / f"{name}.json"
        argv = ["check", "paper", "--robots", "4", "--json", str(out), "--traces", str(tmp_path / name), "-q"]
        if name == "centralized":
            argv[1] = "paper-centralized"
        assert fatline(*argv, cwd=ROOT).returncode == 1
        s = json.loads(out.read_text())["searches"][0]
        searches[name] = (s["states"], s["transitions"])  # type: ignore[index]
    assert searches[2] == (11243, 17726)
    assert searches[1] == searches["centralized"]  # type: ignore[index]
    assert searches[4] == searches["ssync"]  # type: ignore[index]


def test_k_is_in_the_fingerprint_the_trace_and_replay(tmp_path: Path, installed: None) -> None:
    from fatline_verify.check.checker import check_fingerprint
    from fatline_verify.trace.traces import trace_model

    two, three = load_model(_pairs_model(tmp_path, "")), load_model(_pairs_model(tmp_path, "[scheduler]\nk = 3\n"))
    assert two.setting("scheduler") == {"k": 2} and three.setting("scheduler") == {"k": 3}
    assert check_fingerprint(two) != check_fingerprint(three)
    assert model_to_mapping(three)["scheduler"] == {"k": 3}
    assert "scheduler k=3" in three.describe()
    model = _pairs_model(tmp_path, "[scheduler]\nk = 3\n")
    trace = tmp_path / "three.json"
    sim = fatline("simulate", str(model), "--init", "0,0 0,3 2,2", "--schedule", "0,1,2", "--trace", str(trace))
    assert sim.returncode in (0, 1), sim.stderr
    doc = json.loads(trace.read_text())
    assert doc["model"]["scheduler"] == {"k": 3}
    assert "reproduces" in fatline("replay", str(trace)).stdout
    assert trace_model(doc).setting("scheduler") == {"k": 3}
    other = fatline("replay", str(trace), "--model", str(PAIRS))  # k = 2: replayed as another model
    assert other.returncode == 0 and "reproduces under paper-pairs" in other.stdout, other.stdout + other.stderr
    doc["model"]["scheduler"] = {"k": 0}
    trace.write_text(json.dumps(doc))
    bad = fatline("replay", str(trace))
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    assert "scheduler.k=0: expected a whole number 1..64 (at most k robots a round)" in bad.stderr


@pytest.mark.parametrize(
    ("table", "error"),
    [
        ("[scheduler]\nj = 2\n", "scheduler.j=2: unknown key; expected one of k"),
        ('[scheduler]\nk = "two"\n', "scheduler.k='two': expected a whole number 1..64 (at most k robots a round)"),
        ("[scheduler]\nk = 0\n", "scheduler.k=0: expected a whole number 1..64 (at most k robots a round)"),
        ("[scheduler]\nk = true\n", "scheduler.k=True: expected a whole number 1..64 (at most k robots a round)"),
        ("scheduler = 3\n", "scheduler=3: expected a table of the scheduler 'pairs''s parameters"),
    ],
)
def test_a_bad_scheduler_parameter_is_one_line_before_any_work(tmp_path: Path, table: str, error: str) -> None:
    model = _pairs_model(tmp_path, table) if not table.startswith("scheduler =") else tmp_path / "m.toml"
    if table.startswith("scheduler ="):
        model.write_text(table + PAIRS.read_text())
    out = tmp_path / "out.json"
    got = fatline("check", str(model), "--json", str(out))
    assert (got.returncode, got.stdout, got.stderr) == (2, "", f"fatline: error: {error}\n")
    assert not out.exists()


def test_a_scheduler_that_declares_none_takes_none(tmp_path: Path) -> None:
    model = tmp_path / "m.toml"
    model.write_text('name = "m"\n[options]\nscheduler = "ssync"\n[scheduler]\nk = 2\n')
    got = fatline("check", str(model))
    assert got.returncode == 2
    assert got.stderr == "fatline: error: scheduler.k=2: unknown key; the scheduler 'ssync' takes no parameters\n"


def test_the_rule_set_s_parameter_is_set_in_its_rules_table(tmp_path: Path, toy: registry.RuleSet) -> None:
    model = tmp_path / "reach.toml"
    model.write_text(
        MODEL.read_text()
        .replace('rules = "toy-step"\n', "")
        .replace("[parameters]", '[rules]\nname = "toy-step"\nreach = 4\n\n[parameters]', 1)
    )
    far = load_model(model)
    assert far.rules == "toy-step" and far.setting("rules") == {"reach": 4}
    assert not registry.decide([(3, 0)], far).moves  # 3 radii right is no longer far enough
    assert registry.decide([(4, 0)], far).moves
    assert registry.decide([(3, 0)], load_model(MODEL)).moves  # the default, 3
    assert model_to_mapping(far)["rules"] == {"name": "toy-step", "reach": 4}
    back = model_from_mapping(model_to_mapping(far))
    assert (back.rules, back.settings) == (far.rules, far.settings)
    for text, error in (
        ('[rules]\nname = "toy-step"\nreach = 0\n', "rules.reach=0: expected a whole number >= 1 (how many radii"),
        ('[rules]\nname = "toy-step"\nfar = 4\n', "rules.far=4: unknown key; expected one of reach"),
        ("[rules]\nreach = 4\n", "rules.name=None: expected the name of a rule set in the [rules] table"),
        ('[rules]\nname = "paper"\nreach = 4\n', "rules.reach=4: unknown key; the rule set 'paper' takes no param"),
    ):
        bad = tmp_path / "bad.toml"
        bad.write_text('name = "bad"\n' + text)
        got = fatline("check", str(bad))
        assert got.returncode == 2 and got.stderr.startswith(f"fatline: error: {error}"), got.stderr
        assert got.stderr.count("\n") == 1


def test_a_scheduler_with_parameters_must_take_them() -> None:
    from fatline_verify.model.options import SchedulerName
    from fatline_verify.model.seams import Param
    from fatline_verify.schedulers.activation import register

    class Deaf:
        kind = SchedulerName("deaf")
        alone = True
        encoded = False
        parameters: ClassVar[dict[str, Param]] = {"k": Param(2, "k")}

    with pytest.raises(ValueError, match=r"scheduler 'deaf': declares parameters but no configured\(\*\*values\)"):
        register(Deaf())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="expected an int, a bool or a str"):
        Param(1.5, "a float")  # type: ignore[arg-type]
