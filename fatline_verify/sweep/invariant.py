"""Which readings a liveness lemma holds under because a checked reading's states trap them.

Graph equality (:mod:`fatline_verify.sweep.equivalent`) closes few readings for ``progress`` and
``termination``: any reading that changes any decision anywhere in the graph differs. Both lemmas
hold for a weaker reason, an *inductive invariant*. Let E be the states the check of reading c
expanded (``after_violation = stop``, every robot count). A reading c' is *trapped* by E when

- every initial state of c' is in E (the initial condition is read through c''s options), and
- for every state s of E, under c': every transition the checker follows (inside the bound, violating
  nothing) leads into E, and s is not a deadlock (some robot enabled, or the robots on the goal).

Then, level by level, c''s search expands only states of E, none of them a deadlock: ``progress``
holds under c' (:func:`fatline_verify.checker.lemma_verdicts` reads deadlocks off expanded states).
For ``termination`` c's non-goal graph must have no cycle (so c has no fair cycle for a reason a
rank can carry): each state gets its place in a topological order, and c' is trapped when, besides
the above, it has the same goal states on E, no transition leaves the bound (nothing escapes, so
"holds" is not "inconclusive"), and every followed transition between non-goal states goes up in
rank: c''s non-goal graph then has no cycle, fair or not. Both conditions are judged state by state
(:class:`fatline_verify.sweep.memo.Memo`: each state's expansion under every reading, replayed
once per branch of the options it reads and kept across checks), so a reading that differs from c
in a state's decision is still closed if its own decision stays in E.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import networkx as nx
import numpy as np

from ..config import Model
from ..properties import Lemma
from ..systems import system_for
from ..systems.base import KeyExpansion, expand_keys
from .equivalent import Equivalence, Explored
from .memo import Memo
from .space import Space

TRAPPED = (Lemma.PROGRESS, Lemma.TERMINATION)
"""The lemmas an invariant closes."""


@dataclass(frozen=True, slots=True)
class Trap:
    """One robot count's invariant: c's expanded states and, for ``termination``, their goal and rank."""

    n: int
    bound: tuple[int, int]
    window: tuple[int, int]
    states: np.ndarray
    """Sorted canonical keys."""
    goal: np.ndarray | None = None
    rank: np.ndarray | None = None


def _expand(trap: Trap, keys: np.ndarray, model: Model) -> KeyExpansion:
    """The executable model's expansion of ``keys`` (the scalar engine: every option read is recorded)."""
    system = system_for(model)
    return expand_keys(system, system.engine("scalar"), system.codec(trap.n, trap.bound), keys)


def traps(reference: Model, explored: list[Explored], lemma: Lemma) -> list[Trap] | None:
    """The invariants of ``reference``'s stopped explorations for ``lemma``; ``None`` when ``lemma``
    is ``termination`` and some robot count's non-goal graph has a cycle (no rank exists)."""
    out = []
    for ex in explored:
        trap = Trap(ex.n, ex.bound, ex.window, np.sort(ex.expanded))
        if lemma is Lemma.TERMINATION:
            got = _expand(trap, trap.states, reference)
            follow = got.fits & (got.flags == 0)
            dst = np.searchsorted(trap.states, got.key[follow])
            graph = nx.DiGraph()
            graph.add_nodes_from(np.flatnonzero(~got.goal).tolist())
            src = got.src[follow]
            inner = ~got.goal[src] & ~got.goal[dst]
            graph.add_edges_from(zip(src[inner].tolist(), dst[inner].tolist(), strict=True))
            if not nx.is_directed_acyclic_graph(graph):
                return None
            rank = np.zeros(len(trap.states), dtype=np.int64)
            for place, state in enumerate(nx.topological_sort(graph)):
                rank[state] = place
            trap = Trap(trap.n, trap.bound, trap.window, trap.states, got.goal.copy(), rank)
        out.append(trap)
    return out


@dataclass(frozen=True, slots=True)
class Step:
    """What the invariant reads of one state's expansion under one reading."""

    enabled: bool
    goal: bool
    followed: np.ndarray
    """Keys of the transitions the checker follows (inside the bound, violating nothing)."""
    fits: bool
    """Every transition inside the bound."""


def _initial(trap: Trap, model: Model) -> np.ndarray:
    from ..checker import initial_keys_for

    system = system_for(model)
    return initial_keys_for(system, trap.n, trap.window, system.codec(trap.n, trap.bound))


def _step(trap: Trap, key: np.ndarray, model: Model) -> Step:
    got = _expand(trap, key, model)
    follow = got.fits & (got.flags == 0)
    return Step(bool(got.enabled[0] != 0), bool(got.goal[0]), got.key[follow], bool(got.fits.all()))


def _kept(trap: Trap, k: int, step: Step) -> bool:
    """Whether state ``k`` of the trap, expanding to ``step``, keeps a reading inside it (see the
    module docstring)."""
    if not np.isin(step.followed, trap.states).all():
        return False
    if not step.goal and not step.enabled:
        return False  # a deadlock
    if trap.rank is None or trap.goal is None:
        return True
    if step.goal != trap.goal[k] or not step.fits:
        return False
    if step.goal:
        return True
    dst = np.searchsorted(trap.states, step.followed)
    inner = ~trap.goal[dst]
    return bool((trap.rank[dst[inner]] > trap.rank[k]).all())


def trapped(
    space: Space,
    among: np.ndarray,
    reference: Model,
    explored: list[Explored],
    lemma: Lemma,
    memo: Memo | None = None,
) -> Equivalence:
    """Of ``among`` (a mask over ``space``), the combinations that ``reference``'s stopped explorations
    trap (see the module docstring): ``lemma`` holds there within the same bounds. ``memo``: the
    states' expansions under every reading asked so far (kept by the sweep across checks)."""
    found = traps(reference, explored, lemma) if lemma in TRAPPED else None
    if found is None:
        return Equivalence(np.zeros_like(among), 0)
    memo = Memo(space) if memo is None else memo
    before = memo.replays
    same = among.copy()
    for trap in found:
        where = (trap.n, trap.bound)
        initial = memo.answers(("initial", *where, trap.window), partial(_initial, trap), np.flatnonzero(same))
        for inside, keys in list(initial):
            if not np.isin(keys, trap.states).all():
                same[inside] = False
        for k, key in enumerate(trap.states):
            if not same.any():
                return Equivalence(same, memo.replays - before)
            answers = memo.answers(
                ("step", *where, key.tobytes()), partial(_step, trap, trap.states[k : k + 1]), np.flatnonzero(same)
            )
            for inside, step in list(answers):
                if not _kept(trap, k, step):
                    same[inside] = False
    return Equivalence(same, memo.replays - before)
