"""The prover never answers for a scheduler with another scheduler's semantics."""

from __future__ import annotations

from fatline_verify.properties import Verdict
from fatline_verify.prover import prove, tasks_for
from tests.conftest import make_model


def test_async_obligations_are_inconclusive_with_the_reason(tmp_path):
    model = make_model(scheduler="async")
    results = prove(model, slots=2, timeout=1, out=tmp_path)
    assert len(results) == len(tasks_for(make_model())) > 0  # the SSYNC obligations, none decided
    assert {r.verdict for r in results} == {Verdict.INCONCLUSIVE}
    assert all("scheduler=async: not encoded" in r.reason for r in results)
    assert not list(tmp_path.rglob("*.smt2"))  # nothing was encoded, so nothing is written as if it were


def test_async_through_the_cli_exits_3(capsys, tmp_path):
    from fatline_verify.cli import main

    path = tmp_path / "m.toml"
    path.write_text('name = "m-async"\n[options]\nscheduler = "async"\n')
    assert main(["prove", str(path), "--out", str(tmp_path / "p"), "-q"]) == 3
    out = capsys.readouterr().out
    assert "VIOLATED" not in out and "not encoded" in out
