"""A published rule set is usable as a plug-in would be: an installed package (a ``fatline.plugins`` entry
point, a fresh interpreter) registers Ando et al.'s rule from the same ``decide``, parameters and
setting, and ``fatline check`` gives it the verdicts the built-in ``ando`` model gets."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

PLUGIN = '''"""Ando et al. (1999) registered from an installed package, as a user would."""
from fatline_verify.rules.published.ando import ANDO, decide
from fatline_verify.rules.registry import RuleSet, register

register(RuleSet("ando-plugin", decide, "Ando et al. 1999, from a plug-in package.", labels=dict(ANDO.labels),
                 lemmas=ANDO.lemmas, parameters=dict(ANDO.parameters), goal=ANDO.goal, robots=ANDO.robots))
'''


def _site(root: Path) -> Path:
    site = root / "site"
    (site / "ando_plugin").mkdir(parents=True)
    (site / "ando_plugin" / "__init__.py").write_text(PLUGIN)
    info = site / "ando_plugin-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: ando-plugin\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text("[fatline.plugins]\nando-plugin = ando_plugin\n")
    return site


def _verdicts(argv: list[str], site: Path, out: Path) -> list[tuple[str, int, str]]:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")])}
    got = subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", "check", *argv, "--json", str(out), "-q", "--traces",
         str(out.parent / out.stem)],
        capture_output=True, text=True, env=env,
    )  # fmt: skip
    assert got.returncode in (0, 1, 3), got.stderr
    rows = json.loads(out.read_text())["lemmas"]
    return sorted((r["lemma"], r["robots"], r["verdict"]) for r in rows)


def test_ando_from_an_installed_package_gets_the_built_in_verdicts(tmp_path: Path) -> None:
    from fatline_verify.model.config import load_model

    site = _site(tmp_path)
    shipped = load_model("ando")
    text = Path(shipped.source).read_text().replace('rules = "ando"', 'rules = "ando-plugin"')
    model = tmp_path / "ando-plugin.toml"
    model.write_text(text.replace('name = "ando"', 'name = "ando-plugin"'))
    built_in = _verdicts(["ando", "--robots", "2"], site, tmp_path / "built-in.json")
    plugged = _verdicts([str(model), "--robots", "2"], site, tmp_path / "plugin.json")
    assert plugged == built_in
    assert {lemma for lemma, _, _ in plugged} == set(shipped.expected)
