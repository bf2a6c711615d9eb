"""The pieces every report page is made of: a lemma's worst verdict and its prover counts, a model's
readings (linked to the catalogue ``docs/readings.md``), numbers short with the exact value on hover,
tables, a trace's step-through viewer and the page around it with its assets (``viewer.js``,
``style.css``). Rendered from result data, never from strings of other pages.
"""

from __future__ import annotations

import html
import json
import re
from collections.abc import Callable
from typing import Any

from ..lemmas.properties import PROVED_LEMMAS
from ..model.config import IMPLIED
from ..model.options import CATALOGUE
from ..prove.coverage import LemmaVerdict, lemma_verdicts
from ..schedulers.activation import round_scheduler
from ..text import SHORT, NumberStyle, exact_text, violation_line
from .data import ModelReport
from .places import Places

RANK = {"VIOLATED": 0, "INCONCLUSIVE": 1, "HOLDS_WITHIN_BOUNDS": 2, "PROVED": 3}
PROVER_LEMMAS = PROVED_LEMMAS
"""The prover's lemmas, in its results order: the report's prove columns."""

VIEWER_JS = """
document.querySelectorAll('.viewer').forEach(function (v) {
  var frames = JSON.parse(v.dataset.frames), i = 0, timer = null;
  var img = v.querySelector('img'), counter = v.querySelector('.counter');
  function show(k) {
    i = (k + frames.length) % frames.length;
    img.src = frames[i];
    counter.textContent = 'frame ' + (i + 1) + ' / ' + frames.length;
  }
  v.querySelector('.prev').onclick = function () { show(i - 1); };
  v.querySelector('.next').onclick = function () { show(i + 1); };
  v.querySelector('.play').onclick = function () {
    if (timer) { clearInterval(timer); timer = null; this.textContent = 'play'; }
    else { timer = setInterval(function () { show(i + 1); }, 1200); this.textContent = 'pause'; }
  };
  show(0);
});
"""

CSS = """
body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
body.wide { max-width: 1340px; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }
td { overflow-wrap: break-word; }
td.detail { overflow-wrap: anywhere; min-width: 22em; }
td.nw { white-space: nowrap; }
table:not(.matrix) td:is(.VIOLATED, .HOLDS_WITHIN_BOUNDS, .PROVED, .INCONCLUSIVE) { white-space: nowrap; }
p.legend { font-size: 0.85em; color: #444; }
.index { line-height: 1.6; } .index a { white-space: nowrap; }
th { background: #f3f3f3; }
.VIOLATED { background: #fde0e0; } .HOLDS_WITHIN_BOUNDS { background: #e3f4e3; }
.PROVED { background: #c8ecc8; } .INCONCLUSIVE { background: #fff4d6; }
table.matrix { width: 100%; font-size: 0.76em; }
.matrix th { font-weight: 600; }
.matrix th:not(.group) { white-space: nowrap; }
.matrix th, .matrix td { padding: 0.3em 0.3em; }
.matrix th.group { text-align: center; }
.matrix td.notrun { color: #555; font-style: italic; text-align: center; }
.matrix td.notencoded { color: #555; font-style: italic; }
.matrix td.model { white-space: nowrap; }
.matrix td.readings { min-width: 10em; max-width: 14em; }
.matrix td.readings code { font-size: 0.95em; }
.matrix .robots { color: #555; white-space: nowrap; }
.matrix .rows { color: #555; }
.nowrap { white-space: nowrap; }
.viewer { border: 1px solid #ccc; padding: 0.6em; margin: 1em 0; overflow-wrap: anywhere; }
.viewer img { max-width: 100%; height: auto; display: block; margin: 0.5em 0; }
.card { margin: 1.5em 0; } .card h3 { margin-bottom: 0.2em; } .card p { margin: 0.2em 0; }
.exact { border-bottom: 1px dotted #777; cursor: help; }
code { background: #f5f5f5; padding: 0 0.2em; }
"""


def worst_of(rows: list[dict[str, Any]], lemma: str) -> tuple[str, int] | None:
    """The worst verdict over robot counts and the smallest robot count that has it."""
    mine = [(RANK[r["verdict"]], r["robots"], r["verdict"]) for r in rows if r["lemma"] == lemma]
    if not mine:
        return None
    _, robots, verdict = min(mine)
    return verdict, robots


def worst_text(rows: list[dict[str, Any]], lemma: str) -> str:
    """The worst verdict over robot counts, with the smallest robot count that has it."""
    worst = worst_of(rows, lemma)
    if worst is None:
        return ""
    verdict, robots = worst
    return f"{verdict} ({robots} robots)" if verdict == "VIOLATED" else verdict


def prover_counts(rows: list[dict[str, Any]], lemma: str) -> list[tuple[str, int]]:
    """How many of a lemma's obligations have each verdict, worst first."""
    mine = [r["verdict"] for r in rows if r["lemma"] == lemma]
    return [(v, mine.count(v)) for v in sorted(RANK, key=RANK.__getitem__) if mine.count(v)]


def model_lemma_verdicts(report: ModelReport) -> dict[str, LemmaVerdict]:
    """The model's lemma-level prover verdicts (:mod:`fatline_verify.prove.coverage`), by lemma."""
    rows = report.prove["obligations"]
    return {v.lemma: v for v in lemma_verdicts(report.model, rows, tuple(lemma.value for lemma in PROVER_LEMMAS))}


ROWS = "obligation rows"
"""What a prover cell's counts are: its obligations (rows of ``results.json``) by verdict, not the lemma."""


def lemma_summary(report: ModelReport, lemma: str) -> str:
    """A matrix cell: the lemma-level verdict, then its obligation rows' counts (PROVED split by basis), each
    said for what it is: ``lemma NOT PROVED; obligation rows: 25 PROVED`` (25 rows PROVED, the lemma not)."""
    if not claims(report, lemma):
        return NOT_CLAIMED
    v = model_lemma_verdicts(report).get(lemma)
    if v is None or not report.prove.get("obligations"):  # no prover run (a scheduler it refuses): no claim
        return ""
    return f"lemma {v.verdict}; {ROWS}: {v.counts}" if v.rows else v.verdict  # NOT ENCODED: no rows to count


def _own_rules(report: ModelReport) -> str | None:
    """``rules=NAME`` for a model of a rule set other than the paper's (which reads none of its readings)."""
    return None if report.model.rules in IMPLIED else f"rules={report.model.rules}"


def readings_text(report: ModelReport) -> str:
    """The model's rule set where it is not the paper's, then the readings that differ from the defaults."""
    diff = [f"{k}={v}" for k, v in report.model.options.differences().items()]
    own = _own_rules(report)
    return ", ".join([own, *diff] if own else diff) or "every default reading"


def claims(report: ModelReport, lemma: str) -> bool:
    """Whether the model's rule set claims ``lemma`` (``RuleSet(lemmas=...)``: a lemma it leaves out is
    neither judged nor proved, and its cells read "not claimed", never blank)."""
    from ..rules import registry

    return any(claimed.value == lemma for claimed in registry.applies(report.model))


NOT_CLAIMED = "not claimed"
"""A cell of a lemma the model's rule set does not claim."""


def meaning(name: str, value: str) -> str:
    """What reading ``value`` of option ``name`` means: the catalogue's words, or for a registered
    scheduler of one's own (a plug-in) the first line of its class's docstring."""
    if value in CATALOGUE[name].readings:
        return CATALOGUE[name].readings[value]
    doc = (type(round_scheduler(value)).__doc__ or "").strip() if name == "scheduler" else ""
    return doc.splitlines()[0] if doc else f"{name}={value}"


def readings_html(report: ModelReport, root: str, sep: str = ", ") -> str:
    """The model's rule set where it is not the paper's, then its readings, each linked to its entry in
    the catalogue where the report has one (:mod:`.places`; a plug-in scheduler's reading has none),
    its meaning on hover."""
    catalogue = report.places.readings(root)
    docs = html.escape(catalogue or "")
    diff = report.model.options.differences()
    own = _own_rules(report)
    shown = [f"<code>{html.escape(own)}</code>"] if own else []
    if not diff and not own:
        return f'<a href="{docs}">every default reading</a>' if catalogue else "every default reading"
    for k, v in diff.items():
        code = (
            f'<code><span class="nowrap">{html.escape(k)}=</span><wbr>'
            f'<span class="nowrap">{html.escape(v)}</span></code>'
        )
        title = html.escape(meaning(k, v))
        if catalogue is not None and v in CATALOGUE[k].readings:  # a plug-in scheduler's reading is not in it
            shown.append(f'<a href="{docs}#{html.escape(k)}" title="{title}">{code}</a>')
        else:
            shown.append(f'<span title="{title}">{code}</span>')
    return sep.join(shown)


def html_numbers(render: Callable[[NumberStyle], str]) -> str:
    """The text ``render`` writes with :data:`~fatline_verify.text.SHORT` numbers, as HTML: each
    number that is shown rounded or shortened carries its exact value in a ``title`` (on hover)."""
    shown: list[tuple[str, str]] = []

    def marking(fmt: Callable[[object], str]) -> Callable[[object], str]:
        def mark(value: object) -> str:
            shown.append((fmt(value), exact_text(value)))
            return f"\x00{len(shown) - 1}\x00"

        return mark

    text = html.escape(render(NumberStyle(marking(SHORT.area), marking(SHORT.coordinate))))
    return re.sub("\x00(\\d+)\x00", lambda m: _number_html(*shown[int(m[1])]), text)


def _number_html(display: str, exact: str) -> str:
    if display == exact:
        return html.escape(display)
    return f'<span class="exact" title="exact: {html.escape(exact)}">{html.escape(display)}</span>'


def md_table(headers: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    out += ["| " + " | ".join(c.replace("|", "\\\\|") for c in r) + " |" for r in rows]
    return out


def trace_text(t: dict[str, Any], style: NumberStyle = SHORT) -> str:
    v = t["doc"].get("violation")
    return violation_line(v, style) if v else t["doc"]["outcome"]


def viewer(t: dict[str, Any], prefix: str = "", places: Places | None = None) -> str:
    """A trace's step-through viewer: caption (numbers exact on hover), buttons, the pictures, and the
    command that replays it (:mod:`.places`: from where the report was made)."""
    places = places or Places()
    frames = [prefix + f for f in t["frames"]]
    caption = html_numbers(lambda style: trace_text(t, style))
    return (
        f'<div class="viewer" id="{html.escape(t["name"])}" data-frames="{html.escape(json.dumps(frames))}">'
        f"<strong>{html.escape(t['name'])}</strong>: {html.escape(t['source'])}, {html.escape(t['lemma'])}, "
        f"{html.escape(t['what'])} ({html.escape(t['verdict'])}): {caption}<br>"
        '<button class="prev">previous</button> <button class="next">next</button> '
        '<button class="play">play</button> <span class="counter"></span>'
        f'<img alt="picture of the trace" src="{html.escape(frames[0])}">'
        f'<a href="{html.escape(prefix + t["path"])}">trace file</a> &middot; replay with '
        f"<code>{html.escape(places.replay(t['name']))}</code></div>"
    )


ASSETS = {"viewer.js": VIEWER_JS.lstrip(), "style.css": CSS.lstrip()}
"""Written once at the report root; every page links them (relative paths work from the file system)."""


def html_page(title: str, body: str, root: str, wide: bool = False) -> str:
    """A page; ``wide``: the body may take 1340 px (the matrix has a column per lemma and tool)."""
    klass = ' class="wide"' if wide else ""
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
        f'<link rel="stylesheet" href="{root}style.css"></head><body{klass}>\n{body}\n'
        f'<script src="{root}viewer.js"></script></body></html>\n'
    )


__all__ = [
    "ASSETS",
    "CSS",
    "NOT_CLAIMED",
    "PROVER_LEMMAS",
    "RANK",
    "ROWS",
    "VIEWER_JS",
    "claims",
    "html_numbers",
    "html_page",
    "lemma_summary",
    "md_table",
    "model_lemma_verdicts",
    "prover_counts",
    "readings_html",
    "readings_text",
    "trace_text",
    "viewer",
    "worst_of",
    "worst_text",
]
