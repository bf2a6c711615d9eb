"""The ``fatline`` command: a thin shell over the library.

Handlers take parsed arguments and return an exit code; every bad input is one line on stderr.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path

from . import __version__
from .config import Model, load_model, parse_robots, parse_window, shipped_models
from .errors import FatlineError, InvalidInput, TraceDidNotReproduce
from .numbers import parse_number
from .options import CATALOGUE, Scheduler
from .simulate import Outcome, simulate
from .swarm import State
from .text import check_lines, explain_lines, prove_lines, trace_lines
from .trace import check_replay, load_trace, run_to_json, write_json, write_trace

EXIT_OK, EXIT_FOUND, EXIT_BAD, EXIT_INCONCLUSIVE = 0, 1, 2, 3

EPILOG = """exit codes:
  0  everything asked holds (check: every lemma HOLDS_WITHIN_BOUNDS; simulate: no violation and no
     deadlock; replay: every trace reproduces)
  1  a violation or deadlock was found, or a trace did not reproduce
  2  bad input (malformed model, trace or argument) or an internal error
  3  check only: nothing violated, but some verdict is INCONCLUSIVE (a bound was hit)
"""


def _print(lines: Sequence[str]) -> None:
    sys.stdout.write("\n".join(lines) + ("\n" if lines else ""))


def parse_init(text: str, model: Model) -> State:
    """``"0,0 3,0 5/2,3"`` (robot radii) to lattice positions."""
    points = []
    for token in text.split():
        parts = token.split(",")
        if len(parts) != 2:
            raise InvalidInput(f"init={token!r}: expected a position x,y such as 3,0 or 5/2,-1")
        try:
            x = parse_number(parts[0], name="init x")
            y = parse_number(parts[1], name="init y")
        except ValueError:
            raise InvalidInput(
                f"init={token!r}: expected a position x,y of integers or fractions such as 3,0 or 5/2,-1"
            ) from None
        points.append(model.to_lattice((x, y)))
    if not points:
        raise InvalidInput(f"init={text!r}: expected at least one position x,y")
    return tuple(points)


def cmd_explain(args: argparse.Namespace) -> int:
    if args.option is not None and args.option not in CATALOGUE:
        raise InvalidInput(f"option={args.option!r}: unknown option; expected one of {', '.join(CATALOGUE)}")
    model = load_model(args.model) if args.model else None
    _print(explain_lines(args.option, model))
    return EXIT_OK


def cmd_models(args: argparse.Namespace) -> int:
    for path in shipped_models():
        model = load_model(path)
        print(f"{path.stem}: {model.description}")
        print(f"  {model.describe()}")
    return EXIT_OK


def cmd_simulate(args: argparse.Namespace) -> int:
    model = load_model(args.model)
    if args.rounds < 0:
        raise InvalidInput(f"rounds={args.rounds}: expected a number of rounds >= 0")
    initial = parse_init(args.init, model)
    scheduler = Scheduler(args.scheduler) if args.scheduler else model.options.scheduler
    run = simulate(initial, model, scheduler=scheduler, seed=args.seed, max_rounds=args.rounds)
    doc = run_to_json(run, {"tool": "fatline simulate", "scheduler": str(scheduler), "seed": args.seed})
    print(f"model {model.describe()}")
    print(f"scheduler {scheduler}, seed {args.seed}, at most {args.rounds} rounds")
    _print(trace_lines(doc))
    if args.trace:
        write_trace(doc, Path(args.trace))
        print(f"trace written to {args.trace}")
    return EXIT_FOUND if run.outcome in (Outcome.VIOLATION, Outcome.DEADLOCK) else EXIT_OK


def cmd_replay(args: argparse.Namespace) -> int:
    worst = EXIT_OK
    override = load_model(args.model) if args.model else None
    for name in args.traces:
        try:
            doc = load_trace(name)
            run = check_replay(doc, override)
        except TraceDidNotReproduce as exc:
            print(f"{name}: DID NOT REPRODUCE: {exc}")
            worst = max(worst, EXIT_FOUND)
            continue
        except FatlineError as exc:
            print(f"fatline: error: {exc}", file=sys.stderr)
            worst = EXIT_BAD
            continue
        v = doc["violation"]
        what = f"{doc['outcome']}" + (f" ({v['property']} in round {v['round']})" if v else "")
        print(f"{name}: reproduces: {len(run.rounds)} rounds, {what}")
        if args.verbose:
            _print(["  " + line for line in trace_lines(doc)])
        if args.picture:
            from .report.pictures import frames

            target = Path(args.picture)
            if target.exists() and not target.is_dir():
                raise InvalidInput(f"picture={args.picture!r}: exists and is not a directory; expected a directory")
            target.mkdir(parents=True, exist_ok=True)
            for k, svg in enumerate(frames(run, doc)):
                (target / f"{Path(name).stem}-{k}.svg").write_text(svg, encoding="utf-8")
            print(f"  pictures written to {target}")
    return worst


def cmd_check(args: argparse.Namespace) -> int:
    from .checker import check, check_to_json, write_witnesses

    model = load_model(args.model)
    robots = parse_robots(args.robots, error=InvalidInput) if args.robots else None
    window = parse_window(args.window, error=InvalidInput) if args.window else None
    if args.q is not None:
        model = _with_q(model, args.q)
    traces_dir = Path(args.traces)
    if traces_dir.exists() and not traces_dir.is_dir():
        raise InvalidInput(
            f"traces={args.traces!r}: exists and is not a directory; expected a directory for witness traces"
        )
    if args.json and Path(args.json).is_dir():
        raise InvalidInput(f"json={args.json!r}: is a directory; expected a file name")
    with _Progress(enabled=not args.quiet) as bar:
        result = check(
            model,
            robots,
            window,
            max_states=args.max_states,
            engine=args.engine,
            after_violation=args.after_violation,
            progress=bar.update,
        )
    paths = write_witnesses(result, traces_dir, f"{model.name}-")
    _print(check_lines(result, paths))
    if args.json:
        write_json(Path(args.json), check_to_json(result, paths))
        print(f"results written to {args.json}")
    if result.any_violated:
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if result.any_inconclusive else EXIT_OK


def cmd_prove(args: argparse.Namespace) -> int:
    from .prover import prove, prove_fingerprint, results_json, write_witnesses
    from .smt.obligations import LEMMAS

    model = load_model(args.model)
    if args.timeout <= 0:
        raise InvalidInput(f"timeout={args.timeout}: expected a positive number of seconds")
    if args.slots < 1:
        raise InvalidInput(f"slots={args.slots}: expected at least 1 slot robot")
    lemmas = LEMMAS if args.lemma == "all" else (args.lemma,)
    out = Path(args.out) / model.name
    if out.exists() and not out.is_dir():
        raise InvalidInput(f"out={args.out!r}: {out} is not a directory; expected a directory for proof artefacts")
    traces_dir = Path(args.traces) if args.traces else out / "traces"
    if traces_dir.exists() and not traces_dir.is_dir():
        raise InvalidInput(f"traces={str(traces_dir)!r}: exists and is not a directory; expected a directory")
    done = []

    def tick(label: str) -> None:
        done.append(label)
        if not args.quiet and sys.stderr.isatty():
            print(f"\r[{len(done)}] {label:60}", end="", file=sys.stderr, flush=True)

    results = prove(model, lemmas, slots=args.slots, timeout=args.timeout, out=out, jobs=args.jobs, progress=tick)
    if not args.quiet and sys.stderr.isatty():
        print(file=sys.stderr)
    traces = write_witnesses(model, results, traces_dir)

    data = {"fingerprint": prove_fingerprint(model, args.slots, args.timeout), **results_json(model, results, traces)}
    write_json(out / "results.json", data)
    _print(prove_lines(model, results, traces, out))
    if args.json:
        write_json(Path(args.json), data)
    if any(r.verdict.value == "VIOLATED" for r in results):
        return EXIT_FOUND
    return EXIT_INCONCLUSIVE if any(r.verdict.value == "INCONCLUSIVE" for r in results) else EXIT_OK


def cmd_report(args: argparse.Namespace) -> int:
    from .report.build import build_report

    specs = args.models or [p.stem for p in shipped_models()]
    models = [load_model(s) for s in specs]
    names = [m.name for m in models]
    if len(set(names)) != len(names):
        raise InvalidInput(f"models={specs}: two models share a name; expected distinct model names")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise InvalidInput(f"out={args.out!r}: exists and is not a directory; expected a directory for the reports")

    def tick(label: str) -> None:
        if not args.quiet:
            print(label, file=sys.stderr, flush=True)

    reports = build_report(
        models,
        out,
        proofs=Path(args.proofs),
        slots=args.slots,
        timeout=args.timeout,
        refresh=args.refresh,
        progress=tick,
    )
    for r in reports:
        print(f"{out / r.model.name / 'README.md'}: {len(r.traces)} counterexample traces")
    print(f"{out / 'index.html'} and {out / 'README.md'}: the readings x lemmas matrix")
    return EXIT_OK


def _with_q(model: Model, q: int) -> Model:
    from dataclasses import replace

    from .config import Parameters

    p = model.parameters
    return replace(model, parameters=Parameters(rad_v=p.rad_v, q=q, delta=p.delta))


class _Progress:
    """A progress bar on stderr (tqdm), shown only on a terminal."""

    def __init__(self, enabled: bool) -> None:
        self.enabled = enabled
        self.bar = None

    def __enter__(self) -> _Progress:
        if self.enabled:
            from tqdm import tqdm

            self.bar = tqdm(total=None, unit=" states", file=sys.stderr, disable=None, leave=False)
        return self

    def update(self, label: str, done: int, total: int) -> None:
        if self.bar is not None:
            self.bar.set_description(label)
            self.bar.n = total
            self.bar.refresh()

    def __exit__(self, *exc: object) -> None:
        if self.bar is not None:
            self.bar.close()


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="fatline",
        description="Verify 'Line Formation by Fat Robots under Limited Visibility' (Sil & Gan Chaudhuri).",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"fatline-verify {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    def add(name: str, help_text: str) -> argparse.ArgumentParser:
        return sub.add_parser(
            name,
            help=help_text,
            description=help_text,
            epilog=EPILOG,
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )

    p = add("explain", "print the paper's open points: quote, readings, default")
    p.add_argument("option", nargs="?", help="one option (default: all)")
    p.add_argument("--model", help="mark the readings this model file selects")
    p.set_defaults(handler=cmd_explain)

    p = add("models", "list the shipped model files")
    p.set_defaults(handler=cmd_models)

    p = add("check", "check every lemma on every small swarm and every activation set (bounded)")
    p.add_argument("model", nargs="?", default="paper", help="model file or shipped model name (default: paper)")
    p.add_argument("--robots", help="robot count or range, e.g. 3 or 2..4 (default: the model's bounds)")
    p.add_argument("--window", help="WIDTHxHEIGHT lattice points, e.g. 9x9 (default: the model's bounds)")
    p.add_argument("--q", type=int, help="lattice points per radius (default: the model's q)")
    p.add_argument("--max-states", type=int, help="stop a search after this many states (default: the model's)")
    p.add_argument("--engine", choices=["fast", "scalar"], default="fast", help="exploration engine (default fast)")
    p.add_argument(
        "--after-violation",
        choices=["stop", "continue"],
        default="stop",
        help="explore states reached through a violating round (default: stop)",
    )
    p.add_argument("--json", help="write the results as JSON to this file")
    p.add_argument("--traces", default="traces", help="directory for witness traces (default: traces)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=cmd_check)

    p = add("prove", "prove or refute the collision and connectivity lemmas per rule with z3, for any swarm size")
    p.add_argument("model", nargs="?", default="paper", help="model file or shipped model name (default: paper)")
    p.add_argument("--lemma", choices=["no-collision", "connectivity", "all"], default="all")
    p.add_argument("--timeout", type=float, default=10.0, help="solver seconds per obligation (default 10)")
    p.add_argument("--slots", type=int, default=3, help="symbolic robots besides r (default 3)")
    p.add_argument("--jobs", type=int, help="obligations solved at once (default: the number of cores)")
    p.add_argument("--out", default="proofs", help="directory for .smt2 files and results.json (default: proofs)")
    p.add_argument("--traces", help="directory for counterexample traces (default: OUT/MODEL/traces)")
    p.add_argument("--json", help="also write the results as JSON to this file")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress line")
    p.set_defaults(handler=cmd_prove)

    p = add("simulate", "run one swarm under a seeded, fair random scheduler")
    p.add_argument("model", nargs="?", default="paper", help="model file or shipped model name (default: paper)")
    p.add_argument("--init", required=True, help='initial centres in robot radii, e.g. "0,0 3,0 5/2,3"')
    p.add_argument("--scheduler", choices=[s.value for s in Scheduler], help="override the model's scheduler")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--rounds", type=int, default=100, help="stop after this many rounds (default 100)")
    p.add_argument("--trace", help="write the run as a trace JSON file")
    p.set_defaults(handler=cmd_simulate)

    p = add("replay", "recompute traces from their initial positions and compare every recorded value")
    p.add_argument("traces", nargs="+", metavar="TRACE")
    p.add_argument("--model", help="replay under this model instead of the trace's own")
    p.add_argument("-v", "--verbose", action="store_true", help="print every round")
    p.add_argument("--picture", metavar="DIR", help="write one SVG picture per round of each trace into DIR")
    p.set_defaults(handler=cmd_replay)

    p = add("report", "write per-model reports with pictures, the regression corpus and the readings x lemmas matrix")
    p.add_argument("models", nargs="*", metavar="MODEL", help="model files or names (default: every shipped model)")
    p.add_argument("--out", default="reports", help="report directory (default: reports)")
    p.add_argument("--proofs", default="proofs", help="prover artefacts directory (default: proofs)")
    p.add_argument("--slots", type=int, default=3, help="prover slot robots (default 3)")
    p.add_argument("--timeout", type=float, default=10.0, help="prover budget per obligation in seconds (default 10)")
    p.add_argument("--refresh", action="store_true", help="recompute results even when the cached ones are up to date")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    p.set_defaults(handler=cmd_report)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: parse, dispatch, turn every expected error into one line and exit 2."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse already printed its one-line usage error
        return int(exc.code or 0)
    try:
        return int(args.handler(args))
    except FatlineError as exc:
        print(f"fatline: error: {exc}", file=sys.stderr)
        return EXIT_BAD
    except KeyboardInterrupt:
        print("fatline: interrupted", file=sys.stderr)
        return EXIT_BAD
    except BrokenPipeError:
        return EXIT_OK
    except Exception as exc:  # a bug of the tool: one line, the traceback on request
        if os.environ.get("FATLINE_DEBUG"):
            raise
        print(
            f"fatline: internal error: {exc.__class__.__name__}: {exc} (set FATLINE_DEBUG=1 for the traceback)",
            file=sys.stderr,
        )
        return EXIT_BAD


def run() -> None:
    """Console-script wrapper."""
    sys.exit(main())


if __name__ == "__main__":
    run()
