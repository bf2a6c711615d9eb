"""The package's shape: no import cycle (function-level imports counted), a small root, and the README's
Layout tree in step with the packages on disk."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import networkx as nx

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "fatline_verify"


def modules() -> dict[str, tuple[Path, bool]]:
    """Every module of the package by dotted name, with its file and whether it is a package."""
    out = {}
    for path in PKG.rglob("*.py"):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        is_pkg = parts[-1] == "__init__"
        if is_pkg:
            parts = parts[:-1]
        out[".".join(parts)] = (path, is_pkg)
    return out


def import_graph() -> nx.DiGraph:
    """Module -> module it imports, every ``import`` and ``from ... import`` anywhere in the file
    (inside functions too; not under ``if TYPE_CHECKING:``, which never runs); ``from pkg import name``
    counts ``pkg.name`` when that is a module, else ``pkg``."""
    mods = modules()
    graph = nx.DiGraph()
    for name, (path, is_pkg) in mods.items():
        graph.add_node(name)
        base = name.split(".") if is_pkg else name.split(".")[:-1]
        tree = ast.parse(path.read_text(encoding="utf-8"))
        typing_only = {
            id(n)
            for block in ast.walk(tree)
            if isinstance(block, ast.If) and "TYPE_CHECKING" in ast.unparse(block.test)
            for stmt in block.body
            for n in ast.walk(stmt)
        }
        for node in ast.walk(tree):
            if id(node) in typing_only:
                continue
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    prefix = base[: len(base) - node.level + 1]
                    module = ".".join(prefix + ([node.module] if node.module else []))
                else:
                    module = node.module or ""
                targets = [f"{module}.{a.name}" if f"{module}.{a.name}" in mods else module for a in node.names]
            for target in targets:
                if target in mods and target != name:
                    graph.add_edge(name, target)
    return graph


def test_the_import_graph_has_no_cycle() -> None:
    graph = import_graph()
    cycles = [sorted(c) for c in nx.strongly_connected_components(graph) if len(c) > 1]
    assert cycles == []
    assert graph.number_of_nodes() > 50  # the walk saw the package


def test_the_option_catalogue_imports_no_rule_set() -> None:
    """Rule sets declare their options into the model layer (``RuleSet(options=...)``), not the other way."""
    graph = import_graph()
    for module in ("fatline_verify.model.options", "fatline_verify.model.option_spec"):
        reached = nx.descendants(graph, module)
        assert not any(m.startswith("fatline_verify.rules") for m in reached), sorted(reached)
    assert "fatline_verify.model.option_spec" in nx.descendants(graph, "fatline_verify.model.options")  # seen


def test_the_graph_sees_function_level_imports(tmp_path: Path) -> None:
    """The walk is not fooled by an import inside a function (the kind that hides a cycle)."""
    edges = import_graph().edges
    assert ("fatline_verify.model.config", "fatline_verify.rules.registry") in edges  # imported in a function


def test_the_package_root_is_small() -> None:
    root = [p.stem for p in PKG.glob("*.py") if p.stem != "__init__"]
    assert len(root) <= 12, root


def readme_tree() -> list[str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Layout") :]
    block = section[section.index("```\n") + 4 :]
    return block[: block.index("```")].splitlines()


def test_the_readme_layout_is_the_package_tree() -> None:
    lines = readme_tree()
    assert lines[0] == "fatline_verify/"
    listed: set[str] = set()
    stack: list[tuple[int, str]] = []
    root_modules: set[str] = set()
    for line in lines[1:]:
        indent = len(line) - len(line.lstrip())
        word = line.split()[0]
        if word.endswith("/"):
            while stack and stack[-1][0] >= indent:
                stack.pop()
            path = "/".join([s for _, s in stack] + [word.rstrip("/")])
            listed.add(path)
            stack.append((indent, word.rstrip("/")))
        else:
            root_modules |= {w[:-3] for w in line.split() if re.fullmatch(r"\w+\.py", w)}
    packages = {str(p.parent.relative_to(PKG)) for p in PKG.rglob("__init__.py") if p.parent != PKG}
    assert listed == packages
    assert root_modules == {p.stem for p in PKG.glob("*.py") if p.stem != "__init__"}


def _slug(heading: str) -> str:
    """GitHub's anchor for a Markdown heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def test_the_readme_and_docs_links_resolve() -> None:
    """Every relative link of README.md and docs/*.md names a file that ships, and an anchor a heading of it."""
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    broken = []
    for page in pages:
        text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            file = (page.parent / path).resolve() if path else page
            if not file.exists():
                broken.append(f"{page.name}: {target}")
            elif anchor and file.suffix == ".md":
                headings = re.findall(r"^#+ (.*)$", file.read_text(encoding="utf-8"), flags=re.M)
                if anchor not in {_slug(h) for h in headings}:
                    broken.append(f"{page.name}: {target} (no such heading)")
    assert broken == []
