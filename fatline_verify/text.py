"""Human text rendered from data: traces, decisions, violations, numbers, the option catalogue.

The engine never prints; the CLI prints what these functions return. Numbers stay exact in the
data (traces hold ``"p/q"`` strings); text shows a squared distance as a short decimal (``≈3.94``,
the ``≈`` marking a rounded value) and a long coordinate likewise, so a 200-digit fraction never
reaches a caption. Rounding is done on the exact :class:`~fractions.Fraction`, for display only.
"""

from __future__ import annotations

import ast
import inspect
import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import Any

from .goals.registry import fallback_note, outcome_words
from .lemmas.properties import Lemma
from .model.config import Model
from .model.numbers import Point, format_number, parse_number
from .model.options import CATALOGUE, MODEL, Options
from .model.options import owner as option_owner
from .rules import registry
from .rules.decision import Decision
from .rules.paper.algorithm import Rule
from .schedulers.round import decide_all
from .trace.traces import trace_model

DIGITS = 2
"""Decimals of a rounded number (more when rounding would land on a whole number it is not)."""
MAX_DIGITS = 12
SHORT_EXACT = 9
"""An exact value written in at most this many characters is shown as it is (``41/16``)."""
SHORT_FRACTION = 15
"""Plain text adds the exact fraction after a rounded squared distance when it is at most this long."""


# --- numbers for display -------------------------------------------------------------------------


def plural(count: int, word: str, words: str | None = None) -> str:
    """``1 round``, ``0 rounds``, ``1,024 states`` (``words``: an irregular plural)."""
    return f"{count:,} {word if count == 1 else (words or word + 's')}"


def exact_value(value: object) -> Fraction:
    """A number of a trace document (``int``, ``"p/q"``) or of the engine, exactly."""
    if isinstance(value, Fraction | int):
        return Fraction(value)
    return Fraction(parse_number(value, name="number"))


def exact_text(value: object) -> str:
    """The exact value as the trace writes it: ``20`` or ``8474.../2135...``."""
    return str(format_number(exact_value(value)))


def _decimal(scaled: int, digits: int) -> str:
    """``scaled / 10**digits`` in decimal notation, trailing zeros dropped."""
    sign, size = ("-" if scaled < 0 else ""), abs(scaled)
    whole, frac = divmod(size, 10**digits)
    tail = str(frac).rjust(digits, "0").rstrip("0")
    return f"{sign}{whole}" + (f".{tail}" if tail else "")


def decimal_text(value: object, digits: int = DIGITS) -> str:
    """A short decimal: exact when it is (``2.5``), else rounded and marked (``≈3.94``). A value
    that would round to a whole number it is not gets more digits (``≈3.9999``, not ``≈4``), so a
    rounded squared distance never reads as the contact or visibility boundary it misses."""
    f = exact_value(value)
    d = digits
    while True:
        scaled = round(f * 10**d)
        shown = Fraction(scaled, 10**d)
        if shown == f:
            return _decimal(scaled, d)
        if shown.denominator != 1 or d >= MAX_DIGITS:
            return "≈" + _decimal(scaled, d)
        d += 1


def is_rounded(shown: str) -> bool:
    """Whether a displayed number is not the exact value."""
    return shown.startswith("≈")


def coordinate_text(value: object) -> str:
    """A coordinate: exact when short (``3``, ``41/16``), else a short decimal."""
    text = exact_text(value)
    return text if len(text) <= SHORT_EXACT else decimal_text(value)


def area_text(value: object) -> str:
    """A squared distance for plain text: the short decimal, then the exact fraction when it is
    short (``≈3.94 (63/16)``); a long one is only in the trace."""
    shown, text = decimal_text(value), exact_text(value)
    return f"{shown} ({text})" if is_rounded(shown) and len(text) <= SHORT_FRACTION else shown


@dataclass(frozen=True, slots=True)
class NumberStyle:
    """How a caption writes its numbers: squared distances (``area``) and coordinates."""

    area: Callable[[object], str]
    coordinate: Callable[[object], str]


TEXT = NumberStyle(area_text, coordinate_text)
"""Plain text (the CLI): short decimals, short exact fractions kept."""
SHORT = NumberStyle(decimal_text, coordinate_text)
"""Captions of pictures and pages: short decimals only (the exact value is in the trace, or on hover)."""


def _pt(p: Sequence[Any], style: NumberStyle = TEXT) -> str:
    return f"({style.coordinate(p[0])}, {style.coordinate(p[1])})"


def violation_line(v: dict[str, Any], style: NumberStyle = TEXT) -> str:
    """One line for a violation record of a trace."""
    prop = v["property"]
    robots = " ".join(f"r{i}" for i in v["robots"])
    if prop == Lemma.NO_COLLISION:
        how = "both moving" if v.get("both_moved") else "one moving"
        closest = style.area(v["closest_distance2"])
        return f"{prop}: {robots} collide ({how}); closest squared centre distance {closest} (discs touch at 4)"
    if prop == Lemma.CONNECTIVITY:
        edges = ", ".join(
            f"r{a}-r{b} (distance^2 {style.area(d)})"
            for (a, b), d in zip(v["lost_edges"], v["distance2_after"], strict=True)
        )
        comps = " | ".join(" ".join(f"r{i}" for i in c) for c in v["components"])
        return f"{prop}: visibility graph split into {comps}; lost {edges}"
    if prop == Lemma.RMA_FIXED:
        return (
            f"{prop}: {robots} went from the right-most axis x={style.coordinate(v['rma_x'])} "
            f"to x={style.coordinate(v['x_after'])}"
        )
    if prop == Lemma.CONNECTIVITY_EDGE:
        (a, b), d2 = v["robots"], v["distance2_after"][0]
        return (
            f"{prop}: r{a} and r{b} no longer see each other (distance^2 {style.area(d2)}); the graph stays connected"
        )
    if prop == Lemma.PROGRESS:
        return f"{prop}: deadlock: no robot is enabled and the robots are not on a line"
    if prop == Lemma.TERMINATION:
        return f"{prop}: this execution never forms the line (a deadlock or a fair cycle)"
    if prop == Lemma.APPROACH:
        return f"{prop}: {robots} left of the right-most axis never move right again"
    return f"{prop}: {robots}"


# --- why a robot stays -----------------------------------------------------------------------------


@cache
def rule_notes() -> dict[Rule, str]:
    """Each :class:`~fatline_verify.rules.paper.algorithm.Rule`'s docstring in ``algorithm.py`` (for the
    NoMovement bullets: the paper's words), whitespace collapsed; read from the source, so the
    text lives in one place."""
    try:
        tree = ast.parse(inspect.getsource(Rule))
    except (OSError, TypeError):  # no source (a frozen install): rules are named, not quoted
        return {}
    body = tree.body[0].body if tree.body and isinstance(tree.body[0], ast.ClassDef) else []
    notes = {}
    for node, doc in itertools.pairwise(body):
        if (
            isinstance(node, ast.Assign)
            and isinstance(node.targets[0], ast.Name)
            and isinstance(doc, ast.Expr)
            and isinstance(doc.value, ast.Constant)
            and isinstance(doc.value.value, str)
        ):
            notes[Rule[node.targets[0].id]] = " ".join(doc.value.value.replace("``", "").split())
    return notes


def rule_label(rule: Rule) -> str:
    """``NoMovement bullet 4`` for a NoMovement rule, else the rule's name."""
    value = str(rule)
    if value.startswith("nomovement-"):
        return f"NoMovement bullet {value.split('-')[1]}"
    return value


def rule_quote(rule: Rule) -> str:
    """The paper's words for a rule (the quoted part of its docstring), else its docstring."""
    note = rule_notes().get(rule, "")
    if note.startswith('"') and '"' in note[1:]:
        return note[: note.index('"', 1) + 1]
    return note


def _seen(i: int, decision: Decision, state: Sequence[Point], model: Model | None = None) -> str:
    """``sees r1 in A, r2 in A and C``: the robots ``i`` sees and the sets it put them in (a rule set
    that does not classify into the paper's sets: the robots it sees, by ``model``'s visibility)."""
    index = {p: j for j, p in enumerate(state)}
    ox, oy = state[i]
    if not decision.classification and model is not None:
        seen_ids = [f"r{j}" for j, p in enumerate(state) if j != i and model.sees((p[0] - ox) ** 2 + (p[1] - oy) ** 2)]
        return "sees " + ", ".join(seen_ids) if seen_ids else "sees no robot"
    seen = [
        f"r{index[(ox + c[0], oy + c[1])]} in {' and '.join(sorted(m)) or 'no set'}" for c, m in decision.classification
    ]
    return "sees " + ", ".join(seen) if seen else "sees no robot"


def stay_lines(state: Sequence[Point], model: Model) -> list[str]:
    """Why each robot of ``state`` (a deadlock) keeps still: per robot the rule (for NoMovement the
    bullet) and what it sees, then each rule used with the paper's words."""
    decisions = decide_all(state, model)
    lines, used = [], []
    for i, d in sorted(decisions.items()):
        status = "enabled, " if d.moves else ""
        lines.append(f"r{i}: {status}{rule_label(d.rule)} ({_seen(i, d, state, model)})")
        if d.rule not in used:
            used.append(d.rule)
    own = registry.of(model).labels
    for rule in used:
        quote = rule_quote(rule) if isinstance(rule, Rule) else own.get(str(rule), "")
        if quote:
            lines.append(f"{rule_label(rule)}: {quote}")
    return lines


def final_state(doc: dict[str, Any], model: Model) -> tuple[Point, ...]:
    """The positions after a trace's last round, in ``model``'s lattice units."""
    points = doc["rounds"][-1]["positions"] if doc["rounds"] else doc["initial"]
    return tuple(model.to_lattice((exact_value(x), exact_value(y))) for x, y in points)


# --- traces ----------------------------------------------------------------------------------------


_CASE_NOTE = {
    "scenario-2": " (Scenario 2's search found no vacant point)",
    "scenario-3": " (Scenario 3's search found no vacant point)",
    "uncovered": " (a case Scenarios 1-3 leave out)",
}


def _positions_line(points: list[Any]) -> str:
    return "  ".join(f"r{i} {_pt(p)}" for i, p in enumerate(points))


_EVENT_TEXT = {
    "look": "r{robot} looks and computes",
    "move": "r{robot} takes a move step",
    "stop": "r{robot} ends its move here",
}


def trace_lines(doc: dict[str, Any], model: Model | None = None) -> list[str]:
    """The rounds of a trace document, one block per round, and its outcome; for a deadlock, why
    each robot stays (under ``model``, by default the trace's own)."""
    lines = ["start: " + _positions_line(doc["initial"])]
    word = "round"
    for k, rnd in enumerate(doc["rounds"], start=1):
        if "event" in rnd:
            word = "event"
            lines.append(f"event {k}: {_EVENT_TEXT[rnd['event']].format(robot=rnd['robot'])}")
        else:
            lines.append(f"round {k}: active " + " ".join(f"r{i}" for i in rnd["active"]))
        for d in rnd["decisions"]:
            psi = f", psi_right x={coordinate_text(d['psi'])}" if d.get("psi") is not None else ""
            case = _CASE_NOTE.get(d.get("case") or "", "") if d["rule"].startswith(("scenario-4", "uncovered")) else ""
            lines.append(f"  r{d['robot']} {d['rule']}{case} -> {_pt(d['destination'])}{psi}")
        lines.append("  now: " + _positions_line(rnd["positions"]))
        for mv in rnd.get("moving", ()):
            lines.append(f"  moving: r{mv['robot']} -> {_pt(mv['path'][-1])}, {mv['step']} of {mv['of']} steps done")
        for v in rnd["violations"]:
            lines.append("  VIOLATED " + violation_line(v))
    n = len(doc["rounds"])
    tail = {
        "violation": "stopped at a violation",
        "round-limit": "round limit reached: neither the goal, a deadlock nor a violation",
        **outcome_words(doc["model"]["options"].get("goal", "vertical-line")),
    }[doc["outcome"]]
    lines.append(f"outcome after {n} {word}{'s' if n != 1 else ''}: {tail}")
    if doc["outcome"] == "deadlock":
        model = model or trace_model(doc)
        lines += ["  " + line for line in stay_lines(final_state(doc, model), model)]
    if doc.get("loop_start") is not None:
        lines.append(f"the {word}s after {word} {doc['loop_start']} repeat forever (the swarm returns, translated)")
    if doc.get("violation"):
        lines.append("witnesses " + violation_line(doc["violation"]))
    return lines


def _reading_marks(spec: Any, reading: str, chosen: dict[str, str], model: Model | None) -> str:
    marks = []
    if reading == spec.default.value:
        marks.append("default")
    if model is not None and chosen[spec.name] == reading:
        marks.append(f"model {model.name}")
    return f" [{', '.join(marks)}]" if marks else ""


def explain_lines(name: str | None = None, model: Model | None = None) -> list[str]:
    """The catalogue (or one option): the quote, every reading, the default, the model's choice, and the
    rule set that declares it (the model layer's options: none); without a model every registered rule
    set's options (plug-ins loaded), for a model only the options its rule set reads. Then the parameters
    registered schedulers and rule sets declare (:func:`parameter_lines`); ``name`` may be one of those
    (``scheduler.k``)."""
    if model is None:
        registry.names()  # the plug-ins' rule sets declare their options when they load
    if name is not None and name not in CATALOGUE:
        return parameter_lines(model, name)[:-1]
    options = model.options if model else Options()
    chosen = {n: str(getattr(options, n)) for n in CATALOGUE}
    reads = registry.of(model) if model is not None else None
    names = [name] if name else [n for n in CATALOGUE if reads is None or reads.accepts(n)]
    lines: list[str] = []
    for n in names:
        spec = CATALOGUE[n]
        lines.append(f"{n}")
        lines.append(f'  paper: "{spec.quote}"')
        for reading, meaning in spec.readings.items():
            pointer = "*" if chosen[n] == reading else " "
            lines.append(f"  {pointer} {reading}{_reading_marks(spec, reading, chosen, model)}: {meaning}")
        if spec.note:
            lines.append(f"  note: {spec.note}")
        declarer = option_owner(n)
        if declarer != MODEL:
            lines.append(f"  an option of rule set {declarer!r}, set in a model file's [options] table")
        lines.append("")
    if name is None:
        lines += parameter_lines(model)
    return lines[:-1] if lines and not lines[-1] else lines


def declared_parameters(model: Model | None = None) -> dict[str, tuple[str, Any]]:
    """The parameters of one's own there are, by their model-file name (``scheduler.k``, ``rules.reach``):
    per name, what declares it ("scheduler 'pairs'") and its :class:`~fatline_verify.model.seams.Param`.
    For a model, its scheduler's and rule set's; else every registered one's (plug-ins loaded)."""
    from .model.config import own_parameters
    from .model.seams import declared
    from .schedulers.activation import ROUND_SCHEDULERS

    if model is not None:
        return dict(own_parameters(model))
    names = registry.names()  # loads the plug-ins, which may register schedulers too
    owners = [("scheduler", kind, found) for kind, found in ROUND_SCHEDULERS.items()]
    owners += [("rules", rules, registry.get(rules)) for rules in names]
    found: dict[str, tuple[str, Any]] = {}
    for seam, owner_name, owner in owners:
        what = f"scheduler {owner_name!r}" if seam == "scheduler" else f"rule set {owner_name!r}"
        for key, param in declared(owner).items():
            found.setdefault(f"{seam}.{key}", (what, param))  # two owners of one name: the first's words
    return found


def parameter_lines(model: Model | None = None, name: str | None = None) -> list[str]:
    """The parameters of one's own (``[scheduler]``, ``[rules]`` tables of a model file): what each
    means, its values, its default, the model's value; ``name`` one of them (else a one-line
    :class:`~fatline_verify.errors.InvalidInput` naming every option and parameter there is)."""
    from .errors import InvalidInput

    params = declared_parameters(model)
    if name is not None and name not in params:
        reads = registry.of(model) if model is not None else None
        known = ", ".join([*(n for n in CATALOGUE if reads is None or reads.accepts(n)), *params])
        raise InvalidInput(f"option={name!r}: unknown option; expected one of {known}")
    lines: list[str] = []
    for key, (what, param) in params.items():
        if name is not None and key != name:
            continue
        seam, own = key.split(".", 1)
        chosen = f" [model {model.name}: {model.setting(seam)[own]!r}]" if model is not None else ""
        lines.append(f"{key} (a parameter of {what}, set in the model file's [{seam}] table)")
        lines.append(f"  {param.doc}")
        lines.append(f"  {param.expected()}; default {param.default!r}{chosen}")
        lines.append("")
    return lines


READINGS_DOC = "docs/readings.md"
"""Where the catalogue ships, relative to the repository root (``python -m fatline_verify.docs``)."""


def readings_markdown() -> str:
    """``docs/readings.md``: every option of the catalogue with the paper's words, every reading with
    its meaning, the default. Generated from the options the model layer and this package's rule sets
    declare (``model/options.py``, ``rules/*/options.py``; no plug-in is loaded); a test keeps the shipped
    file equal."""
    lines = [
        "<!-- generated by fatline-verify: python -m fatline_verify.docs (from fatline_verify/model/options.py "
        "and the rule sets' fatline_verify/rules/*/options.py); do not edit -->",
        "# Readings of the paper",
        "",
        "The paper is informal; each place where its text admits several precise readings is an *option*",
        "with named *readings*. A model file chooses one reading per option (`[options]` in `models/*.toml`);",
        "an option it leaves out keeps its default. `fatline explain [OPTION] [--model M]` prints the same",
        "catalogue, and the reports name readings as `option=reading`.",
        "",
        "| option | default | other readings |",
        "|---|---|---|",
    ]
    for name, spec in CATALOGUE.items():
        others = ", ".join(f"`{r}`" for r in spec.readings if r != spec.default.value)
        lines.append(f"| [{name}](#{name}) | `{spec.default.value}` | {others} |")
    for name, spec in CATALOGUE.items():
        lines += ["", f"## {name}", "", f"The paper: “{spec.quote}”", ""]
        for reading, meaning in spec.readings.items():
            default = " (default)" if reading == spec.default.value else ""
            lines.append(f"- `{reading}`{default}: {meaning}")
        if spec.note:
            lines += ["", f"Note: {spec.note}."]
    return "\n".join(lines) + "\n"


def table(headers: list[str], rows: list[list[str]]) -> list[str]:
    """A plain-text table with aligned columns."""
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    line = "  ".join(h.ljust(w) for h, w in zip(headers, widths, strict=True)).rstrip()
    out = [line, "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
    return out


def check_lines(result: Any, trace_paths: dict[tuple[str, int], str]) -> list[str]:
    """The summary of a :class:`fatline_verify.check.checker.CheckResult`."""
    from .resources import format_size
    from .schedulers.systems import system_for

    model = result.model
    system = system_for(model)
    word = system.step_word
    w, h = result.window
    where = f"window {w}x{h} lattice points"
    if result.bound is not None:
        where += f", exploration bound {result.bound[0]}x{result.bound[1]}"
    if result.max_states is not None:
        cap = f"at most {result.max_states:,} states per robot count"
    else:
        cap = f"as many states as --max-memory {format_size(result.max_memory)} holds"
    lines = [f"model {model.describe()}", f"{where}, {cap}"]
    lines.append("")
    fine = system.scale > 1 or any(s.off_lattice for s in result.stats)
    rows = []
    for s in result.stats:
        rows.append(
            [
                str(s.robots),
                str(s.initial),
                str(s.states),
                str(s.transitions),
                str(s.escaped),
                *([str(s.off_lattice)] if fine else []),
                str(s.violating_only),
                "yes" if s.truncated else "no",
                f"{s.seconds:.2f}",
                s.engine,
            ]
        )
    lines += table(
        [
            "robots",
            "initial",
            "states",
            "transitions",
            "escaped",
            *(["off-lattice"] if fine else []),
            "violating-only",
            "truncated",
            "seconds",
            "engine",
        ],
        rows,
    )
    lines += [
        f"n={s.robots}: a decision off the model's lattice: searched by the {s.engine} engine (the {s.asked} engine "
        "packs lattice moves only; off-lattice successors are judged on their step and counted, not explored)"
        for s in result.stats
        if s.asked
    ]
    lines += [note for note in dict.fromkeys(fallback_note(model, s.engine) for s in result.stats) if note]
    lines.append("")
    rows = []
    for lemma in dict.fromkeys(x.lemma for x in result.results):  # the paper's, then registered ones
        for r in (x for x in result.results if x.lemma is lemma):
            trace = trace_paths.get((lemma.value, r.robots), "")
            witness = "" if r.witness_rounds is None else plural(r.witness_rounds, word)
            rows.append([lemma.value, str(r.robots), r.verdict.value, witness, r.reason, trace])
    lines += table(["lemma", "robots", "verdict", "witness", "detail", "trace"], rows)
    lines.append("")
    if result.after_violation == "stop":
        lines.append(
            f"States reached only through a violating {word} are not explored further; liveness verdicts are over "
            "executions that break no safety lemma."
        )
    else:
        lines.append(f"States reached through violating {word}s are explored further (--after-violation continue).")
    off = ""
    if system.scale > 1:
        off = (
            f" off-lattice = successors (counted in escaped) with a robot between points of the {system.scale}-times "
            "finer lattice (a move decided on a halfway view), not explored;"
        )
    elif fine:
        off = (
            " off-lattice = successors with a robot off the model's lattice (a destination between its points), "
            "judged on their step and counted in escaped, not explored;"
        )
    outside, scope = ("window", "window") if result.bound is None else ("exploration bound", "window and bound")
    lines += [
        f"Columns: initial = initial configurations up to translation; escaped = successors outside the {outside} "
        f"(not explored);{off} violating-only = violating {word}s into a state no other {word} reaches "
        f"(counted per {word}, not per state; not explored); truncated = the search stopped at --max-states or "
        "--max-memory before it expanded every state (a lemma it found no violation of is then INCONCLUSIVE); "
        f"witness = {word}s in the shortest witness (replayed before it is reported).",
        f"A lemma that holds, holds for these robot counts and this {scope} only. "
        + {
            "VIOLATED": "Exit code 1: violations were found.",
            "INCONCLUSIVE": "Exit code 3: nothing violated, but a bound was hit (INCONCLUSIVE).",
            "HOLDS_WITHIN_BOUNDS": "Exit code 0: every lemma holds within these bounds.",
        }["VIOLATED" if result.any_violated else "INCONCLUSIVE" if result.any_inconclusive else "HOLDS_WITHIN_BOUNDS"],
    ]
    return lines
