"""A run's shared answers (:mod:`fatline_verify.prove.memo`): a question asked by several obligations,
each in its own process, is answered once, and the answer read is the one the reader would compute."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from fatline_verify.fresh import run_fresh
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove import basis
from fatline_verify.prove.memo import key_of, remembered
from fatline_verify.prove.smt.claims import SEEN, X_NONDECREASING, Spec
from fatline_verify.prove.tasks import ProofResult
from fatline_verify.rules.paper.cases import moving_cases

pytestmark = pytest.mark.skipif(os.name != "posix", reason="answers are shared through POSIX file locks")


def _count_and_answer(memo: str, log: str, key: str) -> bool:
    """A question whose computing is logged (one line per process that computed it)."""

    def compute() -> bool:
        with open(log, "a") as f:
            f.write(f"{os.getpid()}\n")
        return True

    return remembered(Path(memo), key, compute)


def test_a_question_asked_by_many_processes_is_computed_once(tmp_path):
    memo, log = tmp_path / "memo", tmp_path / "log"
    memo.mkdir()
    answers: dict[int, bool] = {}
    calls = [(_count_and_answer, (str(memo), str(log), "k"), {})] * 6
    run_fresh(calls, 2, answers.__setitem__)
    assert answers == dict.fromkeys(range(6), True)
    assert len(log.read_text().split()) == 1


def test_without_a_directory_every_question_is_computed(tmp_path):
    got: list[int] = []
    for _ in range(2):
        remembered(None, "k", lambda: got.append(1) or False)
    assert got == [1, 1]


def test_the_key_names_every_part_in_order():
    assert key_of("basis", "10.0", "text") != key_of("basis", "10.0", "text ")
    assert key_of("a", "bc") != key_of("ab", "c")


def _spec(lemma: Lemma, form: str, case: str) -> Spec:
    (c,) = [c for c in moving_cases(load_model("paper")) if c.name == case]
    return Spec.of(lemma, form, c)


def test_the_lemmas_of_one_case_share_its_vacuity_answer_and_get_the_kinds_they_get_alone(tmp_path):
    """``rma-fixed/seen`` and ``approach/x-nondecreasing`` of one case ask the same vacuity query: the
    second reads the first's answer, and each row's kind is the one it gets with nothing shared."""
    model = load_model("paper")
    proved = ProofResult(Lemma.RMA_FIXED, SEEN, "scenario-1", Verdict.PROVED, 0, True, 0.0, "unsat", "")
    specs = [_spec(Lemma.RMA_FIXED, SEEN, "scenario-1"), _spec(Lemma.APPROACH, X_NONDECREASING, "scenario-1")]
    alone = [basis.basis_of(model, spec, proved) for spec in specs]
    shared = [basis.basis_of(model, spec, proved, memo=tmp_path) for spec in specs]
    assert shared == alone
    assert len(list(tmp_path.glob("*.json"))) == 3  # one vacuity answer for both, one immediacy answer each


def test_the_longest_obligations_go_first():
    """By an earlier run's seconds; the rest in task order."""
    from fatline_verify.prove.prover import _first, task_key, tasks_for

    tasks = tasks_for(load_model("paper"), (Lemma.NO_COLLISION, Lemma.PROGRESS))
    assert sorted(tasks, key=lambda t: _first(t, None)) == tasks
    slow, quick = task_key(tasks[-1]), task_key(tasks[3])
    earlier = {slow: {"seconds": 40.0}, quick: {"seconds": 0.5}}
    again = [task_key(t) for t in sorted(tasks, key=lambda t: _first(t, earlier))]
    assert again[:2] == [slow, quick] and again[2:] == [task_key(t) for t in tasks if task_key(t) not in earlier]
