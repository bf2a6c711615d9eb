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
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import Any

from .goals.registry import fallback_note, outcome_words
from .lemmas.properties import Lemma
from .model.config import Model
from .model.numbers import Point, format_number, parse_number
from .model.options import CATALOGUE, Options
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
    """The catalogue (or one option): the quote, every reading, the default, the model's choice."""
    options = model.options if model else Options()
    chosen = {n: str(getattr(options, n)) for n in CATALOGUE}
    names = [name] if name else list(CATALOGUE)
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
        lines.append("")
    return lines[:-1] if lines else lines


READINGS_DOC = "docs/readings.md"
"""Where the catalogue ships, relative to the repository root (``python -m fatline_verify.docs``)."""


def readings_markdown() -> str:
    """``docs/readings.md``: every option of the catalogue with the paper's words, every reading with
    its meaning, the default. Generated from ``options.py``; a test keeps the shipped file equal."""
    lines = [
        "<!-- generated by fatline-verify: python -m fatline_verify.docs (from fatline_verify/model/options.py); "
        "do not edit -->",
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


PROVE_COLUMNS = ["lemma", "form", "case", "verdict", "robots", "seconds", "detail", "trace"]
"""``fatline prove -v``: every field of a row (the default table: :data:`PROVE_SHORT_COLUMNS`)."""
PROVE_SHORT_COLUMNS = ["obligation", "verdict", "seconds", "reason"]
PROVE_ROBOTS_LEGEND = (
    "robots = the robots an obligation names besides r: the witnesses of r's case and the robot the claim is "
    "about (each obligation's header argues for every other robot of a swarm of any size); for the global form "
    "of connectivity, its slots"
)
SHORT_REASON = 52
"""Characters of a reason in the default ``fatline prove`` table (``-v`` and ``results.json``: all of it)."""
SHORTER = (
    (r"\bfrom an initial configuration of (\d+) robots\b", r"from \1 robots"),
    (r"^unsat over the reals: holds for swarms of every size\b", "unsat: holds for every swarm size"),
    (r"^the case never fires under these readings\b", "vacuous: the case never fires"),
    (r"^an edge is lost and the graph splits\b", "the graph splits"),
    (r"^r moves to \([^()]*\) and is not closer to the robot at \([^()]*\) in ", "r is not closer to the robot in "),
    (r"^r moves to \([^()]*\): x decreases\b", "r's x decreases"),
)
"""The commonest reasons' words, shorter (the default table only)."""


def prove_row(r: dict[str, Any], trace: str) -> list[str]:
    """One ``results.json`` row as table cells (``trace``: how the page or terminal shows the trace).
    ``robots``: the robots the obligation names besides r (the global form: its slots)."""
    case = r.get("case", r["rule"]) + (f" + {r['other']}" if r.get("other") else "")
    return [r["lemma"], r["form"], case, r["verdict"], str(r["slots"]), f"{r['seconds']:.1f}", r["reason"], trace]


def short_reason(reason: str, width: int = SHORT_REASON) -> str:
    """A reason as one short cell: its parenthetical asides dropped (a group with a word in it; a point
    such as ``(73/30, -1)`` stays), the commonest phrases shortened (:data:`SHORTER`), cut at a word
    before ``width`` characters with an ellipsis."""
    out: list[str] = []
    depth, group = 0, ""
    for ch in reason:
        if depth:
            group += ch
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if not depth:
                if not any(len(word) >= 3 and word.isalpha() for word in re.split(r"[^A-Za-z]+", group)):
                    out.append(group)
                group = ""
        elif ch == "(":
            depth, group = 1, ch
        else:
            out.append(ch)
    out.append(group)  # an aside never closed stays
    text = " ".join("".join(out).split()).replace(" ,", ",").replace(" :", ":").replace(" ;", ";")
    for pattern, replacement in SHORTER:
        text = re.sub(pattern, replacement, text)
    if len(text) <= width:
        return text
    cut = text[: width - 1].rsplit(" ", 1)[0].rstrip(",;:")
    return cut + "…"


PROVE_WIDTH = 140
"""Characters a line of the default ``fatline prove`` table takes at most (a long obligation name
leaves its reason less room, never fewer than 24 characters)."""


def prove_short_row(r: dict[str, Any], width: int = SHORT_REASON) -> list[str]:
    """One ``results.json`` row as the default table shows it: obligation, verdict, seconds, a short reason."""
    from .prove.tasks import row_key

    return [row_key(r), r["verdict"], f"{r['seconds']:.1f}", short_reason(r["reason"], width)]


def prove_short_rows(results: list[dict[str, Any]]) -> list[list[str]]:
    """Every row as :func:`prove_short_row`, the reasons cut so a line fits :data:`PROVE_WIDTH`."""
    from .prove.tasks import row_key

    key = max((len(row_key(r)) for r in results), default=0)
    verdict = max([len("verdict"), *(len(r["verdict"]) for r in results)])
    seconds = max([len("seconds"), *(len(f"{r['seconds']:.1f}") for r in results)])
    width = max(24, min(SHORT_REASON, PROVE_WIDTH - key - verdict - seconds - 6))
    return [prove_short_row(r, width) for r in results]


def prove_counts(results: list[dict[str, Any]]) -> list[str]:
    """One line per lemma: how many obligations have each verdict, PROVED split by basis (substantive,
    immediate, vacuous: :mod:`fatline_verify.prove.basis`) where the rows record it."""
    from .prove.basis import counts_text

    lines = []
    for lemma in dict.fromkeys(r["lemma"] for r in results):
        rows = [r for r in results if r["lemma"] == lemma]
        mine = [r["verdict"] for r in rows]
        split = f" ({counts_text(rows)})" if any(r.get("basis") for r in rows) else ""
        kinds = dict.fromkeys(sorted(mine))
        counts = ", ".join(f"{mine.count(v)} {v}" + (split if v == "PROVED" else "") for v in kinds)
        lines.append(f"{lemma}: {len(mine)} obligation{'s' if len(mine) != 1 else ''}: {counts}")
    return lines


DECIDED_BY = {
    "search": "the search",
    "corpus": "the shipped counterexample corpus",
    "earlier": "an earlier run's counterexample",
    "given": "--known",
}
"""How the summary names what decided a row (:data:`fatline_verify.prove.corpus.DECIDERS`)."""


def prove_deciders(results: list[dict[str, Any]]) -> list[str]:
    """One line: what decided the VIOLATED rows (a row's ``decided_by``; rows written before it was
    recorded are not counted), none without such a row."""
    got = [str(r["decided_by"]) for r in results if r.get("verdict") == "VIOLATED" and r.get("decided_by")]
    if not got:
        return []
    counts = ", ".join(
        f"{got.count(k)} by {DECIDED_BY.get(k, k)}" for k in dict.fromkeys([*DECIDED_BY, *got]) if k in got
    )
    return [f"VIOLATED decided: {counts} (each replayed by the executable model)"]


def lemma_lines(model: Any, results: list[dict[str, Any]]) -> list[str]:
    """One line per lemma with rows: its lemma-level verdict and why (:mod:`fatline_verify.prove.coverage`);
    under a PROVED, one line for each thing it rests on (obligations, facts assumed, lattice, rounds, solver)."""
    from .prove.coverage import lemma_verdicts

    lines = []
    for v in lemma_verdicts(model, results):
        lines.append(f"{v.lemma}: {v.verdict}: {v.why}")
        lines += [f"    rests on: {line}" for line in v.rests_on]
    return lines


def prove_lines(model: Any, results: list[dict[str, Any]], out: Any, *, verbose: bool = False) -> list[str]:
    """The summary of ``fatline prove``: verdict counts per lemma, then one line per results row:
    obligation, verdict, seconds and a short reason; ``verbose``: every field, the reason in full, the
    trace, and what the ``robots`` column counts."""
    lines = [f"model {model.describe()}", "", "lemmas (from the forms that together imply each):"]
    lines += [f"  {line}" for line in lemma_lines(model, results)]
    lines += ["", "obligations:", *prove_counts(results), *prove_deciders(results), ""]
    if verbose:
        rows = [[*prove_row(r, r.get("trace") or ""), str(r.get("decided_by", ""))] for r in results]
        lines += table([*PROVE_COLUMNS, "decided by"], rows)
        lines += ["", f"Columns: {PROVE_ROBOTS_LEGEND}."]
    else:
        lines += table(PROVE_SHORT_COLUMNS, prove_short_rows(results))
        traces = sorted({str(r["trace"]).rsplit("/", 1)[0] for r in results if r.get("trace")})
        if traces:
            lines += ["", f"counterexample traces in {', '.join(traces)} (fatline replay TRACE -v plays one)"]
        else:
            lines.append("")
        lines.append("each reason in full, each trace and the robots a case names: fatline prove -v (or results.json)")
    lines += ["", f"obligations (SMT-LIB2, each with its any-size argument) and results.json in {out}"]
    return lines
