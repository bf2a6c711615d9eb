"""What ``fatline prove --known TRACE`` takes, and what it refuses before any work.

A trace is taken when the executable model of the model being proved replays it from an initial
configuration and it is one of two kinds:

- a **violation** of a lemma some per-case obligation of the model decides: its initial
  configuration is replayed against every per-case obligation before its search, every robot tried
  as r (:func:`fatline_verify.prove.small.given_counterexample`);
- a **deadlock** (connected, not a goal, no robot moves; reached after any number of rounds): the
  enabledness row of each case its named robot decides is VIOLATED by it
  (:mod:`fatline_verify.prove.deadlock`), and with it progress and termination.

Anything else is refused in one line naming the file and what was expected (exit 2): a trace of
another rule set, an outcome that is neither (a goal, a round limit, a cycle: no obligation takes a
run), a violation no obligation encodes, a run that does not start from an initial configuration or
that this model does not reproduce, a deadlock this model has no enabledness row for. A trace taken
but used by no row of the run is named after it, with why (:func:`unused_line`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..errors import FatlineError, InvalidTrace
from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.swarm import initial_problems
from ..trace.simulate import Outcome
from .deadlock import Deadlock, deadlock_of, deadlock_problem


def given_source(name: str) -> str:
    """How a row's reason names a trace given with ``--known`` (followed by a comma in every reason)."""
    return f"given with --known {name}"


@dataclass(frozen=True)
class KnownTrace:
    """A trace ``--known`` takes: its file, and either a violation's initial positions (radii) or a
    replayed deadlock."""

    name: str
    radii: tuple[Point, ...] = ()
    deadlock: Deadlock | None = None


def read_known(model: Model, name: str, tasks: Sequence[Any]) -> KnownTrace:
    """Read ``--known`` trace ``name`` for ``model`` (whose obligations are ``tasks``, all of them):
    taken as a violation or a deadlock, or refused with one :class:`InvalidTrace` line naming the file
    and what was expected."""
    from ..trace.traces import check_replay, initial_positions, initial_radii, load_trace, trace_model
    from .smt.claims import Spec
    from .smt.liveness import ENABLED, LiveSpec

    doc = load_trace(name)  # a bad file: one line
    where = f"known={name!r}"
    theirs = trace_model(doc)
    if theirs.rules != model.rules:
        raise InvalidTrace(
            f"{where}: a trace of rule set {theirs.rules!r} (model {theirs.name}); expected a trace of model "
            f"{model.name}'s rule set {model.rules!r}"
        )
    safety = sorted({str(t.lemma) for t in tasks if isinstance(t, Spec)})
    has_enabled = any(isinstance(t, LiveSpec) and t.form == ENABLED for t in tasks)
    kinds = " or ".join(
        (["a deadlock (a counterexample to progress)"] if has_enabled else [])
        + ([f"a violation of {', '.join(safety)}"] if safety else [])
    )
    outcome = str(doc.get("outcome"))
    usable = (outcome == Outcome.DEADLOCK and has_enabled) or (outcome == Outcome.VIOLATION and safety)
    if not usable:
        if outcome == Outcome.DEADLOCK:
            got = f"a deadlock, but model {model.name} has no enabledness obligation for it to decide"
        else:
            got = f"outcome {outcome!r}"
        expected = (
            f"{kinds}, which obligations of model {model.name} decide"
            if kinds
            else f"no trace: no obligation of model {model.name} takes one"
        )
        raise InvalidTrace(f"{where}: {got}; expected {expected}")
    try:
        start = initial_positions(doc, model)
        problems = initial_problems(start, model)
    except (FatlineError, ValueError) as exc:
        raise InvalidTrace(f"{where}: its initial positions are not on model {model.name}'s lattice ({exc})") from None
    if problems:
        raise InvalidTrace(f"{where}: its first configuration is not initial ({problems[0]}); expected a run from one")
    try:
        run = check_replay(doc, model)
    except FatlineError as exc:
        raise InvalidTrace(
            f"{where}: does not replay under model {model.name} ({exc}); expected a trace its executable model "
            "reproduces"
        ) from None
    if outcome == Outcome.VIOLATION:
        last = {v.lemma.value for v in run.rounds[-1].violations} if run.rounds else set()
        if not last & set(safety):
            raise InvalidTrace(f"{where}: a violation of {', '.join(sorted(last)) or 'nothing'}; expected {kinds}")
        return KnownTrace(name, radii=initial_radii(doc))
    problem = deadlock_problem(model, run)
    if problem:
        raise InvalidTrace(f"{where}: {problem}; expected a connected deadlock that is not a goal")
    origin = {"tool": "fatline prove", "known": name, "from": doc.get("origin", {})}
    found = deadlock_of(model, run, given_source(name), origin)
    assert found is not None
    return KnownTrace(name, deadlock=found)


def unused_line(known: KnownTrace, tasks: Sequence[Any], rows: Iterable[Mapping[str, Any]]) -> str:
    """One line naming ``known`` and why no row of this run (obligations ``tasks``, results ``rows``) used
    it; ``""`` when a row names it as what decided it."""
    from .smt.claims import Spec

    mark = f"{given_source(known.name)},"
    if any(r.get("decided_by") == "given" and mark in str(r.get("reason", "")) for r in rows):
        return ""
    keys = [t.key for t in tasks]
    if known.deadlock is not None:
        wanted = [f"progress/enabled-{case}" for case in known.deadlock.cases]
        run_here = [k for k in wanted if k in keys]
        why = (
            f"its deadlock decides {', '.join(wanted)}, which this run does not prove (--lemma, --redo-inconclusive)"
            if not run_here
            else f"{', '.join(run_here)} did not finish"
        )
    else:
        start = ", ".join(show_point(p) for p in known.radii)
        per_case = [t for t in tasks if isinstance(t, Spec)]
        why = (
            f"its initial configuration {start}, every robot tried as r, decided none of the {len(per_case)} per-case "
            "obligations run here (it breaks none of them, or the corpus or an earlier run's counterexample decided "
            "it first)"
        )
    return f"--known {known.name}: not used: {why}"


__all__ = ["KnownTrace", "given_source", "read_known", "unused_line"]
