"""``fatline sweep`` as a long run (issue 30): progress from the first second, every step saved as it
finishes, a stop after --max-time or an interrupt that keeps the finished steps, a resumed run that
ends as a fresh one, memory within --max-memory, and the new state files checked when read back."""

from __future__ import annotations

import functools
import io
import json
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.cli import main
from fatline_verify.cli import sweep as sweep_cli
from fatline_verify.model.config import load_model
from fatline_verify.progress import Progress
from fatline_verify.sweep.run import HOLDS, INCONCLUSIVE, REFUTED, Sweep, SweepBounds
from fatline_verify.sweep.space import Space

VARY = ("contact", "timing", "goal")
BOUNDS = SweepBounds((2, 2), (5, 5))
SMALL = ["paper", "--vary", ",".join(VARY), "--robots", "2", "--window", "5x5"]


def comparable(data: dict) -> dict:
    """A sweep.json without what measures the run rather than the sweep: the seconds each check took,
    the replays done (a resumed run forgets the remembered answers and replays them again) and the
    digest over both. Everything else, the digests of status.npz, known.npz and each trace included,
    must be equal."""
    data = {k: v for k, v in data.items() if k not in ("digest", "replays")}
    data["checks"] = [{k: v for k, v in c.items() if k != "seconds"} for c in data["checks"]]
    return data


def _sweep(out: Path) -> Sweep:
    return Sweep(Space(load_model("paper"), VARY), BOUNDS, out)


def test_a_sweep_stopped_after_every_step_ends_as_a_fresh_one(tmp_path):
    """A deadline already passed: each run makes exactly one step (one lemma closed from one check),
    saves it and stops; a new process (a new Sweep) resumes from the files alone. After as many runs as
    steps, sweep.json and every file it names are the fresh run's."""
    fresh = _sweep(tmp_path / "fresh")
    assert fresh.run()
    fresh.save()
    steps = len(fresh.checks) * len(fresh.lemmas)
    runs = 0
    while True:
        sweep = _sweep(tmp_path / "stepped")
        resumed = sweep.resume()
        assert resumed == (runs > 0)
        before = (len(sweep.checks), len(sweep.absorbed), sweep.open_count())
        done = sweep.run(deadline=time.monotonic() - 1)
        runs += 1
        assert (len(sweep.checks), len(sweep.absorbed), sweep.open_count()) != before or done  # it got on
        if done and not sweep.pending:
            break
        assert runs <= steps
        saved = json.loads(sweep.json_path.read_text())
        assert "pending" in saved or saved["checks"]  # a check under way is saved with the lemmas closed from it
    sweep.save()
    want, got = (json.loads((tmp_path / d / "sweep.json").read_text()) for d in ("fresh", "stepped"))
    assert comparable(got) == comparable(want)
    assert any(keys.size for keys in sweep.known.values())  # the spread closures ran (and were resumed)
    assert runs > len(fresh.checks)


def test_the_cli_stops_after_max_time_keeps_its_steps_and_resumes_to_the_fresh_result(tmp_path, capsys):
    argv = ["sweep", *SMALL, "-q"]
    assert main([*argv, "--out", str(tmp_path / "fresh")]) in (0, 1)
    codes = []
    for _ in range(40):
        codes.append(main([*argv, "--out", str(tmp_path / "stepped"), "--max-time", "0.001s"]))
        out = capsys.readouterr().out
        if codes[-1] != 3:
            break
        assert "stopped after --max-time 0.001s" in out and "the same command resumes" in out
    assert codes[-1] in (0, 1) and len(codes) > 2, codes
    want, got = (json.loads((tmp_path / d / "paper" / "sweep.json").read_text()) for d in ("fresh", "stepped"))
    assert comparable(got) == comparable(want)


def test_the_first_progress_line_comes_within_a_second_in_a_pipe(tmp_path, monkeypatch):
    """Off a terminal, the plan line (what is swept, what a check explores, the memory and time limits)
    comes before any check, and the counts follow within FIRST seconds while the first check runs."""
    stream = io.StringIO()
    monkeypatch.setattr(sweep_cli, "Progress", functools.partial(Progress, stream=stream, tty=False))
    argv = ["sweep", "paper", "--vary", "path,timing,contact,goal", "--robots", "2..3", "--window", "6x6"]
    result: list[int] = []
    runner = threading.Thread(target=lambda: result.append(main([*argv, "--out", str(tmp_path), "--max-time", "2s"])))
    started = time.monotonic()
    runner.start()
    first = second = None
    while runner.is_alive() and second is None:
        lines = [line for line in stream.getvalue().splitlines() if line.startswith("fatline: ")]
        if lines and first is None:
            first = time.monotonic() - started
        if len(lines) > 1 and second is None:
            second = time.monotonic() - started
        time.sleep(0.02)
    runner.join(timeout=120)
    assert result, "the sweep did not end"
    lines = stream.getvalue().splitlines()
    assert first is not None and first < 1.0, (first, lines[:3])
    assert lines[0].startswith("fatline: sweep of paper: 4 options varied, ") and "stops after 2 s" in lines[0]
    assert "memory up to " in lines[0] and "each check explores robots 2..3 in 6x6" in lines[0]
    assert any(line.startswith("fatline: judging: ") and " MB" in line for line in lines), lines[:5]


# slow tier: under the default suite's load (the other worker busy) this interrupt did not take effect
# within 30 s in every full run of 2026-11-28 (a check interrupted at n = 7 took over 50 s to exit with
# one busy core beside it), and its leftover process starved the tests after it; it passes alone
@pytest.mark.slow
def test_an_interrupt_keeps_the_saved_steps_and_the_rerun_ends_as_a_fresh_one(tmp_path):
    """SIGINT once the first step is saved: exit 130, the saved sweep is the last finished step's (it
    resumes), and the rerun ends where a fresh run ends."""
    argv = ["sweep", "paper", "--vary", "path,timing,contact,goal", "--robots", "2..3", "--window", "6x6", "-q"]
    cli = [sys.executable, "-m", "fatline_verify.cli"]
    proc = subprocess.Popen(
        [*cli, *argv, "--out", "stepped"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    saved = tmp_path / "stepped" / "paper" / "sweep.json"
    t0 = time.monotonic()
    while not saved.exists():
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() - t0 < 120
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "INTERRUPTED" in out
    kept = json.loads(saved.read_text())
    assert "pending" in kept or kept["checks"]
    assert subprocess.run([*cli, *argv, "--out", "stepped"], cwd=tmp_path, capture_output=True).returncode in (0, 1)
    assert subprocess.run([*cli, *argv, "--out", "fresh"], cwd=tmp_path, capture_output=True).returncode in (0, 1)
    want, got = (json.loads((tmp_path / d / "paper" / "sweep.json").read_text()) for d in ("fresh", "stepped"))
    assert comparable(got) == comparable(want)


@pytest.mark.parametrize("text", ["0", "-1s", "10x", "nan", "8d", ""])
def test_a_bad_max_time_is_refused_in_one_line(text, tmp_path, capsys):
    code = main(["sweep", *SMALL, "--out", str(tmp_path / "x"), "--max-time", text])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "max-time" in err, err
    assert not (tmp_path / "x").exists()


def test_max_memory_reaches_the_checks_the_memo_and_the_spread(tmp_path):
    """--max-memory is shared out: a check's search gets half (the checker's own guard), the memo and a
    spread's sets a quarter each (their bounds: tests/test_sweep_invariant.py). Within a tight budget the
    checks stop early and say INCONCLUSIVE, as check does; every definite verdict is the free run's."""
    space = Space(load_model("paper"), ("path", "timing", "contact", "goal"))
    bounds = SweepBounds((2, 3), (6, 6))
    free = Sweep(space, bounds, tmp_path / "free")
    assert free.run()
    tight = Sweep(space, bounds, tmp_path / "tight", max_memory=2**16)
    assert tight._check_bounds().max_memory == 2**15
    assert tight._memo.limit == 2**14
    tight.run(max_checks=3)
    cut = 0
    for lemma in free.lemmas:
        definite = np.isin(tight.status[lemma], (REFUTED, HOLDS))
        assert (tight.status[lemma][definite] == free.status[lemma][definite]).all(), lemma
        cut += int(((tight.status[lemma] == INCONCLUSIVE) & (free.status[lemma] != INCONCLUSIVE)).sum())
    assert cut > 0  # the checks' searches stopped at their share, INCONCLUSIVE as check says


def test_a_graph_equality_closure_out_of_work_closes_nothing():
    """``work``: past that many replays a graph-equality closure closes nothing (equality is known only
    once every signature was judged); with room, it closes what the free closure closes."""
    from fatline_verify.lemmas.properties import Verdict
    from fatline_verify.sweep.check import check_combo
    from fatline_verify.sweep.equivalent import same_exploration

    space = Space(load_model("paper"), ("path", "timing", "contact", "goal"))
    bounds = SweepBounds((2, 3), (6, 6))
    for i in range(space.size):
        found = check_combo(space.model(space.combo(i)), bounds, space.combo(i))
        held = [
            lemma for lemma, v in found.verdicts.items() if v is Verdict.HOLDS_WITHIN_BOUNDS and lemma in found.held
        ]
        if held:
            break
    reference, everything = space.model(space.combo(i)), np.ones(space.size, dtype=bool)
    free = same_exploration(space, everything, reference, list(found.explored), held[0])
    assert free.same.sum() > 1 and free.replays > 3
    assert not same_exploration(space, everything, reference, list(found.explored), held[0], work=3).same.any()
    roomy = same_exploration(space, everything, reference, list(found.explored), held[0], work=free.replays + 1)
    assert (roomy.same == free.same).all()
