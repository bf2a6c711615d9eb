"""Parameters of a scheduler's or rule set's own (``[scheduler]`` and ``[rules]`` tables): set in a
model file, checked before any work, in fingerprints and traces, seen by ``explain`` and ``sweep``, and
held to on replay."""

from __future__ import annotations

import json
from pathlib import Path
from typing import ClassVar

import pytest

from fatline_verify.model.config import load_model, model_from_mapping, model_to_mapping
from fatline_verify.rules import registry
from tests.plugins.cli import MODEL, PAIRS, ROOT, fatline

# --- parameters of a scheduler's or rule set's own: [scheduler] and [rules] tables ------------------


def _pairs_model(tmp_path: Path, table: str, name: str = "pairs-k") -> Path:
    """``pairs.toml`` with a ``[scheduler]`` table (or any other text) appended."""
    path = tmp_path / f"{name}.toml"
    path.write_text(PAIRS.read_text().replace('name = "paper-pairs"', f'name = "{name}"') + "\n" + table)
    return path


def test_the_scheduler_s_k_is_set_in_the_model_file_and_changes_the_rounds(tmp_path: Path) -> None:
    """k = 1 plays exactly centralized's rounds, k = 2 (the default) the toy's as before, k >= n every
    set, as ssync: the same states, as many transitions."""
    searches = {}
    for k in (1, 2, 4):
        out = tmp_path / f"k{k}.json"
        model = _pairs_model(tmp_path, f"[scheduler]\nk = {k}\n", f"pairs-k{k}")
        traces = tmp_path / f"traces-k{k}"
        got = fatline("check", str(model), "--robots", "4", "--json", str(out), "--traces", str(traces), "-q")
        assert got.returncode == 1, got.stderr
        data = json.loads(out.read_text())
        assert data["model"]["scheduler"] == {"k": k}
        searches[k] = (data["searches"][0]["states"], data["searches"][0]["transitions"])
    for name in ("centralized", "ssync"):
        out = tmp_path / f"{name}.json"
        argv = ["check", "paper", "--robots", "4", "--json", str(out), "--traces", str(tmp_path / name), "-q"]
        if name == "centralized":
            argv[1] = "paper-centralized"
        assert fatline(*argv, cwd=ROOT).returncode == 1
        s = json.loads(out.read_text())["searches"][0]
        searches[name] = (s["states"], s["transitions"])  # type: ignore[index]
    assert searches[2] == (11243, 17726)
    assert searches[1] == searches["centralized"]  # type: ignore[index]
    assert searches[4] == searches["ssync"]  # type: ignore[index]


def test_k_is_in_the_fingerprint_the_trace_and_replay(tmp_path: Path, installed: None) -> None:
    from fatline_verify.check.checker import check_fingerprint
    from fatline_verify.trace.traces import trace_model

    two, three = load_model(_pairs_model(tmp_path, "")), load_model(_pairs_model(tmp_path, "[scheduler]\nk = 3\n"))
    assert two.setting("scheduler") == {"k": 2} and three.setting("scheduler") == {"k": 3}
    assert check_fingerprint(two) != check_fingerprint(three)
    assert model_to_mapping(three)["scheduler"] == {"k": 3}
    assert "scheduler k=3" in three.describe()
    model = _pairs_model(tmp_path, "[scheduler]\nk = 3\n")
    trace = tmp_path / "three.json"
    sim = fatline("simulate", str(model), "--init", "0,0 0,3 2,2", "--schedule", "0,1,2", "--trace", str(trace))
    assert sim.returncode in (0, 1), sim.stderr
    doc = json.loads(trace.read_text())
    assert doc["model"]["scheduler"] == {"k": 3}
    assert "reproduces" in fatline("replay", str(trace)).stdout
    assert trace_model(doc).setting("scheduler") == {"k": 3}
    other = fatline("replay", str(trace), "--model", str(PAIRS))  # k = 2: a round of three cannot be played
    assert (other.returncode, other.stderr) == (1, ""), other.stderr
    assert other.stdout == (
        f"{trace}: COULD NOT BE REPLAYED under paper-pairs: rounds/0/active=[0, 1, 2]: round 1 activates 3 robots; "
        "expected one or two under scheduler=pairs\n"
    )
    two_doc = json.loads(json.dumps(doc))
    two_doc["model"]["scheduler"] = {"k": 2}  # its own model says k = 2: the file records no run of it
    two_trace = tmp_path / "claims-two.json"
    two_trace.write_text(json.dumps(two_doc))
    got = fatline("replay", str(trace), str(two_trace))
    assert (got.returncode, got.stdout) == (2, ""), got.stdout  # refused before any trace's line
    assert got.stderr == (
        f"fatline: error: {two_trace}: rounds/0/active=[0, 1, 2]: round 1 activates 3 robots; expected one or two "
        "under scheduler=pairs\n"
    )
    doc["model"]["scheduler"] = {"k": 0}
    trace.write_text(json.dumps(doc))
    bad = fatline("replay", str(trace))
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    assert "scheduler.k=0: expected a whole number 1..64 (at most k robots a round)" in bad.stderr


@pytest.mark.parametrize(
    ("table", "error"),
    [
        ("[scheduler]\nj = 2\n", "scheduler.j=2: unknown key; expected one of k"),
        ('[scheduler]\nk = "two"\n', "scheduler.k='two': expected a whole number 1..64 (at most k robots a round)"),
        ("[scheduler]\nk = 0\n", "scheduler.k=0: expected a whole number 1..64 (at most k robots a round)"),
        ("[scheduler]\nk = true\n", "scheduler.k=True: expected a whole number 1..64 (at most k robots a round)"),
        (
            "scheduler = 3\n",
            "scheduler=3: expected a [scheduler] table of the parameters of the scheduler 'pairs' (the scheduler "
            "itself is [options] scheduler)",
        ),
    ],
)
def test_a_bad_scheduler_parameter_is_one_line_before_any_work(tmp_path: Path, table: str, error: str) -> None:
    model = _pairs_model(tmp_path, table) if not table.startswith("scheduler =") else tmp_path / "m.toml"
    if table.startswith("scheduler ="):
        model.write_text(table + PAIRS.read_text())
    out = tmp_path / "out.json"
    got = fatline("check", str(model), "--json", str(out))
    assert (got.returncode, got.stdout, got.stderr) == (2, "", f"fatline: error: {error}\n")
    assert not out.exists()


def test_a_scheduler_that_declares_none_takes_none(tmp_path: Path) -> None:
    model = tmp_path / "m.toml"
    model.write_text('name = "m"\n[options]\nscheduler = "ssync"\n[scheduler]\nk = 2\n')
    got = fatline("check", str(model))
    assert got.returncode == 2
    assert got.stderr == "fatline: error: scheduler.k=2: unknown key; the scheduler 'ssync' takes no parameters\n"


def test_the_rule_set_s_parameter_is_set_in_its_rules_table(tmp_path: Path, toy: registry.RuleSet) -> None:
    model = tmp_path / "reach.toml"
    model.write_text(
        MODEL.read_text()
        .replace('rules = "toy-step"\n', "")
        .replace("[parameters]", '[rules]\nname = "toy-step"\nreach = 4\n\n[parameters]', 1)
    )
    far = load_model(model)
    assert far.rules == "toy-step" and far.setting("rules") == {"reach": 4}
    assert not registry.decide([(3, 0)], far).moves  # 3 radii right is no longer far enough
    assert registry.decide([(4, 0)], far).moves
    assert registry.decide([(3, 0)], load_model(MODEL)).moves  # the default, 3
    assert model_to_mapping(far)["rules"] == {"name": "toy-step", "reach": 4}
    back = model_from_mapping(model_to_mapping(far))
    assert (back.rules, back.settings) == (far.rules, far.settings)
    for text, error in (
        ('[rules]\nname = "toy-step"\nreach = 0\n', "rules.reach=0: expected a whole number >= 1 (how many radii"),
        ('[rules]\nname = "toy-step"\nfar = 4\n', "rules.far=4: unknown key; expected one of reach"),
        ("[rules]\nreach = 4\n", "rules.name=None: expected the name of a rule set in the [rules] table"),
        ('[rules]\nname = "paper"\nreach = 4\n', "rules.reach=4: unknown key; the rule set 'paper' takes no param"),
    ):
        bad = tmp_path / "bad.toml"
        bad.write_text('name = "bad"\n' + text)
        got = fatline("check", str(bad))
        assert got.returncode == 2 and got.stderr.startswith(f"fatline: error: {error}"), got.stderr
        assert got.stderr.count("\n") == 1


def test_a_scheduler_with_parameters_must_take_them() -> None:
    from fatline_verify.model.options import SchedulerName
    from fatline_verify.model.seams import Param
    from fatline_verify.schedulers.activation import register

    class Deaf:
        kind = SchedulerName("deaf")
        alone = True
        encoded = False
        parameters: ClassVar[dict[str, Param]] = {"k": Param(2, "k")}

    with pytest.raises(ValueError, match=r"scheduler 'deaf': declares parameters but no configured\(\*\*values\)"):
        register(Deaf())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="expected an int, a bool or a str"):
        Param(1.5, "a float")  # type: ignore[arg-type]


# --- explain and sweep see them ---------------------------------------------------------------------


def test_explain_lists_the_parameters_schedulers_and_rule_sets_declare() -> None:
    everything = fatline("explain")
    assert everything.returncode == 0, everything.stderr
    assert (
        "scheduler.k (a parameter of scheduler 'pairs', set in the model file's [scheduler] table)" in everything.stdout
    )
    assert (
        "rules.reach (a parameter of rule set 'toy-step', set in the model file's [rules] table)" in everything.stdout
    )
    one = fatline("explain", "scheduler.k")
    assert one.stdout == (
        "scheduler.k (a parameter of scheduler 'pairs', set in the model file's [scheduler] table)\n"
        "  at most k robots a round\n  a whole number 1..64; default 2\n"
    )
    mine = fatline("explain", "--model", str(MODEL))
    assert "quadrants" not in mine.stdout  # the toy reads none of the paper's readings
    assert mine.stdout.startswith("scheduler\n") and "goal\n" in mine.stdout
    assert mine.stdout.endswith("  a whole number >= 1; default 3 [model toy-step: 3]\n")
    bad = fatline("explain", "rules.far", "--model", str(MODEL))
    assert (bad.returncode, bad.stdout) == (2, "") and bad.stderr.count("\n") == 1
    assert bad.stderr == (
        "fatline: error: option='rules.far': unknown option; expected one of scheduler, motion, timing, contact, "
        "goal, rules.reach\n"
    )


def test_sweep_takes_a_rule_set_s_parameter_through_its_values(tmp_path: Path) -> None:
    """``--vary rules.reach``: one sweep per declared value (3, 4), each of the model with that value, in a
    directory of its own, with its own fingerprint; the default ``--vary`` takes it too."""
    out = tmp_path / "sweeps"
    argv = ["--lemma", "connectivity,progress", "--robots", "2..3", "--out", str(out), "-q"]
    got = fatline("sweep", str(MODEL), "--vary", "rules.reach", *argv)
    assert got.returncode == 1, got.stderr  # progress is refuted under both values
    assert [line for line in got.stdout.splitlines() if line.startswith("rules.reach-")] == [
        "rules.reach-3: rules.reach=3",
        "rules.reach-4: rules.reach=4",
    ]
    saved = {k: json.loads((out / "toy-step" / f"rules.reach-{k}" / "sweep.json").read_text()) for k in (3, 4)}
    assert {k: d["model"]["rules"] for k, d in saved.items()} == {
        3: {"name": "toy-step", "reach": 3},
        4: {"name": "toy-step", "reach": 4},
    }
    assert saved[3]["fingerprint"] != saved[4]["fingerprint"]
    argv[-2] = str(tmp_path / "default")  # the default --vary: the declared parameter and the options
    again = fatline("sweep", str(MODEL), *argv)
    assert again.returncode == 1 and "rules.reach-4: rules.reach=4" in again.stdout, again.stderr


@pytest.mark.parametrize(
    ("model", "vary", "error"),
    [
        (PAIRS, "scheduler.k", "vary='scheduler.k': scheduler 'pairs' declares no values to sweep it through"),
        (PAIRS, "rules.reach", "vary='rules.reach': not a parameter of model paper-pairs's scheduler or rule set; "),
        (MODEL, "rules.reach,rules.reach", "vary='rules.reach,rules.reach': a parameter is named twice"),
        (MODEL, "rules.reach,colour", "vary='colour': unknown option; expected one of "),
    ],
)
def test_a_bad_parameter_to_sweep_is_one_line_before_any_work(
    tmp_path: Path, model: Path, vary: str, error: str
) -> None:
    got = fatline("sweep", str(model), "--vary", vary, "--out", str(tmp_path / "s"), "-q")
    assert (got.returncode, got.stdout) == (2, ""), got.stdout
    assert got.stderr.startswith(f"fatline: error: {error}") and got.stderr.count("\n") == 1, got.stderr
    assert not (tmp_path / "s").exists()


def test_a_sweep_s_fingerprint_holds_the_plug_ins_sources(installed: None, monkeypatch: pytest.MonkeyPatch) -> None:
    """As check's and prove's do: an edited plug-in is never resumed from (a built-in model's is as it was)."""
    from fatline_verify import provenance
    from fatline_verify.sweep.run import Sweep, SweepBounds
    from fatline_verify.sweep.space import Space

    def fingerprint(model):  # type: ignore[no-untyped-def]
        bounds = SweepBounds((2, 3), (7, 7), None, None, None)
        return Sweep(Space(model, ()), bounds, Path("unused"), (), 2**30, 0).fingerprint()

    toy, paper = load_model(MODEL), load_model("paper")
    before = fingerprint(toy), fingerprint(paper)
    real = provenance.plugin_digest
    monkeypatch.setattr(provenance, "plugin_digest", lambda model: real(model) and "edited")
    assert fingerprint(toy) != before[0]
    assert provenance.plugin_digest(toy) == "edited"
    assert fingerprint(paper) != before[1]  # the toy lemmas installed decide for the paper's model too
    monkeypatch.setattr(provenance, "plugin_digest", lambda model: "")  # nothing outside the package decides
    from fatline_verify.cache import fingerprint as plain
    from fatline_verify.sweep.run import VERSION

    bounds = SweepBounds((2, 3), (7, 7), None, None, None).as_json()
    assert fingerprint(paper) == plain(paper, "sweep", vary=[], bounds=bounds, lemmas=[], version=VERSION)


def test_the_shipped_tables_are_in_the_source_digest(monkeypatch: pytest.MonkeyPatch) -> None:
    """A table rule set decides by its JSON file: editing one renames the compiled engine's kept answers."""
    from fatline_verify import provenance

    root = Path(provenance.__file__).resolve().parent
    tables = sorted(f for pattern in provenance.DATA for f in root.glob(pattern))
    assert [t.name for t in tables] == ["q1-7x7-ssync.json", "q1-9x9-ssync.json"]
    before = provenance.source_digest.__wrapped__()
    real = provenance._file_digest
    monkeypatch.setattr(provenance, "_file_digest", lambda p: "edited" if p == tables[0] else real(p))
    assert provenance.source_digest.__wrapped__() != before


def test_a_bad_declaration_is_refused_when_the_plug_in_registers() -> None:
    """A plug-in that declares a parameter wrongly is told so in one line when it registers (through an
    entry point: "plugin NAME cannot be loaded (ValueError: ...)"), never when a model is read."""
    from fatline_verify.model.seams import Param

    def stay(snapshot, model):  # type: ignore[no-untyped-def]
        return None

    for parameters, error in (
        ({"k": 3}, r"bad: parameters\['k'\]=3: expected a Param \(fatline_verify.model.seams\)"),
        ({"a.b": Param(1, "x")}, r"bad: parameters key 'a.b': expected a name of letters, digits, '_' and '-'"),
        ([("k", Param(1, "x"))], r"bad: parameters=\[.*\]: expected a dict of name -> Param"),
    ):
        with pytest.raises(ValueError, match=error):
            registry.register(registry.RuleSet("bad", stay, "bad", parameters=parameters))  # type: ignore[arg-type]
    assert "bad" not in registry._REGISTRY
    with pytest.raises(ValueError, match=r"Param values=\(3, 3\): expected a tuple of distinct values"):
        Param(3, "x", values=(3, 3))
    with pytest.raises(ValueError, match=r"Param values=0: expected a whole number >= 1 \(x\)"):
        Param(3, "x", minimum=1, values=(0, 3))
