"""Pictures of a trace, one per round, drawn with matplotlib as deterministic SVG.

Every picture is drawn from the *replayed* run, never from the trace's text: the discs to scale,
the acting robot's visibility circle with its bands A ... I shaded and labelled, each move as an
arrow along its path (the destination as a dotted disc), and the round's violation highlighted
(colliding discs in red with the closest squared distance, lost edges dashed, the RMA). A deadlock's
last picture says, per robot, which NoMovement bullet keeps it still, with the paper's words.
Floats are used for drawing only; captions show long numbers as short decimals (the exact values
are in the trace).
"""

from __future__ import annotations

import io
from fractions import Fraction
from typing import Any

import matplotlib

matplotlib.use("Agg")
import itertools

import matplotlib.pyplot as plt
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle

from ..goals.registry import missed
from ..model.config import Model
from ..model.options import Visibility
from ..rules import registry
from ..rules.paper.algorithm import Band
from ..rules.paper.options import Bands, Quadrants
from ..schedulers.base import Marks
from ..schedulers.round import Collision, Disconnection, RmaMoved
from ..schedulers.systems import system_for
from ..text import SHORT, stay_lines, violation_line
from ..trace.simulate import Run

plt.rcParams["svg.hashsalt"] = "fatline-verify"
plt.rcParams["svg.fonttype"] = "none"
plt.rcParams["font.size"] = 9

ACTING, ACTIVE, IDLE, BAD = "#f28e2b", "#ffd59e", "#d9d9d9", "#d62728"


def _f(v: Fraction | int) -> float:
    return float(v)


def _radii(model: Model, p: tuple[Any, Any]) -> tuple[float, float]:
    x, y = model.from_lattice(p)
    return _f(x), _f(y)


def _reach(model: Model) -> float:
    extra = {Visibility.CENTRE: 0, Visibility.ANY_PART: 1, Visibility.WHOLE_DISC: -1}[model.options.visibility]
    return float(model.parameters.rad_v) + extra


def _bands(ax: Any, centre: tuple[float, float], model: Model, clip: Circle) -> None:
    """Shade the acting robot's bands A/I (vertical) and C/F (horizontal), label every set."""
    cx, cy = centre
    reach = _reach(model)
    half = 2.0 if model.options.bands is Bands.DISC else 1.0
    for rect in (
        Rectangle((cx - half, cy - reach), 2 * half, 2 * reach),
        Rectangle((cx - reach, cy - half), 2 * reach, 2 * half),
    ):
        rect.set(facecolor="#4e79a7", alpha=0.10, edgecolor="none")
        ax.add_patch(rect)
        rect.set_clip_path(clip)
    d = reach * 0.78
    q = max(half + 0.6, reach * 0.6)  # inside a quadrant, clear of the bands
    labels = {Band.A: (0, d), Band.I: (0, -d), Band.C: (d, 0), Band.F: (-d, 0)}
    if model.options.quadrants is Quadrants.LOWER_RIGHT:
        labels.update({Band.B: (q, q), Band.D: (q, -q), Band.E: (-q, q), Band.G: (-q, -q)})
    else:
        labels.update({Band.B: (q, q), Band.D: (-q, q), Band.E: (-q, -q), Band.G: (q, -q)})
    for band, (dx, dy) in labels.items():
        ax.text(cx + dx, cy + dy, band.value, color="#4e79a7", ha="center", va="center", fontsize=11, alpha=0.8)


def frame_svg(run: Run, k: int, doc: dict[str, Any]) -> str:
    """The picture of round ``k`` (1-based) of a replayed run as SVG text; ``k = 0`` pictures the
    start alone, ``k = len(rounds) + 1`` the final state."""
    fig = frame_figure(run, k, doc)
    buf = io.StringIO()
    fig.savefig(buf, format="svg", metadata={"Date": None}, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def frame_figure(run: Run, k: int, doc: dict[str, Any]) -> Any:
    """The matplotlib figure of :func:`frame_svg` (the caller closes it)."""
    model = run.model
    n_rounds = len(run.rounds)
    fig, ax = plt.subplots(figsize=(5.2, 5.2))
    ax.set_aspect("equal")
    rnd = run.rounds[k - 1] if 1 <= k <= n_rounds else None
    state = rnd.before if rnd else (run.final if k > n_rounds else run.initial)
    pts = [_radii(model, p) for p in state]
    after = [_radii(model, p) for p in rnd.after] if rnd else pts
    marks = system_for(model).marks(rnd) if rnd else Marks(0)
    acting = marks.acting
    reach = _reach(model)
    size = 0.25 if model.points else 1.0  # a point robot is drawn as a dot, not a disc of one radius

    clip = Circle(pts[acting], reach, fill=False, ls="--", lw=1, color="#4e79a7")
    ax.add_patch(clip)
    if registry.of(model).bands:
        _bands(ax, pts[acting], model, clip)

    bad: set[int] = set()
    if rnd:
        for v in rnd.violations:
            if isinstance(v, Collision):
                bad.update(v.robots)
    for i, (x, y) in enumerate(pts):
        face = ACTING if i == acting and rnd else ACTIVE if rnd and i in rnd.active else IDLE
        edge = BAD if i in bad else "black"
        ax.add_patch(Circle((x, y), size, facecolor=face, edgecolor=edge, lw=2.2 if i in bad else 1.0, zorder=3))
        ax.text(x, y, f"r{i}", ha="center", va="center", zorder=4)
    for p in marks.ghosts:  # what the acting robot decided on, where it is no longer
        ax.add_patch(Circle(_radii(model, p), size, facecolor=IDLE, edgecolor="#999999", alpha=0.35, ls="--", zorder=2))
    for line in marks.remaining:  # moves under way: from where the robot is to its destination
        path = [_radii(model, p) for p in line]
        ax.plot([p[0] for p in path], [p[1] for p in path], ls="--", lw=1.2, color="#7f7f7f", zorder=4)
        ax.add_patch(Circle(path[-1], size, fill=False, ls=":", lw=1.0, edgecolor="#7f7f7f", zorder=2))
    if rnd:
        for line in marks.arrows:
            path = [_radii(model, p) for p in line]
            for a, b in itertools.pairwise(path):
                ax.add_patch(
                    FancyArrowPatch(a, b, arrowstyle="-|>", mutation_scale=14, lw=1.6, color="#333333", zorder=5)
                )
        for p in marks.targets:
            ax.add_patch(Circle(_radii(model, p), size, fill=False, ls=":", lw=1.2, edgecolor="#333333", zorder=2))
        for v in rnd.violations:
            if isinstance(v, Disconnection):
                for ea, eb in v.lost_edges:
                    ax.plot(
                        [after[ea][0], after[eb][0]], [after[ea][1], after[eb][1]], ls="--", color=BAD, lw=1.5, zorder=6
                    )
            if isinstance(v, RmaMoved):
                rma = _f(Fraction(v.rma_x) / model.radius)
                ax.axvline(rma, color=BAD, lw=1, ls="-.", zorder=1)
    extra = [_radii(model, p) for line in (*marks.remaining, *marks.arrows) for p in line]
    extra += [_radii(model, p) for p in (*marks.ghosts, *marks.targets)]
    xs = [p[0] for p in pts + after + extra] + [pts[acting][0] - reach, pts[acting][0] + reach]
    ys = [p[1] for p in pts + after + extra] + [pts[acting][1] - reach, pts[acting][1] + reach]
    ax.set_xlim(min(xs) - 1.5, max(xs) + 1.5)
    ax.set_ylim(min(ys) - 1.5, max(ys) + 1.5)
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.set_title(_title(run, doc, k, marks.note), fontsize=9, loc="left")
    return fig


def _title(run: Run, doc: dict[str, Any], k: int, note: str = "") -> str:
    """The caption of picture ``k``: the step's moves and violations, or how the trace ends."""
    n_rounds = len(run.rounds)
    if 1 <= k <= n_rounds:
        rec = doc["rounds"][k - 1]
        moves = "; ".join(
            f"r{d['robot']} {d['rule']} -> ({SHORT.coordinate(d['destination'][0])}, "
            f"{SHORT.coordinate(d['destination'][1])})"
            for d in rec["decisions"]
        )
        word = system_for(run.model).step_word
        lines = [f"{word} {k} of {n_rounds}: " + "; ".join(x for x in (note, moves) if x)]
        lines += [violation_line(v, SHORT) for v in rec["violations"]]
        return "\n".join(_wrap(line) for line in lines)
    if k == 0:
        return "start"
    tail = {
        "deadlock": f"deadlock: nobody moves, {missed(str(run.model.options.goal))}",
        "cycle": "the loop repeats forever",
        "goal": "goal reached",
        "violation": f"after the violating {system_for(run.model).step_word}",
        "round-limit": "end of trace",
    }
    v = doc.get("violation")
    lines = [f"end: {tail[doc['outcome']]}" + (f"; {violation_line(v, SHORT)}" if v else "")]
    if doc["outcome"] == "deadlock":
        lines += stay_lines(run.final, run.model)
    return "\n".join(_wrap(line) for line in lines)


def _wrap(text: str, width: int = 80) -> str:
    words, lines, line = text.split(" "), [], ""
    for w in words:
        if len(line) + len(w) + 1 > width and line:
            lines.append(line)
            line = w
        else:
            line = f"{line} {w}".strip()
    lines.append(line)
    return "\n".join(lines)


def frames(run: Run, doc: dict[str, Any]) -> list[str]:
    """All pictures of a trace: one per round, then the end state (the start alone if no round)."""
    if not run.rounds:
        return [frame_svg(run, 0, doc), frame_svg(run, 1, doc)]
    return [frame_svg(run, k, doc) for k in range(1, len(run.rounds) + 2)]
