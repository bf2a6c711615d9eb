"""The report's per-model pages, rendered from result data (never from strings of other pages).

Markdown for reading on a repository page; HTML with an offline step-through viewer: plain HTML,
SVG pictures referenced by relative path, and a few lines of JavaScript (previous, next, play).
Numbers in captions are short decimals, in HTML with the exact value on hover; readings link to the
catalogue ``docs/readings.md``. The pieces every page is made of are in :mod:`.parts`, the
cross-model pages in :mod:`.matrix` (both importable from here too).
"""

from __future__ import annotations

import html
import re

from ..prove.coverage import NOT_ENCODED
from ..prove.text import PROVE_ROBOTS_LEGEND, prove_row
from ..rules import registry
from ..schedulers.systems import system_for
from ..text import plural
from .against_pages import against_html, against_markdown
from .data import ModelReport
from .matrix import cross_model_html, cross_model_markdown, featured, markdown_html
from .parts import (
    ASSETS,
    PROVER_LEMMAS,
    html_numbers,
    html_page,
    md_table,
    model_lemma_verdicts,
    readings_html,
    readings_text,
    trace_text,
    viewer,
)
from .places import explain

LEMMA_HEAD = ["lemma", "verdict", "obligations", "why"]


def _lemma_rows(report: ModelReport) -> list[list[str]]:
    return [
        [v.lemma, v.verdict, v.counts or "none", v.why]
        for v in model_lemma_verdicts(report).values()
        if v.rows or v.verdict == NOT_ENCODED
    ]


LEMMA_LEGEND = (
    "A lemma is PROVED only when every part of its argument is (the obligation forms that together imply it), "
    "VIOLATED only when a replayed counterexample breaks the lemma itself (a lost edge alone is not a split swarm), "
    "NOT PROVED otherwise (the parts missing named), NOT ENCODED when a part has no obligation form (liveness). "
    "PROVED obligations are counted by basis: vacuous (the case never fires), immediate (the claim follows from "
    "the rule's construction: unsat without the case's universal conditions), substantive (the rest)."
)


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


def _rule_set(report: ModelReport) -> str:
    """The model's rule set, named, with its own summary (Markdown)."""
    rule_set = registry.of(report.model)
    own = report.model.setting("rules")
    values = f" ({', '.join(f'{k}={v}' for k, v in own.items())})" if own else ""
    return f"Rule set `{rule_set.name}`{values}: {rule_set.summary.rstrip('.')}."


def _readings_where(report: ModelReport) -> str:
    """Where the readings' meanings are (Markdown): the catalogue, linked, where the report has one."""
    link = report.places.readings("../")
    if link is not None:
        return f"[what the readings mean]({link})"
    return f"what each means: `{explain(report.model)}`"


def _regenerate(report: ModelReport) -> str:
    """The command that writes this page again (Markdown), from where the report was made."""
    places = report.places
    return (
        f"Regenerate: `{places.regenerate([report.model])}` (reuses the cached results while they are up to date; "
        f"`--refresh` recomputes).{places.where([report.model])}"
    )


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


def model_markdown(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    lines = [
        f"# Model `{m.name}`",
        "",
        m.description,
        "",
        f"{_rule_set(report)} Readings: {readings_text(report)} ({_readings_where(report)}). "
        f"Parameters: {_parameters(report)}.",
        "",
        f"{_regenerate(report)} [HTML version with a step-through viewer](index.html).",
        "",
        *_index_markdown(report),
        "## Bounded model checker",
        "",
        f"Robots {b.robots[0]}..{b.robots[1]}, window {b.window[0]}x{b.window[1]} lattice points"
        f"{'' if b.max_states is None else f', at most {b.max_states} states'}. States reached only through a "
        f"violating {_word(report)} are not explored further.",
        "",
    ]
    lines += [*md_table(_search_head(report), _search_rows(report)), ""]
    lines += [*md_table(CHECK_HEAD, _check_rows(report)), "", _search_legend(report), ""]
    lines += ["## Prover (z3, any swarm size)", "", f"Solver: {report.prove['solver']}.", ""]
    unproved = _not_encoded(report)
    lines += (
        [unproved, ""]
        if unproved
        else [
            *md_table(LEMMA_HEAD, _lemma_rows(report)),
            "",
            LEMMA_LEGEND,
            "",
            "Per obligation form:",
            "",
            *md_table(PROVE_HEAD, _prove_rows(report)),
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
            f"{t['source']}: {t['lemma']}, {t['what']} ({t['verdict']}): {trace_text(t)}.",
            "",
            f"Replay: `{report.places.replay(t['name'])}`",
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


def model_html(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    parts = [
        f"<h1>Model <code>{html.escape(m.name)}</code></h1><p>{html.escape(m.description)}</p>",
        f"<p>{markdown_html(_rule_set(report))} Readings: {readings_html(report, '../')} "
        f"({markdown_html(_readings_where(report))}). <a href='../index.html'>All models</a>.</p>",
        f"<p>{markdown_html(_regenerate(report))}</p>",
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
    parts += [viewer(t, places=report.places) for t in report.traces]
    return html_page(f"fatline-verify: {m.name}", "\n".join(parts), "../")


__all__ = [
    "ASSETS",
    "PROVER_LEMMAS",
    "cross_model_html",
    "cross_model_markdown",
    "featured",
    "html_numbers",
    "model_html",
    "model_markdown",
    "viewer",
]
