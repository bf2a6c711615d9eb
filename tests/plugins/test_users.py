"""Rule sets written as a user might, through a real installed plug-in package (``tests/plugins/users``).

No verdict a rule set has not earned: a rule set with liveness rows but no safety encoding never gets
termination PROVED, a declared bound is not believed, and a rule set cannot borrow another's encoding,
by name or by object. Moves off the lattice: every engine checks them, with the same verdicts."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent
SITE = HERE / "users"


def fatline(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter with the plug-in package installed (on its path)."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(SITE), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


def test_liveness_rows_without_safety_never_give_termination(tmp_path: Path) -> None:
    """rush-right's liveness rows all prove, and it declares ``bounded_proved=True``; it collides, has no
    safety rows and nothing proves its bound: termination is NOT PROVED, naming each missing part."""
    got = fatline(
        "prove", str(SITE / "rush-right.toml"), "--out", str(tmp_path / "p"), "--json", str(tmp_path / "r.json"),
        "--coverage", "300",
    )  # fmt: skip
    assert got.returncode == 3, got.stderr  # nothing violated; the sampled coverage row is INCONCLUSIVE
    lines = got.stdout.splitlines()
    termination = next(line.strip() for line in lines if line.strip().startswith("termination: "))
    assert termination.startswith("termination: NOT PROVED: ")
    assert "no-collision: no obligations (the rule set has no safety encoding)" in termination
    assert "connectivity: no obligations (the rule set has no safety encoding)" in termination
    assert "component [-1, 0]: needs rma-fixed's seen rows PROVED (no rows)" in termination
    rows = {
        f"{r['lemma']}/{r['form']}": r["verdict"] for r in json.loads((tmp_path / "r.json").read_text())["obligations"]
    }
    # every solver row it has is proved, the cases cover a sample of its views: the parts are missing
    assert rows.pop("progress/coverage") == "INCONCLUSIVE"
    assert set(rows.values()) == {"PROVED"}
    # and the checker finds the collision that makes this matter
    check = fatline("check", str(SITE / "rush-right.toml"), "--robots", "2", "--traces", str(tmp_path / "t"))
    assert check.returncode == 1
    assert any(line.startswith("no-collision") and "VIOLATED" in line for line in check.stdout.splitlines())


def test_a_borrowed_encoding_is_refused_in_one_line(tmp_path: Path) -> None:
    for name, claimed in (("rush-borrow", "prover='paper'"), ("rush-borrow-object", "prover=Encoding('paper')")):
        got = fatline("prove", str(SITE / f"{name}.toml"), "--out", str(tmp_path / name))
        assert got.returncode == 2
        assert got.stdout == "" and got.stderr.count("\n") == 1
        assert got.stderr.startswith(f"fatline: error: rules={name!r}: {claimed} is the encoding of ")
        assert "not of this rule set's decide (users_fatline_plugin.decide)" in got.stderr
        assert not (tmp_path / name).exists()  # refused before any work
        # the rule set itself is fine for the checker
        check = fatline("check", str(SITE / f"{name}.toml"), "--robots", "2")
        assert check.returncode == 1 and "no-collision" in check.stdout


LEMMA_ROWS = ("connectivity", "no-collision", "progress", "rma-fixed", "approach", "termination")


def _verdicts(text: str) -> list[tuple[str, ...]]:
    return [tuple(line.split()[:3]) for line in text.splitlines() if line.split()[:1] and line.split()[0] in LEMMA_ROWS]


def test_moves_off_the_lattice_get_the_same_verdicts_under_every_engine(tmp_path: Path) -> None:
    """half-step moves half a radius at q = 1: the packed engines hand the run to the scalar engine in one
    line, the off-lattice successors are counted (never rounded onto the lattice), the verdicts agree."""
    got = {}
    for engine in ("scalar", "fast", "compiled"):
        run = fatline(
            "check", str(SITE / "half-step.toml"), "--engine", engine, "--json", str(tmp_path / f"{engine}.json")
        )
        assert run.returncode == 1, run.stderr
        assert "internal error" not in run.stderr
        got[engine] = _verdicts(run.stdout)
        stats = json.loads((tmp_path / f"{engine}.json").read_text())["searches"]
        assert {s["engine"] for s in stats} == {"scalar"}
        assert all(s["off_lattice"] > 0 for s in stats)
        handed = [line for line in run.stdout.splitlines() if "a decision off the model's lattice" in line]
        assert len(handed) == (0 if engine == "scalar" else len(stats))
    assert got["scalar"] == got["fast"] == got["compiled"] and len(got["scalar"]) == 2 * len(LEMMA_ROWS)


def test_a_rational_successor_is_never_rounded_onto_the_lattice() -> None:
    from fractions import Fraction

    from fatline_verify.model.config import load_model
    from fatline_verify.schedulers.systems import system_for

    system = system_for(load_model("paper"))
    assert system.exact_array(((Fraction(1, 2), 0), (3, 0))) is None
    assert system.exact_array(((Fraction(4, 2), 0), (3, 0))).tolist() == [[2, 0], [3, 0]]


def test_a_rule_set_of_its_own_setting_is_judged_by_its_own_lemmas_only(tmp_path: Path) -> None:
    """step-left moves its right-most robot left: Lemma 3 fails for it, and it does not claim Lemma 3. Its
    check judges the four lemmas it claims, and its runs go on past a step that moves the RMA; the same
    rules under the paper's six lemmas stop there."""
    check = fatline("check", str(SITE / "step-left.toml"), "--json", str(tmp_path / "own.json"))
    assert check.returncode == 1, check.stderr
    judged = {r["lemma"] for r in json.loads((tmp_path / "own.json").read_text())["lemmas"]}
    assert judged == {"no-collision", "connectivity", "progress", "termination"}
    paper = fatline("check", str(SITE / "step-left-paper.toml"), "--json", str(tmp_path / "paper.json"))
    assert paper.returncode == 1, paper.stderr
    rows = json.loads((tmp_path / "paper.json").read_text())["lemmas"]
    assert {r["lemma"] for r in rows} == set(LEMMA_ROWS)
    assert any(r["lemma"] == "rma-fixed" and r["verdict"] == "VIOLATED" for r in rows)
    # its own: the rma-fixed violations are followed (more states than under the paper's setting)
    own_states = sum(s["states"] for s in json.loads((tmp_path / "own.json").read_text())["searches"])
    paper_states = sum(s["states"] for s in json.loads((tmp_path / "paper.json").read_text())["searches"])
    assert own_states > paper_states, (own_states, paper_states)
    run = ("--init", "0,0 4,0 8,0", "--schedule", "2;1;2")
    own = fatline("simulate", str(SITE / "step-left.toml"), *run)
    assert "outcome after 3 rounds" in own.stdout and "rma-fixed" not in own.stdout
    stopped = fatline("simulate", str(SITE / "step-left-paper.toml"), *run)
    assert "outcome after 1 round: stopped at a violation" in stopped.stdout and "rma-fixed" in stopped.stdout


def test_a_setting_that_names_no_lemma_of_the_checker_is_refused_in_one_line() -> None:
    import pytest

    from fatline_verify.rules.registry import RuleSet

    def stay(snapshot, model):  # pragma: no cover - never called
        raise AssertionError

    with pytest.raises(ValueError, match=r"lemmas='gathering': not a lemma of the checker; expected some of"):
        RuleSet("x", stay, "x", lemmas=("no-collision", "gathering")).check_setting()
    with pytest.raises(ValueError, match=r"safety='rma-fixed': not one of its applicable step lemmas"):
        RuleSet("x", stay, "x", lemmas=("no-collision",), safety=("rma-fixed",)).check_setting()
    with pytest.raises(ValueError, match=r"lemmas='no-collision': expected a tuple of lemma names"):
        RuleSet("x", stay, "x", lemmas="no-collision").check_setting()  # type: ignore[arg-type]
