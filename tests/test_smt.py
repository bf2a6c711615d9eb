"""The z3 encoding against the executable model, obligations re-checked from their SMT-LIB2 files."""

from __future__ import annotations

import json
from fractions import Fraction as Fr
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.lemmas.properties import Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove.prover import isolated, prove_global, prove_spec, tasks_for
from fatline_verify.prove.smt.certificates import cvc5_answer
from fatline_verify.prove.smt.obligations import evaluate, recheck_file
from fatline_verify.rules.registry import decide
from fatline_verify.trace.traces import check_replay
from tests.conftest import make_model, task_named
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


def _cvc5(path):
    """cvc5's answer to a written file, through the tool's own reader (its parser: the file alone is the
    obligation)."""
    pytest.importorskip("cvc5")
    return cvc5_answer(path)


def test_a_proved_obligation_stays_unsat_from_its_file_for_both_solvers(tmp_path):
    # No rule moves r right of every robot it sees, in Scenario 1, for swarms of any size.
    model = make_model()
    result = isolated(prove_spec, model, task_named(model, "rma-fixed/seen-scenario-1"), timeout=20, out=tmp_path)
    assert result.verdict is Verdict.PROVED and result.any_size
    path = tmp_path / "rma-fixed" / "seen-scenario-1.smt2"
    assert "Why unsat covers swarms of every size" in path.read_text()
    assert recheck_file(path) == "unsat"
    assert _cvc5(path) == "unsat"


def test_the_paper_s_hidden_robot_scenario_1_collision_is_found_and_replays():
    # r moves to the foot of psi_right; a robot r cannot see ends closer than 2 to r's destination.
    model = make_model()
    result = isolated(prove_spec, model, task_named(model, "no-collision/one-mover-scenario-1"), timeout=20, out=None)
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)
    assert doc["violation"]["property"] == "no-collision"
    assert doc["rounds"][0]["decisions"][0]["rule"] == "scenario-1"


def test_the_paper_s_scenario_4_drop_collides_and_the_witness_replays():
    # "y_p = 0 - d + 1": r stops one radius above the top robot of I. A defect of the paper itself.
    model = make_model()
    key = "no-collision/one-mover-scenario-4-I-nonempty.from-uncovered-neither"
    result = isolated(prove_spec, model, task_named(model, key), timeout=20, out=None)
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)
    assert doc["rounds"][0]["decisions"][0]["rule"] == "scenario-4-I-nonempty"
    assert Fr(doc["violation"]["closest_distance2"]) < 4


def test_a_case_that_never_fires_is_proved_vacuously(tmp_path):
    # Candidate 4 within view (rad_v = 4) needs x_psi = 0, which no B u C u D robot gives.
    model = make_model()
    result = isolated(
        prove_spec, model, task_named(model, "no-collision/one-mover-scenario-2.down-4"), timeout=10, out=tmp_path
    )
    assert result.verdict is Verdict.PROVED
    assert "never fires" in result.reason
    assert recheck_file(tmp_path / "no-collision" / "one-mover-scenario-2.down-4.smt2") == "unsat"


def test_literal_quadrants_never_fire_scenario_3():
    # Under quadrants=literal D is the upper left: R_psi n C and R_psi n D are never both non-empty.
    model = make_model(quadrants="literal")
    for task in tasks_for(model):
        if getattr(task, "form", "") == "seen" and task.mine[0].rule.value == "scenario-3":
            result = isolated(prove_spec, model, task, timeout=20, out=None)
            assert result.verdict is Verdict.PROVED and "never fires" in result.reason
            break
    else:
        raise AssertionError("no scenario-3 obligation")


def test_seeded_unsafe_reading_is_refuted_with_a_replayed_trace():
    # Seeded: under contact=strict, touching is a collision, and scenario4_drop=touch stops r exactly
    # touching the top robot of I. The prover must find that, from an initial configuration.
    model = make_model(contact="strict", scenario4_drop="touch")
    key = "no-collision/one-mover-scenario-4-I-nonempty.from-uncovered-neither"
    result = isolated(prove_spec, model, task_named(model, key), timeout=20, out=None)
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)
    assert Fr(doc["violation"]["closest_distance2"]) <= 4


def test_a_claim_counterexample_is_a_configuration_decide_replays():
    # Lemma 1's argument: in Scenario 2, r moving down is not always closer to the B robots it sees.
    from fatline_verify.rules.paper.algorithm import Band
    from fatline_verify.rules.paper.cases import case_of

    model = make_model()
    result = isolated(
        prove_spec, model, task_named(model, "connectivity/closer-scenario-2.down-1"), timeout=20, out=None
    )
    assert result.verdict is Verdict.VIOLATED
    state = [tuple(Fr(v) for v in p.split(",")) for p in result.configuration]
    assert state[0] == (0, 0)
    dec = decide([p for p in state[1:] if model.sees(p[0] ** 2 + p[1] ** 2)], model)
    assert case_of(dec, model).name == "scenario-2.down-1"
    dx, dy = dec.destination
    assert any(
        m & {Band.B, Band.C, Band.D} and (c[0] - dx) ** 2 + (c[1] - dy) ** 2 >= c[0] ** 2 + c[1] ** 2
        for c, m in dec.classification
    )


def test_global_connectivity_form_matches_the_checker_on_two_robots(tmp_path):
    # The lattice checker finds 2-robot disconnections under the default readings and none under the
    # literal ones; the global obligation over the reals agrees (sat, and unsat under literal).

    broken = isolated(prove_global, load_model("paper"), slots=1, timeout=20, out=tmp_path)
    assert broken.verdict is Verdict.VIOLATED
    check_replay(json.loads(json.dumps(broken.witness)), load_model("paper"))
    assert broken.witness["violation"]["property"] == "connectivity"
    kept = isolated(prove_global, load_model("paper-literal"), slots=1, timeout=20, out=None)
    assert kept.verdict is Verdict.HOLDS_WITHIN_BOUNDS
    assert recheck_file(tmp_path / "connectivity" / "global.smt2") == "sat"


def test_global_form_looks_on_the_lattice_first_and_keeps_a_one_round_split_only():
    """Under the literal readings two robots never split, three do (the solver alone ran out of time
    on it): the checker's search of every initial configuration in the window finds the round, and
    the result is its replayed trace, one round from an initial configuration."""
    from fatline_verify.prove.prover import _global_on_lattice

    model = load_model("paper-literal")
    assert _global_on_lattice(model, 1) is None
    result = isolated(prove_global, model, slots=2, timeout=5, out=None)
    assert result.verdict is Verdict.VIOLATED and "lattice q=1" in result.reason, result.reason
    assert result.slots == 2 and len(result.witness["initial"]) == 3 and len(result.witness["rounds"]) == 1
    assert result.witness["origin"]["form"] == "global"
    check_replay(json.loads(json.dumps(result.witness)), model)


def test_forms_follow_the_scheduler():
    forms = {
        s: {getattr(t, "form", "") for t in tasks_for(make_model(scheduler=s), two_movers=True)}
        for s in ("ssync", "fsync")
    }
    assert (
        forms["ssync"]
        == forms["fsync"]
        == {
            "one-mover",
            "two-movers",
            "closer",
            "global",
            "seen",
            "on-rma",
            "x-nondecreasing",
            "enabled",
            "measure",
            "coverage",
        }
    )
    assert "two-movers" not in {getattr(t, "form", "") for t in tasks_for(make_model(), two_movers=False)}
    central = tasks_for(make_model(scheduler="centralized"), two_movers=True)
    assert "two-movers" not in {getattr(t, "form", "") for t in central}
    fsync = [t for t in tasks_for(make_model(scheduler="fsync")) if getattr(t, "form", "") == "one-mover"]
    assert fsync and all(t.other_name == "o-stays" and t.other for t in fsync)  # o at rest because it stays


def test_fsync_one_mover_replays_with_every_enabled_robot_moving():
    model = make_model(scheduler="fsync")
    result = isolated(
        prove_spec, model, task_named(model, "no-collision/one-mover-scenario-1.and.o-stays"), timeout=10, out=None
    )
    assert result.verdict is Verdict.VIOLATED
    doc = json.loads(json.dumps(result.witness))
    check_replay(doc, model)


def test_lockstep_l_shaped_paths_are_encoded():
    from fatline_verify.prove.smt.cases import Arith
    from fatline_verify.prove.smt.claims import build

    model = make_model(timing="lockstep", path="horizontal-then-vertical")
    spec = next(t for t in tasks_for(model, two_movers=True) if getattr(t, "form", "") == "two-movers")
    built = build(Arith(None), model, spec)
    assert built.assertions  # encoded over the reals with a common time t (lattices skip this form)


@pytest.mark.parametrize(("scheduler", "movers"), [("centralized", 1), ("fsync", 2)])
def test_global_form_activates_what_the_scheduler_allows(scheduler, movers):
    model = make_model(scheduler=scheduler)
    result = isolated(prove_global, model, slots=1, timeout=20, out=None)
    from fatline_verify.schedulers.round import play_round

    assert result.verdict is Verdict.VIOLATED
    active = result.witness["rounds"][0]["active"]
    check_replay(json.loads(json.dumps(result.witness)), model)
    if movers == 1:
        assert len(active) == 1
    else:  # every robot that moves when all look: each one the rules move is active
        state = tuple(tuple(model.to_lattice(tuple(Fr(str(v)) for v in p))) for p in result.witness["initial"])
        every = play_round(state, tuple(range(len(state))), model)
        assert active == [i for i in range(len(state)) if every.after[i] != state[i]], (active, every.after)


def _cvc5_serve(conn) -> None:
    """A worker: cvc5's answer to each file path it is sent."""
    while True:
        path = conn.recv()
        if path is None:
            return
        conn.send(_cvc5(path))


def _cvc5_guarded(paths, seconds: float) -> dict[str, str]:
    """cvc5's answer per file, each within ``seconds`` of wall clock ("timeout" otherwise). cvc5 does
    not always keep its own time limit, so a worker process answers and is killed when it overruns."""
    import multiprocessing

    ctx = multiprocessing.get_context("spawn")
    answers: dict[str, str] = {}
    worker = conn = None
    for path in map(str, paths):
        if worker is None:
            conn, child = ctx.Pipe()
            worker = ctx.Process(target=_cvc5_serve, args=(child,), daemon=True)
            worker.start()
        conn.send(path)
        if conn.poll(seconds):
            answers[path] = conn.recv()
        else:
            answers[path] = "timeout"
            worker.kill()
            worker.join()
            worker = None
    if worker is not None:
        conn.send(None)
        worker.join()
    return answers


@pytest.mark.slow  # about 490 files, a few of which cvc5 and z3 each take their whole budget on;
# the default tier re-checks a sample of every model's (below)
def test_cvc5_rechecks_every_proved_obligation_from_its_file(tmp_path):
    """Every committed PROVED obligation, its file and certificate regenerated as its row recorded
    (:func:`_regenerated`), is re-checked from the written files alone. One shown on its
    linearization: cvc5 confirms the linear certificate written beside it (``.linear.smt2``), and for
    a few the linearization of the obligation's file alone ends unsat again. Any other: cvc5 for 10 s
    (guarded: it does not always keep its own limit), then a fresh z3 for 30 s. Neither may say sat;
    what neither confirms within those budgets must be fewer than 1 in 20 (the closing note of the
    change that brings one in names it: z3 proved it in the prover's own run)."""
    pytest.importorskip("cvc5")
    rows = _proved_rows(tmp_path, with_reason=True)
    assert rows
    _regenerated(rows)
    _recheck_from_files(rows, lambda linear: linear[:: max(1, len(linear) // 3)][:3])


def test_cvc5_rechecks_a_sample_of_every_models_proved_obligations_from_their_files(tmp_path):
    """The fast representative of the above, on the same terms: of every model's committed PROVED
    obligations, the first shown on its linearization and the first shown otherwise (in the order of
    its ``results.json``), each regenerated as its row recorded; the first linearization also re-done
    from its file alone."""
    pytest.importorskip("cvc5")
    rows, seen = [], set()
    for row in _proved_rows(tmp_path, with_reason=True):
        kind = (row[1], "linearization" in row[2])
        if kind not in seen:
            seen.add(kind)
            rows.append(row)
    _regenerated(rows)
    proofs = Path(__file__).resolve().parent.parent / "proofs"
    assert {model for _, model, _ in rows} == {path.parent.name for path in proofs.glob("*/results.json")}
    _recheck_from_files(rows, lambda linear: linear[:1])


def _recheck_from_files(rows, rechecked_linearizations) -> None:
    """cvc5 (then z3) on the files of PROVED ``rows``; ``rechecked_linearizations`` picks, of the
    obligations shown on their linearization, those whose linearization is done again from the file."""
    linear = [path for path, _, reason in rows if "linearization" in reason]
    certificates = [path.with_suffix(".linear.smt2") for path in linear]
    assert all(c.is_file() for c in certificates), [c for c in certificates if not c.is_file()]
    confirmed = _cvc5_guarded(certificates, 10.0)
    assert all(answer == "unsat" for answer in confirmed.values()), confirmed
    for path in rechecked_linearizations(linear):
        assert _linear_recheck(path) == "unsat", path
    others = [path for path, _, reason in rows if "linearization" not in reason]
    answers = _cvc5_guarded(others, 10.0)
    assert "sat" not in answers.values()
    late = [path for path in others if answers[str(path)] != "unsat"]
    again = {str(path): recheck_file(path, 30.0) for path in late}
    assert "sat" not in again.values()
    unconfirmed = [path for path, answer in again.items() if answer != "unsat"]
    assert len(unconfirmed) * 20 < len(rows), unconfirmed


def _linear_recheck(path: Path) -> str:
    """An obligation the prover showed unsat on its linearization: the linearization of the file alone
    ends unsat, and cvc5 confirms the linear problem it ended with (the cuts' soundness is
    ``tests/test_linearize.py``'s)."""
    import tempfile

    from fatline_verify.prove.smt.linearize import certificate

    text = certificate(path)
    if text is None:
        return "unknown"
    with tempfile.TemporaryDirectory() as tmp:
        linear = Path(tmp) / "linear.smt2"
        linear.write_text(text)
        return _cvc5_guarded([linear], 30.0)[str(linear)]


def _proved_rows(where: Path, with_reason: bool = False):
    """Every committed PROVED obligation with a file: (where its file is regenerated, under
    ``where/MODEL``; model name; obligation key), or with ``with_reason`` (path, model name, reason)."""
    from fatline_verify.prove.emit import obligation_path

    root = Path(__file__).resolve().parent.parent
    out = []
    for results in sorted((root / "proofs").glob("*/results.json")):
        tasks = {t.key: t for t in tasks_for(load_model(results.parent.name), two_movers=True)}
        for row in json.loads(results.read_text())["obligations"]:
            if row["verdict"] == "PROVED" and row.get("smt2_sha256") and row["form"] != "global":
                key = f"{row['lemma']}/{row['form']}-{row['case']}" + (f".and.{row['other']}" if row["other"] else "")
                path = where / results.parent.name / obligation_path(tasks[key])
                out.append((path, results.parent.name, row["reason"] if with_reason else key))
    return out


def _regenerated(rows) -> None:
    """The obligation files of ``rows`` (:func:`_proved_rows`) written from the code, each with the digest
    its committed row recorded, and the certificates of those shown on their linearization regenerated
    (solved again: :func:`fatline_verify.prove.regenerate.regenerate`) byte for byte as recorded."""
    from dataclasses import replace

    from fatline_verify.prove.digests import text_sha256
    from fatline_verify.prove.emit import obligation_path, obligation_text
    from fatline_verify.prove.regenerate import regenerate, wanted

    proofs = Path(__file__).resolve().parent.parent / "proofs"
    missing = []
    for name in dict.fromkeys(model for _, model, _ in rows):
        model = load_model(name)
        tasks = {obligation_path(t): t for t in tasks_for(model, two_movers=True)}
        recorded = {w.key: w for w in wanted(proofs / name / "results.json")}
        for path, _, _ in (row for row in rows if row[1] == name):
            task = tasks[path.relative_to(path.parent.parent).as_posix()]
            got = obligation_text(model, task, slots=3)
            assert got is not None
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(got[1])
            w = recorded.get(task.key)
            if w is not None:
                assert text_sha256(got[1]) == w.smt2_sha256, path
                missing.append(replace(w, obligation=path, certificate=path.with_suffix(".linear.smt2")))
    failures: list[str] = []
    regenerate(missing, 2, lambda path, why: failures.append(f"{path}: {why}"))
    assert not failures, failures


@pytest.mark.parametrize(
    "timeout, expected",
    [(1, [1]), (4, [4]), (10, [10]), (11, [2, 9]), (20, [2, 18]), (60, [2, 8, 50]), (300, [2, 8, 32, 258])],
)
def test_the_budget_grows_in_rounds_and_is_spent_in_full(timeout, expected):
    from fatline_verify.prove.prover import rounds

    got = rounds(timeout)
    assert got == pytest.approx(expected)
    assert sum(got) == pytest.approx(timeout)


def test_a_counterexample_beyond_the_first_round_is_found_in_a_later_one():
    """Scenario 2, up-1 after down (paper): no initial lost edge within the first round's 2 s, one
    later (the linearization finds a violation that is not initial, then an initial one)."""
    model = make_model()
    spec = task_named(model, "connectivity/one-mover-scenario-2.up-1-after-down")
    first = isolated(prove_spec, model, spec, timeout=2, out=None, small=False)  # the solver's search alone
    later = isolated(prove_spec, model, spec, timeout=20, out=None, small=False)
    assert first.verdict is Verdict.INCONCLUSIVE
    assert later.verdict is Verdict.VIOLATED and later.witness is not None
    run = check_replay(later.witness, model)  # raises unless every value reproduces
    assert run.rounds and "an edge is lost" in later.reason and "initial configuration" in later.reason


@pytest.mark.slow  # two 3 s budgets with the machine loaded between; the default tier has the 1 s one below
def test_a_verdict_near_the_budget_is_the_same_on_every_run():
    """The budget is spent by z3's resource count, not the wall clock: a hard obligation given little
    budget answers with the same verdict and the same reason (its rlimit figures included) twice,
    even with the machine busy in between."""
    model = make_model()
    spec = task_named(model, "no-collision/one-mover-scenario-2.up-2-after-down")
    first = isolated(prove_spec, model, spec, timeout=3, out=None, small=False)
    busy = sum(i * i for i in range(2_000_000))  # load between the runs
    second = isolated(prove_spec, model, spec, timeout=3, out=None, small=False)
    assert busy and first.verdict is second.verdict is Verdict.INCONCLUSIVE
    assert first.reason == second.reason and "rlimit" in first.reason, (first.reason, second.reason)


def test_a_verdict_out_of_a_small_budget_is_the_same_twice():
    """The fast representative of the above: the same hard obligation given a 1 s budget answers with
    the same verdict and the same reason, its rlimit figures included, on two runs."""
    model = make_model()
    spec = task_named(model, "no-collision/one-mover-scenario-2.up-2-after-down")
    first = isolated(prove_spec, model, spec, timeout=1, out=None, small=False)
    second = isolated(prove_spec, model, spec, timeout=1, out=None, small=False)
    assert first.verdict is second.verdict is Verdict.INCONCLUSIVE
    if any("stopped by the wall clock" in r.reason for r in (first, second)):
        # a 1 s budget on a loaded machine: the wall-clock guard fired before z3's resource count ran
        # out, as it says; the slow tier's 3 s runs check the equality with room to spare
        pytest.skip(f"machine too busy for a 1 s budget: {first.reason[:80]} / {second.reason[:80]}")
    assert first.reason == second.reason and "rlimit" in first.reason, (first.reason, second.reason)


def test_an_earlier_counterexample_is_replayed_before_any_search():
    """A counterexample once found stays found: the obligation's own trace is replayed first (no
    budget needed); another obligation's trace does not replay for it, and the search runs."""
    from fatline_verify.trace.traces import load_trace

    model = make_model()
    root = Path(__file__).resolve().parent.parent / "proofs" / "paper" / "traces"
    own = load_trace(root / "paper-prove-no-collision-one-mover-scenario-1.json")
    spec = task_named(model, "no-collision/one-mover-scenario-1")
    got = prove_spec(model, spec, timeout=0.05, out=None, known=[("an earlier run's counterexample", own)])
    assert got.verdict is Verdict.VIOLATED and "replayed first" in got.reason and got.witness is not None
    check_replay(got.witness, model)
    other = task_named(model, "connectivity/one-mover-scenario-1")
    missed = prove_spec(model, other, timeout=0.05, out=None, known=[("an earlier run's counterexample", own)])
    assert "replayed first" not in missed.reason
    fine = make_model(q=2)  # a trace stores radii, whatever the lattice of either model
    again = prove_spec(
        fine,
        task_named(fine, "no-collision/one-mover-scenario-1"),
        timeout=0.05,
        out=None,
        known=[("an earlier run's counterexample", own)],
    )
    assert again.verdict is Verdict.VIOLATED and "replayed first" in again.reason, again.reason


def test_the_linear_relaxation_keeps_every_solution_and_nothing_nonlinear():
    """The relaxation replaces exactly the nonlinear comparisons: nothing nonlinear is left, the
    linear ones are kept, and a solution of the obligation (a replayed counterexample, with each
    free Boolean given its comparison's value) still solves it, so its unsat can decide."""
    import z3

    from fatline_verify.prove.smt.cases import Arith
    from fatline_verify.prove.smt.claims import build
    from fatline_verify.prove.smt.solving import _nonlinear, check, relaxation, solver_for

    model = make_model()
    spec = task_named(model, "no-collision/one-mover-scenario-1")
    full = build(Arith(None), model, spec)
    relaxed = relaxation(full)
    memo: dict[int, bool] = {}
    assert not any(_nonlinear(a, memo) for a in relaxed.assertions)
    assert len(relaxed.assertions) == len(full.assertions)
    found = check(solver_for(full, 20), full, 20)
    assert found.status == "sat"
    pinned = z3.Solver(ctx=full.ar.ctx)
    pinned.add(*relaxed.assertions)
    for name, (x, y) in full.bodies.items():
        fx, fy = found.positions[name]
        pinned.add(x == z3.RealVal(str(fx), full.ar.ctx), y == z3.RealVal(str(fy), full.ar.ctx))
    assert pinned.check() == z3.sat


def test_a_case_that_never_fires_is_proved_by_its_linear_relaxation_at_once():
    """paper-literal: R_psi n C (x >= 2, right of the vertical band) and R_psi n D (literal quadrants:
    x <= -2) never meet one width-4 strip, so Scenario 3 never fires; the nonlinear search did not
    see it within 60 s (its blockers), the relaxation sees it with a budget of a tenth of a second."""
    model = load_model("paper-literal")
    for key in ("approach/x-nondecreasing-scenario-3.up-4", "connectivity/closer-scenario-3.up-7"):
        result = isolated(prove_spec, model, task_named(model, key), timeout=0.5, out=None)
        assert result.verdict is Verdict.PROVED and "linear relaxation" in result.reason, (key, result.reason)
    assert _scenario_3_snapshots(model) == []
    assert _scenario_3_snapshots(make_model())  # the same grid meets Scenario 3 under the default quadrants


def _scenario_3_snapshots(model):
    """Scenario 3 decisions of the executable model on a grid of 3-robot snapshots around r."""
    from itertools import combinations

    from fatline_verify.rules.paper.algorithm import Rule

    points = [(Fr(x, 2), Fr(y, 2)) for x in range(-7, 8) for y in range(-7, 8) if x * x + y * y >= 16]
    points = [p for p in points if model.sees(p[0] ** 2 + p[1] ** 2)]
    out = []
    for a, b in combinations(points, 2):
        if (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 >= 4 and decide([a, b], model).rule is Rule.SCENARIO_3:
            out.append((a, b))
    return out


@pytest.mark.parametrize(
    ("z3_reason", "expected"),
    [
        ("max. resource limit exceeded", "budget exhausted (rlimit 4,000,000, about 2.0 s)"),
        ("timeout", "stopped by the wall clock at 3.1 s, before its resource limit (rlimit 4,000,000)"),
        ("canceled", "stopped by the wall clock at 3.1 s"),
        ("(incomplete (theory arithmetic))", "(incomplete (theory arithmetic))"),
    ],
)
def test_an_unknown_says_whether_the_resource_limit_or_the_wall_clock_stopped_it(z3_reason, expected):
    """Only the resource limit is the same on every machine: a check the wall clock stopped says so
    (a verdict it leaves INCONCLUSIVE may be decided on a less busy machine)."""
    from fatline_verify.prove.smt.solving import unknown_reason

    class Stopped:
        def reason_unknown(self) -> str:
            return z3_reason

    assert unknown_reason(Stopped(), 2.0).startswith(expected)  # type: ignore[arg-type]
