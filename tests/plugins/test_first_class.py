"""Issue 39: a plug-in's lemma, scheduler and traces are first-class: a violated plug-in lemma's witness
written and replayed (or, without its package, what to install), ``report`` twice, step lemmas under
ASYNC judged on the events the executable model plays."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.plugins.cli import PAIRS, ROOT, TOY_DIST, evidence_with_and_without, fatline, without_plugin

# --- issue 39: a plug-in's lemma, scheduler and traces are first-class -------------------------------


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
    runs = evidence_with_and_without("paper-async", "2..3", tmp_path)
    (s0, r0, t0), (s1, r1, t1) = runs["without"], runs["with"]
    assert s0 == s1
    assert {k: v for k, v in r1.items() if k[0] not in ("no-left", "no-down")} == r0
    assert {r1[("no-left", n)][0] for n in (2, 3)} == {"HOLDS_WITHIN_BOUNDS"}
    assert {r1[("no-down", n)][0] for n in (2, 3)} == {"VIOLATED"}
    assert {k: v for k, v in t1.items() if "no-down" not in k} == t0
    rep = fatline("replay", *(str(tmp_path / "with" / f"paper-async-no-down-n{n}.json") for n in (2, 3)))
    assert rep.returncode == 0 and rep.stdout.count("reproduces") == 2, rep.stdout + rep.stderr
