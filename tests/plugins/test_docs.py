"""docs/plugins.md says what the code does: its code runs, its model file loads, and every field,
attribute and signature it names is the code's (a new user should not need the source)."""

from __future__ import annotations

import dataclasses
import re
import tomllib
from collections.abc import Callable
from pathlib import Path

import pytest

from fatline_verify.model.config import Model, load_model, model_from_mapping
from fatline_verify.model.seams import Param
from fatline_verify.prove.smt.live_rules import LiveCase
from fatline_verify.rules import registry
from fatline_verify.rules.decision import Decision
from tests.plugins.cli import ROOT, SITE

DOC = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", DOC, re.S)


def _fields(cls: type) -> list[str]:
    return [f.name for f in dataclasses.fields(cls)]


def test_the_rule_set_example_registers_and_decides(install_site: Callable[[Path], None]) -> None:
    """The first code block, run as a plug-in module would be: it registers ``my-step`` (the fixture
    forgets it afterwards), a model file names it, and it decides as its comment says."""
    code = _blocks("python")[0]  # the first: the rule set of one's own
    exec(compile(code, "docs/plugins.md", "exec"), {"__name__": "my_rules"})
    model = model_from_mapping({"name": "mine", "rules": "my-step"})
    step = registry.decide([(3, 0)], model)
    assert (step.rule, step.destination, step.path, step.moves) == ("step", (1, 0), ((0, 0), (1, 0)), True)
    assert not registry.decide([(3, 0), (1, 1)], model).moves  # within two radii of the path: blocked
    assert not registry.decide([(2, 0)], model).moves  # nothing 3 radii right
    assert model.setting("rules") == {}  # it declares no parameter


def test_the_model_file_example_sets_the_plug_ins_parameters(install_site: Callable[[Path], None]) -> None:
    install_site(SITE)
    entry, model_file = _blocks("toml")
    assert tomllib.loads(entry)["project"]["entry-points"]["fatline.plugins"] == {"my-step": "my_rules"}
    model = model_from_mapping({"name": "doc", **tomllib.loads(model_file)})
    assert model.rules == "toy-step" and str(model.options.scheduler) == "pairs"
    assert (model.setting("scheduler"), model.setting("rules")) == ({"k": 3}, {"reach": 4})


def test_every_model_attribute_the_page_names_exists() -> None:
    named = set(re.findall(r"`model\.([a-z_0-9]+)", DOC))
    assert {"radius", "view", "view2", "contact2", "apart2", "sees", "setting", "parameters", "options"} <= named
    model = load_model("paper")
    for name in named:
        assert hasattr(model, name), name
    assert hasattr(Model, "to_lattice") and hasattr(Model, "from_lattice")


@pytest.mark.parametrize(
    ("shown", "cls", "count"),
    [
        ("Decision(rule, destination, path, classification=())", Decision, 4),
        ("LiveCase(name, roles, moves, encode)", LiveCase, 4),
        ("Param(default,\ndoc, minimum=None, maximum=None, values=(), choices=())", Param, 6),
    ],
)
def test_every_signature_the_page_shows_is_the_code_s(shown: str, cls: type, count: int) -> None:
    assert shown in DOC
    names = re.findall(r"([a-z_]+)(?:=[^,)]*)?[,)]", shown.replace("\n", " ").split("(", 1)[1])
    assert names == _fields(cls)[:count]
    assert "(`fatline_verify.rules.decision`" in DOC and "from fatline_verify.rules.decision import Decision" in DOC


def test_the_labels_and_setting_fields_the_page_names_are_the_rule_set_s() -> None:
    for name in ("labels", "lemmas", "safety", "liveness", "parameters", "prover", "bands"):
        assert f"{name}=" in DOC, name
        assert name in _fields(registry.RuleSet), name
