"""The counterexample corpus shipped with the prover (:mod:`fatline_verify.prove.corpus`): every entry
replays, under exactly the shipped models it names; every shipped VIOLATED row of a per-case
obligation has an entry (or was found by the search); a fresh run replays it first and says so.

The in-step tests read the committed ``proofs/``; after ``proofs/`` is regenerated they still pass
(a regenerated row's trace is its corpus entry replayed), and if they do not, the corpus is made
again by ``python -m fatline_verify.prove.corpus --proofs proofs --known docs/known``.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fatline_verify.errors import InvalidInput, OutputFailed
from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.outputs import write_json
from fatline_verify.prove import corpus as corpus_module
from fatline_verify.prove.candidates import corpus_known
from fatline_verify.prove.corpus import (
    CORPUS,
    CORPUS_PATH,
    EARLIER,
    SEARCH,
    Entry,
    build,
    corpus_document,
    known_for,
    read_corpus,
    replays,
)
from fatline_verify.prove.prover import prove
from fatline_verify.prove.search import prove_spec
from fatline_verify.prove.smt.claims import Spec
from fatline_verify.prove.tasks import NotEncodedModel, paper_part, row_key, task_key, tasks_for
from fatline_verify.prove.text import prove_deciders
from tests.conftest import task_named

ROOT = Path(__file__).resolve().parent.parent
PROOFS = ROOT / "proofs"

HAND_FOUND = "no-collision/one-mover-scenario-4-I-nonempty.from-scenario-3"
"""``paper-drop-touch``'s Scenario 4 after Scenario 3's search: found by hand (``docs/known/``); no
lattice up to q = 4 holds it, and 60 s of the search does not find it."""


def _shipped_models() -> list[tuple[str, object, dict[str, Spec], dict[str, dict]]]:
    """Each model proved under ``proofs/``: its name, its paper part, its per-case obligations, its rows."""
    out = []
    for results in sorted(PROOFS.glob("*/results.json")):
        try:
            model = load_model(results.parent.name)
            specs = {task_key(t): t for t in tasks_for(model, two_movers=True) if isinstance(t, Spec)}
        except NotEncodedModel:
            continue
        rows = {row_key(r): r for r in json.loads(results.read_text())["obligations"]}
        out.append((model.name, paper_part(model), specs, rows))
    return out


@pytest.fixture(scope="module")
def shipped():
    return _shipped_models()


def test_the_shipped_corpus_is_small_sealed_and_read():
    entries = read_corpus()
    assert entries and CORPUS_PATH.stat().st_size < 1_000_000
    assert len({(e.key, e.initial, e.focus) for e in entries}) == len(entries)  # deduplicated


def test_every_entry_replays_under_exactly_the_models_it_names_and_there_the_row_is_violated(shipped):
    for entry in read_corpus():
        for name, part, specs, rows in shipped:
            if entry.key not in specs:
                assert name not in entry.models, (entry.key, name)
                continue
            assert replays(part, specs[entry.key], entry) == (name in entry.models), (entry.key, name)
            if name in entry.models and entry.key in rows:
                assert rows[entry.key]["verdict"] == "VIOLATED", (entry.key, name)  # never beside a PROVED row


def test_every_shipped_violated_row_has_an_entry_or_was_found_by_the_search(shipped):
    corpus = corpus_module.shipped()
    for name, _, specs, rows in shipped:
        for key, row in rows.items():
            if row["verdict"] != "VIOLATED" or key not in specs:
                continue  # the global form is the checker's search; a leg obligation has no counterexample here
            covered = any(name in e.models for e in corpus.get(key, ()))
            assert covered or row.get("decided_by") == SEARCH, (name, key)


@pytest.mark.slow
def test_the_corpus_is_in_step_with_the_shipped_proofs():
    """Made again from ``proofs/`` and ``docs/known/`` it is the same (reads the committed artefacts; the
    fast tier has the two tests above, which check each entry and each row)."""
    made = build(PROOFS, sorted((ROOT / "docs" / "known").glob("*.json")))
    assert made and sorted(map(_text, made)) == sorted(map(_text, read_corpus()))


def _text(entry: Entry) -> str:
    return json.dumps(entry.to_json(), sort_keys=True)


def test_an_entry_is_believed_only_when_it_replays():
    model = load_model("paper")
    task = task_named(model, "connectivity/closer-scenario-2.down-1")
    good = Entry(task.key, (("0", "0"), ("73/30", "1"), ("73/30", "31/10")), None, ("paper",), ("proofs/paper",))
    moved = Entry(task.key, (("0", "0"), ("73/30", "1"), ("73/30", "5")), None, ("paper",), ("proofs/paper",))
    assert replays(model, task, good) and not replays(model, task, moved)
    result = prove_spec(model, task, timeout=1.0, out=None, corpus=known_for(model, task.key, {task.key: (good,)}))
    assert result.verdict is Verdict.VIOLATED and result.decided_by == CORPUS
    assert "shipped counterexample corpus, found under model paper" in result.reason
    # a corpus entry that does not replay decides nothing: the earlier run's counterexample does
    earlier = [(EARLIER, {"configuration": ["0,0", "73/30,1", "73/30,31/10"]})]
    result = prove_spec(
        model, task, timeout=1.0, out=None, corpus=known_for(model, task.key, {task.key: (moved,)}), known=earlier
    )
    assert result.verdict is Verdict.VIOLATED and result.decided_by == "earlier"


def test_a_models_own_shipped_counterexample_is_replayed_first():
    model = load_model("paper-drop-touch")
    for key in ("no-collision/one-mover-scenario-1", HAND_FOUND):
        got = known_for(model, key)
        assert got and "under model paper-drop-touch" in got[0][0]


def test_the_mirror_obligations_entries_are_offered_reflected():
    model = load_model("paper")
    key = "connectivity/closer-scenario-3.up-1"
    theirs = known_for(model, "connectivity/closer-scenario-2.down-1")
    got = corpus_known(model, key)
    mirrored = [doc for where, doc in got if where.startswith("the mirror image")]
    assert theirs and len(mirrored) == len(theirs)


def test_a_fresh_prove_is_decided_by_the_corpus(tmp_path):
    """A hand-found counterexample (``docs/known/``) decides a fresh run into an empty directory."""
    model = load_model("paper-drop-touch")
    task = task_named(model, HAND_FOUND)
    [got] = prove(model, tasks=[task], timeout=1.0, out=tmp_path, jobs=1)
    assert got.verdict is Verdict.VIOLATED and got.decided_by == CORPUS
    assert "docs/known" not in got.reason and "found under model paper-drop-touch" in got.reason


@pytest.mark.slow
def test_without_the_corpus_the_search_alone_does_not_find_the_hand_found_one(tmp_path):
    """``corpus=False`` (``--no-corpus``): the search alone, within 1 s and the small swarms, does not
    find it (the fast tier's twin: :func:`test_a_fresh_prove_is_decided_by_the_corpus`)."""
    model = load_model("paper-drop-touch")
    task = task_named(model, HAND_FOUND)
    [alone] = prove(model, tasks=[task], timeout=1.0, out=tmp_path, jobs=1, corpus=False)
    assert alone.decided_by == SEARCH and alone.verdict is not Verdict.VIOLATED


def test_the_summary_counts_what_decided_the_violated_rows():
    rows = [
        {"verdict": "VIOLATED", "decided_by": "corpus"},
        {"verdict": "VIOLATED", "decided_by": "corpus"},
        {"verdict": "VIOLATED", "decided_by": "search"},
        {"verdict": "PROVED", "decided_by": "search"},
    ]
    [line] = prove_deciders(rows)
    assert "1 by the search" in line and "2 by the shipped counterexample corpus" in line
    assert prove_deciders([{"verdict": "VIOLATED"}]) == []  # rows written before decided_by: not counted


def test_a_corrupt_corpus_is_refused_in_one_line(tmp_path):
    entry = Entry("no-collision/one-mover-scenario-1", (("0", "0"), ("3", "2")), 1, ("paper",), ("proofs/paper",))
    path = tmp_path / "corpus.json"
    write_json(path, corpus_document([entry]))
    assert read_corpus(path) == [entry]
    doc = json.loads(path.read_text())
    doc["entries"][0]["initial"][1] = ["3", "1"]  # an edit that does not recompute the digest
    path.write_text(json.dumps(doc))
    with pytest.raises(OutputFailed):
        read_corpus(path)
    bad = corpus_document([entry])
    bad["entries"][0]["focus"] = 7
    write_json(path, corpus_document([]) | {"entries": bad["entries"]})
    with pytest.raises((InvalidInput, OutputFailed)):
        read_corpus(path)
    write_json(path, corpus_module.seal({**bad}))
    with pytest.raises(InvalidInput, match="focus=7"):
        read_corpus(path)


def test_making_the_corpus_refuses_bad_input_before_any_work(tmp_path, capsys):
    precious = tmp_path / "precious.json"
    precious.write_text('{"mine": true}\n')
    assert corpus_module.main(["--proofs", str(tmp_path / "none"), "--out", str(tmp_path / "c.json")]) == 2
    assert "proofs=" in capsys.readouterr().err and not (tmp_path / "c.json").exists()
    assert corpus_module.main(["--proofs", str(PROOFS), "--known", str(tmp_path / "none")]) == 2
    assert "known=" in capsys.readouterr().err
    assert corpus_module.main(["--proofs", str(PROOFS), "--out", str(precious)]) == 2
    assert "not a corpus" in capsys.readouterr().err and precious.read_text() == '{"mine": true}\n'
