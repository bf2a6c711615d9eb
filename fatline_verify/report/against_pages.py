"""A repaired model's page: the regression corpus replayed under it, beside the counterexamples.

Each counterexample of another model (``reports/traces/``) and what the model does from its initial
configuration (:mod:`fatline_verify.repair.against`); for the first counterexample of each model and lemma,
two pictures side by side: the last round of the counterexample, and the same activations under
this model.
"""

from __future__ import annotations

import html
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..model.config import Model
from ..repair.against import Against, corpus_against, its_rounds
from ..trace.traces import load_trace, replayed_document
from .pictures import frame_svg

HEAD = ["counterexample", "breaks", "lemma", "robots", "rounds", "under this model", "detail"]
GONE = ("HOLDS_WITHIN_BOUNDS", "GONE ON ITS ROUNDS")


def against_entries(model: Model, out: Path, write: Callable[[Path, str], None] | None) -> list[dict[str, Any]]:
    """The corpus under ``model`` (a repaired model only), with the side-by-side pictures (drawn when
    ``write`` is given, else only named)."""
    if not model.options.repaired:
        return []
    rows = corpus_against(model, out / "traces")
    shown: set[tuple[str, str]] = set()
    entries = []
    for row in rows:
        entry: dict[str, Any] = {"row": row, "left": "", "right": ""}
        stem = Path(row.trace).stem
        if (row.source, row.lemma) not in shown and row.rounds:
            left = out / row.source / "img" / f"{stem}-{row.rounds - 1}.svg"
            doc = load_trace(out / "traces" / row.trace)
            run = its_rounds(doc, model)
            if left.is_file() and run is not None and run.rounds:
                shown.add((row.source, row.lemma))
                right = out / model.name / "img" / f"against-{stem}.svg"
                if write is not None:
                    origin = {"tool": "fatline report", "lemma": row.lemma, "against": row.trace}
                    write(right, frame_svg(run, len(run.rounds), replayed_document(run, origin, row.lemma)))
                entry.update(left=f"../{row.source}/img/{left.name}", right=f"img/{right.name}")
        entries.append(entry)
    return entries


def _line(entries: list[dict[str, Any]]) -> str:
    verdicts = Counter(e["row"].verdict for e in entries)
    total = len(entries)
    counts = ", ".join(f"{n} {v}" for v, n in sorted(verdicts.items()))
    return (
        f"{total} counterexamples of the other models, each from its own initial configuration under its own "
        f"scheduler: {counts}. HOLDS_WITHIN_BOUNDS: the checker explored every activation from that configuration "
        "(not only the counterexample's); GONE ON ITS ROUNDS: the checker cannot hold the configuration (on no "
        "lattice up to q = 20, or its bound beyond the state keys), so the counterexample's own rounds were replayed "
        "exactly; INCONCLUSIVE: said why in the row. Collision and connectivity are also PROVED for every swarm "
        "(the prover's table above), so no counterexample of them exists under this model at all. The liveness "
        "lemmas still fail under this model from other configurations (the checker's table above)."
    )


def _cells(row: Against) -> list[str]:
    return [Path(row.trace).stem, row.source, row.lemma, str(row.robots), str(row.rounds), row.verdict, row.reason]


def against_markdown(entries: list[dict[str, Any]]) -> list[str]:
    if not entries:
        return []
    lines = ["## The corpus under this model", "", _line(entries), ""]
    lines += ["| " + " | ".join(HEAD) + " |", "|" + "---|" * len(HEAD)]
    lines += ["| " + " | ".join(c.replace("|", "\\|") for c in _cells(e["row"])) + " |" for e in entries]
    lines.append("")
    for e in entries:
        if e["right"]:
            row = e["row"]
            lines += [
                f"**{Path(row.trace).stem}** ({row.source}, {row.lemma}): left, its last round; right, the same "
                f"activations under this model ({row.verdict}).",
                "",
                f"![counterexample]({e['left']}) ![under this model]({e['right']})",
                "",
            ]
    return lines


def against_html(entries: list[dict[str, Any]]) -> str:
    if not entries:
        return ""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in HEAD)
    body = []
    for e in entries:
        cells = _cells(e["row"])
        klass = "HOLDS_WITHIN_BOUNDS" if e["row"].verdict in GONE else "VIOLATED"
        tds = "".join(
            f'<td class="{klass}">{html.escape(c)}</td>' if i == 5 else f"<td>{html.escape(c)}</td>"
            for i, c in enumerate(cells)
        )
        body.append(f"<tr>{tds}</tr>")
    pairs = []
    for e in entries:
        if e["right"]:
            row = e["row"]
            pairs.append(
                f"<figure class='pair'><figcaption><strong>{html.escape(Path(row.trace).stem)}</strong> "
                f"({html.escape(row.source)}, {html.escape(row.lemma)}): left, its last round; right, the same "
                f"activations under this model ({html.escape(row.verdict)})</figcaption>"
                f"<img alt='the counterexample' src='{html.escape(e['left'])}' width='49%'>"
                f"<img alt='under this model' src='{html.escape(e['right'])}' width='49%'></figure>"
            )
    return (
        f"<h2>The corpus under this model</h2><p>{html.escape(_line(entries))}</p>"
        f"{''.join(pairs)}<table><tr>{head}</tr>{''.join(body)}</table>"
    )


__all__ = ["against_entries", "against_html", "against_markdown"]
