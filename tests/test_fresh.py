"""Fresh processes for the prover's obligations: a call past its wall-clock limit is stopped and
reported, the others finish (a solver can ignore its own limits)."""

from __future__ import annotations

import time

from fatline_verify.fresh import run_fresh
from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove.prover import hard_limit, overrun_result, tasks_for


def test_a_call_past_its_limit_is_stopped_and_reported_and_the_others_finish():
    got: dict[int, object] = {}
    start = time.monotonic()
    calls = [(time.sleep, (120,), {}), (abs, (-3,), {}), (time.sleep, (0.1,), {})]
    run_fresh(calls, 2, got.__setitem__, limit=4, overrun=lambda k, s: ("stopped", k, s))
    took = time.monotonic() - start
    assert got[1] == 3 and got[2] is None
    assert got[0][0] == "stopped" and got[0][1] == 0 and 4 <= got[0][2] < 15
    assert took < 30


def test_without_an_overrun_answer_there_is_no_limit():
    got: dict[int, object] = {}
    run_fresh([(time.sleep, (1.5,), {})], 1, got.__setitem__, limit=0.5)
    assert got == {0: None}


def test_a_stopped_obligation_is_an_inconclusive_row_of_its_own_key(tmp_path):
    for name in ("paper", "repaired"):
        model = load_model(name)
        for task in tasks_for(model)[:3] + tasks_for(model)[-2:]:
            row = overrun_result(task, 185.2, 60, tmp_path)
            assert row.key == task.key and row.verdict is Verdict.INCONCLUSIVE
            assert "stopped after 185 s" in row.reason and f"is {hard_limit(60):.0f} s" in row.reason
            assert row.smt2.startswith(tmp_path.as_posix()) and row.smt2.endswith(".smt2")
