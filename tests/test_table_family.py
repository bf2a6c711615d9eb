"""A table's move family narrowed to the views it moves in (``fatline_verify/rules/family/narrow.py``): every
decision of the shipped table lies in it, both interpreters read its guards alike, a move in a view the table
does not list is refused, and the connectivity rows the wider family left INCONCLUSIVE are PROVED by it."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove import family as prove_family_module
from fatline_verify.prove.smt.family import BRIDGED, specs
from fatline_verify.rules import registry
from fatline_verify.rules.family.family import family_of
from fatline_verify.rules.family.lang import Ground, holds
from fatline_verify.rules.family.narrow import narrowed
from fatline_verify.rules.repaired.whatif import legs_family
from fatline_verify.rules.table.algorithm import TABLES, load
from tests.test_family import _z3_holds

MODEL = Path(__file__).resolve().parent.parent / "bench" / "table-q1-7x7-ssync.toml"


@pytest.fixture(scope="module")
def table():
    model = load_model(MODEL)
    shipped = load(TABLES / "q1-7x7-ssync.json")
    base = legs_family(model, shipped.legs)
    return model, shipped, base, family_of(registry.get(model.rules).family, model)


def test_the_table_family_is_the_searched_family_narrowed_to_the_table(table):
    _, shipped, base, fam = table
    assert fam.name == f"{base.name}/{shipped.name}"
    assert {c.name for c in fam.classes} <= {c.name for c in base.classes}
    moving = [v for v, e in shipped.table.legs.items() if e != (0, 0)]
    assert len(moving) > 100
    for cls in fam.classes:
        assert f"view(s) {shipped.name} moves by it" in cls.says


def test_every_move_of_the_table_is_in_its_narrowed_family_and_none_elsewhere(table):
    """Each moving view of the table: its leg admitted from that view. The same leg from that view with one more
    robot the table's view does not show (where the wider family still admits it) is refused."""
    model, shipped, base, fam = table
    decide = registry.get(model.rules).decide
    rng = random.Random(7)
    refused = 0
    for view, leg in sorted(shipped.table.legs.items()):
        if leg == (0, 0):
            continue
        decision = decide(view, model)
        assert decision.destination == leg
        assert fam.admit(view, decision, model) is None, (view, leg)
        for _ in range(3):
            extra = (rng.randint(-4, 4), rng.randint(-4, 4))
            far = all((extra[0] - p[0]) ** 2 + (extra[1] - p[1]) ** 2 >= model.contact2 for p in ((0, 0), *view))
            if not far or not model.sees(extra[0] ** 2 + extra[1] ** 2):
                continue
            more = tuple(sorted((*view, extra)))
            if base.admit(more, decision, model) is None and more not in shipped.table.legs:
                assert fam.admit(more, decision, model) is not None, (more, leg)
                refused += 1
    assert refused > 20, refused


def test_both_interpreters_read_the_narrowed_guards_alike(table):
    """On the table's own views (each robot named: exact), and on those views with one robot moved or left out, the
    concrete guard equals the z3 term; some true, some false."""
    model, shipped, _, fam = table
    rng = random.Random(3)
    seen = {True: 0, False: 0}
    views = sorted(v for v, e in shipped.table.legs.items() if e != (0, 0))
    for view in rng.sample(views, 4):
        leg = shipped.table.legs[view]
        low = (view[0][0], view[0][1] - 1)
        ok = model.sees(low[0] ** 2 + low[1] ** 2) and all(
            (low[0] - p[0]) ** 2 + (low[1] - p[1]) ** 2 >= model.contact2 for p in ((0, 0), *view[1:])
        )
        nudged = tuple(sorted((*view[1:], low))) if ok else view[1:]  # one robot lower, or left out
        for v in (view, nudged):
            for cls in [c for c in fam.classes if holds(c.shape, Ground(model, (), {"me": (0, 0), "end": leg}))]:
                got = holds(cls.guard, Ground(model, v, {"me": (0, 0), "end": leg}))
                assert got == _z3_holds(cls.guard, v, leg, model), (v, cls.name)
                seen[got] += 1
    assert seen[True] and seen[False], seen


@pytest.mark.parametrize(
    "key",
    [
        "connectivity/bridged-left.and.top.by.bridge-rest",
        "connectivity/bridged-left.and.rest.by.vertical-top",
    ],
)
def test_a_row_the_wider_family_leaves_open_is_proved_narrowed(table, key, monkeypatch):
    """Two of the six rows the searched family left INCONCLUSIVE (a configuration its guards admit that the table
    does not play): the wider family still leaves them so, the narrowed one decides them PROVED."""
    model, _, base, fam = table
    (spec,) = [s for s in specs(base, (Lemma.CONNECTIVITY,)) if s.form == BRIDGED and s.key == key]
    got = {}
    for name, family in (("wider", base), ("narrowed", fam)):
        monkeypatch.setattr(prove_family_module, "family_for", lambda m, f=family: f)
        got[name] = prove_family_module.prove_family(model, spec, timeout=30, out=None).verdict
    assert got == {"wider": Verdict.INCONCLUSIVE, "narrowed": Verdict.PROVED}


def test_narrowing_to_no_move_is_refused(table):
    model, _, base, _ = table
    with pytest.raises(ValueError, match="makes no move"):
        narrowed(base, {((1, 3),): (0, 0)}, model, "still")
