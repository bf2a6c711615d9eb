"""A counterexample once found stays found: an earlier run's trace-less counterexample (the replayed
configuration of a ``closer``, ``seen`` or ``x-nondecreasing`` row) is replayed before any search."""

from __future__ import annotations

from fatline_verify.config import load_model
from fatline_verify.properties import Verdict
from fatline_verify.prove_replay import replay_known
from fatline_verify.prove_search import prove_spec
from fatline_verify.prover import _known_configuration, tasks_for

# paper, closer, scenario 2 down-1: r moves to (73/30, -1) and is not closer to (73/30, 31/10) in B
CONFIGURATION = ["0,0", "73/30,1", "73/30,31/10"]
KEY = "connectivity/closer-scenario-2.down-1"


def _task(model, key):
    return next(t for t in tasks_for(model) if t.key == key)


def test_a_stored_configuration_is_replayed_first_and_decides():
    model = load_model("paper")
    task = _task(model, KEY)
    rows = {KEY: {"verdict": "VIOLATED", "configuration": CONFIGURATION}}
    known = _known_configuration(task, rows)
    assert known == {"configuration": CONFIGURATION}
    got = replay_known(model, task, known)
    assert got is not None and got.initial and "not closer" in got.what
    result = prove_spec(model, task, timeout=5.0, out=None, known=known)
    assert result.verdict is Verdict.VIOLATED and "earlier run's counterexample" in result.reason


def test_a_stored_configuration_that_no_longer_breaks_the_claim_is_searched_past():
    model = load_model("paper")
    task = _task(model, KEY)
    assert _known_configuration(task, {KEY: {"verdict": "PROVED", "configuration": CONFIGURATION}}) is None
    assert _known_configuration(task, {KEY: {"verdict": "VIOLATED", "configuration": []}}) is None
    moved = ["0,0", "73/30,1", "73/30,5"]  # the robot of B out of view: r decides otherwise, or the claim holds
    assert replay_known(model, task, {"configuration": moved}) is None
    assert replay_known(model, task, {"configuration": ["0,0", "x,1"]}) is None
    other = _task(model, "connectivity/closer-scenario-3.up-1")  # another case: r's decision differs
    assert replay_known(model, other, {"configuration": CONFIGURATION}) is None
