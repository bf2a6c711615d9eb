"""Where a report was written, and how its pages point at things: every command a page prints runs from
the directory ``fatline report`` ran in (the model as the user named it, ``--out`` and ``--proofs`` as
given), and every link is relative to the page (the readings catalogue only where one is found above the
report, else ``fatline explain``, which needs neither a checkout nor a network).

The committed ``reports/`` (``fatline report`` in the repository, ``docs/`` beside ``reports/``) keep
their commands and links: ``fatline report paper``, ``fatline replay reports/traces/NAME.json -v``,
``../docs/readings.md``.
"""

from __future__ import annotations

import os
import shlex
from dataclasses import dataclass
from pathlib import Path

from ..model.config import Model
from ..outputs import Kind, is_output
from ..text import READINGS_DOC

DEFAULT_OUT = Path("reports")
DEFAULT_PROOFS = Path("proofs")


def _arg(value: str) -> str:
    """One word of a shell command, quoted only when it must be (a path with a space)."""
    return shlex.quote(value)


def find_catalogue(out: Path) -> str | None:
    """The readings catalogue (``docs/readings.md``, as ``python -m fatline_verify.docs`` wrote it) in
    the report root's parent or an ancestor of it, as a link relative to the report root; ``None`` when
    there is none (a report outside a checkout)."""
    root = out.resolve()
    for above in root.parents:
        candidate = above / READINGS_DOC
        if candidate.is_file() and is_output(candidate, Kind.PAGE):
            return Path(os.path.relpath(candidate, root)).as_posix()
    return None


@dataclass(frozen=True, slots=True)
class Places:
    """A report's location as the user named it (``out``, ``proofs``: relative to the directory the
    command ran in, or absolute) and the readings catalogue relative to its root (``None``: none found)."""

    out: Path = DEFAULT_OUT
    proofs: Path = DEFAULT_PROOFS
    catalogue: str | None = f"../{READINGS_DOC}"

    @classmethod
    def of(cls, out: Path, proofs: Path) -> Places:
        """The places of a report written to ``out`` with prover results in ``proofs``."""
        return cls(Path(out), Path(proofs), find_catalogue(Path(out)))

    def _outputs(self) -> list[str]:
        """``--out`` and ``--proofs``, where they are not the defaults."""
        words = []
        if self.out != DEFAULT_OUT:
            words += ["--out", _arg(self.out.as_posix())]
        if self.proofs != DEFAULT_PROOFS:
            words += ["--proofs", _arg(self.proofs.as_posix())]
        return words

    def regenerate(self, models: list[Model] | None = None) -> str:
        """The command that writes this report again: ``models`` by the name or file they were given
        as (``None``: every shipped model, the command's default)."""
        refs = [_arg(m.ref) for m in models] if models is not None else []
        return " ".join(["fatline", "report", *refs, *self._outputs()])

    def replay(self, trace: str) -> str:
        """The command that replays the corpus trace ``trace`` (a file name's stem) round by round."""
        return f"fatline replay {_arg((self.out / 'traces' / f'{trace}.json').as_posix())} -v"

    def where(self, models: list[Model] | None = None) -> str:
        """Where the pages' commands run, as a sentence: "" when every path they name (``--out``,
        ``--proofs``, a model file) is absolute (a shipped model's name runs anywhere)."""
        paths = [self.out, self.proofs, *(Path(m.ref) for m in models or () if m.ref != m.name)]
        if all(p.is_absolute() for p in paths):
            return ""
        return " Commands on this page run from the directory the report was made in."

    def readings(self, page_root: str) -> str | None:
        """The catalogue as a link from a page ``page_root`` below the report root (``""``, ``"../"``),
        or ``None``."""
        return None if self.catalogue is None else page_root + self.catalogue


def explain(model: Model | None = None) -> str:
    """Where a reading's meaning is found when the report has no catalogue above it: ``fatline explain``
    (every option, reading and declared parameter), for a model the options and parameters it has."""
    return "fatline explain" if model is None else f"fatline explain --model {_arg(model.ref)}"


__all__ = ["DEFAULT_OUT", "DEFAULT_PROOFS", "Places", "explain", "find_catalogue"]
