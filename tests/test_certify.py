"""Linear certificates checked from their own files (:mod:`fatline_verify.prove.smt.certificates`,
``python -m fatline_verify.prove.certify DIR``): proved fresh into tmp_path, then checked, then
tampered with in each of the ways the check must catch."""

from __future__ import annotations

import re
import shutil

import pytest

from fatline_verify.model.config import load_model
from fatline_verify.prove import certify
from fatline_verify.prove.search import prove_spec
from fatline_verify.prove.smt.certificates import check_certificate
from fatline_verify.prove.tasks import tasks_for

KEY = "rma-fixed/seen-scenario-2.down-1"
"""A PROVED obligation the linearization decides (Scenario 2's first candidate below psi_right)."""


@pytest.fixture(scope="module")
def proved(tmp_path_factory):
    out = tmp_path_factory.mktemp("cert")
    model = load_model("paper")
    (task,) = [t for t in tasks_for(model) if t.key == KEY]
    got = prove_spec(model, task, timeout=20, out=out, small=False)
    assert got.verdict.value == "PROVED" and "linearization" in got.reason
    path = out / "rma-fixed" / "seen-scenario-2.down-1.linear.smt2"
    assert path.is_file()
    return path


def _copy(proved, tmp_path, edit):
    for p in (proved, proved.with_name(proved.name.replace(".linear", ""))):
        shutil.copy(p, tmp_path / p.name)
    target = tmp_path / proved.name
    target.write_text(edit(target.read_text()))
    return target


def test_a_fresh_certificate_checks_from_its_own_files(proved):
    got = check_certificate(proved)
    assert got.ok, got.why
    assert got.atoms > 0 and got.cuts > 0
    text = proved.read_text()
    assert "; relaxed assertions: " in text and text.count("; cut relaxed!") == got.cuts


def test_the_command_checks_a_directory_and_exits_0(proved, capsys):
    assert certify.main([str(proved.parent)]) == 0
    assert "1 of 1 certificates check" in capsys.readouterr().out


def test_the_command_refuses_a_missing_directory(tmp_path, capsys):
    assert certify.main([str(tmp_path / "nowhere")]) == 2
    assert "nowhere: no such directory" in capsys.readouterr().err


def test_a_wrong_atom_is_caught(proved, tmp_path):
    """An atom recorded with another radius no longer gives back the obligation's assert."""
    bad = _copy(proved, tmp_path, lambda t: re.sub(r"(; atom relaxed!\d+ \(<= )4\.0", r"\g<1>5.0", t, count=1))
    got = check_certificate(bad, cvc5_check=False)
    assert not got.ok and "is not the obligation's" in got.why


def test_a_cut_that_does_not_follow_is_caught(proved, tmp_path):
    """A tangent moved inward (its bound lowered) is not implied by the disc its Boolean stands for."""

    def shrink(text):
        lines = text.splitlines(keepends=True)
        k = next(i for i, line in enumerate(lines) if line.startswith("; cut ")) + 1
        lines[k] = lines[k].replace(") 2.0)))", ") 1.0)))", 1)  # |l| <= 2 inside the disc of radius 2: now 1
        return "".join(lines)

    bad = _copy(proved, tmp_path, shrink)
    assert bad.read_text() != proved.read_text()
    got = check_certificate(bad, cvc5_check=False)
    assert not got.ok and "cut 0" in got.why


def test_a_certificate_without_its_records_is_refused(proved, tmp_path):
    bad = _copy(proved, tmp_path, lambda t: re.sub(r"^; relaxed assertions:.*\n", "", t, flags=re.M))
    assert not check_certificate(bad, cvc5_check=False).ok
    unmarked = _copy(proved, tmp_path, lambda t: t.replace("; cut relaxed!", "; relaxed!", 1))
    got = check_certificate(unmarked, cvc5_check=False)
    assert not got.ok and "'; cut' marks" in got.why


def test_the_command_checks_with_two_processes(proved, capsys):
    assert certify.main(["--jobs", "2", str(proved.parent)]) == 0
    assert "1 of 1 certificates check" in capsys.readouterr().out


@pytest.mark.parametrize("value", ["0", "two", "-1"])
def test_the_command_refuses_a_bad_jobs_count(value, tmp_path, capsys):
    assert certify.main(["--jobs", value, str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert f"--jobs {value}" in err and "positive whole number" in err and len(err.strip().splitlines()) == 1


def test_help_is_a_usage_text(capsys):
    """``--help`` prints the usage, what it checks and its exit codes, exit 0 (it was "no such directory")."""
    from fatline_verify.prove import certify

    assert certify.main(["--help"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("usage: python -m fatline_verify.prove.certify [-h] [--jobs N] [DIR ...]")
    assert "exit codes:" in out and "no such directory" not in out + err
    assert certify.main(["--frobnicate"]) == 2
    assert capsys.readouterr().err.strip() == "fatline: certify: unrecognized arguments: --frobnicate"
