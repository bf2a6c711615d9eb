"""Partial runs merge into what exists: no row, model or trace they did not recompute is dropped."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from fatline_verify.cli import main
from fatline_verify.integrity import seal
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model, shipped_models
from fatline_verify.prove import prover
from fatline_verify.prove.prover import ProofResult
from fatline_verify.prove.results import ProofResults, row_key

ROOT = Path(__file__).resolve().parent.parent


def _fake_prove(verdict: Verdict):
    """A stand-in for the solver: every obligation asked for gets ``verdict`` at once."""

    def fake(
        model,
        lemmas=(),
        *,
        slots,
        timeout,
        out,
        jobs=None,
        progress=None,
        tasks=None,
        on_result=None,
        traces=None,
        earlier=None,
        given=(),
        on_start=None,
        corpus=True,
        deadlocks=(),
    ):
        tasks = prover.tasks_for(model, lemmas) if tasks is None else tasks
        results = []
        for task in tasks:
            case = getattr(task, "name", "any")
            other = getattr(task, "other_name", "")
            r = ProofResult(task.lemma, task.form, case, verdict, slots, False, 0.0, "fake", "", case=case, other=other)
            results.append(r)
            if on_result:
                on_result(r)
            if progress:
                progress(task.key)
        return results

    return fake


def _rows(path: Path) -> dict[str, dict]:
    data = json.loads(path.read_text())
    return {row_key(r): r for r in data["obligations"]}


def test_prove_one_lemma_keeps_the_other_lemmas_rows(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    out = tmp_path / "proofs"
    shutil.copytree(ROOT / "proofs" / "paper", out / "paper")
    before = _rows(out / "paper" / "results.json")
    monkeypatch.setattr(prover, "prove", _fake_prove(Verdict.INCONCLUSIVE))
    code = main(["prove", "paper", "--lemma", "no-collision", "--out", str(out), "-q", "--fresh"])
    assert code == 3
    after = _rows(out / "paper" / "results.json")
    assert after.keys() == before.keys()  # none dropped
    for key, row in after.items():
        if key.startswith("no-collision/"):
            assert row["reason"] == "fake"  # recomputed
        else:
            assert row == {"fingerprint": row["fingerprint"], **before[key]}  # kept as it was
    printed = capsys.readouterr().out.splitlines()
    own = len(prover.tasks_for(load_model("paper"), (Lemma.NO_COLLISION,)))
    assert sum(line.startswith("no-collision/") for line in printed) == own  # the run's own rows only
    assert not any(line.startswith("connectivity/") for line in printed)


def test_prove_redo_inconclusive_reruns_only_those_rows(tmp_path, monkeypatch):
    """``--redo-inconclusive``: the obligations whose saved row is INCONCLUSIVE are recomputed, every
    other row is kept byte for byte (fingerprint included)."""
    monkeypatch.chdir(ROOT)
    out = tmp_path / "proofs"
    shutil.copytree(ROOT / "proofs" / "paper", out / "paper")
    # The committed rows may all be decided: make two INCONCLUSIVE and drop a third (missing) here.
    results = out / "paper" / "results.json"
    data = json.loads(results.read_text())
    committed_open = sum(row["verdict"] == "INCONCLUSIVE" for row in data["obligations"][3:])
    for row in data["obligations"][:2]:
        row["verdict"] = "INCONCLUSIVE"
    missing = row_key(data["obligations"].pop(2))
    results.write_text(json.dumps(seal(data)))  # as a run that left them open wrote it
    before = _rows(results)
    asked: list[str] = []
    fake = _fake_prove(Verdict.PROVED)

    def counting(model, lemmas=(), **kwargs):
        asked.extend(t.key for t in kwargs["tasks"])
        return fake(model, lemmas, **kwargs)

    monkeypatch.setattr(prover, "prove", counting)
    code = main(["prove", "paper", "--redo-inconclusive", "--out", str(out), "-q"])
    assert code in (0, 1)
    # obligations the committed rows do not have yet (added since proofs/ was generated) are missing too
    absent = {t.key for t in prover.tasks_for(load_model("paper"))} - before.keys() - {missing}
    open_keys = {k for k, row in before.items() if row["verdict"] == "INCONCLUSIVE"} | {missing} | absent
    assert len(open_keys) == 3 + committed_open + len(absent) and set(asked) == open_keys
    after = _rows(out / "paper" / "results.json")
    assert after.keys() == before.keys() | {missing} | absent
    for key, row in after.items():
        if key in open_keys:
            assert row["reason"] == "fake" and row["verdict"] == "PROVED"
        else:
            assert row == before[key]


def test_store_saves_each_result_and_keeps_foreign_rows(tmp_path):
    model = load_model("paper")
    (tmp_path / "results.json").write_text(
        json.dumps(
            {
                "format": "fatline-prove",
                "model": "paper",
                "solver": "z3",
                "obligations": [
                    {"lemma": "no-collision", "form": "three-movers", "rule": "x", "verdict": "VIOLATED", "trace": None}
                ],
            }
        )
    )
    store = ProofResults(model, tmp_path, tmp_path / "traces", slots=3, timeout=10.0)
    task = prover.tasks_for(model)[0]
    assert store.fresh(task) is None
    store.add(
        ProofResult(
            "no-collision", "one-mover", "scenario-1", Verdict.PROVED, 3, True, 1.0, "unsat", "", case=task.name
        )
    )
    saved = _rows(tmp_path / "results.json")  # written at once, not at the end of a run
    assert saved["no-collision/one-mover-scenario-1"]["verdict"] == "PROVED"
    assert "no-collision/three-movers-x" in saved
    assert store.fresh(task) is not None
    assert ProofResults(model, tmp_path, tmp_path / "traces", slots=3, timeout=5.0).fresh(task) is None


def test_report_one_model_keeps_the_matrix_and_the_corpus(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    out, proofs = tmp_path / "reports", tmp_path / "proofs"
    for model in shipped_models():
        (out / model.stem).mkdir(parents=True)
        shutil.copyfile(ROOT / "reports" / model.stem / "check.json", out / model.stem / "check.json")
        for svg in (ROOT / "reports" / model.stem / "img").glob("*.svg"):
            (out / model.stem / "img").mkdir(exist_ok=True)
            shutil.copyfile(svg, out / model.stem / "img" / svg.name)
        if (ROOT / "proofs" / model.stem).is_dir():  # a scheduler the prover does not encode has none
            shutil.copytree(ROOT / "proofs" / model.stem, proofs / model.stem)
    shutil.copytree(ROOT / "reports" / "traces", out / "traces")
    corpus_before = sorted(p.name for p in (out / "traces").iterdir())
    stray = out / "traces" / "paper-centralized-prove-from-an-earlier-run.json"
    shutil.copyfile(ROOT / "reports" / "traces" / "paper-centralized-check-progress-n2.json", stray)
    monkeypatch.setattr(prover, "prove", _fake_prove(Verdict.INCONCLUSIVE))  # any recomputation is visible

    model = load_model("paper-centralized")
    store = ProofResults(model, proofs / model.name, proofs / model.name / "traces", slots=3, timeout=60.0)
    current = {k: store.digest(t) for t in prover.tasks_for(model, prover.LEMMAS) if (k := prover.task_key(t))}
    rows = _rows(proofs / model.name / "results.json")
    up_to_date = {k for k, r in rows.items() if r.get("fingerprint") == current.get(k)}
    code = main(["report", "paper-centralized", "--out", str(out), "--proofs", str(proofs), "-q"])
    assert code == 0
    matrix = (out / "README.md").read_text()
    for m in shipped_models():
        assert f"[{m.stem}]({m.stem}/README.md)" in matrix  # every model keeps its row
    # an up-to-date row is reused, never recomputed; a stale one (the code changed since the committed
    # proofs/ were made) is recomputed, which the fake prover shows
    after = _rows(proofs / model.name / "results.json")
    assert all(after[k]["reason"] != "fake" for k in up_to_date)
    assert all(r["reason"] == "fake" for k, r in after.items() if k not in up_to_date and k in current)
    assert stray.exists()
    assert set(corpus_before) <= {p.name for p in (out / "traces").iterdir()}
    assert "kept from earlier runs in the matrix" in capsys.readouterr().out
