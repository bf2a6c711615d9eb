"""Checking a linear certificate from its files alone: ``NAME.linear.smt2`` against the obligation
``NAME.smt2`` beside it (:func:`check_certificate`).

An unsat linear certificate proves its obligation unsat when (1) every solution of the obligation
gives one of the certificate, each relaxed Boolean set to the truth of the comparison it stands for,
and (2) the certificate is unsat. The checker re-derives (1) from the two files, trusting neither the
tool's code nor its memory:

1. **The relaxed part is the obligation**: the certificate's first ``relaxed assertions`` asserts, each
   relaxed Boolean replaced by its recorded atom (``; atom NAME SEXPR``), are exactly the obligation
   file's asserts (term for term, as z3 parses both files into one context); a Boolean without an atom,
   or an assert that differs, fails the check.
2. **Every cut is implied**: each later assert (marked ``; cut NAME``), every relaxed Boolean in it
   replaced by its atom, is valid over the reals: z3 finds no counterexample to it (``unsat`` of its
   negation; each a comparison of two linear terms against a disc: a small nonlinear problem).
3. **The linear problem is unsat**, by cvc5 (its own parser, the file as written): a second solver
   confirms what z3 found.

A certificate that passes all three proves its obligation unsat independently of how the prover found
it. ``python -m fatline_verify.prove.certify DIR`` runs this on every certificate under ``DIR``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import z3

CUT_BUDGET_MS = 20_000
"""z3's wall-clock limit on one cut's validity (each took well under a second where measured)."""

_ATOM = re.compile(r"^; atom (\S+) (.*)$")
_CUT = re.compile(r"^; cut (\S+)$")
_COUNTS = re.compile(r"^; relaxed assertions: (\d+); cuts: (\d+)$")


@dataclass(frozen=True)
class Checked:
    """One certificate's check: ``ok`` only if all three steps passed; ``why`` says the first that did not."""

    path: str
    ok: bool
    why: str
    atoms: int = 0
    cuts: int = 0


def _declarations(text: str) -> str:
    return "".join(line + "\n" for line in text.splitlines() if line.startswith(("(declare-fun", "(declare-const")))


def check_certificate(linear: Path, *, cvc5_check: bool = True) -> Checked:
    """Check ``linear`` (a ``.linear.smt2`` file) against the obligation beside it (see the module
    docstring)."""
    where = linear.as_posix()
    obligation = linear.with_name(linear.name.replace(".linear.smt2", ".smt2"))
    if not obligation.is_file():
        return Checked(where, False, f"no obligation file {obligation.name} beside it")
    text = linear.read_text()
    lines = text.splitlines()
    counts = next((m for line in lines if (m := _COUNTS.match(line))), None)
    if counts is None:
        return Checked(where, False, "no '; relaxed assertions: K; cuts: M' line: not a recorded certificate")
    n_relaxed, n_cuts = int(counts.group(1)), int(counts.group(2))
    atom_text = {m.group(1): m.group(2) for line in lines if (m := _ATOM.match(line))}
    cut_names = [m.group(1) for line in lines if (m := _CUT.match(line))]
    if len(cut_names) != n_cuts:
        return Checked(where, False, f"{len(cut_names)} '; cut' marks, expected {n_cuts}")
    ctx = z3.Context()
    original = list(z3.parse_smt2_file(str(obligation), ctx=ctx))
    cert = list(z3.parse_smt2_string(text, ctx=ctx))
    if len(cert) != n_relaxed + n_cuts:
        return Checked(where, False, f"{len(cert)} asserts, expected {n_relaxed} relaxed and {n_cuts} cuts")
    decls = _declarations(obligation.read_text())
    pairs = []
    for name, sexpr in atom_text.items():
        (atom,) = z3.parse_smt2_string(f"{decls}(assert {sexpr})", ctx=ctx)
        pairs.append((z3.Bool(name, ctx), atom))
    relaxed, cuts = cert[:n_relaxed], cert[n_relaxed:]
    if len(relaxed) != len(original):
        return Checked(where, False, f"{len(relaxed)} relaxed asserts, the obligation has {len(original)}")
    for k, (mine, theirs) in enumerate(zip(relaxed, original, strict=True)):
        back = z3.substitute(mine, *pairs) if pairs else mine
        if not back.eq(theirs) and not z3.simplify(back).eq(z3.simplify(theirs)):
            return Checked(
                where, False, f"relaxed assert {k}, its Booleans replaced by their atoms, is not the obligation's"
            )
    names = set(atom_text)
    for k, (name, cut) in enumerate(zip(cut_names, cuts, strict=True)):
        used = {str(c) for c in _booleans(cut)}
        if name not in names or not used <= names:
            return Checked(where, False, f"cut {k} uses a Boolean without a recorded atom ({sorted(used - names)})")
        claim = z3.substitute(cut, *pairs)
        solver = z3.Solver(ctx=ctx)
        solver.set("timeout", CUT_BUDGET_MS)
        solver.add(z3.Not(claim))
        got = solver.check()
        if got != z3.unsat:
            return Checked(where, False, f"cut {k} (on {name}) is not shown implied by its atom: z3 says {got}")
    if cvc5_check:
        said = cvc5_answer(linear)
        if said != "unsat":
            return Checked(where, False, f"cvc5 says {said} of the linear problem", len(pairs), len(cuts))
    return Checked(where, True, "every cut implied by its atom; the linear problem unsat", len(pairs), len(cuts))


def _booleans(e: z3.ExprRef) -> set[z3.ExprRef]:
    out: set[z3.ExprRef] = set()
    seen: set[int] = set()
    todo = [e]
    while todo:
        t = todo.pop()
        if t.get_id() in seen:
            continue
        seen.add(t.get_id())
        if z3.is_const(t) and z3.is_bool(t) and not (z3.is_true(t) or z3.is_false(t)):
            out.add(t)
        todo += t.children()
    return out


def cvc5_answer(path: Path, limit_ms: int = 60_000) -> str:
    """cvc5's answer to a written file, by its own parser; ``cvc5 not installed`` without it."""
    try:
        import cvc5
    except ImportError:
        return "nothing: cvc5 not installed (pip install cvc5)"
    tm = cvc5.TermManager()
    solver = cvc5.Solver(tm)
    solver.setOption("tlimit-per", str(limit_ms))
    symbols = cvc5.SymbolManager(tm)
    parser = cvc5.InputParser(solver, symbols)
    parser.setFileInput(cvc5.InputLanguage.SMT_LIB_2_6, str(path))
    answer = "no answer"
    while True:
        cmd = parser.nextCommand()
        if cmd.isNull():
            break
        said = cmd.invoke(solver, symbols)
        answer = said.strip() or answer
    return answer


__all__ = ["Checked", "check_certificate", "cvc5_answer"]
