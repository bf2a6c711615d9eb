"""The facts the repaired rules' leg obligations rest on (:mod:`fatline_verify.prove.facts`), held to the
repaired rules' own ``decide`` on views: every move a leg whose conditions hold, each edge kept or
bridged; the lock (a robot that sees one strictly left of it stays)."""

from __future__ import annotations

import pytest

from fatline_verify.model.config import load_model
from fatline_verify.prove.facts import check_facts, leg_problem, lock_problem, sampled_facts
from fatline_verify.rules import registry
from fatline_verify.rules.paper.algorithm import Decision


@pytest.fixture(scope="module")
def repaired():
    return load_model("repaired")


def test_the_repaired_rules_keep_both_facts_on_a_sample_of_views(repaired) -> None:
    got = sampled_facts(repaired, 1500, seed=3)
    assert got.views == 1500 and got.moving > 100  # the sample has moves to judge
    assert got.holds, got.text()


def test_a_move_that_breaks_the_lock_or_leaves_the_legs_is_named(repaired) -> None:
    """The checks can fail: a robot that sees one strictly left of it and moves breaks the lock; a move
    left is no leg; a move into a robot it sees fails a leg condition."""
    view = ((-3, 0), (3, 0))
    left = Decision("cheat", (-1, 0), ((0, 0), (-1, 0)), ())
    assert "strictly left" in (lock_problem(view, left) or "")
    assert "not to the right" in (leg_problem(repaired, view, left) or "")
    into = Decision("cheat", (1, 0), ((0, 0), (1, 0)), ())
    assert "condition fails for the robot at (2, 1)" in (leg_problem(repaired, ((2, 1),), into) or "")
    stay = registry.decide(view, repaired)
    assert lock_problem(view, stay) is None and leg_problem(repaired, view, stay) is None


@pytest.mark.slow
def test_the_repaired_rules_keep_both_facts_on_every_view_at_q1(repaired) -> None:
    """Every one of the 1,624,375 views at q = 1, rad_v = 4 (2,337 of them with a move; 40 s on one core)."""
    got = check_facts(repaired)
    assert got.views == 1_624_375 and got.moving > 1000
    assert got.holds, got.text()
