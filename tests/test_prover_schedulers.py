"""The prover never answers for a scheduler with another scheduler's semantics."""

from __future__ import annotations

import pytest

from fatline_verify.errors import InvalidInput
from fatline_verify.prove.prover import prove, tasks_for
from tests.conftest import make_model


def test_async_is_refused_before_any_work(tmp_path):
    model = make_model(scheduler="async")
    with pytest.raises(InvalidInput, match="scheduler=async"):
        tasks_for(model)
    with pytest.raises(InvalidInput, match="scheduler=async"):
        prove(model, timeout=1, out=tmp_path)
    assert not list(tmp_path.rglob("*"))  # nothing was encoded, so nothing is written as if it were


def test_async_through_the_cli_is_a_one_line_error(capsys, tmp_path):
    from fatline_verify.cli import main

    path = tmp_path / "m.toml"
    path.write_text('name = "m-async"\n[options]\nscheduler = "async"\n')
    assert main(["prove", str(path), "--out", str(tmp_path / "p"), "-q"]) == 2
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert "scheduler=async" in err and len(err.splitlines()) == 1
    assert "VIOLATED" not in captured.out
    assert not (tmp_path / "p").exists()
