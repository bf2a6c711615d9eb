"""Which readings a liveness lemma holds under because a checked reading's states trap them.

Graph equality (:mod:`fatline_verify.sweep.equivalent`) closes few readings for ``progress`` and
``termination``: any reading that changes any decision anywhere in the graph differs. Both lemmas
hold for a weaker reason, an *inductive invariant*. Let E be the states the check of reading c
expanded (``after_violation = stop``, every robot count). A reading c' is *trapped* by E when

- every initial state of c' is in E (the initial condition is read through c''s options), and
- for every state s of E, under c': every transition the checker follows (inside the bound, violating
  nothing) leads into E, and s is not a deadlock (some robot enabled, or the robots on the goal).

Then, level by level, c''s search expands only states of E, none of them a deadlock: ``progress``
holds under c' (:func:`fatline_verify.check.checker.lemma_verdicts` reads deadlocks off expanded states).
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

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial

import networkx as nx
import numpy as np

from ..check.engines import engine_for
from ..lemmas.properties import SAFETY, Lemma
from ..model.config import Model
from ..schedulers.base import KeyExpansion, expand_keys
from ..schedulers.systems import system_for
from .equivalent import Equivalence, Explored
from .memo import Memo
from .space import Space

TRAPPED = (Lemma.PROGRESS, Lemma.TERMINATION)
"""The lemmas an invariant closes."""
SPREAD_SAFETY = SAFETY
"""The step lemmas a spread of the open readings' searches closes (:func:`within_known` with ``lemma``):
a reading holds one when no state its search expands has a transition that violates it."""


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
    return expand_keys(system, engine_for(system, "scalar"), system.codec(trap.n, trap.bound), keys)


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
    flags: int = 0
    """The violation bits of every transition, or-ed (a step lemma is violated here when its bit is set)."""


def _initial(trap: Trap, model: Model) -> np.ndarray:
    from ..check.checker import initial_keys_for

    system = system_for(model)
    return initial_keys_for(system, trap.n, trap.window, system.codec(trap.n, trap.bound))


def _step(trap: Trap, key: np.ndarray, model: Model) -> Step:
    got = _expand(trap, key, model)
    follow = got.fits & (got.flags == 0)
    flags = int(np.bitwise_or.reduce(got.flags)) if len(got.flags) else 0
    return Step(bool(got.enabled[0] != 0), bool(got.goal[0]), got.key[follow], bool(got.fits.all()), flags)


def _broken(lemma: Lemma, step: Step) -> bool:
    """Whether a state expanding to ``step`` refutes ``lemma`` there: a step lemma's bit on one of its
    transitions; for the others, a deadlock (no robot enabled, not on the goal)."""
    if lemma in SPREAD_SAFETY:
        return bool(step.flags & lemma.flag)
    return not step.goal and not step.enabled


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


def within_known(
    space: Space,
    among: np.ndarray,
    known: list[Trap],
    memo: Memo,
    ranks: Ranks | None = None,
    grow: int = 0,
    taken: Ranks | None = None,
    lemma: Lemma = Lemma.PROGRESS,
    budget: int = 0,
    tick: Callable[[int], None] | None = None,
    work: int = 0,
) -> Equivalence:
    """Of ``among`` (a mask over ``space``), the combinations under which ``progress`` holds because
    every state their own search reaches is one of ``known`` (the states earlier checks expanded, per
    robot count), none of them a deadlock there; with a step ``lemma`` (:data:`SPREAD_SAFETY`), the
    combinations under which it holds because no state their search reaches has a transition that
    violates it (:func:`fatline_verify.check.checker.lemma_verdicts`: a step lemma is judged on every
    transition out of an expanded state, followed or not).

    A search over all of these combinations at once: each known state carries the combinations that
    reach it; its expansion is asked of ``memo`` for those that are new, and each answer's followed
    successors pass them on. A combination that reaches a state outside ``known`` is dropped (not
    judged), one that reaches a deadlock too (the check that judges it gives the counterexample). What
    is left has followed, from its own initial states, exactly its own transitions into known states
    only, and met no deadlock: the checker's verdict there is HOLDS_WITHIN_BOUNDS. (A single trap is
    the case of one reference; this closes every combination any mixture of them covers.)

    With ``ranks`` (a rank per known state: a topological order of the transitions out of non-goal
    states that the checked readings took), the combinations left also hold ``termination``: a
    combination is dropped as well where a transition leaves the bound (nothing may escape) or where
    a followed transition out of a state that is not a goal there fails to go up in rank. Every
    transition between non-goal states then goes up, so there is no cycle among them, fair or not.

    ``grow`` > 0 (not with ``ranks``): a state outside ``known`` is taken in rather than dropping the
    combinations that reach it, up to ``grow`` new states per robot count. The spread is then every
    open combination's own search at once, and what is left is exactly where no deadlock is reached.
    ``taken``: where to record every transition the spread followed out of a non-goal state (so that
    :func:`spread_termination` can rank them).

    ``budget`` > 0: the bytes the spread's sets of combinations may hold (per state a bit per
    combination, and the combinations not yet passed on); combinations that would pass it are dropped
    like those that leave what is known: fewer closed, none closed wrongly. ``work`` > 0: per robot
    count, the answers (a state's expansion under a class of combinations) the spread may use; past
    them it stops, and every combination whose search is not finished (some state it reached not yet
    passed on) is dropped. Both bounds are counted the same however much ``memo`` remembers, so a run
    with an empty memo closes what one with a full memo closes. ``tick`` hears the states passed on
    so far."""
    before = memo.replays
    alive = among.copy()
    done = peak = 0
    for trap in known:
        where = (trap.n, trap.bound)
        rank = None if ranks is None else ranks.rank(trap.n, trap.bound, trap.window)
        spread = _Spread(
            {key.tobytes() for key in trap.states},
            np.flatnonzero(alive),
            alive,
            0 if rank is not None else grow,
            budget,
        )
        initial = memo.answers(("initial", *where, trap.window), partial(_initial, trap), spread.ids)
        answered = 0
        for inside, keys in list(initial):
            answered += 1
            for key in keys:
                spread.add(key.tobytes(), spread.positions(inside))
        dtype = trap.states.dtype
        while spread.pending:
            if work and answered >= work:
                spread.abandon()  # out of work: what is not finished is not judged here
                break
            key, delta = spread.pop()
            done += 1
            if tick is not None:
                tick(done)
            if not len(delta):
                continue
            compute = partial(_step, trap, np.frombuffer(key, dtype=dtype).copy())
            for inside, step in list(memo.answers(("step", *where, key), compute, delta)):
                answered += 1
                if _broken(lemma, step):
                    alive[inside] = False  # a deadlock, or a violating transition
                    continue
                if rank is not None and not _up(rank, key, step):
                    alive[inside] = False  # something escapes, or a transition does not go up
                    continue
                positions = spread.positions(inside)
                for successor in step.followed:
                    spread.add(successor.tobytes(), positions)
                if taken is not None:
                    taken.take(
                        (trap.n, trap.bound, trap.window), key, step.followed[:0] if step.goal else step.followed
                    )
        peak = max(peak, spread.peak)
    return Equivalence(alive, memo.replays - before, peak)


def spread_termination(
    space: Space,
    among: np.ndarray,
    known: list[Trap],
    memo: Memo,
    grow: int,
    budget: int = 0,
    tick: Callable[[int], None] | None = None,
    work: int = 0,
) -> Equivalence:
    """Of ``among``, the combinations under which ``termination`` holds because no transition of their
    own search lies on a cycle of *any* of their searches.

    First the searches of all of them run together from ``known``, taking in new states (``grow``),
    and every transition they follow out of a non-goal state is recorded: the union graph U. Its
    strongly connected components, in topological order, rank every state (a state's rank is its
    component's place). Then :func:`within_known` with those ranks keeps the combinations whose every
    followed transition out of a non-goal state goes strictly up, nothing escaping and no deadlock:
    such a search never takes a transition inside a component of U, so its non-goal graph (a
    subgraph of U) has no cycle, fair or not, and the checker finds termination holding. ``budget``,
    ``work`` and ``tick``: as for :func:`within_known`, each pass."""
    union = Ranks()
    first = within_known(space, among, known, memo, grow=grow, taken=union, budget=budget, tick=tick, work=work)
    ranked = [
        Trap(t.n, t.bound, t.window, np.union1d(t.states, union.states(t.n, t.bound, t.window, t.states.dtype)))
        for t in known
    ]
    second = within_known(
        space, among & first.same, ranked, memo, union.by_components(), budget=budget, tick=tick, work=work
    )
    return Equivalence(second.same, first.replays + second.replays, max(first.peak, second.peak))


def _up(rank: dict[bytes, int], key: bytes, step: Step) -> bool:
    """Nothing escapes from the state ``key``, and, if it is not a goal, each followed transition
    goes to a state of higher rank (an unranked state counts as lower)."""
    if not step.fits:
        return False
    if step.goal:
        return True
    here = rank.get(key)
    return here is not None and all(rank.get(t.tobytes(), -1) > here for t in step.followed)


@dataclass
class Ranks:
    """Per robot count and bounds, a directed acyclic graph over states: the transitions out of
    non-goal states that checked readings took (a reading whose transitions would close a cycle adds
    none), and its topological order as ranks."""

    graphs: dict[tuple[int, tuple[int, int], tuple[int, int]], nx.DiGraph] = field(default_factory=dict)
    _ranks: dict[tuple[int, tuple[int, int], tuple[int, int]], dict[bytes, int]] = field(default_factory=dict)

    def add(self, reference: Model, explored: list[Explored]) -> None:
        """The transitions of ``reference``'s stopped explorations out of its non-goal states."""
        for ex in explored:
            trap = Trap(ex.n, ex.bound, ex.window, np.sort(ex.expanded))
            got = _expand(trap, trap.states, reference)
            follow = got.fits & (got.flags == 0)
            src = got.src[follow]
            keep = ~got.goal[src]
            edges = [
                (trap.states[a].tobytes(), b.tobytes()) for a, b in zip(src[keep], got.key[follow][keep], strict=True)
            ]
            where = (ex.n, ex.bound, ex.window)
            graph = self.graphs.setdefault(where, nx.DiGraph())
            before = set(graph.edges)
            graph.add_nodes_from(key.tobytes() for key in trap.states)
            graph.add_edges_from(edges)
            if not nx.is_directed_acyclic_graph(graph):
                graph.remove_edges_from([e for e in edges if e not in before])
            self._ranks.pop(where, None)

    def take(self, where: tuple[int, tuple[int, int], tuple[int, int]], key: bytes, targets: np.ndarray) -> None:
        """Record the transitions from ``key`` to ``targets`` (cycles allowed: see :meth:`by_components`)."""
        graph = self.graphs.setdefault(where, nx.DiGraph())
        graph.add_node(key)
        graph.add_edges_from((key, t.tobytes()) for t in targets)
        self._ranks.pop(where, None)

    def states(self, n: int, bound: tuple[int, int], window: tuple[int, int], dtype: np.dtype) -> np.ndarray:
        """Every state of the graph of ``(n, bound, window)``, as keys of ``dtype``."""
        graph = self.graphs.get((n, bound, window), nx.DiGraph())
        return np.array([np.frombuffer(key, dtype=dtype)[0] for key in graph.nodes], dtype=dtype)

    def by_components(self) -> Ranks:
        """Ranks in which each state's rank is its strongly connected component's place in a topological
        order of the components: a transition inside a component never goes up."""
        out = Ranks()
        for where, graph in self.graphs.items():
            condensed = nx.condensation(graph)
            place = {c: k for k, c in enumerate(nx.topological_sort(condensed))}
            out._ranks[where] = {key: place[c] for key, c in condensed.graph["mapping"].items()}
            out.graphs[where] = graph
        return out

    def rank(self, n: int, bound: tuple[int, int], window: tuple[int, int]) -> dict[bytes, int]:
        where = (n, bound, window)
        if where not in self._ranks:
            graph = self.graphs.get(where, nx.DiGraph())
            self._ranks[where] = {state: place for place, state in enumerate(nx.topological_sort(graph))}
        return self._ranks[where]


@dataclass
class _Spread:
    """Which of the combinations ``ids`` (sorted numbers; positions in it stand for them) reach each
    known state (keys as bytes), and those not yet passed on."""

    states: set[bytes]
    ids: np.ndarray
    alive: np.ndarray
    """A mask over every combination, shared with the caller: the ones still judged."""
    grow: int = 0
    """How many more unknown states may be taken in."""
    budget: int = 0
    """Bytes ``reach`` and ``pending`` may hold (0: no bound)."""
    reach: dict[bytes, np.ndarray] = field(default_factory=dict)
    """Per state, a bit per position (packed, little bit order): the combinations that reach it."""
    pending: dict[bytes, list[np.ndarray]] = field(default_factory=dict)
    used: int = 0
    """Bytes ``reach`` and ``pending`` hold now."""
    peak: int = 0

    def positions(self, combos: np.ndarray) -> np.ndarray:
        return np.searchsorted(self.ids, combos)

    def _drop(self, positions: np.ndarray) -> None:
        self.alive[self.ids[positions]] = False

    def _fits(self, more: int) -> bool:
        return not self.budget or self.used + more <= self.budget

    def add(self, key: bytes, positions: np.ndarray) -> None:
        positions = positions[self.alive[self.ids[positions]]]
        if not len(positions):
            return
        mask = self.reach.get(key)
        if mask is None:
            unknown = key not in self.states
            size = (len(self.ids) + 7) // 8
            if (unknown and self.grow <= 0) or not self._fits(size + 4 * len(positions)):
                self._drop(positions)  # it leaves what is known, or the budget: not judged here
                return
            if unknown:
                self.states.add(key)
                self.grow -= 1
            mask = self.reach[key] = np.zeros(size, dtype=np.uint8)
            self.used += size
        new = positions[~_bits(mask, positions, len(self.ids))]
        if not len(new):
            return
        if not self._fits(4 * len(new)):
            self._drop(new)
            return
        _set_bits(mask, new, len(self.ids))
        self.pending.setdefault(key, []).append(new.astype(np.int32))
        self.used += 4 * len(new)
        self.peak = max(self.peak, self.used)

    def abandon(self) -> None:
        """Drop every combination not yet passed on from some state (its search is not finished)."""
        for parts in self.pending.values():
            for part in parts:
                self._drop(part)
        self.pending.clear()
        self.used = 0

    def pop(self) -> tuple[bytes, np.ndarray]:
        """A state with combinations not yet passed on, and those still judged (numbers, sorted)."""
        key, parts = self.pending.popitem()
        self.used -= sum(4 * len(p) for p in parts)
        combos = self.ids[np.sort(np.concatenate(parts))]
        return key, combos[self.alive[combos]]


SPARSE = 256
"""Positions fewer than one in this many of the bits: read and set them one by one; more: unpack the
whole mask once (a bit operation per position costs about as much as unpacking this many bits)."""


def _bits(mask: np.ndarray, positions: np.ndarray, n: int) -> np.ndarray:
    """The bits at ``positions`` of the packed ``mask`` of ``n`` bits (little bit order), as booleans."""
    if len(positions) * SPARSE < n:
        return ((mask[positions >> 3] >> (positions & 7).astype(np.uint8)) & 1).astype(bool)
    return np.unpackbits(mask, count=n, bitorder="little").view(bool)[positions]


def _set_bits(mask: np.ndarray, positions: np.ndarray, n: int) -> None:
    """Set the bits at ``positions`` (each once) of the packed ``mask`` of ``n`` bits."""
    if len(positions) * SPARSE < n:
        np.bitwise_or.at(mask, positions >> 3, np.left_shift(1, positions & 7).astype(np.uint8))
        return
    bits = np.unpackbits(mask, count=n, bitorder="little").view(bool)
    bits[positions] = True
    mask[:] = np.packbits(bits, bitorder="little")
