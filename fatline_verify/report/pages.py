"""The report's pages, rendered from result data (never from strings of other pages).

Markdown for reading on a repository page; HTML with an offline step-through viewer: plain HTML,
SVG pictures referenced by relative path, and a few lines of JavaScript (previous, next, play).
"""

from __future__ import annotations

import html
import json
from typing import Any

from ..properties import Lemma
from ..text import violation_line
from .data import ModelReport

RANK = {"VIOLATED": 0, "INCONCLUSIVE": 1, "HOLDS_WITHIN_BOUNDS": 2, "PROVED": 3}
PROVER_LEMMAS = ("no-collision", "connectivity")

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
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
.VIOLATED { background: #fde0e0; } .HOLDS_WITHIN_BOUNDS { background: #e3f4e3; }
.PROVED { background: #c8ecc8; } .INCONCLUSIVE { background: #fff4d6; }
.viewer { border: 1px solid #ccc; padding: 0.6em; margin: 1em 0; }
.viewer img { max-width: 100%; height: auto; display: block; margin: 0.5em 0; }
code { background: #f5f5f5; padding: 0 0.2em; }
"""


def _worst(rows: list[dict[str, Any]], lemma: str) -> str:
    """The worst verdict over robot counts, with the smallest robot count that has it."""
    mine = [(RANK[r["verdict"]], r["robots"], r["verdict"]) for r in rows if r["lemma"] == lemma]
    if not mine:
        return ""
    _, robots, verdict = min(mine)
    return f"{verdict} ({robots} robots)" if verdict == "VIOLATED" else verdict


def _prover_summary(rows: list[dict[str, Any]], lemma: str) -> str:
    mine = [r["verdict"] for r in rows if r["lemma"] == lemma]
    counts = {v: mine.count(v) for v in RANK if mine.count(v)}
    return ", ".join(f"{n} {v}" for v, n in sorted(counts.items(), key=lambda kv: RANK[kv[0]]))


def _readings(report: ModelReport) -> str:
    diff = report.model.options.differences()
    return ", ".join(f"{k}={v}" for k, v in diff.items()) or "every default reading"


def _md_table(headers: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    out += ["| " + " | ".join(c.replace("|", "\\\\|") for c in r) + " |" for r in rows]
    return out


def _check_rows(report: ModelReport) -> list[list[str]]:
    return [
        [
            r["lemma"],
            str(r["robots"]),
            r["verdict"],
            "" if r["witness_rounds"] is None else f"{r['witness_rounds']} rounds",
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
            str(s["violating_only"]),
            "yes" if s["truncated"] else "no",
            f"{s['seconds']:.2f}",
        ]
        for s in report.check["searches"]
    ]


def _prove_rows(report: ModelReport) -> list[list[str]]:
    return [
        [
            r["lemma"],
            r["form"],
            r["rule"],
            r["verdict"],
            str(r["slots"]),
            f"{r['seconds']:.1f}",
            r["reason"],
            f"[trace](../traces/{r['trace'].split('/')[-1]})" if r.get("trace") else "",
        ]
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
PROVE_HEAD = ["lemma", "form", "rule", "verdict", "slots", "seconds", "detail", "trace"]


def _trace_text(t: dict[str, Any]) -> str:
    v = t["doc"].get("violation")
    return violation_line(v) if v else t["doc"]["outcome"]


def model_markdown(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    lines = [
        f"# Model `{m.name}`",
        "",
        m.description,
        "",
        f"Readings: {_readings(report)}. Parameters: rad_v={m.parameters.rad_v}, q={m.parameters.q}, "
        f"delta={m.parameters.delta}.",
        "",
        f"Regenerate: `fatline report models/{m.name}.toml` (reuses the cached results while they are up to date; "
        "`--refresh` recomputes). [HTML version with a step-through viewer](index.html).",
        "",
        "## Bounded model checker",
        "",
        f"Robots {b.robots[0]}..{b.robots[1]}, window {b.window[0]}x{b.window[1]} lattice points, "
        f"at most {b.max_states} states. States reached only through a violating round are not explored further.",
        "",
    ]
    lines += [*_md_table(SEARCH_HEAD, _search_rows(report)), ""]
    lines += [*_md_table(CHECK_HEAD, _check_rows(report)), ""]
    lines += ["## Prover (z3, any swarm size)", "", f"Solver: {report.prove['solver']}.", ""]
    lines += [*_md_table(PROVE_HEAD, _prove_rows(report)), ""]
    lines += ["## Counterexamples", ""]
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


def _html_table(headers: list[str], rows: list[list[str]], verdict_col: int | None = None) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = []
    for r in rows:
        cells = []
        for i, c in enumerate(r):
            cls = f' class="{html.escape(c)}"' if i == verdict_col else ""
            if c.startswith("[trace]("):
                href = c[len("[trace](") : -1]
                c_html = f'<a href="{html.escape(href)}">trace</a>'
            else:
                c_html = html.escape(c)
            cells.append(f"<td{cls}>{c_html}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><tr>{head}</tr>{''.join(body)}</table>"


def viewer(t: dict[str, Any], prefix: str = "") -> str:
    frames = [prefix + f for f in t["frames"]]
    return (
        f'<div class="viewer" id="{html.escape(t["name"])}" data-frames="{html.escape(json.dumps(frames))}">'
        f"<strong>{html.escape(t['name'])}</strong>: {html.escape(t['source'])}, {html.escape(t['lemma'])}, "
        f"{html.escape(t['what'])} ({html.escape(t['verdict'])}): {html.escape(_trace_text(t))}<br>"
        '<button class="prev">previous</button> <button class="next">next</button> '
        '<button class="play">play</button> <span class="counter"></span>'
        f'<img alt="picture of the trace" src="{html.escape(frames[0])}">'
        f'<a href="{html.escape(prefix + t["path"])}">trace file</a> &middot; replay with '
        f"<code>fatline replay reports/traces/{html.escape(t['name'])}.json -v</code></div>"
    )


ASSETS = {"viewer.js": VIEWER_JS.lstrip(), "style.css": CSS.lstrip()}
"""Written once at the report root; every page links them (relative paths work from the file system)."""


def _page(title: str, body: str, root: str) -> str:
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
        f'<link rel="stylesheet" href="{root}style.css"></head><body>\n{body}\n'
        f'<script src="{root}viewer.js"></script></body></html>\n'
    )


def model_html(report: ModelReport) -> str:
    m = report.model
    b = m.bounds
    parts = [
        f"<h1>Model <code>{html.escape(m.name)}</code></h1><p>{html.escape(m.description)}</p>",
        f"<p>Readings: {html.escape(_readings(report))}. <a href='../index.html'>All models</a>.</p>",
        f"<h2>Bounded model checker</h2><p>Robots {b.robots[0]}..{b.robots[1]}, "
        f"window {b.window[0]}x{b.window[1]}.</p>",
        _html_table(SEARCH_HEAD, _search_rows(report)),
        _html_table(CHECK_HEAD, _check_rows(report), verdict_col=2),
        f"<h2>Prover</h2><p>Solver: {html.escape(report.prove['solver'])}.</p>",
        _html_table(PROVE_HEAD, _prove_rows(report), verdict_col=3),
        "<h2>Counterexamples</h2>",
    ]
    parts += [viewer(t) for t in report.traces]
    return _page(f"fatline-verify: {m.name}", "\n".join(parts), "../")


def _matrix(reports: list[ModelReport]) -> tuple[list[str], list[list[str]]]:
    headers = (
        ["model", "readings"]
        + [f"{lemma.value} (check)" for lemma in Lemma]
        + [f"{lemma} (prove)" for lemma in PROVER_LEMMAS]
    )
    rows = []
    for r in reports:
        row = [r.model.name, _readings(r)]
        row += [_worst(r.check["lemmas"], lemma.value) for lemma in Lemma]
        row += [_prover_summary(r.prove["obligations"], lemma) for lemma in PROVER_LEMMAS]
        rows.append(row)
    return headers, rows


INTRO = (
    "Which reading of the paper breaks which lemma. *check*: the bounded model checker at each model's bounds "
    "(worst verdict over the robot counts, with the smallest swarm that shows it). "
    "*prove*: z3 obligations per rule over the reals, counted by verdict. "
    "Every VIOLATED verdict has a counterexample trace in `traces/` that `fatline replay` reproduces."
)


def cross_model_markdown(reports: list[ModelReport]) -> str:
    headers, rows = _matrix(reports)
    rows = [[f"[{r[0]}]({r[0]}/README.md)", *r[1:]] for r in rows]
    lines = ["# fatline-verify reports", "", INTRO, "", *_md_table(headers, rows), ""]
    lines += ["Regenerate everything: `fatline report` (every shipped model).", ""]
    return "\n".join(lines)


def cross_model_html(reports: list[ModelReport]) -> str:
    headers, rows = _matrix(reports)
    table = _html_table(headers, rows)
    for r in reports:
        table = table.replace(
            f"<td>{html.escape(r.model.name)}</td>",
            f'<td><a href="{html.escape(r.model.name)}/index.html">{html.escape(r.model.name)}</a></td>',
            1,
        )
    for v in RANK:
        table = table.replace(f"<td>{v}", f'<td class="{v}">{v}')
    featured = [viewer(r.traces[0], prefix=f"{r.model.name}/") for r in reports if r.traces]
    intro = html.escape(INTRO.replace("*", "").replace("`", ""))
    body = f"<h1>fatline-verify reports</h1><p>{intro}</p>{table}<h2>A counterexample per model</h2>" + "\n".join(
        featured
    )
    return _page("fatline-verify reports", body, "")
