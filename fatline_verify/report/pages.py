"""The report's pages, rendered from result data (never from strings of other pages).

Markdown for reading on a repository page; HTML with an offline step-through viewer: plain HTML,
SVG pictures referenced by relative path, and a few lines of JavaScript (previous, next, play).
The cross-model matrix fits a 1400 px window; numbers in captions are short decimals, in HTML
with the exact value on hover; readings link to the catalogue ``docs/readings.md``.
"""

from __future__ import annotations

import html
import json
import re
from collections.abc import Callable
from typing import Any

from ..lemmas.properties import CHECKED, Lemma
from ..model.config import IMPLIED
from ..model.options import CATALOGUE, Scheduler
from ..prove.basis import counts_text
from ..prove.coverage import LemmaVerdict, lemma_verdicts
from ..schedulers.systems import system_for
from ..text import (
    PROVE_ROBOTS_LEGEND,
    READINGS_DOC,
    SHORT,
    NumberStyle,
    exact_text,
    plural,
    prove_row,
    violation_line,
)
from .against_pages import against_html, against_markdown
from .data import ModelReport

RANK = {"VIOLATED": 0, "INCONCLUSIVE": 1, "HOLDS_WITHIN_BOUNDS": 2, "PROVED": 3}
PROVER_LEMMAS = (Lemma.NO_COLLISION, Lemma.CONNECTIVITY, Lemma.RMA_FIXED, Lemma.APPROACH)
"""The prover's lemmas, in its results order (:data:`fatline_verify.prove.prover.LEMMAS`, without z3)."""

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
table.matrix { width: 100%; font-size: 0.8em; }
.matrix th { font-weight: 600; }
.matrix th:not(.group) { white-space: nowrap; }
.matrix th, .matrix td { padding: 0.3em 0.35em; }
.matrix th.group { text-align: center; }
.matrix td.notrun { color: #555; font-style: italic; text-align: center; }
.matrix td.notencoded { color: #555; font-style: italic; }
.matrix td.model { white-space: nowrap; }
.matrix td.readings { min-width: 10em; max-width: 14em; }
.matrix td.readings code { font-size: 0.95em; }
.matrix .robots { color: #555; white-space: nowrap; }
.viewer { border: 1px solid #ccc; padding: 0.6em; margin: 1em 0; overflow-wrap: anywhere; }
.viewer img { max-width: 100%; height: auto; display: block; margin: 0.5em 0; }
.card { margin: 1.5em 0; } .card h3 { margin-bottom: 0.2em; } .card p { margin: 0.2em 0; }
.exact { border-bottom: 1px dotted #777; cursor: help; }
code { background: #f5f5f5; padding: 0 0.2em; }
"""

DOCS_LINK = f"../{READINGS_DOC}"
"""The readings catalogue, relative to the report root (``reports/`` sits beside ``docs/``)."""


def _worst_of(rows: list[dict[str, Any]], lemma: str) -> tuple[str, int] | None:
    """The worst verdict over robot counts and the smallest robot count that has it."""
    mine = [(RANK[r["verdict"]], r["robots"], r["verdict"]) for r in rows if r["lemma"] == lemma]
    if not mine:
        return None
    _, robots, verdict = min(mine)
    return verdict, robots


def _worst(rows: list[dict[str, Any]], lemma: str) -> str:
    """The worst verdict over robot counts, with the smallest robot count that has it."""
    worst = _worst_of(rows, lemma)
    if worst is None:
        return ""
    verdict, robots = worst
    return f"{verdict} ({robots} robots)" if verdict == "VIOLATED" else verdict


def _prover_counts(rows: list[dict[str, Any]], lemma: str) -> list[tuple[str, int]]:
    """How many of a lemma's obligations have each verdict, worst first."""
    mine = [r["verdict"] for r in rows if r["lemma"] == lemma]
    return [(v, mine.count(v)) for v in sorted(RANK, key=RANK.__getitem__) if mine.count(v)]


def _prover_summary(rows: list[dict[str, Any]], lemma: str) -> str:
    return ", ".join(f"{n} {v}" for v, n in _prover_counts(rows, lemma))


def _lemma_verdicts(report: ModelReport) -> dict[str, LemmaVerdict]:
    """The model's lemma-level prover verdicts (:mod:`fatline_verify.prove.coverage`), by lemma."""
    rows = report.prove["obligations"]
    return {v.lemma: v for v in lemma_verdicts(report.model, rows, tuple(lemma.value for lemma in PROVER_LEMMAS))}


def _lemma_summary(report: ModelReport, lemma: str) -> str:
    """A matrix cell: the lemma-level verdict, then its rows' counts (PROVED split by basis)."""
    v = _lemma_verdicts(report).get(lemma)
    if v is None or not v.rows:
        return ""
    return f"{v.verdict}: {v.counts}"


LEMMA_HEAD = ["lemma", "verdict", "obligations", "why"]


def _lemma_rows(report: ModelReport) -> list[list[str]]:
    return [[v.lemma, v.verdict, v.counts, v.why] for v in _lemma_verdicts(report).values() if v.rows]


LEMMA_LEGEND = (
    "A lemma is PROVED only when every part of its argument is (the obligation forms that together imply it), "
    "VIOLATED only when a replayed counterexample breaks the lemma itself (a lost edge alone is not a split swarm), "
    "NOT PROVED otherwise (the parts missing named), NOT ENCODED when a part has no obligation form (liveness). "
    "PROVED obligations are counted by basis: vacuous (the case never fires), immediate (the claim follows from "
    "the rule's construction: unsat without the case's universal conditions), substantive (the rest)."
)


def _own_rules(report: ModelReport) -> str | None:
    """``rules=NAME`` for a model of a rule set other than the paper's (which reads none of its readings)."""
    return None if report.model.rules in IMPLIED else f"rules={report.model.rules}"


def _readings(report: ModelReport) -> str:
    diff = report.model.options.differences()
    return ", ".join(f"{k}={v}" for k, v in diff.items()) or _own_rules(report) or "every default reading"


def _readings_html(report: ModelReport, root: str, sep: str = ", ") -> str:
    """The model's readings, each linked to its entry in the catalogue, its meaning on hover."""
    docs = html.escape(root + DOCS_LINK)
    diff = report.model.options.differences()
    own = _own_rules(report)
    if not diff and own:
        return f"<code>{html.escape(own)}</code>"
    if not diff:
        return f'<a href="{docs}">every default reading</a>'
    return sep.join(
        f'<a href="{docs}#{html.escape(k)}" title="{html.escape(CATALOGUE[k].readings[v])}">'
        f"<code>{html.escape(k)}=<wbr>{html.escape(v)}</code></a>"
        for k, v in diff.items()
    )


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


def _md_table(headers: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    out += ["| " + " | ".join(c.replace("|", "\\\\|") for c in r) + " |" for r in rows]
    return out


def _word(report: ModelReport) -> str:
    """What one step of the model's scheduler is called ("round", "event")."""
    return system_for(report.model).step_word


def _fine(report: ModelReport) -> bool:
    """Whether the search table has an off-lattice column (a system on a finer lattice, ASYNC)."""
    return system_for(report.model).scale > 1


def _check_rows(report: ModelReport) -> list[list[str]]:
    word = _word(report)
    return [
        [
            r["lemma"],
            str(r["robots"]),
            r["verdict"],
            "" if r["witness_rounds"] is None else plural(r["witness_rounds"], word),
            r["reason"],
            f"[trace](../traces/{r['trace'].split('/')[-1]})" if r.get("trace") else "",
        ]
        for r in report.check["lemmas"]
    ]


def _search_rows(report: ModelReport) -> list[list[str]]:
    return [
        [
            str(s["robots"]),
            str(s["initial"]),
            str(s["states"]),
            str(s["transitions"]),
            str(s["escaped"]),
            *([str(s.get("off_lattice", 0))] if _fine(report) else []),
            str(s["violating_only"]),
            "yes" if s["truncated"] else "no",
            f"{s['seconds']:.2f}",
        ]
        for s in report.check["searches"]
    ]


def _not_encoded(report: ModelReport) -> str:
    """One sentence instead of the prover table when no obligation was run: every row INCONCLUSIVE for
    the same reason (a scheduler the prover does not encode)."""
    if report.prove.get("not_encoded"):
        return f"No obligations: {report.prove['not_encoded']}."
    rows = report.prove["obligations"]
    reasons = {r["reason"] for r in rows}
    if not rows or len(reasons) != 1 or any(r["verdict"] != "INCONCLUSIVE" or r["seconds"] for r in rows):
        return ""
    return f"All {len(rows)} obligations INCONCLUSIVE, none run: {reasons.pop()}."


def _search_head(report: ModelReport) -> list[str]:
    if not _fine(report):
        return SEARCH_HEAD
    return [*SEARCH_HEAD[:5], "off-lattice", *SEARCH_HEAD[5:]]


def _parameters(report: ModelReport) -> str:
    p = report.model.parameters
    steps = f", async_steps={p.async_steps}" if _fine(report) else ""
    return f"rad_v={p.rad_v}, q={p.q}, delta={p.delta}{steps}"


def _prove_rows(report: ModelReport) -> list[list[str]]:
    return [
        prove_row(r, f"[trace](../traces/{r['trace'].split('/')[-1]})" if r.get("trace") else "")
        for r in report.prove["obligations"]
    ]


SEARCH_HEAD = [
    "robots",
    "initial configurations",
    "states",
    "transitions",
    "escaped",
    "violating-only",
    "truncated",
    "seconds",
]
CHECK_HEAD = ["lemma", "robots", "verdict", "witness", "detail", "trace"]
PROVE_HEAD = ["lemma", "form", "case", "verdict", "robots", "seconds", "detail", "trace"]
NOWRAP = ("lemma", "form", "case", "robots", "witness", "seconds", "trace", "states", "transitions", "escaped")
"""Columns whose cells never wrap (a lemma's name, a number, a link; a case's name only after a dot): a
word is never broken."""


def _search_legend(report: ModelReport) -> str:
    """What the search table's columns count."""
    word = _word(report)
    off = "off-lattice = successors between points of the finer lattice (counted in escaped); " if _fine(report) else ""
    return (
        "Columns: initial configurations up to translation; escaped = successors outside the window (not explored); "
        f"{off}violating-only = violating {word}s into a state no other {word} reaches (not explored); truncated = the "
        "search stopped at its state or memory bound before it expanded every state (a lemma it found no violation of "
        f"is then INCONCLUSIVE); witness = {word}s in the shortest witness."
    )


PROVE_LEGEND = f"Columns: {PROVE_ROBOTS_LEGEND}; seconds = the solver's."


def _index_groups(report: ModelReport) -> list[tuple[str, list[tuple[str, str]]]]:
    """The counterexamples by source and lemma, in page order: per group, (anchor name, link text)."""
    groups: dict[str, list[tuple[str, str]]] = {}
    for t in report.traces:
        prefix = f"{report.model.name}-{t['source']}-{t['lemma']}-"
        short = t["name"].removeprefix(prefix) if t["name"].startswith(prefix) else t["name"]
        groups.setdefault(f"{t['source']}, {t['lemma']}", []).append((t["name"], short))
    return list(groups.items())


def _md_anchor(title: str) -> str:
    """The anchor a Markdown renderer (GitHub's) gives a heading: lower case, punctuation dropped."""
    return re.sub(r"[^a-z0-9 _-]", "", title.lower()).replace(" ", "-")


def _index_markdown(report: ModelReport) -> list[str]:
    if not report.traces:
        return []
    lines = [f"Counterexamples ({len(report.traces)}, pictures below):", ""]
    for group, items in _index_groups(report):
        links = " · ".join(f"[{text}](#{_md_anchor(name)})" for name, text in items)
        lines.append(f"- {group}: {links}")
    return [*lines, ""]


def _index_html(report: ModelReport) -> str:
    if not report.traces:
        return ""
    rows = "".join(
        f"<li>{html.escape(group)}: "
        + " · ".join(f'<a href="#{html.escape(name)}">{html.escape(text)}</a>' for name, text in items)
        + "</li>"
        for group, items in _index_groups(report)
    )
    return f'<p>Counterexamples ({len(report.traces)}, pictures below):</p><ul class="index">{rows}</ul>'


def _trace_text(t: dict[str, Any], style: NumberStyle = SHORT) -> str:
    v = t["doc"].get("violation")
    return violation_line(v, style) if v else t["doc"]["outcome"]


def model_markdown(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    lines = [
        f"# Model `{m.name}`",
        "",
        m.description,
        "",
        f"Readings: {_readings(report)} ([what the readings mean](../{DOCS_LINK})). Parameters: {_parameters(report)}.",
        "",
        f"Regenerate: `fatline report models/{m.name}.toml` (reuses the cached results while they are up to date; "
        "`--refresh` recomputes). [HTML version with a step-through viewer](index.html).",
        "",
        *_index_markdown(report),
        "## Bounded model checker",
        "",
        f"Robots {b.robots[0]}..{b.robots[1]}, window {b.window[0]}x{b.window[1]} lattice points"
        f"{'' if b.max_states is None else f', at most {b.max_states} states'}. States reached only through a "
        f"violating {_word(report)} are not explored further.",
        "",
    ]
    lines += [*_md_table(_search_head(report), _search_rows(report)), ""]
    lines += [*_md_table(CHECK_HEAD, _check_rows(report)), "", _search_legend(report), ""]
    lines += ["## Prover (z3, any swarm size)", "", f"Solver: {report.prove['solver']}.", ""]
    unproved = _not_encoded(report)
    lines += (
        [unproved, ""]
        if unproved
        else [
            *_md_table(LEMMA_HEAD, _lemma_rows(report)),
            "",
            LEMMA_LEGEND,
            "",
            "Per obligation form:",
            "",
            *_md_table(PROVE_HEAD, _prove_rows(report)),
            "",
            PROVE_LEGEND,
            "",
        ]
    )
    lines += against_markdown(report.against)
    lines += ["## Counterexamples", "", "Long numbers are rounded (≈); the trace files hold them exactly.", ""]
    for t in report.traces:
        lines += [
            f"### {t['name']}",
            "",
            f"{t['source']}: {t['lemma']}, {t['what']} ({t['verdict']}): {_trace_text(t)}.",
            "",
            f"Replay: `fatline replay reports/traces/{t['name']}.json -v`",
            "",
        ]
        lines += [f"![frame {k + 1}]({f})" for k, f in enumerate(t["frames"])] + [""]
    return "\n".join(lines)


def _html_table(
    headers: list[str],
    rows: list[list[str]],
    verdict_col: int | None = None,
    nowrap: tuple[str, ...] = (),
    detail: str | None = None,
) -> str:
    """A table; the cells of the columns named in ``nowrap`` never wrap (a lemma, a verdict, a
    number); the ``detail`` column's long numbers may break anywhere, no other word breaks."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    classes = ["nw" if h in nowrap else "detail" if h == detail else "" for h in headers]
    body = []
    for r in rows:
        cells = []
        for i, c in enumerate(r):
            names = " ".join(part for part in (c if i == verdict_col else "", classes[i]) if part)
            cls = f' class="{html.escape(names)}"' if names else ""
            if c.startswith("[trace]("):
                href = c[len("[trace](") : -1]
                c_html = f'<a href="{html.escape(href)}">trace</a>'
            elif headers[i] == "case":  # a case's name breaks only after a dot or a "+" (no hyphen breaks)
                c_html = html.escape(c).replace(".", ".<wbr>").replace(" + ", " +<wbr> ")
            else:
                c_html = html.escape(c)
            cells.append(f"<td{cls}>{c_html}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><tr>{head}</tr>{''.join(body)}</table>"


def viewer(t: dict[str, Any], prefix: str = "") -> str:
    """A trace's step-through viewer: caption (numbers exact on hover), buttons, the pictures."""
    frames = [prefix + f for f in t["frames"]]
    caption = html_numbers(lambda style: _trace_text(t, style))
    return (
        f'<div class="viewer" id="{html.escape(t["name"])}" data-frames="{html.escape(json.dumps(frames))}">'
        f"<strong>{html.escape(t['name'])}</strong>: {html.escape(t['source'])}, {html.escape(t['lemma'])}, "
        f"{html.escape(t['what'])} ({html.escape(t['verdict'])}): {caption}<br>"
        '<button class="prev">previous</button> <button class="next">next</button> '
        '<button class="play">play</button> <span class="counter"></span>'
        f'<img alt="picture of the trace" src="{html.escape(frames[0])}">'
        f'<a href="{html.escape(prefix + t["path"])}">trace file</a> &middot; replay with '
        f"<code>fatline replay reports/traces/{html.escape(t['name'])}.json -v</code></div>"
    )


ASSETS = {"viewer.js": VIEWER_JS.lstrip(), "style.css": CSS.lstrip()}
"""Written once at the report root; every page links them (relative paths work from the file system)."""


def _page(title: str, body: str, root: str, wide: bool = False) -> str:
    """A page; ``wide``: the body may take 1340 px (the matrix has a column per lemma and tool)."""
    klass = ' class="wide"' if wide else ""
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
        f'<link rel="stylesheet" href="{root}style.css"></head><body{klass}>\n{body}\n'
        f'<script src="{root}viewer.js"></script></body></html>\n'
    )


def model_html(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    parts = [
        f"<h1>Model <code>{html.escape(m.name)}</code></h1><p>{html.escape(m.description)}</p>",
        f"<p>Readings: {_readings_html(report, '../')} (<a href='{html.escape('../' + DOCS_LINK)}'>what the readings "
        "mean</a>). <a href='../index.html'>All models</a>.</p>",
        _index_html(report),
        f"<h2>Bounded model checker</h2><p>Robots {b.robots[0]}..{b.robots[1]}, "
        f"window {b.window[0]}x{b.window[1]}.</p>",
        _html_table(_search_head(report), _search_rows(report), nowrap=tuple(_search_head(report))),
        _html_table(CHECK_HEAD, _check_rows(report), verdict_col=2, nowrap=NOWRAP, detail="detail"),
        f'<p class="legend">{html.escape(_search_legend(report))}</p>',
        f"<h2>Prover</h2><p>Solver: {html.escape(report.prove['solver'])}.</p>",
        f"<p>{html.escape(_not_encoded(report))}</p>"
        if _not_encoded(report)
        else _html_table(LEMMA_HEAD, _lemma_rows(report), nowrap=("lemma", "verdict"))
        + f'<p class="legend">{html.escape(LEMMA_LEGEND)}</p><h3>Per obligation form</h3>'
        + _html_table(PROVE_HEAD, _prove_rows(report), verdict_col=3, nowrap=NOWRAP, detail="detail")
        + f'<p class="legend">{html.escape(PROVE_LEGEND)}</p>',
        *([against_html(report.against)] if report.against else []),
        "<h2>Counterexamples</h2>",
    ]
    parts += [viewer(t) for t in report.traces]
    return _page(f"fatline-verify: {m.name}", "\n".join(parts), "../")


def _matrix(reports: list[ModelReport]) -> tuple[list[str], list[list[str]]]:
    headers = (
        ["model", "readings"]
        + [f"{lemma.value} (check)" for lemma in CHECKED]
        + [f"{lemma.value} (prove)" for lemma in PROVER_LEMMAS]
    )
    rows = []
    for r in reports:
        row = [r.model.name, _readings(r)]
        row += [_worst(r.check["lemmas"], lemma.value) for lemma in CHECKED]
        row += [_lemma_summary(r, lemma.value) for lemma in PROVER_LEMMAS]
        rows.append(row)
    return headers, rows


INTRO = (
    "Which reading of the paper breaks which lemma. *check*: the bounded model checker at each model's bounds "
    "(worst verdict over the robot counts, with the smallest swarm that shows it). "
    "*prove*: the lemma-level verdict from z3 obligations per decision case of the rules (a repaired model: per "
    "pair of leg classes): PROVED (for every swarm size) only when the forms that together imply the lemma are all "
    "PROVED, VIOLATED only by a replayed counterexample of the lemma itself, else NOT PROVED or NOT ENCODED "
    "(approach is liveness); then the obligations counted by verdict, PROVED split into substantive, immediate "
    "(true by the rule's construction) and vacuous (the case never fires). "
    "Every VIOLATED verdict has a counterexample trace in `traces/` that `fatline replay` reproduces."
)


def cross_model_markdown(reports: list[ModelReport]) -> str:
    headers, rows = _matrix(reports)
    rows = [[f"[{r[0]}]({r[0]}/README.md)", *r[1:]] for r in rows]
    lines = ["# fatline-verify reports", "", INTRO, "", *_md_table(headers, rows), ""]
    notes = _not_run_markdown(reports)
    lines += [*notes, ""] if notes else []
    lines += [f"What each reading (`option=reading`) means: [{READINGS_DOC}]({DOCS_LINK}).", ""]
    lines += ["Regenerate everything: `fatline report` (every shipped model).", ""]
    return "\n".join(lines)


CHECK_TITLE = "bounded model checker: worst verdict over the robot counts, with the smallest swarm that shows it"
PROVE_TITLE = (
    "prover: the lemma-level verdict from the obligation forms that together imply the lemma, then the "
    "obligations counted by verdict (PROVED: substantive, immediate, vacuous)"
)


def _verdict_html(verdict: str) -> str:
    """A verdict that may wrap at its underscores (``HOLDS_WITHIN_BOUNDS`` is wider than a column)."""
    return html.escape(verdict).replace("_", "_<wbr>")


def _check_cell(rows: list[dict[str, Any]], lemma: str) -> str:
    worst = _worst_of(rows, lemma)
    if worst is None:
        return "<td></td>"
    verdict, robots = worst
    swarm = f'<br><span class="robots">{robots} robots</span>' if verdict == "VIOLATED" else ""
    return f'<td class="{html.escape(verdict)}">{_verdict_html(verdict)}{swarm}</td>'


LEMMA_CLASS = {"PROVED": "PROVED", "VIOLATED": "VIOLATED", "NOT PROVED": "INCONCLUSIVE", "NOT ENCODED": "notencoded"}
"""The colour of a lemma-level verdict's cell (the per-row verdicts' classes)."""


def _prove_cell(report: ModelReport, lemma: str) -> str:
    v = _lemma_verdicts(report).get(lemma)
    if v is None or not v.rows:
        return "<td></td>"
    rows = [r for r in report.prove["obligations"] if r["lemma"] == lemma]
    split = f" ({html.escape(counts_text(rows))})" if any(r.get("basis") for r in rows) else ""
    counts = _prover_counts(rows, lemma)
    lines = "<br>".join(f"{n}&nbsp;{_verdict_html(k)}" + (split if k == "PROVED" else "") for k, n in counts)
    title = html.escape(f"{v.verdict}: {v.why}. Obligations: {v.counts}")
    return (
        f'<td class="{LEMMA_CLASS[v.verdict]}" title="{title}"><strong>{html.escape(v.verdict)}</strong><br>'
        f"{lines}</td>"
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
        cells.append(f'<td class="readings">{_readings_html(r, "", sep="<br>")}</td>')
        cells += [_check_cell(r.check["lemmas"], lemma.value) for lemma in CHECKED]
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
        f"<p>Readings: {_readings_html(report, '')}. Shown: {html.escape(why)}.</p>"
    )
    return head + (viewer(trace, prefix=f"{report.model.name}/") if trace else "") + "</div>"


def cross_model_html(reports: list[ModelReport]) -> str:
    intro = html.escape(INTRO.replace("*", "").replace("`", ""))
    docs = f'<p>What each reading means: <a href="{html.escape(DOCS_LINK)}">{html.escape(READINGS_DOC)}</a>.</p>'
    cards = "\n".join(_card(r, t, why) for r, t, why in featured(reports))
    body = (
        f"<h1>fatline-verify reports</h1><p>{intro}</p>{_matrix_html(reports)}{docs}"
        f"<h2>A counterexample per model</h2>{cards}"
    )
    return _page("fatline-verify reports", body, "", wide=True)
