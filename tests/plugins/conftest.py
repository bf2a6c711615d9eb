"""Installing a plug-in package for one test, in this process: its entry points loaded, and afterwards
the registries and modules as they were."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest


@pytest.fixture
def install_site(monkeypatch: pytest.MonkeyPatch) -> Iterator[Callable[[Path], None]]:
    """``install(site)``: put ``site`` (a package and its ``.dist-info`` with the entry points) on the
    path and load the plug-ins; at the end of the test, the rule sets, lemmas, schedulers and goals registered
    and the ``toy_fatline_plugin`` modules imported since are forgotten (no other test sees them)."""
    from fatline_verify.goals import registry as goals
    from fatline_verify.lemmas import registry as lemmas
    from fatline_verify.rules import registry
    from fatline_verify.schedulers import activation

    lemmas.registered()  # the package's own, loaded before the snapshot
    goals.names()
    registries: tuple[dict[Any, Any], ...] = (
        registry._REGISTRY,
        lemmas._REGISTRY,
        activation.ROUND_SCHEDULERS,
        registry._PROVIDERS,
        goals._REGISTRY,
    )
    saved = [(reg, dict(reg)) for reg in registries]

    def install(site: Path) -> None:
        monkeypatch.syspath_prepend(str(site))
        registry.load_plugins()

    yield install
    for reg, before in saved:
        reg.clear()
        reg.update(before)
    for name in [m for m in sys.modules if m.split(".")[0] == "toy_fatline_plugin"]:
        del sys.modules[name]
