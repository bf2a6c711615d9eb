"""Human text rendered from data: traces, decisions, violations, the option catalogue.

The engine never prints; the CLI prints what these functions return.
"""

from __future__ import annotations

from typing import Any

from .config import Model
from .options import CATALOGUE, Options


def _pt(p: list[Any]) -> str:
    return f"({p[0]}, {p[1]})"


def violation_line(v: dict[str, Any]) -> str:
    """One line for a violation record of a trace."""
    prop = v["property"]
    robots = " ".join(f"r{i}" for i in v["robots"])
    if prop == "no-collision":
        how = "both moving" if v.get("both_moved") else "one moving"
        closest = v["closest_distance2"]
        return f"{prop}: {robots} collide ({how}); closest squared centre distance {closest} (discs touch at 4)"
    if prop == "connectivity":
        edges = ", ".join(
            f"r{a}-r{b} (distance^2 {d})" for (a, b), d in zip(v["lost_edges"], v["distance2_after"], strict=True)
        )
        comps = " | ".join(" ".join(f"r{i}" for i in c) for c in v["components"])
        return f"{prop}: visibility graph split into {comps}; lost {edges}"
    if prop == "rma-fixed":
        return f"{prop}: {robots} went from the right-most axis x={v['rma_x']} to x={v['x_after']}"
    if prop == "connectivity-edge":
        (a, b), d2 = v["robots"], v["distance2_after"][0]
        return f"{prop}: r{a} and r{b} no longer see each other (distance^2 {d2}); the graph stays connected"
    if prop == "progress":
        return f"{prop}: deadlock: no robot is enabled and the robots are not on a line"
    if prop == "termination":
        return f"{prop}: this execution never forms the line (a deadlock or a fair cycle)"
    if prop == "approach":
        return f"{prop}: {robots} left of the right-most axis never move right again"
    return f"{prop}: {robots}"


_CASE_NOTE = {
    "scenario-2": " (Scenario 2's search found no vacant point)",
    "scenario-3": " (Scenario 3's search found no vacant point)",
    "uncovered": " (a case Scenarios 1-3 leave out)",
}


def trace_lines(doc: dict[str, Any]) -> list[str]:
    """The rounds of a trace document, one block per round, and its outcome."""
    lines = ["start: " + "  ".join(f"r{i} {_pt(p)}" for i, p in enumerate(doc["initial"]))]
    for k, rnd in enumerate(doc["rounds"], start=1):
        lines.append(f"round {k}: active " + " ".join(f"r{i}" for i in rnd["active"]))
        for d in rnd["decisions"]:
            psi = f", psi_right x={d['psi']}" if d.get("psi") is not None else ""
            case = _CASE_NOTE.get(d.get("case") or "", "") if d["rule"].startswith(("scenario-4", "uncovered")) else ""
            lines.append(f"  r{d['robot']} {d['rule']}{case} -> {_pt(d['destination'])}{psi}")
        lines.append("  now: " + "  ".join(f"r{i} {_pt(p)}" for i, p in enumerate(rnd["positions"])))
        for v in rnd["violations"]:
            lines.append("  VIOLATED " + violation_line(v))
    n = len(doc["rounds"])
    tail = {
        "goal": f"goal reached: the robots form a line ({doc['model']['options'].get('goal', 'vertical-line')})",
        "deadlock": "deadlock: no robot is enabled and the robots do not form a line",
        "violation": "stopped at a violation",
        "round-limit": "round limit reached: neither the goal, a deadlock nor a violation",
        "cycle": "a fair cycle: the loop below repeats forever without forming the line",
    }[doc["outcome"]]
    lines.append(f"outcome after {n} round{'s' if n != 1 else ''}: {tail}")
    if doc.get("loop_start") is not None:
        lines.append(f"the rounds after round {doc['loop_start']} repeat forever (the swarm returns, translated)")
    if doc.get("violation"):
        lines.append("witnesses " + violation_line(doc["violation"]))
    return lines


def explain_lines(name: str | None = None, model: Model | None = None) -> list[str]:
    """The catalogue (or one option): the quote, every reading, the default, the model's choice."""
    chosen = (model.options if model else Options()).as_dict()
    names = [name] if name else list(CATALOGUE)
    lines: list[str] = []
    for n in names:
        spec = CATALOGUE[n]
        lines.append(f"{n}")
        lines.append(f'  paper: "{spec.quote}"')
        for reading, meaning in spec.readings.items():
            marks = []
            if reading == spec.default.value:
                marks.append("default")
            if model is not None and chosen[n] == reading:
                marks.append(f"model {model.name}")
            tag = f" [{', '.join(marks)}]" if marks else ""
            pointer = "*" if chosen[n] == reading else " "
            lines.append(f"  {pointer} {reading}{tag}: {meaning}")
        if spec.note:
            lines.append(f"  note: {spec.note}")
        lines.append("")
    return lines[:-1] if lines else lines


def table(headers: list[str], rows: list[list[str]]) -> list[str]:
    """A plain-text table with aligned columns."""
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    line = "  ".join(h.ljust(w) for h, w in zip(headers, widths, strict=True)).rstrip()
    out = [line, "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
    return out


def check_lines(result: Any, trace_paths: dict[tuple[str, int], str]) -> list[str]:
    """The summary of a :class:`fatline_verify.checker.CheckResult`."""
    from .properties import Lemma

    model = result.model
    w, h = result.window
    lines = [
        f"model {model.describe()}",
        f"window {w}x{h} lattice points, at most {result.max_states} states per robot count",
    ]
    lines.append("")
    rows = []
    for s in result.stats:
        rows.append(
            [
                str(s.robots),
                str(s.initial),
                str(s.states),
                str(s.transitions),
                str(s.escaped),
                str(s.violating_only),
                "yes" if s.truncated else "no",
                f"{s.seconds:.2f}",
                s.engine,
            ]
        )
    lines += table(
        ["robots", "initial", "states", "transitions", "escaped", "violating-only", "truncated", "seconds", "engine"],
        rows,
    )
    lines.append("")
    rows = []
    for lemma in Lemma:
        for r in (x for x in result.results if x.lemma is lemma):
            trace = trace_paths.get((lemma.value, r.robots), "")
            witness = "" if r.witness_rounds is None else f"{r.witness_rounds} rounds"
            rows.append([lemma.value, str(r.robots), r.verdict.value, witness, r.reason, trace])
    lines += table(["lemma", "robots", "verdict", "witness", "detail", "trace"], rows)
    lines.append("")
    if result.after_violation == "stop":
        lines.append(
            "States reached only through a violating round are not explored further; liveness verdicts are over "
            "executions that break no safety lemma."
        )
    else:
        lines.append("States reached through violating rounds are explored further (--after-violation continue).")
    return lines


def prove_lines(model: Any, results: list[dict[str, Any]], out: Any) -> list[str]:
    """The summary of ``fatline prove``: one line per results row."""
    rows = [
        [
            r["lemma"],
            r["form"],
            r["rule"],
            r["verdict"],
            str(r["slots"]),
            f"{r['seconds']:.1f}",
            r["reason"],
            r.get("trace") or "",
        ]
        for r in results
    ]
    lines = [f"model {model.describe()}", ""]
    lines += table(["lemma", "form", "rule", "verdict", "slots", "seconds", "detail", "trace"], rows)
    lines += ["", f"obligations (SMT-LIB2, each with its any-size argument) and results.json in {out}"]
    return lines
