"""``fatline reach`` (:mod:`fatline_verify.repair.reach`): which initial configurations no rule set of the repaired
family can bring to a line, and which it could."""

from __future__ import annotations

import json
import random
from collections import deque
from itertools import combinations

import pytest

from fatline_verify.cli import main
from fatline_verify.model.config import load_model
from fatline_verify.model.swarm import is_connected, is_goal
from fatline_verify.repair.pocket import POCKET
from fatline_verify.repair.reach import PROVED, Family, Kind, canonical, family_legs, universal_deadlock
from fatline_verify.repair.search import confirm_stuck, reach, replay_witness
from fatline_verify.schedulers.round import decide_all, enabled, play_round, snapshot

PROGRESS = "bench/repaired-progress.toml"


def _random_state(rng: random.Random, n: int, model, span: int):
    """A connected, collision-free state of ``n`` robots on ``model``'s lattice (rejection sampling)."""
    while True:
        pts = {(rng.randrange(span), rng.randrange(span)) for _ in range(n)}
        state = tuple(sorted(pts))
        if (
            len(state) == n
            and all((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 >= model.contact2 for a, b in combinations(state, 2))
            and is_connected(state, model)
        ):
            return state


@pytest.mark.parametrize("spec", ["repaired", PROGRESS])
@pytest.mark.parametrize("q", [1, 2])
def test_every_move_of_the_repaired_rules_is_a_leg_of_the_family(spec, q):
    """The family holds the shipped rule sets: whatever they decide is one of the mover's legs (so "no
    rule set of the family" includes them)."""
    model = load_model(spec).with_q(q)
    rng = random.Random(q)
    moves = 0
    for _ in range(300):
        state = _random_state(rng, rng.randrange(2, 6), model, 9 * q)
        for i, d in decide_all(state, model).items():
            if d.moves:
                moves += 1
                legs = {end for end, _ in family_legs(snapshot(state, i, model), model)}
                assert d.destination in legs, (state, i, d.rule, d.destination, legs)
    assert moves > 50


def test_the_pocket_is_stuck_and_left_legs_free_it():
    model = load_model("repaired").with_q(2)
    pocket = canonical(model.to_lattice(p) for p in POCKET.robots)
    # no robot has a leg: the certificate of fatline_verify/repair/pocket.py
    assert confirm_stuck(pocket, Family(model)) == 1
    with pytest.raises(AssertionError, match="reaches the line"):
        confirm_stuck(pocket, Family(model, PROVED | {Kind.LEFT}))


@pytest.mark.parametrize(
    ("q", "n"),
    [(1, 3), pytest.param(1, 4, marks=pytest.mark.slow), (2, 3)],  # 4 robots: the slow tier
    ids=["q1-3robots", "q1-4robots", "q2-3robots"],
)
def test_two_phases_find_what_one_search_of_every_set_of_movers_finds(q, n):
    """Phase 1 (one mover) is a shortcut: the stuck sets equal those of one search with every set of movers."""
    from fatline_verify.repair.reach import starts
    from fatline_verify.repair.search import _Graph

    model = load_model("repaired").with_q(q)
    family = Family(model)
    first = starts(model, n, (9, 9))
    graph = _Graph(family.any_movers, family.safe)
    graph.close(first)
    good = graph.distances(lambda s, m=model: is_goal(s, m))
    assert tuple(sorted(s for s in first if s not in good)) == reach(model, n, (9, 9)).stuck
    assert graph.unsafe == 0  # the proved legs never fail the executable model's checks


def _rules_reach_a_line(state, model, limit=20_000) -> bool:
    """Every activation of the model's own rules from ``state`` (breadth first): is a line reachable?"""
    seen = {canonical(state)}
    queue = deque([state])
    while queue:
        s = queue.popleft()
        if is_goal(s, model):
            return True
        on = enabled(decide_all(s, model))
        for k in range(1, len(on) + 1):
            for active in combinations(on, k):
                nxt = play_round(s, active, model).after
                c = canonical(nxt)
                if c not in seen:
                    seen.add(c)
                    queue.append(c)
        assert len(seen) < limit
    return False


def test_stuck_configurations_are_not_brought_to_a_line_by_the_rules_and_every_other_way_replays():
    """A differential with the executable rules: from each stuck configuration, no activation of the
    repaired rules (with the detour) reaches a line either; each way to a line found replays."""
    model = load_model(PROGRESS).with_q(2)
    result = reach(model, 3, (9, 9), witnesses=True)
    assert result.stuck and result.replayed and result.reached == len(result.witnesses)
    assert result.initial == result.reached + len(result.stuck)
    for s in result.stuck:
        assert not _rules_reach_a_line(s, model)
    some = sorted(result.witnesses)[:: max(1, len(result.witnesses) // 50)]
    assert any(_rules_reach_a_line(s, model) for s in some)


def test_a_way_that_breaks_the_rules_is_reported():
    model = load_model("repaired").with_q(2)
    result = reach(model, 3, (9, 9), witnesses=True)
    family = Family(model)
    start, steps = next((s, w) for s, w in sorted(result.witnesses.items()) if len(w) >= 2)
    assert replay_witness(start, steps, family) == []
    at, moves = steps[0]
    (i, end), *_ = moves
    twisted = [(at, ((i, (-end[0] - 1, end[1])),)), *steps[1:]]
    assert any("has no leg to" in p for p in replay_witness(start, twisted, family))
    assert any("starts from" in p for p in replay_witness(start, steps[1:], family))
    assert any("ends off a line" in p for p in replay_witness(start, steps[:-1], family))
    locked_robot = next(j for j in range(3) if any(c[0] < 0 for c in snapshot(at, j, model)))
    held = [(at, ((locked_robot, (0, 1)),))]
    assert any("held by the lock" in p for p in replay_witness(start, held, family))


def test_the_safety_check_of_what_if_rounds_catches_a_collision():
    model = load_model("repaired")
    family = Family(model, PROVED | {Kind.LEFT})
    state = ((0, 0), (3, 0))
    assert family.safe(state, ((0, (1, 0)),))
    assert not family.safe(state, ((0, (1, 0)), (1, (-1, 0))))


def test_cli_reports_stuck_configurations_and_writes_json(tmp_path, capsys):
    out = tmp_path / "reach.json"
    code = main(["reach", "repaired", "--q", "2", "--robots", "2..3", "--json", str(out), "-q"])
    text = capsys.readouterr().out
    assert code == 1
    command = 'fatline simulate repaired --q 2 --init "0,3/2 1,7/2 3/2,0"'
    assert command in text
    data = json.loads(out.read_text())
    assert data["format"] == "fatline-reach"
    three = data["searches"][1]
    assert three["robots"] == 3 and ["0", "3/2"] in three["stuck"][0]
    assert three["initial"] == three["line_any_movers"] + len(three["stuck"])
    assert three["deadlocked_for_every_algorithm_of_one_radius_lattice_moves"] == []
    assert three["unsafe_rounds"] == 0
    capsys.readouterr()
    assert main(["simulate", "repaired", "--q", "2", "--init", "0,3/2 1,7/2 3/2,0"]) == 1  # the command it prints
    assert "deadlock" in capsys.readouterr().out


def test_cli_without_a_model_reaches_with_the_repaired_one(capsys):
    """The family is the repaired rule set's legs: with no model named, reach uses ``repaired`` (the
    default of the other commands, ``paper``, has no repairs and is refused)."""
    code = main(["reach", "--robots", "2", "-q"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert out.startswith("model repaired:")
    assert main(["reach", "--help"]) == 0
    assert "(default: repaired)" in " ".join(capsys.readouterr().out.split())


def test_cli_with_left_legs_reaches_every_line_and_replays(capsys):
    code = main(["reach", "repaired", "--q", "2", "--robots", "3", "--with", "left", "--verify", "-q"])
    text = capsys.readouterr().out
    assert code == 0
    assert "what-if left" in text and "every initial configuration reaches a line" in text
    assert "was replayed by fatline_verify.schedulers.round.play_round" in text


def _repaired_file(tmp_path, **options):
    from fatline_verify.model.config import model_from_mapping, model_to_mapping

    data = model_to_mapping(load_model("repaired"))
    data["options"].update(options)  # type: ignore[attr-defined]
    model = model_from_mapping(data)
    path = tmp_path / "variant.toml"
    options = data["options"]
    assert isinstance(options, dict)
    lines = ['name = "variant"', "[options]", *(f'{k} = "{v}"' for k, v in options.items())]
    path.write_text("\n".join(lines) + "\n")
    assert load_model(str(path)).options == model.options
    return str(path)


def test_under_fsync_no_deadlock_for_every_algorithm_is_claimed(tmp_path, capsys):
    path = _repaired_file(tmp_path, scheduler="fsync")
    assert main(["reach", path, "--robots", "4", "--window", "9x9", "-q"]) == 1
    text = capsys.readouterr().out
    assert "not looked for under fsync" in text and "DEADLOCKED FOR EVERY ALGORITHM" not in text


@pytest.mark.parametrize(
    ("options", "needle"),
    [
        ({"repair_progress": "corner"}, "repair_progress='corner'"),
        ({"scheduler": "async"}, "scheduler=async"),
        ({"goal": "any-line"}, "goal=any-line"),
    ],
)
def test_models_without_proved_legs_or_another_goal_are_refused(tmp_path, capsys, options, needle):
    assert main(["reach", _repaired_file(tmp_path, **options), "--robots", "2"]) == 2
    err = capsys.readouterr().err
    assert needle in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["reach", "paper"], "expected a model with repair_lock=left-first"),
        (["reach", "repaired", "--window", "3x3", "--robots", "3"], "no initial configuration of 3 robots fits"),
        (["reach", "repaired", "--window", "99999x99999", "--robots", "2"], "does not pack into 63 bits"),
        (["reach", "repaired", "--with", "up"], "with='up': expected what-if leg kinds from left, left-alone, corner"),
        (["reach", "repaired", "--q", "0"], "q='0'"),
        (["reach", "repaired", "--robots", "0"], "robots='0'"),
        (["reach", "repaired", "--window", "9"], "window='9'"),
        (["reach", "repaired", "--max-memory", "lots"], "max-memory='lots'"),
        (["reach", "repaired", "--robots", "3..4", "--window", "9x9", "--max-memory", "1M"], "robots=4 window=9x9"),
    ],
)
def test_cli_bad_input_is_one_line_and_exit_2(argv, needle, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert needle in err and len(err.strip().splitlines()) == 1


def test_cli_does_not_overwrite_a_file_it_did_not_write(tmp_path, capsys):
    mine = tmp_path / "notes.json"
    mine.write_text('{"mine": true}')
    assert main(["reach", "repaired", "--robots", "2", "--json", str(mine), "-q"]) == 2
    assert "is not a fatline reach result" in capsys.readouterr().err
    assert mine.read_text() == '{"mine": true}'


SQUARE = ((0, 0), (0, 4), (4, 0), (4, 4))


def test_the_square_is_a_deadlock_for_every_algorithm_of_one_radius_moves():
    """Each robot of the square, alone with the robots it sees (an L), splits that swarm by each of its
    four unit moves: played again here by the executable model, round by round."""
    from fatline_verify.rules.paper.algorithm import ORIGIN, Decision, Rule

    model = load_model("repaired")
    rows = universal_deadlock(SQUARE, model)
    assert rows is not None and len(rows) == 4 * 4
    for i, end, what in rows:
        star = (ORIGIN, *snapshot(SQUARE, i, model))
        assert len(star) == 3 and is_connected(star, model)  # a legal swarm: the corner of an L
        result = play_round(star, [0], model, {0: Decision(Rule.REPAIR_DETOUR, end, (ORIGIN, end), ())})
        assert result.violations and what == "splits the swarm"


def test_one_radius_moves_off_the_axes_free_the_square_at_q2_and_the_l_is_no_deadlock():
    model = load_model("repaired")
    assert universal_deadlock(SQUARE[:3], model) is None  # the L's other robots may move
    at2 = model.with_q(2)
    assert universal_deadlock(tuple((2 * x, 2 * y) for x, y in SQUARE), at2) is None  # (1/2, 1/2) keeps both edges


def test_the_every_algorithm_deadlocks_are_stuck_for_the_family_and_the_rules_do_not_move_there():
    model = load_model("repaired")
    result = reach(model, 4, (9, 9))
    assert result.universal == (SQUARE,)
    assert set(result.universal) <= set(result.stuck)
    for spec in ("repaired", PROGRESS):
        assert enabled(decide_all(SQUARE, load_model(spec))) == ()


def test_a_longer_move_is_what_frees_the_square_at_q1():
    """The corner repair (a leg of sqrt(2) radii, beyond what the unit-step argument covers) moves there."""
    model = load_model("bench/repaired-corner.toml")
    moves = [d.destination for d in decide_all(SQUARE, model).values() if d.moves]
    assert moves and all(dx * dx + dy * dy > model.radius**2 for dx, dy in moves)
