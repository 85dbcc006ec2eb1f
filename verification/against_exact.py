"""``run --against-exact``: how far a penalty answer is from the exact one.

A ``unilateral`` or ``coulomb`` law enforced by its springs k_N, k_T
answers for those springs: a closed point carries ``t_N = k_N g_N``, so Γ
interpenetrates by ``|t_N|/k_N`` and a sticking point shears elastically by
``|t_T|/k_T``.  The same law enforced exactly (Signorini contact and
Coulomb friction without elastic slip, by Nitsche's method; Chouly, Hild &
Renard, Math. Comp. 2015; docs/contact-enforcement.md) is the answer the
springs approach as k → ∞.  Solving both with one method at one
discretisation isolates the springs' share of the answer from the
discretisation's.

Per profile and quantity, Δ = penalty − exact is measured as
:mod:`verification.agreement` measures a method against its reference,
the exact answer the reference: the **worst sample**, max |Δ| over the kept
samples as a share of the exact scale's max there, and the **RMS share**,
RMS(Δ)/RMS(scale) over the same samples (different denominators: the RMS
share exceeds the worst sample's where the scale is small over most
samples and Δ is not; grader16 F4); samples near singular points are
left out (:func:`verification.agreement.default_exclusion`).  The scale
is the exact quantity itself, except on Γ: a jump component (g_N, g_T) is
measured against the exact jump's magnitude |g| = √(g_N² + g_T²) floored
as the agreement floors an exact law's gaps (√(|g|² + f²), f a tenth of
the displacement scale: :func:`verification.agreement.gap_floor`), and a
traction component against |t|, because the exact g_N of a closed contact
is zero (but for the enforcement's residue); a profile that holds one
component of a vector alone measures it against its own |value|, a gap
floored alike.  A share of the vector hides
how much of a small component the penalty misses (C-coulomb's t_T, a fifth
of |t|, missed almost whole), so the **share of its own size** is kept
beside it: max |Δ| over the component's own largest exact |value|, a gap
floored as above.
The largest |Δ|, |exact|, own size and scale are kept in the quantity's
unit too.  The
**status split** is the number of Γ's quadrature points open, sticking and
slipping at the last increment, and the share of Γ's length (by
quadrature weight) each covers.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from contactcore import ContactError, Scene
from contactcore.enforcement import make_law
from contactcore.exact import BONDED, EXACT_LAWS
from contactcore.interface_path import InterfacePath
from contactcore.laws import REPORTED_STATUS_NAMES, STATUS_NAMES

from . import files
from .agreement import (Agreement, default_exclusion, gap_floor, gap_floors, kept_samples, percent, profile_agreements,
                        share, size_floor, user_floors)

#: How the exact run is named in tables and figures.
EXACT = "exact"


def exact_law(law, field: str):
    """``law`` (a penalty law) enforced exactly, its other parameters (μ)
    kept and its springs dropped; a SceneError naming ``field`` for a law
    that has no exact enforcement (``linear``)."""
    params = {k: getattr(law, k) for k in law.parameters if k not in ("kN", "kT")}
    return make_law({"type": law.name, "enforcement": EXACT, **params}, field)


def penalty_counterpart(law) -> str:
    """How a law enforced exactly gets a penalty answer, in words:
    ``bonded`` through the ``linear`` law's springs, the others through
    their own."""
    return ('type = "linear", with kN and kT, is its penalty counterpart' if law.name in BONDED
            else 'give the file enforcement = "penalty" with kN and kT')


def exact_twin(scene: Scene, field: str = "--against-exact") -> Scene:
    """``scene`` with its penalty law enforced exactly; a ContactError
    naming ``field`` when there is nothing to compare: a law already
    enforced exactly, or one that has no exact enforcement."""
    law = scene.law
    if law.enforcement == EXACT:
        raise ContactError(f"{field}: scene {scene.name}'s '{law.name}' law is already enforced exactly, so there "
                           f"is no penalty answer to compare with it ({penalty_counterpart(law)})")
    if law.name not in EXACT_LAWS:
        raise ContactError(f"{field}: scene {scene.name}'s '{law.name}' law is enforced by its springs only, so "
                           f"there is no exact answer to compare with (exact enforcement: "
                           f"{', '.join(n for n in EXACT_LAWS if n not in BONDED)})")
    return scene.with_changes(law=exact_law(law, f"{field}: interface.law"))


def status_split(path: InterfacePath) -> dict:
    """Open, sticking and slipping points of Γ at the last increment (and
    partial ones, where the unilateral law's partial answer has them), and
    the share of Γ's length (quadrature weight) of each."""
    return {**path.final.counts(), **{f"{name}_share": share for name, share in path.status_shares().items()}}


#: Γ's components and the vector each is measured against (module doc).
VECTORS = {"gN": ("gN", "gT"), "gT": ("gN", "gT"), "tN": ("tN", "tT"), "tT": ("tN", "tT")}


def floor_of(scene: Scene, exact: dict, quantity: str, floors: dict | None = None) -> float:
    """The floor of ``quantity``'s sizes: the larger of an exact law's gap
    floor (:func:`~verification.agreement.gap_floors` of ``scene``), the
    user's ``floors`` and round-off of its kind on ``exact`` or of the
    scene's own scale (:func:`~verification.agreement.size_floor`): a
    quantity zero in the exact answer has no size of its own."""
    return max(gap_floors(scene).get(quantity, 0.0), size_floor(quantity, user_floors(floors), exact, scene=scene))


def vector_of(prof, q: str) -> tuple[str, ...]:
    """The components ``q`` of profile ``prof`` is measured against: Γ's
    vector (:data:`VECTORS`) where the profile holds both its components,
    else ``q`` alone."""
    both = VECTORS.get(q, (q,))
    return both if len(both) > 1 and set(both) <= set(prof.names) else (q,)


def scales(scene: Scene, exact: dict, floors: dict | None = None) -> dict:
    """``(profile id, quantity) -> per-sample scale`` of every quantity of
    the exact answer: for each Γ component a profile holds, |g| or |t| (its
    own |value| where the profile lacks the vector's other component,
    :func:`vector_of`), for any other its own |value|; floored
    (:func:`floor_of`, module doc)."""
    out = {}
    for pid, prof in exact.items():
        for q in prof.names[3:]:
            vector = vector_of(prof, q)
            size = (np.hypot(*(prof.columns[c] for c in vector)) if len(vector) > 1
                    else np.abs(prof.columns[q]))
            out[pid, q] = np.hypot(size, floor_of(scene, exact, q, floors))
    return out


def differences(scene: Scene, label: str, penalty: dict, exact: dict, floors: dict | None = None) -> list[Agreement]:
    """Every profile quantity of ``penalty`` against ``exact`` (id ->
    ProfileData), as :class:`~verification.agreement.Agreement` rows of
    ``label`` (module doc), sizes floored by ``floors`` (:func:`scales`),
    each row's ``against`` naming its vector (``|(gN, gT)|``; "" the
    quantity itself)."""
    rows = profile_agreements(scene, label, penalty, exact, default_exclusion(scene), scales(scene, exact, floors))
    named = {(pid, q): vector_of(prof, q) for pid, prof in exact.items() for q in prof.names[3:]}
    return [dataclasses.replace(a, against="|(" + ", ".join(named[a.profile, a.quantity]) + ")|")
            if len(named[a.profile, a.quantity]) > 1 else a for a in rows]


def largest(scene: Scene, exact: dict, row: Agreement, vector_scales: dict, floors: dict | None = None
            ) -> tuple[float, float, float]:
    """The largest |exact| of ``row``'s quantity, of its own size (floored
    as :func:`scales` floors it) and of the scale it is measured against
    (``vector_scales``: :func:`scales` of ``exact``), over the kept
    samples."""
    prof = exact[row.profile]
    own = np.abs(prof.columns[row.quantity])
    size = np.hypot(own, floor_of(scene, exact, row.quantity, floors))
    scale = vector_scales.get((row.profile, row.quantity), own)
    keep = kept_samples(scene, prof, default_exclusion(scene))
    return tuple(float(np.max(v[keep], initial=0.0)) for v in (own, size, scale))


def record(scene: Scene, rows: list[Agreement], exact: dict, penalty_path: InterfacePath,
           exact_path: InterfacePath, floors: dict | None = None) -> dict:
    """summary.json's ``"against_exact"``: per profile and quantity the
    worst-sample share, the share of its own size (``worst_own``) and the
    RMS share, where the worst sample lies, the largest |Δ|, |exact|, own
    size and scale (in the quantity's unit); the status
    split of each run and the distance from singular points inside which
    samples were left out."""
    by_profile, vector_scales = {}, scales(scene, exact, floors)
    for a in rows:
        own, size, scale = largest(scene, exact, a, vector_scales, floors)
        difference = abs(a.value - a.reference)
        by_profile.setdefault(a.profile, {})[a.quantity] = {
            "worst": a.worst, "worst_own": share(difference, size), "rms": a.rms,
            "at": {"s": a.s, "x": a.x, "y": a.y}, "largest_difference": difference, "largest_exact": own,
            "own_size": size, "scale": scale, "kept": a.kept, "samples": a.samples}
    return {"exclude": default_exclusion(scene), "profiles": by_profile,
            "status": {"penalty": status_split(penalty_path), "exact": status_split(exact_path)}}


def section(scene: Scene, law_name: str, records: dict[str, dict]) -> str:
    """summary.md's "Penalty against exact": the shares of every method
    (label -> :func:`record`) and their status splits."""
    exclude = next(iter(records.values()))["exclude"]
    lines = ["\n## Penalty against exact\n",
             f"Each method also solved scene {scene.name} with its '{law_name}' law enforced exactly (Nitsche; "
             "k_N, k_T play no part) at the same discretisation. Per profile and quantity, Δ = penalty − exact: "
             "the worst sample is max |Δ| as a share of the largest exact scale, the RMS share "
             f"RMS(Δ) / RMS(scale), over the samples at least {exclude:.3g} {scene.units.length} from the scene's "
             "singular points. "
             "The scale is the exact quantity itself, except on Γ: g_N and g_T are measured against the exact "
             f"jump's magnitude |g| floored as √(|g|² + ({gap_floor(scene):.3g} {scene.units.length})²), a tenth "
             "of the displacement scale, t_N and t_T against |t| (the exact g_N of a closed contact is zero); "
             "a profile holding one component of a vector alone, against its own |value|, a gap floored alike. "
             "Beside it, max |Δ| as a share of the component's own largest exact |value| (a gap floored as "
             "above): what a vector's share hides of a small component. The worst sample and the RMS share have "
             "different denominators (the scale's largest value, its RMS), so the RMS share exceeds the worst "
             "sample's where the scale is small over most samples and Δ is not: a worst sample below the RMS "
             "share is no contradiction. The last three columns are in the quantity's unit.\n",
             "| method | profile | quantity | worst sample (of max scale) | of its own size | at s (x, y) "
             "| RMS (of RMS scale) | max \\|Δ\\| "
             "| max \\|exact\\| | max scale |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for label, rec in records.items():
        for pid, quantities in rec["profiles"].items():
            for q, d in quantities.items():
                at = d["at"]
                lines.append(f"| {label} | {pid} | {q} | {percent(d['worst'])} | {percent(d['worst_own'])} | "
                             f"{at['s']:.4g} ({at['x']:.4g}, {at['y']:.4g}) | {percent(d['rms'])} | "
                             f"{files.cell(d['largest_difference'])} | "
                             f"{files.cell(d['largest_exact'])} | {files.cell(d['scale'])} |")
    names = [n for n in REPORTED_STATUS_NAMES if n in STATUS_NAMES or any(
        n in split for rec in records.values() for split in rec["status"].values())]  # partial where a run has it
    lines += ["", "Status on Γ at the last increment: quadrature points (share of Γ's length).", "",
              "| method | enforcement | " + " | ".join(names) + " |", "|---|---|" + "---|" * len(names)]
    for label, rec in records.items():
        for enforcement, split in rec["status"].items():
            lines.append(f"| {label} | {enforcement} | " + " | ".join(
                f"{split.get(name, 0)} ({percent(split.get(f'{name}_share', 0.0))})" for name in names) + " |")
    return "\n".join(lines) + "\n"
