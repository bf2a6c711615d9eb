"""What ``fatline sweep`` prints of a sweep: the table of counts per lemma and one headline each."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lemmas.properties import Lemma

if TYPE_CHECKING:
    from .run import Sweep


def sweep_lines(sweep: Sweep) -> list[str]:
    """What ``fatline sweep`` prints: per lemma the headline, then the table and the witnesses."""
    b = sweep.bounds
    lo, hi = b.robots
    robots = str(lo) if lo == hi else f"{lo}..{hi}"
    lines = [
        f"sweep of {sweep.space.base.describe()}",
        f"varied: {', '.join(sweep.space.names)}; each combination checked at robots {robots}, "
        f"window {b.window[0]}x{b.window[1]}" + (f", bound {b.bound[0]}x{b.bound[1]}" if b.bound else ""),
        "",
    ]
    rows = [("lemma", "readings", "refuted", "holds", "inconclusive", "open", "counterexamples")]
    for lemma in sweep.lemmas:
        s = sweep.lemma_summary(lemma)
        rows.append((lemma.value, f"{s['combinations']:,}", f"{s['refuted']:,}", f"{s['holds']:,}",
                     f"{s['inconclusive']:,}", f"{s['open']:,}", str(s["counterexamples"])))  # fmt: skip
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
    for r in rows:
        lines.append(
            "  ".join(c.ljust(w) if k == 0 else c.rjust(w) for k, (c, w) in enumerate(zip(r, widths, strict=True)))
        )
    lines.append("")
    for lemma in sweep.lemmas:
        lines.append(headline(sweep, lemma))
    lines.append("")
    lines.append(f"{len(sweep.checks)} checks, {sweep.replays:,} replays; results in {sweep.json_path}")
    return lines


def headline(sweep: Sweep, lemma: Lemma) -> str:
    """One sentence: refuted under every reading by k counterexamples, or where it survives."""
    s = sweep.lemma_summary(lemma)
    n, k = s["combinations"], s["counterexamples"]
    by = f"by {k} counterexample{'s' if k != 1 else ''}"
    if s["refuted"] == n:
        return f"{lemma.value}: refuted under all {n:,} readings {by}"
    parts = []
    if s["holds"]:
        parts.append(f"holds within bounds under {s['holds']:,}")
    if s["inconclusive"]:
        parts.append(f"inconclusive under {s['inconclusive']:,}")
    if s["refuted"]:
        parts.append(f"refuted under {s['refuted']:,} {by}")
    if s["open"]:
        parts.append(f"{s['open']:,} not judged yet (rerun to go on)")
    return f"{lemma.value}: of {n:,} readings, " + "; ".join(parts)
