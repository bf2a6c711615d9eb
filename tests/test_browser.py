"""The report as a person uses it: open reports/index.html in headless Chromium, step through a
counterexample with the viewer's buttons, check the counter and the picture change, save a screenshot.

Needs Debian's ``chromium`` and ``chromium-driver`` (``.ci/run`` installs them). Skipped where they
are missing, except under CI, where their absence is a failure.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CHROMIUM = shutil.which("chromium")
DRIVER = shutil.which("chromedriver")


@pytest.fixture
def browser(tmp_path):
    if not (CHROMIUM and DRIVER):
        if os.environ.get("CI"):
            pytest.fail("chromium and chromedriver are required under CI (.ci/run installs them)")
        pytest.skip("chromium / chromedriver not installed")
    webdriver = pytest.importorskip("selenium.webdriver")
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in (
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        f"--user-data-dir={tmp_path / 'profile'}",
        "--window-size=1200,1400",
    ):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    try:
        yield driver
    finally:
        driver.quit()


def test_step_through_a_counterexample(browser, tmp_path):
    from selenium.webdriver.common.by import By

    browser.get((ROOT / "reports" / "index.html").as_uri())
    viewer = browser.find_elements(By.CSS_SELECTOR, ".viewer")[0]
    counter = viewer.find_element(By.CSS_SELECTOR, ".counter")
    img = viewer.find_element(By.TAG_NAME, "img")
    first_src, first_count = img.get_attribute("src"), counter.text
    assert first_count.startswith("frame 1 / ")
    assert browser.execute_script("return arguments[0].complete && arguments[0].naturalWidth > 0", img)
    viewer.find_element(By.CSS_SELECTOR, ".next").click()
    assert counter.text.startswith("frame 2 / ")
    assert img.get_attribute("src") != first_src
    assert browser.execute_script("return arguments[0].complete && arguments[0].naturalWidth > 0", img)
    viewer.find_element(By.CSS_SELECTOR, ".prev").click()
    assert counter.text == first_count and img.get_attribute("src") == first_src
    shot = tmp_path / "report.png"
    browser.save_screenshot(str(shot))
    assert shot.stat().st_size > 10_000


def _render_fresh(tmp_path: Path, reports: list) -> Path:
    """The report pages as this code renders them from the committed results (``reports``: conftest.py's
    ``committed_reports``), in ``tmp_path``; the pictures are the committed ones (linked), so the page
    is what a regenerated report shows."""
    from fatline_verify.report.build import stamp
    from fatline_verify.report.pages import ASSETS, cross_model_html, model_html

    out = tmp_path / "reports"
    out.mkdir()
    (tmp_path / "docs").symlink_to(ROOT / "docs")
    for name, text in ASSETS.items():
        (out / name).write_text(stamp(name, text), encoding="utf-8")
    for r in reports:
        (out / r.model.name).mkdir()
        (out / r.model.name / "img").symlink_to(ROOT / "reports" / r.model.name / "img")
        (out / r.model.name / "index.html").write_text(model_html(r), encoding="utf-8")
    (out / "index.html").write_text(cross_model_html(reports), encoding="utf-8")
    return out


def test_the_pages_fit_a_1400_px_window(browser, tmp_path, committed_reports):
    """The matrix page (and every model page) has no horizontal scroll bar at 1400 px, and the
    matrix stays inside the page's column."""
    out = _render_fresh(tmp_path, committed_reports)
    browser.set_window_size(1400, 1000)
    pages = [out / "index.html", *sorted(out.glob("*/index.html"))]
    for page in pages:
        browser.get(page.as_uri())
        scroll, client = browser.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth]"
        )
        assert client >= 1300 and scroll <= client, (page.relative_to(out), scroll, client)
    browser.get((out / "index.html").as_uri())
    table, body = browser.execute_script(
        "var t = document.querySelector('table.matrix').getBoundingClientRect();"
        "var s = getComputedStyle(document.body), b = document.body.getBoundingClientRect();"
        "return [t.right, b.right - parseFloat(s.paddingRight)]"
    )
    assert table <= body + 1
    shot = tmp_path / "matrix-1400.png"
    browser.save_screenshot(str(shot))
    assert shot.stat().st_size > 10_000


BROKEN_WORDS = """
var broken = [];
document.querySelectorAll(arguments[0]).forEach(function (cell) {
  var walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
  for (var node = walker.nextNode(); node; node = walker.nextNode()) {
    var re = /[^\\s\\u00a0]+/g, m;
    while ((m = re.exec(node.data)) !== null) {
      var range = document.createRange();
      range.setStart(node, m.index);
      range.setEnd(node, m.index + m[0].length);
      if (range.getClientRects().length > 1) { broken.push(m[0]); }
    }
  }
});
return broken;
"""
"""The words of the cells ``arguments[0]`` selects that a line break cuts in two (a word spans two boxes)."""


def test_no_verdict_lemma_or_number_is_broken_across_lines_at_1400_px(browser, tmp_path, committed_reports):
    """The prover's table and the matrix at 1400 px: "VIOLATED", "connectivity", a model's or a case's
    name, a count each stay on one line (a case's name may break after a dot; HOLDS_WITHIN_BOUNDS at its
    underscores, which are separate text around <wbr>; a reading such as band_overlap=vertical-first in
    the matrix's narrow readings column, at its hyphens)."""
    out = _render_fresh(tmp_path, committed_reports)
    browser.set_window_size(1400, 1000)
    for page in [out / "index.html", *sorted(out.glob("*/index.html"))]:
        browser.get(page.as_uri())
        cells = (
            "td.nw, table:not(.matrix) td.VIOLATED, table:not(.matrix) td.PROVED, .matrix td:not(.readings), .matrix th"
        )
        broken = browser.execute_script(BROKEN_WORDS, cells)
        assert not broken, (page.relative_to(out), broken[:10])
    browser.get((out / "paper" / "index.html").as_uri())
    assert (
        browser.execute_script(BROKEN_WORDS, "td.nw") == []
        and browser.execute_script("return document.querySelectorAll('td.nw').length") > 100
    )


def test_a_model_page_opens_with_an_index_of_its_counterexamples(browser, tmp_path, committed_reports):
    """The first counterexample is a click away: the index is above the first table, each link lands on
    its viewer."""
    from selenium.webdriver.common.by import By

    out = _render_fresh(tmp_path, committed_reports)
    browser.set_window_size(1400, 1000)
    browser.get((out / "paper" / "index.html").as_uri())
    index_top, table_top = browser.execute_script(
        "return [document.querySelector('ul.index').getBoundingClientRect().top,"
        " document.querySelector('table').getBoundingClientRect().top]"
    )
    assert index_top < table_top < 1000  # on the first screen
    links = browser.find_elements(By.CSS_SELECTOR, "ul.index a")
    viewers = browser.find_elements(By.CSS_SELECTOR, ".viewer")
    assert len(links) == len(viewers) > 10
    links[0].click()
    target = links[0].get_attribute("href").split("#", 1)[1]
    top = browser.execute_script(f"return document.getElementById('{target}').getBoundingClientRect().top")
    assert abs(top) < 5  # scrolled to that viewer
