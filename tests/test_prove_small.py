"""The prover's small swarms (``fatline_verify.prove.small``): every initial configuration of a few
robots on a coarse lattice, each robot as r, searched for the obligation's case and a broken claim by
the executable model alone."""

from __future__ import annotations

from pathlib import Path

import pytest

from fatline_verify.integrity import seal
from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove.prover import tasks_for
from fatline_verify.prove.search import prove_spec
from fatline_verify.prove.small import SMALL, small_swarm_counterexample
from fatline_verify.rules.paper.cases import case_of
from fatline_verify.schedulers.round import decide_all, play_round
from fatline_verify.trace.traces import check_replay
from tests.conftest import task_named

# paper-drop-touch: Scenario 2's search fails both ways, I's top robot is also in C less than 2 below
# r, so "y_p = -d + 2" moves r *up*, into a robot of A (the solver's search of 13 named robots found
# no initial counterexample within 60 s).
DROP_UP = "no-collision/one-mover-scenario-4-I-nonempty.from-scenario-2"


def test_small_swarms_find_the_drop_that_goes_up():
    model = load_model("paper-drop-touch")
    task = task_named(model, DROP_UP)
    found = small_swarm_counterexample(model, task)
    assert found is not None
    got, q = found
    assert q == 2 and got.initial and got.what == "collision"  # q = 1 holds no robot of I u C beyond delta
    state = got.state
    decisions = decide_all(state, model)
    assert case_of(decisions[0], model) in task.mine
    dy = decisions[0].destination[1]
    assert dy > 0  # the "drop" goes up
    result = play_round(state, [0], model, decisions)
    assert any(v.lemma.value == "no-collision" and 0 in v.robots for v in result.violations)
    check_replay(got.doc, model)  # the trace reproduces value for value


@pytest.mark.parametrize(
    "key",
    [
        pytest.param("connectivity/closer-scenario-1", marks=pytest.mark.slow),
        "rma-fixed/seen-scenario-1",  # the quickest to enumerate: the default tier's one
        pytest.param("approach/x-nondecreasing-scenario-1", marks=pytest.mark.slow),
    ],
)
def test_a_case_the_prover_proves_has_no_small_swarm_counterexample(key):
    """Differential: where z3 proves a claim for every swarm size, the enumeration finds nothing (and
    where it refutes one, the test below, it finds one too)."""
    model = load_model("paper")
    task = task_named(model, key)
    assert small_swarm_counterexample(model, task) is None, key
    assert prove_spec(model, task, timeout=20, out=None, small=False).verdict is Verdict.PROVED, key


def test_a_case_the_prover_refutes_has_a_small_swarm_counterexample():
    """Differential, the other way: Scenario 1's collision with a robot r cannot see is found too."""
    model = load_model("paper")
    found = small_swarm_counterexample(model, task_named(model, "no-collision/one-mover-scenario-1"))
    assert found is not None and found[0].what == "collision"


@pytest.mark.slow
@pytest.mark.parametrize("name", ["paper", "paper-literal", "paper-drop-touch"])
def test_no_proved_row_of_the_shipped_proofs_has_a_small_swarm_counterexample(name):
    """Differential, exhaustive: every obligation ``proofs/`` holds PROVED, enumerated."""
    import json
    from pathlib import Path

    from fatline_verify.prove.results import row_key

    model = load_model(name)
    rows = json.loads((Path(__file__).parent.parent / "proofs" / name / "results.json").read_text())["obligations"]
    proved = {row_key(r) for r in rows if r["verdict"] == "PROVED"}
    tasks = [t for t in tasks_for(model) if getattr(t, "key", None) in proved]
    assert tasks
    assert [t.key for t in tasks if small_swarm_counterexample(model, t) is not None] == []


def test_the_prover_asks_the_small_swarms_after_its_first_round():
    """With one round too small for the solver, the enumeration decides and says where it looked."""
    model = load_model("paper-drop-touch")
    task = task_named(model, DROP_UP)
    result = prove_spec(model, task, timeout=0.5, out=None)
    assert result.verdict is Verdict.VIOLATED and "small swarms enumerated, lattice q=2" in result.reason
    alone = prove_spec(model, task, timeout=0.5, out=None, small=False)
    assert alone.verdict is Verdict.INCONCLUSIVE and "small swarms" not in alone.reason


@pytest.mark.parametrize("q, robots, window", SMALL)
def test_the_enumerated_lattices_are_within_one_obligation_s_means(q, robots, window):
    """What the step enumerates stays small: its bound is part of every reason that cites it."""
    from fatline_verify.check.initial import initial_array

    model = load_model("paper").with_q(q)
    assert sum(len(initial_array(n, window, model)) for n in range(2, robots + 1)) < 50_000


def test_a_lattice_the_model_cannot_be_put_on_is_left_out():
    """rad_v = 7/2 is whole at q = 2 only: the enumeration skips q = 1 instead of failing."""
    from dataclasses import replace
    from fractions import Fraction

    from fatline_verify.model.config import Parameters

    model = load_model("paper")
    model = replace(model, parameters=Parameters(rad_v=Fraction(7, 2), q=2, delta=Fraction(21, 10)))
    task = task_named(model, "rma-fixed/seen-scenario-1")
    assert small_swarm_counterexample(model, task) is None


KNOWN = Path(__file__).resolve().parent.parent / "docs" / "known"


def test_every_hand_built_counterexample_replays():
    from fatline_verify.trace.traces import load_trace

    files = sorted(KNOWN.glob("*.json"))
    assert len(files) == 3
    for path in files:
        run = check_replay(load_trace(path))
        assert run.rounds and any(v.lemma.value == "no-collision" for v in run.rounds[-1].violations), path


def test_known_traces_decide_the_obligations_they_break_and_only_those(tmp_path, capsys):
    """``fatline prove --known``: each hand-built trace decides its own case; a trace that breaks no
    open obligation changes nothing."""
    import json
    import shutil

    from fatline_verify.cli import main

    out = tmp_path / "proofs"
    shutil.copytree(KNOWN.parent.parent / "proofs" / "paper-drop-touch", out / "paper-drop-touch")
    results = out / "paper-drop-touch" / "results.json"
    data = json.loads(results.read_text())
    open_cases = ("scenario-4-I-nonempty.from-scenario-3", "scenario-4-I-nonempty.from-uncovered-both")
    for row in data["obligations"]:  # whatever the committed rows say, these two are open here
        if row["lemma"] == "no-collision" and row["form"] == "one-mover" and row["case"] in open_cases:
            row["verdict"] = "INCONCLUSIVE"
    results.write_text(json.dumps(seal(data)))  # as a run that left them open wrote it
    for case in open_cases:  # nor are their own traces there to be replayed first
        (out / "paper-drop-touch" / "traces" / f"paper-drop-touch-prove-no-collision-one-mover-{case}.json").unlink()
    before = {r["case"]: r for r in data["obligations"] if r["lemma"] == "no-collision"}
    known = [str(p) for p in sorted(KNOWN.glob("*.json"))]
    argv = [
        "prove",
        "paper-drop-touch",
        "--redo-inconclusive",
        "--known",
        *known,
        "--out",
        str(out),
        "-q",
        "--coverage",
        "200",
    ]
    code = main([*argv, "--no-corpus"])  # nor the shipped corpus, which holds them too
    assert code == 1
    rows = {r["case"]: r for r in json.loads(results.read_text())["obligations"] if r["lemma"] == "no-collision"}
    for case in open_cases:
        assert rows[case]["verdict"] == "VIOLATED" and "given with --known" in rows[case]["reason"], rows[case]
        assert rows[case]["decided_by"] == "given"
        assert rows[case]["form"] == "one-mover"
    for case, row in rows.items():  # the after-Scenario-2 trace breaks a row already decided: kept as it was
        if case not in open_cases:
            assert row == before[case], case
