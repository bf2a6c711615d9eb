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


def test_a_limit_per_call_stops_only_the_calls_that_have_one():
    """The views' rows have no solver budget and no wall-clock limit; the solvers' calls keep theirs."""
    got: dict[int, object] = {}
    calls = [(time.sleep, (3,), {}), (time.sleep, (60,), {})]
    run_fresh(calls, 2, got.__setitem__, limit=lambda k: None if k == 0 else 1.0, overrun=lambda k, s: ("stopped", k))
    assert got == {0: None, 1: ("stopped", 1)}


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


def _fresh_state() -> tuple[int, int, bool, bool]:
    """What an obligation's process finds when its call starts: its pid and its parent's, whether z3
    has a context yet and whether it is alone (one thread); then it uses z3, as an obligation does."""
    import os
    import threading

    import z3

    state = (os.getpid(), os.getppid(), z3.z3._main_ctx is None, threading.active_count() == 1)
    x = z3.Real("x")
    solver = z3.Solver()
    solver.add(x * x == 2)
    assert solver.check() == z3.sat
    return state


def test_each_call_runs_in_a_process_of_its_own_forked_from_one_server_with_no_z3_state():
    """Every obligation runs in a process of its own, forked from a server that imported the prover
    and nothing else (so the imports are paid once): the z3 context an earlier call made is not there."""
    import os

    got: dict[int, tuple[int, int, bool, bool]] = {}
    run_fresh([(_fresh_state, (), {})] * 4, 1, got.__setitem__)
    pids = {state[0] for state in got.values()}
    parents = {state[1] for state in got.values()}
    assert len(pids) == 4 and os.getpid() not in pids  # a process per call
    assert len(parents) == 1 and os.getpid() not in parents  # forked by the one fork server, not spawned here
    assert all(fresh and alone for _, _, fresh, alone in got.values()), got
