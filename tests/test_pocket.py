"""Pockets (``fatline_verify.repair.pocket``): an initial configuration no repair keeping the lock and moving
robots only rightwards can bring to a line, its certificate checked exactly."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from hypothesis import given
from hypothesis import strategies as st

from fatline_verify.model.config import load_model
from fatline_verify.repair.pocket import POCKET, check
from fatline_verify.rules.repaired.algorithm import locked
from fatline_verify.schedulers.round import decide_all, enabled


def test_the_pocket_is_a_certificate():
    assert check(POCKET, load_model("repaired")) == []


def test_a_broken_certificate_says_what_is_wrong():
    model = load_model("repaired")
    assert any("right side is not covered" in p for p in check(replace(POCKET, cover=POCKET.cover[:3]), model))
    (a, b), k = POCKET.cover[0]
    moved = replace(POCKET, cover=((((Fraction(-1), a[1]), b), k), *POCKET.cover[1:]))  # (-1, 13/10) is outside
    assert any("not inside the disc" in p for p in check(moved, model))
    far = (POCKET.robots[0], POCKET.robots[1], (Fraction(9, 2), Fraction(0)))  # no longer closing the pocket
    assert check(replace(POCKET, robots=far), model)
    wide = replace(POCKET, box=(Fraction(0), Fraction(3, 2), *POCKET.box[2:]))  # the box reaches the blocker
    assert any("strictly to its left" in p for p in check(wide, model))


@given(st.fractions(0, Fraction(1, 2)), st.fractions(Fraction(13, 10), Fraction(177, 100)))
def test_wherever_r_is_in_the_box_both_blockers_are_locked(x, y):
    """The executable lock (``repairs.locked``) on each blocker's snapshot, r anywhere in the box."""
    model = load_model("repaired")
    r = (x, y)
    for b in POCKET.robots[1:]:
        snapshot = [(r[0] - b[0], r[1] - b[1])]
        assert model.sees(model.to_lattice(snapshot[0])[0] ** 2 + model.to_lattice(snapshot[0])[1] ** 2)
        assert locked(snapshot)


def test_the_checker_meets_the_pocket_as_a_deadlock_of_the_repaired_rules():
    """Under the repaired rules with every progress repair on, at q = 2, no robot of it moves."""
    from fatline_verify.model.config import model_from_mapping, model_to_mapping

    data = model_to_mapping(load_model("repaired"))
    data["options"]["repair_progress"] = "corner"  # type: ignore[index]
    model = model_from_mapping(data).with_q(2)
    state = tuple(model.to_lattice(p) for p in POCKET.robots)
    assert enabled(decide_all(state, model)) == ()
