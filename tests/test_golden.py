"""The golden corpus: each shipped model file carries the verdicts `fatline check` gives at its own
bounds; a change of behaviour shows up here."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fatline_verify.model.config import load_model, shipped_models
from fatline_verify.rules import registry
from tests.test_cli import run_cli

BENCH = sorted((Path(__file__).resolve().parent.parent / "bench").glob("*.toml"))
"""Models kept out of models/ (not shipped) that carry golden verdicts too."""


SLOW = {"gravity", "universal"}
"""Models whose golden run takes half a minute or more: 4 robots whose moves leave the lattice, searched
by the scalar engine (docs/published/); the slow tier runs them."""


def _golden(path: Path) -> object:
    return pytest.param(path, marks=pytest.mark.slow) if path.stem in SLOW else path


@pytest.mark.parametrize("path", [_golden(p) for p in shipped_models() + BENCH], ids=lambda p: p.stem)
def test_shipped_model_verdicts(capsys, tmp_path, path):
    model = load_model(path)
    assert set(model.expected) == {lemma.value for lemma in registry.of(model).applies()}  # its own setting's
    out_json = tmp_path / "r.json"
    run_cli(capsys, "check", str(path), "--json", str(out_json), "--traces", str(tmp_path / "t"), "-q")
    data = json.loads(out_json.read_text())
    rank = {"VIOLATED": 0, "INCONCLUSIVE": 1, "HOLDS_WITHIN_BOUNDS": 2, "PROVED": 3}
    worst: dict[str, str] = {}
    for row in data["lemmas"]:
        if row["lemma"] not in worst or rank[row["verdict"]] < rank[worst[row["lemma"]]]:
            worst[row["lemma"]] = row["verdict"]
    extra = {k: v for k, v in worst.items() if k not in model.expected}  # registered step lemmas (in-family)
    assert {k: v for k, v in worst.items() if k in model.expected} == model.expected
    assert all(v == "HOLDS_WITHIN_BOUNDS" for v in extra.values()), extra  # a shipped rule set stays in its family
