"""Outputs of one run that would destroy each other (or what the run reads) are refused before any work:
exit 2, one line naming both options and the path, every file as it was (issue 41)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.errors import InvalidInput
from fatline_verify.outputs import Output, distinct_outputs
from tests.hostile import PRECIOUS, ROOT, snapshot

TRACE = ROOT / "reports" / "traces" / "paper-check-progress-n2.json"


def _world(root: Path) -> None:
    (root / "traces").mkdir()
    (root / "traces" / "paper-connectivity-n2.json").write_bytes(PRECIOUS)
    (root / "model.toml").write_text((ROOT / "models" / "paper.toml").read_text())
    (root / "repaired.toml").write_text((ROOT / "models" / "repaired.toml").read_text())
    for directory in ("x", "ck", "t", "p/paper"):
        (root / directory).mkdir(parents=True)
    (root / "corpus").mkdir()
    (root / "corpus" / "t.json").write_bytes(TRACE.read_bytes())


CASES = [
    # two outputs naming one file
    ("check-json-junit", ["check", "--json", "F", "--junit", "F"], ("json='F'", "junit='F'")),
    ("check-json-junit-spelled", ["check", "--json", "F", "--junit", "./x/../F"], ("json='F'", "junit='x/../F'")),
    ("prove-json-junit", ["prove", "--out", "p", "--json", "F", "--junit", "F"], ("json='F'", "junit='F'")),
    # a file inside another output's directory
    (
        "check-json-in-traces",
        ["check", "--json", "traces/paper-check-connectivity-n2.json", "--traces", "traces"],
        ("json='traces/paper-check-connectivity-n2.json'", "traces='traces'"),
    ),
    ("check-junit-in-checkpoint", ["check", "--junit", "ck/j.xml", "--checkpoint", "ck"], ("junit=", "checkpoint=")),
    ("prove-json-in-out", ["prove", "--out", "p", "--json", "p/paper/results.json"], ("json=", "out='p/paper'")),
    ("prove-junit-in-traces", ["prove", "--out", "p", "--traces", "t", "--junit", "t/j.xml"], ("junit=", "traces='t'")),
    # two outputs naming one directory
    ("check-traces-checkpoint", ["check", "--traces", "d", "--checkpoint", "d"], ("traces='d'", "checkpoint='d'")),
    ("prove-traces-out", ["prove", "--out", "p", "--traces", "p/paper"], ("out='p/paper'", "traces='p/paper'")),
    ("report-out-proofs", ["report", "paper", "--out", "r", "--proofs", "r"], ("out='r'", "proofs='r'")),
    # an output naming an input file
    ("check-json-model", ["check", "model.toml", "--json", "model.toml", "--force"], ("json=", "model='model.toml'")),
    (
        "simulate-trace-model",
        ["simulate", "model.toml", "--init", "0,0 3,0", "--trace", "model.toml", "--force"],
        ("trace='model.toml'", "model='model.toml'"),
    ),
    ("reach-json-model", ["reach", "repaired.toml", "--json", "repaired.toml", "--force"], ("json=", "model=")),
    ("synth-json-model", ["synth", "repaired.toml", "--json", "repaired.toml", "--force"], ("json=", "model=")),
    (
        "regress-junit-trace",
        ["regress", "corpus", "--junit", "corpus/t.json", "--force"],
        ("junit='corpus/t.json'", "dir='corpus/t.json'"),
    ),
]


@pytest.mark.parametrize(("argv", "fragments"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_outputs_that_would_collide_are_refused(capsys, tmp_path, monkeypatch, argv, fragments):
    _world(tmp_path)
    monkeypatch.chdir(tmp_path)
    before = snapshot(tmp_path)
    quiet = ["-q"] if argv[0] in ("check", "prove", "report", "reach", "synth", "regress") else []
    code = main([*argv, *quiet])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1, err
    assert lines[0].startswith("fatline: error: ")
    for fragment in fragments:
        assert fragment in lines[0], lines[0]
    assert out == ""  # refused before any work: no verdict printed
    assert snapshot(tmp_path) == before


def test_a_link_to_the_same_file_is_the_same_file(tmp_path):
    (tmp_path / "a.json").write_text("{}")
    os.symlink(tmp_path / "a.json", tmp_path / "b.json")
    with pytest.raises(InvalidInput, match=r"json=.*junit=.*both name one path"):
        distinct_outputs([Output("json", tmp_path / "a.json"), Output("junit", tmp_path / "b.json")])


def test_separate_outputs_pass(tmp_path):
    """Distinct files, nested directories (prove's OUT/MODEL/traces) and outputs not asked for are fine."""
    distinct_outputs(
        [
            Output("json", tmp_path / "r.json"),
            Output("junit", tmp_path / "r.xml"),
            Output("out", tmp_path / "p" / "paper", directory=True),
            Output("traces", tmp_path / "p" / "paper" / "traces", directory=True),
            Output("checkpoint", None, directory=True),
        ],
        [("model", "paper"), ("model", tmp_path / "missing.toml")],
    )
