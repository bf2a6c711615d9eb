"""``fatline prove``: each lemma per decision case with z3: PROVED for swarms of every size, or
VIOLATED with a counterexample the executable model replays from an initial configuration.

Obligations (:mod:`fatline_verify.prove.smt.claims`) name r, the witnesses of r's case, and the robot the
claim is about; the rest of any swarm is covered by the witness argument written in each one's
header. Each obligation runs in a fresh process (:mod:`fatline_verify.fresh`). The parts:

- :mod:`fatline_verify.prove.tasks`: which obligations a model has, what a result is, which models
  are refused;
- :mod:`fatline_verify.prove.search`: one decision case decided, in rounds of growing budget
  (vacuity, lattices, the reals);
- :mod:`fatline_verify.prove.replay`: every answer replayed by the executable model;
- :mod:`fatline_verify.prove.family`: a move family's obligations (the repaired rule set's legs among them);
- here: the global form of Lemma 1 (the whole graph; no witness argument, a bounded slot encoding:
  :func:`prove_global`), and :func:`prove`, which runs them all.
"""

from __future__ import annotations

import math
import os
import tempfile
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from ..fresh import isolated, run_fresh
from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.swarm import initial_problems
from ..schedulers.activation import scheduler_for
from ..schedulers.round import play_round
from ..trace.simulate import Outcome, Run
from ..trace.traces import replayed_document
from .candidates import _known_all, corpus_known, witness_path
from .deadlock import Deadlock
from .replay import Replayed, replay, replay_known
from .search import MIN_CHECK, Budget, Given, prove_spec, rounds, rounds_text
from .smt import obligations as ob
from .smt.claims import (
    Spec,
)
from .smt.family import FamilySpec
from .smt.liveness import LiveSpec
from .tasks import (
    DEFAULT_SLOTS,
    DEFAULT_TIMEOUT,
    ENCODED,
    LEMMAS,
    PAPER_PART_NOTE,
    CoverageSpec,
    GlobalTask,
    NotEncodedModel,
    ProofResult,
    Task,
    ViewsSpec,
    check_encoded,
    paper_part,
    task_key,
    tasks_for,
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

    from .smt.solving import WALL

    t0 = time.perf_counter()
    found = _global_on_lattice(model, slots)
    spent = time.perf_counter() - t0
    if found is not None:
        k, doc = found
        return result(
            Verdict.VIOLATED,
            k,
            f"the graph splits, from an initial configuration of {k + 1} robots (lattice q={model.parameters.q}, "
            f"every initial configuration in a {GLOBAL_WINDOW[0]}x{GLOBAL_WINDOW[1]} window and every activation set, "
            "replayed)",
            doc,
        )
    attempts = [(k, True, timeout / 2 / slots) for k in range(1, slots + 1)] + [(slots, False, timeout / 2)]
    last = None
    for k, initial, planned in attempts:
        limit = min(planned, max(0.0, timeout - spent)) / WALL  # even stopped by the wall clock, within timeout
        if limit < MIN_CHECK:
            return result(
                Verdict.INCONCLUSIVE,
                k,
                f"budget exhausted before the {k + 1}-robot attempt; rerun with a larger --timeout",
            )
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
        if scheduler_for(model).forbids(tuple(active), len(state)) is not None:
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


GLOBAL_WINDOW = (7, 7)
"""Where the global form looks on the model's own lattice before asking the solver."""
GLOBAL_STATES = 200_000
"""At most this many states per robot count for that look (it needs only the first round)."""


def _global_on_lattice(model: Model, slots: int) -> tuple[int, dict[str, Any]] | None:
    """A round that splits the graph from an initial configuration on the model's lattice, found by the
    checker's own search (every initial configuration of 2 to ``slots + 1`` robots in
    :data:`GLOBAL_WINDOW`, every activation set the scheduler allows): its shortest connectivity
    witness, when that is one round long, is a counterexample of the global form, already replayed by
    the executable model. ``(slots, trace)`` with the robots besides r, or ``None``."""
    from ..check.checker import CheckPlan, explore_robots
    from ..check.verdicts import lemma_verdicts

    for n in range(2, slots + 2):
        plan = CheckPlan.of(model, (n, n), GLOBAL_WINDOW, max_states=GLOBAL_STATES, engine="fast")
        for got in lemma_verdicts(explore_robots(plan, n)):
            doc = got.witness
            if got.lemma is not Lemma.CONNECTIVITY or got.verdict is not Verdict.VIOLATED or doc is None:
                continue
            if len(doc.get("rounds", [])) == 1 and doc.get("violation", {}).get("components"):
                origin = {"tool": "fatline prove", "lemma": Lemma.CONNECTIVITY.value, "form": "global"}
                return n - 1, {**doc, "origin": origin}
    return None


def prove(
    model: Model,
    lemmas: tuple[Lemma, ...] = LEMMAS,
    *,
    slots: int = DEFAULT_SLOTS,
    timeout: float = DEFAULT_TIMEOUT,
    out: Path | None = None,
    jobs: int | None = None,
    progress: Callable[[str], None] | None = None,
    tasks: list[Task] | None = None,
    on_result: Callable[[ProofResult], None] | None = None,
    traces: Path | None = None,
    earlier: Mapping[str, dict[str, Any]] | None = None,
    given: Sequence[Given] = (),
    on_start: Callable[[str], None] | None = None,
    corpus: bool = True,
    deadlocks: Sequence[Deadlock] = (),
) -> list[ProofResult]:
    """Every obligation of ``lemmas`` (or exactly ``tasks``) for ``model``; ``.smt2`` files under ``out``.

    Each obligation runs in a fresh process (:func:`fatline_verify.fresh.run_fresh`), which also
    spreads them over the cores. ``on_result`` sees each result as it finishes (so a caller can save
    it at once); the list returned is in task order. An interrupt stops the workers and propagates.
    ``traces``: where earlier runs wrote their counterexamples (default ``out/traces``); an
    obligation's own is replayed before any search, so a counterexample once found stays found;
    ``earlier``: an earlier run's results rows by obligation key, whose replayed configurations (the
    claims without a trace: ``closer``, ``seen``, ``x-nondecreasing``) are replayed first likewise;
    ``given``: configurations handed in (``--known``), replayed against every per-case obligation;
    ``on_start(key)``: an obligation's process has started (``progress(key)``: it has finished);
    ``corpus``: the shipped counterexample corpus (:mod:`fatline_verify.prove.corpus`) is replayed
    first of all (``fatline prove --no-corpus``: not at all); ``deadlocks``: replayed deadlocks handed in
    (``--known``), each VIOLATING the enabledness rows of the cases its named robots decide.
    """
    tasks = tasks_for(model, lemmas) if tasks is None else tasks
    if not tasks:
        return []
    check_encoded(model)
    from .basis import decided
    from .family import prove_family, prove_views
    from .live import prove_live
    from .refine import prove_coverage

    views = [k for k, task in enumerate(tasks) if isinstance(task, ViewsSpec)]
    solved = sorted(range(len(tasks)), key=lambda k: _first(tasks[k], earlier, again=k in views[1:]))
    workers = max(1, min(jobs or os.cpu_count() or 1, len(tasks)))
    memo = tempfile.TemporaryDirectory(prefix="fatline-answers-")  # the run's shared answers (prove.memo)
    calls: list[tuple[Callable[..., ProofResult], tuple[Any, ...], dict[str, Any]]] = []
    for task in (tasks[k] for k in solved):
        if isinstance(task, FamilySpec):
            calls.append((decided, (prove_family, model, task), {"timeout": timeout, "out": out, "memo": memo.name}))
        elif isinstance(task, LiveSpec):
            calls.append((prove_live, (model, task), {"timeout": timeout, "out": out, "given": tuple(deadlocks)}))
        elif isinstance(task, Spec):
            note = PAPER_PART_NOTE if model.options.repaired else ""
            written = traces if traces is not None else out / "traces" if out else None
            known = _known_all(model, task.key, written, out, earlier)
            kwargs = {"timeout": timeout, "out": out, "note": note, "known": known, "given": tuple(given)}
            if corpus:
                kwargs["corpus"] = corpus_known(paper_part(model), task.key)
            calls.append((decided, (prove_spec, paper_part(model), task), {**kwargs, "memo": memo.name}))
        elif isinstance(task, ViewsSpec):  # no solver budget: every view is read once
            calls.append((prove_views, (model, task), {"sample": task.sample, "memo": memo.name}))
        elif isinstance(task, CoverageSpec):
            exhaustive = task.views is None
            sample = task.views or 0  # one process (a worker's, daemonic, has no children), beside the solvers
            calls.append((prove_coverage, (model,), {"exhaustive": exhaustive, "sample": sample, "processes": 1}))
        else:
            calls.append((prove_global, (model,), {"slots": slots, "timeout": timeout, "out": out}))
    results: list[ProofResult | None] = [None] * len(tasks)

    def done(k: int, result: ProofResult) -> None:
        results[k] = result
        if on_result:
            on_result(result)
        if progress:
            progress(task_key(tasks[k]))

    def overrun(k: int, seconds: float) -> ProofResult:
        return overrun_result(tasks[solved[k]], seconds, timeout, out)

    def start(k: int) -> None:
        if on_start:
            on_start(task_key(tasks[k]))

    with memo:
        run_fresh(
            calls,
            workers,
            lambda k, result: done(solved[k], result),
            limit=lambda k: None if _reads_views(tasks[solved[k]]) else hard_limit(timeout),
            overrun=overrun,
            on_start=lambda k: start(solved[k]),
        )
    return [r for r in results if r is not None]


def _reads_views(task: Task) -> bool:
    """A views' row (the coverage sample, the in-family views): it reads views, without a solver budget."""
    return isinstance(task, CoverageSpec | ViewsSpec)


def _first(task: Task, earlier: Mapping[str, dict[str, Any]] | None, *, again: bool = False) -> float:
    """Where ``task`` goes in the queue: the views' rows first (each reads every view or a sample of them,
    without a solver budget: among the longest, and without an earlier row the only ones known to be),
    except an in-family views row ``again`` (another lemma's computes the same check): it reads that one's
    answer (:func:`fatline_verify.prove.family.shared_views`), so it goes last, not beside it;
    then the longest first by an earlier run's seconds (its row under ``--out``), so that a run does not end
    on one long obligation while the other cores idle; without an earlier row, in task order (a stable
    sort), which puts the quick rows the corpus decides first."""
    if again:
        return math.inf
    if _reads_views(task):
        return -math.inf
    row = (earlier or {}).get(task_key(task))
    seconds = row.get("seconds") if row is not None else None
    return -float(seconds) if isinstance(seconds, int | float) else 0.0


def hard_limit(timeout: float) -> float:
    """Wall-clock seconds after which an obligation's process is stopped: twice ``--timeout`` and a
    minute more. The budget itself is z3's resource count; what it does not count (the linearization's
    Python, the small swarms, a slow machine) took up to 2.2 times the budget (133 s of a 60 s budget);
    beyond this, a solver ignores its limits."""
    return 2 * timeout + 60


def overrun_result(task: Task, seconds: float, timeout: float, out: Path | None) -> ProofResult:
    """INCONCLUSIVE for an obligation whose process :func:`hard_limit` stopped, saying so."""
    reason = (
        f"stopped after {seconds:.0f} s of wall clock (the limit for --timeout {timeout:g} is "
        f"{hard_limit(timeout):.0f} s): the solver did not keep to its budget; rerun with another --timeout "
        "(its search differs with its budget)"
    )
    lemma, rest = task.key.split("/", 1)
    name = "global.smt2" if isinstance(task, GlobalTask) else f"{rest}.smt2"  # as each form writes it
    path = (out / lemma / name).as_posix() if out is not None else ""
    if isinstance(task, GlobalTask):
        return ProofResult(task.lemma, task.form, "any", Verdict.INCONCLUSIVE, 0, False, seconds, reason, path)
    if isinstance(task, FamilySpec | LiveSpec | CoverageSpec | ViewsSpec):
        rule, case, other = "any", task.name, task.other
    else:
        rule, case, other = task.mine[0].rule.value, task.name, task.other_name
    return ProofResult(
        task.lemma, task.form, rule, Verdict.INCONCLUSIVE, 0, True, seconds, reason, path, case=case, other=other
    )


__all__ = [
    "DEFAULT_SLOTS",
    "DEFAULT_TIMEOUT",
    "ENCODED",
    "LEMMAS",
    "MIN_CHECK",
    "Budget",
    "GlobalTask",
    "NotEncodedModel",
    "ProofResult",
    "Replayed",
    "Task",
    "check_encoded",
    "isolated",
    "paper_part",
    "prove",
    "prove_global",
    "prove_spec",
    "replay",
    "replay_known",
    "rounds",
    "rounds_text",
    "task_key",
    "tasks_for",
    "witness_path",
]
"""The prover's interface, wherever each part lives (:mod:`fatline_verify.prove.tasks`,
:mod:`fatline_verify.prove.search`, :mod:`fatline_verify.prove.replay`)."""
