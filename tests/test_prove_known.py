"""A counterexample once found stays found: an earlier run's trace-less counterexample (the replayed
configuration of a ``closer``, ``seen`` or ``x-nondecreasing`` row) is replayed before any search."""

from __future__ import annotations

from pathlib import Path

from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove.candidates import (
    EARLIER,
    _known_all,
    _known_beside,
    _known_configuration,
    mirror_key,
    reflect,
)
from fatline_verify.prove.replay import replay_known
from fatline_verify.prove.search import prove_spec
from tests.conftest import task_named

# paper, closer, scenario 2 down-1: r moves to (73/30, -1) and is not closer to (73/30, 31/10) in B
CONFIGURATION = ["0,0", "73/30,1", "73/30,31/10"]
KEY = "connectivity/closer-scenario-2.down-1"


def test_a_stored_configuration_is_replayed_first_and_decides():
    model = load_model("paper")
    task = task_named(model, KEY)
    rows = {KEY: {"verdict": "VIOLATED", "configuration": CONFIGURATION}}
    known = _known_configuration(task.key, rows)
    assert known == {"configuration": CONFIGURATION}
    got = replay_known(model, task, known)
    assert got is not None and got.initial and "not closer" in got.what
    result = prove_spec(model, task, timeout=5.0, out=None, known=[(EARLIER, known)])
    assert result.verdict is Verdict.VIOLATED and "earlier run's counterexample" in result.reason


def test_a_stored_configuration_that_no_longer_breaks_the_claim_is_searched_past():
    model = load_model("paper")
    task = task_named(model, KEY)
    assert _known_configuration(task.key, {KEY: {"verdict": "PROVED", "configuration": CONFIGURATION}}) is None
    assert _known_configuration(task.key, {KEY: {"verdict": "VIOLATED", "configuration": []}}) is None
    moved = ["0,0", "73/30,1", "73/30,5"]  # the robot of B out of view: r decides otherwise, or the claim holds
    assert replay_known(model, task, {"configuration": moved}) is None
    assert replay_known(model, task, {"configuration": ["0,0", "x,1"]}) is None
    other = task_named(model, "connectivity/closer-scenario-3.up-1")  # another case: r's decision differs
    assert replay_known(model, other, {"configuration": CONFIGURATION}) is None


UP_2 = "no-collision/one-mover-scenario-2.up-2-after-down"


def _beside(tmp_path, sibling: str, key: str, doc) -> Path:
    """A proofs root holding ``sibling``'s results and its trace of ``key``; returns the directory
    another model's obligations would be written to."""
    from fatline_verify.outputs import Kind, write_json
    from fatline_verify.trace.traces import write_trace

    lemma, rest = key.split("/", 1)
    write_json(tmp_path / sibling / "results.json", {"format": Kind.PROVE.value, "model": sibling, "obligations": []})
    write_trace(doc, tmp_path / sibling / "traces" / f"{sibling}-prove-{lemma}-{rest}.json")
    return tmp_path / "paper"


def test_a_counterexample_found_under_a_model_beside_is_replayed_first(tmp_path):
    """The same obligation's counterexample under another model proved beside this one decides here
    when the replay under this model keeps the case and the claim (uncovered=stay does not bear on
    Scenario 2's search); the reason names the model it was found under."""
    from fatline_verify.trace.traces import check_replay, load_trace

    root = Path(__file__).resolve().parent.parent / "proofs"
    doc = load_trace(
        root
        / "paper-uncovered-stay"
        / "traces"
        / "paper-uncovered-stay-prove-no-collision-one-mover-scenario-2.up-2-after-down.json"
    )
    model = load_model("paper")
    task = task_named(model, UP_2)
    out = _beside(tmp_path, "paper-uncovered-stay", UP_2, doc)
    known = _known_beside(task.key, out)
    assert [where for where, _ in known] == ["a counterexample found under model paper-uncovered-stay"]
    result = prove_spec(model, task, timeout=0.05, out=None, known=known)
    assert result.verdict is Verdict.VIOLATED, result.reason
    assert "found under model paper-uncovered-stay, replayed first" in result.reason
    assert result.witness is not None
    check_replay(result.witness, model)


def test_a_counterexample_beside_that_does_not_replay_here_is_searched_past(tmp_path):
    """Another obligation's trace, or one under a reading that changes the case, decides nothing: the
    search runs (and with almost no budget says INCONCLUSIVE, never VIOLATED)."""
    from fatline_verify.trace.traces import load_trace

    root = Path(__file__).resolve().parent.parent / "proofs"
    doc = load_trace(root / "paper" / "traces" / "paper-prove-no-collision-one-mover-scenario-1.json")
    model = load_model("paper")
    task = task_named(model, UP_2)
    out = _beside(tmp_path, "paper-centralized", UP_2, doc)  # filed under UP_2, but a Scenario 1 trace
    known = _known_beside(task.key, out)
    assert len(known) == 1
    result = prove_spec(model, task, timeout=0.05, out=None, known=known)
    assert result.verdict is not Verdict.VIOLATED and "replayed first" not in result.reason
    assert _known_beside(task.key, None) == []
    foreign = _beside(tmp_path, "foreign", UP_2, doc).parent / "foreign"
    (foreign / "results.json").write_text("{}")  # not a prover's results: its traces are not read
    assert len(_known_beside(task.key, out)) == 1


def test_an_earlier_non_initial_violation_is_kept_when_no_initial_one_is_found():
    """An INCONCLUSIVE row's own trace (a violation from a configuration that is not initial) is
    replayed first: with no budget left for a search, the verdict stays INCONCLUSIVE and keeps that
    configuration and its trace, instead of losing them to a budget-only reason."""
    from fatline_verify.trace.traces import load_trace

    key = "no-collision/one-mover-scenario-4-I-nonempty.from-uncovered-both"
    # the row's own trace while it was INCONCLUSIVE (proofs/ now holds an initial counterexample)
    doc = load_trace(Path(__file__).parent / "fixtures" / "prove" / "paper-drop-touch-non-initial-uncovered-both.json")
    model = load_model("paper-drop-touch")
    task = task_named(model, key)
    assert replay_known(model, task, doc) is None  # not initial: it decides nothing on its own
    got = replay_known(model, task, doc, initial=False)
    assert got is not None and not got.initial and got.problems
    result = prove_spec(model, task, timeout=0.05, out=None, known=[(EARLIER, doc)])
    assert result.verdict is Verdict.INCONCLUSIVE, result.reason
    assert "not initial" in result.reason and got.problems[0] in result.reason
    assert result.witness is not None
    assert sorted(map(str, result.witness["initial"])) == sorted(map(str, doc["initial"]))  # the same robots


def test_the_mirror_of_a_case_swaps_scenarios_2_and_3_and_up_and_down():
    """Scenario 2 moves up and Scenario 3 down: reflected in the x-axis, each case is the other's; a
    case of another rule has no mirror, and mirroring twice is the identity."""
    pairs = {
        "connectivity/one-mover-scenario-2.up-3-after-down": "connectivity/one-mover-scenario-3.down-3-after-up",
        "no-collision/one-mover-scenario-2.down-1": "no-collision/one-mover-scenario-3.up-1",
        "connectivity/closer-scenario-3.down-2-after-up": "connectivity/closer-scenario-2.up-2-after-down",
    }
    for key, mirror in pairs.items():
        assert mirror_key(key) == mirror and mirror_key(mirror) == key
    for key in (
        "no-collision/one-mover-scenario-1",
        "connectivity/one-mover-scenario-4-I-empty.from-scenario-2",
        "no-collision/one-mover-uncovered-search.up-3-after-down.from-uncovered-both",
    ):
        assert mirror_key(key) is None
    doc = {"initial": [[0, 0], ["5/2", "-9/4"], [1, 3]], "rounds": []}
    assert reflect(doc)["initial"] == [[0, "0"], ["5/2", "9/4"], [1, "-3"]] and doc["initial"][2] == [1, 3]
    assert reflect(reflect({"configuration": ["0,0", "73/30,1"]})) == {"configuration": ["0,0", "73/30,1"]}


def test_the_reflected_counterexample_of_the_mirror_case_decides_this_one(tmp_path):
    """Under paper, the one-mover connectivity obligation of Scenario 2's third upward candidate has
    only a counterexample from a configuration that is not initial of its own; Scenario 3's third
    downward one, reflected, is one from an initial configuration. Not reflected, it decides nothing
    (r then takes Scenario 3's case)."""
    from fatline_verify.trace.traces import check_replay, load_trace, write_trace

    model = load_model("paper")
    key = "connectivity/one-mover-scenario-2.up-3-after-down"
    task = task_named(model, key)
    root = Path(__file__).resolve().parent.parent / "proofs" / "paper" / "traces"
    theirs = load_trace(root / "paper-prove-connectivity-one-mover-scenario-3.down-3-after-up.json")
    assert replay_known(model, task, theirs) is None
    write_trace(theirs, tmp_path / "traces" / "paper-prove-connectivity-one-mover-scenario-3.down-3-after-up.json")
    known = _known_all(model, key, tmp_path / "traces", None, None)
    assert [where for where, _ in known] == [
        "the mirror image (y to -y) of an earlier run's counterexample for one-mover-scenario-3.down-3-after-up"
    ]
    result = prove_spec(model, task, timeout=0.05, out=None, known=known)
    assert result.verdict is Verdict.VIOLATED and "mirror image" in result.reason, result.reason
    assert result.witness is not None
    check_replay(result.witness, model)
