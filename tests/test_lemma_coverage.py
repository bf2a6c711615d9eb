"""What PROVED certifies: Lemma 3's other half (``on-rma``), each PROVED row's basis found by solver
query (vacuous, immediate, substantive), and lemma-level verdicts from the forms that together imply a
lemma (:mod:`fatline_verify.prove.coverage`). Everything is proved fresh here, never read from the
committed ``proofs/``."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from fatline_verify.fresh import run_fresh
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove import basis
from fatline_verify.prove.basis import IMMEDIATE, SUBSTANTIVE, VACUOUS, basis_of, counts_text, decided
from fatline_verify.prove.coverage import NOT_ENCODED, NOT_PROVED, PROVED, TABLE, VIOLATED, lemma_verdicts
from fatline_verify.prove.family import prove_family
from fatline_verify.prove.memo import key_of, remembered
from fatline_verify.prove.replay import replay_known
from fatline_verify.prove.search import prove_spec
from fatline_verify.prove.smt.claims import ON_RMA, SEEN, X_NONDECREASING, Spec
from fatline_verify.prove.smt.family import FamilySpec
from fatline_verify.prove.tasks import ProofResult, tasks_for
from fatline_verify.rules.paper.cases import moving_cases
from fatline_verify.schedulers.round import decide_all


def _spec(model_name: str, form: str, case: str, lemma: Lemma = Lemma.RMA_FIXED) -> Spec:
    model = load_model(model_name)
    (c,) = [c for c in moving_cases(model) if c.name == case]
    return Spec.of(lemma, form, c)


def test_on_rma_is_an_obligation_of_every_moving_case():
    model = load_model("paper")
    keys = {t.key for t in tasks_for(model, (Lemma.RMA_FIXED,))}
    for c in moving_cases(model):
        assert f"rma-fixed/seen-{c.name}" in keys and f"rma-fixed/on-rma-{c.name}" in keys


def test_on_rma_finds_the_paper_literal_counterexample_and_the_model_replays_it():
    """The issue's ``fatline simulate paper-literal --init "0,2 2,0" --schedule "1"``: r, alone on the
    right-most axis, takes the x of a robot up-left of it as psi_right and leaves the axis."""
    model = load_model("paper-literal")
    spec = _spec("paper-literal", ON_RMA, "scenario-1")
    got = decided(prove_spec, model, spec, timeout=20, out=None, small=False)
    assert got.verdict is Verdict.VIOLATED and "leaves the axis" in got.reason
    assert got.basis == ""  # only PROVED rows have a basis
    again = replay_known(model, spec, {"configuration": list(got.configuration)})
    assert again is not None and again.initial  # the executable model replays it from an initial configuration
    # the issue's own configuration breaks the same claim: r = (2, 0) sees (0, 2) and moves to x = 0
    issue = replay_known(model, spec, {"configuration": ["2,0", "0,2"]})
    assert issue is not None and "leaves the axis" in issue.what
    state = ((2, 0), (0, 2))
    assert decide_all(state, model)[0].destination[0] == -2


def test_on_rma_holds_where_quadrants_are_lower_right():
    """The default readings: B and D are the right quadrants, so psi_right is never left of r; with no
    robot right of r, Scenario 1 keeps r's x: on-rma is PROVED, and by the witness's construction alone."""
    model = load_model("paper")
    got = decided(prove_spec, model, _spec("paper", ON_RMA, "scenario-1"), timeout=20, out=None, small=False)
    assert got.verdict is Verdict.PROVED and got.basis == IMMEDIATE


def test_seen_is_immediate_for_scenario_1():
    """Scenario 1 moves to psi_right, the x of a robot r sees: the claim needs no universal condition."""
    model = load_model("paper")
    got = decided(prove_spec, model, _spec("paper", SEEN, "scenario-1"), timeout=20, out=None, small=False)
    assert got.verdict is Verdict.PROVED and got.basis == IMMEDIATE


def test_a_family_obligation_that_needs_the_guard_is_substantive():
    """A family's obligation is immediate when the classes' shapes alone decide it, substantive when it
    needs a guard: r's horizontal leg against a robot at rest needs the clearance."""
    model = load_model("repaired")
    spec = FamilySpec(Lemma.NO_COLLISION, "leg", "horizontal", "rest")
    got = decided(prove_family, model, spec, timeout=30, out=None)
    assert got.verdict is Verdict.PROVED and got.basis == SUBSTANTIVE
    kept = FamilySpec(Lemma.CONNECTIVITY, "kept", "horizontal", "rest")
    got = decided(prove_family, model, kept, timeout=30, out=None)
    assert got.verdict is Verdict.PROVED and got.basis == SUBSTANTIVE


def test_a_row_that_cannot_fire_is_vacuous_however_unsat_was_reached():
    """A row the search reached by the full obligation is still asked whether it can fire."""
    from fatline_verify.prove.tasks import ProofResult

    model = load_model("paper-literal")
    spec = _spec("paper-literal", SEEN, "scenario-3.up-1")
    reached = ProofResult(Lemma.RMA_FIXED, SEEN, "scenario-3", Verdict.PROVED, 0, True, 0.0, "unsat over the reals", "")
    assert basis_of(model, spec, reached) == VACUOUS
    fires = _spec("paper-literal", SEEN, "scenario-1")
    assert basis_of(model, fires, reached) == IMMEDIATE


def _row(lemma: str, form: str, verdict: str, case: str = "c", basis: str = "") -> dict:
    row = {"lemma": lemma, "form": form, "verdict": verdict, "case": case, "rule": case, "reason": "r"}
    return {**row, "basis": basis} if basis else row


def _verdicts(model_name: str, rows: list[dict]) -> dict[str, object]:
    return {v.lemma: v for v in lemma_verdicts(load_model(model_name), rows)}


def test_a_lost_edge_alone_does_not_refute_connectivity_but_a_split_does():
    rows = [_row("connectivity", "one-mover", "VIOLATED"), _row("connectivity", "one-mover", "PROVED", "d", VACUOUS)]
    v = _verdicts("paper", rows)["connectivity"]
    assert v.verdict == NOT_PROVED and "one-mover: 1 of 2 not PROVED" in v.why and "two-movers: no rows" in v.why
    rows.append(_row("connectivity", "global", "VIOLATED", "any"))
    assert _verdicts("paper", rows)["connectivity"].verdict == VIOLATED


def test_rma_fixed_is_proved_only_with_on_rma():
    seen = [_row("rma-fixed", "seen", "PROVED", "a", IMMEDIATE), _row("rma-fixed", "seen", "PROVED", "b", VACUOUS)]
    v = _verdicts("paper", seen)["rma-fixed"]
    assert v.verdict == NOT_PROVED and "on-rma: no rows" in v.why
    on = [_row("rma-fixed", "on-rma", "PROVED", "a", SUBSTANTIVE), _row("rma-fixed", "on-rma", "PROVED", "b", VACUOUS)]
    v = _verdicts("paper", seen + on)["rma-fixed"]
    assert v.verdict == PROVED and v.counts == "4 PROVED (1 substantive, 1 immediate, 2 vacuous)"
    broken = [*seen, _row("rma-fixed", "on-rma", "VIOLATED", "a")]
    assert _verdicts("paper", broken)["rma-fixed"].verdict == VIOLATED
    # a move right of every robot seen does not by itself move the axis
    right = [_row("rma-fixed", "seen", "VIOLATED", "a"), *on]
    assert _verdicts("paper", right)["rma-fixed"].verdict == NOT_PROVED


def test_approach_is_liveness_not_encoded_whatever_its_step_rows_say():
    rows = [_row("approach", "x-nondecreasing", "PROVED", "a", IMMEDIATE)]
    v = _verdicts("paper", rows)["approach"]
    assert v.verdict == NOT_ENCODED and "liveness" in v.why


def test_two_movers_are_needed_except_under_the_centralized_scheduler():
    rows = [_row("no-collision", "one-mover", "PROVED", "a", SUBSTANTIVE)]
    assert _verdicts("paper", rows)["no-collision"].verdict == NOT_PROVED
    v = _verdicts("paper-centralized", rows)["no-collision"]
    assert v.verdict == PROVED and "no two robots move at once" in v.why


def test_a_familys_lemmas_need_the_row_that_holds_decide_to_it():
    """The leg rows prove the family safe; without the in-family views row they say nothing of the rule set."""
    rows = [_row("no-collision", "leg", "PROVED", c, SUBSTANTIVE) for c in ("horizontal", "top", "bottom")]
    v = _verdicts("repaired", rows)["no-collision"]
    assert v.verdict == NOT_PROVED and "in-family: no rows" in v.why, v.why
    rows += [_row("no-collision", "in-family-views", "PROVED", "any")]
    assert _verdicts("repaired", rows)["no-collision"].verdict == PROVED
    rows[-1] = _row("no-collision", "in-family-views", "VIOLATED", "any")
    assert _verdicts("repaired", rows)["no-collision"].verdict == NOT_PROVED


def test_the_repairs_own_destinations_are_obligations():
    """repair-align and repair-approach never decrease x, never move right of every robot seen, never
    take a robot off the right-most axis; repair-contract keeps x: each PROVED, from the rules' encoding."""
    from fatline_verify.prove.tasks import paper_part

    model = load_model("repaired")
    specs = [t for t in tasks_for(model, (Lemma.RMA_FIXED, Lemma.APPROACH)) if getattr(t, "repair", "")]
    assert {t.repair for t in specs} == {"align", "approach", "contract"}
    picked = {}
    for t in specs:
        picked.setdefault((t.form, t.repair), t)
    for t in picked.values():
        got = decided(prove_spec, paper_part(model), t, timeout=20, out=None, small=False)
        assert got.verdict is Verdict.PROVED, (t.key, got.reason)


def test_every_table_entry_has_parts_and_an_argument():
    for entry in TABLE:
        assert entry.parts and entry.argument
        assert all(part.says for part in entry.parts)


def test_counts_split_proved_rows_by_basis():
    rows = [_row("x", "f", "PROVED", basis=k) for k in (SUBSTANTIVE, IMMEDIATE, IMMEDIATE, VACUOUS)]
    assert counts_text(rows) == "1 substantive, 2 immediate, 1 vacuous"
    assert counts_text([_row("x", "f", "PROVED")]) == "1 unclassified"


@pytest.mark.slow
@pytest.mark.parametrize("name", ["paper", "paper-literal"])
def test_no_lemma_proved_beside_a_violated_check_in_a_fresh_slice(name, tmp_path):
    """rma-fixed proved fresh into tmp_path: its lemma-level verdict is never PROVED where the checker
    finds rma-fixed VIOLATED (paper-literal), and is PROVED where both halves are (paper)."""
    from fatline_verify.cli import main
    from fatline_verify.outputs import read_json

    code = main(["prove", name, "--lemma", "rma-fixed", "--out", str(tmp_path), "-q", "--timeout", "20"])
    rows = read_json(tmp_path / name / "results.json")["obligations"]
    v = _verdicts(name, rows)["rma-fixed"]
    assert all(r.get("basis") for r in rows if r["verdict"] == "PROVED")
    if name == "paper-literal":
        assert code == 1 and v.verdict == VIOLATED and "on-rma" in v.why
    else:
        assert code == 0 and v.verdict == PROVED


# A run's shared answers (prove/memo.py): a question asked by several obligations, each in its own
# process, is answered once, and the answer read is the one the reader would compute.


POSIX = pytest.mark.skipif(os.name != "posix", reason="answers are shared through POSIX file locks")


def _count_and_answer(memo: str, log: str, key: str) -> bool:
    """A question whose computing is logged (one line per process that computed it)."""

    def compute() -> bool:
        with open(log, "a") as f:
            f.write(f"{os.getpid()}\n")
        return True

    return remembered(Path(memo), key, compute)


@POSIX
def test_a_question_asked_by_many_processes_is_computed_once(tmp_path):
    memo, log = tmp_path / "memo", tmp_path / "log"
    memo.mkdir()
    answers: dict[int, bool] = {}
    calls = [(_count_and_answer, (str(memo), str(log), "k"), {})] * 6
    run_fresh(calls, 2, answers.__setitem__)
    assert answers == dict.fromkeys(range(6), True)
    assert len(log.read_text().split()) == 1


def test_without_a_directory_every_question_is_computed(tmp_path):
    got: list[int] = []
    for _ in range(2):
        remembered(None, "k", lambda: got.append(1) or False)
    assert got == [1, 1]


def test_the_key_names_every_part_in_order():
    assert key_of("basis", "10.0", "text") != key_of("basis", "10.0", "text ")
    assert key_of("a", "bc") != key_of("ab", "c")


@POSIX
def test_the_lemmas_of_one_case_share_its_vacuity_answer_and_get_the_kinds_they_get_alone(tmp_path):
    """``rma-fixed/seen`` and ``approach/x-nondecreasing`` of one case ask the same vacuity query: the
    second reads the first's answer, and each row's kind is the one it gets with nothing shared."""
    model = load_model("paper")
    proved = ProofResult(Lemma.RMA_FIXED, SEEN, "scenario-1", Verdict.PROVED, 0, True, 0.0, "unsat", "")
    specs = [_spec("paper", SEEN, "scenario-1"), _spec("paper", X_NONDECREASING, "scenario-1", Lemma.APPROACH)]
    alone = [basis.basis_of(model, spec, proved) for spec in specs]
    shared = [basis.basis_of(model, spec, proved, memo=tmp_path) for spec in specs]
    assert shared == alone
    assert len(list(tmp_path.glob("*.json"))) == 3  # one vacuity answer for both, one immediacy answer each


def test_the_longest_obligations_go_first():
    """The views' rows first; then by an earlier run's seconds; the rest in task order."""
    from fatline_verify.prove.prover import CoverageSpec, ViewsSpec, _first, task_key, tasks_for

    tasks = tasks_for(load_model("paper"), (Lemma.NO_COLLISION, Lemma.PROGRESS))
    views = [t for t in tasks if isinstance(t, CoverageSpec | ViewsSpec)]
    solved = [t for t in tasks if t not in views]
    assert views and solved
    assert sorted(tasks, key=lambda t: _first(t, None)) == views + solved
    slow, quick = task_key(solved[-1]), task_key(solved[3])
    earlier = {slow: {"seconds": 40.0}, quick: {"seconds": 0.5}, task_key(views[0]): {"seconds": 1.0}}
    again = [task_key(t) for t in sorted(tasks, key=lambda t: _first(t, earlier))]
    assert again[: len(views)] == [task_key(t) for t in views]
    rest = again[len(views) :]
    assert rest[:2] == [slow, quick] and rest[2:] == [task_key(t) for t in solved if task_key(t) not in earlier]


def test_the_in_family_views_are_read_once_per_run(tmp_path, monkeypatch):
    """Both lemmas' in-family views rows read the same views against the same family: the first row's check
    is the answer of the second (read from the run's memo, not computed again), and the second goes last in
    the queue rather than beside the first."""
    import fatline_verify.prove.family as fam
    from fatline_verify.prove.prover import ViewsSpec, _first

    model = load_model("repaired")
    found = fam.ViewsCheck(7, 3, True, 1.5, ((((1, 2), (0, -3)), "right: not clear"),), 1)
    calls: list[int] = []

    def counted(m, sample=0):
        calls.append(sample)
        return found

    monkeypatch.setattr(fam, "check_views", counted)
    first = fam.prove_views(model, ViewsSpec(Lemma.NO_COLLISION), sample=0, memo=str(tmp_path))
    second = fam.prove_views(model, ViewsSpec(Lemma.CONNECTIVITY), sample=0, memo=str(tmp_path))
    assert calls == [0]
    assert first.verdict is second.verdict is Verdict.VIOLATED
    assert first.reason == second.reason and first.configuration == second.configuration
    assert fam.prove_views(model, ViewsSpec(Lemma.CONNECTIVITY), sample=0).reason == first.reason and calls == [0, 0]
    tasks = [ViewsSpec(Lemma.NO_COLLISION), ViewsSpec(Lemma.CONNECTIVITY)]
    assert _first(tasks[0], None) == float("-inf") and _first(tasks[1], None, again=True) == float("inf")


def test_a_vacuity_query_is_answered_by_a_shipped_counterexample_of_its_case():
    """Scenario 2's up-3-after-down fires, but neither z3 over the reals, the lattice q = 1 nor the
    linearization shows it within the budget (each spent it whole): the corpus's counterexamples of that
    case put r there, and with every named robot among their robots z3 finds a solution at once. The
    configurations of another case do not solve it (r decides otherwise there), so the step is not a
    formality."""
    from fatline_verify.prove.corpus import firing
    from fatline_verify.prove.search import Budget
    from fatline_verify.prove.smt.cases import Arith
    from fatline_verify.prove.smt.claims import build

    model = load_model("paper")
    spec = _spec("paper", SEEN, "scenario-2.up-3-after-down")
    query = build(Arith(None), model, spec, vacuity=True)
    known = firing(spec.name, model.name)
    assert known and all(points[0] == (0, 0) for points in known)
    assert basis._sat_at_known(query, known, Budget(10), 0.5)
    others = firing("scenario-1", model.name)
    assert others and not basis._sat_at_known(query, others, Budget(10), 0.5)
    assert firing("no-such-case", model.name) == []
