"""``fatline report``: per-model pages and the cross-model matrix, from cached or fresh results.

Results are cached as JSON with a fingerprint of what produced them (the model's readings,
parameters and bounds, the prover's settings, the tool's version). An up-to-date cache is reused,
so regenerating a report from committed results is byte-identical; a stale one is recomputed —
for the prover, only the obligations whose rows are stale.

Nothing is lost (docs/commands.md, "Outputs: nothing destroyed by default"): reporting one model keeps
every other model's row in the matrix; counterexample traces in the corpus ``reports/traces/`` are
never deleted (a trace a later run no longer finds still replays, and the corpus tests replay it);
a file the report did not write is not overwritten without ``force``. Every file written carries
:data:`~fatline_verify.outputs.TEXT_MARKER` or a JSON format marker.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..check.checker import check, check_fingerprint, check_to_json, write_witnesses
from ..errors import FatlineError
from ..model.config import Model, load_model, model_from_mapping, model_to_mapping, shipped_models
from ..outputs import TEXT_MARKER, Kind, child, claim_dir, claim_files, is_output, read_json, write_json, write_text
from ..prove.prover import DEFAULT_SLOTS, DEFAULT_TIMEOUT, NotEncodedModel, prove, task_key, tasks_for
from ..prove.results import ProofResults
from ..trace.traces import check_replay, load_trace
from .against_pages import against_entries
from .data import ModelReport
from .pages import ASSETS, cross_model_html, cross_model_markdown, model_html, model_markdown
from .pictures import frames

PAGES = ("README.md", "index.html")


def stamp(name: str, text: str, command: str = "fatline report") -> str:
    """``text`` with the generated-by marker (naming ``command``), in the comment syntax of the file's kind."""
    mark = f"{TEXT_MARKER}: {command}"
    if name.endswith(".svg"):
        head, sep, rest = text.partition("?>\n")
        return f"{head}{sep}<!-- {mark} -->\n{rest}" if sep else f"<!-- {mark} -->\n{text}"
    if name.endswith((".md", ".html")):
        return f"<!-- {mark} -->\n{text}"
    if name.endswith(".css"):
        return f"/* {mark} */\n{text}"
    return f"// {mark}\n{text}"


def _write_page(path: Path, text: str) -> None:
    write_text(path, stamp(path.name, text))


def planned_files(models: list[Model], out: Path) -> list[Path]:
    """The pages a report of ``models`` writes (checked for ownership before any work)."""
    files = [out / name for name in (*PAGES, *ASSETS)]
    for model in models:
        files += [child(out, model.name) / name for name in PAGES]
    return files


def claim(models: list[Model], out: Path, proofs: Path, force: bool) -> None:
    """Every output path of a report, checked before any work."""
    claim_dir(out, name="out")
    claim_dir(proofs, name="proofs")
    claim_files(planned_files(models, out), name="out", kind=Kind.PAGE, force=force)
    claim_files([child(out, m.name) / "check.json" for m in models], name="out", kind=Kind.CHECK, force=force)
    claim_files([child(proofs, m.name) / "results.json" for m in models], name="proofs", kind=Kind.PROVE, force=force)


def cached_check(model: Model, cache: Path, traces: Path, refresh: bool) -> dict[str, Any]:
    """The model's check results (its own bounds), reused when the fingerprint matches."""
    fp = check_fingerprint(model)
    old = read_json(cache)
    if old and old.get("fingerprint") == fp and not refresh:
        return old
    result = check(model)
    paths = write_witnesses(result, traces, f"{model.name}-check-")
    data = {"fingerprint": fp, **check_to_json(result, paths)}
    write_json(cache, data)
    return data


def cached_prove(model: Model, proofs: Path, slots: int, timeout: float, refresh: bool) -> dict[str, Any]:
    """The model's prover results (``proofs/MODEL/results.json``): up-to-date rows are reused, the
    others recomputed and merged in; rows of other settings or obligations are kept."""
    refused = _refusal(model, proofs, slots, timeout)
    if refused is not None:
        return refused
    store = ProofResults(model, proofs, proofs / "traces", slots=slots, timeout=timeout)
    tasks = tasks_for(model)
    todo = tasks if refresh else [t for t in tasks if store.fresh(t) is None]
    if todo:
        prove(model, slots=slots, timeout=timeout, out=proofs, tasks=todo, on_result=store.add)
    return store.document([task_key(t) for t in tasks])


def build_report(
    models: list[Model],
    out: Path,
    *,
    proofs: Path = Path("proofs"),
    slots: int = DEFAULT_SLOTS,
    timeout: float = DEFAULT_TIMEOUT,
    refresh: bool = False,
    force: bool = False,
    progress: Callable[[str], None] | None = None,
) -> list[ModelReport]:
    """Write every model's pages, the corpus and the cross-model pages under ``out``; return the
    reports of every model in the matrix (those asked for and those already reported there)."""
    claim(models, out, proofs, force)
    corpus = out / "traces"
    reports = []
    for model in models:
        if progress:
            progress(f"{model.name}: check")
        check_data = cached_check(model, child(out, model.name) / "check.json", corpus, refresh)
        if progress:
            progress(f"{model.name}: prove")
        prove_data = cached_prove(model, child(proofs, model.name), slots, timeout, refresh)
        if progress:
            progress(f"{model.name}: pictures")
        traces = _collect(model, out, check_data, prove_data, draw=True)
        against = against_entries(model, out, _write_page)
        report = ModelReport(model, check_data, prove_data, traces, against)
        _write_page(out / model.name / "README.md", model_markdown(report))
        _write_page(out / model.name / "index.html", model_html(report))
        reports.append(report)
    everyone = sorted([*reports, *_earlier(models, out, proofs)], key=lambda r: r.model.name)
    for name, text in ASSETS.items():
        _write_page(out / name, text)
    _write_page(out / "README.md", cross_model_markdown(everyone))
    _write_page(out / "index.html", cross_model_html(everyone))
    return everyone


def _earlier(models: list[Model], out: Path, proofs: Path) -> list[ModelReport]:
    """The models reported under ``out`` before and not recomputed now, from their cached results."""
    asked = {m.name for m in models}
    found = []
    for cache in sorted(out.glob("*/check.json")):
        name = cache.parent.name
        if name in asked or not is_output(cache, Kind.CHECK):
            continue
        check_data = read_json(cache)
        assert check_data is not None
        try:
            model = _model_of(check_data["model"])
            prove_data = _saved_prove(model, proofs / name)
            if prove_data is None:
                continue
            traces = _collect(model, out, check_data, prove_data, draw=False)
        except (FatlineError, KeyError, OSError):
            continue  # an unreadable earlier report is left as it is, not shown in the matrix
        found.append(ModelReport(model, check_data, prove_data, traces))
    return found


def _saved_prove(model: Model, proofs: Path) -> dict[str, Any] | None:
    """An earlier model's saved prover results; for a scheduler the prover refuses, the refusal (there
    is nothing to save); ``None`` if neither."""
    path = proofs / "results.json"
    if is_output(path, Kind.PROVE):
        return read_json(path)
    return _refusal(model, proofs, DEFAULT_SLOTS, DEFAULT_TIMEOUT)


def _refusal(model: Model, proofs: Path, slots: int, timeout: float) -> dict[str, Any] | None:
    """For a scheduler the prover does not encode, the prover results document saying so; else ``None``."""
    try:
        tasks_for(model)
    except NotEncodedModel as exc:
        store = ProofResults(model, proofs, proofs / "traces", slots=slots, timeout=timeout)
        return {**store.document([]), "not_encoded": str(exc)}
    return None


def _model_of(mapping: dict[str, Any]) -> Model:
    """A cached result's model: the shipped model of that name if it is the same, else the mapping."""
    for path in shipped_models():
        if path.stem == mapping.get("name"):
            shipped = load_model(path)
            if model_to_mapping(shipped) == mapping:
                return shipped
    return model_from_mapping(mapping, default_name=str(mapping.get("name")))


def _collect(
    model: Model, out: Path, check_data: dict[str, Any], prove_data: dict[str, Any], *, draw: bool
) -> list[dict[str, Any]]:
    """Copy every trace into the corpus (stable names), replay it and (if ``draw``) draw its frames."""
    corpus, img = out / "traces", out / model.name / "img"
    if draw:
        for old in img.glob("*.svg"):  # pictures of an earlier run: ours only
            if is_output(old, Kind.PAGE):
                old.unlink()
    found = []
    for row in check_data["lemmas"]:
        if row.get("trace"):
            found.append(("check", row["lemma"], f"{row['robots']} robots", row["verdict"], row["trace"]))
    for row in prove_data["obligations"]:
        if row.get("trace"):
            found.append(("prove", row["lemma"], f"{row['form']} {row['rule']}", row["verdict"], row["trace"]))
    traces = []
    for source, lemma, what, verdict, path in found:
        src = Path(path)
        target = corpus / src.name
        if draw and src.resolve() != target.resolve():
            corpus.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, target)
        doc = load_trace(target)
        if draw:
            run = check_replay(doc, model)
            files = []
            for k, svg in enumerate(frames(run, doc)):
                file = img / f"{target.stem}-{k}.svg"
                _write_page(file, svg)
                files.append(f"img/{file.name}")
        else:
            files = sorted(
                (f"img/{f.name}" for f in img.glob(f"{target.stem}-*.svg")),
                key=lambda f: int(f.rsplit("-", 1)[1].removesuffix(".svg")),
            )
        traces.append(
            {
                "name": target.stem,
                "path": f"../traces/{target.name}",
                "source": source,
                "lemma": lemma,
                "what": what,
                "verdict": verdict,
                "frames": files,
                "doc": doc,
            }
        )
    return traces
