"""The sweep's liveness closure: readings a checked reading's states trap hold as the checker says,
and the memo of expansions answers as the executable model does under each reading alone."""

from __future__ import annotations

from functools import partial

import networkx as nx
import numpy as np
import pytest

from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.sweep.invariant import (
    SPREAD_SAFETY,
    TRAPPED,
    Ranks,
    Trap,
    _initial,
    _kept,
    _step,
    spread_termination,
    trapped,
    traps,
    within_known,
)
from fatline_verify.sweep.memo import Memo
from fatline_verify.sweep.run import GROW, SweepBounds, check_combo
from fatline_verify.sweep.space import Space

VARY = ("visibility", "vacant", "contact", "goal")
BOUNDS = SweepBounds((2, 3), (7, 7), bound=(11, 11))


@pytest.fixture(scope="module")
def checked():
    """Every combination of a small space checked on its own (the ground truth)."""
    space = Space(load_model("paper"), VARY)
    found = [check_combo(space.model(space.combo(i)), BOUNDS, space.combo(i)) for i in range(space.size)]
    return space, found


@pytest.mark.parametrize(
    "lemma",
    # termination's closure is in the default tier below (along a rank, the ranked states of several
    # checks, the spread from one reading); its exhaustive run here is in the slow tier
    [pytest.param(lemma, marks=pytest.mark.slow) if lemma is Lemma.TERMINATION else lemma for lemma in TRAPPED],
)
def test_every_trapped_reading_holds_as_its_own_check_says(checked, lemma):
    """Soundness, exhaustively: from every reading where the lemma holds, the readings its states trap
    are ones where the checker, run on them alone, says HOLDS_WITHIN_BOUNDS; and the closure is not
    vacuous (it closes some reading besides its own)."""
    space, found = checked
    holds = np.array([f.verdicts[lemma] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    assert holds.any() and not holds.all()
    memo = Memo(space)
    closed_elsewhere = 0
    for i in np.flatnonzero(holds):
        among = np.ones(space.size, dtype=bool)
        got = trapped(space, among, space.model(space.combo(int(i))), list(found[i].stopped), lemma, memo)
        assert not (got.same & ~holds).any(), [
            space.text(space.combo(int(j))) for j in np.flatnonzero(got.same & ~holds)
        ]
        assert got.same[i], "a reading is trapped by its own states"
        closed_elsewhere += int(got.same.sum()) - 1
    assert closed_elsewhere > 0


def test_a_reading_where_the_lemma_fails_is_never_trapped_by_its_own_states(checked):
    """Where progress fails, the reading's own states hold a deadlock: no invariant closes it."""
    space, found = checked
    i = next(k for k, f in enumerate(found) if f.verdicts[Lemma.PROGRESS] is Verdict.VIOLATED and f.stopped)
    got = trapped(
        space, np.ones(space.size, dtype=bool), space.model(space.combo(i)), list(found[i].stopped), Lemma.PROGRESS
    )
    assert not got.same[i]


def _largest_trap(checked, lemma: Lemma):
    """The first reading where ``lemma`` holds: its largest robot count's trap, and each state's step."""
    space, found = checked
    i = next(k for k, f in enumerate(found) if f.verdicts[lemma] is Verdict.HOLDS_WITHIN_BOUNDS)
    model = space.model(space.combo(i))
    ranked = traps(model, list(found[i].stopped), lemma)
    assert ranked is not None
    trap = ranked[-1]
    return trap, [_step(trap, trap.states[k : k + 1], model) for k in range(len(trap.states))]


def test_termination_is_closed_only_along_a_rank(checked):
    """A reference where termination holds gets a rank on every robot count; with the rank reversed,
    some non-goal transition goes down and its state no longer keeps the reading inside the trap.
    A reference whose non-goal graph cycles (termination fails by a fair cycle) gets no rank."""
    space, found = checked
    trap, steps = _largest_trap(checked, Lemma.TERMINATION)
    assert trap.rank is not None and trap.goal is not None
    assert all(_kept(trap, k, step) for k, step in enumerate(steps))
    broken = Trap(trap.n, trap.bound, trap.window, trap.states, trap.goal, -trap.rank)
    moving = [k for k, step in enumerate(steps) if not step.goal and len(step.followed)]
    assert moving and not all(_kept(broken, k, steps[k]) for k in moving)
    cycles = [f for f in found if f.verdicts[Lemma.PROGRESS] is Verdict.HOLDS_WITHIN_BOUNDS
              and f.verdicts[Lemma.TERMINATION] is Verdict.VIOLATED]  # fmt: skip
    for f in cycles:
        assert traps(space.model(f.combo), list(f.stopped), Lemma.TERMINATION) is None


def test_the_memo_answers_as_the_model_does_under_each_reading_alone():
    """Each combination's answer from the memo's decision tree equals the expansion computed under
    that combination's own model (no recorder), and a second question over the same states costs
    no replay."""
    space = Space(load_model("paper"), ("bands", "vacant", "path", "contact", "timing"))
    base = space.model(space.combo(0))
    from fatline_verify.check.checker import CheckPlan, explore_robots

    ex = explore_robots(CheckPlan.of(base, (3, 3), (7, 7)), 3)
    states = np.sort(ex.keys[ex.expanded])[::7][:12]
    trap = Trap(3, (7, 7), (7, 7), states)
    memo = Memo(space)
    everything = np.arange(space.size)
    for k in range(len(states)):
        compute = partial(_step, trap, states[k : k + 1])
        seen = np.zeros(space.size, dtype=bool)
        for inside, step in memo.answers(("step", k), compute, everything):
            assert not seen[inside].any()
            seen[inside] = True
            for j in inside[:: max(1, len(inside) // 3)]:
                alone = compute(space.model(space.combo(int(j))))
                assert (alone.enabled, alone.goal, alone.fits) == (step.enabled, step.goal, step.fits)
                assert np.array_equal(alone.followed, step.followed)
        assert seen.all()
    before = memo.replays
    assert before < space.size * len(states)  # fewer replays than combinations: the tree shares them
    for k in range(len(states)):
        list(memo.answers(("step", k), partial(_step, trap, states[k : k + 1]), everything))
    assert memo.replays == before
    initial = list(memo.answers(("initial",), partial(_initial, trap), everything))
    assert sum(len(inside) for inside, _ in initial) == space.size


def test_a_state_whose_move_leaves_the_trap_does_not_keep_a_reading_inside(checked):
    """With one reachable state taken out of the trap, the state that moves into it keeps no reading
    inside (its followed transition leaves the invariant), while the full trap keeps it."""
    trap, steps = _largest_trap(checked, Lemma.PROGRESS)
    k, step = next((k, s) for k, s in enumerate(steps) if len(s.followed) and s.followed[0] != trap.states[k])
    assert _kept(trap, k, step)
    fewer = Trap(trap.n, trap.bound, trap.window, trap.states[trap.states != step.followed[0]])
    j = int(np.searchsorted(fewer.states, trap.states[k]))
    assert not _kept(fewer, j, step)


def test_the_states_of_several_checks_close_every_reading_each_trap_does_and_only_where_progress_holds(checked):
    """``within_known`` over the union of the states every holding reading expanded: every reading it
    closes holds progress on its own check, and it closes at least what each single trap closes."""
    space, found = checked
    holds = np.array([f.verdicts[Lemma.PROGRESS] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    union: dict[tuple, np.ndarray] = {}
    memo = Memo(space)
    singles = np.zeros(space.size, dtype=bool)
    for i in np.flatnonzero(holds)[:3]:
        for ex in found[i].stopped:
            where = (ex.n, ex.bound, ex.window)
            union[where] = np.union1d(union.get(where, ex.expanded), ex.expanded)
        everything = np.ones(space.size, dtype=bool)
        singles |= trapped(
            space, everything, space.model(space.combo(int(i))), list(found[i].stopped), Lemma.PROGRESS, memo
        ).same
    known = [Trap(n, bound, window, keys) for (n, bound, window), keys in sorted(union.items())]
    got = within_known(space, np.ones(space.size, dtype=bool), known, memo)
    assert not (got.same & ~holds).any()
    assert (got.same | ~singles).all() and got.same.sum() >= singles.sum() > 0
    assert not within_known(space, ~holds, known, memo).same.any()  # nothing where progress fails


def test_a_spread_within_a_memory_budget_or_a_work_bound_closes_no_more(checked):
    """``budget``: the spread's sets of combinations never hold more bytes; what it closes is a part of
    what the free spread closes (the combinations it could not follow stay open), and a budget as large
    as the free spread's peak changes nothing. A memo that forgets everything answers alike."""
    space, found = checked
    i = next(i for i, f in enumerate(found) if f.verdicts[Lemma.PROGRESS] is Verdict.HOLDS_WITHIN_BOUNDS)
    known = [Trap(ex.n, ex.bound, ex.window, np.sort(ex.expanded)) for ex in found[i].stopped]
    everything = np.ones(space.size, dtype=bool)
    free = within_known(space, everything, known, Memo(space), grow=GROW)
    assert free.peak > 0 and free.same.sum() > 1
    for budget in (free.peak // 2, free.peak // 8):
        tight = within_known(space, everything, known, Memo(space), grow=GROW, budget=budget)
        assert 0 < tight.peak <= budget
        assert not (tight.same & ~free.same).any()
    roomy = within_known(space, everything, known, Memo(space), grow=GROW, budget=free.peak)
    assert (roomy.same == free.same).all() and roomy.peak == free.peak
    forgetful = Memo(space, limit=1)
    again = within_known(space, everything, known, forgetful, grow=GROW)
    assert (again.same == free.same).all() and forgetful.forgotten > 0
    # a work bound: a part of what the free spread closes, the same with an empty memo or a full one
    full = Memo(space)
    within_known(space, everything, known, full, grow=GROW)
    short = [within_known(space, everything, known, memo, grow=GROW, work=40).same for memo in (Memo(space), full)]
    assert (short[0] == short[1]).all() and not (short[0] & ~free.same).any() and short[0].sum() < free.same.sum()
    assert (within_known(space, everything, known, Memo(space), grow=GROW, work=10**9).same == free.same).all()


def test_ranked_states_of_several_checks_close_termination_only_where_it_holds(checked):
    """``within_known`` with the ranks of the readings where termination holds: every reading it
    closes holds termination on its own check (the bound lets nothing escape there), and it closes
    some; a reading where termination fails is never closed."""
    space, found = checked
    holds = np.array([f.verdicts[Lemma.TERMINATION] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    ranks = Ranks()
    union: dict[tuple, np.ndarray] = {}
    for i in np.flatnonzero(holds)[:3]:
        ranks.add(space.model(space.combo(int(i))), list(found[i].stopped))
        for ex in found[i].stopped:
            where = (ex.n, ex.bound, ex.window)
            union[where] = np.union1d(union.get(where, ex.expanded), ex.expanded)
    known = [Trap(n, bound, window, keys) for (n, bound, window), keys in sorted(union.items())]
    memo = Memo(space)
    got = within_known(space, np.ones(space.size, dtype=bool), known, memo, ranks)
    assert not (got.same & ~holds).any()
    assert got.same.sum() >= 3
    assert not within_known(space, ~holds, known, memo, ranks).same.any()
    flat = Ranks()  # no transitions recorded: every non-goal state is unranked, nothing moving is closed
    for where in union:
        flat.graphs[where] = nx.DiGraph()
    moving = within_known(space, np.ones(space.size, dtype=bool), known, memo, flat)
    assert moving.same.sum() < got.same.sum()


def test_a_transition_out_of_a_non_goal_state_must_go_up_in_rank():
    """``_up``: a non-goal state's followed transitions go to higher ranks; an unranked target, a
    lower one or an escaping transition refuses; a goal state only needs nothing to escape."""
    from fatline_verify.sweep.invariant import Step, _up

    keys = np.array([3, 5, 7], dtype=np.uint64)
    rank = {k.tobytes(): place for place, k in enumerate(keys)}

    def step(*targets: int, goal: bool = False, fits: bool = True) -> Step:
        return Step(True, goal, np.array(targets, dtype=np.uint64), fits)

    here = keys[1].tobytes()
    assert _up(rank, here, step(7))
    assert not _up(rank, here, step(3))
    assert not _up(rank, here, step(5))  # a self-loop is a cycle
    assert not _up(rank, here, step(7, 11))  # 11 has no rank
    assert not _up(rank, here, step(7, fits=False))
    assert _up(rank, here, step(3, goal=True))
    assert not _up(rank, np.uint64(11).tobytes(), step(7))


def test_grown_from_one_reading_the_spread_is_every_readings_own_search(checked):
    """With room to take in new states, the spread from one reading's states is the search of every
    reading at once: it closes exactly the readings where progress holds, no more and no fewer."""
    space, found = checked
    holds = np.array([f.verdicts[Lemma.PROGRESS] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    i = int(np.flatnonzero(holds)[0])
    known = [Trap(ex.n, ex.bound, ex.window, np.unique(ex.expanded)) for ex in found[i].stopped]
    got = within_known(space, np.ones(space.size, dtype=bool), known, Memo(space), grow=100_000)
    assert np.array_equal(got.same, holds), [space.text(space.combo(int(j))) for j in np.flatnonzero(got.same != holds)]
    tight = within_known(space, np.ones(space.size, dtype=bool), known, Memo(space), grow=1)
    assert tight.same.sum() < holds.sum()  # with no room, what leaves the states is not judged


STEP_SPACES = {
    Lemma.RMA_FIXED: ("paper", ("quadrants", "path", "contact", "psi_right")),
    Lemma.CONNECTIVITY: ("repaired", ("repair_edges", "repair_lock", "repair_step")),
    Lemma.NO_COLLISION: ("repaired", ("repair_edges", "repair_lock", "repair_step")),
}
"""Per step lemma, a small space where it holds under some readings and not others."""


@pytest.mark.parametrize(
    "lemma",
    # no-collision spreads over the same space of the same model as connectivity: slow tier
    [pytest.param(lemma, marks=pytest.mark.slow) if lemma is Lemma.NO_COLLISION else lemma for lemma in SPREAD_SAFETY],
    ids=lambda lemma: lemma.value,
)
def test_grown_the_spread_closes_a_step_lemma_exactly_where_its_own_check_finds_it_holding(lemma):
    """A step lemma spread from one reading's states: the readings left are exactly those whose own
    check finds no violating transition (some hold and some do not, so both sides are tested)."""
    name, vary = STEP_SPACES[lemma]
    space = Space(load_model(name), vary)
    found = [check_combo(space.model(space.combo(i)), BOUNDS, space.combo(i)) for i in range(space.size)]
    holds = np.array([f.verdicts[lemma] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    assert 0 < holds.sum() < space.size
    i = int(np.flatnonzero(holds)[0])
    known = [Trap(ex.n, ex.bound, ex.window, np.unique(ex.expanded)) for ex in found[i].stopped]
    got = within_known(space, np.ones(space.size, dtype=bool), known, Memo(space), grow=100_000, lemma=lemma)
    assert np.array_equal(got.same, holds), [space.text(space.combo(int(j))) for j in np.flatnonzero(got.same != holds)]


def test_termination_spread_from_one_reading_closes_only_where_termination_holds(checked):
    """Grown from one reading's states, the readings whose transitions never lie on a cycle of the
    union of all their searches hold termination on their own checks; here that is every reading
    where termination holds (none of them has a cycle that is not fair)."""
    space, found = checked
    holds = np.array([f.verdicts[Lemma.TERMINATION] is Verdict.HOLDS_WITHIN_BOUNDS for f in found])
    i = int(np.flatnonzero(holds)[0])
    known = [Trap(ex.n, ex.bound, ex.window, np.unique(ex.expanded)) for ex in found[i].stopped]
    got = spread_termination(space, np.ones(space.size, dtype=bool), known, Memo(space), 100_000)
    assert not (got.same & ~holds).any()
    assert np.array_equal(got.same, holds)


def test_a_transition_inside_a_cycle_of_the_union_never_goes_up():
    """``Ranks.by_components``: states on one cycle share a rank (so ``_up`` refuses a transition
    between them, a self-loop included), and a transition out of the cycle goes up."""
    from fatline_verify.sweep.invariant import Step, _up

    a, b, c = (np.array([v], dtype=np.uint64) for v in (1, 2, 3))
    where = (3, (11, 11), (7, 7))
    union = Ranks()
    union.take(where, a.tobytes(), b)
    union.take(where, b.tobytes(), np.concatenate([a, c]))
    union.take(where, c.tobytes(), c)
    rank = union.by_components().rank(*where)
    assert rank[a.tobytes()] == rank[b.tobytes()] < rank[c.tobytes()]
    assert not _up(rank, a.tobytes(), Step(True, False, b, True))
    assert _up(rank, b.tobytes(), Step(True, False, c, True))
    assert not _up(rank, c.tobytes(), Step(True, False, c, True))
    assert list(union.states(*where, np.dtype(np.uint64))) == [1, 2, 3]
