"""The corpus under another rule set (``fatline_verify/repair/against.py``): under ``repaired`` every
counterexample of the other models is gone from its own initial configuration, while a model that
shares the paper's rules keeps them (the check can fail), and the repaired model's page shows it."""

from __future__ import annotations

import json
import re
from collections import Counter
from pathlib import Path

import pytest

from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.repair.against import (
    GONE_ON_ITS_ROUNDS,
    NOT_CHECKED,
    STILL_ON_ITS_ROUNDS,
    against,
    corpus_against,
    its_rounds,
)
from fatline_verify.rules import registry
from fatline_verify.trace.traces import check_replay, initial_positions

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "reports" / "traces"


@pytest.mark.slow  # the whole corpus (about 380 counterexamples), each explored under the repaired
# rules; the default tier takes each model's first of each kind (below)
def test_every_corpus_counterexample_is_gone_under_the_repaired_rules():
    rows = corpus_against(load_model("repaired"), CORPUS)
    others = [p for p in CORPUS.glob("*.json") if not p.name.startswith("repaired-")]
    assert len(rows) == len(others)
    verdicts = Counter(r.verdict for r in rows)
    assert verdicts[Verdict.VIOLATED.value] == 0 and verdicts[STILL_ON_ITS_ROUNDS] == 0, verdicts
    assert verdicts[Verdict.HOLDS_WITHIN_BOUNDS.value] > len(rows) // 2
    assert verdicts[GONE_ON_ITS_ROUNDS] and not verdicts[NOT_CHECKED]
    unsure = [r for r in rows if r.verdict == Verdict.INCONCLUSIVE.value]
    assert all(r.scheduler == "async" and "leave the window" in r.reason for r in unsure), unsure


def test_each_models_first_counterexamples_are_gone_under_the_repaired_rules():
    """The fast representative of the above: of every other model, its first counterexample (by file
    name) from the checker and its first from the prover, under the repaired rules."""
    first: dict[str, Path] = {}
    for path in sorted(CORPUS.glob("*.json")):
        source = re.match(r"(.+)-(check|prove)-", path.name)
        assert source is not None, path.name
        if source[1] != "repaired" and registry.of(load_model(source[1])).robots == "discs":
            first.setdefault(f"{source[1]} {source[2]}", path)  # point robots' traces are no configurations of discs
    assert {key.split()[1] for key in first} == {"check", "prove"} and len(first) > 2
    model = load_model("repaired")
    rows = [against(model, path) for path in first.values()]
    assert all(row is not None for row in rows)
    verdicts = Counter(r.verdict for r in rows)
    assert verdicts[Verdict.VIOLATED.value] == 0 and verdicts[STILL_ON_ITS_ROUNDS] == 0, verdicts
    assert not verdicts[NOT_CHECKED]
    unsure = [r for r in rows if r.verdict == Verdict.INCONCLUSIVE.value]
    assert all(r.scheduler == "async" and "leave the window" in r.reason for r in unsure), unsure


def test_a_model_with_the_paper_s_rules_keeps_the_counterexamples():
    """paper-centralized under the trace's own scheduler (ssync) is the paper: its counterexamples
    come back, explored (with a replayed witness) or on their own rounds."""
    model = load_model("paper-centralized")
    explored = against(model, CORPUS / "paper-check-connectivity-n2.json")
    assert explored is not None and explored.verdict == Verdict.VIOLATED.value and explored.scheduler == "ssync"
    assert explored.witness is not None
    check_replay(explored.witness)
    fine = against(model, CORPUS / "paper-prove-no-collision-two-movers-scenario-1.json")
    assert fine is not None and fine.verdict == STILL_ON_ITS_ROUNDS, fine
    assert fine.witness is not None
    check_replay(fine.witness)
    assert against(model, CORPUS / "paper-centralized-check-connectivity-n2.json") is None  # its own


def test_the_repaired_page_shows_the_corpus_side_by_side():
    page = (ROOT / "reports" / "repaired" / "README.md").read_text()
    assert "## The corpus under this model" in page
    assert "![counterexample](../paper/img/" in page and "![under this model](img/against-paper-" in page
    assert "## The corpus under this model" not in (ROOT / "reports" / "paper" / "README.md").read_text()


def test_a_counterexample_recorded_on_a_finer_lattice_starts_where_its_file_says(tmp_path):
    """A trace stores radii whatever its model's lattice: the same counterexample recorded under q = 2
    comes back from the same configuration, explored or on its own rounds."""
    model = load_model("paper-centralized")
    for name in ("paper-check-connectivity-n2.json", "paper-prove-no-collision-two-movers-scenario-1.json"):
        doc = json.loads((CORPUS / name).read_text())
        doc["model"]["parameters"]["q"] = 2
        doc["model"]["name"] = "paper-q2"
        fine = tmp_path / name
        fine.write_text(json.dumps(doc))
        a, b = against(model, CORPUS / name), against(model, fine)
        assert a is not None and b is not None
        assert (b.verdict, b.robots, b.reason) == (a.verdict, a.robots, a.reason)
        assert its_rounds(doc, model) is not None
        assert its_rounds(doc, model).initial == initial_positions(doc, model)
