"""Traces: schema, round trip, replay, and the first differing value when a trace is tampered with."""

from __future__ import annotations

import copy
import json

import pytest

from fatline_verify.errors import InvalidTrace, TraceDidNotReproduce
from fatline_verify.trace.simulate import Outcome, simulate
from fatline_verify.trace.traces import check_replay, load_trace, run_to_json, validate, write_trace
from tests.conftest import make_model


@pytest.fixture
def doc():
    run = simulate(((0, 0), (3, 0), (2, 3)), make_model(), seed=1)
    return json.loads(json.dumps(run_to_json(run, {"tool": "test"})))


def test_written_trace_validates_and_replays(tmp_path, doc):
    path = tmp_path / "t.json"
    write_trace(doc, path)
    loaded = load_trace(path)
    assert loaded == doc
    run = check_replay(loaded)
    assert run.outcome is Outcome(doc["outcome"])


def test_fractions_survive_the_round_trip():
    # Off-lattice start: positions are exact "p/q" strings in the trace.
    from fractions import Fraction as Fr

    run = simulate(((0, 0), (Fr(5, 2), Fr(3, 2))), make_model(), max_rounds=5)
    doc = run_to_json(run)
    assert doc["initial"][1] == ["5/2", "3/2"]
    assert check_replay(json.loads(json.dumps(doc))).final == run.final


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        (("rounds", 0, "decisions", 0, "destination"), [9, 9], "rounds[0].decisions[0].destination[0]: recorded 9"),
        (("rounds", 0, "decisions", 0, "rule"), "scenario-1", 'rounds[0].decisions[0].rule: recorded "scenario-1"'),
        (("rounds", 0, "positions", 0), [7, 7], "rounds[0].positions[0][0]: recorded 7"),
        (("outcome",), "goal", 'outcome: recorded "goal"'),
    ],
)
def test_tampering_names_the_first_difference(doc, path, value, message):
    bad = copy.deepcopy(doc)
    target = bad
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    with pytest.raises(TraceDidNotReproduce, match=message.replace("[", r"\[").replace("]", r"\]")):
        check_replay(bad)


def test_tampered_measured_quantity_is_caught():
    run = simulate(((0, 0), (3, 0)), make_model())
    doc = json.loads(json.dumps(run_to_json(run)))
    assert doc["violation"]["property"] == "connectivity"
    assert doc["violation"]["distance2_after"] == [18]
    doc["rounds"][0]["violations"][0]["distance2_after"] = [17]
    with pytest.raises(TraceDidNotReproduce, match=r"distance2_after\[0\]: recorded 17, replayed 18"):
        check_replay(doc)


def test_replay_under_another_model_shows_the_difference(doc):
    # r0's Scenario 2 needs C robot (3,0) in R_psi. Under touch-line psi = 1 and (3,0) is exactly 2 from
    # it: outside R_psi (|x - psi| < 2), so Scenario 1 fires instead; the rule is the first difference.
    assert doc["rounds"][0]["decisions"][0]["destination"] == [2, -2]
    with pytest.raises(TraceDidNotReproduce, match='rule: recorded "scenario-2", replayed "scenario-1"'):
        check_replay(doc, make_model(psi_right="touch-line"))


@pytest.mark.parametrize(
    ("mutate", "message"),
    [
        (lambda d: d.pop("rounds"), "'rounds' is a required property"),
        (lambda d: d.__setitem__("version", 3), "at version"),
        (lambda d: d["initial"].__setitem__(0, ["1.5", 0]), "at initial/0/0"),
        (lambda d: d["model"]["options"].__setitem__("vacant", "maybe"), "option vacant='maybe': unknown reading"),
        (lambda d: d["model"]["options"].__setitem__("colour", "red"), "option colour='red': unknown option"),
        (lambda d: d["model"]["parameters"].__setitem__("delta", 2), "delta=2: expected delta > 2"),
    ],
)
def test_malformed_traces(tmp_path, doc, mutate, message):
    mutate(doc)
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidTrace, match=message):
        check_replay(load_trace(path))


def test_active_robot_out_of_range(doc):
    doc["rounds"][0]["active"] = [7]
    with pytest.raises(InvalidTrace, match="robot 7 does not exist"):
        check_replay(doc)


def test_not_json(tmp_path):
    path = tmp_path / "x.json"
    path.write_text("{not json")
    with pytest.raises(InvalidTrace, match="not JSON"):
        load_trace(path)


def test_write_refuses_malformed_documents(tmp_path):
    path = tmp_path / "keep.json"
    path.write_text("precious")
    with pytest.raises(InvalidTrace):
        write_trace({"format": "fatline-trace"}, path)
    assert path.read_text() == "precious"


def test_schema_rejects_unknown_top_level_keys(doc):
    doc["extra"] = 1
    with pytest.raises(InvalidTrace, match="Additional properties"):
        validate(doc)
