"""The lemma table in ``properties.py`` is the only place a lemma is named: no other module of the
package spells a lemma name as a string, and the table itself is well formed."""

from __future__ import annotations

import ast
from pathlib import Path

from fatline_verify.cli import prove as cli_prove
from fatline_verify.cli.prove import LEMMA_CHOICES
from fatline_verify.lemmas.properties import CHECKED, FLAG, SAFETY, SPECS, Judged, Lemma
from fatline_verify.model.config import load_model
from fatline_verify.prove import prover
from fatline_verify.prove.prover import LEMMAS
from fatline_verify.prove.tasks import tasks_for
from fatline_verify.report.pages import PROVER_LEMMAS

PACKAGE = Path(__file__).resolve().parent.parent / "fatline_verify"
TABLE = PACKAGE / "lemmas" / "properties.py"
NAMES = {lemma.value for lemma in Lemma}


def _docstrings(tree: ast.Module) -> set[int]:
    """The ids of the docstring nodes: the first statement of the module, a class or a function
    when it is a string expression."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                out.add(id(first.value))
    return out


def literals_in(source: str, where: str) -> list[str]:
    """``where:line: 'name'`` for every string constant of ``source`` equal to a lemma name
    (docstrings aside), in source order."""
    tree = ast.parse(source, filename=where)
    skip = _docstrings(tree)
    hits = [
        node
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in NAMES
        if id(node) not in skip
    ]
    return [f"{where}:{node.lineno}: {node.value!r}" for node in sorted(hits, key=lambda n: (n.lineno, n.col_offset))]


def lemma_literals(path: Path) -> list[str]:
    """The lemma names spelled in one file of the package."""
    return literals_in(path.read_text(encoding="utf-8"), path.relative_to(PACKAGE.parent).as_posix())


REPAIR_NOT_LEMMA = {
    "fatline_verify/prove/replay.py": "approach",
    "fatline_verify/prove/smt/claims.py": "approach",
    "fatline_verify/prove/tasks.py": "approach",
}
"""Files where ``'approach'`` names the repair ``repair_approach`` (its destination's obligations), not the lemma."""


def test_no_lemma_name_outside_the_table():
    found = [
        hit
        for path in sorted(PACKAGE.rglob("*.py"))
        if path != TABLE
        for hit in lemma_literals(path)
        if not hit.endswith(f": {REPAIR_NOT_LEMMA.get(hit.split(':')[0], '')!r}")
    ]
    assert not found, "lemma names spelled outside properties.py (use the Lemma members):\n" + "\n".join(found)


def test_the_scan_sees_literals_and_skips_docstrings():
    source = "\n".join(
        [
            '"""connectivity"""',
            "class C:",
            '    """progress"""',
            "def f():",
            '    """termination"""',
            '    return {"no-collision": f"{1}approach", "x": "rma-fixed"}',
            'g = f"connectivity-edge"',
        ]
    )
    assert literals_in(source, "m.py") == [
        "m.py:6: 'no-collision'",
        "m.py:6: 'approach'",
        "m.py:6: 'rma-fixed'",
        "m.py:7: 'connectivity-edge'",
    ]


def test_checked_lemmas_in_report_order():
    assert [lemma.value for lemma in CHECKED] == [
        "connectivity",
        "no-collision",
        "progress",
        "rma-fixed",
        "approach",
        "termination",
    ]
    assert Lemma.CONNECTIVITY_EDGE not in CHECKED
    assert not SPECS[Lemma.CONNECTIVITY_EDGE].checked
    assert set(SPECS) == set(Lemma)


def test_safety_flags_are_distinct_bits():
    assert SAFETY
    assert all(SPECS[lemma].judged is Judged.STEP for lemma in SAFETY)
    flags = [FLAG[lemma] for lemma in SAFETY]
    assert all(f > 0 and f & (f - 1) == 0 for f in flags), flags
    assert len(set(flags)) == len(flags), flags
    assert set(FLAG) == set(SAFETY)
    assert all(lemma.flag == FLAG[lemma] for lemma in SAFETY)


def test_prover_lemmas_named_alike():
    """The CLI's ``--lemma`` choices and the report's prover columns name the lemmas the prover makes
    obligations for (one z3-free tuple): every one of them has obligations for the paper's rules, and
    no obligation is of a lemma outside it."""
    assert LEMMA_CHOICES == LEMMAS == PROVER_LEMMAS
    made = {task.lemma for task in tasks_for(load_model("paper"), LEMMAS)}
    assert made == set(LEMMAS), made
    assert {task.lemma for task in tasks_for(load_model("paper"), tuple(Lemma))} <= set(LEMMAS)


def test_prover_defaults_named_alike():
    """The CLI's prover defaults (named without importing z3) are the prover's."""
    assert (cli_prove.DEFAULT_SLOTS, cli_prove.DEFAULT_TIMEOUT) == (prover.DEFAULT_SLOTS, prover.DEFAULT_TIMEOUT)
