"""``python -m fatline_verify.prove.certify [DIR...]``: check every linear certificate
(``*.linear.smt2``) under the directories (default ``proofs``) against the obligation file beside it,
from the two files alone (:mod:`fatline_verify.prove.smt.certificates`): the relaxed part is the
obligation, every cut is implied by the atom its Boolean stands for, and cvc5 finds the linear problem
unsat. Prints one line per certificate that fails and a count; exit 0 if every one passed, 1 if one
failed, 2 for a directory that does not exist."""

from __future__ import annotations

import sys
from pathlib import Path


def main(argv: list[str] | None = None) -> int:
    from .smt.certificates import check_certificate

    dirs = [Path(a) for a in (sys.argv[1:] if argv is None else argv)] or [Path("proofs")]
    for d in dirs:
        if not d.is_dir():
            print(
                f"fatline: certify: {d.as_posix()}: no such directory; expected a directory of proofs", file=sys.stderr
            )
            return 2
    files = sorted(p for d in dirs for p in d.rglob("*.linear.smt2"))
    failed = 0
    for path in files:
        got = check_certificate(path)
        if not got.ok:
            failed += 1
            print(f"FAILED {got.path}: {got.why}")
    print(f"{len(files) - failed} of {len(files)} certificates check from their own files (atoms, cuts, cvc5)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
