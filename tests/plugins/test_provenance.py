"""Issue 37, hole 5: the caches are named by the sources that decide for a model, a plug-in's too
(:mod:`fatline_verify.provenance`). An edited plug-in is a new answers file, a new check fingerprint
and a new prover fingerprint; a built-in model's fingerprints stay the committed ones."""

from __future__ import annotations

import functools
import json
import os
import shutil
import subprocess
import sys
import types
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from fatline_verify import provenance
from fatline_verify.cache import fingerprint
from fatline_verify.check import answers
from fatline_verify.check.checker import CHECKER_VERSION, check_fingerprint
from fatline_verify.lemmas.registry import judged
from fatline_verify.model.config import Model, load_model
from fatline_verify.prove.digests import row_digest
from fatline_verify.prove.tasks import GlobalTask

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
SITE = HERE / "site"
MODEL = HERE / "toy-step.toml"
CLEAR = " and all(_clear(c, rho) for c in snapshot)"
"""The toy's condition that the way is clear: the edit removes it, and the toy steps into a collision."""


def prove_fingerprint(model: Model, slots: int, timeout: float) -> str:
    """The fingerprint of ``model``'s global-form row (:func:`fatline_verify.prove.digests.row_digest`)."""
    return row_digest(model, GlobalTask(), slots=slots, timeout=timeout)


def _committed(kind: str) -> dict[str, str]:
    """The fingerprint each committed ``reports/NAME/check.json`` or ``proofs/NAME/results.json`` carries."""
    where, name = {"check": ("reports", "check.json"), "prove": ("proofs", "results.json")}[kind]
    return {p.parent.name: json.loads(p.read_text())["fingerprint"] for p in sorted((ROOT / where).glob(f"*/{name}"))}


def test_the_built_in_models_keep_their_committed_fingerprints() -> None:
    """No plug-in decides for a built-in model: its plug-in digest is empty, no ``plugins`` setting is
    added, and its check fingerprints are the ones the committed reports carry (its prove rows' are held
    to the current code row by row: ``tests/test_digests.py``)."""
    checks = _committed("check")
    assert len(checks) >= 9
    for name, committed in checks.items():
        model = load_model(name)
        assert provenance.plugin_digest(model) == "" and provenance.plugin_settings(model) == {}
        own = {lemma.name: lemma.version for lemma in judged(model)}  # this package's in-family, for a family
        expected = fingerprint(model, "check", engine=CHECKER_VERSION, **({"lemmas": own} if own else {}))
        assert check_fingerprint(model) == committed == expected, name


def test_a_plugin_digest_is_in_every_fingerprint_when_there_is_one(monkeypatch: pytest.MonkeyPatch) -> None:
    """The other side of the test above: the fingerprints do read the plug-in digest when it is not empty."""
    model = load_model("paper")
    monkeypatch.setenv(answers.ENV, "/nowhere")
    before = (check_fingerprint(model), prove_fingerprint(model, 3, 5.0), answers.answers_path(model, 3))
    monkeypatch.setattr(provenance, "plugin_digest", lambda m: "0" * 64)
    after = (check_fingerprint(model), prove_fingerprint(model, 3, 5.0), answers.answers_path(model, 3))
    assert all(a != b for a, b in zip(before, after, strict=True)) and None not in after
    assert answers.answers_path(model, 3) == after[2]  # the same name on every call
    monkeypatch.setenv(answers.ENV, "off")
    assert answers.answers_path(model, 3) is None


@pytest.fixture
def site(tmp_path: Path) -> Path:
    """A copy of the toy plug-in package (with its ``.dist-info``) to edit."""
    copy = tmp_path / "site"
    shutil.copytree(SITE, copy, ignore=shutil.ignore_patterns("__pycache__"))
    return copy


def _edit(site: Path) -> None:
    """The toy no longer looks whether its way is clear (it steps into robots)."""
    path = site / "toy_fatline_plugin" / "__init__.py"
    text = path.read_text()
    assert CLEAR in text
    path.write_text(text.replace(CLEAR, ""))


def test_the_digest_follows_the_plugin_s_files_and_nothing_else(
    site: Path, install_site: Callable[[Path], None]
) -> None:
    install_site(site)
    toy, paper = load_model(MODEL), load_model("paper")
    first = provenance.plugin_digest(toy)
    assert len(first) == 64 and provenance.reusable(first)
    assert provenance.plugin_digest(toy) == first
    names = {what: provenance._module_of(obj) for what, obj in provenance.deciders(toy)}
    assert names == {
        "rules": "toy_fatline_plugin",
        "lemma no-left": "toy_fatline_plugin.lemma",
        "lemma no-down": "toy_fatline_plugin.down",
    }
    # the plug-in's lemma decides for a built-in model too
    assert provenance.plugin_digest(paper) not in ("", first)
    # files outside the plug-in's package: its .dist-info, a module beside it
    (site / "toy_fatline_plugin-0.1.dist-info" / "METADATA").write_text("Metadata-Version: 2.1\nName: other\n")
    (site / "beside.py").write_text("X = 1\n")
    assert provenance.plugin_digest(toy) == first
    # a file of the package that no deciding object is defined in still counts (it may be imported)
    (site / "toy_fatline_plugin" / "helpers.py").write_text("Y = 2\n")
    second = provenance.plugin_digest(toy)
    assert second != first
    _edit(site)
    third = provenance.plugin_digest(toy)
    assert third not in (first, second)
    assert provenance.model_digest(toy) != provenance.model_digest(paper)


def _careful(snapshot: Any, model: Model) -> Any:
    """A rule of this file: the toy's step (a model's own replacement of its rule set)."""
    from fatline_verify.rules.paper.algorithm import Decision

    rho = model.radius
    if any(c[0] >= 3 * rho for c in snapshot):
        return Decision("step", (rho, 0), ((0, 0), (rho, 0)), ())  # type: ignore[arg-type]  # a plug-in's label
    return Decision("stay", (0, 0), ((0, 0),), ())  # type: ignore[arg-type]


def _stay(snapshot: Any, model: Model) -> Any:
    """Another rule of this file."""
    return _careful([], model)


def test_a_model_s_own_rule_is_digested_by_its_module_and_name() -> None:
    """``model.algorithm`` defined in a module with a file: a stable digest, and two functions of the
    same file differ (the name counts beside the bytes)."""
    base = load_model("paper")
    careful, stay = replace(base, algorithm=_careful), replace(base, algorithm=_stay)
    digest = provenance.plugin_digest(careful)
    assert provenance.reusable(digest) and digest == provenance.plugin_digest(careful)
    assert provenance.plugin_digest(stay) not in ("", digest)


def _closure(step: int) -> Callable[[Any, Model], Any]:
    def decide(snapshot: Any, model: Model) -> Any:
        return _careful(snapshot, model) if step else _stay(snapshot, model)

    return decide


def _no_file(monkeypatch: pytest.MonkeyPatch) -> Callable[[Any, Model], Any]:
    """A rule defined in an imported module without a file, as in a REPL."""
    module = types.ModuleType("repl_like_rules")
    exec("def decide(snapshot, model):\n    return None\n", module.__dict__)
    monkeypatch.setitem(sys.modules, module.__name__, module)
    return module.decide  # type: ignore[no-any-return]


RULES: dict[str, Callable[[pytest.MonkeyPatch], Callable[[Any, Model], Any]]] = {
    "closure": lambda _: _closure(1),
    "partial": lambda _: functools.partial(_careful),
    "no-file": _no_file,
}


@pytest.mark.parametrize("kind", RULES)
def test_a_rule_its_source_does_not_fix_is_never_reused(
    kind: str, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """A closure, a partial or a function without a source file: a new token on every call, so no
    fingerprint matches twice and the compiled engine keeps no answers."""
    rule = RULES[kind](monkeypatch)
    model = replace(load_model("paper"), algorithm=rule)
    one, two = provenance.plugin_digest(model), provenance.plugin_digest(model)
    assert one.startswith(provenance.UNREADABLE) and not provenance.reusable(one) and one != two
    assert check_fingerprint(model) != check_fingerprint(model)
    assert prove_fingerprint(model, 3, 5.0) != prove_fingerprint(model, 3, 5.0)
    monkeypatch.setenv(answers.ENV, str(tmp_path))
    assert answers.answers_path(model, 3) is None
    assert answers.answers_path(load_model("paper"), 3) is not None


def test_a_disagreement_on_kept_answers_says_they_may_be_stale(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """The witness replay's "recorded ..., replayed ..." names the kept answers and FATLINE_ANSWERS=off,
    in the same line, when the compiled engine had a file of them; otherwise the message is as it was."""
    from fatline_verify.check.witness import EngineDisagreement, _kept_answers_named
    from fatline_verify.errors import TraceDidNotReproduce

    model = load_model("paper")
    ex = types.SimpleNamespace(model=model, n=3, engine="compiled")
    said = 'outcome: recorded "violation", replayed "deadlock"'
    monkeypatch.setenv(answers.ENV, str(tmp_path))
    kept_file = answers.answers_path(model, 3)
    assert kept_file is not None
    for engine, kept, exc in (("compiled", False, TraceDidNotReproduce), ("fast", True, EngineDisagreement)):
        ex.engine = engine
        if kept:
            kept_file.parent.mkdir(parents=True, exist_ok=True)
            kept_file.write_bytes(b"x")
        with pytest.raises(exc) as plain, _kept_answers_named(ex):  # type: ignore[arg-type]
            raise exc(said)
        assert str(plain.value) == said
    ex.engine = "compiled"
    with pytest.raises(TraceDidNotReproduce) as named, _kept_answers_named(ex):  # type: ignore[arg-type]
        raise TraceDidNotReproduce(said)
    assert str(named.value) == (
        f"{said}; the compiled engine's answers kept between runs ({kept_file.as_posix()}) may be stale: run again "
        "with FATLINE_ANSWERS=off to check without them"
    )
    assert "\n" not in str(named.value)
    monkeypatch.setenv(answers.ENV, "off")
    with pytest.raises(TraceDidNotReproduce) as off, _kept_answers_named(ex):  # type: ignore[arg-type]
        raise TraceDidNotReproduce(said)
    assert str(off.value) == said


# --- through the command line, the plug-in installed and edited between runs ----------------------


def _fatline(site: Path, cache: str, *argv: str) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter with ``site`` installed and ``FATLINE_ANSWERS=cache``."""
    path = os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")])
    env = {**os.environ, "PYTHONPATH": path, answers.ENV: cache}
    return subprocess.run([sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env)


def _rows(path: Path) -> dict[tuple[str, int], tuple[str, str, int | None]]:
    """A check result's rows: (lemma, robots) -> (verdict, reason, witness rounds)."""
    data = json.loads(path.read_text())
    return {(r["lemma"], r["robots"]): (r["verdict"], r["reason"], r["witness_rounds"]) for r in data["lemmas"]}


def _check(site: Path, cache: str, out: Path) -> dict[tuple[str, int], tuple[str, str, int | None]]:
    got = _fatline(site, cache, "check", str(MODEL), "--json", str(out), "--traces", str(out.with_suffix("")), "-q")
    assert got.returncode == 1, got.stderr  # the toy deadlocks and splits the swarm
    return _rows(out)


def test_check_after_an_edit_of_the_plugin_answers_afresh(site: Path, tmp_path: Path) -> None:
    """Before the fix the second run read the answers the first kept for the old rules and reported
    no-collision HOLDS_WITHIN_BOUNDS at 3 robots, which the edited rules violate."""
    kept = tmp_path / "answers"
    before = _check(site, str(kept), tmp_path / "before.json")
    assert before[("no-collision", 3)][0] == "HOLDS_WITHIN_BOUNDS"
    files = set(kept.glob("*.npz"))
    assert len(files) == 2  # one per robot count
    assert _check(site, str(kept), tmp_path / "again.json") == before
    assert set(kept.glob("*.npz")) == files  # unchanged rules: the kept answers were read, none new
    _edit(site)
    after = _check(site, str(kept), tmp_path / "after.json")
    fresh = _check(site, "off", tmp_path / "fresh.json")
    assert after == fresh
    assert after[("no-collision", 3)][0] == "VIOLATED"
    assert set(kept.glob("*.npz")) > files  # new names for the edited rules


def test_report_after_an_edit_of_the_plugin_checks_again(site: Path, tmp_path: Path) -> None:
    """``fatline report``'s cached check.json is reused while the plug-in is unchanged and recomputed
    after an edit (its fingerprint reads the plug-in's sources)."""
    kept, out = str(tmp_path / "answers"), tmp_path / "reports"
    cached = out / "toy-step" / "check.json"

    def report() -> tuple[str, dict[tuple[str, int], tuple[str, str, int | None]]]:
        got = _fatline(site, kept, "report", str(MODEL), "--out", str(out))
        assert got.returncode in (0, 1), got.stderr
        return json.loads(cached.read_text())["fingerprint"], _rows(cached)

    first, rows = report()
    assert rows[("no-collision", 3)][0] == "HOLDS_WITHIN_BOUNDS"
    written = cached.stat().st_mtime_ns
    assert report() == (first, rows) and cached.stat().st_mtime_ns == written  # reused as it was
    _edit(site)
    second, edited = report()
    assert second != first
    assert edited == _check(site, "off", tmp_path / "fresh.json")
    assert edited[("no-collision", 3)][0] == "VIOLATED"
