"""Hostile input: every bad value is one line on stderr and exit 2, before any work, and every file
that existed before the command is byte-identical after it (nothing clobbered, nothing written
outside its directory)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from fatline_verify.cli import main

PRECIOUS = b"precious: not an output of fatline\n"


def _world(root: Path) -> None:
    """A working directory with files a careless command could destroy."""
    for name in ("README.md", "pyproject.toml", "precious.txt", "notes.json"):
        (root / name).write_bytes(PRECIOUS)
    (root / "adir").mkdir()
    (root / "empty.toml").write_bytes(b"")
    (root / "traversal.toml").write_text('name = "../../x"\n')
    (root / "absolute.toml").write_text('name = "/abs/x"\n')
    (root / "upper.toml").write_text('name = "Paper"\n')
    (root / "floaty.toml").write_text("[parameters]\ndelta = nan\n")
    (root / "traces").mkdir()
    (root / "traces" / "paper-connectivity-n2.json").write_bytes(PRECIOUS)
    (root / "proofs-taken" / "paper").mkdir(parents=True)
    (root / "proofs-taken" / "paper" / "results.json").write_bytes(PRECIOUS)
    (root / "proofs-file").mkdir()
    (root / "proofs-file" / "paper").write_bytes(PRECIOUS)


def _snapshot(root: Path) -> dict[str, bytes | None]:
    out: dict[str, bytes | None] = {}
    for path in sorted(root.rglob("*")):
        out[str(path.relative_to(root))] = path.read_bytes() if path.is_file() else None
    return out


CASES = [
    # check: empty values
    ("check-robots-empty", ["check", "--robots", ""], "robots=''"),
    ("check-window-empty", ["check", "--window", ""], "window=''"),
    ("check-json-empty", ["check", "--json", ""], "json=''"),
    ("check-traces-empty", ["check", "--traces", ""], "traces=''"),
    ("check-model-empty", ["check", ""], "model=''"),
    # check: numbers
    ("check-q-zero", ["check", "--q", "0"], "q='0': expected a whole number"),
    ("check-q-huge", ["check", "--q", "5000"], "q='5000'"),
    ("check-q-lattice-too-big", ["check", "--q", "1000", "--robots", "2"], "q=1000: a robot sees"),
    ("check-max-states-negative", ["check", "--max-states", "-5"], "max-states='-5'"),
    ("check-max-states-nan", ["check", "--max-states", "nan"], "max-states='nan'"),
    ("check-robots-junk", ["check", "--robots", "2..x"], "robots='2..x'"),
    ("check-robots-huge-window", ["check", "--robots", "9", "--window", "128x128"], "63 bits"),
    ("check-window-tiny", ["check", "--robots", "2", "--window", "1x1"], "window=1x1: no two robots fit"),
    ("check-engine", ["check", "--engine", "gpu"], "engine='gpu': expected one of compiled, fast, scalar"),
    ("check-flag-value-missing", ["check", "--robots"], "robots: no value given"),
    ("check-unknown-flag", ["check", "--frobnicate"], "argument='--frobnicate': unknown"),
    # check: wrong kind of path, clobber, unwritable
    ("check-json-clobber-readme", ["check", "--json", "README.md"], "exists and is not a fatline check result"),
    ("check-json-directory", ["check", "--json", "adir"], "is a directory"),
    ("check-json-no-parent", ["check", "--json", "missing/out.json"], "does not exist"),
    ("check-traces-is-file", ["check", "--traces", "precious.txt"], "not a directory"),
    ("check-traces-uncreatable", ["check", "--traces", "/dev/null/t"], "cannot be created"),
    ("check-trace-clobber", ["check", "--robots", "2", "--traces", "traces"], "paper-connectivity-n2.json"),
    # models: empty, traversal, non-slug, non-finite
    ("model-empty-file", ["check", "empty.toml"], "the file is empty"),
    ("model-traversal", ["check", "traversal.toml"], "name='../../x': expected a slug"),
    ("model-absolute", ["check", "absolute.toml"], "name='/abs/x': expected a slug"),
    ("model-upper-case", ["check", "upper.toml"], "name='Paper'"),
    ("model-nan", ["check", "floaty.toml"], "delta=nan"),
    # prove
    ("prove-timeout-nan", ["prove", "--timeout", "nan"], "timeout='nan': expected a positive, finite"),
    ("prove-timeout-inf", ["prove", "--timeout", "inf"], "timeout='inf'"),
    ("prove-timeout-negative", ["prove", "--timeout", "-1"], "timeout='-1'"),
    ("prove-jobs-zero", ["prove", "--jobs", "0"], "jobs='0'"),
    ("prove-jobs-negative", ["prove", "--jobs", "-3"], "jobs='-3'"),
    ("prove-slots-zero", ["prove", "--slots", "0"], "slots='0'"),
    ("prove-slots-huge", ["prove", "--slots", "99"], "slots='99'"),
    ("prove-lemma", ["prove", "--lemma", "happiness"], "lemma='happiness': expected one of"),
    ("prove-out-empty", ["prove", "--out", ""], "out=''"),
    ("prove-out-is-file", ["prove", "--out", "precious.txt"], "not a directory"),
    ("prove-out-model-is-file", ["prove", "--out", "proofs-file"], "not a directory"),
    ("prove-results-clobber", ["prove", "--out", "proofs-taken"], "exists and is not a fatline prove result"),
    ("prove-json-clobber", ["prove", "--out", "p", "--json", "notes.json"], "exists and is not a fatline prove"),
    ("prove-traces-is-file", ["prove", "--out", "p", "--traces", "precious.txt"], "not a directory"),
    # simulate
    ("simulate-trace-empty", ["simulate", "--init", "0,0 3,0", "--trace", ""], "trace=''"),
    ("simulate-trace-directory", ["simulate", "--init", "0,0 3,0", "--trace", "adir"], "is a directory"),
    ("simulate-trace-clobber", ["simulate", "--init", "0,0 3,0", "--trace", "pyproject.toml"], "not a fatline trace"),
    ("simulate-rounds-negative", ["simulate", "--init", "0,0 3,0", "--rounds", "-1"], "rounds='-1'"),
    ("simulate-rounds-huge", ["simulate", "--init", "0,0 3,0", "--rounds", "10000000000"], "rounds='10000000000'"),
    ("simulate-seed-junk", ["simulate", "--init", "0,0 3,0", "--seed", "x"], "seed='x'"),
    ("simulate-init-nan", ["simulate", "--init", "0,0 nan,0"], "init='nan,0'"),
    ("simulate-init-inf", ["simulate", "--init", "0,0 inf,0"], "init='inf,0'"),
    ("simulate-init-exponent", ["simulate", "--init", "0,0 3e0,0"], "init='3e0,0'"),
    ("simulate-init-missing", ["simulate"], "init: missing"),
    ("simulate-scheduler", ["simulate", "--init", "0,0 3,0", "--scheduler", "chaos"], "scheduler='chaos'"),
    # replay
    ("replay-missing", ["replay", "nope.json"], "no such file"),
    ("replay-not-a-trace", ["replay", "precious.txt"], "not JSON"),
    ("replay-picture-is-file", ["replay", "precious.txt", "--picture", "README.md"], "not a directory"),
    ("replay-model-empty", ["replay", "precious.txt", "--model", ""], "model=''"),
    # report
    ("report-timeout-negative", ["report", "paper", "--timeout", "-1"], "timeout='-1'"),
    ("report-slots-zero", ["report", "paper", "--slots", "0"], "slots='0'"),
    ("report-out-is-file", ["report", "paper", "--out", "precious.txt"], "not a directory"),
    ("report-out-clobber-readme", ["report", "paper", "--out", "."], "README.md"),
    ("report-proofs-is-file", ["report", "paper", "--out", "r", "--proofs", "precious.txt"], "not a directory"),
    ("report-proofs-clobber", ["report", "paper", "--out", "r", "--proofs", "proofs-taken"], "results.json"),
    ("report-model-traversal", ["report", "traversal.toml", "--out", "r"], "expected a slug"),
    # explain, top level
    ("explain-option", ["explain", "colour"], "option='colour': unknown option"),
    ("explain-model", ["explain", "--model", "nope"], "model='nope'"),
    ("no-command", [], "COMMAND: missing"),
    ("unknown-command", ["frobnicate"], "COMMAND='frobnicate': expected one of"),
]


@pytest.mark.parametrize(("argv", "fragment"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_hostile_input(capsys, tmp_path, monkeypatch, argv, fragment):
    _world(tmp_path)
    monkeypatch.chdir(tmp_path)
    before = _snapshot(tmp_path)
    code = main([*argv, *(["-q"] if argv and argv[0] in ("check", "prove", "report") else [])])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1, err
    assert lines[0].startswith("fatline: error: "), lines[0]
    assert fragment in lines[0], lines[0]
    assert "Traceback" not in err and "usage:" not in err
    assert _snapshot(tmp_path) == before  # nothing destroyed, nothing written


def test_the_suite_is_big_enough():
    assert len(CASES) >= 40
    assert {c[1][0] for c in CASES if c[1]} >= {"check", "prove", "simulate", "replay", "report", "explain"}


def test_force_overwrites_only_when_asked(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "out.json").write_bytes(PRECIOUS)
    args = ["simulate", "--init", "0,0 3,0", "--trace", "out.json"]
    assert main(args) == 2
    assert (tmp_path / "out.json").read_bytes() == PRECIOUS
    assert main([*args, "--force"]) == 1  # the default readings break connectivity here
    assert b'"format": "fatline-trace"' in (tmp_path / "out.json").read_bytes()
    capsys.readouterr()
    assert main(args) == 1  # an earlier trace is rewritten without --force
    capsys.readouterr()


def test_help_is_the_only_place_for_usage(capsys):
    assert main(["check", "--help"]) == 0
    assert "usage:" in capsys.readouterr().out


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write into any directory")
def test_unwritable_directory(capsys, tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        assert main(["check", "--json", str(ro / "x.json"), "-q"]) == 2
        assert "not writable" in capsys.readouterr().err
    finally:
        ro.chmod(0o700)
