"""``fatline prove``: the collision and connectivity lemmas over the reals, per rule, with z3.

For every lemma form and every rule that moves r, an obligation asks for a configuration where the
rule breaks the lemma (:mod:`fatline_verify.smt.obligations`). Answers become verdicts only this way:

- ``unsat`` with enough slot robots for the witness argument: PROVED for swarms of every size;
  with fewer: HOLDS_WITHIN_BOUNDS for configurations of at most k + 1 robots.
- ``sat``: the model is turned into exact rationals (irrational values rounded and re-checked) and
  replayed by the executable model. Only if the replay shows the violation is it a counterexample:
  VIOLATED when the configuration is an initial one (so the violation is reachable in one round),
  INCONCLUSIVE otherwise (a violating configuration whose reachability is not decided). A replay that
  disagrees is an encoding disagreement: a bug of the tool, reported as such.
- ``unknown`` (timeout): INCONCLUSIVE with the solver's reason.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.connection
import os
import signal
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from multiprocessing.connection import Connection
from pathlib import Path
from typing import Any, cast

from .algorithm import Rule
from .config import Model
from .options import Scheduler, Uncovered
from .properties import Lemma, Verdict
from .schedule import Collision, decide_all, lost_edges, play_round
from .schedulers import round_scheduler
from .simulate import Outcome, Run, outcome_after
from .smt import obligations as ob
from .smt.symbolic import MOVING
from .swarm import initial_problems
from .trace import replayed_document


@dataclass(frozen=True, slots=True)
class ProofResult:
    """One obligation's verdict."""

    lemma: Lemma
    form: str
    rule: str
    verdict: Verdict
    slots: int
    any_size: bool
    seconds: float
    reason: str
    smt2: str
    witness: dict[str, Any] | None = field(default=None, repr=False, compare=False)
    comment: str = field(default="", repr=False, compare=False)


def rules_for(model: Model) -> list[Rule]:
    """The moving rules this model's readings can fire."""
    rules = [r for r in MOVING if r is not Rule.UNCOVERED_SEARCH or model.options.uncovered is Uncovered.SEARCH_BOTH]
    return rules


def replay_answer(
    model: Model, lemma: Lemma, form: str, rule: Rule, points: tuple[tuple[Fraction, Fraction], ...]
) -> tuple[dict[str, Any], bool] | str:
    """Replay a sat model; return (trace, is_initial) or the reason it does not reproduce."""
    state = ((0, 0), *(model.to_lattice(p) for p in points))
    active = [0] if form == "one-mover" else [0, 1]
    decisions = decide_all(state, model)
    if decisions[0].rule is not rule or not decisions[0].moves:
        return f"r fires {decisions[0].rule.value}, not {rule.value}"
    if form == "two-movers" and not decisions[1].moves:
        return "the second robot does not move"
    result = play_round(state, active, model, decisions)
    focus: Lemma
    if lemma == Lemma.NO_COLLISION:
        if not any(isinstance(v, Collision) and v.robots == (0, 1) for v in result.violations):
            return "r and robot 1 do not collide in the replayed round"
        focus = Lemma.NO_COLLISION
    else:
        if not any(pair == (0, 1) for pair, _ in lost_edges(result.before, result.after, model)):
            return "r and robot 1 keep their edge in the replayed round"
        disconnected = any(v.lemma == Lemma.CONNECTIVITY for v in result.violations)
        focus = Lemma.CONNECTIVITY if disconnected else Lemma.CONNECTIVITY_EDGE
    run = Run(model, state, (result,), outcome_after(result.after, result, model) or Outcome.ROUND_LIMIT)
    origin = {"tool": "fatline prove", "lemma": lemma, "form": form, "rule": rule.value}
    return replayed_document(run, origin, focus), not initial_problems(state, model)


def prove_one(
    model: Model, lemma: Lemma, form: str, rule: Rule, *, slots: int, timeout: float, out: Path | None
) -> ProofResult:
    """Decide one obligation (see the module docstring for the verdict rules).

    The artefact written is always the full obligation with ``slots`` slot robots, whatever answered
    first, so the ``.smt2`` files depend only on the model and ``slots``.
    """
    try:
        full = ob.build(model, lemma, form, rule, slots)
    except ob.NotEncoded as exc:
        return ProofResult(lemma, form, rule.value, Verdict.INCONCLUSIVE, slots, False, 0.0, str(exc), "")
    path = ""
    if out is not None:
        target = out / lemma / f"{full.name}.smt2"
        ob.write(full, target)
        path = str(target)
    spent = 0.0

    def result(verdict: Verdict, k: int, reason: str, doc: dict[str, Any] | None = None) -> ProofResult:
        return ProofResult(lemma, form, rule.value, verdict, k, full.any_size, spent, reason, path, doc, full.comment)

    for k in range(1, slots + 1):  # a counterexample from an initial configuration, smallest first
        ans = ob.solve(ob.build(model, lemma, form, rule, k, initial=True), timeout / slots)
        spent += ans.seconds
        if ans.status == "sat":
            got = replay_answer(model, lemma, form, rule, ans.positions)
            if isinstance(got, str):
                return result(Verdict.INCONCLUSIVE, k, f"encoding disagreement: {got}")
            doc, initial = got
            if initial:
                return result(Verdict.VIOLATED, k, _found(doc, k, ans.rounded), doc)
    ans = ob.solve(full, timeout)
    spent += ans.seconds
    if ans.status == "unsat":
        if full.any_size:
            return result(Verdict.PROVED, slots, "unsat: holds for swarms of every size")
        return result(Verdict.HOLDS_WITHIN_BOUNDS, slots, f"unsat for configurations of at most {slots + 1} robots")
    if ans.status == "unknown":
        return result(Verdict.INCONCLUSIVE, slots, f"solver: {ans.reason}")
    got = replay_answer(model, lemma, form, rule, ans.positions)
    if isinstance(got, str):
        return result(Verdict.INCONCLUSIVE, slots, f"encoding disagreement: {got}")
    doc, initial = got
    if initial:
        return result(Verdict.VIOLATED, slots, _found(doc, len(ans.positions), ans.rounded), doc)
    return result(
        Verdict.INCONCLUSIVE,
        slots,
        "violating configuration found, not an initial one; whether it is reachable is not decided",
        doc,
    )


def prove_global(model: Model, *, slots: int, timeout: float, out: Path | None) -> ProofResult:
    """Lemma 1, global form, for configurations of at most ``slots + 1`` robots."""
    full = ob.build_global(model, slots)
    path = ""
    if out is not None:
        target = out / Lemma.CONNECTIVITY.value / "global.smt2"
        ob.write(full, target)
        path = str(target)
    spent = 0.0

    def result(verdict: Verdict, k: int, reason: str, doc: dict[str, Any] | None = None) -> ProofResult:
        return ProofResult(
            Lemma.CONNECTIVITY, "global", "any", verdict, k, False, spent, reason, path, doc, full.comment
        )

    attempts = [(k, True, timeout / slots) for k in range(1, slots + 1)] + [(slots, False, timeout)]
    last = None
    for k, initial, limit in attempts:
        obligation = ob.build_global(model, k, initial=initial)
        ans = ob.solve(obligation, limit)
        spent += ans.seconds
        last = (k, ans)
        if ans.status != "sat":
            continue
        active_flags, present = ans.flags[: k + 1], ans.flags[k + 1 :]
        state = ((0, 0), *(model.to_lattice(p) for p in ans.positions))
        index = [0] + [1 + sum(present[:i]) for i in range(k)]  # state index of r and of each slot
        active = [index[i] for i in range(k + 1) if active_flags[i] and (i == 0 or present[i - 1])]
        if round_scheduler(model.options.scheduler).forbids(tuple(active), len(state)) is not None:
            return result(
                Verdict.INCONCLUSIVE, k, f"encoding disagreement: activation set {active} breaks the scheduler"
            )
        run_result = play_round(state, active, model)
        if not any(v.lemma == Lemma.CONNECTIVITY for v in run_result.violations):
            return result(
                Verdict.INCONCLUSIVE, k, "encoding disagreement: the replayed round keeps the graph connected"
            )
        run = Run(model, state, (run_result,), Outcome.VIOLATION)
        origin = {"tool": "fatline prove", "lemma": Lemma.CONNECTIVITY.value, "form": "global"}
        doc = replayed_document(run, origin, Lemma.CONNECTIVITY)
        if not initial_problems(state, model):
            return result(
                Verdict.VIOLATED, k, f"the graph splits, from an initial configuration of {k + 1} robots", doc
            )
        if not initial:
            return result(Verdict.INCONCLUSIVE, k, "disconnecting configuration found, not an initial one", doc)
    assert last is not None
    k, ans = last
    if ans.status == "unsat":
        return result(Verdict.HOLDS_WITHIN_BOUNDS, k, f"unsat for configurations of at most {k + 1} robots")
    return result(Verdict.INCONCLUSIVE, k, f"solver: {ans.reason}")


def _found(doc: dict[str, Any], k: int, rounded: bool) -> str:
    prop = doc["violation"]["property"]
    what = {
        Lemma.NO_COLLISION: "collision",
        Lemma.CONNECTIVITY: "an edge is lost and the visibility graph splits (Lemma 1)",
        Lemma.CONNECTIVITY_EDGE: "an edge is lost, the visibility graph stays connected (the proof's claim fails)",
    }[prop]
    note = "; values rounded from algebraic numbers and re-checked" if rounded else ""
    return f"{what}, from an initial configuration of {k + 1} robots{note}"


Task = tuple[Lemma, str, "Rule | None"]
"""One obligation: (lemma, form, rule); rule ``None`` is the global connectivity form."""


def tasks_for(model: Model, lemmas: tuple[Lemma, ...] = ob.LEMMAS) -> list[Task]:
    """Every obligation ``prove`` decides for ``model`` and ``lemmas``, in results order."""
    scheduler = model.options.scheduler
    forms = ob.forms_for(Scheduler.SSYNC if scheduler not in ENCODED else scheduler)
    tasks: list[Task] = [(lemma, form, rule) for lemma in lemmas for form in forms for rule in rules_for(model)]
    if Lemma.CONNECTIVITY in lemmas:
        tasks.append((Lemma.CONNECTIVITY, "global", None))
    return tasks


def task_key(task: Task) -> str:
    """``lemma/form-rule``: how results rows and witness files name an obligation."""
    lemma, form, rule = task
    return f"{lemma}/{form}-{rule.value if rule is not None else 'any'}"


def prove(
    model: Model,
    lemmas: tuple[Lemma, ...] = ob.LEMMAS,
    *,
    slots: int = 3,
    timeout: float = 10.0,
    out: Path | None = None,
    jobs: int | None = None,
    progress: Callable[[str], None] | None = None,
    tasks: list[Task] | None = None,
    on_result: Callable[[ProofResult], None] | None = None,
) -> list[ProofResult]:
    """Every obligation of ``lemmas`` (or exactly ``tasks``) for ``model``; ``.smt2`` files under ``out``.

    Each obligation runs in a fresh process: z3's answers (and times) depend on the terms a process
    created before, so isolation makes every obligation's answer independent of the others and of
    the order; it also spreads the obligations over the cores. ``on_result`` sees each result as it
    finishes (so a caller can save it at once); the list returned is in task order. An interrupt
    stops the workers at once and propagates.
    """
    tasks = tasks_for(model, lemmas) if tasks is None else tasks
    if not tasks:
        return []
    if model.options.scheduler not in ENCODED:
        return _not_encoded(model, tasks, slots, on_result, progress)
    workers = max(1, min(jobs or os.cpu_count() or 1, len(tasks)))
    calls = [
        (prove_one, (model, lemma, form, rule), {"slots": slots, "timeout": timeout, "out": out})
        if rule is not None
        else (prove_global, (model,), {"slots": slots, "timeout": timeout, "out": out})
        for lemma, form, rule in tasks
    ]
    results: list[ProofResult | None] = [None] * len(tasks)

    def done(k: int, result: ProofResult) -> None:
        results[k] = result
        if on_result:
            on_result(result)
        if progress:
            progress(task_key(tasks[k]))

    run_fresh(calls, workers, done)
    return [r for r in results if r is not None]


ENCODED = (Scheduler.SSYNC, Scheduler.FSYNC, Scheduler.CENTRALIZED)
"""The schedulers whose rounds the obligations encode: every mover decides on one shared snapshot."""


def _not_encoded(
    model: Model,
    tasks: list[Task],
    slots: int,
    on_result: Callable[[ProofResult], None] | None,
    progress: Callable[[str], None] | None,
) -> list[ProofResult]:
    """INCONCLUSIVE for every obligation of a scheduler the encoding does not cover: never another
    scheduler's semantics in its place."""
    reason = (
        f"scheduler={model.options.scheduler}: not encoded; the obligations encode rounds in which every mover "
        "decides on one shared snapshot (ssync, fsync, centralized), and an asynchronous robot may decide on a "
        "stale view (another robot seen at an earlier point of its path); use fatline check for this scheduler"
    )
    results = []
    for task in tasks:
        lemma, form, rule = task
        r = ProofResult(lemma, form, rule.value if rule else "any", Verdict.INCONCLUSIVE, slots, False, 0.0, reason, "")
        results.append(r)
        if on_result:
            on_result(r)
        if progress:
            progress(task_key(task))
    return results


Call = tuple[Callable[..., Any], tuple[Any, ...], dict[str, Any]]


def _child(conn: Any, fn: Callable[..., Any], args: tuple[Any, ...], kwargs: dict[str, Any]) -> None:
    """A fresh process's one task: its answer (or its exception) goes back through ``conn``.
    SIGINT is ignored: an interrupt is the parent's to handle, and the parent kills the workers."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        answer: tuple[bool, Any] = (True, fn(*args, **kwargs))
    except Exception as exc:  # sent to the parent, which raises it there
        answer = (False, exc)
    try:
        conn.send(answer)
    except Exception as exc:  # an unpicklable answer or exception
        conn.send((False, RuntimeError(f"{fn.__name__}: {exc.__class__.__name__}: {exc}")))
    conn.close()


def run_fresh(calls: list[Call], workers: int, done: Callable[[int, Any], None]) -> None:
    """Run each call in a new interpreter (spawn), at most ``workers`` at once; ``done(k, answer)``
    as each finishes. z3's answers depend on the terms a process created before, so one process per
    call makes every answer independent of the others and of the order.

    An interrupt (or any error) kills every running worker at once and propagates: nothing waits for
    a solver to finish. (``ProcessPoolExecutor`` cannot promise that: after ``shutdown`` its manager
    thread waits for work it has already queued, and interpreter exit waits for the manager.)
    """
    ctx = multiprocessing.get_context("spawn")
    pending = list(enumerate(calls))[::-1]
    running: dict[Any, tuple[int, Any]] = {}
    try:
        while pending or running:
            while pending and len(running) < workers:
                k, (fn, args, kwargs) = pending.pop()
                receive, send = ctx.Pipe(duplex=False)
                proc = ctx.Process(target=_child, args=(send, fn, args, kwargs), daemon=True)
                proc.start()
                send.close()
                running[receive] = (k, proc)
            for ready in multiprocessing.connection.wait(list(running)):
                conn = cast(Connection, ready)
                k, proc = running.pop(conn)
                try:
                    ok, answer = conn.recv()
                except EOFError:
                    ok, answer = False, RuntimeError(f"a worker process died (exit code {proc.exitcode})")
                conn.close()
                proc.join()
                if not ok:
                    raise answer if isinstance(answer, BaseException) else RuntimeError(str(answer))
                done(k, answer)
    finally:
        for conn, (_, proc) in running.items():
            proc.kill()
            proc.join(timeout=5)
            conn.close()


def isolated(fn: Callable[..., ProofResult], *args: Any, **kwargs: Any) -> ProofResult:
    """Run :func:`prove_one` or :func:`prove_global` in a fresh process, as ``fatline prove`` does."""
    answers: list[ProofResult] = []
    run_fresh([(fn, args, kwargs)], 1, lambda _, answer: answers.append(answer))
    return answers[0]


def prove_fingerprint(model: Model, slots: int, timeout: float) -> str:
    """What a prover result depends on: the model, the settings, the encoding's version."""
    from .cache import fingerprint

    return fingerprint(model, "prove", slots=slots, timeout=timeout, encoding=ob.ENCODING_VERSION)


__all__ = ["ProofResult", "Task", "prove", "prove_one", "rules_for", "task_key", "tasks_for"]
