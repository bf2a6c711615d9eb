"""The prover's results as text: the ``fatline prove`` summary (verdict counts per lemma, what decided
each, a table of rows with short reasons) and the per-obligation rows the report pages show.

Rendered from the rows of ``results.json`` (:mod:`.results`); the engine never prints.
"""

from __future__ import annotations

import re
from typing import Any

from ..text import table

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
    from .tasks import row_key

    return [row_key(r), r["verdict"], f"{r['seconds']:.1f}", short_reason(r["reason"], width)]


def prove_short_rows(results: list[dict[str, Any]]) -> list[list[str]]:
    """Every row as :func:`prove_short_row`, the reasons cut so a line fits :data:`PROVE_WIDTH`."""
    from .tasks import row_key

    key = max((len(row_key(r)) for r in results), default=0)
    verdict = max([len("verdict"), *(len(r["verdict"]) for r in results)])
    seconds = max([len("seconds"), *(len(f"{r['seconds']:.1f}") for r in results)])
    width = max(24, min(SHORT_REASON, PROVE_WIDTH - key - verdict - seconds - 6))
    return [prove_short_row(r, width) for r in results]


def prove_counts(results: list[dict[str, Any]]) -> list[str]:
    """One line per lemma: how many obligations have each verdict, PROVED split by basis (substantive,
    immediate, vacuous: :mod:`fatline_verify.prove.basis`) where the rows record it."""
    from .basis import counts_text

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
    from .coverage import lemma_verdicts

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
    lines += [
        "",
        f"results.json in {out}; every obligation as SMT-LIB2, each with its any-size argument: "
        f"fatline prove {model.name} --emit DIR",
    ]
    return lines
