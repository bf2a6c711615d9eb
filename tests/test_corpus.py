"""The regression corpus and the committed reports.

Every counterexample the checker and the prover found for the shipped models is kept in
``reports/traces/`` with a stable name; each must keep reproducing. The committed reports must
regenerate byte-identically from the committed results.
"""

from __future__ import annotations

import filecmp
import shutil
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.model.config import load_model, shipped_models
from fatline_verify.report.build import build_report
from fatline_verify.trace.traces import check_replay, load_trace

ROOT = Path(__file__).resolve().parent.parent
CORPUS = sorted((ROOT / "reports" / "traces").glob("*.json"))


def test_the_corpus_is_not_empty_and_covers_every_shipped_model():
    assert CORPUS
    names = {p.name for p in CORPUS}
    for model in shipped_models():
        if "VIOLATED" in load_model(model).expected.values():  # a model that breaks a lemma has its witness here
            assert any(n.startswith(f"{model.stem}-check-") for n in names), model.stem


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.stem)
def test_every_corpus_trace_reproduces(path):
    doc = load_trace(path)
    check_replay(doc)
    assert doc["violation"] is not None or doc["outcome"] in ("deadlock", "cycle", "round-limit", "goal")


def test_a_corpus_trace_replayed_under_another_model_shows_the_difference(capsys):
    # The 2-robot disconnection of the default readings does not happen when uncovered cases stay put.
    trace = ROOT / "reports" / "traces" / "paper-check-connectivity-n2.json"
    other = ROOT / "tmp-stay.toml"
    try:
        other.write_text('[options]\nuncovered = "stay"\n')
        assert main(["replay", str(trace), "--model", str(other)]) == 1
        assert "DID NOT REPRODUCE" in capsys.readouterr().out
    finally:
        other.unlink()


def _beside_docs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[Path, Path]:
    """``reports`` and ``proofs`` named as ``fatline report`` in the repository names them (relative to
    the directory it runs in: the pages' commands name them so), with the readings catalogue beside them
    (the pages link it where it is found above the report)."""
    (tmp_path / "docs").mkdir()
    shutil.copyfile(ROOT / "docs" / "readings.md", tmp_path / "docs" / "readings.md")
    monkeypatch.chdir(tmp_path)
    return Path("reports"), Path("proofs")


@pytest.mark.slow  # every shipped model's pages and pictures drawn again (about 650 SVG frames);
# the default tier regenerates one model's among the others' (below)
def test_reports_regenerate_byte_identically(tmp_path, monkeypatch):
    out, proofs = _beside_docs(tmp_path, monkeypatch)
    for model in shipped_models():
        (out / model.stem).mkdir(parents=True)
        shutil.copyfile(ROOT / "reports" / model.stem / "check.json", out / model.stem / "check.json")
        if (ROOT / "proofs" / model.stem).is_dir():  # a scheduler the prover does not encode has none
            shutil.copytree(ROOT / "proofs" / model.stem, proofs / model.stem)
    shutil.copytree(ROOT / "reports" / "traces", out / "traces")  # the corpus keeps traces of earlier runs
    build_report([load_model(p) for p in shipped_models()], out, proofs=proofs)
    differing = _differing(out)
    assert not differing, differing[:10]


def test_one_models_report_regenerates_byte_identically_among_the_others(tmp_path, monkeypatch):
    """The fast representative of the above: one model's pages and pictures, and the cross-model
    pages, are drawn again (deleted first) beside the other models' committed ones, and the whole tree
    is the committed one byte for byte."""
    from fatline_verify.report.pages import ASSETS

    name = "paper-async"  # the quickest shipped model to draw again (33 pictures, no prover rows)
    out, proofs = _beside_docs(tmp_path, monkeypatch)
    shutil.copytree(ROOT / "reports", out)
    shutil.copytree(ROOT / "proofs", proofs)
    shutil.rmtree(out / name / "img")
    for page in (out / name / "README.md", out / name / "index.html", out / "README.md", out / "index.html"):
        page.unlink()
    for asset in ASSETS:
        (out / asset).unlink()
    build_report([load_model(name)], out, proofs=proofs)
    assert (out / name / "img").is_dir() and (out / "index.html").is_file()
    differing = _differing(out)
    assert not differing, differing[:10]


def _differing(out: Path) -> list[str]:
    """Files of the committed ``reports/`` that ``out`` lacks or has otherwise, and files only in ``out``."""
    cmp = filecmp.dircmp(ROOT / "reports", out)
    differing: list[str] = []

    def walk(c: filecmp.dircmp, prefix: str) -> None:
        differing.extend(prefix + f for f in c.diff_files + c.left_only + c.right_only)
        for name, sub in c.subdirs.items():
            walk(sub, f"{prefix}{name}/")

    walk(cmp, "")
    # filecmp compares shallowly by stat; compare contents of every file too
    for path in (ROOT / "reports").rglob("*"):
        if path.is_file():
            twin = out / path.relative_to(ROOT / "reports")
            if not twin.exists() or twin.read_bytes() != path.read_bytes():
                differing.append(str(path.relative_to(ROOT)))
    return differing


def test_replay_writes_pictures(tmp_path, capsys):
    trace = ROOT / "reports" / "traces" / "paper-check-no-collision-n3.json"
    assert main(["replay", str(trace), "--picture", str(tmp_path)]) == 0
    pictures = sorted(tmp_path.glob("*.svg"))
    assert [p.name for p in pictures] == ["paper-check-no-collision-n3-0.svg", "paper-check-no-collision-n3-1.svg"]
    svg = pictures[0].read_text()
    assert svg.startswith("<?xml") and "no-collision" in svg and "closest squared centre distance" in svg


def test_the_findings_page_shows_the_current_verdict_matrix():
    """docs/findings.md's copy of the readings x lemmas matrix is the generated one (links adjusted)."""
    generated = (ROOT / "reports" / "README.md").read_text().splitlines()
    rows = [line for line in generated if line.startswith("| [")]
    assert rows
    page = (ROOT / "docs" / "findings.md").read_text()
    for row in rows:
        assert row.replace("](", "](../reports/") in page, row[:80]
