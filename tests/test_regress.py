"""``fatline regress`` and the JUnit XML reports: every document written is validated against the JUnit
schema (``tests/fixtures/junit.xsd``); what XSD 1.0 cannot say (a suite's counts equal its cases') is
checked beside it."""

from __future__ import annotations

import json
import os
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import xmlschema

from fatline_verify import outputs
from fatline_verify.errors import TraceDidNotReproduce
from fatline_verify.junit import Case, Outcome, Suite, to_xml
from fatline_verify.trace.traces import check_replay, load_trace
from tests.test_cli import assert_one_line_error, run_cli

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "reports" / "traces"
SCHEMA = xmlschema.XMLSchema10(ROOT / "tests" / "fixtures" / "junit.xsd")

CONNECTIVITY = "paper-check-connectivity-n2.json"
COLLISION = "paper-check-no-collision-n3.json"


def validated(source: Path | str) -> ET.Element:
    """The document, valid under the JUnit schema, its counts those of its cases; its root."""
    SCHEMA.validate(str(source) if isinstance(source, Path) else source)
    root = ET.fromstring(source.read_text(encoding="utf-8") if isinstance(source, Path) else source)
    totals = dict.fromkeys(("tests", "failures", "errors"), 0)
    for suite in root.iter("testsuite"):
        cases = suite.findall("testcase")
        counts = {
            "tests": len(cases),
            "failures": sum(c.find("failure") is not None for c in cases),
            "errors": sum(c.find("error") is not None for c in cases),
            "skipped": sum(c.find("skipped") is not None for c in cases),
        }
        assert {k: int(suite.get(k, "0")) for k in counts} == counts, suite.get("name")
        for k in totals:
            totals[k] += counts[k]
    assert {k: int(root.get(k, "0")) for k in totals} == totals
    return root


def cases(root: ET.Element) -> dict[str, ET.Element]:
    return {f"{c.get('classname')}/{c.get('name')}": c for c in root.iter("testcase")}


@pytest.fixture
def two(tmp_path) -> Path:
    """A directory of two corpus traces."""
    d = tmp_path / "traces"
    d.mkdir()
    for name in (CONNECTIVITY, COLLISION):
        shutil.copyfile(CORPUS / name, d / name)
    return d


def tamper(path: Path) -> None:
    """Move robot 1's recorded destination in the first round (the collision witness's mover)."""
    doc = json.loads(path.read_text())
    doc["rounds"][0]["decisions"][0]["destination"] = [0, 2]
    doc["rounds"][0]["positions"][1] = [0, 2]
    path.write_text(json.dumps(doc))


# --- the schema itself ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "broken",
    [
        '<testsuite name="a" tests="0" failures="0" errors="0"/>',  # the root must be testsuites
        '<testsuites><testsuite name="a" tests="x" failures="0" errors="0"/></testsuites>',
        '<testsuites><testsuite name="a" tests="1" failures="0" errors="0">'
        '<testcase classname="c" name="n"><failure/><skipped/></testcase></testsuite></testsuites>',
        '<testsuites><testsuite name="a" tests="1" failures="0" errors="0">'
        '<testcase classname="c" name="n" time="-1"/></testsuite></testsuites>',
        '<testsuites><testsuite name="a" tests="1" failures="0" errors="0">'
        '<testcase classname="c" name="n" verdict="x"/></testsuite></testsuites>',
    ],
)
def test_the_schema_rejects_what_ci_systems_would_not_read(broken):
    assert not SCHEMA.is_valid(broken)


def test_every_outcome_and_awkward_text_make_a_valid_document():
    text = 'quote " amp & lt < control \x01\x1b lone \udc80 -- comment end, ünïcode'
    suites = [
        Suite(
            text,
            (
                Case("m", "passed", 0.25),
                Case("m", "failed", 1.0, Outcome.FAILURE, text, "TraceDidNotReproduce", text),
                Case("m", "error", None, Outcome.ERROR, text, "InvalidTrace"),
                Case("m", "skipped", None, Outcome.SKIPPED, "INCONCLUSIVE: bound hit"),
            ),
            properties=(("model", text),),
        ),
        Suite("empty", ()),
    ]
    root = validated(to_xml(suites, name=text))
    failure = cases(root)["m/failed"].find("failure")
    assert failure is not None and failure.get("message", "").startswith('quote " amp & lt < control ')
    assert root.get("tests") == "4" and root.get("time") == "1.250"


# --- fatline regress ----------------------------------------------------------------------------------


def test_the_corpus_replays_green(capsys, tmp_path):
    junit = tmp_path / "junit.xml"
    code, out, err = run_cli(capsys, "regress", str(CORPUS), "--junit", str(junit), "-q")
    assert code == 0, out + err
    root = validated(junit)
    corpus = sorted(CORPUS.glob("*.json"))
    testcases = list(root.iter("testcase"))
    assert [c.get("name") for c in testcases] == [p.name for p in corpus]
    assert not any(list(c) for c in testcases)  # no failure, error or skipped
    assert {c.get("classname") for c in testcases} == {load_trace(p)["model"]["name"] for p in corpus}
    assert all(float(c.get("time", "-1")) >= 0 for c in testcases)
    assert f"{len(corpus)} traces in 1 directory replayed" in out and "0 did not" in out


def test_a_tampered_trace_fails_naming_the_first_differing_value(capsys, two, tmp_path):
    tamper(two / COLLISION)
    with pytest.raises(TraceDidNotReproduce) as raised:
        check_replay(load_trace(two / COLLISION))
    junit = tmp_path / "junit.xml"
    code, out, _ = run_cli(capsys, "regress", str(two), "--junit", str(junit), "-q")
    assert code == 1
    by_name = cases(validated(junit))
    failure = by_name[f"paper/{COLLISION}"].find("failure")
    assert failure is not None
    assert failure.get("message") == str(raised.value)
    assert failure.get("message", "").startswith("rounds[0].decisions[0].destination[1]: recorded 2, replayed 1")
    assert failure.get("type") == "TraceDidNotReproduce"
    assert f"fatline replay {two / COLLISION} -v" in (failure.text or "")
    assert list(by_name[f"paper/{CONNECTIVITY}"]) == []  # the other one passes
    assert f"{two / COLLISION}: DID NOT REPRODUCE: rounds[0].decisions[0].destination[1]" in out
    assert "1 reproduce, 1 did not" in out


def test_a_step_the_model_refuses_is_an_error(capsys, two, tmp_path):
    doc = json.loads((two / CONNECTIVITY).read_text())
    doc["rounds"][0]["active"] = [5]
    (two / CONNECTIVITY).write_text(json.dumps(doc))
    junit = tmp_path / "junit.xml"
    code, out, _ = run_cli(capsys, "regress", str(two), "--junit", str(junit), "-q")
    assert code == 1
    error = cases(validated(junit))[f"paper/{CONNECTIVITY}"].find("error")
    assert error is not None and "robot 5 does not exist" in error.get("message", "")
    assert "1 could not be replayed" in out


def test_under_another_model_a_gone_counterexample_fails(capsys, two, tmp_path):
    model = tmp_path / "stay.toml"
    model.write_text('name = "stay"\n[options]\nuncovered = "stay"\n')
    junit = tmp_path / "junit.xml"
    code, _, _ = run_cli(capsys, "regress", str(two), "--model", str(model), "--junit", str(junit), "-q")
    assert code == 1
    root = validated(junit)
    failure = cases(root)[f"paper/{CONNECTIVITY}"].find("failure")
    assert failure is not None and failure.get("message", "").startswith("the counterexample is gone under stay")
    assert root.find("testsuite").get("name", "").endswith("under stay")


def test_directories_are_searched_recursively_and_other_outputs_skipped(capsys, two, tmp_path):
    sub = two / "more" / "deeper"
    sub.mkdir(parents=True)
    shutil.copyfile(CORPUS / "repaired-check-progress-n3.json", sub / "r.json")
    shutil.copyfile(ROOT / "proofs" / "paper" / "results.json", two / "results.json")  # a fatline prove result
    hidden = two / ".cache"
    hidden.mkdir()
    (hidden / "junk.json").write_text("not json")
    (two / "notes.txt").write_text("not a trace, not *.json")
    junit = tmp_path / "junit.xml"
    code, out, _ = run_cli(capsys, "regress", str(two), str(CORPUS / CONNECTIVITY), "--junit", str(junit), "-q")
    assert code == 0
    suites = validated(junit).findall("testsuite")
    assert [[c.get("name") for c in s.iter("testcase")] for s in suites] == [
        ["more/deeper/r.json", CONNECTIVITY, COLLISION],  # by path under the directory
        [CONNECTIVITY],
    ]
    assert "(1 other fatline output skipped)" in out


def test_it_rewrites_its_own_report_and_any_other_only_with_force(capsys, two, tmp_path):
    junit = tmp_path / "junit.xml"
    for _ in range(2):
        assert run_cli(capsys, "regress", str(two), "--junit", str(junit), "-q")[0] == 0
    foreign = tmp_path / "theirs.xml"
    foreign.write_text("<testsuites/><!-- generated by fatline-verify, but not a report of ours -->")
    code, _, err = run_cli(capsys, "regress", str(two), "--junit", str(foreign), "-q")
    assert_one_line_error(code, err, "junit=", "exists and is not a JUnit XML report fatline wrote", "--force")
    assert foreign.read_text().startswith("<testsuites/>")
    assert run_cli(capsys, "regress", str(two), "--junit", str(foreign), "--force", "-q")[0] == 0
    validated(foreign)


@pytest.mark.parametrize(
    ("make", "argv", "fragment"),
    [
        (None, ["nope"], "dir='nope': no such directory"),
        ("empty", ["empty"], "dir='empty': no trace files in it"),
        ("results", ["results"], "no trace files in it (1 other fatline output skipped)"),
        ("bad", ["bad"], "bad/x.json: at (top level): 'format' is a required property"),
        ("notjson", ["notjson"], "notjson/x.json'"),
        ("unknown", ["unknown"], "unknown/x.json'"),
        (None, ["traces", "--junit", "nodir/j.xml"], "junit='nodir/j.xml': directory 'nodir' does not exist"),
        (None, ["traces", "--junit", "traces"], "junit='traces': is a directory"),
        (None, ["traces", "--junit", ""], "junit='': expected a file name"),
        (None, ["traces", "--model", "nope.toml"], "model='nope.toml'"),
        (None, [], "DIR: missing"),
    ],
)
def test_bad_input_is_one_line_and_exit_2_before_any_work(capsys, two, tmp_path, monkeypatch, make, argv, fragment):
    monkeypatch.chdir(tmp_path)
    if make is not None:
        (tmp_path / make).mkdir()
    if make == "results":
        shutil.copyfile(ROOT / "proofs" / "paper" / "results.json", tmp_path / make / "results.json")
    elif make == "bad":
        (tmp_path / make / "x.json").write_text('{"rounds": []}')
    elif make == "notjson":
        (tmp_path / make / "x.json").write_text("{")
    elif make == "unknown":  # a reading no model has: found while loading, not while replaying
        doc = json.loads((CORPUS / CONNECTIVITY).read_text())
        doc["model"]["options"]["uncovered"] = "teleport"
        (tmp_path / make / "x.json").write_text(json.dumps(doc))
    code, out, err = run_cli(capsys, "regress", *argv, "-q")
    assert_one_line_error(code, err, fragment)
    assert out == ""
    assert not (tmp_path / "nodir").exists()


def test_an_unwritable_junit_directory_is_refused(capsys, two, tmp_path, monkeypatch):
    ro = tmp_path / "ro"
    ro.mkdir()
    real = os.access
    # as root every directory is writable: make this one read-only to the check
    monkeypatch.setattr(outputs.os, "access", lambda p, mode: real(p, mode) and Path(p) != ro)
    code, _, err = run_cli(capsys, "regress", str(two), "--junit", str(ro / "j.xml"), "-q")
    assert_one_line_error(code, err, f"junit='{ro / 'j.xml'}'", "is not writable")
    assert not (ro / "j.xml").exists()
