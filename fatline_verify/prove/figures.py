"""The figures the README and ``docs/prover.md`` quote from the prover's committed rows, computed from
``proofs/MODEL/results.json``: ``python -m fatline_verify.prove.figures [PROOFS]`` prints the table of
``docs/prover.md`` and every quoted sentence with today's figures; ``tests/test_figures.py`` holds the
documents to them, so a figure cannot drift from the rows it quotes.

Each sentence (:data:`CLAIMS`) is a template over :func:`figures`; a document holds it when the
formatted sentence is in it, line breaks and runs of spaces counting as one space.
"""

from __future__ import annotations

import json
import statistics
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma

LIVENESS = (str(Lemma.PROGRESS), str(Lemma.TERMINATION))
"""The lemmas of the liveness rows (the rest are the safety lemmas' rows: per case, per leg, global)."""


def _rows(proofs: Path, model: str) -> list[dict[str, Any]]:
    path = proofs / model / "results.json"
    return list(json.loads(path.read_text(encoding="utf-8"))["obligations"]) if path.is_file() else []


def _verdicts(rows: list[dict[str, Any]], prefix: str) -> dict[str, int]:
    """``PREFIX`` (how many), ``PREFIX_proved`` … ``PREFIX_inconclusive`` and the PROVED rows' bases."""
    verdicts = Counter(r["verdict"] for r in rows)
    bases = Counter(r.get("basis", "") for r in rows if r["verdict"] == "PROVED")
    out = {prefix: len(rows)}
    for verdict in ("PROVED", "VIOLATED", "INCONCLUSIVE"):
        out[f"{prefix}_{verdict.lower()}"] = verdicts[verdict]
    for basis in ("substantive", "immediate", "vacuous"):
        out[f"{prefix}_{basis}"] = bases[basis]
    return out


def figures(proofs: Path) -> dict[str, int]:
    """Every figure a :data:`CLAIMS` sentence names, from the rows under ``proofs``."""
    paper, repaired = _rows(proofs, "paper"), _rows(proofs, "repaired")
    every = [r for p in sorted(proofs.glob("*/results.json")) for r in _rows(proofs, p.parent.name)]
    open_rows = [r for r in every if r["verdict"] == "INCONCLUSIVE" and r["form"] != "coverage"]
    out: dict[str, int] = {}
    out |= _verdicts([r for r in paper if r["lemma"] not in LIVENESS], "paper_cases")
    out |= _verdicts([r for r in paper if r["form"] == "enabled"], "paper_enabled")
    out |= _verdicts([r for r in paper if r["form"] == "measure"], "paper_measure")
    out |= _verdicts(repaired, "repaired")
    out |= _verdicts([r for r in repaired if r["form"] in ("leg", "kept", "bridged")], "repaired_legs")
    out["open"] = len(open_rows)
    out["open_enabled"] = sum(r["form"] == "enabled" for r in open_rows)
    out["open_solution"] = sum(r["reason"].startswith("a solution exists") for r in open_rows)
    out["open_clock"] = sum("stopped by the wall clock" in r["reason"] for r in open_rows)
    out["certificates"] = sum(bool(r.get("certificate_sha256")) for r in every)
    out |= stales(proofs)
    return out


STALES = {
    "stales_repaired_rules": "rules/repaired/algorithm.py",
    "stales_repaired_family": "rules/repaired/family.py",
    "stales_family_builder": "prove/smt/family.py",
    "stales_family_language": "rules/family/lang.py",
    "stales_liveness": "prove/smt/liveness.py",
    "stales_refine": "prove/refine.py",
    "stales_claims": "prove/smt/claims.py",
    "stales_search": "prove/search.py",
    "stales_paper_rules": "rules/paper/algorithm.py",
}
"""Source files (under the package) whose committed dependants ``docs/prover.md`` counts."""


def stales(proofs: Path) -> dict[str, int]:
    """``rows``: the committed rows; per :data:`STALES` file, how many of them an edit to its code stales
    (the rows whose sources, :func:`fatline_verify.prove.digests.kind_sources`, include it)."""
    from ..model.config import load_model
    from .digests import ROOT, kind_of, kind_sources
    from .tasks import row_key, task_key, tasks_for

    counts = dict.fromkeys(STALES, 0)
    total = 0
    for path in sorted(proofs.glob("*/results.json")):
        model = load_model(path.parent.name)
        tasks = {task_key(t): t for t in tasks_for(model, two_movers=True)}
        for row in _rows(proofs, path.parent.name):
            total += 1
            sources = {p.relative_to(ROOT).as_posix() for p in kind_sources(kind_of(tasks[row_key(row)]), model)}
            for name, file in STALES.items():
                counts[name] += file in sources
    return {"rows": total, **counts}


CLAIMS: tuple[tuple[str, str], ...] = (
    (
        "README.md",
        "**Of its {paper_cases} per-case obligations, {paper_cases_violated} VIOLATED and {paper_cases_proved} "
        "PROVED: {paper_cases_substantive} substantive, {paper_cases_immediate} immediate**",
    ),
    ("README.md", "**and {paper_cases_vacuous} vacuous** (the case never fires)"),
    (
        "README.md",
        "moves in {paper_enabled_proved} of {paper_enabled} cases (PROVED); in NoMovement's only-A-or-I case it "
        "does not",
    ),
    ("README.md", "{paper_enabled_inconclusive} cases stay open"),
    ("README.md", "Every move of the {paper_measure_proved} moving cases makes the measure"),
    (
        "README.md",
        "{repaired_legs} family obligations ({repaired_legs_substantive} substantive",
    ),
    (
        "README.md",
        "{repaired} obligations, {repaired_proved} PROVED: {repaired_substantive} substantive, "
        "{repaired_immediate} immediate, {repaired_vacuous} vacuous",
    ),
    (
        "README.md",
        "nothing in the shipped `proofs/` is INCONCLUSIVE but {open} enabledness rows of Scenario 4 with I non-empty "
        "({open_solution} have a solution over the reals that no lattice or small-swarm configuration replays; "
        "{open_clock} were stopped by the wall clock",
    ),
    ("README.md", "`python -m fatline_verify.prove.certify proofs` ({certificates} certificates,"),
    (
        "docs/prover.md",
        "What an edit to a file's code stales, of the {rows} committed rows: `rules/repaired/algorithm.py` "
        "{stales_repaired_rules} (the repaired model's); `rules/repaired/family.py` {stales_repaired_family} and "
        "the family language `rules/family/lang.py` {stales_family_language} (every row of a model whose rule set "
        "declares a family: its replays hold each decision to it); `prove/smt/family.py` {stales_family_builder} "
        "(the family rows); `prove/smt/liveness.py` {stales_liveness} (the liveness rows); `prove/refine.py` "
        "{stales_refine} (the coverage rows); `prove/smt/claims.py` {stales_claims} (the per-case rows); the shared "
        "search (`prove/search.py`) {stales_search} and the paper's rules (`rules/paper/algorithm.py`, which every "
        "per-case obligation encodes) {stales_paper_rules}.",
    ),
)
"""Each sentence of a document that quotes the committed rows, as a template over :func:`figures`."""


def prove_table(proofs: Path) -> list[str]:
    """``docs/prover.md``'s table: per model its rows, their verdicts (PROVED split by basis) and the median
    and largest solver seconds."""
    rows = []
    for path in sorted(proofs.glob("*/results.json")):
        got = _rows(proofs, path.parent.name)
        v = _verdicts(got, "m")
        seconds = [float(r["seconds"]) for r in got]
        rows.append(
            [
                path.parent.name,
                str(len(got)),
                f"{v['m_proved']} ({v['m_substantive']}/{v['m_immediate']}/{v['m_vacuous']})",
                str(v["m_violated"]),
                str(v["m_inconclusive"]),
                f"{statistics.median(seconds):.2f}",
                f"{max(seconds):.2f}",
            ]
        )
    head = ["model", "rows", "PROVED (subst./immed./vac.)", "VIOLATED", "INCONCL.", "median s", "max s"]
    return [f"| {' | '.join(cells)} |" for cells in (head, ["---"] * len(head), *rows)]


def flat(text: str) -> str:
    """``text`` with every run of whitespace one space (a sentence may break across lines)."""
    return " ".join(text.split())


def main(argv: list[str] | None = None) -> int:
    """Print the table and every claim with today's figures (exit 0), or name a missing directory (exit 2)."""
    args = sys.argv[1:] if argv is None else argv
    proofs = Path(args[0] if args else "proofs")
    if not proofs.is_dir():
        print(
            f"fatline: figures: {proofs.as_posix()}: no such directory; expected a directory of proofs", file=sys.stderr
        )
        return 2
    print("\n".join(prove_table(proofs)))
    got = figures(proofs)
    for where, template in CLAIMS:
        print(f"{where}: {template.format(**got)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
