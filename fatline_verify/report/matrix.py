"""The cross-model pages: the readings x lemmas matrix (worst check verdict, lemma-level prover verdict)
in Markdown and HTML, and a card per model with the counterexample it is featured by. The matrix fits a
1400 px window.
"""

from __future__ import annotations

import html
import json
import re
from typing import Any

from ..lemmas.properties import CHECKED
from ..model.config import shipped_models
from ..model.options import Scheduler
from ..prove.basis import counts_text
from ..text import READINGS_DOC
from .data import ModelReport
from .parts import (
    NOT_CLAIMED,
    PROVER_LEMMAS,
    ROWS,
    claims,
    html_page,
    lemma_summary,
    md_table,
    model_lemma_verdicts,
    prover_counts,
    readings_html,
    readings_text,
    viewer,
    worst_of,
    worst_text,
)
from .places import Places, explain


def _matrix(reports: list[ModelReport]) -> tuple[list[str], list[list[str]]]:
    headers = (
        ["model", "readings"]
        + [f"{lemma.value} (check)" for lemma in CHECKED]
        + [f"{lemma.value} (prove)" for lemma in PROVER_LEMMAS]
    )
    rows = []
    for r in reports:
        row = [r.model.name, readings_text(r)]
        row += [
            worst_text(r.check["lemmas"], lemma.value) if claims(r, lemma.value) else NOT_CLAIMED for lemma in CHECKED
        ]
        row += [lemma_summary(r, lemma.value) for lemma in PROVER_LEMMAS]
        rows.append(row)
    return headers, rows


def rule_sets(reports: list[ModelReport]) -> str:
    """The rule sets of the matrix's models, named (the paper's as the paper's)."""
    names = sorted({r.model.rules for r in reports})
    words = [f"`{name}`" + (" (the paper's rules)" if name == "paper" else "") for name in names]
    return ", ".join(words) or "none"


def intro(reports: list[ModelReport]) -> str:
    """The matrix's first sentence names the rule sets it holds; then what the cells mean."""
    word = "rule set" if len({r.model.rules for r in reports}) == 1 else "rule sets"
    return f"Which reading of which rule set breaks which lemma ({word}: {rule_sets(reports)}). {INTRO}"


INTRO = (
    "*check*: the bounded model checker at each model's bounds "
    "(worst verdict over the robot counts, with the smallest swarm that shows it). "
    "*prove*: the lemma-level verdict from z3 obligations per decision case of the rules (a repaired model: per "
    "pair of leg classes): PROVED (for every swarm size) only when the forms that together imply the lemma are all "
    "PROVED, VIOLATED only by a replayed counterexample of the lemma itself, else NOT PROVED or NOT ENCODED "
    "(approach, a liveness lemma, has no obligation of its own; progress and termination are judged from the "
    "liveness obligations, enabledness per decision case and a ranking measure, where a rule set declares them: "
    "an empty cell claims nothing); then its obligation rows counted by verdict (one row per obligation: "
    "*lemma NOT PROVED; obligation rows: 25 PROVED* is a lemma not proved although each of its 25 rows is: "
    "those rows are not all the forms that together imply it), safety rows' PROVED split into "
    "substantive, immediate (true by the rule's construction) and vacuous (the case never fires). "
    "HOLDS_WITHIN_BOUNDS reads *HOLDS within bounds* in the HTML matrix. "
    "Every VIOLATED verdict has a counterexample trace in `traces/` that `fatline replay` reproduces. "
    f"*{NOT_CLAIMED}*: a lemma the model's rule set does not claim (`RuleSet(lemmas=...)`), neither judged nor proved."
)


def _places(reports: list[ModelReport]) -> Places:
    """Where the report was written (every model's report says the same)."""
    return reports[0].places if reports else Places()


def _all_shipped(reports: list[ModelReport]) -> bool:
    """Whether every model of the matrix is a shipped one, named by its name (``fatline report`` with no
    model writes them all again)."""
    shipped = {p.stem for p in shipped_models()}
    return all(r.model.name in shipped and r.model.ref == r.model.name for r in reports)


def regenerate_text(reports: list[ModelReport]) -> str:
    """How the cross-model pages are written again, as Markdown: every shipped model's command, or each
    model's own command on its page (rows of models not asked for are kept)."""
    places = _places(reports)
    if reports and _all_shipped(reports):
        return f"Regenerate everything: `{places.regenerate()}` (every shipped model).{places.where()}"
    return "Regenerate a model's row: the command on its page (the other models' rows are kept)."


def readings_text_line(reports: list[ModelReport], root: str = "") -> str:
    """Where each reading's meaning is found, as Markdown: the catalogue where the report has one beside
    it, else ``fatline explain``."""
    link = _places(reports).readings(root)
    if link is not None:
        return f"What each reading (`option=reading`) means: [{READINGS_DOC}]({link})."
    return f"What each reading (`option=reading`) and parameter means: `{explain()}` (every one there is)."


def cross_model_markdown(reports: list[ModelReport]) -> str:
    headers, rows = _matrix(reports)
    rows = [[f"[{r[0]}]({r[0]}/README.md)", *r[1:]] for r in rows]
    lines = ["# fatline-verify reports", "", intro(reports), "", *md_table(headers, rows), ""]
    notes = _not_run_markdown(reports)
    lines += [*notes, ""] if notes else []
    lines += [readings_text_line(reports), ""]
    lines += [regenerate_text(reports), ""]
    return "\n".join(lines)


CHECK_TITLE = "bounded model checker: worst verdict over the robot counts, with the smallest swarm that shows it"
PROVE_TITLE = (
    "prover: the lemma-level verdict from the obligation forms that together imply the lemma, then the "
    "obligations counted by verdict (PROVED: substantive, immediate, vacuous)"
)


def _verdict_html(verdict: str) -> str:
    """A verdict on at most two lines that never break inside a word: ``HOLDS_WITHIN_BOUNDS`` (wider than a
    column, and it wrapped onto three lines at its underscores) is "HOLDS" over "within bounds", the full
    name on hover."""
    if verdict == "HOLDS_WITHIN_BOUNDS":
        return f'<span class="nowrap" title="{verdict}">HOLDS</span><br><span class="rows">within bounds</span>'
    return f'<span class="nowrap">{html.escape(verdict)}</span>'


ROWS_HTML = f'<span class="rows">{ROWS}:</span>'
"""Above a prover cell's counts: they count obligation rows, not the lemma."""


NOT_CLAIMED_HTML = f'<td class="notencoded" title="the rule set does not claim this lemma">{NOT_CLAIMED}</td>'
"""A cell of a lemma the model's rule set does not claim."""


def _check_cell(report: ModelReport, lemma: str) -> str:
    if not claims(report, lemma):
        return NOT_CLAIMED_HTML
    worst = worst_of(report.check["lemmas"], lemma)
    if worst is None:
        return "<td></td>"
    verdict, robots = worst
    swarm = f'<br><span class="robots">{robots} robots</span>' if verdict == "VIOLATED" else ""
    return f'<td class="{html.escape(verdict)}">{_verdict_html(verdict)}{swarm}</td>'


LEMMA_CLASS = {"PROVED": "PROVED", "VIOLATED": "VIOLATED", "NOT PROVED": "INCONCLUSIVE", "NOT ENCODED": "notencoded"}
"""The colour of a lemma-level verdict's cell (the per-row verdicts' classes)."""


def _prove_cell(report: ModelReport, lemma: str) -> str:
    if not claims(report, lemma):
        return NOT_CLAIMED_HTML
    v = model_lemma_verdicts(report).get(lemma)
    if v is None or not report.prove.get("obligations"):  # no prover run: no claim
        return "<td></td>"
    if not v.rows:  # NOT ENCODED: no obligation to count
        title = html.escape(f"{v.verdict}: {v.why}")
        verdict = html.escape(v.verdict)
        return f'<td class="{LEMMA_CLASS[v.verdict]}" title="{title}"><strong>lemma {verdict}</strong></td>'
    rows = [r for r in report.prove["obligations"] if r["lemma"] == lemma]
    split = f" ({html.escape(counts_text(rows))})" if any(r.get("basis") for r in rows) else ""
    counts = prover_counts(rows, lemma)
    lines = "<br>".join(f"{n}&nbsp;{_verdict_html(k)}" + (split if k == "PROVED" else "") for k, n in counts)
    title = html.escape(f"{v.verdict}: {v.why}. Obligations: {v.counts}")
    return (
        f'<td class="{LEMMA_CLASS[v.verdict]}" title="{title}"><strong>lemma {html.escape(v.verdict)}</strong><br>'
        f"{ROWS_HTML}<br>{lines}</td>"
    )


def _matrix_html(reports: list[ModelReport]) -> str:
    """The readings x lemmas matrix: grouped headers, a compact readings column, verdicts that wrap."""
    check, prove = len(CHECKED), len(PROVER_LEMMAS)
    head = (
        '<tr><th rowspan="2">model</th><th rowspan="2">readings</th>'
        f'<th class="group" colspan="{check}" title="{html.escape(CHECK_TITLE)}">check (bounded model checker)</th>'
        f'<th class="group" colspan="{prove}" title="{html.escape(PROVE_TITLE)}">prove (z3, per rule)</th></tr><tr>'
        + "".join(f'<th title="{html.escape(CHECK_TITLE)}">{html.escape(lemma.value)}</th>' for lemma in CHECKED)
        + "".join(f'<th title="{html.escape(PROVE_TITLE)}">{html.escape(lemma.value)}</th>' for lemma in PROVER_LEMMAS)
        + "</tr>"
    )
    body = []
    for r in reports:
        name = html.escape(r.model.name)
        cells = [f'<td class="model"><a href="{name}/index.html">{name}</a></td>']
        cells.append(f'<td class="readings">{readings_html(r, "", sep="<br>")}</td>')
        cells += [_check_cell(r, lemma.value) for lemma in CHECKED]
        not_run = _not_run(r)
        if not_run:
            title = html.escape(str(r.prove["not_encoded"]))
            cells.append(f'<td class="notrun" colspan="{prove}" title="{title}">{html.escape(not_run)}</td>')
        else:
            cells += [_prove_cell(r, lemma.value) for lemma in PROVER_LEMMAS]
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f'<table class="matrix">{head}{"".join(body)}</table>'


def _not_run(report: ModelReport) -> str:
    """Why a model's prover cells are empty (the prover refuses it), in a few words; "" if they are not."""
    if not report.prove.get("not_encoded"):
        return ""
    if report.model.options.scheduler is Scheduler.ASYNC:
        return "not run: the prover encodes round schedulers only (an asynchronous robot may act on a stale view)"
    return "not run: the prover has no encoding of this model (its page says why)"


def _not_run_markdown(reports: list[ModelReport]) -> list[str]:
    """Below the Markdown matrix: why a model's prover cells are empty."""
    return [f"{r.model.name}: no prover cells, {_not_run(r)}." for r in reports if _not_run(r)]


LEMMA_ORDER = {lemma.value: k for k, lemma in enumerate(CHECKED)}


def _smallest_first(t: dict[str, Any]) -> tuple[int, int, int, str]:
    """Fewest robots, then fewest rounds, then the matrix's lemma order."""
    doc = t["doc"]
    return len(doc["initial"]), len(doc["rounds"]), LEMMA_ORDER.get(t["lemma"], len(LEMMA_ORDER)), t["name"]


def _run_of(t: dict[str, Any]) -> str:
    """What a trace's pictures show: the start, every round, the end (not the model's name)."""
    doc = t["doc"]
    return json.dumps([doc["initial"], doc["rounds"], doc["outcome"]])


def _pick(report: ModelReport, shown: set[str]) -> tuple[dict[str, Any] | None, str]:
    """The model's own counterexample for its card, and why it is that one."""
    checked = sorted((t for t in report.traces if t["source"] == "check"), key=_smallest_first)
    pool, what = (
        (checked, "check witness") if checked else (sorted(report.traces, key=_smallest_first), "prover counterexample")
    )
    if not pool:
        return None, "no counterexample: every lemma holds within the bounds or is inconclusive"
    fresh = [t for t in pool if _run_of(t) not in shown]
    why = f"its smallest {what} (fewest robots, then fewest rounds)"
    if not fresh:
        return pool[0], why + "; a run also shown above"
    return fresh[0], why + (" whose run no model above shows" if fresh[0] is not pool[0] else "")


def featured(reports: list[ModelReport]) -> list[tuple[ModelReport, dict[str, Any] | None, str]]:
    """Per model, the counterexample its card shows and why: its own smallest check witness (a
    prover counterexample when the checker found none), skipping runs a card above already shows —
    several models share the smallest runs, and a card repeating one would say nothing new."""
    shown: set[str] = set()
    out: list[tuple[ModelReport, dict[str, Any] | None, str]] = []
    for r in reports:
        pick, why = _pick(r, shown)
        if pick is not None:
            shown.add(_run_of(pick))
        out.append((r, pick, why))
    return out


def _card(report: ModelReport, trace: dict[str, Any] | None, why: str) -> str:
    name = html.escape(report.model.name)
    head = (
        f'<div class="card" id="card-{name}"><h3>Model <a href="{name}/index.html">{name}</a></h3>'
        f"<p>Readings: {readings_html(report, '')}. Shown: {html.escape(why)}.</p>"
    )
    return head + (viewer(trace, prefix=f"{report.model.name}/", places=report.places) if trace else "") + "</div>"


def markdown_html(text: str) -> str:
    """One line of this module's Markdown as HTML: `code` and [text](link), the rest escaped."""
    out = html.escape(text.replace("*", ""))
    out = re.sub(r"\[([^\]]+)\]\(([^)]+)\)", r'<a href="\2">\1</a>', out)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", out)


def cross_model_html(reports: list[ModelReport]) -> str:
    head = html.escape(intro(reports).replace("*", "").replace("`", ""))
    docs = f"<p>{markdown_html(readings_text_line(reports))}</p><p>{markdown_html(regenerate_text(reports))}</p>"
    cards = "\n".join(_card(r, t, why) for r, t, why in featured(reports))
    body = (
        f"<h1>fatline-verify reports</h1><p>{head}</p>{_matrix_html(reports)}{docs}"
        f"<h2>A counterexample per model</h2>{cards}"
    )
    return html_page("fatline-verify reports", body, "", wide=True)


__all__ = [
    "CHECK_TITLE",
    "INTRO",
    "LEMMA_CLASS",
    "LEMMA_ORDER",
    "PROVE_TITLE",
    "cross_model_html",
    "cross_model_markdown",
    "featured",
    "intro",
    "markdown_html",
    "readings_text_line",
    "regenerate_text",
    "rule_sets",
]
