"""Each lemma's verdict on one explored graph (:class:`~fatline_verify.check.exploration.Exploration`):
VIOLATED with a shortest witness replayed by the executable model (a violating step, a deadlock, a fair
cycle), HOLDS_WITHIN_BOUNDS with the bounds and counts, or INCONCLUSIVE with the reason."""

from typing import Any

import numpy as np

from ..goals.registry import LINES, missed
from ..lemmas.properties import SAFETY, Lemma, LemmaResult, StopReason, Verdict
from ..lemmas.registry import StepLemma, registered
from ..resources import format_size, machine_memory
from ..rules.registry import applies as rule_lemmas
from ..trace.traces import approach_stuck
from .exploration import Exploration, Limit
from .liveness import fair_cycles
from .witness import lasso_run, lasso_witness, state_witness, transition_witness

MAX_LASSOS_TRIED = 20
"""Fair cycles examined for an approach witness before the verdict is INCONCLUSIVE."""


def _result(
    ex: Exploration, lemma: Lemma | StepLemma, verdict: Verdict, reason: str = "", doc: Any = None
) -> LemmaResult:
    rounds = len(doc["rounds"]) if doc else None
    return LemmaResult(lemma, verdict, ex.n, ex.start_window, reason, rounds, doc)


def _bounded(ex: Exploration, lemma: Lemma | StepLemma, liveness: bool) -> LemmaResult:
    """No violation found: HOLDS_WITHIN_BOUNDS, unless a bound cut the search short."""
    if ex.limit is Limit.MAX_MEMORY:
        return _result(
            ex,
            lemma,
            Verdict.INCONCLUSIVE,
            StopReason.MAX_MEMORY.describe(
                f"{ex.n_states:,} states found, {ex.n_states - int(ex.expanded.sum()):,} of them unexplored; the next "
                f"level needs about {format_size(ex.needed_bytes)}; "
                + (
                    f"rerun with --max-memory {format_size(ex.needed_bytes)} or more (deeper levels may need more)"
                    if ex.needed_bytes <= machine_memory()
                    else f"more than this machine's {format_size(machine_memory())}: share it with --cluster, or a "
                    "smaller --bound or --window"
                )
            ),
        )
    if ex.truncated:
        return _result(
            ex,
            lemma,
            Verdict.INCONCLUSIVE,
            StopReason.MAX_STATES.describe(
                f"{ex.n_states:,} states found, {ex.n_states - int(ex.expanded.sum()):,} of them unexplored; "
                f"rerun with --max-states {ex.n_states:,} or more (deeper levels may need more)"
            ),
        )
    if liveness and ex.escaped:
        off = f", {ex.off_lattice} of them off the lattice" if ex.off_lattice else ""
        return _result(ex, lemma, Verdict.INCONCLUSIVE, StopReason.WINDOW.describe(f"{ex.escaped} transitions{off}"))
    w, h = ex.window
    off = f"; {ex.off_lattice} transitions off the lattice not followed" if ex.off_lattice else ""
    iw, ih = ex.start_window
    where = f"window {w}x{h}" if ex.initial_window is None else f"window {iw}x{ih}, bound {w}x{h}"
    return _result(ex, lemma, Verdict.HOLDS_WITHIN_BOUNDS, f"{ex.n} robots, {where}, {ex.n_states} states{off}")


def lemma_verdicts(ex: Exploration) -> list[LemmaResult]:
    """Every lemma's verdict on one explored graph, witnesses replayed."""
    out: dict[Any, LemmaResult] = {}
    expanded = ex.expanded
    extras = registered()
    applies = rule_lemmas(ex.model)  # the rule set's own setting: a lemma it does not claim is not judged
    step: tuple[Lemma | StepLemma, ...] = (*(lemma for lemma in SAFETY if lemma in applies), *extras)
    for lemma in step:
        first = ex.least_violating(lemma.flag)  # the search's summaries: the least (source, action)
        if first is not None:
            doc = transition_witness(ex, *first, lemma)
            out[lemma] = _result(ex, lemma, Verdict.VIOLATED, f"a violating {ex.system.step_word}", doc)
        else:
            out[lemma] = _bounded(ex, lemma, liveness=False)

    terminal = expanded & (ex.enabled == 0)
    deadlocks = np.nonzero(terminal & ~ex.goal)[0]
    if Lemma.PROGRESS in applies or Lemma.TERMINATION in applies:
        out.update(_liveness(ex, expanded, deadlocks))
    if Lemma.APPROACH in applies:
        out[Lemma.APPROACH] = _approach(ex, terminal)
    return [out[lemma] for lemma in (*applies, *extras)]


def _never(goal: str) -> str:
    """A fair cycle's reason: the paper's words for its line goals, the goal's name for the others."""
    return "a fair cycle never forms the line" if goal in LINES else f"a fair cycle never reaches the goal ({goal})"


def _liveness(ex: Exploration, expanded: np.ndarray, deadlocks: np.ndarray) -> dict[Lemma, LemmaResult]:
    """Progress (a reachable deadlock) and termination (a deadlock, or a fair cycle that never reaches the goal)."""
    out: dict[Lemma, LemmaResult] = {}
    if len(deadlocks):
        for lemma in (Lemma.PROGRESS, Lemma.TERMINATION):
            doc = state_witness(ex, int(deadlocks[0]), lemma)
            reason = f"a deadlock: no robot enabled, {missed(str(ex.model.options.goal))}"
            out[lemma] = _result(ex, lemma, Verdict.VIOLATED, reason, doc)
        return out
    out[Lemma.PROGRESS] = _bounded(ex, Lemma.PROGRESS, liveness=False)
    lassos = fair_cycles(ex, expanded & ~ex.goal)
    if lassos:
        doc = lasso_witness(lasso_run(ex, lassos[0].start, lassos[0].cycle), ex, Lemma.TERMINATION)
        out[Lemma.TERMINATION] = _result(
            ex, Lemma.TERMINATION, Verdict.VIOLATED, _never(str(ex.model.options.goal)), doc
        )
    else:
        out[Lemma.TERMINATION] = _bounded(ex, Lemma.TERMINATION, liveness=True)
    return out


def _approach(ex: Exploration, terminal: np.ndarray) -> LemmaResult:
    """Lemma 5: a terminal state with a robot left of the RMA, or a fair cycle where one never moves right."""
    candidates = np.nonzero(terminal)[0]  # only terminal states are decoded
    xs = ex.system.array_positions(ex.state_array(candidates))[:, :, 0]
    stuck = candidates[xs.min(axis=1) < xs.max(axis=1)]
    if len(stuck):
        doc = state_witness(ex, int(stuck[0]), Lemma.APPROACH)
        return _result(ex, Lemma.APPROACH, Verdict.VIOLATED, "no robot can move and some are left of the RMA", doc)
    lassos = fair_cycles(ex, ex.expanded)
    for lasso in lassos[:MAX_LASSOS_TRIED]:
        run = lasso_run(ex, lasso.start, lasso.cycle)
        if approach_stuck(run):
            doc = lasso_witness(run, ex, Lemma.APPROACH)
            return _result(ex, Lemma.APPROACH, Verdict.VIOLATED, "a fair cycle where a robot never moves right", doc)
    if lassos:
        detail = f"{min(len(lassos), MAX_LASSOS_TRIED)} of {len(lassos)} fair cycles examined"
        return _result(ex, Lemma.APPROACH, Verdict.INCONCLUSIVE, StopReason.CYCLE_NOT_DECISIVE.describe(detail))
    return _bounded(ex, Lemma.APPROACH, liveness=True)
