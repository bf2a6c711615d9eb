"""Registered goals (:mod:`fatline_verify.goals`): the exact shape tests against their vectorised twins,
the compiled kernel against both, the registry's refusals, and a model file choosing a goal."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.errors import InvalidModel
from fatline_verify.goals import Goal, register_goal
from fatline_verify.goals import registry as goals
from fatline_verify.goals.shapes import (
    at_one_point,
    at_one_point_batch,
    discs_connected,
    discs_connected_batch,
    in_disc,
    in_disc_batch,
    on_circle,
    on_circle_batch,
)
from fatline_verify.model.config import load_model, model_from_mapping, model_to_mapping


def _states(seed: int, m: int, n: int, span: int) -> np.ndarray:
    """Random small states with many repeated points (so ties and coincidences are common)."""
    rng = np.random.default_rng(seed)
    return rng.integers(0, span, size=(m, n, 2)).astype(np.int64)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_vectorised_shapes_equal_the_exact_ones(n: int) -> None:
    states = _states(n, 400, n, 4)
    as_points = [[tuple(p) for p in s] for s in states.tolist()]
    assert at_one_point_batch(states).tolist() == [at_one_point(s) for s in as_points]
    for d in (0, 1, 2, 3, 4):
        assert in_disc_batch(states, d).tolist() == [in_disc(s, d) for s in as_points]
    for r in (0, 1, 2, 3):
        got = on_circle_batch(states, r).tolist()
        assert got == [on_circle(s, r) for s in as_points]
    assert any(on_circle(s, 0) for s in as_points if len(set(s)) >= 3) or n < 3  # the test can tell
    for reach2 in (0, 1, 2, 4, 5):
        got = discs_connected_batch(states, reach2).tolist()
        assert got == [discs_connected(s, reach2) for s in as_points]
        assert n == 1 or reach2 == 0 or (any(got) and not all(got))  # the test can tell


def test_shapes_on_known_configurations() -> None:
    pythagorean = [(5, 0), (0, 5), (3, 4), (-4, 3), (-5, 0)]  # all on the circle of radius 5 about 0
    assert on_circle(pythagorean, 5) and on_circle(pythagorean, 0)
    assert not on_circle(pythagorean, 4)
    assert not on_circle([(0, 0), (1, 0), (2, 0)])  # three on a line are on no circle
    assert on_circle([(0, 0), (2, 0), (0, 2), (2, 2)]) and not on_circle([(0, 0), (2, 0), (0, 2), (3, 3)])
    assert on_circle([(0, 0), (6, 0)], 3) and not on_circle([(0, 0), (7, 0)], 3)
    # the smallest enclosing circle: a diameter for two points, a circumcircle for an acute triangle
    assert in_disc([(0, 0), (4, 0)], 4) and not in_disc([(0, 0), (4, 0)], 3)
    tri = [(0, 0), (4, 0), (2, 3)]  # circumradius 13/6: diameter 13/3 > 4
    assert in_disc(tri, Fraction(13, 3)) and not in_disc(tri, Fraction(43, 10))
    assert in_disc([(Fraction(1, 2), 0), (Fraction(1, 2), 0)], 0) and at_one_point([(1, 2), (1, 2)])
    # discs of radius 1 (reach2 = 4): a chain touching end to end holds together, a gap of any size splits it
    chain = [(0, 0), (2, 0), (2, 2), (4, 2)]
    assert discs_connected(chain, 4) and not discs_connected([*chain[:3], (5, 2)], 4)
    assert not discs_connected([(0, 0), (2, 0), (10, 0), (12, 0)], 4)  # two touching pairs, apart
    assert discs_connected([(0, 0), (Fraction(6, 5), Fraction(8, 5))], 4)  # 2 apart exactly, off the lattice
    assert not discs_connected([(0, 0), (Fraction(6, 5), Fraction(81, 50))], 4) and discs_connected([(3, 3)], 0)


def test_the_compiled_kernel_judges_point_as_the_registry() -> None:
    from fatline_verify.check.compiled_common import at_goal

    states = _states(7, 300, 3, 2)
    want = at_one_point_batch(states).tolist()
    assert any(want) and not all(want)
    assert [at_goal(s, goals.KERNELS["point"], 2) for s in states] == want
    assert not at_goal(states[0], goals.NO_KERNEL, 2)


def _model(goal: str, **table: int) -> object:
    data: dict[str, object] = {"name": "g", "options": {"goal": goal}}
    if table:
        data["goal"] = table
    return model_from_mapping(data)


def test_judge_batch_off_the_lattice_uses_the_exact_check() -> None:
    """Async positions in halves: a state with a robot between lattice points is judged on fractions."""
    model = _model("near-gathering", eps=1)
    halves = np.array([[[0, 0], [2, 0]], [[0, 0], [3, 0]], [[1, 0], [2, 0]], [[0, 0], [0, 0]]], dtype=np.int64)
    got = goals.judge_batch(halves, model, unit=2)
    want = [goals.holds([(Fraction(x, 2), Fraction(y, 2)) for x, y in s], model) for s in halves.tolist()]
    assert got.tolist() == want == [True, False, True, True]


def test_a_model_file_chooses_a_goal_and_its_parameters() -> None:
    model = _model("near-gathering", eps=3)
    assert model.setting("goal") == {"eps": 3}
    data = model_to_mapping(model)
    assert data["goal"] == {"eps": 3} and data["options"]["goal"] == "near-gathering"  # type: ignore[index]
    assert model_from_mapping(data) == model
    assert "goal" not in model_to_mapping(load_model("paper"))  # the paper's data as it was
    with pytest.raises(InvalidModel, match=r"^goal.radius=2: unknown key; expected one of eps$"):
        _model("near-gathering", radius=2)
    with pytest.raises(InvalidModel, match=r"^goal.eps=-1: expected a whole number >= 0"):
        _model("near-gathering", eps=-1)
    with pytest.raises(InvalidModel, match="unknown goal; expected one of vertical-line, any-line, line-meets-discs"):
        _model("gather-all")
    with pytest.raises(InvalidModel, match="goal='point': a goal for points only"):
        _model("point")


def test_an_unknown_goal_is_one_line_exit_2(tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text('name = "m"\n[options]\ngoal = "gather-all"\n')
    got = subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", "check", str(path)], capture_output=True, text=True
    )
    assert got.returncode == 2 and got.stdout == "" and got.stderr.count("\n") == 1
    assert "options.goal='gather-all': unknown goal; expected one of " in got.stderr
    assert "circle" in got.stderr and "near-gathering" in got.stderr


def test_the_registry_refuses_what_a_plug_in_cannot_claim() -> None:
    def always(state: object, model: object) -> bool:
        return True

    with pytest.raises(ValueError, match="compiled kernels are this package's"):
        register_goal(Goal("my-vertical", "x", always, kernel=0))
    with pytest.raises(ValueError, match="registered twice"):
        register_goal(Goal("point", "x", always))
    with pytest.raises(ValueError, match=r"robots=.*expected a tuple of discs, points"):
        register_goal(Goal("my-goal", "x", always, robots=("blobs",)))
    assert "my-goal" not in goals.names() and "my-vertical" not in goals.names()


@pytest.mark.parametrize(("goal", "table"), [("near-gathering", {"eps": 4}), ("circle", {})])
def test_every_engine_gives_the_same_verdicts_for_a_goal_without_a_kernel(goal: str, table: dict[str, int]) -> None:
    """``near-gathering`` and ``circle`` have no compiled kernel: the compiled engine judges them after its
    kernels, by their vectorised checks; the scalar engine by the exact ones. Same verdicts, same states."""
    from fatline_verify.check.checker import check

    model = _model(goal, **table)
    got = {}
    for engine in ("scalar", "fast", "compiled"):
        result = check(model, (2, 3), (7, 7), engine=engine)
        got[engine] = (
            [(r.lemma.value, r.robots, r.verdict.value) for r in result.results],
            [(s.states, s.transitions) for s in result.stats],
        )
    assert got["scalar"] == got["fast"] == got["compiled"]
    liveness = {v for lemma, _, v in got["scalar"][0] if lemma in ("progress", "termination")}
    assert liveness == {"VIOLATED", "HOLDS_WITHIN_BOUNDS"}  # the goal decides something here


def test_touching_is_judged_alike_by_every_engine_and_is_not_a_line() -> None:
    """``touching`` (fat robots' gathering) has no compiled kernel: every engine explores the same states
    and gives the same verdicts; the 2-robot deadlock it finds is on one vertical line, the paper's goal,
    yet its discs are apart, so it is a deadlock short of this goal and not of the paper's."""
    from fatline_verify.check.checker import check

    model = _model("touching")
    got = {}
    for engine in ("scalar", "fast", "compiled"):
        result = check(model, (2, 3), (7, 7), engine=engine)
        got[engine] = (
            [(r.lemma.value, r.robots, r.verdict.value) for r in result.results],
            [(s.states, s.transitions) for s in result.stats],
        )
        progress = next(r for r in result.results if r.lemma.value == "progress" and r.robots == 2)
        assert progress.witness is not None and progress.witness["rounds"] == []
        stuck = [tuple(p) for p in progress.witness["initial"]]
        assert len({x for x, _ in stuck}) == 1 and not discs_connected(stuck, model.contact2)
        assert goals.holds(stuck, _model("vertical-line")) and not goals.holds(stuck, model)
    assert got["scalar"] == got["fast"] == got["compiled"]


def test_touching_between_lattice_points_and_for_points() -> None:
    """Async positions in halves are judged by the vectorised check at that unit, as the exact one does;
    a rule set of point robots cannot name a goal of discs."""
    model = _model("touching")
    halves = np.array([[[0, 0], [4, 0]], [[0, 0], [5, 0]], [[1, 1], [4, 3]], [[0, 0], [3, 3]]], dtype=np.int64)
    got = goals.judge_batch(halves, model, unit=2)
    want = [goals.holds([(Fraction(x, 2), Fraction(y, 2)) for x, y in s], model) for s in halves.tolist()]
    assert got.tolist() == want == [True, False, True, False]
    with pytest.raises(InvalidModel, match="goal='touching': a goal for discs only"):
        model_from_mapping({"name": "g", "rules": "ando", "options": {"goal": "touching"}})


def test_the_prover_claims_nothing_for_a_goal_it_does_not_encode() -> None:
    from fatline_verify.prove.goals import goal_problem

    assert goal_problem(load_model("paper")) == ""
    for goal in ("circle", "near-gathering", "any-line", "touching"):
        assert goal_problem(_model(goal)).endswith("this goal is not encoded, so nothing is claimed")


def test_point_robots_initial_configurations_are_every_distinct_connected_set(monkeypatch: pytest.MonkeyPatch) -> None:
    """For point robots the checker's kernel enumerates distinct positions only (no delta), as the Python
    references do: the same count as brute force over every subset, pairs closer than delta included."""
    from fatline_verify.check.initial import initial_array
    from fatline_verify.check.initial_reference import count_by_brute_force, initial_configurations
    from fatline_verify.model.config import Model
    from fatline_verify.rules import registry
    from fatline_verify.rules.decision import Decision

    def stay(snapshot: object, model: object) -> Decision:  # pragma: no cover - never called
        return Decision("stay", (0, 0), ((0, 0),), ())

    registry.names()
    monkeypatch.setitem(registry._REGISTRY, "test-points", registry.RuleSet("test-points", stay, "x", robots="points"))
    points, discs = Model(rules="test-points"), Model()
    assert points.points and not discs.points and points.apart2 == 1
    for n, window in ((2, (4, 4)), (3, (4, 4)), (3, (5, 3))):
        got = initial_array(n, window, points)
        assert (
            len(got) == count_by_brute_force(n, window, points) == len(list(initial_configurations(n, window, points)))
        )
        assert len(got) > len(initial_array(n, window, discs))
        d2 = ((got[:, :, None, :] - got[:, None, :, :]) ** 2).sum(axis=-1)
        off_diagonal = d2[:, ~np.eye(n, dtype=bool)]
        assert (off_diagonal > 0).all() and (off_diagonal < discs.apart2).any()
