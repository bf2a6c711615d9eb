"""The figures the README and docs/prover.md quote from the committed rows are today's
(:mod:`fatline_verify.prove.figures`): a re-proof that changes a count, or an edit of the text, is red
here until the two agree again."""

from __future__ import annotations

from pathlib import Path

import pytest

from fatline_verify.prove.figures import CLAIMS, figures, flat, main, prove_table

ROOT = Path(__file__).resolve().parent.parent
PROOFS = ROOT / "proofs"


@pytest.mark.parametrize("where, template", CLAIMS, ids=[t[:40] for _, t in CLAIMS])
def test_a_quoted_figure_is_the_committed_rows(where, template):
    said = template.format(**figures(PROOFS))
    assert flat(said) in flat((ROOT / where).read_text(encoding="utf-8")), (
        f"{where} no longer says: {said!r} (the figures of proofs/*/results.json; python -m "
        "fatline_verify.prove.figures prints every one)"
    )


def test_the_prover_table_is_the_committed_rows():
    table = "\n".join(prove_table(PROOFS))
    assert table in (ROOT / "docs" / "prover.md").read_text(encoding="utf-8"), (
        "docs/prover.md's table is not the committed rows': paste python -m fatline_verify.prove.figures"
    )


def test_the_figures_follow_the_rows(tmp_path):
    """Honest, not fixed: one row more, one VIOLATED, moves the counts it belongs to."""
    import json
    import shutil

    shutil.copytree(PROOFS / "repaired", tmp_path / "repaired")
    path = tmp_path / "repaired" / "results.json"
    data = json.loads(path.read_text())
    data["obligations"][0] = {**data["obligations"][0], "verdict": "VIOLATED"}
    path.write_text(json.dumps(data))
    before, after = figures(PROOFS), figures(tmp_path)
    assert after["repaired_proved"] == before["repaired_proved"] - 1 and after["repaired_violated"] == 1
    assert main([str(tmp_path / "none")]) == 2
