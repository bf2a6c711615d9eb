"""The progress layer off a terminal: plain lines at the times asked, the stage's own counts (a stage
that counts nothing shows its seconds; one without an ETA, its elapsed time and what runs now)."""

from __future__ import annotations

import io
import re
import time

from fatline_verify.progress import Progress, duration_text, estimate, rate_text


def _lines(stream: io.StringIO) -> list[str]:
    return [line for line in stream.getvalue().splitlines() if line]


def test_a_pipe_gets_its_first_line_within_first_and_then_every_few_seconds():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, first=0.2, every=0.5) as bar:
        bar.stage("n=3: level 2", total=100_000)
        time.sleep(0.05)
        bar.update(250, note="2,000 states")  # 250 in 0.05 s: the other 99,750 take minutes
        time.sleep(0.4)
        first = _lines(stream)
        time.sleep(0.7)
    assert len(first) == 1, first
    expected = (
        r"fatline: n=3: level 2: 250/100,000 \(0%\) states, [\d,]+/s, ETA [\d,]+ (s|min), [\d,]+ MB, 2,000 states"
    )
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


# --- the rate and the ETA (issue 41: "2/3 (67%) robot counts, 0/s" while the ETA grew without end) ---------


def test_a_slow_rate_is_said_as_seconds_each_never_zero_a_second():
    assert rate_text(2 / 60) == "30 s each"
    assert rate_text(1 / 600) == "10 min each"
    assert rate_text(2.5) == "2.5/s"
    assert rate_text(12_345.6) == "12,346/s"
    assert "0/s" not in rate_text(0.001)


def test_nothing_done_has_no_rate_and_no_eta():
    assert estimate(0, 100, started=0.0, last=0.0, now=50.0) == (None, None)


def test_the_eta_is_the_remaining_units_at_the_rate_done_and_counts_down():
    # 25 of 100 done in the first 10 s: 75 more take 30 s from then
    rate, left = estimate(25, 100, started=0.0, last=10.0, now=10.0)
    assert rate == 2.5 and left == 30.0
    # 12 s later, nothing new: the ETA has counted down, the average rate fallen
    rate, left = estimate(25, 100, started=0.0, last=10.0, now=22.0)
    assert left == 18.0 and rate == 25 / 22


def test_an_overdue_eta_is_dropped_not_grown():
    """Past its estimate with nothing new the ETA is gone; it never grows while nothing moves."""
    etas = [estimate(2, 3, started=0.0, last=20.0, now=now)[1] for now in (20.0, 25.0, 29.0, 31.0, 100.0, 1000.0)]
    assert etas[:3] == [10.0, 5.0, 1.0]
    assert etas[3:] == [None, None, None]
    shown = [e for e in etas if e is not None]
    assert shown == sorted(shown, reverse=True)


def test_the_eta_converges_on_steady_work():
    """Units done at a steady pace: each update's ETA is the true time left."""
    for done in range(1, 10):
        _, left = estimate(done, 10, started=0.0, last=done * 4.0, now=done * 4.0)
        assert left == (10 - done) * 4.0


def test_without_a_total_there_is_a_rate_and_no_eta():
    assert estimate(5_000, None, started=0.0, last=2.0, now=2.0) == (2_500.0, None)


def test_durations_read_in_the_unit_that_fits():
    assert [duration_text(s) for s in (45, 600, 9000)] == ["45 s", "10 min", "2.5 h"]


def test_follow_starts_a_stage_per_label_and_counts_without_a_total():
    stream = io.StringIO()
    with Progress(unit="states", stream=stream, tty=False, first=0.25, every=10) as bar:
        bar.follow("3 robots: states by one mover", 0)
        time.sleep(0.05)
        bar.follow("3 robots: states by one mover", 4_000)
        time.sleep(0.35)
    (line,) = _lines(stream)
    assert re.fullmatch(r"fatline: 3 robots: states by one mover: 4,000 states, [\d,]+/s, [\d,]+ MB", line), line


def test_a_sweep_step_shows_the_rate_of_what_it_counts():
    """While a closure replays, the judgements stand still: the step's own count moves, with its rate."""
    from fatline_verify.sweep.check import Doing

    doing = Doing()
    doing.set("check 1: replaying the connectivity counterexample", "replays")
    assert str(doing) == "check 1: replaying the connectivity counterexample, 0 replays"
    doing.since -= 10
    doing.tick(5_000)
    expected = r"check 1: replaying the connectivity counterexample, 5,000 replays \((49\d|500)/s\)"
    assert re.fullmatch(expected, str(doing))


def test_regress_reports_each_trace_as_it_loads(tmp_path):
    """regress loads and schema-checks every trace before the first replay: a stage of its own, one step
    per file (10,000 traces took 52 s of silence)."""
    import shutil

    from fatline_verify.cli.regress import _files, collect
    from tests.hostile import ROOT

    for name in ("paper-check-connectivity-n2.json", "paper-check-progress-n2.json"):
        shutil.copy(ROOT / "reports" / "traces" / name, tmp_path / name)
    seen: list[str] = []
    entries, skipped = collect(str(tmp_path), _files(str(tmp_path)), None, seen.append)
    assert seen == ["paper-check-connectivity-n2.json", "paper-check-progress-n2.json"]
    assert len(entries) == 2 and skipped == 0
