"""``fatline report``: per-model pages and the cross-model matrix, from cached or fresh results.

Results are cached as JSON with a fingerprint of what produced them (the model's readings,
parameters and bounds, the prover's settings, the tool's version). An up-to-date cache is reused,
so regenerating a report from committed results is byte-identical; a stale one is recomputed.
Every counterexample trace is copied into ``reports/traces/`` under a stable name: the regression
corpus, which ``tests/test_corpus.py`` replays.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .. import prover
from ..checker import check, check_fingerprint, check_to_json, write_witnesses
from ..config import Model
from ..prover import prove, prove_fingerprint, results_json
from ..trace import check_replay, load_trace, write_json
from .pages import ASSETS, cross_model_html, cross_model_markdown, model_html, model_markdown
from .pictures import frames


@dataclass(frozen=True)
class ModelReport:
    """What the report knows of one model."""

    model: Model
    check: dict[str, Any]
    prove: dict[str, Any]
    traces: list[dict[str, Any]]
    """Per trace: name, path (relative to the report root), source, lemma, summary, frame files."""


def _read(path: Path) -> dict[str, Any] | None:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def cached_check(model: Model, cache: Path, traces: Path, refresh: bool) -> dict[str, Any]:
    """The model's check results (its own bounds), reused when the fingerprint matches."""
    fp = check_fingerprint(model)
    old = _read(cache)
    if old and old.get("fingerprint") == fp and not refresh:
        return old
    result = check(model)
    for stale in traces.glob(f"{model.name}-check-*.json"):
        stale.unlink()
    paths = write_witnesses(result, traces, f"{model.name}-check-")
    data = {"fingerprint": fp, **check_to_json(result, paths)}
    write_json(cache, data)
    return data


def cached_prove(model: Model, proofs: Path, slots: int, timeout: float, refresh: bool) -> dict[str, Any]:
    """The model's prover results (``proofs/MODEL/results.json``), reused when the fingerprint matches."""
    fp = prove_fingerprint(model, slots, timeout)
    cache = proofs / "results.json"
    old = _read(cache)
    if old and old.get("fingerprint") == fp and not refresh:
        return old
    for stale in [*proofs.glob("*/*.smt2"), *proofs.glob("traces/*.json")]:
        stale.unlink()
    results = prove(model, slots=slots, timeout=timeout, out=proofs)
    paths = prover.write_witnesses(model, results, proofs / "traces")
    data = {"fingerprint": fp, **results_json(model, results, paths)}
    write_json(cache, data)
    return data


def build_report(
    models: list[Model],
    out: Path,
    *,
    proofs: Path = Path("proofs"),
    slots: int = 3,
    timeout: float = 10.0,
    refresh: bool = False,
    progress: Callable[[str], None] | None = None,
) -> list[ModelReport]:
    """Write every model's pages, the corpus and the cross-model pages under ``out``."""
    corpus = out / "traces"
    reports = []
    for model in models:
        if progress:
            progress(f"{model.name}: check")
        check_data = cached_check(model, out / model.name / "check.json", corpus, refresh)
        if progress:
            progress(f"{model.name}: prove")
        prove_data = cached_prove(model, proofs / model.name, slots, timeout, refresh)
        if progress:
            progress(f"{model.name}: pictures")
        traces = _collect(model, out, check_data, prove_data)
        report = ModelReport(model, check_data, prove_data, traces)
        (out / model.name / "README.md").write_text(model_markdown(report), encoding="utf-8")
        (out / model.name / "index.html").write_text(model_html(report), encoding="utf-8")
        reports.append(report)
    for name, text in ASSETS.items():
        (out / name).write_text(text, encoding="utf-8")
    (out / "README.md").write_text(cross_model_markdown(reports), encoding="utf-8")
    (out / "index.html").write_text(cross_model_html(reports), encoding="utf-8")
    return reports


def _collect(model: Model, out: Path, check_data: dict[str, Any], prove_data: dict[str, Any]) -> list[dict[str, Any]]:
    """Copy every trace into the corpus (stable names), replay it, draw its frames."""
    corpus, img = out / "traces", out / model.name / "img"
    if img.exists():
        shutil.rmtree(img)
    img.mkdir(parents=True)
    found = []
    for row in check_data["lemmas"]:
        if row.get("trace"):
            found.append(("check", row["lemma"], f"{row['robots']} robots", row["verdict"], row["trace"]))
    for row in prove_data["obligations"]:
        if row.get("trace"):
            found.append(("prove", row["lemma"], f"{row['form']} {row['rule']}", row["verdict"], row["trace"]))
    keep = {Path(path).name for *_, path in found}
    for stale in [*corpus.glob(f"{model.name}-check-*.json"), *corpus.glob(f"{model.name}-prove-*.json")]:
        if stale.name not in keep:
            stale.unlink()
    traces = []
    for source, lemma, what, verdict, path in found:
        src = Path(path)
        name = src.name
        target = corpus / name
        if src.resolve() != target.resolve():
            corpus.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, target)
        doc = load_trace(target)
        run = check_replay(doc, model)
        files = []
        for k, svg in enumerate(frames(run, doc)):
            file = img / f"{target.stem}-{k}.svg"
            file.write_text(svg, encoding="utf-8")
            files.append(f"img/{file.name}")
        traces.append(
            {
                "name": target.stem,
                "path": f"../traces/{name}",
                "source": source,
                "lemma": lemma,
                "what": what,
                "verdict": verdict,
                "frames": files,
                "doc": doc,
            }
        )
    return traces
