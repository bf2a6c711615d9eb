"""``fatline sweep``: one witness judged under a whole product of readings, as each one alone would be."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.cli import main
from fatline_verify.lemmas.properties import SAFETY, Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.sweep.cover import Recorder, cover, refutes
from fatline_verify.sweep.run import HOLDS, REFUTED, Sweep, SweepBounds, check_combo
from fatline_verify.sweep.space import Space, bearing, default_vary

ROOT = Path(__file__).resolve().parent.parent
TRACES = ROOT / "reports" / "traces"


def brute_force(space: Space, judge) -> np.ndarray:
    return np.array([judge(space.model(space.combo(i))) for i in range(space.size)])


def test_cover_equals_one_judgement_per_combination_for_a_known_function():
    space = Space(load_model("paper"), ("bands", "vacant", "path", "contact"))

    def judge(model) -> bool:
        o = model.options
        if str(o.bands) == "disc":
            return str(o.contact) == "strict"
        return str(o.path) != "straight"

    got = cover(space, np.ones(space.size, dtype=bool), judge)
    assert (got.refuted == brute_force(space, judge)).all()
    assert got.replays == 2 + 3  # one leaf per (disc, contact) and per (centre, path); vacant never read


@pytest.mark.parametrize(
    ("trace", "vary"),
    [
        ("paper-check-no-collision-n3", ("quadrants", "visibility", "vacant", "scenario4_drop", "timing", "contact")),
        ("paper-check-connectivity-n2", ("bands", "visibility", "psi_right", "uncovered", "scenario4_free_path")),
        ("paper-check-approach-n2", ("quadrants", "bands", "search_order", "scenario4_drop", "goal")),
        ("paper-check-termination-n4", ("visibility", "scenario4_guard", "goal")),
    ],
)
def test_cover_of_a_witness_equals_its_replay_under_each_combination(trace, vary):
    doc = json.loads((TRACES / f"{trace}.json").read_text())
    lemma = Lemma(doc["violation"]["property"])
    space = Space(load_model("paper"), bearing(lemma, vary))
    among = np.ones(space.size, dtype=bool)
    among[::5] = False  # only the combinations asked about
    got = cover(space, among, lambda m: refutes(doc, lemma, m))
    want = brute_force(space, lambda m: refutes(doc, lemma, m)) & among
    assert (got.refuted == want).all()
    assert got.refuted.any()  # the witness refutes its own readings at least
    assert got.replays < among.sum()


def test_a_step_lemma_never_reads_the_goal():
    for name in ("paper-check-no-collision-n3", "paper-check-connectivity-n3"):
        doc = json.loads((TRACES / f"{name}.json").read_text())
        lemma = Lemma(doc["violation"]["property"])
        assert lemma in SAFETY
        model = load_model("paper")
        recorder = Recorder(model.options, default_vary(model))
        assert refutes(doc, lemma, replace(model, options=recorder))  # type: ignore[arg-type]
        assert "goal" not in recorder.reads
        assert "visibility" in recorder.reads


def test_the_recorder_counts_a_method_as_reading_everything():
    model = load_model("paper")
    recorder = Recorder(model.options, ("bands", "goal"))
    recorder.as_dict()
    assert set(recorder.reads) == {"bands", "goal"}


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_sweep_cli_covers_a_small_space_and_resumes(tmp_path, capsys):
    out = tmp_path / "s"
    argv = ("sweep", "paper", "--vary", "contact,timing,goal", "--robots", "2", "--window", "5x5", "--out", str(out))
    code, stdout, err = run(capsys, *argv, "-q")
    assert code in (0, 1), err
    data = json.loads((out / "paper" / "sweep.json").read_text())
    assert data["format"] == "fatline-sweep"
    rows = {r["lemma"]: r for r in data["lemmas"]}
    assert rows["no-collision"]["combinations"] == 4  # goal does not bear on a step lemma
    assert rows["termination"]["combinations"] == 12
    for r in rows.values():
        assert r["open"] == 0
        assert r["refuted"] + r["holds"] + r["inconclusive"] == r["combinations"]
    for w in data["witnesses"]:
        trace = json.loads((out / "paper" / w["trace"]).read_text())
        lemma = Lemma(w["lemma"])
        found = load_model("paper").options.with_(**w["found_under"])
        assert refutes(trace, lemma, replace(load_model("paper"), options=found))
    assert "readings" in stdout and "checks" in stdout
    checks = len(data["checks"])
    code, stdout, err = run(capsys, *argv)
    assert "resuming" in err
    assert len(json.loads((out / "paper" / "sweep.json").read_text())["checks"]) == checks
    argv = ["sweep", "paper", "--vary", "contact", "--robots", "2", "--window", "5x5", "--out", str(out)]
    code, _, err = run(capsys, *argv)
    assert code == 2 and "other settings" in err


def test_a_sweep_writes_a_report_page_with_each_counterexample_and_where_a_lemma_survives(tmp_path, capsys):
    out = tmp_path / "s"
    argv = ("sweep", "paper", "--vary", "path,contact", "--lemma", "no-collision,rma-fixed", "--robots", "2..3")
    code, stdout, err = run(capsys, *argv, "--window", "5x5", "--out", str(out), "-q")
    assert code in (0, 1), err
    data = json.loads((out / "paper" / "sweep.json").read_text())
    page = (out / "paper" / "index.html").read_text()
    readme = (out / "paper" / "README.md").read_text()
    assert f"report page: {out / 'paper' / 'index.html'}" in stdout
    assert "<!-- generated by fatline-verify: fatline sweep -->" in page.splitlines()[0]
    for row in data["lemmas"]:
        assert row["lemma"] in page and row["lemma"] in readme
    assert data["witnesses"], "paper's no-collision fails at 3 robots under some of these readings"
    mine = sum(1 for w in data["witnesses"] if w["lemma"] == "no-collision")
    for k in range(1, mine + 1):
        for tag in ("start", "end"):
            picture = out / "paper" / "img" / f"no-collision-{k}-{tag}.svg"
            assert "<svg" in picture.read_text()
            assert f"img/{picture.name}" in page
    holds = next(r for r in data["lemmas"] if r["lemma"] == "rma-fixed")["holds"]
    assert holds and f"Where it holds within the bounds: {holds:,} readings" in readme
    # --max-checks 0 rewrites the page from what is saved, without a check
    (out / "paper" / "index.html").unlink()
    code, _, err = run(capsys, *argv, "--window", "5x5", "--out", str(out), "--max-checks", "0", "-q")
    assert (out / "paper" / "index.html").read_text() == page
    assert len(json.loads((out / "paper" / "sweep.json").read_text())["checks"]) == len(data["checks"])


def test_a_sweep_does_not_overwrite_a_page_it_did_not_write(tmp_path, capsys):
    out = tmp_path / "s"
    (out / "paper").mkdir(parents=True)
    (out / "paper" / "index.html").write_text("my notes")
    code, _, err = run(capsys, "sweep", "paper", "--vary", "contact", "--robots", "2", "--out", str(out))
    assert code == 2 and "index.html" in err and len(err.strip().splitlines()) == 1
    assert (out / "paper" / "index.html").read_text() == "my notes"
    assert not (out / "paper" / "sweep.json").exists()


@pytest.mark.parametrize(
    ("argv", "fragment"),
    [
        (("--vary", "nonsense"), "vary='nonsense': unknown option"),
        (("--vary", "scheduler"), "the scheduler is fixed"),
        (("--vary", "motion"), "means nothing under scheduler=ssync"),
        (("--vary", "bands,bands"), "named twice"),
        (("--vary", ","), "expected a comma-separated list"),
        (("--lemma", "happiness"), "lemma='happiness': expected a comma-separated list of connectivity"),
        (("--lemma", "approach,approach"), "expected each lemma once"),
        (("--robots", "0"), "robots"),
        (("--max-checks", "-1"), "max-checks"),
    ],
)
def test_sweep_refuses_bad_input_in_one_line(argv, fragment, capsys, tmp_path):
    code, _, err = run(capsys, "sweep", "paper", "--out", str(tmp_path / "x"), *argv)
    assert code == 2
    assert len(err.strip().splitlines()) == 1, err
    assert fragment in err
    assert not (tmp_path / "x").exists()


def test_every_sweep_verdict_is_what_the_checker_says_at_that_combination(tmp_path):
    """The sweep closes combinations it never checked (covered by a witness, or exploring the same
    graph as a checked one); at each of them the checker, run there, gives the same verdict."""
    model = load_model("paper")
    bounds = SweepBounds((2, 3), (6, 6))
    sweep = Sweep(Space(model, ("path", "timing", "contact", "goal")), bounds, tmp_path / "s")
    assert sweep.run()
    equivalent = 0
    verdicts: dict = {}  # per model: a step lemma's space (no goal) meets the same models as the others'
    for lemma in sweep.lemmas:
        space = sweep.spaces[lemma]
        for index in range(space.size):
            combo = space.combo(index)
            at = space.model(combo)
            if at not in verdicts:  # the checker's verdicts depend on the model and the bounds alone
                verdicts[at] = check_combo(at, bounds, combo).verdicts
            got = verdicts[at][lemma]
            expected = {REFUTED: Verdict.VIOLATED, HOLDS: Verdict.HOLDS_WITHIN_BOUNDS}.get(
                int(sweep.status[lemma][index]), Verdict.INCONCLUSIVE
            )
            assert got is expected, (lemma, space.text(combo))
        equivalent += int((sweep.status[lemma] == HOLDS).sum())
    assert len(sweep.checks) < sum(s.size for s in sweep.spaces.values())  # it did not check each one
    assert equivalent > len([c for c in sweep.checks if "HOLDS_WITHIN_BOUNDS" in c["verdicts"].values()])


def test_a_bound_nothing_escapes_from_decides_termination_where_the_window_alone_cannot(tmp_path, capsys):
    """Without --bound, successors leave the 7x7 window and termination is INCONCLUSIVE wherever
    progress holds; with --bound 11x11 nothing escapes and it holds there. The bound is saved, named on
    the page, and part of the sweep's settings (another bound is another sweep); a sweep without it
    keeps the fingerprint it had before the option existed."""
    argv = ("sweep", "paper", "--vary", "contact,goal,vacant", "--lemma", "progress,termination", "--robots", "2..3")
    rows = {}
    for name, extra in (("window", ()), ("bound", ("--bound", "11x11"))):
        code, _, err = run(capsys, *argv, "--window", "7x7", *extra, "--out", str(tmp_path / name), "-q")
        assert code in (0, 1), err
        data = json.loads((tmp_path / name / "paper" / "sweep.json").read_text())
        rows[name] = {r["lemma"]: r for r in data["lemmas"]}
        assert ("bound" in data["bounds"]) == (name == "bound")
    assert rows["window"]["progress"]["holds"] == rows["bound"]["progress"]["holds"] > 0
    assert rows["window"]["termination"]["inconclusive"] == rows["window"]["progress"]["holds"]
    assert rows["bound"]["termination"]["holds"] == rows["bound"]["progress"]["holds"]
    assert rows["bound"]["termination"]["inconclusive"] == 0
    assert "explored within 11x11" in (tmp_path / "bound" / "paper" / "index.html").read_text()
    code, _, err = run(capsys, *argv, "--window", "7x7", "--bound", "13x13", "--out", str(tmp_path / "bound"))
    assert code == 2 and "other settings" in err
    assert SweepBounds((2, 3), (7, 7)).as_json() == {"robots": [2, 3], "window": [7, 7], "max_states": None}
