"""Installing a plug-in package for one test, in this process: its entry points loaded, and afterwards
the registries and modules as they were."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.plugins.cli import SITE


@pytest.fixture
def install_site(monkeypatch: pytest.MonkeyPatch) -> Iterator[Callable[[Path], None]]:
    """``install(site)``: put ``site`` (a package and its ``.dist-info`` with the entry points) on the
    path and load the plug-ins; at the end of the test, the rule sets, lemmas, schedulers and goals registered,
    the options declared and the installed packages' modules imported since are forgotten (no other test sees
    them)."""
    from fatline_verify.goals import registry as goals
    from fatline_verify.lemmas import registry as lemmas
    from fatline_verify.model import options
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
        options._DECLARED,
    )
    saved = [(reg, dict(reg)) for reg in registries]
    packages = {"toy_fatline_plugin"}

    def install(site: Path) -> None:
        monkeypatch.syspath_prepend(str(site))
        packages.update(p.name for p in site.iterdir() if (p / "__init__.py").is_file())
        registry.load_plugins()

    yield install
    for reg, before in saved:
        reg.clear()
        reg.update(before)
    for name in [m for m in sys.modules if m.split(".")[0] in packages]:
        del sys.modules[name]


@pytest.fixture
def installed(install_site: Callable[[Path], None]) -> None:
    """The plug-in package installed for one test (no other test sees the toy rule set, lemma or
    scheduler)."""
    install_site(SITE)


@pytest.fixture
def toy(installed: None) -> Any:
    """The toy rule set, found by its entry point."""
    from fatline_verify.rules import registry

    return registry.get("toy-step")


@pytest.fixture
def no_left(installed: None) -> object:
    """The toy lemma, registered through its entry point."""
    from fatline_verify.lemmas import registry as lemmas

    found = lemmas.find("no-left")
    assert found is not None
    return found
