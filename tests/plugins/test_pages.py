"""Report pages for any directory and any rule set (issue 39, item 4), through installed plug-in packages:
a report written with ``--out`` somewhere else, of model files given by relative paths, has pages whose
every relative link resolves and whose every printed command runs from the directory the user is in;
headers name the rule sets; a lemma a rule set does not claim reads "not claimed"; ``prove``'s advice
names the model file; ``replay`` without the package says what to install."""

from __future__ import annotations

import json
import re
import shlex
import shutil
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urlsplit

import pytest

from tests.plugins.cli import HERE, MODEL, PAIRS, SITE, USERS, fatline, without_plugin

SITES = (SITE, USERS)


class _Links(HTMLParser):
    """Every ``href`` and ``src`` of a page, and the text of every ``<code>``."""

    def __init__(self) -> None:
        super().__init__()
        self.links: list[str] = []
        self.code: list[str] = []
        self._in_code = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.links += [v for k, v in attrs if k in ("href", "src") and v]
        self._in_code = self._in_code or tag == "code"
        if tag == "code":
            self.code.append("")

    def handle_endtag(self, tag: str) -> None:
        if tag == "code":
            self._in_code = False

    def handle_data(self, data: str) -> None:
        if self._in_code:
            self.code[-1] += data


def _targets(page: Path) -> tuple[list[str], list[str]]:
    """A page's links and the commands it prints (code that starts with ``fatline`` and has arguments)."""
    text = page.read_text(encoding="utf-8")
    if page.suffix == ".html":
        parser = _Links()
        parser.feed(text)
        links, code = parser.links, parser.code
    else:
        links = re.findall(r"\]\(([^)\s]+)\)", text)
        code = re.findall(r"`([^`\n]+)`", text)
    return links, [c for c in code if c.startswith("fatline ") and len(shlex.split(c)) > 2]


@pytest.fixture(scope="module")
def written(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """``fatline report models/...toml --out out/rep`` run in a directory of one's own (no ``docs/``
    above it): three models of plug-ins, one of which does not claim Lemma 3."""
    work = tmp_path_factory.mktemp("work")
    (work / "models").mkdir()
    shutil.copyfile(MODEL, work / "models" / "toy-step.toml")
    shutil.copyfile(USERS / "step-left.toml", work / "models" / "step-left.toml")
    small = PAIRS.read_text().replace('robots = "2..4"', 'robots = "2..3"').replace('"9x9"', '"7x7"')
    (work / "models" / "pairs.toml").write_text(small)
    models = ["models/toy-step.toml", "models/step-left.toml", "models/pairs.toml"]
    got = fatline("report", *models, "--out", "out/rep", "-q", cwd=work, sites=SITES)
    assert got.returncode == 0, got.stderr
    return work, work / "out" / "rep"


def test_every_relative_link_of_every_page_resolves(written: tuple[Path, Path]) -> None:
    _, out = written
    pages = sorted(out.rglob("*.html")) + sorted(out.rglob("README.md"))
    assert len(pages) == 8  # the cross-model pages and each model's two
    checked = 0
    for page in pages:
        links, _ = _targets(page)
        for link in links:
            parts = urlsplit(link)
            assert not parts.scheme and not parts.netloc, f"{page}: {link} leaves the report"
            if not parts.path:
                continue  # an anchor on the same page
            assert (page.parent / parts.path).exists(), f"{page.relative_to(out)}: {link} does not resolve"
            checked += 1
    assert checked > 50
    assert "readings.md" not in "".join(p.read_text() for p in pages)  # no catalogue above the report


def test_every_printed_command_runs_from_the_directory_the_user_is_in(written: tuple[Path, Path]) -> None:
    work, out = written
    commands: set[str] = set()
    for page in [*out.rglob("*.html"), *out.rglob("README.md")]:
        commands.update(_targets(page)[1])
    kinds = {shlex.split(c)[1] for c in commands}
    assert kinds == {"report", "replay", "explain"}, commands
    toy = (out / "toy-step" / "README.md").read_text()
    assert "Regenerate: `fatline report models/toy-step.toml --out out/rep`" in toy
    assert "Replay: `fatline replay out/rep/traces/toy-step-check-progress-n2.json -v`" in toy
    assert "what each means: `fatline explain --model models/toy-step.toml`" in toy
    assert "Commands on this page run from the directory the report was made in." in toy
    for command in sorted(commands):
        got = fatline(*shlex.split(command)[1:], cwd=work, sites=SITES)
        assert got.returncode in (0, 1), f"{command}: {got.stderr}"
        assert "error" not in got.stderr, f"{command}: {got.stderr}"


def test_headers_name_the_rule_sets_and_unclaimed_lemmas_say_so(written: tuple[Path, Path]) -> None:
    _, out = written
    matrix = (out / "README.md").read_text()
    assert "Which reading of the paper" not in matrix
    assert "(rule sets: `paper` (the paper's rules), `step-left`, `toy-step`)" in matrix
    row = next(line for line in matrix.splitlines() if line.startswith("| [step-left]"))
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[5:7] == ["not claimed", "not claimed"]  # rma-fixed and approach (check)
    assert cells[10:12] == ["not claimed", "not claimed"]  # and (prove), where the prover has nothing to run
    toy_row = next(line for line in matrix.splitlines() if line.startswith("| [toy-step]"))
    assert "not claimed" not in toy_row  # the toy claims the paper's six
    page = (out / "index.html").read_text()
    assert page.count(">not claimed</td>") == 2  # the prove cells: one "not run" cell, its reason on hover
    assert (
        "Rule set `step-left`: One radius left toward a robot 3 radii left."
        in (out / "step-left" / "README.md").read_text()
    )
    assert "Rule set `toy-step` (reach=3)" in (out / "toy-step" / "README.md").read_text()


def test_a_report_beside_the_catalogue_links_it(tmp_path: Path) -> None:
    """Under a directory whose ``docs/readings.md`` is the catalogue, the pages link it relatively (as the
    committed reports link ``../docs/readings.md``); an absolute ``--out`` needs no "run from" sentence."""
    root = HERE.parent.parent
    (tmp_path / "docs").mkdir()
    shutil.copyfile(root / "docs" / "readings.md", tmp_path / "docs" / "readings.md")
    out = tmp_path / "deep" / "rep"
    model = tmp_path / "pairs.toml"
    model.write_text(PAIRS.read_text().replace('robots = "2..4"', "robots = 2").replace('"9x9"', '"7x7"'))
    proofs = tmp_path / "p"
    got = fatline("report", str(model), "--out", str(out), "--proofs", str(proofs), "-q", cwd=tmp_path)
    assert got.returncode == 0, got.stderr
    page = (out / "paper-pairs" / "README.md").read_text()
    assert "[what the readings mean](../../../docs/readings.md)" in page
    assert f"Regenerate: `fatline report {model} --out {out} --proofs {proofs}`" in page
    assert "run from the directory" not in page
    assert "](../../docs/readings.md)" in (out / "README.md").read_text()


def test_prove_advice_names_the_model_file(written: tuple[Path, Path]) -> None:
    work, _ = written
    got = fatline("prove", "models/toy-step.toml", "--out", "p", cwd=work, sites=SITES)
    assert got.returncode == 2 and got.stderr.count("\n") == 1
    advice = got.stderr.rstrip().rsplit("Use ", 1)[1]
    assert advice == "fatline check models/toy-step.toml"
    assert fatline(*shlex.split(advice)[1:], "-q", cwd=work, sites=SITES).returncode == 1  # it runs: violations


def test_replay_without_the_rule_set_s_package_says_what_to_install(written: tuple[Path, Path]) -> None:
    work, _ = written
    trace = "out/rep/traces/toy-step-check-progress-n2.json"
    got = without_plugin("replay", trace, cwd=work)
    assert (got.returncode, got.stdout) == (2, "")
    assert got.stderr == (
        f"fatline: error: {trace}: rule set 'toy-step' is a plug-in that is not installed; expected its package "
        "installed: pip install 'toy-fatline-plugin==0.1'\n"
    )
    old = json.loads((work / trace).read_text())  # as written before traces named their plug-ins
    del old["plugins"]
    (work / "old.json").write_text(json.dumps(old))
    got = without_plugin("replay", "old.json", cwd=work)
    assert (got.returncode, got.stdout) == (2, "") and got.stderr.count("\n") == 1
    assert got.stderr.startswith("fatline: error: old.json: rules='toy-step': unknown rule set; expected one of ")
    assert got.stderr.rstrip().endswith(
        "(a plug-in's rule set: install the package that registers it; this trace does not record which)"
    )
