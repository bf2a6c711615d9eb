"""``fatline prove MODEL --with left|left-alone,corner [--q Q]``: the what-if legs' obligations, rows of their own;
the shipped obligations are not touched.

The legs are a move family (:func:`fatline_verify.rules.repaired.whatif.legs_family`, the family ``fatline reach`` and
``fatline synth`` search), so its obligations are those of every family (:mod:`fatline_verify.prove.smt.family`,
decided on the lattice ``--q`` by :func:`fatline_verify.prove.family.prove_family`); an answer is replayed by the
legs the family admits from each robot's own view (no policy). Without ``corner`` a pair whose classes are
all the repaired family's is left out: the what-if guard of those classes implies the shipped one, whose row
``fatline prove repaired`` decides (under ``corner`` the edge tests differ: every pair)."""

from __future__ import annotations

import argparse
import time

from ..errors import InvalidInput
from ..integrity import seal
from ..lemmas.properties import Lemma
from ..outputs import Kind, Output, child, claim_dir, claim_file, claim_files, distinct_outputs, write_json
from ..prove.smt.family import FamilySpec
from ..prove.tasks import ProofResult
from ..rules.family.family import MoveFamily
from .common import EXIT_FOUND, EXIT_INCONCLUSIVE, EXIT_INTERRUPTED, EXIT_OK, emit, model_arg

ALL = "all"


def parse_with(text: str) -> frozenset[str]:
    """``left`` or ``left-alone``, ``corner``, comma-separated (``fatline reach --with``'s names); bad ones
    are one line."""
    from ..repair.reach import check_kinds
    from ..rules.repaired.whatif import KINDS

    names = [t.strip() for t in text.split(",") if t.strip()]
    bad = [t for t in names if t not in KINDS]
    if not names or bad:
        raise InvalidInput(f"with={text!r}: expected what-if leg kinds, comma-separated, of {', '.join(KINDS)}")
    check_kinds(names)
    return frozenset(names)


def obligations(family: MoveFamily, kinds: frozenset[str], lemmas: tuple[Lemma, ...]) -> list[FamilySpec]:
    """The family's obligations (:func:`fatline_verify.prove.smt.family.specs`), without the pairs the shipped
    rows cover (module docstring)."""
    from ..prove.smt.family import specs
    from ..rules.family.family import REST
    from ..rules.repaired.whatif import CORNER, SHIPPED

    shipped = {*SHIPPED, REST, ""}
    return [s for s in specs(family, lemmas) if CORNER in kinds or not {s.mine, s.other, s.witness} <= shipped]


def row(result: ProofResult, q: int, kinds: frozenset[str], family: MoveFamily) -> dict[str, object]:
    """One obligation's row of ``OUT/MODEL/whatif-KINDS-qQ.json``."""
    out: dict[str, object] = {
        "key": f"{result.key}@q{q}",
        "lemma": str(result.lemma),
        "form": result.form,
        "case": result.case,
        "other": result.other,
        "q": q,
        "with": sorted(kinds),
        "verdict": str(result.verdict),
        "reason": result.reason,
        "seconds": round(result.seconds, 3),
        "smt2": result.smt2,
        "configuration": list(result.configuration),
    }
    alone = next((c for c in family.classes if c.name == "left-alone"), None)
    if alone is not None:
        out["left_alone"] = alone.says
    return out


def cmd_prove_whatif(args: argparse.Namespace) -> int:
    """The what-if rows: checked input first (one line, exit 2), then each obligation in turn, the JSON
    rewritten after each (an interrupted run keeps what it finished)."""
    from ..prove.family import prove_family
    from ..prove.smt.solving import solver_version
    from ..prove.tasks import check_encoded
    from ..rules.repaired.family import missing as missing_repairs
    from ..rules.repaired.whatif import legs_family

    kinds = parse_with(args.with_)
    model = model_arg(args.model)
    missing = missing_repairs(model)
    if missing:
        raise InvalidInput(
            f"model={model.name!r}: the what-if legs extend the repaired family's; expected a model with "
            f"{', '.join(missing)} (e.g. repaired)"
        )
    check_encoded(model)  # ASYNC and corner rules are refused as by fatline prove
    if args.q is not None and args.q != model.parameters.q:
        model = model.with_q(args.q)
    q = model.parameters.q
    if args.lemma not in (ALL, Lemma.NO_COLLISION, Lemma.CONNECTIVITY):
        raise InvalidInput(f"lemma={args.lemma}: --with decides only no-collision and connectivity (or all)")
    lemmas = (Lemma.NO_COLLISION, Lemma.CONNECTIVITY) if args.lemma == ALL else (Lemma(args.lemma),)
    family = legs_family(model, kinds)
    specs = obligations(family, kinds, lemmas)
    tag = f"whatif-{'-'.join(sorted(kinds))}-q{q}"
    root = claim_dir(args.out, name="out")
    out = claim_dir(child(root, model.name), name="out")
    json_path = out / f"{tag}.json"
    claim_files([json_path], name="out", kind=Kind.PROVE, force=args.force)
    extra = claim_file(args.json, name="json", kind=Kind.PROVE, force=args.force) if args.json else None
    distinct_outputs([Output("out", out, directory=True), Output("json", extra)], [("model", args.model)])
    smt_dir = out / tag
    rows: list[dict[str, object]] = []

    def document() -> dict[str, object]:
        return seal(
            {
                "format": Kind.PROVE.value,
                "model": model.name,
                "what_if": sorted(kinds),
                "family": family.name,
                "q": q,
                "solver": solver_version(),
                "timeout": args.timeout,
                "obligations": rows,
            }
        )

    interrupted = False
    t0 = time.monotonic()
    try:
        for spec in specs:
            got = prove_family(model, spec, timeout=args.timeout, out=smt_dir, family=family)
            rows.append(row(got, q, kinds, family))
            write_json(json_path, document())
            if not args.quiet:
                emit([f"{got.verdict:<12} {got.seconds:7.2f} s  {spec.key}"])
    except KeyboardInterrupt:
        interrupted = True
    counts = {v: sum(r["verdict"] == v for r in rows) for v in ("PROVED", "VIOLATED", "INCONCLUSIVE")}
    lines = [
        f"{model.name} --with {','.join(sorted(kinds))} (what-if legs, not the shipped rules), lattice q = {q}: "
        f"{len(rows)} of {len(specs)} obligations, {counts['PROVED']} PROVED, {counts['VIOLATED']} VIOLATED, "
        f"{counts['INCONCLUSIVE']} INCONCLUSIVE in {time.monotonic() - t0:.1f} s; rows in {json_path}"
    ]
    if args.verbose or not args.quiet:
        lines += [f"  {r['key']}: {r['verdict']}: {r['reason']}" for r in rows if r["verdict"] != "PROVED"]
    if interrupted:
        lines.append(f"INTERRUPTED: {len(rows)} of {len(specs)} obligations finished and saved in {json_path}")
    emit(lines)
    if extra is not None:
        write_json(extra, document())
    if interrupted:
        return EXIT_INTERRUPTED
    if counts["VIOLATED"]:
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if counts["INCONCLUSIVE"] else EXIT_OK


__all__ = ["cmd_prove_whatif", "obligations", "parse_with"]
