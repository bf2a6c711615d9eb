"""``fatline prove``'s output a terminal can show: one short row per obligation (obligation, verdict,
seconds, a short reason), everything else in ``-v`` and ``results.json``; progress that says how long
the running obligations have taken, not a rate or an ETA."""

from __future__ import annotations

import functools
import json
import time
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.cli import prove as prove_cli
from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.progress import Progress
from fatline_verify.prove import prover
from fatline_verify.prove.prover import ProofResult
from fatline_verify.prove.tasks import row_key
from fatline_verify.prove.text import SHORT_REASON, prove_counts, prove_lines, short_reason

ROOT = Path(__file__).resolve().parent.parent
SHIPPED = sorted(p.parent.name for p in (ROOT / "proofs").glob("*/results.json"))


@pytest.mark.parametrize(
    ("reason", "short"),
    [
        (
            "collision, from an initial configuration of 3 robots (an earlier run's counterexample, replayed first, "
            "replayed)",
            "collision, from 3 robots",
        ),
        (
            "unsat over the reals: holds for swarms of every size (the header's argument) (shown on its linearization "
            "after 0 refinement(s): each solution satisfies its exact tangent lines and sector half-planes, which "
            "nothing does)",
            "unsat: holds for every swarm size",
        ),
        ("the case never fires under these readings (vacuous)", "vacuous: the case never fires"),
        (
            "r moves to (73/30, -1) and is not closer to the robot at (73/30, 31/10) in B, from an initial "
            "configuration of 3 robots (an earlier run's counterexample, replayed first, replayed)",
            "r is not closer to the robot in B, from 3 robots",
        ),
        ("solver: unknown (after (nested) parentheses) at last", "solver: unknown at last"),
        ("an aside (never closed", "an aside (never closed"),
    ],
)
def test_a_short_reason_drops_the_asides_and_keeps_the_gist(reason, short):
    assert short_reason(reason) == short


def test_a_long_reason_is_cut_at_a_word_with_an_ellipsis():
    reason = "stopped after 185 s of wall clock (the limit is 180 s): the solver did not keep to its budget; rerun"
    got = short_reason(reason)
    assert len(got) <= SHORT_REASON and got.endswith("…") and got.startswith("stopped after 185 s of wall clock:")
    assert not got[:-1].endswith(" ")


@pytest.mark.parametrize("name", SHIPPED)
def test_the_default_rows_fit_a_terminal_and_v_has_everything(name):
    rows = json.loads((ROOT / "proofs" / name / "results.json").read_text())["obligations"]
    model = load_model(name)
    lines = prove_lines(model, rows, f"proofs/{name}")
    header = next(k for k, line in enumerate(lines) if line.startswith("obligation "))
    table = lines[header : header + 2 + len(rows)]
    assert table[0].split() == ["obligation", "verdict", "seconds", "reason"]
    assert max(len(line) for line in table) <= 140, max(table, key=len)
    for row, line in zip(rows, table[2:], strict=True):
        assert line.startswith(row_key(row) + " ") and row["verdict"] in line
    assert "(an earlier run's counterexample" not in "\n".join(lines)  # the asides are in -v and the JSON
    verbose = "\n".join(prove_lines(model, rows, f"proofs/{name}", verbose=True))
    for row in rows:
        assert row["reason"] in verbose
        if row.get("trace"):
            assert row["trace"] in verbose
    assert "robots = the robots an obligation names besides r" in verbose


def test_counts_say_one_obligation():
    rows = [
        {"lemma": "rma-fixed", "verdict": "PROVED"},
        {"lemma": "approach", "verdict": "PROVED"},
        {"lemma": "approach", "verdict": "VIOLATED"},
    ]
    assert prove_counts(rows) == [
        "rma-fixed: 1 obligation: 1 PROVED",
        "approach: 2 obligations: 1 PROVED, 1 VIOLATED",
    ]


def test_the_running_note_names_the_longest_running_first():
    now = time.monotonic()
    note = prove_cli.running_note({"a/x": now - 3, "b/y": now - 75, "c/z": now - 1})
    assert note == "running b/y for 75 s, a/x for 3 s and 1 more"
    assert prove_cli.running_note({}) == ""


def _slow_prove(model, lemmas=(), *, slots, timeout, out, tasks=None, on_result=None, progress=None, on_start=None,
                **_):  # fmt: skip
    """A stand-in for the prover: the first obligation takes a second, the others none."""
    results = []
    for k, task in enumerate(tasks or prover.tasks_for(model, lemmas)):
        if on_start:
            on_start(task.key)
        if k == 0:
            time.sleep(1.2)
        case = getattr(task, "name", "any")
        reason = "unsat over the reals: holds for swarms of every size (the header's argument) (a long aside)"
        r = ProofResult(task.lemma, task.form, case, Verdict.PROVED, slots, True, 0.0, reason, "", case=case)
        results.append(r)
        if on_result:
            on_result(r)
        if progress:
            progress(task.key)
    return results


def test_prove_progress_shows_the_seconds_on_the_running_obligation(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(prover, "prove", _slow_prove)
    monkeypatch.setattr(prove_cli, "Progress", functools.partial(Progress, first=0.3, every=10))
    code = main(["prove", "paper", "--lemma", "rma-fixed", "--out", str(tmp_path / "p")])
    out, err = capsys.readouterr()
    assert code == 0, err
    tasks = prover.tasks_for(load_model("paper"), (prover.Lemma.RMA_FIXED,))  # seen and on-rma, per moving case
    first = tasks[0].key
    line = next(line for line in err.splitlines() if line.startswith("fatline: paper: proving: "))
    assert line.startswith(f"fatline: paper: proving: 0/{len(tasks)} (0%) obligations, ") and "ETA" not in line, line
    assert f"running {first} for 0 s" in line or f"running {first} for 1 s" in line, line
    assert "unsat: holds for every swarm size" in out and "(a long aside)" not in out
    assert main(["prove", "paper", "--lemma", "rma-fixed", "--out", str(tmp_path / "p"), "-v", "-q"]) == 0
    out, err = capsys.readouterr()
    assert "(a long aside)" in out and err == ""
