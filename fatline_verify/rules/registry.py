"""Rule sets by name: what a robot decides from what it sees, one registered entry each.

A model file names its rule set at the top level (``rules = "paper"``). A rule set declares its own
options and names the others it reads (``RuleSet(options=...)``: the paper's readings belong to the paper's
rule set, the repairs to the repaired one; a rule set of one's own reads none of them, and may declare
options of its own), its decision function, how its pictures are drawn and whether the prover encodes it:
``fatline prove`` refuses a rule set without an encoding, by construction, rather than proving it
against another rule set's case table.

Rule sets come from this package (:data:`BUILTIN`) and from installed packages that declare an entry
point in the group ``fatline.plugins`` (see the README, "Plug-ins: your own rule set, lemma or
scheduler"): the entry point names a module whose import calls :func:`register`, or a callable that
does when called.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from ..errors import InvalidModel
from ..lemmas.properties import CHECKED, SAFETY, Lemma
from ..model import options as catalogue
from ..model.option_spec import OptionSpec
from ..model.options import MODEL_OPTIONS
from ..model.seams import Param, declared

Model = Any
"""A :class:`fatline_verify.model.config.Model` (not imported: the model package imports this one)."""
Point = tuple[Any, Any]

Decide = Callable[[Sequence[Point], Model], Any]
"""``decide(snapshot, model) -> Decision``: the robot at the origin, ``snapshot`` the robots it sees
(relative positions, lattice units). The result needs ``rule``, ``destination``, ``path`` and
``moves`` as :class:`fatline_verify.rules.paper.algorithm.Decision` has them."""

GROUP = "fatline.plugins"
"""The entry-point group a plug-in package declares."""

BUILTIN = (
    "fatline_verify.rules.family.enforce",
    "fatline_verify.rules.paper.rule_set",
    "fatline_verify.rules.repaired.rule_set",
    "fatline_verify.rules.certified.rule_set",
    "fatline_verify.rules.table.rule_set",
    "fatline_verify.rules.published.ando",
    "fatline_verify.rules.published.gravity",
    "fatline_verify.rules.published.universal",
)
"""The modules that register this package's own rule sets (and the lemma that holds a rule set to its family)."""


@dataclass(frozen=True, slots=True)
class Encoding:
    """The prover's encoding of one rule set's rules: the obligations it builds (:attr:`name`: ``"paper"``,
    the paper's decision cases; ``"legs"``, the repaired rules' legs) and the decision function it is an
    encoding **of**. A rule set carries the object itself (:attr:`RuleSet.prover`); the prover uses it only
    for a rule set whose ``decide`` is that function (:func:`encoding_of`), so no rule set borrows another's
    proofs by naming them."""

    name: str
    says: str
    encodes: Decide = field(repr=False)
    """The decision function the obligations encode (identity is what is checked)."""


ENCODINGS: dict[str, Encoding] = {}
"""This package's encodings by name (filled by the rule sets that own them, :func:`register_encoding`)."""


def register_encoding(encoding: Encoding) -> Encoding:
    """Name ``encoding`` (once) so that error messages can say what each name encodes."""
    ENCODINGS.setdefault(encoding.name, encoding)
    return encoding


def _where(fn: Any) -> str:
    return f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', repr(fn))}"


def encoding_of(rule_set: RuleSet, model: Model | None = None) -> Encoding | None:
    """The prover's encoding of ``rule_set`` (``None``: it has none), refused in one line
    (:class:`InvalidModel`) when it is not an encoding of this rule set's own decision function: a name
    (``prover="paper"``, the API before encodings were objects) or another rule set's encoding object
    stands for another ``decide``, whose proofs say nothing of this one. ``model``: a model whose
    ``algorithm`` replaces the rule set's ``decide`` (seeded-bug tests) is refused likewise."""
    claimed = rule_set.prover
    if claimed is None:
        return None
    _load(plugins=False)
    encoding = ENCODINGS.get(claimed) if isinstance(claimed, str) else claimed
    if not isinstance(encoding, Encoding):
        raise InvalidModel(
            f"rules={rule_set.name!r}: prover={claimed!r} is not an encoding; expected None or an Encoding object "
            f"(fatline_verify.rules.registry.Encoding) of this rule set's own decide"
        )
    decide = model.algorithm if model is not None and model.algorithm is not None else rule_set.decide
    if encoding.encodes is not decide:
        named = f"prover={claimed!r}" if isinstance(claimed, str) else f"prover=Encoding({encoding.name!r})"
        raise InvalidModel(
            f"rules={rule_set.name!r}: {named} is the encoding of {_where(encoding.encodes)}, not of this rule "
            f"set's decide ({_where(decide)}); a rule set cannot claim another's proofs. Set prover=None (fatline "
            "check still checks every lemma; fatline prove decides the liveness obligations a rule set declares)"
        )
    return encoding


@dataclass(frozen=True, slots=True)
class Liveness:
    """What a rule set declares so that ``fatline prove`` can state its liveness obligations
    (:mod:`fatline_verify.prove.live`): its decision cases encoded for the solver, and a ranking measure.

    The measure is lexicographic, each component a sum over the robots of an integer-linear function
    of the robot's own centre in lattice units, ``a * X + b * Y`` for a component ``(a, b)``. A move
    must make the mover's own term fall, lexicographically, by at least one lattice unit; since the
    lexicographic order of integer vectors is compatible with addition, the moves of any set of
    movers in one round then make the sum fall too (the argument of the obligations' headers)."""

    encoding: str | Callable[..., Any]
    """The decision cases for the solver: ``"module:function"`` (imported by the prover only, so
    this package's rule sets never import z3 here) or the function itself (a plug-in's). Called as
    ``function(model)``, it returns :class:`fatline_verify.prove.smt.live_rules.LiveCase` s, every
    decision of the rule set in exactly one of them."""
    measure: tuple[tuple[int, int], ...]
    """The components ``(a, b)`` of the lexicographic measure, most significant first."""
    words: str
    """The measure in words (written in each measure obligation's header)."""
    bounded: str
    """Why the rule set's author thinks each component's sum is bounded below on the configurations the
    rules reach (written in the measure obligations' headers; what the tool accepts as a bound is only
    what its own obligations prove, :func:`fatline_verify.prove.coverage.measure_bounds`)."""
    bounded_proved: bool = False
    """Not believed (the field is kept so that rule sets written against the earlier API still load): a
    component's bound counts only where an obligation of the rule set's own proves it
    (:func:`fatline_verify.prove.coverage.measure_bounds`), whatever this says."""


@dataclass(frozen=True, slots=True)
class RuleSet:
    """One rule set: its name, its decision function and what it declares about itself."""

    name: str
    decide: Decide = field(repr=False)
    summary: str
    options: tuple[OptionSpec | str, ...] | frozenset[str] = ()
    """The options it reads beside :data:`MODEL_OPTIONS`, in the order ``fatline explain`` lists them: each
    one it declares, an :class:`~fatline_verify.model.option_spec.OptionSpec` (``spec(name, enum, quote,
    readings)``: its own, added to the catalogue when it registers), or the name of one the model layer or
    an earlier rule set declares (``"visibility"``; the repaired rule set names the paper's readings). A
    model setting any other option is refused; its decision function reads each as ``model.options.NAME``.
    (A frozenset of names, the API before rule sets declared options, still works.)"""
    prover: Encoding | str | None = None
    """The prover's encoding of these rules, an :class:`Encoding` of this rule set's own ``decide``
    (the paper's decision cases; the repaired rules' legs); ``None``: ``fatline prove`` refuses the rule
    set's safety lemmas. A name (``"paper"``) or an encoding of another ``decide`` is refused by
    :func:`encoding_of`, the only way the prover reads this field."""
    bands: bool = False
    """Whether pictures shade the acting robot's bands A ... I (the paper's sets)."""
    labels: dict[str, str] = field(default_factory=dict, repr=False, compare=False)
    """What each rule label its decision function returns means (shown beside a deadlock's rules)."""
    liveness: Liveness | None = field(default=None, compare=False)
    """What the liveness obligations need (``None``: ``fatline prove`` has none for this rule set)."""
    lemmas: tuple[str, ...] | None = None
    """The checker's built-in lemmas that apply to this rule set, by name (``None``: all six, the paper's
    setting). A rule set that does not claim Lemma 3, say, leaves ``rma-fixed`` (and ``approach``, which is
    stated against the RMA) out: it is then neither judged nor reported, and its violations never stop a
    search or a simulation. Registered step lemmas (:mod:`fatline_verify.lemmas.registry`) are judged
    for every rule set, as before."""
    safety: tuple[str, ...] | None = None
    """The step lemmas whose violating steps the search does not follow (``None``: every applicable one:
    ``no-collision``, ``connectivity``, ``rma-fixed``). A lemma left out is still judged, and its
    violations found, but the search goes on past them, as ``--after-violation continue`` does for all."""

    goal: str | None = None
    """The registered goal (:mod:`fatline_verify.goals`) this rule set is for, by name: what a model of it
    takes when its file sets no ``goal`` option (``None``: the option's default, the paper's
    ``vertical-line``). The liveness lemmas (progress, approach, termination) are judged against the
    model's goal."""
    robots: str = "discs"
    """What a robot is: ``"discs"`` (the paper's fat robots of one radius) or ``"points"``. For points
    ``no-collision`` does not apply (robots may share a point) and an initial configuration needs only
    distinct positions, not centres ``delta`` apart."""

    def applies(self) -> tuple[Lemma, ...]:
        """The built-in lemmas judged for this rule set, in report order (never ``no-collision`` for points)."""
        found = CHECKED if self.lemmas is None else tuple(lemma for lemma in CHECKED if lemma.value in self.lemmas)
        if self.robots == "points":
            found = tuple(lemma for lemma in found if lemma is not Lemma.NO_COLLISION)
        return found

    def prunes(self) -> tuple[Lemma, ...]:
        """The step lemmas whose violating steps are not followed."""
        step = tuple(lemma for lemma in self.applies() if lemma in SAFETY)
        return step if self.safety is None else tuple(lemma for lemma in step if lemma.value in self.safety)

    def check_setting(self) -> None:
        """Refuse, in one line, a setting that names no lemma of the checker or prunes one that does not apply."""
        declared(self)  # parameters a dict of names to Param, or one line
        if isinstance(self.options, str) or not isinstance(self.options, tuple | list | set | frozenset):
            raise ValueError(
                f"rule set {self.name!r}: options={self.options!r}: expected a tuple of option declarations "
                "(fatline_verify.model.option_spec.spec) and names"
            )
        if self.robots not in ("discs", "points"):
            raise ValueError(f"rule set {self.name!r}: robots={self.robots!r}: expected 'discs' or 'points'")
        if self.goal is not None and not isinstance(self.goal, str):
            raise ValueError(f"rule set {self.name!r}: goal={self.goal!r}: expected the name of a registered goal")
        if self.robots == "points" and self.lemmas is not None and Lemma.NO_COLLISION.value in self.lemmas:
            raise ValueError(
                f"rule set {self.name!r}: lemmas names 'no-collision' with robots='points': point robots may share "
                "a point, so there is no collision to judge; expected robots='discs' or no-collision left out"
            )
        known = {lemma.value for lemma in CHECKED}
        for name, given in (("lemmas", self.lemmas), ("safety", self.safety)):
            if given is None:
                continue
            if isinstance(given, str) or not all(isinstance(x, str) for x in given):
                raise ValueError(f"rule set {self.name!r}: {name}={given!r}: expected a tuple of lemma names")
            bad = sorted(set(given) - known)
            if bad:
                raise ValueError(
                    f"rule set {self.name!r}: {name}={bad[0]!r}: not a lemma of the checker; expected some of "
                    f"{', '.join(sorted(known))}"
                )
        if self.safety is not None:
            step = {lemma.value for lemma in self.applies() if lemma in SAFETY}
            extra = sorted(set(self.safety) - step)
            if extra:
                raise ValueError(
                    f"rule set {self.name!r}: safety={extra[0]!r}: not one of its applicable step lemmas; expected "
                    f"some of {', '.join(sorted(step)) or 'none'}"
                )

    family: Any = field(default=None, repr=False, compare=False)
    """Its move family (:class:`fatline_verify.rules.family.MoveFamily`, or a function of the model giving one
    or ``None``): every decision is held to it as the rule set runs (the step lemma ``in-family``), and
    ``fatline prove`` proves no-collision and connectivity from it for every swarm size, whatever the policy
    of ``decide`` (:mod:`fatline_verify.prove.smt.family`). ``None``: no family."""

    parameters: dict[str, Param] = field(default_factory=dict, repr=False, compare=False)
    """Parameters of its own (:mod:`fatline_verify.model.seams`), set in a model file's ``[rules]``
    table; its decision function reads their values as ``model.setting("rules")``."""

    def reads(self) -> tuple[str, ...]:
        """The names of the options it reads beside :data:`MODEL_OPTIONS` (its own and the others it names)."""
        return tuple(entry.name if isinstance(entry, OptionSpec) else entry for entry in self.options)

    def own_options(self) -> tuple[OptionSpec, ...]:
        """The options it declares."""
        return tuple(entry for entry in self.options if isinstance(entry, OptionSpec))

    def accepts(self, option: str) -> bool:
        """Whether a model of this rule set may set ``option``."""
        return option in MODEL_OPTIONS or option in self.reads()


_REGISTRY: dict[str, RuleSet] = {}
_loaded: set[str] = set()
"""What has been loaded: ``"builtin"`` (this package's rule sets), ``"plugins"`` (the entry points)."""


def register(rule_set: RuleSet) -> RuleSet:
    """Add ``rule_set`` (once per name: registering another under a taken name is an error; a setting
    that names a lemma the checker does not have is one too, :meth:`RuleSet.check_setting`) and the options
    it declares (:func:`fatline_verify.model.options.declare`: one it names must be declared already, one it
    declares must have a name of its own)."""
    rule_set.check_setting()
    known = _REGISTRY.get(rule_set.name)
    if known is not None and known != rule_set:
        raise ValueError(f"rule set {rule_set.name!r} is registered twice")
    catalogue.declare(rule_set.options, rule_set.name)
    _REGISTRY[rule_set.name] = rule_set
    claim("rules", rule_set.name)
    return rule_set


def _load(*, plugins: bool = True) -> None:
    """Load this package's rule sets, and (``plugins``) the installed plug-ins: scanning the entry
    points costs a tenth of a second, so a model of the package's own rule sets does without it."""
    if "builtin" not in _loaded:
        _loaded.add("builtin")
        for module in BUILTIN:
            importlib.import_module(module)
    if plugins and "plugins" not in _loaded:
        _loaded.add("plugins")
        load_plugins()


catalogue.add_completer(lambda: _load(plugins=False))
"""Reading the option catalogue loads this package's rule sets first, so that it lists the options they declare."""


@dataclass(frozen=True, slots=True)
class Provider:
    """The installed distribution whose entry point registered a plug-in (as ``importlib.metadata``
    names it): what a trace records, and what replay asks for when the plug-in is missing."""

    distribution: str
    version: str

    def __str__(self) -> str:
        return f"{self.distribution} {self.version}"


_PROVIDERS: dict[tuple[str, str], Provider] = {}
"""``(kind, name) -> Provider`` for everything an entry point registered; kind is ``"rules"``,
``"lemma"`` or ``"scheduler"``."""

_loading: list[Provider] = []
"""The distribution whose entry point is being loaded (what :func:`claim` attributes to)."""


def claim(kind: str, name: str) -> None:
    """Called by each registry's ``register``: remember that the entry point being loaded, if any,
    registered the ``kind`` called ``name``."""
    if _loading:
        _PROVIDERS.setdefault((kind, name), _loading[-1])


def load_plugins() -> None:
    """Import every ``fatline.plugins`` entry point (a module registers on import; a callable is called),
    and remember which distribution registered what (:func:`provider`)."""
    from importlib import metadata  # a twentieth of a second to import: only when plug-ins are asked for

    for ep in metadata.entry_points(group=GROUP):
        dist = ep.dist
        _loading.append(Provider(dist.name, dist.version) if dist is not None else Provider(ep.value.split(".")[0], ""))
        try:
            try:
                obj = ep.load()
            except Exception as exc:  # a broken plug-in is named, not a traceback
                why = f"{exc.__class__.__name__}: {exc}"[:200]
                raise InvalidModel(f"plugin {ep.name}={ep.value!r}: cannot be loaded ({why})") from None
            if callable(obj):
                obj()
        finally:
            _loading.pop()


def provider(kind: str, name: str) -> Provider | None:
    """The installed distribution that registered the ``kind`` (``"rules"``, ``"lemma"``,
    ``"scheduler"``) called ``name``; ``None`` for this package's own and for one registered in
    process (a test's)."""
    return _PROVIDERS.get((kind, name))


def names() -> tuple[str, ...]:
    """Every registered rule set's name, sorted."""
    _load()
    return tuple(sorted(_REGISTRY))


def get(name: str) -> RuleSet:
    """The rule set called ``name``, or a one-line :class:`InvalidModel`."""
    _load(plugins=False)
    if name not in _REGISTRY:
        _load()
    try:
        return _REGISTRY[name]
    except KeyError:
        raise InvalidModel(f"rules={name!r}: unknown rule set; expected one of {', '.join(names())}") from None


def of(model: Model) -> RuleSet:
    """The rule set ``model`` names."""
    return get(model.rules)


def decide(snapshot: Sequence[Point], model: Model) -> Any:
    """Compute for the robot at the origin: the model's own replacement (seeded-bug tests) or its rule set's."""
    if model.algorithm is not None:
        return model.algorithm(snapshot, model)
    return of(model).decide(snapshot, model)


def lemma_flags(model: Model) -> tuple[int, int]:
    """``(judged, pruned)``: the violation bits of ``model``'s rule set's applicable step lemmas, and of those
    whose violating steps the search does not follow (:meth:`RuleSet.prunes`)."""
    rule_set = of(model)
    judged = pruned = 0
    for lemma in rule_set.applies():
        judged |= lemma.flag
    for lemma in rule_set.prunes():
        pruned |= lemma.flag
    return judged, pruned


def applies(model: Model) -> tuple[Lemma, ...]:
    """The built-in lemmas judged for ``model`` (its rule set's :meth:`RuleSet.applies`)."""
    return of(model).applies()


def family(model: Model) -> Any:
    """The move family of ``model``'s rule set under ``model`` (``None``: it declares none, or not for
    these options); a declaration that is not a family is refused in one line."""
    from .family.family import family_of

    rule_set = of(model)
    try:
        return family_of(rule_set.family, model)
    except TypeError as exc:
        raise InvalidModel(f"rules={rule_set.name!r}: family: {exc}") from None


def decider(model: Model) -> Decide:
    """The decision function of ``model``, looked up once (engines call it per snapshot)."""
    return model.algorithm or of(model).decide


__all__ = [
    "BUILTIN",
    "ENCODINGS",
    "GROUP",
    "MODEL_OPTIONS",
    "Decide",
    "Encoding",
    "Liveness",
    "Provider",
    "RuleSet",
    "applies",
    "claim",
    "decide",
    "decider",
    "encoding_of",
    "family",
    "get",
    "lemma_flags",
    "load_plugins",
    "names",
    "of",
    "provider",
    "register",
    "register_encoding",
]
