"""Versioned, schema-checked JSON traces, and replay.

A trace holds the model (every option and parameter), the initial positions, and per step the
active robots, each decision taken (rule, psi_right, destination), the positions after and the step's
violations with their exact measured quantities. Positions are in robot radii. A step is a round
under the round schedulers; under ``async`` it is one event (version 2): ``event`` (look, move, stop)
and ``robot``, and after it every moving robot's path, progress and the positions it decided on.
Version 1 (rounds only) is still read and replayed.

:func:`replay` recomputes everything from the initial positions and the recorded actions, with the
model's transition system; :func:`check_replay` raises :class:`TraceDidNotReproduce` naming the first
value that differs.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

import jsonschema

from ..errors import FatlineError, InvalidInput, InvalidTrace, TraceDidNotReproduce, Unsupported
from ..goals import registry as goal_registry
from ..lemmas import registry as lemma_registry
from ..lemmas.properties import SAFETY, Lemma
from ..model.config import Model, model_from_mapping, model_to_mapping
from ..model.numbers import Point, parse_number
from ..model.options import Scheduler
from ..model.swarm import State
from ..outputs import NotReadable, parse_json, read_regular, write_json
from ..rules import registry as rules_registry
from ..schedulers.base import Step
from ..schedulers.round import lost_edges
from ..schedulers.systems import TransitionSystem, system_for
from .simulate import Outcome, Run, outcome_after
from .steps import _area, _point

FORMAT = "fatline-trace"
VERSION = 2
READABLE_VERSIONS = (1, 2)


@cache
def schema() -> dict[str, Any]:
    """The trace JSON Schema shipped in the package."""
    text = resources.files("fatline_verify").joinpath("schemas/trace.schema.json").read_text(encoding="utf-8")
    return json.loads(text)  # type: ignore[no-any-return]


# --- to JSON ---------------------------------------------------------------------------------------


def run_to_json(run: Run, origin: dict[str, Any] | None = None, focus: str | None = None) -> dict[str, Any]:
    """A whole run as a trace document (schema-valid). ``focus`` names the lemma the trace witnesses
    (default: the first violation of a violating run, or ``progress`` for a deadlock)."""
    model = run.model
    system = system_for(model)
    rounds = [system.step_to_json(r) for r in run.rounds]
    doc: dict[str, Any] = {
        "format": FORMAT,
        "version": VERSION,
        "model": model_to_mapping(model),
        "initial": [_point(model, p) for p in run.initial],
        "rounds": rounds,
        "outcome": str(run.outcome),
        "loop_start": run.loop_start,
        "violation": derive_violation(run, rounds, focus),
    }
    used = plugins_used(model, doc["violation"]["property"] if doc["violation"] else None)
    if used:
        doc["plugins"] = used
    if origin:
        doc["origin"] = origin
    return doc


def plugins_used(model: Model, lemma: str | None) -> list[dict[str, str]]:
    """The plug-ins a trace of ``model`` witnessing ``lemma`` needs to be replayed: its rule set, its
    scheduler, its goal and its lemma where an installed package's entry point registered them, each with that
    package's distribution name and version (``importlib.metadata``)."""
    used = [("rules", model.rules), ("scheduler", str(model.options.scheduler)), ("goal", str(model.options.goal))]
    if lemma is not None:
        used.append(("lemma", lemma))
    out = []
    for kind, name in used:
        found = rules_registry.provider(kind, name)
        if found is not None:
            out.append({"kind": kind, "name": name, "distribution": found.distribution, "version": found.version})
    return out


def require_plugins(doc: dict[str, Any], where: str = "trace") -> None:
    """Every plug-in ``doc`` records (``plugins``) is registered here, or one :class:`InvalidTrace`
    line naming the first missing one and the package to install; a lemma the trace witnesses must
    be known (the paper's or a registered one) even when the trace records no plug-in."""
    known = {
        "rules": lambda name: name in rules_registry.names(),
        "scheduler": _scheduler_known,
        "lemma": lambda name: lemma_registry.find(name) is not None,
        "goal": lambda name: name in goal_registry.names(),
    }
    for entry in doc.get("plugins", ()):
        kind, name = entry["kind"], entry["name"]
        if not known[kind](name):
            dist, version = entry["distribution"], entry["version"]
            package = f"{dist}=={version}" if version else dist
            raise InvalidTrace(
                f"{where}: {kind} {name!r} is a plug-in that is not installed; expected its package "
                f"installed: pip install '{package}'"
            )
    focus = doc["violation"]["property"] if doc.get("violation") else None
    if focus is not None and focus not in {m.value for m in Lemma} and lemma_registry.find(focus) is None:
        names = [*(m.value for m in Lemma), *(m.name for m in lemma_registry.registered())]
        raise InvalidTrace(
            f"{where}: violation.property={focus!r}: unknown lemma; expected one of {', '.join(names)} "
            "(a plug-in's lemma: install its package)"
        )


def _scheduler_known(name: str) -> bool:
    """Whether ``name`` is a scheduler here: ASYNC or a registered round scheduler (plug-ins loaded)."""
    from ..schedulers.activation import round_scheduler

    if name == Scheduler.ASYNC.value:
        return True
    try:
        round_scheduler(name)
    except Unsupported:
        return False
    return True


def approach_stuck(run: Run) -> list[int]:
    """Robots off the right-most axis that never move right again in this execution.

    Lemma 5: "Each robot will move closer to RMA in finite time interval." For a lasso: robots
    left of the loop-start state's RMA whose x does not increase in any round of the loop. For a
    finite run: robots left of the final state's RMA when no robot is enabled there (the execution
    is over). The RMA is the right-most axis of the state at hand, which is the initial one as long
    as rma-fixed holds.
    """
    system = system_for(run.model)
    if run.loop_start is not None:
        start = run.state_at(run.loop_start)
        rma = max(p[0] for p in start)
        loop = run.rounds[run.loop_start :]
        return [i for i, p in enumerate(start) if p[0] < rma and not any(r.after[i][0] > r.before[i][0] for r in loop)]
    final = run.final
    if system.enabled(_state_at(run, system, len(run.rounds))):
        return []
    rma = max(p[0] for p in final)
    return [i for i, p in enumerate(final) if p[0] < rma]


def derive_violation(run: Run, rounds: list[dict[str, Any]], focus: str | None) -> dict[str, Any] | None:
    """The violation record a run witnesses, recomputed from the run (replay compares it)."""
    n_rounds = len(rounds)
    if focus is None:
        if run.outcome is Outcome.VIOLATION:
            focus = rounds[-1]["violations"][0]["property"]
        elif run.outcome is Outcome.DEADLOCK:
            focus = Lemma.PROGRESS
        else:
            return None
    extra = lemma_registry.find(str(focus))
    if extra is not None:
        last = run.rounds[-1] if run.rounds else None
        robots = extra.violators(last.before, last.after, run.model) if last else []
        return {"property": extra.name, "robots": sorted(robots), "round": n_rounds} if robots else None
    try:
        focus = Lemma(focus)
    except ValueError:
        raise InvalidTrace(f"violation.property={focus!r}: unknown lemma") from None
    if focus in SAFETY:
        if run.outcome is not Outcome.VIOLATION:
            return None
        match = next((v for v in rounds[-1]["violations"] if v["property"] == focus), None)
        return None if match is None else {**match, "round": n_rounds}
    name = focus.value
    if focus is Lemma.CONNECTIVITY_EDGE:
        last = run.rounds[-1] if run.rounds else None
        lost = lost_edges(last.before, last.after, run.model) if last else []
        if not lost:
            return None
        (i, j), d2 = lost[0]
        return {"property": name, "robots": [i, j], "distance2_after": [_area(run.model, d2)], "round": n_rounds}
    if focus is Lemma.PROGRESS:
        return {"property": name, "robots": [], "round": n_rounds} if run.outcome is Outcome.DEADLOCK else None
    if focus is Lemma.TERMINATION:
        if run.outcome is Outcome.DEADLOCK or (run.outcome is Outcome.CYCLE and not _loop_meets_goal(run)):
            return {"property": name, "robots": [], "round": n_rounds}
        return None
    assert focus is Lemma.APPROACH
    stuck = approach_stuck(run) if run.outcome in (Outcome.CYCLE, Outcome.DEADLOCK, Outcome.GOAL) else []
    return {"property": name, "robots": stuck, "round": n_rounds} if stuck else None


def _loop_meets_goal(run: Run) -> bool:
    assert run.loop_start is not None
    system = system_for(run.model)
    return any(system.is_goal(_state_at(run, system, k)) for k in range(run.loop_start, len(run.rounds)))


def _state_at(run: Run, system: TransitionSystem, k: int) -> Any:
    """The system state after ``k`` steps."""
    return run.rounds[k - 1].target if k else system.start(run.initial)


def write_trace(doc: dict[str, Any], path: Path) -> None:
    """Write a trace document (validated first, so nothing malformed is ever written)."""
    validate(doc, where=str(path))
    write_json(path, doc)


# --- from JSON --------------------------------------------------------------------------------------


@cache
def _validator() -> Any:
    """The schema's validator, the schema itself checked once (``jsonschema.validate`` checks it on every
    call, 95 % of the time of loading a trace: 13 s for the 385 traces of the corpus)."""
    cls = jsonschema.validators.validator_for(schema())
    cls.check_schema(schema())
    return cls(schema())


def validate(doc: object, *, where: str = "trace") -> None:
    """Check ``doc`` against the schema; one-line :class:`InvalidTrace` naming the first problem (the
    error ``jsonschema.validate`` would raise)."""
    try:
        exc = jsonschema.exceptions.best_match(_validator().iter_errors(doc))
    except RecursionError:
        raise InvalidTrace(f"{where}: arrays or objects nested too deep; expected a trace JSON file") from None
    if exc is not None:
        path = "/".join(str(p) for p in exc.absolute_path) or "(top level)"
        raise InvalidTrace(f"{where}: at {path}: {exc.message}") from None


def load_trace(path: str | Path) -> dict[str, Any]:
    """Read and schema-check a trace file."""
    p = Path(path)
    try:
        data = read_regular(p)  # a FIFO or a device is refused, not waited on or read without end
    except NotReadable as exc:
        raise InvalidTrace(f"trace={str(p)!r}: {exc}; expected a trace JSON file") from None
    try:
        doc = parse_json(data)
    except ValueError as exc:
        raise InvalidTrace(f"trace={str(p)!r}: {exc}; expected a trace JSON file") from None
    validate(doc, where=str(p))
    require_plugins(doc, where=str(p))
    return doc  # type: ignore[no-any-return]


def trace_model(doc: dict[str, Any]) -> Model:
    """The model a trace was recorded under; an unknown option or reading is :class:`InvalidTrace`."""
    try:
        return model_from_mapping(doc["model"], default_name=doc["model"]["name"])
    except FatlineError as exc:
        raise InvalidTrace(f"trace model: {exc}") from None


def _radii(doc_points: list[list[Any]], where: str) -> tuple[Point, ...]:
    out = []
    for k, (x, y) in enumerate(doc_points):
        try:
            out.append((parse_number(x, name=f"{where}[{k}].x"), parse_number(y, name=f"{where}[{k}].y")))
        except ValueError as exc:
            raise InvalidTrace(str(exc)) from None
    return tuple(out)


def _positions(doc_points: list[list[Any]], model: Model, where: str) -> State:
    return tuple(model.to_lattice(p) for p in _radii(doc_points, where))


def initial_radii(doc: dict[str, Any]) -> tuple[Point, ...]:
    """A trace's initial positions as the file stores them: exact, in radius units (whatever its
    model's lattice); a malformed number is :class:`InvalidTrace`."""
    return _radii(doc["initial"], "initial")


def initial_positions(doc: dict[str, Any], model: Model) -> State:
    """A trace's initial positions in ``model``'s lattice units."""
    return _positions(doc["initial"], model, "initial")


def replay(doc: dict[str, Any], model: Model | None = None) -> Run:
    """Recompute a trace's run from its initial positions and actions (under ``model``, by default the
    trace's own), with the model's transition system. Every recorded step is replayed, also past a goal
    state (the robots do not know they form a line, so the checker's witnesses may go on); the outcome
    is judged at the end, and for a lasso (``loop_start``) the loop is checked to close, fairly."""
    model = model or trace_model(doc)
    system = system_for(model)
    initial = initial_positions(doc, model)
    loop_start = doc.get("loop_start")
    n = len(initial)
    state = system.start(initial)
    steps: list[Step] = []
    last: Step | None = None
    for k, record in enumerate(doc["rounds"], start=1):
        where = f"rounds/{k - 1}"
        action = system.action_from_json(record, n, where)
        try:
            system.check_action(state, action, k)
        except InvalidInput as exc:
            raise InvalidTrace(f"{where}: {exc}") from None
        last = system.play(state, action)
        steps.append(last)
        state = last.target
    if loop_start is not None:
        if loop_start >= len(steps):
            raise InvalidTrace(f"loop_start={loop_start}: expected fewer than the {len(steps)} rounds")
        run = Run(model, initial, tuple(steps), Outcome.CYCLE, loop_start)
        closes = system.translated(_state_at(run, system, loop_start), state) and loop_is_fair(run)
        clean = not any(r.violations for r in steps)
        return Run(model, initial, tuple(steps), Outcome.CYCLE if closes and clean else Outcome.ROUND_LIMIT, loop_start)
    outcome = outcome_after(state, last, model, system) or Outcome.ROUND_LIMIT
    return Run(model, initial, tuple(steps), outcome)


def loop_is_fair(run: Run) -> bool:
    """No robot is enabled in every state of the loop without acting in one of its steps."""
    assert run.loop_start is not None
    system = system_for(run.model)
    loop = run.rounds[run.loop_start :]
    for i in range(len(run.initial)):
        idle = not any(i in r.active for r in loop)
        if idle and all(i in system.enabled(r.source) for r in loop):
            return False
    return True


def _walk(recorded: Any, replayed: Any, path: str) -> Iterator[str]:
    """Paths where two JSON values differ, in document order."""
    if isinstance(recorded, dict) and isinstance(replayed, dict):
        for key in list(recorded) + [k for k in replayed if k not in recorded]:
            yield from _walk(recorded.get(key), replayed.get(key), f"{path}.{key}" if path else key)
    elif isinstance(recorded, list) and isinstance(replayed, list):
        for k in range(max(len(recorded), len(replayed))):
            a = recorded[k] if k < len(recorded) else "<missing>"
            b = replayed[k] if k < len(replayed) else "<missing>"
            yield from _walk(a, b, f"{path}[{k}]")
    elif recorded != replayed:
        yield f"{path}: recorded {json.dumps(recorded)}, replayed {json.dumps(replayed)}"


def differences(doc: dict[str, Any], run: Run) -> list[str]:
    """Every recorded value the replayed ``run`` does not reproduce (rounds, outcome, violation)."""
    focus = doc["violation"]["property"] if doc.get("violation") else None
    again = run_to_json(run, focus=focus)
    keys = ("rounds", "outcome", "loop_start", "violation")
    return [d for key in keys for d in _walk(doc.get(key), again.get(key), key)]


def replayed_document(run: Run, origin: dict[str, Any], focus: str) -> dict[str, Any]:
    """The trace of ``run`` as it reads back from JSON, replayed under the run's own model: what a
    tool may report as a witness of ``focus``."""
    doc = json.loads(json.dumps(run_to_json(run, origin, focus=focus)))
    check_replay(doc, run.model)
    return doc


def check_replay(doc: dict[str, Any], model: Model | None = None) -> Run:
    """Replay ``doc``; raise :class:`TraceDidNotReproduce` naming the first differing value."""
    run = replay(doc, model)
    diffs = differences(doc, run)
    if diffs:
        more = f" (and {len(diffs) - 1} more)" if len(diffs) > 1 else ""
        raise TraceDidNotReproduce(f"{diffs[0]}{more}")
    return run
