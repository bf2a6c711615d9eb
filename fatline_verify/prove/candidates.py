"""The counterexamples known for an obligation before its search: its own from an earlier run, the same
obligation's under the models proved beside it, the shipped corpus's, and each of these for its mirror
image (Scenarios 2 and 3 reflected in the x-axis). Each is only a candidate: the replay
(:func:`fatline_verify.prove.replay.replay_known`) decides under the model being proved.

A module of its own so that what a per-case row depends on is one small set of sources
(:mod:`fatline_verify.prove.digests`), apart from the prover's dispatch in :mod:`fatline_verify.prove.prover`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..model.config import Model
from .replay import Known
from .tasks import row_key


def witness_path(model: Model, directory: Path, key: str) -> Path:
    """``DIRECTORY/MODEL-prove-LEMMA-FORM-RULE.json`` for the obligation ``key``."""
    from ..outputs import child

    lemma, rest = key.split("/", 1)
    return child(directory, f"{model.name}-prove-{lemma}-{rest}", ".json")


def _known_all(
    model: Model,
    key: str,
    traces: Path | None,
    out: Path | None,
    earlier: Mapping[str, dict[str, Any]] | None,
) -> list[Known]:
    """Every counterexample known for the obligation ``key`` before its search, in the order they are
    replayed: its own from an earlier run, the same obligation's under the models proved beside this
    one, then the same for its mirror image (:func:`mirror_key`), reflected in the x-axis. Each is only
    a candidate: :func:`replay_known` keeps it only if, under this model, its r decides this case and
    breaks this claim."""
    own = _known(model, key, traces) or _known_configuration(key, earlier)
    found = ([(EARLIER, own)] if own else []) + _known_beside(key, out)
    mirror = mirror_key(key)
    if mirror is not None:
        theirs = _known(model, mirror, traces) or _known_configuration(mirror, earlier)
        mirrored = ([(EARLIER, theirs)] if theirs else []) + _known_beside(mirror, out)
        _, case = mirror.split("/", 1)
        found += [(f"the mirror image (y to -y) of {where} for {case}", reflect(doc)) for where, doc in mirrored]
    return found


def corpus_known(model: Model, key: str) -> list[Known]:
    """The shipped corpus's candidates for the obligation ``key`` (:func:`fatline_verify.prove.corpus.known_for`),
    then its mirror obligation's (:func:`mirror_key`), reflected in the x-axis, as for an earlier run's."""
    from .corpus import known_for

    found = known_for(model, key)
    mirror = mirror_key(key)
    if mirror is not None:
        _, case = mirror.split("/", 1)
        found += [
            (f"the mirror image (y to -y) of {where} for {case}", reflect(doc))
            for where, doc in known_for(model, mirror)
        ]
    return found


_MIRROR = {"scenario-2": "scenario-3", "scenario-3": "scenario-2", "up": "down", "down": "up"}


def mirror_key(key: str) -> str | None:
    """The obligation whose case is ``key``'s reflected in the x-axis: Scenario 2 ("R∩B is non-empty
    ... moves upwards") and Scenario 3 (R∩D, downwards) trade places, and so do their search's up and
    down candidates; ``None`` for a case of another rule (Scenario 1 moves right, Scenario 4 towards
    −Y: neither has a mirror among the rules)."""
    lemma, rest = key.split("/", 1)
    if ("scenario-2" not in rest and "scenario-3" not in rest) or "scenario-4" in rest or "scenario-1" in rest:
        return None
    return f"{lemma}/" + re.sub(r"scenario-[23]|\bup\b|\bdown\b", lambda m: _MIRROR[m.group(0)], rest)


def reflect(doc: dict[str, Any]) -> dict[str, Any]:
    """A counterexample reflected in the x-axis: the initial positions (a trace) or the configuration
    (a results row) with y negated; everything else as it was (the replay recomputes the rest)."""

    def neg(v: Any) -> str:
        return str(-Fraction(str(v)))

    if "configuration" in doc:
        flipped = []
        for point in doc["configuration"]:
            x, _, y = str(point).partition(",")
            flipped.append(f"{x},{neg(y)}" if y else str(point))
        return {"configuration": flipped, **({"focus": doc["focus"]} if "focus" in doc else {})}
    out = dict(doc)
    if isinstance(doc.get("initial"), list):
        out["initial"] = [[p[0], neg(p[1])] if isinstance(p, list) and len(p) == 2 else p for p in doc["initial"]]
    return out


def _known(model: Model, key: str, traces: Path | None) -> dict[str, Any] | None:
    """The counterexample an earlier run wrote for the obligation ``key`` under ``traces``, if any."""
    from ..outputs import Kind, is_output, read_json

    if traces is None:
        return None
    path = witness_path(model, traces, key)
    return read_json(path) if path.is_file() and is_output(path, Kind.TRACE) else None


def _known_beside(key: str, out: Path | None) -> list[Known]:
    """The same obligation's counterexamples under the other models proved beside this one
    (``OUT/../OTHER``: its trace, or for a claim without a trace its results row's configuration), in
    name order. A reading that does not bear on the case leaves such a counterexample one here too;
    the replay (:func:`replay_known`) decides, under this model, that its r decides the same case,
    breaks the same claim and starts from an initial configuration."""
    from ..outputs import Kind, is_output, read_json

    if out is None or not out.parent.is_dir():
        return []
    lemma, rest = key.split("/", 1)
    found: list[Known] = []
    for results in sorted(out.parent.glob("*/results.json")):
        other = results.parent
        if other.resolve() == out.resolve() or not is_output(results, Kind.PROVE):
            continue
        where = f"a counterexample found under model {other.name}"
        path = other / "traces" / f"{other.name}-prove-{lemma}-{rest}.json"
        if path.is_file() and is_output(path, Kind.TRACE):
            doc = read_json(path)
            if doc is not None:
                found.append((where, doc))
                continue
        rows = read_json(results) or {}
        by_key = {row_key(row): row for row in rows.get("obligations", []) if isinstance(row, dict)}
        configuration = _known_configuration(key, by_key)
        if configuration is not None:
            found.append((where, configuration))
    return found


def _known_configuration(key: str, earlier: Mapping[str, dict[str, Any]] | None) -> dict[str, Any] | None:
    """The configuration an earlier run replayed as a counterexample of the obligation ``key`` (a
    claim without a trace), from its results row, if any."""
    row = (earlier or {}).get(key)
    if row is None or row.get("verdict") != "VIOLATED" or not row.get("configuration"):
        return None
    return {"configuration": list(row["configuration"])}


EARLIER = "an earlier run's counterexample"
"""Where an obligation's own counterexample from an earlier run comes from, as its reason says."""
