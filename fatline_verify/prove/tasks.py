"""Which obligations ``fatline prove`` has for a model (:func:`tasks_for`), what a result is
(:class:`ProofResult`), and which models it refuses (:func:`check_encoded`): a decision case of the
paper's rules (:class:`~fatline_verify.prove.smt.claims.Spec`), Lemma 1's global form, or a move family's
obligation (:class:`~fatline_verify.prove.smt.family.FamilySpec`: the repaired rule set's legs, or any rule
set's declared family)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from ..errors import InvalidInput
from ..lemmas.properties import PROVED_LEMMAS, Lemma, Verdict
from ..model.config import Model
from ..model.options import CATALOGUE, Scheduler
from ..rules import registry
from ..rules.paper.cases import Case, moving_cases, staying_cases
from ..rules.repaired.options import RepairProgress
from ..schedulers.activation import encoded_schedulers
from .goals import goal_problem
from .smt.claims import (
    CLOSER,
    GLOBAL,
    ON_RMA,
    ONE_MOVER,
    SEEN,
    TWO_MOVERS,
    X_NONDECREASING,
    Spec,
)
from .smt.family import FamilySpec, specs
from .smt.live_rules import live_cases
from .smt.liveness import LiveSpec, live_specs

ENCODED = encoded_schedulers()
"""The schedulers the obligations encode: every mover decides on one shared snapshot."""


def encoding_name(model: Model) -> str | None:
    """The obligations ``model`` is proved by: the encoding its rule set carries
    (:func:`fatline_verify.rules.registry.encoding_of`, refused in one line when it encodes another
    rule set's ``decide``), ``None`` without one. The repaired rules' legs with every repair off are
    the paper's rules (:func:`fatline_verify.rules.repaired.algorithm.repair` leaves each decision as
    it is), proved by the paper's case table."""
    encoding = registry.encoding_of(registry.of(model), model)
    if encoding is None:
        return "family" if registry.family(model) is not None else None
    return "paper" if encoding.name == "legs" and not model.options.repaired else encoding.name


class NotEncodedModel(InvalidInput):
    """``fatline prove`` on a model the obligations do not encode (exit 2, before any work): a scheduler
    other than :data:`ENCODED`, or a repair (:mod:`fatline_verify.rules.repaired.algorithm`)."""


@dataclass(frozen=True, slots=True)
class ProofResult:
    """One obligation's verdict."""

    lemma: Lemma
    form: str
    rule: str
    verdict: Verdict
    slots: int
    """Named robots besides r (the global form: slot robots)."""
    any_size: bool
    seconds: float
    reason: str
    smt2: str
    witness: dict[str, Any] | None = field(default=None, repr=False, compare=False)
    comment: str = field(default="", repr=False, compare=False)
    case: str = "any"
    other: str = ""
    configuration: tuple[str, ...] = ()
    """For a claim without a trace (``seen``, ``on-rma``, ``x-nondecreasing``, ``closer``): the replayed
    configuration, r first, as exact ``x,y`` strings in lattice units (radii when q = 1)."""
    decided_by: str = "search"
    """What decided it (:data:`fatline_verify.prove.corpus.DECIDERS`): the search, or a counterexample
    replayed first from the shipped corpus, an earlier run, or ``--known``."""
    basis: str = ""
    """For PROVED: ``vacuous``, ``immediate`` or ``substantive`` (:mod:`fatline_verify.prove.basis`)."""

    @property
    def key(self) -> str:
        tail = f".and.{self.other}" if self.other else ""
        return f"{self.lemma}/{self.form}-{self.case}{tail}"


def row_key(row: dict[str, Any]) -> str:
    """``lemma/form-case[.and.other]`` (rows before encoding 3 had no case: their rule stands in)."""
    tail = f".and.{row['other']}" if row.get("other") else ""
    return f"{row['lemma']}/{row['form']}-{row.get('case', row['rule'])}{tail}"


DEFAULT_SLOTS = 3
"""Slot robots of the global connectivity form, unless asked otherwise."""
DEFAULT_TIMEOUT = 60.0
"""Solver seconds per obligation, unless asked otherwise."""

LEMMAS = PROVED_LEMMAS
"""The lemmas the prover decides, in results order (progress and termination: the liveness
obligations, for a rule set that declares them, :mod:`fatline_verify.prove.smt.liveness`)."""

LIVENESS = (Lemma.PROGRESS, Lemma.TERMINATION)
"""The lemmas of the liveness obligations."""


@dataclass(frozen=True, slots=True)
class GlobalTask:
    """Lemma 1 in its global form (the whole graph after one round)."""

    lemma: Lemma = Lemma.CONNECTIVITY
    form: str = GLOBAL

    @property
    def key(self) -> str:
        return f"{self.lemma}/{GLOBAL}-any"


@dataclass(frozen=True, slots=True)
class CoverageSpec:
    """The liveness cases held to ``decide`` on views (:mod:`fatline_verify.prove.refine`): the row
    ``progress/coverage-cases``, without which no liveness verdict is PROVED (the enabledness and measure
    rows speak of the declared cases only). ``views``: ``None`` every view of the model's lattice (a
    PROVED is possible: ``fatline prove --coverage all``), else a random sample of that many (covered:
    INCONCLUSIVE; the default, seconds rather than minutes)."""

    views: int | None = 20_000
    lemma: Lemma = Lemma.PROGRESS
    form: str = "coverage"
    case: str = "cases"

    @property
    def name(self) -> str:
        return self.case

    @property
    def other(self) -> str:
        return ""

    @property
    def key(self) -> str:
        return f"{self.lemma}/{self.form}-{self.case}"


VIEWS_FORM = "in-family-views"
"""The form of the rows that hold ``decide`` to its move family on views."""


@dataclass(frozen=True, slots=True)
class ViewsSpec:
    """The row ``LEMMA/in-family-views-any`` (:func:`fatline_verify.prove.family.prove_views`): ``decide`` on
    every view of the model's lattice makes a decision its move family admits; without it, the family's
    obligations say nothing of the rule set."""

    lemma: Lemma
    form: str = VIEWS_FORM
    name: str = "any"
    other: str = ""
    sample: int | None = None
    """``None``: every view of the lattice when it has at most a few million (PROVED possible); else a random
    sample of that many (INCONCLUSIVE at best: ``fatline prove --views N``)."""

    @property
    def key(self) -> str:
        return f"{self.lemma}/{self.form}-any"


Task = Spec | GlobalTask | FamilySpec | LiveSpec | CoverageSpec | ViewsSpec
"""An obligation: a decision case of the paper's rules, the global form, a move family's obligation (the
repaired rule set's legs among them), a liveness obligation, the liveness cases' coverage of ``decide``,
or a family held to ``decide`` on views."""


def rule_groups(cases: Sequence[Case]) -> list[tuple[str, tuple[Case, ...]]]:
    """The moving cases grouped by rule (a second mover's obligations take one group each)."""
    groups: dict[str, list[Case]] = {}
    for case in cases:
        groups.setdefault(case.rule.value, []).append(case)
    return [(name, tuple(group)) for name, group in groups.items()]


def check_encoded(model: Model) -> None:
    """Refuse a model the obligations do not encode: never another scheduler's semantics, never the
    paper's rules in place of a repaired rule set the leg obligations do not cover, never a rule set
    without an encoding of its own (:attr:`fatline_verify.rules.registry.RuleSet.prover`)."""
    rule_set = registry.of(model)
    if encoding_name(model) is None and rule_set.liveness is None:
        raise NotEncodedModel(
            f"rules={rule_set.name!r}: fatline prove has no encoding of this rule set (RuleSet.prover is None; "
            f"it encodes {', '.join(e.says for e in registry.ENCODINGS.values())}, each for its own rule set); "
            f"expected a rule set with an encoding of its own. Use fatline check {model.ref}"
        )
    scheduler = model.options.scheduler
    if scheduler not in ENCODED and scheduler is not Scheduler.ASYNC:
        raise NotEncodedModel(
            f"scheduler={scheduler}: fatline prove has no encoding of this scheduler's rounds (it encodes "
            f"{', '.join(s.value for s in ENCODED)}); expected one of those. Use fatline check {model.ref}"
        )
    if scheduler not in ENCODED:
        raise NotEncodedModel(
            f"scheduler={scheduler}: fatline prove encodes rounds in which every mover decides on one shared "
            f"snapshot ({', '.join(s.value for s in ENCODED)}); an asynchronous robot may decide on a stale view. "
            f"Use fatline check {model.ref} for this scheduler"
        )
    if encoding_name(model) == "legs":
        from ..rules.repaired.family import missing as missing_repairs

        missing = missing_repairs(model)
        if missing:
            raise NotEncodedModel(
                f"{', '.join(missing)} not set: fatline prove encodes a repaired rule set by its legs, which rest "
                f"on the lock, unit steps, clear paths and kept edges together. Set them, or use fatline check "
                f"{model.name}"
            )
        if model.options.repair_progress is RepairProgress.CORNER:
            raise NotEncodedModel(
                "repair_progress='corner': the leg obligations do not cover corner legs (right and vertical at "
                "once, up to sqrt(2) long, so two far movers may close a gap of more than rad_v to less than 2 "
                f"unless their neighbours rule it out); expected off or detour. Use fatline check {model.ref}"
            )


PAPER_PART_NOTE = (
    "Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg "
    "toward their destination (never farther right, never left of r), or a repair's own: repair-align to the "
    "greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical."
)
"""The header line of a repaired model's per-case obligations: what they say of the repaired rules."""


def paper_part(model: Model) -> Model:
    """The paper's rules under ``model``'s readings (its repairs off): what the per-case obligations
    of a repaired model encode (a repaired move is a leg toward their destination, or a repair's own)."""
    if not model.options.repaired:
        return model
    from dataclasses import replace

    off = {name: "off" for name in model.options.as_dict() if CATALOGUE[name].repair}
    return replace(model, options=model.options.with_(**off))


def tasks_for(model: Model, lemmas: tuple[Lemma, ...] = LEMMAS, *, two_movers: bool = False) -> list[Task]:
    """Every obligation ``prove`` decides for ``model`` and ``lemmas``, in results order.

    ``two_movers``: also the two-mover obligations (one per pair of rules; searched on the lattices
    only, as their real form is beyond the budgets tried), which ``fatline prove --two-movers`` asks for."""
    check_encoded(model)
    live = _live_tasks(model, lemmas)
    encoding = encoding_name(model)
    if encoding is None:  # liveness declared, safety not encoded
        safety = [lemma for lemma in lemmas if lemma not in LIVENESS]
        if safety and tuple(lemmas) != LEMMAS:
            raise NotEncodedModel(
                f"rules={model.rules!r}: fatline prove encodes only this rule set's liveness obligations (it declares "
                "no safety encoding); expected --lemma progress, termination or liveness. "
                f"Use fatline check {model.ref}"
            )
        return live
    if encoding == "legs":
        return _repaired_tasks(model, lemmas) + live
    if encoding == "family":
        return family_tasks(model, lemmas) + live
    scheduler = model.options.scheduler
    moving = moving_cases(model)
    stays = tuple(staying_cases(model)) if scheduler is Scheduler.FSYNC else ()
    groups = rule_groups(moving) if two_movers and scheduler is not Scheduler.CENTRALIZED else []
    tasks: list[Task] = []
    for lemma in lemmas:
        if lemma in (Lemma.NO_COLLISION, Lemma.CONNECTIVITY):
            tasks += [Spec.of(lemma, ONE_MOVER, c, stays, "o-stays" if stays else "") for c in moving]
            tasks += [
                Spec(lemma, TWO_MOVERS, mine, theirs, other)
                for k, (_, mine) in enumerate(groups)
                for other, theirs in groups[k:]
            ]
        if lemma is Lemma.CONNECTIVITY:
            tasks += [Spec.of(lemma, CLOSER, c) for c in moving if c.rule.value in CLOSER_RULES]
            tasks.append(GlobalTask())
        if lemma is Lemma.RMA_FIXED:
            tasks += [Spec.of(lemma, SEEN, c) for c in moving]
            tasks += [Spec.of(lemma, ON_RMA, c) for c in moving]
        if lemma is Lemma.APPROACH:
            tasks += [Spec.of(lemma, X_NONDECREASING, c) for c in moving]
    return tasks + live


def _live_tasks(model: Model, lemmas: tuple[Lemma, ...]) -> list[Task]:
    """The liveness obligations of ``lemmas`` for a rule set that declares them. Asked for by name
    (``--lemma progress``, ``termination``) of one that does not: refused (exit 2)."""
    asked = tuple(lemma for lemma in lemmas if lemma in LIVENESS)
    if not asked:
        return []
    if registry.of(model).liveness is None:
        if set(lemmas) <= set(LIVENESS):
            raise NotEncodedModel(
                f"rules={model.rules!r}: the rule set declares no liveness obligations (rules/registry.py, "
                f"RuleSet.liveness); expected a rule set that does. Use fatline check {model.ref}"
            )
        return []
    problem = goal_problem(model)
    if problem and Lemma.PROGRESS in asked:  # the enabledness rows encode goal=vertical-line only
        if set(lemmas) <= {Lemma.PROGRESS}:
            raise NotEncodedModel(f"{problem}; expected a model with goal=vertical-line for --lemma progress")
        asked = tuple(lemma for lemma in asked if lemma is not Lemma.PROGRESS)
    specs: list[Task] = list(live_specs(model, live_cases(model), asked))
    return specs + ([CoverageSpec()] if asked else [])


def _repaired_tasks(model: Model, lemmas: tuple[Lemma, ...]) -> list[Task]:
    """A repaired model's obligations: the leg obligations of the collision and connectivity lemmas
    (:mod:`fatline_verify.rules.repaired.family`,
    :mod:`fatline_verify.prove.smt.family`), and the per-case claims ``seen`` and ``x-nondecreasing`` of the
    paper's rules under its readings (:func:`paper_part`; the legs' rightward horizontal rests on
    the latter)."""
    moving = moving_cases(paper_part(model))
    repairs = repair_cases(model)
    tasks: list[Task] = []
    tasks += family_tasks(model, lemmas)
    for lemma in lemmas:
        if lemma is Lemma.RMA_FIXED:
            tasks += [Spec.of(lemma, SEEN, c) for c in moving]
            tasks += [Spec.of(lemma, ON_RMA, c) for c in moving]
            tasks += [Spec(lemma, form, (c,), repair=k) for form in (SEEN, ON_RMA) for k, c in repairs]
        if lemma is Lemma.APPROACH:
            tasks += [Spec.of(lemma, X_NONDECREASING, c) for c in moving]
            tasks += [Spec(lemma, X_NONDECREASING, (c,), repair=k) for k, c in repairs if k != "contract"]
    return tasks


def family_tasks(model: Model, lemmas: tuple[Lemma, ...]) -> list[Task]:
    """A move family's obligations (:mod:`fatline_verify.prove.smt.family`) for the lemmas of ``lemmas`` it
    speaks of (no-collision, connectivity), each lemma's with the row that holds ``decide`` to the family."""
    family = registry.family(model)
    tasks: list[Task] = []
    for lemma in lemmas:
        got = specs(family, (lemma,))
        tasks += [*got, ViewsSpec(lemma)] if got else []
    return tasks


def repair_cases(model: Model) -> list[tuple[str, Case]]:
    """The repaired rule set's own destinations (:data:`~fatline_verify.prove.smt.claims.REPAIRS`) the model
    turns on, each with the paper case it replaces: ``align`` and ``contract`` the only-A u I stay,
    ``approach`` each moving Scenario 4 case. (A vertical contraction keeps x: it has seen and on-rma
    obligations, no x-nondecreasing one, and makes no horizontal leg.)"""
    from ..rules.paper.algorithm import Rule
    from ..rules.repaired.algorithm import SCENARIO_4
    from ..rules.repaired.options import RepairApproach, RepairStack

    paper = paper_part(model)
    out: list[tuple[str, Case]] = []
    if model.options.repair_stack is RepairStack.ALIGN:
        stays = [c for c in staying_cases(paper) if c.rule is Rule.ONLY_AI]
        out += [(k, c) for k in ("align", "contract") for c in stays]
    if model.options.repair_approach is RepairApproach.ON:
        out += [("approach", c) for c in moving_cases(paper) if c.rule in SCENARIO_4]
    return out


CLOSER_RULES = ("scenario-1", "scenario-2", "scenario-3", "uncovered-search")
"""The rules Lemma 1's proof argues about ("under scenario 2 and 3 ... it becomes closer")."""


def task_key(task: Task) -> str:
    """``lemma/form-case[.and.other]``: how results rows and witness files name an obligation."""
    return task.key
