"""A rule set's own option, from an installed package (``tests/plugins/optioned``: ``turn-step``, whose option
``turn`` reads which way a robot steps): a model file sets it, the rules read it, ``fatline explain`` lists it
with its readings, ``fatline sweep`` takes a model through them, a trace records it and replays under it; a
model setting an option its rule set does not declare is refused in one line naming both. Rule sets written
against the API before (``options=frozenset({...})`` of names) keep working."""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from enum import StrEnum
from pathlib import Path

import pytest

from fatline_verify.errors import InvalidModel
from fatline_verify.model import options
from fatline_verify.model.config import load_model, model_from_mapping, model_to_mapping
from fatline_verify.model.option_spec import spec
from fatline_verify.rules import registry
from fatline_verify.rules.decision import stay
from fatline_verify.sweep.space import default_vary
from tests.plugins.cli import OPTIONED, ROOT, fatline, without_plugin

TURN_LEFT = OPTIONED / "turn-left.toml"


def _write(tmp_path: Path, options_table: str, rules: str = "turn-step") -> Path:
    path = tmp_path / "m.toml"
    path.write_text(f'name = "m"\nrules = "{rules}"\n\n[options]\n{options_table}', encoding="utf-8")
    return path


def test_the_model_file_sets_the_option_and_the_rules_read_it(install_site: Callable[[Path], None]) -> None:
    install_site(OPTIONED)
    model = load_model(TURN_LEFT)
    assert (model.rules, str(model.options.turn), options.owner("turn")) == ("turn-step", "left", "turn-step")
    assert list(options.CATALOGUE)[-1] == "turn"  # after this package's options, in their order
    assert model_to_mapping(model)["options"]["turn"] == "left"  # in the model's data: fingerprints, traces
    assert registry.decide([(-3, 0)], model).destination == (-1, 0)
    assert not registry.decide([(3, 0)], model).moves
    right = model.options.with_(turn="right")
    assert model.options != right and right.turn is type(model.options.turn).RIGHT
    assert model_from_mapping({"name": "r", "rules": "turn-step"}).options.turn == "right"  # the default
    assert "turn" in default_vary(model)  # a sweep takes it through its readings by default
    assert "turn" not in model_to_mapping(load_model("paper"))["options"]  # no other rule set's data changes


def test_explain_lists_the_option_with_its_readings() -> None:
    everything = fatline("explain", sites=(OPTIONED,))
    assert everything.returncode == 0, everything.stderr
    assert "\nturn\n" in everything.stdout and "an option of rule set 'turn-step'" in everything.stdout
    one = fatline("explain", "turn", "--model", str(TURN_LEFT), sites=(OPTIONED,))
    assert one.returncode == 0, one.stderr
    assert one.stdout.splitlines() == [
        "turn",
        '  paper: "each robot moves towards its far neighbour"',
        "    right [default]: toward a robot seen at least 3 radii right: the right-most robot never moves",
        "  * left [model turn-left]: toward a robot seen at least 3 radii left: the right-most robot may leave its "
        "vertical",
        "  note: the rule set's own option (a plug-in's), not one of the paper's",
        "  an option of rule set 'turn-step', set in a model file's [options] table",
    ]
    mine = fatline("explain", "--model", str(TURN_LEFT), sites=(OPTIONED,))
    assert "\nturn\n" in mine.stdout and "quadrants" not in mine.stdout  # it reads none of the paper's
    gone = without_plugin("explain", "turn")
    assert gone.returncode == 2 and gone.stderr.startswith("fatline: error: option='turn': unknown option")


def test_fatline_explain_sees_it_only_with_the_package_installed() -> None:
    got = fatline("explain", "turn", sites=(OPTIONED,))
    assert got.returncode == 0 and got.stdout.startswith("turn\n"), got.stderr


def test_sweep_takes_the_model_through_the_option_s_readings(tmp_path: Path) -> None:
    """Under ``turn = right`` the right-most robot never moves (Lemma 3 holds within bounds); under ``left``
    it steps off its vertical: one counterexample refutes that reading."""
    out = tmp_path / "sweeps"
    argv = ["--vary", "turn", "--lemma", "rma-fixed", "--robots", "2..3", "--out", str(out), "-q"]
    got = fatline("sweep", str(TURN_LEFT), *argv, sites=(OPTIONED,))
    assert got.returncode == 1, got.stderr  # refuted under one reading
    saved = json.loads((out / "turn-left" / "sweep.json").read_text(encoding="utf-8"))
    assert saved["vary"] == ["turn"] and saved["model"]["options"]["turn"] == "left"
    (row,) = saved["lemmas"]
    assert (row["combinations"], row["refuted"], row["holds"], row["holds_under"]) == (2, 1, 1, [{"turn": "right"}])


def test_a_trace_records_the_option_and_replays_under_it(tmp_path: Path) -> None:
    traces = tmp_path / "traces"
    argv = ["--robots", "2", "--traces", str(traces), "-q"]
    got = fatline("check", str(TURN_LEFT), *argv, sites=(OPTIONED,))
    assert got.returncode == 1, got.stderr
    trace = traces / "turn-left-rma-fixed-n2.json"
    doc = json.loads(trace.read_text(encoding="utf-8"))
    assert doc["model"]["rules"] == "turn-step" and doc["model"]["options"]["turn"] == "left"
    assert [p["distribution"] for p in doc["plugins"]] == ["optioned-fatline-plugin"]
    again = fatline("replay", str(trace), sites=(OPTIONED,))
    assert "reproduces" in again.stdout, again.stdout + again.stderr
    missing = without_plugin("replay", str(trace))
    assert missing.returncode == 2 and "optioned-fatline-plugin" in missing.stderr, missing.stderr


@pytest.mark.parametrize(
    ("table", "rules", "error"),
    [
        (
            'trun = "left"\n',
            "turn-step",
            "options.trun='left': not an option of rule set 'turn-step'; expected one of contact, goal, motion, "
            "scheduler, timing, turn",
        ),
        ('turn = "left"\n', "paper", "options.turn='left': not an option of rule set 'paper'; expected one of "),
        ('turn = "up"\n', "turn-step", "option turn='up': unknown reading; expected one of right, left"),
        ('quadrants = "literal"\n', "turn-step", "options.quadrants='literal': not an option of rule set 'turn-step'"),
    ],
)
def test_an_option_its_rule_set_does_not_declare_is_one_line(
    tmp_path: Path, table: str, rules: str, error: str
) -> None:
    got = fatline("check", str(_write(tmp_path, table, rules)), "-q", sites=(OPTIONED,))
    assert (got.returncode, got.stdout) == (2, ""), got.stdout
    assert got.stderr.startswith(f"fatline: error: {error}") and got.stderr.count("\n") == 1, got.stderr


class Colour(StrEnum):
    RED = "red"
    BLUE = "blue"


COLOURS = {"red": "a red robot", "blue": "a blue robot"}


def _decide(snapshot: object, model: object) -> object:
    return stay("wait")


@pytest.mark.parametrize(
    ("entries", "error"),
    [
        (
            (spec("quadrants", Colour, "", {"red": "", "blue": ""}),),
            "option 'quadrants' is declared by rule set 'paper'",
        ),
        ((spec("contact", Colour, "", {"red": "", "blue": ""}),), "option 'contact' is declared by the model layer"),
        (("colour",), "options names 'colour': no such option; expected one of quadrants, "),
        (("goal", "goal"), "options names 'goal' twice"),
        ("quadrants", "options='quadrants': expected a tuple of option declarations"),
        ((spec("Colour", Colour, "", COLOURS),), "option 'Colour': expected a name of lower-case"),
    ],
)
def test_a_declaration_that_clashes_is_refused_when_it_registers(
    install_site: Callable[[Path], None], entries: object, error: str
) -> None:
    with pytest.raises(ValueError, match=rf"^rule set 'clash': .*{error.replace('(', '.').replace(')', '.')}"):
        registry.register(registry.RuleSet("clash", _decide, "x", options=entries))  # type: ignore[arg-type]
    assert "clash" not in registry._REGISTRY and "Colour" not in options.CATALOGUE


def test_a_rule_set_of_the_api_before_still_names_options(install_site: Callable[[Path], None]) -> None:
    """``options=frozenset({...})`` of names (the API before rule sets declared options) and a copy of another
    rule set's ``options`` still register and read them; ``model.options.NAME`` reads any declared option."""
    registry.register(registry.RuleSet("old-api", _decide, "x", options=frozenset({"quadrants", "bands"})))
    paper = registry.get("paper")
    registry.register(registry.RuleSet("paper-copy", paper.decide, "x", options=paper.options))
    old = model_from_mapping({"name": "o", "rules": "old-api", "options": {"quadrants": "literal"}})
    assert (str(old.options.quadrants), str(old.options.repair_lock)) == ("literal", "off")
    assert model_to_mapping(old)["options"] == {
        "quadrants": "literal",
        "bands": "disc",
        "scheduler": "ssync",
        "timing": "any-speed",
        "contact": "touch-allowed",
        "goal": "vertical-line",
    }
    copy = model_from_mapping({"name": "c", "rules": "paper-copy", "options": {"uncovered": "stay"}})
    assert options.owner("uncovered") == "paper" and str(copy.options.uncovered) == "stay"
    with pytest.raises(InvalidModel, match=r"^options.repair_lock='left-first': not an option of rule set 'old-api'"):
        model_from_mapping({"name": "o", "rules": "old-api", "options": {"repair_lock": "left-first"}})


def test_an_import_of_a_moved_reading_says_where_it_is() -> None:
    with pytest.raises(ImportError, match=r"moved to fatline_verify.rules.paper.options"):
        from fatline_verify.model.options import Quadrants
    from fatline_verify.rules.paper.options import Quadrants

    assert options.CATALOGUE["quadrants"].enum is Quadrants


def test_the_page_s_example_declares_its_option(install_site: Callable[[Path], None]) -> None:
    """docs/plugins.md's option example, run as a plug-in module would be: a model file sets its option, the
    rules read it, and a misspelt one is refused with the words the page shows."""
    page = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")
    (code,) = [b for b in re.findall(r"```python\n(.*?)```", page, re.S) if "turn_rules" in b]
    exec(compile(code, "docs/plugins.md", "exec"), {"__name__": "turn_rules"})
    model = model_from_mapping({"name": "t", "rules": "turn-step", "options": {"turn": "left"}})
    assert registry.decide([(-3, 0)], model).destination == (-1, 0)
    assert not registry.decide([(3, 0)], model).moves
    shown = re.search(r'\("(options\.trun=.*?)"\)', page.replace("\n  ", " "))
    assert shown is not None
    with pytest.raises(InvalidModel) as refused:
        model_from_mapping({"name": "t", "rules": "turn-step", "options": {"trun": "left"}})
    assert str(refused.value) == shown.group(1)
