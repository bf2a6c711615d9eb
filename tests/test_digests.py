"""Rows keyed by what produced them (:mod:`fatline_verify.prove.digests`): every committed row is current,
a small part of it is proved again here and must come out the same, an obligation's SMT-LIB regenerates
byte for byte, and an edit to one kind's builder stales only that kind's rows."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.integrity import seal
from fatline_verify.model.config import load_model
from fatline_verify.outputs import write_json
from fatline_verify.prove import digests
from fatline_verify.prove.digests import KINDS, kind_of, kind_sources, text_sha256
from fatline_verify.prove.emit import obligation_text
from fatline_verify.prove.results import STALE, ProofResults
from fatline_verify.prove.tasks import row_key, task_key, tasks_for

ROOT = Path(__file__).resolve().parent.parent
PROOFS = ROOT / "proofs"
MODELS = sorted(p.parent.name for p in PROOFS.glob("*/results.json"))


def _store(name: str, where: Path = PROOFS) -> ProofResults:
    return ProofResults(load_model(name), where / name, where / name / "traces", slots=3, timeout=60.0)


@pytest.mark.parametrize("name", MODELS)
def test_every_committed_row_is_current(name):
    """A change to what decides a row (its kind's sources, the model file, the solver) without proving
    again is red here, with the one command that makes the rows current (it solves only the stale ones)."""
    store = _store(name)
    stale = store.stale()
    assert not stale, (
        f"{len(stale)} of {len(store.rows)} rows of proofs/{name}/results.json are stale (first: {stale[0]}): "
        f"the code, model or solver that decided them changed. Run: fatline prove {name} --out proofs "
        "(it solves the stale rows only) and commit proofs/"
    )


def test_a_part_of_the_committed_rows_proved_again_is_the_same(tmp_path):
    """The paper's no-collision obligations proved afresh (the shipped corpus, no earlier run) give the
    committed rows: verdict, reason, what decided it, basis, configuration, fingerprint and the digest of
    the obligation written, field for field (not the seconds)."""
    code = main(["prove", "paper", "--lemma", "no-collision", "--out", str(tmp_path), "-q", "--jobs", "2"])
    assert code == 1  # the collisions are replayed
    fresh = json.loads((tmp_path / "paper" / "results.json").read_text())["obligations"]
    stored = {row_key(r): r for r in json.loads((PROOFS / "paper" / "results.json").read_text())["obligations"]}
    assert len(fresh) == 25
    fields = ("verdict", "reason", "decided_by", "basis", "configuration", "fingerprint", "smt2_sha256")
    for row in fresh:
        old = stored[row_key(row)]
        assert {f: row.get(f) for f in fields} == {f: old.get(f) for f in fields}, row_key(row)


def test_an_obligation_regenerates_byte_for_byte_as_its_row_recorded():
    """One obligation of each kind of each model, built by ``--emit``'s builder, has the digest of the file
    the prover wrote when it decided the row."""
    checked = 0
    for name in MODELS:
        model = load_model(name)
        rows = _store(name).rows
        seen: set[str] = set()
        for task in tasks_for(model):
            kind = kind_of(task)
            row = rows.get(task_key(task))
            if kind in seen or row is None or not row.get("smt2_sha256"):
                continue
            seen.add(kind)
            got = obligation_text(model, task, slots=3)
            assert got is not None and text_sha256(got[1]) == row["smt2_sha256"], (name, task_key(task))
            checked += 1
    assert checked >= 2 * len(MODELS)


def test_emit_writes_the_obligations_and_checks_their_digests(tmp_path, capsys):
    """``fatline prove MODEL --emit DIR``: every obligation asked for, each checked against its row
    (exit 0); a file there that is not an obligation is refused in one line (exit 2), before any work."""
    code = main(["prove", "paper-literal", "--lemma", "approach", "--emit", str(tmp_path / "e"), "--out", str(PROOFS)])
    out = capsys.readouterr().out
    assert code == 0, out
    assert out.strip().endswith("19 matches")
    written = sorted((tmp_path / "e" / "paper-literal" / "approach").glob("*.smt2"))
    assert len(written) == 19
    precious = written[0]
    precious.write_text("not mine\n")
    code = main(["prove", "paper-literal", "--lemma", "approach", "--emit", str(tmp_path / "e"), "--out", str(PROOFS)])
    err = capsys.readouterr().err
    assert code == 2 and "is not an SMT-LIB2 obligation" in err and precious.read_text() == "not mine\n"


def test_a_stale_row_is_shown_stale_and_solved_again(tmp_path, monkeypatch, capsys):
    """With nothing changed ``fatline prove`` solves nothing and prints what the run that made the rows
    printed; a row whose fingerprint no longer matches is shown STALE, never with its old verdict, and the
    next run solves that row alone."""
    from fatline_verify.prove import prover

    shutil.copytree(PROOFS / "paper-literal", tmp_path / "paper-literal")
    asked: list[list[str]] = []
    real = prover.prove

    def spy(model, *args, tasks=None, **kwargs):
        asked.append([task_key(t) for t in tasks or []])
        return real(model, *args, tasks=tasks, **kwargs)

    monkeypatch.setattr(prover, "prove", spy)
    argv = ["prove", "paper-literal", "--lemma", "approach", "--out", str(tmp_path), "-q", "--jobs", "1"]
    code = main(argv)
    first = capsys.readouterr().out
    assert code == 1 and asked == [[]]  # paper-literal's Scenario 1 moves left: VIOLATED, replayed
    assert main(argv) == code and capsys.readouterr().out == first
    key = "approach/x-nondecreasing-scenario-1"
    results = tmp_path / "paper-literal" / "results.json"
    data = json.loads(results.read_text())
    for row in data["obligations"]:
        if row_key(row) == key:
            row["fingerprint"] = "0" * 16  # as if made by other code
    write_json(results, seal({k: v for k, v in data.items() if k != "digest"}))
    store = _store("paper-literal", tmp_path)
    shown = {row_key(r): r for r in store.shown()}
    assert shown[key]["verdict"] == STALE and "fatline prove paper-literal" in shown[key]["reason"]
    assert store.stale() == [key]
    assert main(argv) == code
    assert asked[-1] == [key] and capsys.readouterr().out == first


def test_each_kind_is_keyed_by_its_own_builder_and_rule_set():
    """The leg builder is only in the leg rows' sources, the liveness builder only in the liveness rows',
    the repaired rules only in the repaired model's rows, and the shared search in every solving kind's:
    so an edit to one stales its dependants only."""
    paper, repaired = load_model("paper"), load_model("repaired")

    def names(kind, model):
        return {p.relative_to(digests.ROOT).as_posix() for p in kind_sources(kind, model)}

    for kind in KINDS:
        for model in (paper, repaired):
            got = names(kind, model)
            assert ("prove/smt/family.py" in got) == (kind in ("leg",)), (kind, model.name)
            if kind in ("leg", "views"):  # the family's language and the rule set that declares it
                assert ("rules/repaired/family.py" in got) == (model is repaired), kind
            # the family language keys only the rows of a model whose rule set declares a family (its
            # replays hold every decision to the family)
            assert ("rules/family/lang.py" in got) == (model is repaired), kind
            assert ("prove/smt/liveness.py" in got) == (kind == "live"), (kind, model.name)
            assert ("rules/repaired/algorithm.py" in got) == (model is repaired and kind != "coverage"), kind
            assert "rules/paper/algorithm.py" in got
            assert "prove/digests.py" not in got, kind  # what keys the rows is no source of theirs
            assert ("prove/search.py" in got) == (kind != "coverage"), kind


def test_a_row_is_keyed_by_code_not_by_docstrings_comments_or_layout(tmp_path):
    """A source file counts by its syntax tree without docstrings: a docstring, a comment or a line
    break edited leaves the digest as it was; a changed constant, name or operator changes it."""
    base = 'from x import y\n\n\ndef f(a):\n    """Doc."""\n    return a + 1  # note\n\n\nK = 2\n"""K doc."""\n'
    same = [
        base.replace('"""Doc."""', '"""Another doc, longer."""'),
        base.replace("# note", "# another note"),
        base.replace("return a + 1", "return (\n        a + 1\n    )"),
        base.replace('"""K doc."""\n', ""),
    ]
    other = [base.replace("a + 1", "a + 2"), base.replace("a + 1", "a - 1"), base.replace("K = 2", "L = 2")]

    def code(text: str, name: str) -> str:
        path = tmp_path / f"{name}.py"
        path.write_text(text, encoding="utf-8")
        return digests._code(path, text)

    first = code(base, "base")
    assert all(code(t, f"same{k}") == first for k, t in enumerate(same))
    assert all(code(t, f"other{k}") != first for k, t in enumerate(other))
