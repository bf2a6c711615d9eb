"""The progress layer off a terminal: plain lines at the times asked, the stage's own counts (a stage
that counts nothing shows its seconds; one without an ETA, its elapsed time and what runs now)."""

from __future__ import annotations

import io
import re
import time

from fatline_verify.progress import Progress


def _lines(stream: io.StringIO) -> list[str]:
    return [line for line in stream.getvalue().splitlines() if line]


def test_a_pipe_gets_its_first_line_within_first_and_then_every_few_seconds():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, first=0.2, every=0.5) as bar:
        bar.stage("n=3: level 2", total=1000)
        bar.update(250, note="2,000 states")
        time.sleep(0.45)
        first = _lines(stream)
        time.sleep(0.7)
    assert len(first) == 1, first
    expected = r"fatline: n=3: level 2: 250/1,000 \(25%\) states, [\d,]+/s, ETA [\d,]+ s, [\d,]+ MB, 2,000 states"
    assert re.fullmatch(expected, first[0]), first[0]
    assert len(_lines(stream)) == 2  # one more after `every`


def test_the_default_first_line_waits_a_whole_interval():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, every=0.6) as bar:
        bar.stage("quick", total=10)
        time.sleep(0.3)
    assert _lines(stream) == []  # a short run prints nothing


def test_a_stage_that_counts_nothing_shows_its_seconds_not_a_rate():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, first=0.3, every=10) as bar:
        bar.stage("n=2: compiling kernels, first run only", timer=True)
        time.sleep(0.5)
    (line,) = _lines(stream)
    assert re.fullmatch(r"fatline: n=2: compiling kernels, first run only: \d+ s, [\d,]+ MB", line), line
    assert "0/s" not in line and "states" not in line


def test_without_eta_the_line_has_the_elapsed_time_and_the_live_note():
    stream = io.StringIO()
    started = time.monotonic() - 42
    with Progress(unit="obligations", stream=stream, tty=False, first=0.2, every=10) as bar:
        bar.stage(
            "paper: proving", total=118, eta=False, live=lambda: f"running x/y for {time.monotonic() - started:.0f} s"
        )
        bar.update(3, note="")
        time.sleep(0.4)
    (line,) = _lines(stream)
    assert line.startswith("fatline: paper: proving: 3/118 (3%) obligations, "), line
    assert "ETA" not in line and "/s" not in line
    assert re.search(r"running x/y for 4[23] s$", line), line


def test_quiet_prints_nothing():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, enabled=False, first=0, every=0.1) as bar:
        bar.stage("anything", total=5)
        bar.update(2)
        time.sleep(0.3)
    assert stream.getvalue() == ""
