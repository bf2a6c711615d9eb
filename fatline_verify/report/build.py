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

Nothing cached is shown without being checked first, before any work: a cache's digest
(:mod:`fatline_verify.integrity`; a cache written before digests has none, and gets one when it is next
recomputed), its rows' fields, and the evidence beside it: every trace a row names is read only if it
is a regular file, parsed and replayed before it is copied into the corpus (atomically: a link in the
corpus is refused, never followed), a VIOLATED row needs a trace that replays a violation of its
lemma, and a HOLDS_WITHIN_BOUNDS row may not stand beside a corpus witness of the same lemma, robot
count and bounds that replays. Paths a cache records are found relative to the cache
(:func:`~fatline_verify.outputs.resolve_recorded`), so a report or proofs directory can be copied and
reported from anywhere.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..check.checker import check, check_fingerprint, check_to_json, write_witnesses
from ..errors import FatlineError, InvalidInput, InvalidTrace, OutputFailed, TraceDidNotReproduce
from ..integrity import seal, sealed
from ..lemmas.registry import checked as checked_lemmas
from ..model.config import Model, load_model, model_from_mapping, model_to_mapping, shipped_models
from ..outputs import (
    FILE_NAME,
    TEXT_MARKER,
    Kind,
    NotReadable,
    child,
    claim_dir,
    claim_files,
    is_output,
    load_json,
    parse_json,
    read_regular,
    resolve_recorded,
    write_bytes,
    write_json,
    write_text,
)
from ..prove.prover import DEFAULT_SLOTS, DEFAULT_TIMEOUT, NotEncodedModel, prove, task_key, tasks_for
from ..prove.results import ProofResults, stale_view
from ..prove.tasks import CoverageSpec, row_key
from ..trace.traces import check_replay, load_trace, validate
from .against_pages import against_entries
from .data import ModelReport
from .pages import ASSETS, PROVER_LEMMAS, cross_model_html, cross_model_markdown, model_html, model_markdown
from .pictures import frames
from .places import Places

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
    claim_corpus(out, force)


def claim_corpus(out: Path, force: bool) -> None:
    """The corpus ``OUT/traces`` holds the traces fatline wrote and nothing else a copy could overwrite:
    no link (a copy never follows one out of the directory, and one there was not put by fatline), and
    no JSON file that is not a fatline trace (unless ``force``)."""
    corpus = out / "traces"
    if corpus.is_symlink():
        raise InvalidInput(f"out={str(out)!r}: traces is a link; expected the corpus directory fatline writes")
    if not corpus.is_dir():
        return
    for entry in sorted(corpus.iterdir()):
        shown = f"out={str(out)!r}: traces/{entry.name}"
        if entry.is_symlink():
            raise InvalidInput(
                f"{shown} is a link; expected the corpus to hold the traces fatline wrote, never a link (move it away)"
            )
        if entry.suffix == ".json" and not force and not is_output(entry, Kind.TRACE):
            raise InvalidInput(f"{shown} is not a fatline trace; expected it moved away (or --force to overwrite it)")


def read_check_cache(cache: Path) -> dict[str, Any] | None:
    """A model's cached check results (``None``: none, or a file of another kind that ``claim`` let
    through with ``force``): its digest checked, its rows of the fields the report reads (a row's
    lemma one of the paper's or a registered one)."""
    if not cache.is_file() or not is_output(cache, Kind.CHECK):
        return None
    where = cache.as_posix()
    data = load_json(cache, what=where, expected="the check.json fatline report wrote")
    sealed(data, cache)
    lemmas, searches, model = data.get("lemmas"), data.get("searches"), data.get("model")
    if not isinstance(lemmas, list) or not isinstance(searches, list) or not isinstance(model, dict):
        raise InvalidInput(f"{where}: lemmas, searches or model malformed; expected the file fatline report wrote")
    if not all(isinstance(row, dict) for row in searches):
        raise InvalidInput(f"{where}: searches: expected a list of objects")
    window = data.get("window")
    if not (isinstance(window, list) and len(window) == 2 and all(type(v) is int for v in window)):
        raise InvalidInput(f"{where}: window={str(window)[:40]!r}: expected [width, height]")
    names = {lemma.value for lemma in checked_lemmas()}  # the plug-ins' step lemmas too
    for k, row in enumerate(lemmas):
        at = f"{where}: lemmas[{k}]"
        if not isinstance(row, dict):
            raise InvalidInput(f"{at}={str(row)[:40]!r}: expected a row (an object)")
        checks = (
            ("lemma", row.get("lemma") in names, f"one of {', '.join(sorted(names))}"),
            ("robots", type(row.get("robots")) is int, "a robot count"),
            ("verdict", row.get("verdict") in ("VIOLATED", "HOLDS_WITHIN_BOUNDS", "INCONCLUSIVE"), "a verdict"),
            ("reason", isinstance(row.get("reason"), str), "text"),
            ("witness_rounds", row.get("witness_rounds") is None or type(row.get("witness_rounds")) is int, "a count"),
            ("trace", row.get("trace") is None or isinstance(row.get("trace"), str), "a trace file or null"),
        )
        for name, ok, what in checks:
            if not ok:
                raise InvalidInput(f"{at}.{name}={str(row.get(name))[:40]!r}: expected {what}")
        if row["verdict"] == "VIOLATED" and not row.get("trace"):
            raise OutputFailed(f"{where}: {row['lemma']} with {row['robots']} robots is VIOLATED without a trace")
    return data


def contradicted_holds(model: Model, data: dict[str, Any], corpus: Path, cache: Path) -> None:
    """Refuse a HOLDS_WITHIN_BOUNDS row beside a witness of the same claim that replays: the corpus trace
    the checker wrote for that lemma and robot count, found at the same window and bound."""
    for row in data["lemmas"]:
        if row["verdict"] != "HOLDS_WITHIN_BOUNDS":
            continue
        path = corpus / f"{model.name}-check-{row['lemma']}-n{row['robots']}.json"
        if path.is_symlink() or not path.is_file() or not is_output(path, Kind.TRACE):
            continue
        try:
            doc = load_trace(path)
            origin = doc.get("origin") or {}
            same = (
                origin.get("tool") == "fatline check"
                and origin.get("robots") == row["robots"]
                and origin.get("window") == data["window"]
                and origin.get("bound") == data.get("bound")
                and (doc.get("violation") or {}).get("property") == row["lemma"]
            )
            if same:
                check_replay(doc, model)
        except (InvalidTrace, TraceDidNotReproduce):
            continue  # not a witness under this model (its readings changed): nothing contradicted
        if same:
            raise OutputFailed(
                f"{cache.as_posix()}: {row['lemma']} with {row['robots']} robots is HOLDS_WITHIN_BOUNDS, but "
                f"{path.as_posix()} replays a violation of it at the same bounds; expected the file as fatline report "
                "wrote it (move it away to recompute it)"
            )


def cached_check(model: Model, cache: Path, traces: Path, refresh: bool) -> dict[str, Any]:
    """The model's check results (its own bounds), reused when the fingerprint matches."""
    fp = check_fingerprint(model)
    old = read_check_cache(cache)
    if old and old.get("fingerprint") == fp and not refresh:
        return old
    result = check(model)
    paths = write_witnesses(result, traces, f"{model.name}-check-")
    data = seal({"fingerprint": fp, **check_to_json(result, paths)})
    write_json(cache, data)
    return data


REPORTED = PROVER_LEMMAS
"""The prover's lemmas a report shows and computes: every lemma with obligations, the liveness ones
(progress: enabledness per decision case; termination: the ranking measure) included."""


def cached_prove(model: Model, proofs: Path, slots: int, timeout: float, refresh: bool) -> dict[str, Any]:
    """The model's prover results (``proofs/MODEL/results.json``): up-to-date rows are reused, the
    others recomputed and merged in; rows of other settings or obligations are kept."""
    refused = _refusal(model, proofs, slots, timeout)
    if refused is not None:
        return refused
    store = ProofResults(model, proofs, proofs / "traces", slots=slots, timeout=timeout)
    tasks = tasks_for(model, REPORTED)
    todo = tasks if refresh else [t for t in tasks if store.fresh(t) is None]
    # the liveness cases' coverage is its own step (fatline prove --coverage, minutes at q = 1): a report shows
    # the row an explicit run left, never recomputes it (a report reads what the prover wrote)
    todo = [t for t in todo if not isinstance(t, CoverageSpec)]
    if todo:
        prove(model, slots=slots, timeout=timeout, out=proofs, tasks=todo, on_result=store.add)
    keys = [task_key(t) for t in tasks]
    return {**store.document(keys), "obligations": store.shown(keys)}  # a row left stale (coverage) reads STALE


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
    for model in models:  # every cache read back is checked before any work
        cache = child(out, model.name) / "check.json"
        saved = read_check_cache(cache)
        if saved is not None:
            contradicted_holds(model, saved, corpus, cache)
        if _refusal(model, child(proofs, model.name), slots, timeout) is None:
            here = child(proofs, model.name)
            ProofResults(model, here, here / "traces", slots=slots, timeout=timeout)  # digest, rows, evidence
    places = Places.of(out, proofs)
    earlier = _earlier(models, out, proofs, places)
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
        traces = _collect(model, out, check_data, prove_data, draw=True, proofs=child(proofs, model.name))
        against = against_entries(model, out, _write_page)
        report = ModelReport(model, check_data, prove_data, traces, against, places)
        _write_page(out / model.name / "README.md", model_markdown(report))
        _write_page(out / model.name / "index.html", model_html(report))
        reports.append(report)
    everyone = sorted([*reports, *earlier], key=lambda r: r.model.name)
    for name, text in ASSETS.items():
        _write_page(out / name, text)
    _write_page(out / "README.md", cross_model_markdown(everyone))
    _write_page(out / "index.html", cross_model_html(everyone))
    return everyone


def _earlier(models: list[Model], out: Path, proofs: Path, places: Places | None = None) -> list[ModelReport]:
    """The models reported under ``out`` before and not recomputed now, from their cached results (each
    checked as the asked models' are: a cache or results file changed since it was written, or a verdict
    its evidence contradicts, is refused; one that cannot be read at all is left out of the matrix)."""
    asked = {m.name for m in models}
    places = places or Places.of(out, proofs)
    found = []
    for cache in sorted(out.glob("*/check.json")):
        name = cache.parent.name
        if name in asked or not is_output(cache, Kind.CHECK):
            continue
        try:
            check_data = read_check_cache(cache)
            assert check_data is not None
            model = _model_of(check_data["model"])
            contradicted_holds(model, check_data, out / "traces", cache)
            prove_data = _saved_prove(model, proofs / name)
            if prove_data is None:
                continue
            traces = _collect(model, out, check_data, prove_data, draw=False, proofs=proofs / name)
        except OutputFailed:
            raise  # changed since it was written, or contradicted by its evidence: never shown
        except (FatlineError, KeyError, OSError):
            continue  # an unreadable earlier report is left as it is, not shown in the matrix
        found.append(ModelReport(model, check_data, prove_data, traces, places=places))
    return found


def _saved_prove(model: Model, proofs: Path) -> dict[str, Any] | None:
    """An earlier model's saved prover results; for a scheduler the prover refuses, the refusal (there
    is nothing to save); ``None`` if neither."""
    path = proofs / "results.json"
    if is_output(path, Kind.PROVE):
        store = ProofResults(model, proofs, proofs / "traces", slots=DEFAULT_SLOTS, timeout=DEFAULT_TIMEOUT)
        doc = load_json(path, what=path.as_posix(), expected="the results.json fatline prove wrote")
        shown = {str(lemma) for lemma in REPORTED}  # as cached_prove: the report's lemmas only
        stale = set(store.stale())  # a stale row reads STALE
        rows = [stale_view(r, model.name) if row_key(r) in stale else r for r in doc.get("obligations", [])]
        return {**doc, "obligations": [r for r in rows if r.get("lemma") in shown]}
    return _refusal(model, proofs, DEFAULT_SLOTS, DEFAULT_TIMEOUT)


def _refusal(model: Model, proofs: Path, slots: int, timeout: float) -> dict[str, Any] | None:
    """For a scheduler the prover does not encode, the prover results document saying so; else ``None``."""
    try:
        tasks_for(model, REPORTED)
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
    model: Model, out: Path, check_data: dict[str, Any], prove_data: dict[str, Any], *, draw: bool, proofs: Path
) -> list[dict[str, Any]]:
    """Replay every trace the rows name and (if ``draw``) copy it into the corpus (stable names) and draw
    its frames. A check row's trace is the corpus's own; a prover row's is found relative to its
    results file (``proofs``: ``PROOFS/MODEL``). Each is read (a regular file only), checked and
    replayed before it is copied, and a VIOLATED row's must show a violation of its lemma."""
    corpus, img = out / "traces", out / model.name / "img"
    found = []
    for row in check_data["lemmas"]:
        if row.get("trace"):
            name = Path(row["trace"]).name
            src = corpus / name if FILE_NAME.match(name) else None
            found.append(("check", row, f"{row['robots']} robots", src, out / model.name / "check.json"))
    for row in prove_data["obligations"]:
        if row.get("trace"):
            src = resolve_recorded(row["trace"], proofs)
            found.append(("prove", row, f"{row['form']} {row['rule']}", src, proofs / "results.json"))
    checked = []
    for source, row, what, src, where in found:  # every trace checked before anything is written
        if src is None or not src.is_file() or not FILE_NAME.match(src.name):
            raise InvalidInput(
                f"{where.as_posix()}: {row['lemma']} ({what}): trace={str(row['trace'])[:200]!r}: no such file; "
                "expected the trace fatline wrote beside it"
            )
        data, doc = _read_trace(src)
        run = check_replay(doc, model)
        shown = (doc.get("violation") or {}).get("property", "")
        if row["verdict"] == "VIOLATED" and not (shown == row["lemma"] or shown.startswith(f"{row['lemma']}-")):
            raise OutputFailed(
                f"{where.as_posix()}: {row['lemma']} ({what}) is VIOLATED, but its trace {src.as_posix()} replays "
                f"{f'a violation of {shown}' if shown else 'no violation'}; expected the files as fatline wrote them"
            )
        checked.append((source, row, what, src, data, doc, run))
    if draw:
        for old in img.glob("*.svg"):  # pictures of an earlier run: ours only
            if is_output(old, Kind.PAGE):
                old.unlink()
    traces = []
    for source, row, what, src, data, doc, run in checked:
        target = corpus / src.name
        if draw and src.resolve() != target.resolve():
            write_bytes(target, data)  # atomic: a link at target would be replaced, never written through
        if draw:
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
                "lemma": row["lemma"],
                "what": what,
                "verdict": row["verdict"],
                "frames": files,
                "doc": doc,
            }
        )
    return traces


def _read_trace(path: Path) -> tuple[bytes, dict[str, Any]]:
    """A trace file's bytes (a regular file only) and its schema-checked document."""
    try:
        data = read_regular(path)
        doc = parse_json(data)
    except (NotReadable, ValueError) as exc:
        raise InvalidTrace(f"trace={path.as_posix()!r}: {exc}; expected a trace JSON file") from None
    validate(doc, where=path.as_posix())
    return data, doc
