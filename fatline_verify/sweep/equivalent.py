"""Which readings make a lemma hold for the same reason as a checked one.

A lemma that holds at one combination cannot be covered by a counterexample, and checking each of
half a million combinations one at a time is out of reach. So when a lemma holds at a checked
combination c, the sweep explores c once more with ``after_violation = continue`` (every state
reachable by moves, violating or not) and, if the lemma holds there too, closes every combination c'
whose *continued graph, as this lemma sees it* is c's:

- the same initial states (the window's configurations that meet the initial condition), and
- for every state c expanded, the same expansion: enabled robots, actions, successors, what left the
  bound or the lattice, this lemma's violation bit on each transition, and (for the lemmas about
  where the swarm ends) which states are goal states.

Then c' explores the same continued graph, and the lemma's verdict there is c's: it holds. It holds
under the checker's own semantics too (``after_violation = stop``), which explores a subgraph from the
same initial states: a step lemma is violated on no edge of the subgraph; a deadlock or a fair cycle
of the subgraph is one of the whole graph (fairness is read from the same enabled sets).

A lemma that holds at c only under the checker's own semantics (a liveness lemma where some round
collides: past it the swarm has left the model, and the continued graph may deadlock) closes, the
same way, every c' whose *stopped graph* is c's: the same initial states and, for every state c's
own check expanded, the same expansion as above plus which transitions violate anything (those the
checker does not follow). By induction over the levels, c' then expands exactly c's states with c's
transitions, so every verdict read from them is c's (:func:`fatline_verify.check.checker.lemma_verdicts`
reads only expanded states, their enabled sets and transitions, and the goal). The stopped graph
is smaller, so it also closes readings that differ only past a violation.

Each signature is judged with :func:`fatline_verify.sweep.cover.cover`, one batch of states at a
time; the surviving set shrinks as it goes.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

import numpy as np

from ..check.engines import engine_for
from ..check.exploration import Exploration
from ..check.liveness import fair_cycles
from ..lemmas.properties import CHECKED, SAFETY, Lemma
from ..model.config import Model
from ..schedulers.base import expand_keys
from ..schedulers.systems import system_for
from .cover import cover
from .space import Space

BATCH = 24
"""States judged per replay: fewer means finer splits, more means fewer replays."""


@dataclass(frozen=True, slots=True)
class Explored:
    """What one robot count's exploration started from and expanded (canonical keys)."""

    n: int
    bound: tuple[int, int]
    window: tuple[int, int]
    expanded: np.ndarray
    stopped: bool = False
    """Explored as the checker does (``after_violation = stop``): the signature then also holds which
    transitions violate anything."""

    @classmethod
    def of(cls, ex: Exploration, stopped: bool) -> Explored:
        return cls(ex.n, ex.window, ex.start_window, ex.keys[ex.expanded], stopped)


def held_past_violations(ex: Exploration) -> frozenset[Lemma]:
    """The checked lemmas that hold on a continued exploration (``after_violation = continue``), judged
    as :func:`fatline_verify.check.checker.lemma_verdicts` judges, without witnesses (a witness there may pass
    a violating step, which a trace does not replay). ``approach`` is claimed only with no fair cycle
    at all (the checker examines each cycle's moves)."""
    if ex.truncated:
        return frozenset()
    expanded = ex.expanded
    held = {lemma for lemma in SAFETY if ex.least_violating(lemma.flag) is None}
    if ex.escaped:
        return frozenset(held & set(CHECKED))
    terminal = expanded & (ex.enabled == 0)
    if not np.any(terminal & ~ex.goal):
        held.add(Lemma.PROGRESS)
        if not fair_cycles(ex, expanded & ~ex.goal):
            held.add(Lemma.TERMINATION)
    xs = ex.system.array_positions(ex.state_array(np.nonzero(terminal)[0]))[:, :, 0]
    if not np.any(xs.min(axis=1) < xs.max(axis=1)) and not fair_cycles(ex, expanded):
        held.add(Lemma.APPROACH)
    return frozenset(held & set(CHECKED))


def _initial_sig(n: int, bound: tuple[int, int], window: tuple[int, int], model: Model) -> bytes:
    from ..check.checker import initial_keys_for

    system = system_for(model)
    return initial_keys_for(system, n, window, system.codec(n, bound)).tobytes()


def _expansion_sig(
    n: int, bound: tuple[int, int], keys: np.ndarray, lemma: Lemma, stopped: bool, model: Model
) -> bytes:
    """What ``lemma``'s verdict reads of the expansion of ``keys``, as bytes (the scalar engine: the
    executable model itself, so every reading it depends on is read through the model's options);
    ``stopped``: also which transitions the checker does not follow (they violate something)."""
    system = system_for(model)
    got = expand_keys(system, engine_for(system, "scalar"), system.codec(n, bound), keys)
    parts = [got.enabled, got.src, got.action, got.key, got.fits, got.exact, (got.flags & lemma.flag) != 0]
    if stopped:
        parts.append(got.flags != 0)
    if lemma not in SAFETY:
        parts.append(got.goal)
    return b"|".join(np.ascontiguousarray(p).tobytes() for p in parts)


def _same(signature: Callable[[Model], bytes], reference: bytes, model: Model) -> bool:
    return signature(model) == reference


@dataclass(frozen=True, slots=True)
class Equivalence:
    """The combinations (a mask over the space) whose continued graph the lemma sees as the reference's."""

    same: np.ndarray
    replays: int
    peak: int = 0
    """The most bytes a spread closure's sets of combinations held (0: not a spread)."""


def same_exploration(
    space: Space,
    among: np.ndarray,
    reference: Model,
    explored: list[Explored],
    lemma: Lemma,
    tick: Callable[[int], None] | None = None,
    work: int = 0,
) -> Equivalence:
    """Of ``among`` (a mask over ``space``), the combinations whose continued (or stopped) graph at the
    same bounds ``lemma`` sees as the reference model's, robot count by robot count (see the module
    docstring); ``explored``: the reference's explorations, all continued or all stopped; ``tick`` hears
    the replays so far. ``work`` > 0: past this many replays nothing is closed (equality is known only
    once every signature was judged)."""
    same = among.copy()
    replays = 0
    for ex in explored:
        signatures: list[Callable[[Model], bytes]] = [partial(_initial_sig, ex.n, ex.bound, ex.window)]
        keys = np.sort(ex.expanded)
        signatures += [
            partial(_expansion_sig, ex.n, ex.bound, keys[i : i + BATCH], lemma, ex.stopped)
            for i in range(0, len(keys), BATCH)
        ]
        for signature in signatures:
            if not same.any():
                return Equivalence(same, replays)
            if work and replays >= work:
                return Equivalence(np.zeros_like(among), replays)
            sofar = replays
            inner = None if tick is None else (lambda r: tick(sofar + r))  # noqa: B023 (used at once)
            judged = cover(space, same, partial(_same, signature, signature(reference)), tick=inner)
            replays += judged.replays + 1
            if tick is not None:
                tick(replays)
            same &= judged.refuted
    return Equivalence(same, replays)
