"""How good the error estimates are: their effectivity on the closed forms.

The effectivity of an estimate is the estimate over the true error: 1 is a
perfect estimate, below 1 an optimistic one.  For the Richardson estimate
(:mod:`contactcore.estimate`) it is taken per profile quantity as the RMS
of the estimated error over the RMS of the true error of the finer run
(the closed form sampled by the same code as the method); for the
Zienkiewicz–Zhu estimate as ``η / ‖σ − σ_h‖_E``, on the same background
cells (the truth with more Gauss points, :data:`TRUE_GAUSS`), away from
singular points (:func:`verification.agreement.default_exclusion`).
A quantity whose true error is at round-off (``NEGLIGIBLE_SHARE`` of its
largest exact value), or whose exact value is zero, has no effectivity: its
row says so.

Cases: the interface patch, the pressurised and the twisted rod, the
quadratic layers (shear) and the layered Coulomb slip, each with profiles
through Γ and the bulk; every method and degree at the two finest rungs of
its rate test (``LADDERS``).

The paper's scenes (:func:`scene_table`, ``python -m verification
effectivity``) have no closed form: there the truth is fe P2 at a fine
``ref_h``, and both RMS are over the samples the estimate keeps
(``Estimate.kept``): away from singular points
(:func:`verification.agreement.default_exclusion`) and beyond the
coarse run's reach of them (:func:`contactcore.estimate.beyond_reach`);
a true error at round-off there has no effectivity either (``at_roundoff``).
"""
from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np

from contactcore import InterfaceProfile, LineProfile, ProfileData, sample_profiles, scene_text
from contactcore import estimate as est
from contactcore import tolerances as tol
from contactcore.budget import check_budget
from contactcore.estimate.caveats import ENERGY_KEY
from contactcore.discretisation import solve
from contactcore.scaling import Sizes

from . import methods
from . import files
from .agreement import default_exclusion
from .closed_forms import interface_patch, layered_slip, pressurised_rod, quadratic_layers, twisted_rod
from .sweeps import PATCH_PINS

#: Gauss points per direction of the true energy error ``‖σ − σ_h‖_E``:
#: more than the estimate's own rule (contactcore.tolerances.ENERGY_GAUSS),
#: so that the truth is not integrated as coarsely as the estimate.
TRUE_GAUSS = 4

BULK = ("ux", "uy", "sxx", "syy", "sxy")
GAMMA = ("gN", "gT", "tN", "tT")


def _with_profiles(case, *profiles):
    case.scene = case.scene.with_changes(profiles=profiles)
    return case


#: Case name -> the closed form with its profiles (quantities whose exact
#: value is zero left out where a profile can choose).
CASES = {
    "patch": lambda: _with_profiles(interface_patch(30.0, pins=PATCH_PINS),
                                    InterfaceProfile("gamma", GAMMA, parameter="arclength"),
                                    LineProfile("line", (0.05, 0.2), (0.95, 0.8), BULK)),
    "pressurised_rod": lambda: _with_profiles(pressurised_rod(), InterfaceProfile("gamma", ("gN", "tN")),
                                              LineProfile("radial", (0.0, 0.0), (1.0, 0.0), ("ux", "sxx", "syy"))),
    "twisted_rod": lambda: _with_profiles(twisted_rod(), InterfaceProfile("gamma", ("gT", "tT")),
                                          LineProfile("radial", (0.0, 0.0), (1.0, 0.0), ("uy", "sxy"))),
    "quadratic_layers": lambda: _with_profiles(quadratic_layers("shear"),
                                               InterfaceProfile("gamma", ("gT", "tT"), parameter="arclength"),
                                               LineProfile("vertical", (0.5, 0.0), (0.5, 1.0), ("ux", "sxy"))),
    "layered_slip": layered_slip,
}

#: (method, degree) -> (discretisation options, h of the two finest rungs of
#: its rate tests (tests/test_contract.py's rod ladders, tests/
#: test_verification.py's twisted rod), per case where they differ).
VARIANTS = {
    ("fe", 1): ({}, {"default": (0.1, 0.05)}),
    ("fe", 2): ({}, {"default": (0.1, 0.05)}),
    ("xfem", 1): ({}, {"default": (0.1, 0.05)}),
    ("xfem", 2): ({}, {"default": (0.1, 0.05), "pressurised_rod": (0.05, 0.025)}),
    ("efgm", 1): ({}, {"default": (0.05, 0.025)}),
    ("efgm", 2): ({"gauss": 12}, {"default": (0.1, 0.05)}),
}


def rungs(case: str, key: tuple) -> tuple[float, float]:
    """The h of the two rungs (coarse, fine) at which variant ``key``
    (method, degree) runs closed-form ``case``: :data:`VARIANTS`' own for
    the case, else its default."""
    ladders = VARIANTS[key][1]
    return ladders.get(case, ladders["default"])


def exact_profiles(case) -> dict[str, ProfileData]:
    """The closed form's profiles, sampled as a method's are (the layered
    slip's Γ from its final state: its law has history)."""
    scene = case.scene
    if not hasattr(case, "history"):
        return {p.id: p for p in sample_profiles(scene, case)}
    state = case.history()[-1]
    fields = case.fields(state)
    out = {}
    for prof in scene.profiles:
        if set(prof.quantities) <= set(BULK):
            out[prof.id] = sample_profiles(scene.with_changes(profiles=(prof,)), fields)[0]
            continue
        line = scene.with_changes(profiles=(LineProfile(prof.id, prof.start, prof.end, ("ux",)),))
        s = sample_profiles(line, fields)[0]
        n = len(s.columns["s"])
        values = {"gN": -state.p / case.kN, "gT": state.tau / case.kT + state.slip, "tN": -state.p,
                  "tT": state.tau}
        out[prof.id] = ProfileData(prof.id, s.parameter, {**{k: s.columns[k] for k in ("s", "x", "y")},
                                                          **{q: np.full(n, values[q]) for q in prof.quantities}})
    return out


def profile_rows(estimate: est.Estimate, got: dict, exact: dict) -> list[dict]:
    """One row per profile quantity: estimated and true RMS error of the
    finer run and the effectivity (None at round-off or for a zero)."""
    rows = []
    for pid, qs in estimate.profiles.items():
        for q, e in qs.items():
            want = exact[pid].columns[q]
            true = float(np.sqrt(np.mean((got[pid].columns[q] - want) ** 2)))
            scale = float(np.max(np.abs(want)))
            kind = "zero" if scale == 0 else "round-off" if true <= tol.NEGLIGIBLE_SHARE * scale else "error"
            rows.append({"profile": pid, "quantity": q, "estimate": e.rms, "true": true, "order": e.order,
                         "kind": kind, "effectivity": e.rms / true if kind == "error" else None,
                         "warned": f"{pid}:{q}" in estimate.unsettled})
    return rows


def energy_row(scene, result, estimate: est.Estimate, exact, exclude: float) -> dict:
    """The ZZ estimate against ``‖σ − σ_h‖_E`` on the same background
    cells, :data:`TRUE_GAUSS` points per direction, ``σ_h = σ(u_h)``
    (:func:`contactcore.estimate.direct_stress`: xfem P1's displacement's
    own stress, not the recovered one its profiles read)."""
    er = est.energy_rule(scene, estimate.hs[-1], exclude, TRUE_GAUSS)
    sigma = est.direct_stress(result.fields, er.rule.points, er.rule.bodies)
    true = est.energy_norm(scene, er, exact.stress(er.rule.points, er.rule.bodies) - sigma)
    norm = est.energy_norm(scene, er, sigma)
    eta = estimate.energy.eta
    kind = "round-off" if true <= tol.NEGLIGIBLE_SHARE * norm else "error"
    return {"profile": "energy", "quantity": "‖σ‖_E", "estimate": eta, "true": true, "order": None, "kind": kind,
            "effectivity": eta / true if kind == "error" else None, "warned": ENERGY_KEY in estimate.unsettled}


def effectivity(case_name: str, key: tuple) -> list[dict]:
    """Every row of one case and one (method, degree) at its two rungs."""
    case = CASES[case_name]()
    options, _ = VARIANTS[key]
    disc = methods.discretisation(key[0])(degree=key[1], **options)
    coarse, fine = rungs(case_name, key)
    exclude = default_exclusion(case.scene)
    results = [solve(case.scene, disc, h) for h in (coarse, fine)]
    estimate = est.estimate_runs(case.scene, results, exclude)
    got = {p.id: p for p in sample_profiles(case.scene, results[-1].fields, results[-1].interface)}
    field_exact = case.fields(case.history()[-1]) if hasattr(case, "history") else case
    rows = profile_rows(estimate, got, exact_profiles(case)) + [energy_row(case.scene, results[-1], estimate,
                                                                           field_exact, exclude)]
    return [{"case": case_name, "method": key[0], "degree": key[1], "h": fine, **r} for r in rows]


#: The (method, degree) pairs of the paper scenes' table: every method at
#: both degrees, each with its default options (EFGM P2 with its default
#: Gauss rule, not the closed forms' finer one).
SCENE_VARIANTS = (("fe", 1), ("fe", 2), ("xfem", 1), ("xfem", 2), ("efgm", 1), ("efgm", 2))


def scene_truth(scene, ref_h: float) -> dict[str, ProfileData]:
    """The truth of a scene without a closed form: fe P2 at ``ref_h``, sampled."""
    ref = solve(scene, methods.discretisation("fe")(degree=2), ref_h)
    return {p.id: p for p in sample_profiles(scene, ref.fields, ref.interface)}


def scene_rows(scene, key: tuple, h: float, truth: dict[str, ProfileData], levels: int = 2) -> list[dict]:
    """One row per profile quantity of ``scene`` for one (method, degree)
    estimated from ``levels`` runs from ``h`` down: the RMS of the
    estimate and of the true error (against ``truth``) of the finest run,
    over the samples the estimate keeps (``Estimate.kept``: away from
    singular points and beyond the coarse run's reach of them), the true error
    relative to the quantity's largest |value| there (``relative``: the
    true RMS over the largest |value| of the truth on the same samples,
    no unit), and whether the estimate warned that it is not asymptotic
    (``warned``: :func:`contactcore.estimate.unsettled`, the coarse run's
    stencil, :func:`contactcore.estimate.cell_scale_orders`, its variation
    from cell to cell, :func:`contactcore.estimate.residues`, a difference
    a thousand times below its kind's, :func:`contactcore.estimate.curved_layer`,
    :func:`contactcore.estimate.exact_tractions`,
    :func:`contactcore.estimate.fast_gamma`, EFGM P1's Γ quantities, or
    with three levels :func:`contactcore.estimate.order_mismatch`, the
    observed order: the entries ``Estimate.unsettled`` holds).  A true
    error at round-off (:func:`at_roundoff`) has no effectivity (None), as
    on the closed forms."""
    disc = methods.discretisation(key[0])(degree=key[1])
    results = [solve(scene, disc, hk) for hk in est.levels_of(h, levels)]
    exclude = default_exclusion(scene)
    estimate = est.estimate_runs(scene, results, exclude, energy=False)
    got, rows, sizes = {p.id: p for p in estimate.sampled}, [], Sizes.of(scene)
    for pid, qs in estimate.profiles.items():
        for q, e in qs.items():
            keep = estimate.kept[pid][q]
            want = truth[pid].columns[q][keep]
            true = est.rms(got[pid].columns[q][keep] - want)
            rows.append({"scene": scene.name, "method": key[0], "degree": key[1], "h": estimate.hs[-1],
                         "profile": pid, "quantity": q, "order": e.order, "estimate": est.rms(e.error[keep]),
                         "true": true, "unit": files.column_unit(q, scene.units) or "",
                         "relative": true / np.max(np.abs(want)),
                         "effectivity": (None if at_roundoff(true, want, q, sizes)
                                         else est.rms(e.error[keep]) / true),
                         "warned": f"{pid}:{q}" in estimate.unsettled})
    return rows


def at_roundoff(true: float, want: np.ndarray, quantity: str, sizes: Sizes | None) -> bool:
    """Whether a true RMS error ``true`` is round-off: at most
    :data:`~contactcore.tolerances.NEGLIGIBLE_SHARE` of the truth's largest
    |value| ``want`` or, where that is itself near zero (a stuck Γ's slip),
    of the scene's own size of the quantity's kind
    (:func:`~contactcore.estimate.roundoff_floor`).  A method that
    represents the answer exactly (an affine field in fe P1) then meets a
    truth that does too, and their RMS ratio is round-off over round-off:
    no effectivity (here, and in ``efficiency --ref-h``:
    :func:`verification.efficiency.effectivity_at`)."""
    largest = float(np.max(np.abs(want))) if len(want) else 0.0
    return true <= max(tol.NEGLIGIBLE_SHARE * largest, est.roundoff_floor(sizes, quantity))


def _length(scenes) -> str:
    """The length unit all ``scenes`` share after a space (`` mm``), or
    nothing if they do not share one."""
    lengths = {scene.units.length for scene in scenes}
    return f" {lengths.pop()}" if len(lengths) == 1 else ""


#: The coarsest run's default h: the domain's smaller side (a disc's
#: diameter) over this, so that a scene in mm or km gets the same
#: resolution as one in m (scene A, 1 m across: h = 0.05, the paper
#: scenes' table in docs/error-estimates.md).
DEFAULT_CELLS_ACROSS = 20
#: The truth's default h: the finest run's h over this (scene A at the
#: defaults: runs 0.05, 0.025, truth 0.00625 = 0.025/4).
DEFAULT_TRUTH_REFINEMENT = 4


def smaller_side(scene) -> float:
    """The domain's smaller side, or a disc's diameter, in the scene's units."""
    from contactcore.geometry import Rectangle
    dom = scene.domain
    return float(min(dom.size)) if isinstance(dom, Rectangle) else 2.0 * float(dom.radius)


def resolutions(scene, h: float | None, ref_h: float | None, levels: int) -> tuple[float, str, float, str]:
    """``(h, h's name, ref_h, ref_h's name)`` of ``scene``: ``--h`` and
    ``--ref-h`` as given, or, not given, the defaults scaled to the scene
    (:data:`DEFAULT_CELLS_ACROSS`, :data:`DEFAULT_TRUTH_REFINEMENT`), each
    named by where it came from, so that a refusal never names an option
    the user did not pass."""
    h_name = "--h"
    if h is None:
        h = smaller_side(scene) / DEFAULT_CELLS_ACROSS
        h_name = f"the default h (scene {scene.name}'s smaller side/{DEFAULT_CELLS_ACROSS}; give --h)"
    ref_name = "--ref-h"
    if ref_h is None:
        ref_h = min(est.levels_of(h, levels)) / DEFAULT_TRUTH_REFINEMENT
        ref_name = (f"the default truth h (scene {scene.name}'s finest run's h/{DEFAULT_TRUTH_REFINEMENT}; "
                    "give --ref-h)")
    return h, h_name, ref_h, ref_name


def check_budgets(scenes, h: float | None, ref_h: float | None, levels: int) -> None:
    """Refuse, before any solve, a truth or a run that would not fit this
    machine (:func:`contactcore.budget.check_budget`): ``--h`` and
    ``--ref-h`` are in each scene's own length unit (their defaults
    scaled to it, :func:`resolutions`)."""
    for scene in scenes:
        h_s, h_name, ref_s, ref_name = resolutions(scene, h, ref_h, levels)
        check_budget(scene, ref_s, methods.budgeted("fe", 2), field=ref_name)
        for (name, degree), hk in itertools.product(SCENE_VARIANTS, est.levels_of(h_s, levels)):
            check_budget(scene, hk, methods.budgeted(name, degree), field=h_name)


def scene_table(scene_names, h: float | None, ref_h: float | None, out: Path, levels: int = 2,
                allow_large: bool = False, argv=()) -> str:
    """The effectivity of every :data:`SCENE_VARIANTS` pair on each scene
    (a built-in name or a TOML file; truth: fe P2 at ``ref_h``), written to ``out/effectivity.csv`` and
    ``out/effectivity.md``; returns the Markdown.  ``h`` or ``ref_h``
    None: each scene's default (:func:`resolutions`).  Unless
    ``allow_large``, every solve must fit the machine (:func:`check_budgets`)."""
    from contactcore import SceneError, load_scene
    if h is not None and ref_h is not None and not ref_h < min(est.levels_of(h, levels)):
        finest = min(est.levels_of(h, levels))
        raise SceneError("--ref-h", f"{ref_h:g} is not finer than the finest run's h, {finest:g}: the truth "
                         "must be finer than every run it measures")
    rows, scenes = [], [load_scene(name) for name in scene_names]  # every scene read before any solve
    units = files.shared_units(scenes, "--scene")  # h's one unit in units.json
    chosen = {scene.name: resolutions(scene, h, ref_h, levels) for scene in scenes}
    for scene in scenes:
        h_s, _, ref_s, _ = chosen[scene.name]
        finest = min(est.levels_of(h_s, levels))
        if not ref_s < finest:  # --ref-h given, h the scene's default
            raise SceneError("--ref-h", f"{ref_s:g} is not finer than scene {scene.name}'s finest run's h, "
                             f"{finest:g} (its default --h {h_s:g}): the truth must be finer than every run it "
                             "measures")
    if not allow_large:
        check_budgets(scenes, h, ref_h, levels)
    for scene in scenes:
        h_s, _, ref_s, _ = chosen[scene.name]
        truth = scene_truth(scene, ref_s)
        for key in SCENE_VARIANTS:
            rows += scene_rows(scene, key, h_s, truth, levels)
    columns = ["scene", "method", "degree", "h", "profile", "quantity", "order", "estimate", "true", "unit",
               "relative", "effectivity", "warned"]
    shown = [*columns[:8], "unit", "effectivity", "warned"]
    def setting(sc, truth: str) -> str:
        h_s, _, ref_s, _ = chosen[sc.name]
        return (f"{truth} fe P2 at h = {ref_s:g}{_length([sc])}; runs at "
                f"{', '.join(f'{hk:g}' for hk in est.levels_of(h_s, levels))}{_length([sc])}")
    if len({chosen[sc.name][::2] for sc in scenes}) == 1:
        said = setting(scenes[0], "Truth:")
    else:
        said = "; ".join(setting(sc, f"{sc.name}: truth") for sc in scenes)

    text = (f"# Effectivity against fe P2\n\n{said}, the finest estimated; "
            f"RMS over the samples away from singular points and beyond the coarse run's reach of them; each row's estimate (and true error) in its "
            f"quantity's unit.\n\n"
            + files.markdown_table(rows, shown, [files.labelled(c, c, units) if c == "h" else c for c in shown]))
    files.write_csv(out / "effectivity.csv", rows, columns)
    files.write_text(out / "effectivity.md", text)
    if len(scenes) == 1:  # the scene measured, as efficiency and study keep theirs
        files.write_text(out / files.SCENE_FILE, scene_text(scene_names[0]))
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "scenes": list(scene_names),
                                        "h": {sc.name: chosen[sc.name][0] for sc in scenes},
                                        "ref_h": {sc.name: chosen[sc.name][2] for sc in scenes},
                                        "levels": levels, **files.run_units(units)})
    return text
