"""The report page of a sweep (``OUT/MODEL/index.html`` and ``README.md``): per lemma, the headline,
the counterexamples that cover the refuted readings (each replayed, with its first and last
pictures), and the readings where the lemma survives, summarised option by option."""

from __future__ import annotations

import html
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np

from ..lemmas.properties import Lemma
from ..outputs import Kind, claim_files, is_output, write_text
from ..report.build import stamp
from ..report.pictures import frame_svg
from ..trace.traces import check_replay, load_trace
from .run import HOLDS, Sweep, headline

PAGES = ("index.html", "README.md")
COMMAND = "fatline sweep"
LISTED = 20
"""Surviving readings listed in full per lemma (all of them are counted option by option)."""

CSS = """
body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; overflow-wrap: anywhere; }
th:first-child, td:first-child { text-align: left; }
.witness { border: 1px solid #ddd; border-radius: 6px; padding: 0.6em; margin: 0.6em 0; }
.witness img { width: 360px; margin-right: 0.5em; border: 1px solid #eee; }
code { background: #f4f4f4; padding: 0 0.2em; }
.holds { color: #1a7f37; } .refuted { color: #b42318; }
"""


def page_files(out: Path) -> list[Path]:
    """The pages a sweep writes into its directory (checked for ownership before any work)."""
    return [out / name for name in PAGES]


def claim_pages(out: Path) -> None:
    claim_files(page_files(out), name="out", kind=Kind.PAGE)


def _differs(sweep: Sweep, readings: dict[str, str]) -> str:
    """The readings that differ from the base model's, as ``option=value`` (or the model's own)."""
    base = sweep.space.text(sweep.space.reading_indices(sweep.space.base.options))
    diff = [f"{k}={v}" for k, v in readings.items() if base.get(k) != v]
    return ", ".join(diff) if diff else "the model's own readings"


def _pictures(sweep: Sweep, witness: dict[str, Any], k: int) -> list[str]:
    """Replay the witness (it must reproduce) and draw its first and last pictures; their file names."""
    doc = load_trace(sweep.out / witness["trace"])
    run = check_replay(doc)
    last = len(run.rounds) + 1 if run.rounds else 1
    first = 1 if run.rounds else 0
    names = []
    for tag, index in (("start", first), ("end", last)):
        path = sweep.out / "img" / f"{witness['lemma']}-{k}-{tag}.svg"
        if path.exists() and not is_output(path, Kind.PAGE):
            continue
        write_text(path, stamp(path.name, frame_svg(run, index, doc), COMMAND))
        names.append(f"img/{path.name}")
    return names


def survivors(sweep: Sweep, lemma: Lemma) -> tuple[int, list[tuple[str, Counter[str]]], list[dict[str, str]]]:
    """Readings where ``lemma`` holds within the bounds: how many, per option the values among them
    (with counts), and the first :data:`LISTED` in full."""
    space = sweep.spaces[lemma]
    where = np.flatnonzero(sweep.status[lemma] == HOLDS)
    digits = space.digits[where]
    per_option = []
    for column, name in enumerate(space.names):
        values = space.readings(name)
        found, counts = np.unique(digits[:, column], return_counts=True)
        per_option.append((name, Counter({values[int(d)]: int(n) for d, n in zip(found, counts, strict=True)})))
    listed = [space.text(space.combo(int(i))) for i in where[:LISTED]]
    return len(where), per_option, listed


def write_pages(sweep: Sweep, command: str) -> list[Path]:
    """Write the sweep's HTML and Markdown pages (and the witnesses' pictures); the paths written."""
    b = sweep.bounds
    lo, hi = b.robots
    robots = str(lo) if lo == hi else f"{lo} to {hi}"
    intro = (
        f"{sweep.space.base.describe()}. Varied: {', '.join(sweep.space.names)}; each combination checked at "
        f"{robots} robots in a {b.window[0]}x{b.window[1]} window"
        + (f", explored within {b.bound[0]}x{b.bound[1]}" if b.bound else "")
        + f"; {len(sweep.checks)} checks, "
        f"{sweep.replays:,} replays."
    )
    h = [f"<h1>Sweep of <code>{html.escape(sweep.space.base.name)}</code></h1>", f"<p>{html.escape(intro)}</p>",
         f"<p>Regenerate (resumes, then rewrites this page): <code>{html.escape(command)}</code></p>"]  # fmt: skip
    md = [f"# Sweep of `{sweep.space.base.name}`", "", intro, "", f"Regenerate: `{command}`", ""]
    head = ["lemma", "readings", "refuted", "holds", "inconclusive", "open", "counterexamples"]
    rows = []
    for lemma in sweep.lemmas:
        c = sweep.lemma_summary(lemma)
        counts = (f"{c[n]:,}" for n in head[2:6])
        rows.append([lemma.value, f"{c['combinations']:,}", *counts, str(c["counterexamples"])])
    h.append("<table><tr>" + "".join(f"<th>{x}</th>" for x in head) + "</tr>")
    h += ["<tr>" + "".join(f"<td>{html.escape(x)}</td>" for x in r) + "</tr>" for r in rows]
    h.append("</table>")
    md += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head), *("| " + " | ".join(r) + " |" for r in rows), ""]
    for lemma in sweep.lemmas:
        line = headline(sweep, lemma)
        h += [f"<h2>{html.escape(lemma.value)}</h2>", f"<p><strong>{html.escape(line)}</strong></p>"]
        md += [f"## {lemma.value}", "", f"**{line}**", ""]
        mine = [w for w in sweep.witnesses if w["lemma"] == lemma.value]
        if mine:
            h.append("<h3>The counterexamples that cover the refuted readings</h3>")
            md += ["Counterexamples (each replayed under the readings it was found under):", ""]
        for k, w in enumerate(mine, start=1):
            pics = _pictures(sweep, w, k)
            where = _differs(sweep, w["found_under"])
            text = f"{w['robots']} robots, found under {where}; refutes {w['refutes']:,} readings"
            h.append(
                f'<div class="witness"><strong>{html.escape(lemma.value)} #{k}</strong>: {html.escape(text)} '
                f'(<a href="{html.escape(w["trace"])}">trace</a>; <code>fatline replay '
                f"{html.escape((sweep.out / w['trace']).as_posix())} -v</code>)<br>"
                + "".join(f'<img alt="start and end of the counterexample" src="{p}">' for p in pics)
                + "</div>"
            )
            md.append(
                f"- #{k}: {text} ([trace]({w['trace']}); " + ", ".join(f"[{Path(p).stem}]({p})" for p in pics) + ")"
            )
        if mine:
            md.append("")
        count, per_option, listed = survivors(sweep, lemma)
        if count:
            h.append(f'<h3 class="holds">Where it holds within the bounds: {count:,} readings</h3>')
            md += [f"Where it holds within the bounds: {count:,} readings. Per option, the readings among them:", ""]
            h.append("<table><tr><th>option</th><th>readings among them (how many)</th></tr>")
            for name, values in per_option:
                cell = ", ".join(f"{v} ({n:,})" for v, n in sorted(values.items()))
                h.append(f'<tr><td>{html.escape(name)}</td><td style="text-align:left">{html.escape(cell)}</td></tr>')
                md.append(f"- {name}: {cell}")
            h.append("</table>")
            h.append(f"<p>The first {min(count, LISTED)}, as they differ from the model:</p><ul>")
            h += [f"<li>{html.escape(_differs(sweep, r))}</li>" for r in listed]
            h.append("</ul>")
            md += ["", f"The first {min(count, LISTED)}, as they differ from the model:", ""]
            md += [f"- {_differs(sweep, r)}" for r in listed]
            md.append("")
    body = "\n".join(h)
    page = (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>Sweep of '
        f"{html.escape(sweep.space.base.name)}</title><style>{CSS}</style></head><body>\n{body}\n</body></html>\n"
    )
    paths = page_files(sweep.out)
    for path, text in zip(paths, (page, "\n".join(md) + "\n"), strict=True):
        write_text(path, stamp(path.name, text, COMMAND))
    return paths
