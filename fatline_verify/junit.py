"""JUnit XML, the report format CI systems read: ``fatline regress``, ``check`` and ``prove`` with ``--junit``.

One document: ``<testsuites>`` holding ``<testsuite>``s of ``<testcase>``s, each either passed or
carrying exactly one ``<failure>`` (a trace that did not reproduce, a VIOLATED verdict), ``<error>`` (a
trace its model refuses to replay) or ``<skipped>`` (an INCONCLUSIVE verdict, with the reason): the
shape of the Ant/Jenkins JUnit schema (``junit-10.xsd``) that Jenkins, GitLab and the GitHub test
reporters read. ``tests/fixtures/junit.xsd`` is that schema, and the tests validate every kind of
document written here against it.

The first line after the XML declaration is a comment carrying the format marker
(:data:`fatline_verify.outputs.TEXT_MARKER` and :attr:`Kind.JUNIT <fatline_verify.outputs.Kind>`), so a
later run rewrites a report it wrote and refuses any other file (unless ``--force``).
"""

from __future__ import annotations

import datetime as _dt
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import Any

from .outputs import TEXT_MARKER, Kind, claim_file, write_text


class Outcome(StrEnum):
    """What happened to one test case (the element it carries, if any)."""

    PASSED = "passed"
    FAILURE = "failure"
    ERROR = "error"
    SKIPPED = "skipped"


@dataclass(frozen=True, slots=True)
class Case:
    """One ``<testcase>``."""

    classname: str
    name: str
    seconds: float | None = None
    """Wall-clock seconds of this case alone; ``None`` when it has none of its own (then no ``time``)."""
    outcome: Outcome = Outcome.PASSED
    message: str = ""
    """The one line a CI system shows: the first differing value, the verdict's reason."""
    type: str = ""
    """The ``type`` attribute: the error class or the verdict."""
    text: str = ""
    """The element's body: details and the command that reproduces the case locally."""


@dataclass(frozen=True, slots=True)
class Suite:
    """One ``<testsuite>``."""

    name: str
    cases: tuple[Case, ...]
    seconds: float | None = None
    """Wall-clock seconds of the suite; ``None``: the sum of its cases' seconds."""
    properties: tuple[tuple[str, str], ...] = ()

    def count(self, outcome: Outcome) -> int:
        return sum(c.outcome is outcome for c in self.cases)

    @property
    def time(self) -> float:
        return self.seconds if self.seconds is not None else sum(c.seconds or 0.0 for c in self.cases)


def claim_junit(text: str | os.PathLike[str], *, force: bool = False) -> Path:
    """Check a ``--junit`` path before any work (:func:`fatline_verify.outputs.claim_file`): its directory
    exists and is writable, and an existing file there is a JUnit report this tool wrote (or ``force``)."""
    return claim_file(text, name="junit", kind=Kind.JUNIT, force=force)


_NOT_XML = re.compile("[^\t\n\r\u0020-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
"""Characters XML 1.0 cannot carry (control characters, lone surrogates from undecodable file names)."""


def _text(value: object) -> str:
    return _NOT_XML.sub("\ufffd", str(value))


def _seconds(value: float) -> str:
    return f"{max(value, 0.0):.3f}"


def _set(element: ET.Element, **attributes: object) -> None:
    for key, value in attributes.items():
        element.set(key, _text(value))


def to_xml(suites: Sequence[Suite], *, name: str, timestamp: _dt.datetime | None = None) -> str:
    """The JUnit XML document of ``suites`` (``name``: the command that ran them), marker included."""
    stamp = (timestamp or _dt.datetime.now(_dt.UTC)).replace(microsecond=0, tzinfo=None).isoformat()
    root = ET.Element("testsuites")
    _set(
        root,
        name=name,
        tests=sum(len(s.cases) for s in suites),
        failures=sum(s.count(Outcome.FAILURE) for s in suites),
        errors=sum(s.count(Outcome.ERROR) for s in suites),
        time=_seconds(sum(s.time for s in suites)),
    )
    for k, suite in enumerate(suites):
        node = ET.SubElement(root, "testsuite")
        _set(
            node,
            name=suite.name,
            tests=len(suite.cases),
            failures=suite.count(Outcome.FAILURE),
            errors=suite.count(Outcome.ERROR),
            skipped=suite.count(Outcome.SKIPPED),
            time=_seconds(suite.time),
            timestamp=stamp,
            id=k,
        )
        if suite.properties:
            props = ET.SubElement(node, "properties")
            for key, value in suite.properties:
                _set(ET.SubElement(props, "property"), name=key, value=value)
        for case in suite.cases:
            tc = ET.SubElement(node, "testcase")
            _set(tc, classname=case.classname, name=case.name)
            if case.seconds is not None:
                _set(tc, time=_seconds(case.seconds))
            if case.outcome is not Outcome.PASSED:
                what = ET.SubElement(tc, case.outcome.value)
                _set(what, message=case.message)
                if case.type:
                    _set(what, type=case.type)
                if case.text:
                    what.text = _text(case.text)
    ET.indent(root)
    marker = f"<!-- {TEXT_MARKER} ({Kind.JUNIT.value}): {_text(name).replace('--', '- -')} -->"
    return f'<?xml version="1.0" encoding="UTF-8"?>\n{marker}\n{ET.tostring(root, encoding="unicode")}\n'


def write_junit(path: Path, suites: Sequence[Suite], *, name: str) -> None:
    """Write the report atomically (a reader never sees half a file)."""
    write_text(path, to_xml(suites, name=name))


def totals(suites: Iterable[Suite]) -> dict[Outcome, int]:
    """How many cases have each outcome."""
    counts = dict.fromkeys(Outcome, 0)
    for suite in suites:
        for case in suite.cases:
            counts[case.outcome] += 1
    return counts


# --- the commands' results as test cases ------------------------------------------------------------


def _verdict_case(classname: str, name: str, verdict: str, reason: str, seconds: float | None, text: str) -> Case:
    """VIOLATED is a failure, INCONCLUSIVE is skipped (with its reason), anything else passed."""
    if verdict == "VIOLATED":
        return Case(classname, name, seconds, Outcome.FAILURE, reason or verdict, verdict, text)
    if verdict == "INCONCLUSIVE":
        return Case(classname, name, seconds, Outcome.SKIPPED, reason or verdict, verdict, text)
    return Case(classname, name, seconds)


def check_suites(result: Any, trace_paths: dict[tuple[str, int], str]) -> list[Suite]:
    """``fatline check``: one suite per robot count (its time is the search's, which every lemma of that
    count shares, so the cases carry none), one case per lemma: ``classname`` MODEL.LEMMA, ``name``
    "N robots"."""
    from .lemmas.properties import CHECKED
    from .schedulers.systems import system_for

    model = result.model
    word = system_for(model).step_word
    stats = {s.robots: s for s in result.stats}
    suites = []
    for n in sorted({r.robots for r in result.results} | set(stats)):
        s = stats.get(n)
        w, h = result.window
        props = [("model", model.name), ("robots", str(n)), ("window", f"{w}x{h}")]
        if result.bound is not None:
            props.append(("bound", f"{result.bound[0]}x{result.bound[1]}"))
        if s is not None:
            props += [
                ("initial", str(s.initial)),
                ("states", str(s.states)),
                ("transitions", str(s.transitions)),
                ("truncated", "yes" if s.truncated else "no"),
                ("engine", s.engine),
            ]
        cases = []
        for lemma in CHECKED:
            for r in (x for x in result.results if x.lemma is lemma and x.robots == n):
                trace = trace_paths.get((lemma.value, n))
                reason = r.reason
                if r.witness_rounds is not None:
                    steps = f"{r.witness_rounds} {word}{'s' * (r.witness_rounds != 1)}"
                    reason += f"; witness of {steps}" + (f" in {trace}" if trace else "")
                text = f"fatline replay {trace} -v" if trace else ""
                cases.append(
                    _verdict_case(f"{model.name}.{lemma.value}", f"{n} robots", r.verdict.value, reason, None, text)
                )
        suites.append(
            Suite(f"fatline check {model.name}: {n} robots", tuple(cases), s.seconds if s else 0.0, tuple(props))
        )
    return suites


def prove_suites(model: Any, rows: Sequence[dict[str, Any]]) -> list[Suite]:
    """``fatline prove``: one suite per lemma, one case per obligation row (``results.json``):
    ``classname`` MODEL.LEMMA, ``name`` the obligation (form-case[.and.other]), its solver seconds."""
    from .prove.tasks import row_key

    suites = []
    for lemma in dict.fromkeys(r["lemma"] for r in rows):
        cases = []
        for r in (x for x in rows if x["lemma"] == lemma):
            trace = r.get("trace")
            lines = [f"obligation {r['smt2']}"] if r.get("smt2") else []
            if trace:
                lines.append(f"counterexample {trace}: fatline replay {trace} -v")
            text = "\n".join(lines)
            name = row_key(r).split("/", 1)[1]
            cases.append(
                _verdict_case(f"{model.name}.{lemma}", name, r["verdict"], r.get("reason", ""), r.get("seconds"), text)
            )
        suites.append(Suite(f"fatline prove {model.name}: {lemma}", tuple(cases), properties=(("model", model.name),)))
    return suites


__all__ = ["Case", "Outcome", "Suite", "check_suites", "claim_junit", "prove_suites", "to_xml", "totals", "write_junit"]
