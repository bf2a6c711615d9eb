"""``fatline check --junit`` and ``fatline prove --junit``: one test case per lemma and robot count, per
obligation; VIOLATED a failure, INCONCLUSIVE skipped with its reason; each document validated against
the JUnit schema (:func:`tests.test_regress.validated`)."""

from __future__ import annotations

import json

import pytest

from fatline_verify.junit import prove_suites, to_xml
from tests.test_cli import assert_one_line_error, run_cli
from tests.test_regress import ROOT, cases, validated


def test_check_junit_one_case_per_lemma_and_robot_count(capsys, tmp_path):
    junit = tmp_path / "check.xml"
    argv = ["--robots", "2..3", "--window", "5x5", "--max-states", "50", "--traces", str(tmp_path / "t")]
    code, out, _ = run_cli(capsys, "check", *argv, "--junit", str(junit), "-q")
    assert code == 1
    assert f"JUnit XML written to {junit}" in out
    root = validated(junit)
    by_name = cases(root)
    lemmas = ("connectivity", "no-collision", "progress", "rma-fixed", "approach", "termination")
    assert set(by_name) == {f"paper.{lemma}/{n} robots" for lemma in lemmas for n in (2, 3)}
    # 2 robots searched to the end: VIOLATED is a failure naming its witness, HOLDS passes
    failure = by_name["paper.connectivity/2 robots"].find("failure")
    assert failure is not None and failure.get("type") == "VIOLATED"
    witness = tmp_path / "t" / "paper-connectivity-n2.json"
    assert failure.get("message") == f"a violating round; witness of 1 round in {witness}"
    assert list(by_name["paper.no-collision/2 robots"]) == []
    # 3 robots stopped by --max-states: INCONCLUSIVE is skipped with the reason
    skipped = by_name["paper.no-collision/3 robots"].find("skipped")
    assert skipped is not None and "rerun with --max-states" in skipped.get("message", "")
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == ["fatline check paper: 2 robots", "fatline check paper: 3 robots"]
    props = {p.get("name"): p.get("value") for p in suites[0].iter("property")}
    assert props["window"] == "5x5" and props["robots"] == "2"


def test_check_junit_is_claimed_before_any_work(capsys, tmp_path):
    foreign = tmp_path / "mine.xml"
    foreign.write_text("keep")
    code, _, err = run_cli(capsys, "check", "--robots", "2", "--junit", str(foreign), "--traces", str(tmp_path), "-q")
    assert_one_line_error(code, err, "junit=", "exists and is not a JUnit XML report")
    assert foreign.read_text() == "keep"
    assert not list(tmp_path.glob("*.json"))


def test_prove_junit_one_case_per_obligation(capsys, tmp_path):
    junit = tmp_path / "prove.xml"
    argv = ["repaired", "--lemma", "no-collision", "--timeout", "2", "--views", "500", "--out", str(tmp_path / "p")]
    code, _, _ = run_cli(capsys, "prove", *argv, "--junit", str(junit), "-q")
    assert code == 3  # the views row on a sample: INCONCLUSIVE
    rows = json.loads((tmp_path / "p" / "repaired" / "results.json").read_text())["obligations"]
    root = validated(junit)
    testcases = list(root.iter("testcase"))
    assert len(testcases) == len(rows) == 10  # 9 leg obligations of the repaired family, its views row
    assert {c.get("classname") for c in testcases} == {"repaired.no-collision"}
    tail = [f".and.{r['other']}" if r["other"] else "" for r in rows]
    assert [c.get("name") for c in testcases] == [
        f"{r['form']}-{r['case']}{t}" for r, t in zip(rows, tail, strict=True)
    ]
    assert [float(c.get("time", "")) for c in testcases] == [round(r["seconds"], 3) for r in rows]
    assert all(r["verdict"] == "PROVED" for r in rows[:-1]) and rows[-1]["verdict"] == "INCONCLUSIVE"  # a sample


def test_prove_rows_failure_when_violated_skipped_when_inconclusive():
    from fatline_verify.model.config import load_model

    rows = json.loads((ROOT / "proofs" / "paper" / "results.json").read_text())["obligations"]
    rows = [*rows, {**rows[0], "case": "made-up", "verdict": "INCONCLUSIVE", "reason": "stopped by the wall clock"}]
    root = validated(to_xml(prove_suites(load_model("paper"), rows), name="fatline prove paper"))
    by_name = cases(root)
    assert len(by_name) == len(rows)
    for row in rows:
        case = by_name[
            f"paper.{row['lemma']}/{row['form']}-{row.get('case', row['rule'])}"
            + (f".and.{row['other']}" if row.get("other") else "")
        ]
        kind = {"VIOLATED": "failure", "INCONCLUSIVE": "skipped", "PROVED": None}[row["verdict"]]
        assert [child.tag for child in case] == ([kind] if kind else [])
        if kind:
            assert case[0].get("message") == row["reason"]
        if row.get("trace"):
            assert f"fatline replay {row['trace']} -v" in (case[0].text or "")


@pytest.mark.slow
def test_prove_junit_with_counterexamples(capsys, tmp_path):
    junit = tmp_path / "prove.xml"
    argv = ["paper", "--lemma", "no-collision", "--timeout", "2", "--out", str(tmp_path / "p")]
    code, _, _ = run_cli(capsys, "prove", *argv, "--junit", str(junit), "-q")
    assert code in (1, 3)
    rows = json.loads((tmp_path / "p" / "paper" / "results.json").read_text())["obligations"]
    testcases = list(validated(junit).iter("testcase"))
    assert len(testcases) == len(rows)
    assert sum(c.find("failure") is not None for c in testcases) == sum(r["verdict"] == "VIOLATED" for r in rows) > 0
