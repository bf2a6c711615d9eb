"""Lemma-level verdicts: which obligation forms together imply each lemma (:data:`TABLE`), and the
verdict the rows of one model's ``results.json`` give it (:func:`lemma_verdicts`).

A lemma is

- **VIOLATED** only when a replayed counterexample breaks the lemma itself: a row of a *refuting*
  part (a collision; a robot that leaves the right-most axis; the global form's split swarm). A lost
  edge alone (connectivity's one-mover, two-movers, kept, bridged rows) is not a split swarm, and a
  move right of every robot r sees does not by itself move the RMA: those VIOLATED rows leave the
  lemma NOT PROVED, not VIOLATED.
- **PROVED** only when every part it needs is: each part's rows all PROVED (for every swarm size),
  and no part rests on a fact by inspection.
- **NOT PROVED** otherwise, naming the parts proved and the parts missing (not run, violated,
  inconclusive, by inspection).
- **NOT ENCODED** when a part has no obligation form at all (approach: "each robot will move closer
  to RMA in finite time" is liveness; the prover's ``x-nondecreasing`` is a step fact beside it).

The table is a few constructors (:func:`paper_lemma`, :func:`family_lemma`) over the rules' encodings,
one entry per lemma and encoding; a liveness lemma joins as an entry whose parts name its forms
(progress: ``enabled``; termination: ``measure`` and ``enabled``, resting on safety, rigid moves and
a fair round scheduler); until the prover writes rows of those forms it is NOT ENCODED.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.options import Scheduler
from ..rules import registry
from .basis import counts_text
from .goals import goal_problem
from .rests import Fact, rests_on
from .tasks import VIEWS_FORM

PROVED, VIOLATED, NOT_PROVED, NOT_ENCODED = "PROVED", "VIOLATED", "NOT PROVED", "NOT ENCODED"
LEMMA_VERDICTS = (VIOLATED, NOT_ENCODED, NOT_PROVED, PROVED)
"""Lemma-level verdicts, worst first."""


def _always(model: Model) -> str:
    return ""


def _two_movers(model: Model) -> str:
    """Why two movers need no obligation of their own under ``model``'s scheduler, or ``""``."""
    if model.options.scheduler is Scheduler.CENTRALIZED:
        return "one robot moves per round (centralized): no two robots move at once"
    return ""


@dataclass(frozen=True)
class Part:
    """One part of a lemma's argument: the obligation forms that make it, what it says, whether a
    replayed counterexample of it breaks the lemma itself."""

    name: str
    forms: tuple[str, ...]
    says: str
    refutes: bool = False
    needed: Callable[[Model], str] = field(default=_always, compare=False)
    """``""`` if the model needs the part, else why not (stated on the page)."""
    inspection: str = ""
    """A fact the argument uses that no obligation checks (the part is then never PROVED)."""
    lemma: str = ""
    """The lemma whose rows hold the forms, if not the entry's own (the legs' rightward: approach's)."""
    cases: Callable[[Model], tuple[str, ...]] = field(default=lambda model: (), compare=False)
    """Case-name prefixes the part needs a row of under ``model`` (the repairs' own destinations)."""
    facts: tuple[Fact, ...] = ()
    """Facts about the code its rows assume (listed with every PROVED that rests on the part)."""


@dataclass(frozen=True)
class Entry:
    """A lemma under one encoding: the parts that together imply it, and the argument that they do."""

    lemma: str
    encoding: str
    parts: tuple[Part, ...]
    argument: str
    beside: tuple[Part, ...] = ()
    """Forms shown with the lemma but not part of its argument (Lemma 1's ``closer`` step), or refuting only
    (the global form: a split swarm, bounded)."""


def paper_lemma(lemma: Lemma | str, parts: tuple[Part, ...], argument: str, beside: tuple[Part, ...] = ()) -> Entry:
    """A lemma over the paper's decision cases (every rule that makes a move, one obligation per case)."""
    return Entry(str(lemma), "paper", parts, argument, beside)


def _repairs(model: Model, *, vertical: bool = True) -> tuple[str, ...]:
    """The repaired rule set's own destinations ``model`` turns on, as case-name prefixes
    (:func:`fatline_verify.prove.tasks.repair_cases`); ``vertical=False`` leaves out the contraction,
    which makes no horizontal leg."""
    from ..rules.repaired.options import RepairApproach, RepairStack

    out: list[str] = []
    if model.options.repair_stack is RepairStack.ALIGN:
        out += ["repair-align."] + (["repair-contract."] if vertical else [])
    if model.options.repair_approach is RepairApproach.ON:
        out.append("repair-approach.")
    return tuple(out)


IN_FAMILY = Part(
    "in-family",
    (VIEWS_FORM,),
    "every decision of the rule set's decide, on every view of the lattice, is one its move family admits",
    refutes=False,
)
"""What ties a family's obligations to the rule set (the checker's ``in-family`` lemma holds each run to it too)."""

FAMILY_PARTS = {
    Lemma.NO_COLLISION: (
        (Part("leg", ("leg",), "r's leg against a robot at rest or on any leg: never within 2", refutes=True),),
        "every collision is between a mover and another robot, at rest or moving by a leg of the family",
    ),
    Lemma.CONNECTIVITY: (
        (
            Part("kept", ("kept",), "an edge both movers' tests kept without a witness stays an edge"),
            Part(
                "bridged",
                ("bridged",),
                "an edge a mover's test passed through a witness is a path of two edges",
                needed=lambda model: _witnesses(model),
            ),
            Part(
                "answered",
                ("answered",),
                "an edge whose mover above the other in the family's order kept it without a witness stays an edge",
                needed=lambda model: _inducts(model),
            ),
            Part(
                "chain",
                ("chain-first", "chain-link"),
                "each link of a chain is an edge after the round, or an edge with a mover above the chain's robot",
                needed=lambda model: _inducts(model),
            ),
            Part(
                "rules-out",
                ("rules-out",),
                "no robot moving by a class has a witness of a role that rules the class out",
                needed=lambda model: _rules_out(model),
            ),
        ),
        "every edge before the round is a path of at most two edges after it, or (a family with chains) connected "
        "after it by induction over the family's order",
    ),
}


def _inducts(model: Model) -> str:
    """``""`` when the model's family has chains (its connectivity inducts over its order), else why not."""
    from ..rules import registry
    from .smt.family import inducts

    family = registry.family(model)
    return "" if family is not None and inducts(family) else "the family has no chain: no induction over an order"


def _rules_out(model: Model) -> str:
    """``""`` when the model's family declares roles that rule a class out (used by its obligations), else why not."""
    from ..rules import registry

    family = registry.family(model)
    return "" if family is not None and family.rules_out else "no role of the family rules a class out"


def _witnesses(model: Model) -> str:
    """``""`` when the model's family names an edge's witness in a guard (a bridge: an ``exists`` inside a
    ``forall``), else why no bridged row is needed (a witness a leg needs its mover to see bridges no edge)."""
    from ..rules import registry
    from ..rules.family.lang import edge_roles

    family = registry.family(model)
    if family is None or any(set(edge_roles(c.guard)) - set(family.rules_out) for c in family.classes):
        return ""
    return "no guard of the family names an edge's witness (a bridge), so every edge is kept or chained"


def family_lemma(lemma: Lemma, encoding: str) -> Entry:
    """A lemma over a move family's obligations (:mod:`fatline_verify.prove.smt.family`), every leg class
    against rest and every other class, with the row that holds ``decide`` to the family (:data:`IN_FAMILY`)."""
    parts, argument = FAMILY_PARTS[lemma]
    return Entry(str(lemma), encoding, (*parts, IN_FAMILY), argument)


ONE_COLLIDE = Part("one-mover", ("one-mover",), "r's move never comes within 2 of a robot at rest", refutes=True)
TWO_COLLIDE = Part(
    "two-movers", ("two-movers",), "two robots moving in one round never come within 2", True, _two_movers
)
ONE_EDGE = Part("one-mover", ("one-mover",), "every robot at rest that r saw is still in view after r's move")
TWO_EDGE = Part("two-movers", ("two-movers",), "two movers that saw each other still do", needed=_two_movers)
SEEN = Part("seen", ("seen",), "no move ends right of r and of every robot r sees, so none beyond the RMA")
ON_RMA = Part("on-rma", ("on-rma",), "a robot on the RMA never leaves it", refutes=True)
X_STEP = Part("x-nondecreasing", ("x-nondecreasing",), "no move decreases x (a step fact, not the lemma)")
REACHES = Part("reaches", (), "each robot moves closer to the RMA in finite time (liveness)")

TABLE: tuple[Entry, ...] = (
    paper_lemma(
        Lemma.NO_COLLISION,
        (ONE_COLLIDE, TWO_COLLIDE),
        "a collision in a round is between a mover and a robot at rest, or two movers",
    ),
    paper_lemma(
        Lemma.CONNECTIVITY,
        (ONE_EDGE, TWO_EDGE),
        "every edge with a mover at one end is kept, so the graph after the round has every edge it had",
        beside=(
            Part("global", ("global",), "the whole graph stays connected (bounded slots)", refutes=True),
            Part("closer", ("closer",), "Lemma 1's inner step: r gets closer to the B u C u D robots it sees"),
        ),
    ),
    paper_lemma(
        Lemma.RMA_FIXED,
        (SEEN, ON_RMA),
        "no robot moves beyond the RMA (seen) and none on it leaves it (on-rma), so the RMA stays",
    ),
    paper_lemma(Lemma.APPROACH, (X_STEP, REACHES), "liveness: needs a measure, not a step fact"),
    *(family_lemma(Lemma.NO_COLLISION, encoding) for encoding in ("legs", "family")),
    *(family_lemma(Lemma.CONNECTIVITY, encoding) for encoding in ("legs", "family")),
    Entry(
        str(Lemma.RMA_FIXED),
        "legs",
        (
            Part("seen", SEEN.forms, SEEN.says, cases=_repairs),
            Part("on-rma", ON_RMA.forms, ON_RMA.says, refutes=True, cases=_repairs),
        ),
        "the paper's destinations and the repairs' own (seen, on-rma per case; repair-align, repair-approach, "
        "repair-contract among them); a leg goes no farther than its destination",
    ),
    Entry(str(Lemma.APPROACH), "legs", (X_STEP, REACHES), "liveness: needs a measure, not a step fact"),
)
"""Every lemma under each encoding (``""``: whichever)."""


@dataclass(frozen=True)
class LemmaVerdict:
    """One lemma's verdict from a model's rows, and why."""

    lemma: str
    verdict: str
    why: str
    rows: int
    counts: str
    """Its rows' verdicts, PROVED split by basis (``12 PROVED (1 substantive, 9 immediate, 2 vacuous), 3 VIOLATED``)."""
    rests_on: tuple[str, ...] = ()
    """For PROVED: everything the verdict rests on, one line each (the obligations, the facts assumed and how
    each is checked, the lattice, the scheduler and motion, the solver), as Pactole lists a theorem's
    assumptions; ``fatline prove`` prints them under the lemma."""


def entry_for(lemma: str, encoding: str) -> Entry | None:
    for e in TABLE:
        if e.lemma == lemma and e.encoding in (encoding, ""):
            return e
    return None


_WHERE = re.compile(r"\s\((?:an earlier|lattice|small swarms|reals|linearization|given|the mirror)[^()]*\)")


def _where_dropped(reason: str) -> str:
    """A VIOLATED row's reason without where its counterexample was found (the row keeps it)."""
    return _WHERE.sub("", reason)


def _count(rows: list[dict[str, Any]]) -> str:
    verdicts = [r["verdict"] for r in rows]
    out = []
    for v in ("PROVED", "VIOLATED", "INCONCLUSIVE", "HOLDS_WITHIN_BOUNDS"):
        n = verdicts.count(v)
        if n:
            split = v == "PROVED" and any(r.get("basis") for r in rows)  # liveness rows carry no basis
            out.append(f"{n} {v}" + (f" ({counts_text(rows)})" if split else ""))
    return ", ".join(out)


def judge(entry: Entry, model: Model, rows: list[dict[str, Any]]) -> LemmaVerdict:
    """The lemma's verdict from its rows (every row of ``rows`` with its lemma)."""
    mine = [r for r in rows if r.get("lemma") == entry.lemma]
    by_form: dict[str, list[dict[str, Any]]] = {}
    for r in mine:
        by_form.setdefault(str(r.get("form")), []).append(r)

    def rows_of(part: Part) -> list[dict[str, Any]]:
        if not part.lemma:
            return [r for f in part.forms for r in by_form.get(f, [])]
        return [r for r in rows if r.get("lemma") == part.lemma and r.get("form") in part.forms]

    for part in (*entry.parts, *entry.beside):
        if not part.refutes:
            continue
        for r in rows_of(part):
            if r["verdict"] == "VIOLATED":
                case = r.get("case", r.get("rule", ""))
                return LemmaVerdict(
                    entry.lemma,
                    VIOLATED,
                    f"{part.name} {case}: {_where_dropped(str(r.get('reason', '')))}",
                    len(mine),
                    _count(mine),
                )
    proved, missing, unencoded, skipped = [], [], [], []
    for part in entry.parts:
        why_not = part.needed(model)
        if why_not:
            skipped.append(f"{part.name} not needed: {why_not}")
            continue
        if not part.forms and part.inspection:
            missing.append(f"{part.name}: by inspection: {part.inspection}")
            continue
        if not part.forms:
            unencoded.append(f"{part.name} ({part.says}): no obligation form")
            continue
        got = rows_of(part)
        if not got:
            missing.append(f"{part.name}: no rows (not run)")
        elif absent := [p for p in part.cases(model) if not any(str(r.get("case", "")).startswith(p) for r in got)]:
            missing.append(f"{part.name}: no obligation for {', '.join(a.rstrip('.') for a in absent)}")
        elif any(r["verdict"] != "PROVED" for r in got):
            bad = [r for r in got if r["verdict"] != "PROVED"]
            missing.append(f"{part.name}: {len(bad)} of {len(got)} not PROVED ({_count(bad)})")
        elif part.inspection:
            proved.append(f"{part.name} ({len(got)} PROVED)")
            missing.append(f"{part.name}: by inspection: {part.inspection}")
        else:
            proved.append(f"{part.name} ({len(got)} PROVED)")
    if not part_forms_seen(entry, by_form) and not unencoded:
        return LemmaVerdict(entry.lemma, NOT_ENCODED, "no obligation of its forms in the results", 0, "")
    notes = "; ".join(skipped)
    tail = f" ({notes})" if notes else ""
    if unencoded:
        done = f"; proved: {', '.join(proved)}" if proved else ""
        done += f"; missing: {'; '.join(missing)}" if missing else ""
        return LemmaVerdict(entry.lemma, NOT_ENCODED, "; ".join(unencoded) + done + tail, len(mine), _count(mine))
    if missing:
        done = f"proved: {', '.join(proved)}; " if proved else ""
        return LemmaVerdict(
            entry.lemma, NOT_PROVED, f"{done}missing: {'; '.join(missing)}{tail}", len(mine), _count(mine)
        )
    used = [r for part in entry.parts if not part.needed(model) for r in rows_of(part)]
    facts = tuple(dict.fromkeys(f for part in entry.parts if not part.needed(model) for f in part.facts))
    return LemmaVerdict(
        entry.lemma,
        PROVED,
        f"{entry.argument}: {', '.join(proved)}{tail}",
        len(mine),
        _count(mine),
        rests_on(model, used, facts),
    )


def part_forms_seen(entry: Entry, by_form: dict[str, list[dict[str, Any]]]) -> bool:
    return any(f in by_form for p in (*entry.parts, *entry.beside) for f in p.forms)


def encoding_of(model: Model) -> str:
    """The encoding the prover uses for ``model`` (:func:`fatline_verify.prove.tasks.encoding_name`),
    ``""`` without one (no table entry then: its safety lemmas have no rows)."""
    from .tasks import encoding_name

    return encoding_name(model) or ""


LIVENESS = (str(Lemma.PROGRESS), str(Lemma.TERMINATION))
"""The liveness lemmas: judged by :func:`liveness_verdicts` (their own rules), not by a table entry."""


def liveness_verdicts(model: Model, rows: Sequence[dict[str, Any]]) -> dict[Lemma, tuple[str, str]]:
    """Lemma-level verdicts of progress and termination from the rows of one model (``{}`` for a rule
    set without a liveness declaration or without liveness rows), each ``(verdict, why)``:

    - progress (Lemma 2): VIOLATED by a replayed stuck configuration (a row VIOLATED); PROVED when every
      enabledness row is; otherwise NOT PROVED.
    - termination: VIOLATED only by a replayed stuck configuration (a run that never reaches the goal);
      a VIOLATED measure row only leaves it NOT PROVED (one round that does not decrease the measure is
      not a run that never ends). PROVED only when every part is present and PROVED for this rule set by
      its own rows: progress, every measure row, a bound below for every component of the measure
      (:func:`measure_bounds`: an obligation proves it, never the rule set's word), and no-collision and
      connectivity at lemma level (the argument assumes a swarm that stays connected and never
      collides). A part absent (a rule set without a safety encoding has no such rows) is missing, never
      taken as proved.
    """
    return {lemma: (v.verdict, v.why) for lemma, v in live_verdicts(model, rows).items()}


def measure_bounds(model: Model, rows: Sequence[dict[str, Any]]) -> list[tuple[tuple[int, int], str, bool]]:
    """For each component ``(a, b)`` of the declared measure: why its sum over the robots is bounded below
    on every configuration the rules reach, and whether an obligation of this rule set proves it.

    - ``(0, 0)``: constant.
    - ``(a, 0)`` with ``a < 0``: ``sum(a x) >= a n x_max`` while no robot ever ends right of the initial
      greatest x, which rma-fixed's ``seen`` rows prove (no move ends right of the mover and of every
      robot it sees, so none right of the right-most robot).
    - anything else: no obligation of the tool proves a bound (the rule set's own words, :attr:`Liveness.bounded`,
      are not evidence)."""
    declared = registry.of(model).liveness
    if declared is None:
        return []
    out: list[tuple[tuple[int, int], str, bool]] = []
    for a, b in declared.measure:
        if a == 0 and b == 0:
            out.append(((a, b), "constant", True))
        elif b == 0 and a < 0:
            seen = _part_verdict(model, rows, str(Lemma.RMA_FIXED), "seen")
            if seen is not None and seen.verdict == PROVED:
                out.append(
                    ((a, b), f"no x exceeds the initial greatest x (rma-fixed's seen rows: {seen.counts})", True)
                )
            else:
                why = "no rows" if seen is None else f"{seen.verdict}: {seen.why}"
                out.append(((a, b), f"needs rma-fixed's seen rows PROVED ({why})", False))
        else:
            out.append(((a, b), "no obligation bounds it", False))
    return out


def _part_verdict(model: Model, rows: Sequence[dict[str, Any]], lemma: str, part: str) -> LemmaVerdict | None:
    """The verdict of one part of a lemma's table entry on its own (``None``: no entry or no such part)."""
    entry = entry_for(lemma, encoding_of(model))
    if entry is None:
        return None
    chosen = tuple(p for p in entry.parts if p.name == part)
    if not chosen:
        return None
    return judge(Entry(entry.lemma, entry.encoding, chosen, f"{lemma}'s {part} part"), model, list(rows))


def _safety(model: Model, rows: Sequence[dict[str, Any]]) -> dict[str, LemmaVerdict | None]:
    """No-collision and connectivity at lemma level from ``model``'s own rows (``None``: the rule set has no
    safety encoding, so no such rows)."""
    out: dict[str, LemmaVerdict | None] = {}
    for lemma in (str(Lemma.NO_COLLISION), str(Lemma.CONNECTIVITY)):
        entry = entry_for(lemma, encoding_of(model))
        out[lemma] = None if entry is None else judge(entry, model, list(rows))
    return out


def _unsafe(model: Model, safety: dict[str, LemmaVerdict | None]) -> list[str]:
    """What termination misses of no-collision and connectivity (:func:`_safety`), one entry a lemma."""
    missing = []
    for lemma, v in safety.items():
        if v is None:
            missing.append(f"{lemma}: no obligations (the rule set has no safety encoding)")
        elif v.verdict == PROVED:
            continue
        elif not v.rows:
            missing.append(f"{lemma}: no rows (run fatline prove {model.ref} with every lemma)")
        else:
            missing.append(f"{lemma} {v.verdict}")
    return missing


def live_verdicts(model: Model, rows: Sequence[dict[str, Any]]) -> dict[Lemma, LemmaVerdict]:
    """:func:`liveness_verdicts` with each verdict's rows, counts and what a PROVED rests on."""
    from .tasks import row_key, tasks_for

    declared = registry.of(model).liveness
    if declared is None or not any(r.get("lemma") in LIVENESS for r in rows):
        return {}  # no liveness rows (a scheduler the prover refuses has no rows at all)
    by_key = {row_key(r): r for r in rows}
    from .smt.liveness import ENABLED

    expected = [t.key for t in tasks_for(model, (Lemma.PROGRESS, Lemma.TERMINATION))]
    enabled = [k for k in expected if k.startswith(f"{Lemma.PROGRESS}/{ENABLED}-")]
    measure = [k for k in expected if k.startswith(f"{Lemma.TERMINATION}/")]
    if not any(k in by_key for k in expected):
        return {}

    def verdicts(keys: list[str]) -> list[str]:
        return [by_key[k]["verdict"] if k in by_key else "missing" for k in keys]

    def open_text(keys: list[str]) -> str:
        left = [k.split("/", 1)[1] for k, v in zip(keys, verdicts(keys), strict=True) if v != "PROVED"]
        return f"{len(left)} of {len(keys)} rows not PROVED ({', '.join(left[:3])}{', ...' if len(left) > 3 else ''})"

    def made(lemma: Lemma, verdict: str, why: str, rests: tuple[str, ...] = ()) -> LemmaVerdict:
        mine = [r for r in rows if r.get("lemma") == str(lemma)]
        return LemmaVerdict(str(lemma), verdict, why, len(mine), _count(mine), rests)

    stuck = [k for k, v in zip(enabled, verdicts(enabled), strict=True) if v == "VIOLATED"]
    out: dict[Lemma, LemmaVerdict] = {}
    problem = goal_problem(model)
    if problem:  # no enabledness rows (tasks_for leaves them out): nothing said of progress
        out[Lemma.PROGRESS] = made(Lemma.PROGRESS, NOT_ENCODED, problem)
        out[Lemma.TERMINATION] = made(
            Lemma.TERMINATION,
            NOT_PROVED,
            "progress not encoded for this goal; measure: "
            + ("every row PROVED" if all(v == "PROVED" for v in verdicts(measure)) else open_text(measure)),
        )
        return out
    if stuck:
        why = f"a replayed stuck configuration ({stuck[0]})"
        out[Lemma.PROGRESS] = made(Lemma.PROGRESS, VIOLATED, why)
        out[Lemma.TERMINATION] = made(Lemma.TERMINATION, VIOLATED, why)
        return out
    from .refine import KEY as COVERAGE
    from .refine import refinement_gap

    gap = refinement_gap(rows)  # every decision of decide in a declared case (progress/coverage-cases)
    rows_ok = all(v == "PROVED" for v in verdicts(enabled))
    progress_ok = rows_ok and gap is None
    enabled_rows = [by_key[k] for k in enabled if k in by_key]
    covered = [by_key[COVERAGE]] if gap is None else []
    safety = _safety(model, rows)
    connected = safety[str(Lemma.CONNECTIVITY)]
    link = connected.verdict if connected is not None else "no safety encoding"
    premise = (
        "premise: the claim is about connected non-goal configurations (whether the rules keep a swarm "
        f"connected is connectivity's own lemma; here: {link})"
    )
    if progress_ok:
        out[Lemma.PROGRESS] = made(
            Lemma.PROGRESS,
            PROVED,
            "every enabledness row PROVED, every decision in a declared case",
            rests_on(model, [*enabled_rows, *covered], more=(premise,)),
        )
    else:
        why = "; ".join(t for t in ((open_text(enabled) if not rows_ok else ""), gap or "") if t)
        out[Lemma.PROGRESS] = made(Lemma.PROGRESS, NOT_PROVED, why)
    missing: list[str] = []
    if not rows_ok:
        missing.append("progress not proved")
    if gap is not None:
        missing.append(gap)
    if not all(v == "PROVED" for v in verdicts(measure)):
        missing.append("measure: " + open_text(measure))
    bounds = measure_bounds(model, rows)
    missing += [f"the measure's bound: component {list(c)}: {why}" for c, why, ok in bounds if not ok]
    missing += _unsafe(model, safety)
    if missing:
        out[Lemma.TERMINATION] = made(Lemma.TERMINATION, NOT_PROVED, "; ".join(missing))
        return out
    measure_rows = [by_key[k] for k in measure]
    more = (
        "progress: PROVED (every enabledness row)",
        *(f"bound of component {list(c)}: {why}" for c, why, _ in bounds),
        *(f"{v.lemma}: PROVED ({v.counts})" for v in safety.values() if v is not None),
        f"fair scheduler ({model.options.scheduler}): an enabled robot is activated within finitely many rounds",
    )
    out[Lemma.TERMINATION] = made(
        Lemma.TERMINATION,
        PROVED,
        "progress, the measure and its bound, no-collision and connectivity",
        rests_on(model, [*enabled_rows, *measure_rows, *covered], more=more),
    )
    return out


def lemma_verdicts(
    model: Model, rows: list[dict[str, Any]], lemmas: tuple[str, ...] | None = None
) -> list[LemmaVerdict]:
    """Every lemma with rows in ``rows`` (or each of ``lemmas``), judged by its table entry."""
    wanted = lemmas if lemmas is not None else tuple(dict.fromkeys(str(r.get("lemma")) for r in rows))
    out = []
    live: dict[Lemma, LemmaVerdict] | None = None
    for lemma in wanted:
        if lemma in LIVENESS:
            live = live if live is not None else live_verdicts(model, rows)
            if Lemma(lemma) in live:
                out.append(live[Lemma(lemma)])
            continue
        entry = entry_for(lemma, encoding_of(model))
        if entry is None:
            continue
        out.append(judge(entry, model, rows))
    return out


__all__ = [
    "LEMMA_VERDICTS",
    "NOT_ENCODED",
    "NOT_PROVED",
    "PROVED",
    "TABLE",
    "VIOLATED",
    "Entry",
    "LemmaVerdict",
    "Part",
    "family_lemma",
    "judge",
    "lemma_verdicts",
    "live_verdicts",
    "liveness_verdicts",
    "measure_bounds",
    "paper_lemma",
]
