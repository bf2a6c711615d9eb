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

import os
import re
import time
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
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
from .deadlock import Deadlock
from .replay import Known, Replayed, replay, replay_known
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
    row_key,
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

    covers = [k for k, task in enumerate(tasks) if isinstance(task, CoverageSpec | ViewsSpec)]
    solved = [k for k in range(len(tasks)) if k not in covers]
    workers = max(1, min(jobs or os.cpu_count() or 1, len(tasks)))
    calls: list[tuple[Callable[..., ProofResult], tuple[Any, ...], dict[str, Any]]] = []
    for task in (tasks[k] for k in solved):
        if isinstance(task, FamilySpec):
            calls.append((decided, (prove_family, model, task), {"timeout": timeout, "out": out}))
        elif isinstance(task, LiveSpec):
            calls.append((prove_live, (model, task), {"timeout": timeout, "out": out, "given": tuple(deadlocks)}))
        elif isinstance(task, Spec):
            note = PAPER_PART_NOTE if model.options.repaired else ""
            written = traces if traces is not None else out / "traces" if out else None
            known = _known_all(model, task.key, written, out, earlier)
            kwargs = {"timeout": timeout, "out": out, "note": note, "known": known, "given": tuple(given)}
            if corpus:
                kwargs["corpus"] = corpus_known(paper_part(model), task.key)
            calls.append((decided, (prove_spec, paper_part(model), task), kwargs))
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

    run_fresh(
        calls,
        workers,
        lambda k, result: done(solved[k], result),
        limit=hard_limit(timeout),
        overrun=overrun,
        on_start=lambda k: start(solved[k]),
    )
    for k in covers:  # no solver budget: every view is read once (the views' own processes share the cores)
        from .refine import prove_coverage

        task = tasks[k]
        start(k)
        if isinstance(task, ViewsSpec):
            done(k, prove_views(model, task, sample=task.sample))
            continue
        views = task.views
        exhaustive = views is None
        done(k, prove_coverage(model, exhaustive=exhaustive, sample=views or 0, processes=workers))
    return [r for r in results if r is not None]


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


def witness_path(model: Model, directory: Path, key: str) -> Path:
    """``DIRECTORY/MODEL-prove-LEMMA-FORM-RULE.json`` for the obligation ``key``."""
    from ..outputs import child

    lemma, rest = key.split("/", 1)
    return child(directory, f"{model.name}-prove-{lemma}-{rest}", ".json")


def _known_all(
    model: Model,
    key: str,
    traces: Path | None,
    out: Path | None,
    earlier: Mapping[str, dict[str, Any]] | None,
) -> list[Known]:
    """Every counterexample known for the obligation ``key`` before its search, in the order they are
    replayed: its own from an earlier run, the same obligation's under the models proved beside this
    one, then the same for its mirror image (:func:`mirror_key`), reflected in the x-axis. Each is only
    a candidate: :func:`replay_known` keeps it only if, under this model, its r decides this case and
    breaks this claim."""
    own = _known(model, key, traces) or _known_configuration(key, earlier)
    found = ([(EARLIER, own)] if own else []) + _known_beside(key, out)
    mirror = mirror_key(key)
    if mirror is not None:
        theirs = _known(model, mirror, traces) or _known_configuration(mirror, earlier)
        mirrored = ([(EARLIER, theirs)] if theirs else []) + _known_beside(mirror, out)
        _, case = mirror.split("/", 1)
        found += [(f"the mirror image (y to -y) of {where} for {case}", reflect(doc)) for where, doc in mirrored]
    return found


def corpus_known(model: Model, key: str) -> list[Known]:
    """The shipped corpus's candidates for the obligation ``key`` (:func:`fatline_verify.prove.corpus.known_for`),
    then its mirror obligation's (:func:`mirror_key`), reflected in the x-axis, as for an earlier run's."""
    from .corpus import known_for

    found = known_for(model, key)
    mirror = mirror_key(key)
    if mirror is not None:
        _, case = mirror.split("/", 1)
        found += [
            (f"the mirror image (y to -y) of {where} for {case}", reflect(doc))
            for where, doc in known_for(model, mirror)
        ]
    return found


_MIRROR = {"scenario-2": "scenario-3", "scenario-3": "scenario-2", "up": "down", "down": "up"}


def mirror_key(key: str) -> str | None:
    """The obligation whose case is ``key``'s reflected in the x-axis: Scenario 2 ("R∩B is non-empty
    ... moves upwards") and Scenario 3 (R∩D, downwards) trade places, and so do their search's up and
    down candidates; ``None`` for a case of another rule (Scenario 1 moves right, Scenario 4 towards
    −Y: neither has a mirror among the rules)."""
    lemma, rest = key.split("/", 1)
    if ("scenario-2" not in rest and "scenario-3" not in rest) or "scenario-4" in rest or "scenario-1" in rest:
        return None
    return f"{lemma}/" + re.sub(r"scenario-[23]|\bup\b|\bdown\b", lambda m: _MIRROR[m.group(0)], rest)


def reflect(doc: dict[str, Any]) -> dict[str, Any]:
    """A counterexample reflected in the x-axis: the initial positions (a trace) or the configuration
    (a results row) with y negated; everything else as it was (the replay recomputes the rest)."""

    def neg(v: Any) -> str:
        return str(-Fraction(str(v)))

    if "configuration" in doc:
        flipped = []
        for point in doc["configuration"]:
            x, _, y = str(point).partition(",")
            flipped.append(f"{x},{neg(y)}" if y else str(point))
        return {"configuration": flipped, **({"focus": doc["focus"]} if "focus" in doc else {})}
    out = dict(doc)
    if isinstance(doc.get("initial"), list):
        out["initial"] = [[p[0], neg(p[1])] if isinstance(p, list) and len(p) == 2 else p for p in doc["initial"]]
    return out


def _known(model: Model, key: str, traces: Path | None) -> dict[str, Any] | None:
    """The counterexample an earlier run wrote for the obligation ``key`` under ``traces``, if any."""
    from ..outputs import Kind, is_output, read_json

    if traces is None:
        return None
    path = witness_path(model, traces, key)
    return read_json(path) if path.is_file() and is_output(path, Kind.TRACE) else None


def _known_beside(key: str, out: Path | None) -> list[Known]:
    """The same obligation's counterexamples under the other models proved beside this one
    (``OUT/../OTHER``: its trace, or for a claim without a trace its results row's configuration), in
    name order. A reading that does not bear on the case leaves such a counterexample one here too;
    the replay (:func:`replay_known`) decides, under this model, that its r decides the same case,
    breaks the same claim and starts from an initial configuration."""
    from ..outputs import Kind, is_output, read_json

    if out is None or not out.parent.is_dir():
        return []
    lemma, rest = key.split("/", 1)
    found: list[Known] = []
    for results in sorted(out.parent.glob("*/results.json")):
        other = results.parent
        if other.resolve() == out.resolve() or not is_output(results, Kind.PROVE):
            continue
        where = f"a counterexample found under model {other.name}"
        path = other / "traces" / f"{other.name}-prove-{lemma}-{rest}.json"
        if path.is_file() and is_output(path, Kind.TRACE):
            doc = read_json(path)
            if doc is not None:
                found.append((where, doc))
                continue
        rows = read_json(results) or {}
        by_key = {row_key(row): row for row in rows.get("obligations", []) if isinstance(row, dict)}
        configuration = _known_configuration(key, by_key)
        if configuration is not None:
            found.append((where, configuration))
    return found


def _known_configuration(key: str, earlier: Mapping[str, dict[str, Any]] | None) -> dict[str, Any] | None:
    """The configuration an earlier run replayed as a counterexample of the obligation ``key`` (a
    claim without a trace), from its results row, if any."""
    row = (earlier or {}).get(key)
    if row is None or row.get("verdict") != "VIOLATED" or not row.get("configuration"):
        return None
    return {"configuration": list(row["configuration"])}


EARLIER = "an earlier run's counterexample"
"""Where an obligation's own counterexample from an earlier run comes from, as its reason says."""


def prove_fingerprint(model: Model, slots: int, timeout: float) -> str:
    """What a prover result depends on: the model, the settings, the encoding's version and the
    sources of the plug-ins that decide for the model (:func:`fatline_verify.provenance.plugin_settings`,
    e.g. a plug-in rule set's liveness encoding). This package's own sources are not in it (a change
    of an obligation bumps ``ENCODING_VERSION``), so a built-in model's rows keep their fingerprints."""
    from ..cache import fingerprint
    from ..provenance import plugin_settings

    settings = {"slots": slots, "timeout": timeout, "encoding": ENCODING_VERSION, **plugin_settings(model)}
    return fingerprint(model, "prove", **settings)


ENCODING_VERSION = 11
"""Bumped whenever an obligation's search or meaning changes (part of the cache fingerprint). 3:
role-assigned obligations per decision case; 4: lattices q = 1, 2, 4 with their own shares, an
initial search over the reals after a non-initial solution, fsync replays activate every robot;
5: rounds of growing budget, lattices q = 1, 2, 4, 8, 20, an irrational answer searched past;
6: an obligation's checks end within its budget (blocked retries share their lattice's share), and
vacuity is asked in every round until answered (the repaired rule set's leg obligations were added
under 6: new obligations, no existing one changed); 7: budgets are spent by z3's resource count, not
the wall clock, so verdicts and reasons are the same on every run where the clock stops no check
(a reason says when it did); 8: the linear relaxation of the vacuity question and of the obligation
is asked first (an unsat one decides; the header says so), and what vacuity and the lattices leave
of their shares in a round goes to the reals in that round; 9: the linearization (exact cuts of every
squared distance, refined where a solution breaks them, a solution polished over the reals) replaces
the one relaxation of the obligation, with a share of its own taken from the lattices'; 10: a point
the linearization wrongly puts outside a disc gets local sector cuts (the whole cover was rebuilt on
a finer grid: most of the time went to Python, not z3), its budget counted at 3 times the nonlinear
rate (was 4), a polish repeated at most 3 times per set of free unknowns, and a check's clock limit
0.1 s above 1.5 times its budget (a sliver of budget stopped by the clock was reported as load),
and an earlier run's counterexample of a claim without a trace (its row's configuration) replayed
first, as traces were; 11: every PROVED row carries its basis (vacuous, immediate, substantive:
:mod:`fatline_verify.prove.basis`), a row that cannot fire is reported vacuous however its unsat was
reached, rma-fixed has the ``on-rma`` form (Lemma 3's "a robot on the RMA never leaves it"), and a
repaired model has obligations for the repairs' own destinations (``repair-align``, ``repair-approach``,
``repair-contract``). Not bumped for the small swarms enumerated after the first round
(:mod:`fatline_verify.prove.small`): they find nothing where a row is PROVED (a test runs every
PROVED row of ``proofs/`` through them), and a VIOLATED row replays its own counterexample first, so
only an INCONCLUSIVE row can change, which ``--redo-inconclusive`` re-runs. Nor for the shipped
counterexample corpus (:mod:`fatline_verify.prove.corpus`) and the rows' ``decided_by``: the corpus
only adds candidates replayed first, each believed only if it replays, none of them beside a PROVED
row (``tests/test_prove_corpus.py``), so again only an INCONCLUSIVE row can change. Nor for deadlocks
reached after some rounds (:mod:`fatline_verify.prove.deadlock`: given with ``--known``, or reached from
the small swarms by :func:`fatline_verify.prove.live.reach`): a replayed one makes an enabledness row
VIOLATED that no unsat can have PROVED (the deadlock's named robot is a solution of it), so again only
an INCONCLUSIVE row can change."""


__all__ = [
    "DEFAULT_SLOTS",
    "DEFAULT_TIMEOUT",
    "ENCODED",
    "ENCODING_VERSION",
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
    "prove_fingerprint",
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
