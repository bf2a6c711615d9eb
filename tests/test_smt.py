"""The z3 encoding against the executable model, obligations re-checked from their SMT-LIB2 files."""

from __future__ import annotations

import json
from fractions import Fraction as Fr

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.algorithm import Rule, decide
from fatline_verify.properties import Verdict
from fatline_verify.prover import isolated, prove_global, prove_one
from fatline_verify.smt.obligations import build, evaluate, recheck_file, smt2, solve
from fatline_verify.trace import check_replay
from tests.conftest import make_model
from tests.test_properties import readings

coord = st.one_of(
    st.integers(-5, 5).map(Fr),
    st.fractions(min_value=-5, max_value=5, max_denominator=4),
)


@st.composite
def snapshots(draw):
    """Up to 4 non-overlapping robots around r (visible or not), lattice or rational."""
    out: list[tuple[Fr, Fr]] = []
    for p in draw(st.lists(st.tuples(coord, coord), max_size=4)):
        if p[0] ** 2 + p[1] ** 2 >= 4 and all((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 >= 4 for c in out):
            out.append(p)
    return out


@settings(max_examples=120, deadline=None)
@given(snapshots(), readings())
def test_encoding_agrees_with_decide(snapshot, opts):
    """Same rule, same destination, on random configurations and readings."""
    model = make_model(**opts)
    visible = [p for p in snapshot if model.sees(p[0] ** 2 + p[1] ** 2)]
    expected = decide(visible, model)
    rule, dest = evaluate(model, snapshot)
    assert rule is expected.rule
    assert dest == tuple(Fr(v) for v in expected.destination)


def test_unsat_obligation_stays_unsat_from_its_file(tmp_path):
    # Two movers, r in Scenario 2, one other robot: it cannot collide with r (unsat with 1 slot).
    model = make_model()
    ob = build(model, "no-collision", "two-movers", Rule.SCENARIO_2, 1)
    assert solve(ob, 10).status == "unsat"
    path = tmp_path / "ob.smt2"
    path.write_text(smt2(ob))
    assert recheck_file(path) == "unsat"


def test_second_solver_agrees_on_the_written_files(tmp_path):
    cvc5 = pytest.importorskip("cvc5")
    model = make_model()
    cases = [
        (build(model, "no-collision", "two-movers", Rule.SCENARIO_2, 1), "unsat"),
        (build(model, "no-collision", "one-mover", Rule.SCENARIO_4_I_NONEMPTY, 1), "sat"),
    ]
    for ob, expected in cases:
        assert solve(ob, 10).status == expected
        path = tmp_path / f"{ob.name}.smt2"
        path.write_text(smt2(ob))
        tm = cvc5.TermManager()
        solver = cvc5.Solver(tm)
        symbols = cvc5.SymbolManager(tm)
        parser = cvc5.InputParser(solver, symbols)
        parser.setFileInput(cvc5.InputLanguage.SMT_LIB_2_6, str(path))
        answer = None
        while True:
            cmd = parser.nextCommand()
            if cmd.isNull():
                break
            said = cmd.invoke(solver, symbols)
            answer = said.strip() or answer
        assert answer == expected


def test_the_paper_s_scenario_4_drop_collides_and_the_witness_replays():
    # "y_p = 0 - d + 1": r stops one radius above the top robot of I. A seeded defect of the paper itself.
    model = make_model()
    result = isolated(
        prove_one, model, "no-collision", "one-mover", Rule.SCENARIO_4_I_NONEMPTY, slots=1, timeout=10, out=None
    )
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)
    assert doc["violation"]["property"] == "no-collision"
    assert doc["rounds"][0]["decisions"][0]["rule"] == "scenario-4-I-nonempty"
    assert Fr(doc["violation"]["closest_distance2"]) < 4


def test_unsat_with_too_few_slots_is_only_bounded():
    model = make_model()
    result = isolated(prove_one, model, "no-collision", "two-movers", Rule.SCENARIO_2, slots=1, timeout=10, out=None)
    assert result.verdict is Verdict.HOLDS_WITHIN_BOUNDS
    assert not result.any_size
    assert "at most 2 robots" in result.reason


def test_scenario_1_unsat_is_a_proof_for_every_size_when_it_holds(tmp_path):
    # Scenario 1 needs one witness (the psi_right robot), so 2 slots carry the any-size argument.
    # Under the default readings the edge form of connectivity fails (r can lose a robot it saw), and the
    # obligation says why unsat would have been enough.
    model = make_model()
    result = isolated(prove_one, model, "connectivity", "one-mover", Rule.SCENARIO_1, slots=2, timeout=10, out=tmp_path)
    assert result.any_size
    assert "unsat proves the claim for swarms of every size" in result.comment
    assert result.verdict is Verdict.VIOLATED
    check_replay(json.loads(json.dumps(result.witness)), model)
    assert (tmp_path / "connectivity" / "one-mover-scenario-1.smt2").read_text().startswith("; Obligation:")


def test_seeded_unsafe_reading_is_refuted_with_a_replayed_trace():
    # Seeded: under contact=strict, touching is a collision, and scenario4_drop=touch stops r exactly
    # touching the top robot of I. The prover must find that, from an initial configuration.
    model = make_model(contact="strict", scenario4_drop="touch")
    result = isolated(
        prove_one, model, "no-collision", "one-mover", Rule.SCENARIO_4_I_NONEMPTY, slots=2, timeout=10, out=None
    )
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)
    assert Fr(doc["violation"]["closest_distance2"]) <= 4


def test_global_connectivity_form_matches_the_checker_on_two_robots(tmp_path):
    # The lattice checker finds 2-robot disconnections under the default readings and none under the
    # literal ones; the global obligation over the reals agrees.
    from fatline_verify.config import load_model

    broken = isolated(prove_global, load_model("paper"), slots=1, timeout=10, out=tmp_path)
    assert broken.verdict is Verdict.VIOLATED
    check_replay(json.loads(json.dumps(broken.witness)), load_model("paper"))
    assert broken.witness["violation"]["property"] == "connectivity"
    kept = isolated(prove_global, load_model("paper-literal"), slots=1, timeout=10, out=None)
    assert kept.verdict is Verdict.HOLDS_WITHIN_BOUNDS
    assert recheck_file(tmp_path / "connectivity" / "global.smt2") == "sat"


def test_forms_follow_the_scheduler():
    from fatline_verify.options import Scheduler
    from fatline_verify.smt.obligations import forms_for

    assert forms_for(Scheduler.SSYNC) == ("one-mover", "two-movers")
    assert forms_for(Scheduler.CENTRALIZED) == ("one-mover",)
    assert forms_for(Scheduler.FSYNC) == ()


@pytest.mark.parametrize(("scheduler", "movers"), [("centralized", 1), ("fsync", 2)])
def test_global_form_activates_what_the_scheduler_allows(scheduler, movers):
    model = make_model(scheduler=scheduler)
    result = isolated(prove_global, model, slots=1, timeout=10, out=None)
    assert result.verdict is Verdict.VIOLATED
    assert len(result.witness["rounds"][0]["active"]) == movers
    check_replay(json.loads(json.dumps(result.witness)), model)
