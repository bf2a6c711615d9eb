"""Readable reports: short decimals with exact values on hover, deadlock frames that say why each
robot stays, each model's card showing its own counterexample, and the shipped readings catalogue.

(The browser checks of the page width are in ``test_browser.py``.)
"""

from __future__ import annotations

import json
import re
from fractions import Fraction as Fr
from pathlib import Path
from typing import Any

import pytest

from fatline_verify.docs import main as docs_main
from fatline_verify.model.config import Model
from fatline_verify.model.options import CATALOGUE
from fatline_verify.report.data import ModelReport
from fatline_verify.report.pages import (
    PROVER_LEMMAS,
    cross_model_html,
    cross_model_markdown,
    featured,
    html_numbers,
    model_html,
    model_markdown,
    viewer,
)
from fatline_verify.report.pictures import frame_svg, frames
from fatline_verify.schedulers.round import play_round
from fatline_verify.text import (
    READINGS_DOC,
    SHORT,
    area_text,
    decimal_text,
    readings_markdown,
    trace_lines,
    violation_line,
)
from fatline_verify.trace.simulate import Outcome, Run, simulate
from fatline_verify.trace.traces import run_to_json
from tests.conftest import make_model

ROOT = Path(__file__).resolve().parent.parent
LONG_DIGITS = re.compile(r"\d{20,}")

# A prover counterexample of scenario4_drop=touch: r0's Scenario 1 move grazes r1, whose x is a
# 49-digit fraction; the closest squared distance is a 97-digit fraction just below 4.
HUGE_X = Fr(
    5660371501837459010645243865772934100615199146771,
    1461501637330902918203684832716283019655932542976,
)
GRAZE = ((0, 0), (HUGE_X, Fr(-3, 2)), (Fr(41, 16), Fr(-49, 16)), (0, -5))


def _doc(run: Run) -> dict[str, Any]:
    return json.loads(json.dumps(run_to_json(run)))


@pytest.fixture(scope="module")
def graze() -> tuple[Run, dict[str, Any]]:
    model = make_model(scenario4_drop="touch")
    rnd = play_round(GRAZE, [0], model)
    run = Run(model, GRAZE, (rnd,), Outcome.VIOLATION)
    return run, _doc(run)


# --- numbers -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "shown"),
    [
        (20, "20"),
        ("5/2", "2.5"),
        ("63/16", "≈3.94"),
        ("-41/16", "≈-2.56"),
        ("1/3", "≈0.33"),
        (Fr(4) - Fr(1, 3 * 10**6), "≈3.9999997"),  # never "≈4": that would read as touching
        (Fr(1, 10**7), "0.0000001"),
    ],
)
def test_short_decimals(value, shown):
    assert decimal_text(value) == shown


def test_plain_text_keeps_a_short_exact_fraction():
    assert area_text("63/16") == "≈3.94 (63/16)"
    assert area_text(f"{10**40 + 1}/{10**40}") == "≈1"


def test_a_huge_squared_distance_is_a_short_decimal_with_the_exact_value_on_hover(graze):
    _, doc = graze
    v = doc["violation"]
    exact = v["closest_distance2"]
    assert isinstance(exact, str) and len(exact) > 150 and Fr(exact) < 4  # the trace stays exact
    text = violation_line(v, SHORT)
    assert "closest squared centre distance ≈3.97 (discs touch at 4)" in text
    assert not LONG_DIGITS.search(text)
    page = html_numbers(lambda style: violation_line(v, style))
    assert f'<span class="exact" title="exact: {exact}">≈3.97</span>' in page
    visible = re.sub(r"<[^>]*>", "", page)
    assert not LONG_DIGITS.search(visible) and len(visible) < 120


def test_picture_titles_and_trace_text_carry_no_long_fraction(graze):
    run, doc = graze
    svg = frame_svg(run, 1, doc)
    assert "≈3.97" in svg and "closest squared centre distance" in svg
    assert not LONG_DIGITS.search(svg)
    lines = trace_lines(doc)
    assert any("closest squared centre distance ≈3.97" in line for line in lines)
    assert not any(LONG_DIGITS.search(line) for line in lines)
    assert "r1 (≈3.87, -3/2)" in lines[0]


def test_a_viewer_caption_has_the_exact_value_in_a_title(graze):
    _, doc = graze
    t = _trace("graze", doc, "no-collision")
    html = viewer(t)
    assert f'title="exact: {doc["violation"]["closest_distance2"]}"' in html
    caption = re.sub(r"<[^>]*>", "", html.split("<br>")[0])
    assert "≈3.97" in caption and not LONG_DIGITS.search(caption)


# --- deadlocks -----------------------------------------------------------------------------------

BULLET_4 = '"If B u C u D u E u F u G is empty and A u I is not empty"'


def test_the_deadlock_frame_names_each_robots_bullet():
    run = simulate(((0, 0), (0, 3), (1, 5)), make_model(), seed=0)
    assert run.outcome is Outcome.DEADLOCK and not run.rounds
    doc = _doc(run)
    pictures = frames(run, doc)
    end = pictures[-1]
    for line in ("r0: NoMovement bullet 4 (sees r1 in A)", "r1: NoMovement bullet 4 (sees r0 in I, r2 in A)"):
        assert line in end
    assert "r2: NoMovement bullet 4 (sees r1 in I)" in end
    assert "If B u C u D u E u F u G is empty and A u I is not empty" in end
    assert "NoMovement" not in pictures[0]  # the start picture is not the deadlock frame
    lines = trace_lines(doc)
    assert "  r1: NoMovement bullet 4 (sees r0 in I, r2 in A)" in lines
    assert f"  NoMovement bullet 4: {BULLET_4}" in lines


def test_a_deadlock_of_different_rules_names_each():
    # uncovered=stay: r0 sees r1 only in C (an uncovered case) and stays; r1 sees r0 in F.
    model = make_model(uncovered="stay")
    run = simulate(((0, 0), (2, 1)), model, seed=0)
    assert run.outcome is Outcome.DEADLOCK
    lines = trace_lines(_doc(run))
    assert "  r0: uncovered-stay (sees r1 in C)" in lines
    assert "  r1: NoMovement bullet 2 (sees r0 in F)" in lines
    assert '  NoMovement bullet 2: "If F is not empty"' in lines
    assert any(line.startswith("  uncovered-stay: uncovered=stay:") for line in lines)
    end = frames(run, _doc(run))[-1]
    assert "r0: uncovered-stay" in end and "r1: NoMovement bullet 2" in end


def test_no_stay_lines_outside_a_deadlock(graze):
    run, doc = graze
    assert not any("NoMovement" in line for line in trace_lines(doc))
    assert "NoMovement" not in frame_svg(run, 2, doc)


# --- the cross-model page --------------------------------------------------------------------------


def _trace(name: str, doc: dict[str, Any], lemma: str, source: str = "check") -> dict[str, Any]:
    return {
        "name": name,
        "path": f"../traces/{name}.json",
        "source": source,
        "lemma": lemma,
        "what": f"{len(doc['initial'])} robots",
        "verdict": "VIOLATED",
        "frames": [f"img/{name}-0.svg", f"img/{name}-1.svg"],
        "doc": doc,
    }


def _report(name: str, traces: list[dict[str, Any]], **readings: str) -> ModelReport:
    base = make_model(**readings)
    model = Model(name=name, options=base.options, parameters=base.parameters)
    lemmas = [{"lemma": t["lemma"], "verdict": "VIOLATED", "robots": len(t["doc"]["initial"])} for t in traces]
    return ModelReport(model, {"lemmas": lemmas}, {"obligations": []}, traces)


def _cards(page: str) -> dict[str, str]:
    parts = re.split(r'<div class="card" id="card-', page)[1:]
    return {p.split('"', 1)[0]: p for p in parts}


def test_each_card_shows_its_own_smallest_witness():
    deadlock2 = _doc(simulate(((0, 0), (1, 2)), make_model(), seed=0))
    deadlock3 = _doc(simulate(((0, 0), (0, 3), (1, 5)), make_model(), seed=0))
    split = _doc(simulate(((0, 0), (2, 1)), make_model(), seed=0))
    alpha = _report(
        "alpha",
        [_trace("alpha-check-progress-n3", deadlock3, "progress"), _trace("alpha-check-p-n2", deadlock2, "progress")],
    )
    beta = _report(
        "beta",
        [
            _trace("beta-check-progress-n2", deadlock2, "progress"),
            _trace("beta-check-connectivity-n2", split, "connectivity"),
        ],
        scheduler="centralized",
    )
    gamma = _report("gamma", [])
    page = cross_model_html([alpha, beta, gamma])
    cards = _cards(page)
    assert list(cards) == ["alpha", "beta", "gamma"]
    assert 'href="alpha/index.html">alpha</a></h3>' in cards["alpha"]
    assert 'class="viewer" id="alpha-check-p-n2"' in cards["alpha"]  # 2 robots before 3
    assert "alpha/img/alpha-check-p-n2-0.svg" in cards["alpha"] and "beta" not in cards["alpha"]
    # beta's smallest run is the one alpha's card shows: its card shows its next one instead
    assert 'class="viewer" id="beta-check-connectivity-n2"' in cards["beta"]
    assert "beta/img/beta-check-connectivity-n2-0.svg" in cards["beta"] and "alpha" not in cards["beta"]
    assert "whose run no model above shows" in cards["beta"]
    assert '<span class="nowrap">scheduler=</span><wbr><span class="nowrap">centralized</span>' in cards["beta"]
    assert 'class="viewer"' not in cards["gamma"] and "no counterexample" in cards["gamma"]


@pytest.fixture(scope="module")
def shipped(committed_reports) -> list[ModelReport]:
    reports = committed_reports  # conftest.py: read once a session, shared with test_browser.py
    assert len(reports) >= 2
    return reports


def test_the_shipped_cards_are_each_models_own(shipped):
    cards = _cards(cross_model_html(shipped))
    assert list(cards) == [r.model.name for r in shipped]
    for (report, trace, _), (name, card) in zip(featured(shipped), cards.items(), strict=True):
        assert report.model.name == name
        if trace is None:  # a model with no counterexample at all (the certified rule set): no frames
            assert not report.traces and "data-frames" not in card
            continue
        assert trace in report.traces
        frames_ = json.loads(re.search(r'data-frames="([^"]*)"', card)[1].replace("&quot;", '"'))
        assert frames_ and all(f.startswith(f"{name}/img/{name}-") for f in frames_)
    runs = [json.dumps([t["doc"][k] for k in ("initial", "rounds", "outcome")]) for _, t, _ in featured(shipped) if t]
    assert len(set(runs)) == len(runs)  # no two cards show the same run


def test_the_matrix_page_links_the_readings_and_wraps_verdicts(shipped):
    page = cross_model_html(shipped)
    matrix = page.split('<table class="matrix">', 1)[1].split("</table>", 1)[0]
    # HOLDS_WITHIN_BOUNDS on two lines that never break inside a word (it wrapped onto three at "_<wbr>")
    holds = '<span class="nowrap" title="HOLDS_WITHIN_BOUNDS">HOLDS</span><br><span class="rows">within bounds</span>'
    assert holds in matrix and "_<wbr>" not in matrix
    assert "HOLDS_WITHIN_BOUNDS" not in re.sub(r"<[^>]*>", "", matrix)
    # a reading's link breaks only after its '=', never inside the option's or the reading's name
    codes = re.findall(r'<a href="[^"]*#[^"]*"[^>]*>(<code>.*?</code>)</a>', matrix)
    assert codes
    for code in codes:
        halves = r'<code><span class="nowrap">[\w-]+=</span><wbr><span class="nowrap">[\w-]+</span></code>'
        assert re.fullmatch(halves, code), code
    assert "(check)" not in matrix and "(prove)" not in matrix  # grouped headers instead
    assert f'href="../{READINGS_DOC}#goal"' in matrix
    assert not LONG_DIGITS.search(re.sub(r'title="[^"]*"', "", page))
    assert f"]({f'../{READINGS_DOC}'})" in cross_model_markdown(shipped)


def test_a_prover_cell_says_its_counts_are_obligation_rows(shipped):
    """ "NOT PROVED" above "25 PROVED" needed the intro to decode: the cell says which is the lemma and what
    the counts are (issue 41)."""
    page = cross_model_html(shipped)
    cells = re.findall(r'<td class="[^"]*" title="[^"]*"><strong>(.*?)</td>', page)
    assert cells
    for cell in cells:
        assert cell.startswith("lemma "), cell
        if "<br>" in cell:  # counts follow: they are obligation rows
            assert '</strong><br><span class="rows">obligation rows:</span><br>' in cell, cell
    markdown = cross_model_markdown(shipped)
    assert "| lemma NOT PROVED; obligation rows: 25 PROVED |" in markdown
    assert "| NOT PROVED: " not in markdown and "| NOT ENCODED: " not in markdown


def test_the_matrix_says_why_a_model_has_no_prover_cells(shipped):
    page = cross_model_html(shipped)
    row = page.split('href="paper-async/index.html"', 1)[1].split("</tr>", 1)[0]
    assert f'<td class="notrun" colspan="{len(PROVER_LEMMAS)}"' in row
    assert "not run: the prover encodes round schedulers only" in row
    markdown = cross_model_markdown(shipped)
    assert "paper-async: no prover cells, not run: the prover encodes round schedulers only" in markdown
    others = page.split('href="paper/index.html"', 1)[1].split("</tr>", 1)[0]
    assert "notrun" not in others  # a model the prover runs has its four cells


def test_a_model_page_opens_with_an_index_that_links_every_counterexample(shipped):
    report = next(r for r in shipped if r.model.name == "paper")
    html_page = model_html(report)
    index = html_page.split('<ul class="index">', 1)[1].split("</ul>", 1)[0]
    assert html_page.index('<ul class="index">') < html_page.index("<table")  # above the first table
    targets = re.findall(r'href="#([^"]+)"', index)
    assert sorted(targets) == sorted(t["name"] for t in report.traces)
    for name in targets:
        assert f'<div class="viewer" id="{name}"' in html_page
    markdown = model_markdown(report)
    assert markdown.index(f"Counterexamples ({len(report.traces)}, pictures below):") < markdown.index("| robots |")
    for t in report.traces:  # each link is the anchor a Markdown renderer gives the trace's heading
        heading = f"### {t['name']}"
        anchor = re.sub(r"[^a-z0-9 _-]", "", t["name"].lower())
        assert heading in markdown and f"(#{anchor})" in markdown
    assert "truncated = the search stopped at its state or memory bound" in markdown
    assert "robots = the robots an obligation names besides r" in markdown
    assert "| 1 round |" in markdown and "| 1 rounds |" not in markdown


# --- the readings catalogue ------------------------------------------------------------------------


def test_docs_readings_is_the_generated_catalogue():
    shipped_doc = (ROOT / READINGS_DOC).read_text(encoding="utf-8")
    assert shipped_doc == readings_markdown(), "docs/readings.md is stale: run python -m fatline_verify.docs"


def test_the_catalogue_lists_every_option_reading_and_default():
    text = readings_markdown()
    for name, spec in CATALOGUE.items():
        assert f"\n## {name}\n" in text and spec.quote in text
        for reading, meaning in spec.readings.items():
            default = " (default)" if reading == spec.default.value else ""
            assert f"- `{reading}`{default}: {meaning}\n" in text


def test_the_generator_writes_the_file_and_never_clobbers_another(tmp_path, capsys):
    target = tmp_path / "readings.md"
    assert docs_main([str(target)]) == 0
    assert target.read_text(encoding="utf-8") == readings_markdown()
    assert docs_main([str(target)]) == 0  # its own output is rewritten
    other = tmp_path / "notes.md"
    other.write_text("mine")
    assert docs_main([str(other)]) == 2
    assert other.read_text() == "mine"
    assert "not a page" in capsys.readouterr().err
