"""``fatline prove``: the collision and connectivity lemmas per rule with z3, for any swarm size."""

from __future__ import annotations

import argparse
import time
from typing import Any

from ..junit import claim_junit, prove_suites, write_junit
from ..lemmas.properties import PROVED_LEMMAS, Lemma
from ..outputs import Kind, Output, child, claim_dir, claim_file, claim_files, distinct_outputs, write_json
from ..progress import Progress
from ..prove.text import prove_lines
from .common import (
    EXIT_FOUND,
    EXIT_INCONCLUSIVE,
    EXIT_INTERRUPTED,
    EXIT_OK,
    add_command,
    add_force,
    add_model_argument,
    check_cores,
    cores,
    emit,
    exit_codes,
    integer,
    model_arg,
    nonempty,
    seconds,
)

MAX_SLOTS = 8
MAX_JOBS = 256
LEMMA_CHOICES = PROVED_LEMMAS
"""The lemmas ``--lemma`` offers: the prover's (:data:`~fatline_verify.lemmas.properties.PROVED_LEMMAS`,
named without z3, so building the parser does not load it)."""
DEFAULT_SLOTS, DEFAULT_TIMEOUT = 3, 60.0
"""The prover's defaults (:data:`fatline_verify.prove.prover.DEFAULT_SLOTS`, ``DEFAULT_TIMEOUT``), named here
without importing z3 (a test keeps them equal)."""
ALL = "all"
"""``--lemma all``: every lemma the prover decides."""
LIVENESS = "liveness"
"""``--lemma liveness``: the liveness obligations (progress and termination)."""


def _coverage(text: str) -> int | None:
    """``--coverage``: ``all`` (every view, ``None``) or a sample size."""
    if text.strip() == "all":
        return None
    return integer("coverage", 1, 10**9, " or all")(text)


def cmd_prove(args: argparse.Namespace) -> int:
    check_cores(
        "jobs",
        args.jobs,
        "more solvers than cores only share them against each obligation's wall-clock budget, and rows that "
        "prove alone come out INCONCLUSIVE",
    )
    if args.with_ is not None:
        from .prove_whatif import cmd_prove_whatif

        return cmd_prove_whatif(args)  # what-if rows of their own: the shipped obligations untouched
    if args.q is not None:
        from ..errors import InvalidInput

        raise InvalidInput(f"q={args.q}: --q sets the lattice of the --with obligations; expected --with")
    from ..prove.known import read_known, unused_line
    from ..prove.prover import LEMMAS, prove, task_key, tasks_for
    from ..prove.results import ProofResults
    from ..prove.tasks import CoverageSpec, ViewsSpec

    model = model_arg(args.model)
    if args.emit is not None:
        return _emit(args, model)
    if args.lemma == LIVENESS:
        lemmas: tuple[Lemma, ...] = (Lemma.PROGRESS, Lemma.TERMINATION)
    else:
        lemmas = LEMMAS if args.lemma == ALL else (Lemma(args.lemma),)
    tasks = tasks_for(
        model, lemmas, two_movers=args.two_movers
    )  # refuses a scheduler the obligations do not encode, before any work
    if not tasks:  # an empty table reads as "everything asked holds"
        from ..errors import InvalidInput

        has = sorted({str(t.lemma) for t in tasks_for(model)})
        raise InvalidInput(
            f"--lemma {args.lemma}: model {model.name} has no obligation for it; expected one of {', '.join(has)}"
        )
    if args.coverage != CoverageSpec().views:  # every view, or another sample
        tasks = [CoverageSpec(args.coverage) if isinstance(t, CoverageSpec) else t for t in tasks]
    if args.views is not None:  # a sample of views for the in-family rows
        tasks = [ViewsSpec(t.lemma, sample=args.views) if isinstance(t, ViewsSpec) else t for t in tasks]
    every = tasks_for(model) if args.known else []  # what a trace may decide, whatever --lemma this run asks for
    known = [read_known(model, name, every) for name in args.known]  # one no obligation can use: exit 2
    given = [(k.name, k.radii) for k in known if k.deadlock is None]
    deadlocks = [k.deadlock for k in known if k.deadlock is not None]
    root = claim_dir(args.out, name="out")
    out = claim_dir(child(root, model.name), name="out")
    traces_dir = claim_dir(args.traces, name="traces") if args.traces is not None else out / "traces"
    json_path = claim_file(args.json, name="json", kind=Kind.PROVE, force=args.force) if args.json else None
    junit_path = claim_junit(args.junit, force=args.force) if args.junit else None
    distinct_outputs(
        [
            Output("out", out, directory=True),
            Output("traces", traces_dir, directory=True),
            Output("json", json_path),
            Output("junit", junit_path),
        ],
        [("model", args.model), *(("known", name) for name in args.known)],
    )
    claim_files([out / "results.json"], name="out", kind=Kind.PROVE, force=args.force)
    store = ProofResults(model, out, traces_dir, slots=args.slots, timeout=args.timeout)
    if args.redo_inconclusive:
        tasks = [t for t in tasks if store.verdict(t) in (None, "INCONCLUSIVE")]
    everything = args.fresh or args.redo_inconclusive or args.no_corpus or bool(args.known)
    todo = tasks if everything else [t for t in tasks if store.fresh(t) is None]  # a current row is not solved again
    for task in tasks:
        store.digest(task)  # each row records the fingerprint of the task asked for (--coverage's sample)
    claim_files(store.witness_paths(todo), name="traces", kind=Kind.TRACE, force=args.force)

    interrupted = False
    running: dict[str, float] = {}

    def begun(key: str) -> None:
        running[key] = time.monotonic()

    def finished(key: str) -> None:
        running.pop(key, None)
        bar.step(key)

    with Progress(enabled=not args.quiet, unit="obligations") as bar:
        # No rate or ETA: one obligation takes a tenth of a second, the next a minute; the seconds spent
        # on each one running say whether the run is moving.
        bar.stage(f"{model.name}: proving", total=len(todo), eta=False, live=lambda: running_note(running))
        try:
            prove(
                model,
                slots=args.slots,
                timeout=args.timeout,
                out=out,
                jobs=args.jobs,
                tasks=todo,
                on_result=store.add,
                progress=finished,
                traces=traces_dir,
                earlier=store.rows,
                given=given,
                on_start=begun,
                corpus=not args.no_corpus,
                deadlocks=deadlocks,
            )
        except KeyboardInterrupt:
            interrupted = True
    keys = [task_key(t) for t in tasks if task_key(t) in store.rows]
    rows = store.shown(keys)  # a row this run did not make current (interrupted) reads STALE
    lines = prove_lines(model, rows, out, verbose=args.verbose)
    if not interrupted:  # every trace given is used by a row, or said not to be
        lines += [line for k in known if (line := unused_line(k, tasks, rows))]
    if interrupted:
        lines.append(f"INTERRUPTED: {len(rows)} of {len(tasks)} obligations finished and saved in {store.path}")
    emit(lines)  # the verdicts before the --json file: a full disk does not hide them
    if json_path is not None:
        write_json(json_path, store.document(keys))
    if junit_path is not None:
        write_junit(junit_path, prove_suites(model, rows), name=f"fatline prove {model.name}")
        emit([f"JUnit XML written to {junit_path}"])
    if interrupted:
        return EXIT_INTERRUPTED
    if any(r["verdict"] == "VIOLATED" for r in rows):
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if any(r["verdict"] == "INCONCLUSIVE" for r in rows) else EXIT_OK


def _emit(args: argparse.Namespace, model: Any) -> int:
    """``--emit DIR``: every obligation's SMT-LIB2 under ``DIR/MODEL``, checked against its row's digest
    (exit 0: every one matches; 1: one differs or its row has no digest or no row)."""
    from ..errors import InvalidInput
    from ..prove.emit import MATCH, emit_lines, is_obligation, obligation_path
    from ..prove.emit import emit as emit_obligations
    from ..prove.prover import LEMMAS, tasks_for
    from ..prove.results import ProofResults

    if args.lemma == LIVENESS:
        lemmas: tuple[Lemma, ...] = (Lemma.PROGRESS, Lemma.TERMINATION)
    else:
        lemmas = LEMMAS if args.lemma == ALL else (Lemma(args.lemma),)
    tasks = tasks_for(model, lemmas, two_movers=args.two_movers)
    target = claim_dir(child(claim_dir(args.emit, name="emit"), model.name), name="emit")
    results = child(claim_dir(args.out, name="out"), model.name)
    if target.resolve() == results.resolve():
        raise InvalidInput(f"emit={args.emit!r}: is --out; expected another directory (the rows stay as they are)")
    for task in tasks:  # nothing overwritten that is not an obligation file, before any work
        path = target / obligation_path(task)
        if path.exists() and not args.force and not (path.is_file() and is_obligation(path)):
            raise InvalidInput(
                f"emit={path.as_posix()!r}: exists and is not an SMT-LIB2 obligation; expected it moved away "
                "(or --force to overwrite it)"
            )
    store = ProofResults(model, results, results / "traces", slots=args.slots, timeout=args.timeout)
    done = emit_obligations(model, tasks, store.rows, target, slots=args.slots)
    emit(emit_lines(done, target))
    return EXIT_OK if all(e.status == MATCH for e in done) else EXIT_FOUND


def running_note(running: dict[str, float], shown: int = 2) -> str:
    """The obligations running now, longest first, with the seconds each has taken so far."""
    now = time.monotonic()
    by_age = sorted(dict(running).items(), key=lambda item: item[1])
    text = ", ".join(f"{key} for {now - t0:.0f} s" for key, t0 in by_age[:shown])
    more = len(by_age) - shown
    return ("running " + text + (f" and {more} more" if more > 0 else "")) if text else ""


def register(sub: Any) -> None:
    p = add_command(
        sub,
        "prove",
        "prove (for any swarm size) or refute each lemma per decision case with z3",
        exit_codes(
            "every obligation PROVED",
            "an obligation is VIOLATED (a replayed counterexample for each)",
            "nothing violated, but some obligation is INCONCLUSIVE (the reason in its row)",
            kept=True,
        ),
    )
    add_model_argument(p)
    p.add_argument("--lemma", choices=[*(lemma.value for lemma in LEMMA_CHOICES), LIVENESS, ALL], default=ALL)
    p.add_argument(
        "--timeout",
        type=seconds("timeout"),
        default=DEFAULT_TIMEOUT,
        help="solver seconds per obligation, spent in rounds of 2, 8, ... s until an answer (default 60)",
    )
    p.add_argument(
        "--coverage",
        type=_coverage,
        default=20_000,
        metavar="all|N",
        help="the liveness cases held to decide on N random views of the model's lattice (default 20000: the "
        "row is then INCONCLUSIVE at best, and so progress and termination are NOT PROVED) or on every view "
        "(all: the only way they can be PROVED; at q=1, rad_v=4 1,624,375 views, about 5 minutes on 2 cores)",
    )
    p.add_argument(
        "--views",
        type=integer("views", 1, 10**9),
        default=None,
        metavar="N",
        help="a move family's in-family rows: decide on N random views of the lattice (the rows are then "
        "INCONCLUSIVE at best, and no-collision and connectivity NOT PROVED) instead of every view (the default "
        "when the lattice has at most 3,000,000 views: at q=1, rad_v=4 1,624,375 views, about 40 s)",
    )
    p.add_argument(
        "--slots",
        type=integer("slots", 1, MAX_SLOTS),
        default=DEFAULT_SLOTS,
        help="robots besides r in the global connectivity form (default 3)",
    )
    p.add_argument(
        "--jobs",
        type=integer("jobs", 1, MAX_JOBS),
        default=cores(),
        help="obligations solved at once, at most the number of cores (default: the number of cores)",
    )
    p.add_argument(
        "--out",
        default="proofs",
        type=nonempty("out", "a directory for proof artefacts"),
        help="directory for .smt2 files and results.json (default: proofs)",
    )
    p.add_argument(
        "--traces",
        type=nonempty("traces", "a directory for counterexample traces"),
        help="directory for counterexample traces (default: OUT/MODEL/traces)",
    )
    p.add_argument(
        "--json", type=nonempty("json", "a file name for the JSON results"), help="also write the results as JSON"
    )
    p.add_argument(
        "--junit",
        metavar="FILE",
        type=nonempty("junit", "a file name for the JUnit XML report"),
        help="also write a JUnit XML report: one test case per obligation (VIOLATED a failure, INCONCLUSIVE "
        "skipped with its reason), its solver seconds",
    )
    p.add_argument(
        "--two-movers",
        action="store_true",
        help="also the two-mover obligations (a pair of rules each, lattice searches only)",
    )
    p.add_argument(
        "--fresh",
        action="store_true",
        help="solve every obligation asked for (by default one whose row in OUT/MODEL/results.json is current, its "
        "fingerprint that of the code, model, settings and solver of this run, is shown as it is, not solved again; "
        "--known, --no-corpus and --redo-inconclusive solve what they ask for afresh too)",
    )
    p.add_argument(
        "--emit",
        metavar="DIR",
        type=nonempty("emit", "a directory for the SMT-LIB2 obligations"),
        help="instead of proving: write every obligation asked for (--lemma, --two-movers) as SMT-LIB2 under "
        "DIR/MODEL, regenerated from the code, and check each against the digest its row in OUT/MODEL/results.json "
        "recorded (exit 1 if one differs or has none); nothing is solved",
    )
    p.add_argument(
        "--redo-inconclusive",
        action="store_true",
        help="only the obligations whose row in OUT/MODEL/results.json is INCONCLUSIVE or missing, each solved again "
        "even if current; every other row is kept as it is (shown STALE if its fingerprint is not current)",
    )
    p.add_argument(
        "--known",
        nargs="+",
        action="extend",
        default=[],
        metavar="TRACE",
        help="counterexamples found elsewhere (fatline simulate --trace, fatline check --traces), each replayed by "
        "this model first: a violation's initial configuration is replayed against every per-case obligation "
        "before any search, every robot tried as r (one that decides the case and breaks the claim is VIOLATED, "
        "its source named); a deadlock (connected, not a line, reached after any number of rounds) VIOLATES the "
        "enabledness row of the case its stuck left-most robot decides, and so progress and termination. A trace "
        "of another rule set, of another outcome, or that does not replay is refused; one no row used is named",
    )
    p.add_argument(
        "--with",
        dest="with_",
        metavar="KINDS",
        help="what-if: instead, the obligations of the legs fatline reach --with adds (left or left-alone, corner; "
        "comma-separated), decided on the lattice and replayed by reach's family; rows in "
        "OUT/MODEL/whatif-KINDS-qQ.json",
    )
    p.add_argument(
        "--q",
        type=integer("q", 1, 4),
        help="with --with: lattice points per radius of those obligations (default: the model's q)",
    )
    p.add_argument(
        "--no-corpus",
        action="store_true",
        help="leave out the counterexample corpus shipped with the tool (by default replayed before any search; "
        "each row says whether the search, the corpus, an earlier run or --known decided it)",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    p.add_argument(
        "-v",
        "--verbose",
        action="store_true",
        help="every field of each row: lemma, form, case, the robots its case names, the reason in full, the trace "
        "(the default row: obligation, verdict, seconds, a short reason)",
    )
    add_force(p)
    p.set_defaults(handler=cmd_prove)
