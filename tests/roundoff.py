"""Round-off probes of Newton's decisions: one stiff friction case solved
under one deliberate perturbation of round-off, reduced to what must not
change — the status of every Γ point at every increment, and the
interface's tractions and jumps.

A perturbation is one of:

* ``coretype=NAME``: OpenBLAS's kernels for another CPU (the variable is
  read when OpenBLAS loads, so the case runs in a child process:
  :func:`in_child`);
* ``ordering=K``: MUMPS's fill-reducing ordering ``ICNTL(7) = K`` (fe and
  xfem: the pivot order of every factorisation);
* ``renumber``: EFGM's nodes given in a shuffled order (assembly sums and
  pivot order both change);
* ``load=EPS``: every load and prescribed displacement scaled by ``1 + EPS``.

``python tests/roundoff.py FOLDER PERTURBATION CASE:METHOD ...`` writes the
fingerprints of those probes into FOLDER (the child process of :func:`in_child`).
"""
from __future__ import annotations

import dataclasses
import os
from contextlib import contextmanager
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import tolerances as tol  # noqa: E402


def _scaled_springs(factor: float):
    from contactcore import load_scene

    scene = load_scene("C-coulomb")
    law = dataclasses.replace(scene.law, kN=scene.law.kN * factor, kT=scene.law.kT * factor)
    return scene.with_changes(law=law)


def _layered(E_minus_factor: float = 1.0, E_plus_factor: float = 1.0):
    from verification.closed_forms import layered_slip

    base = layered_slip()
    return layered_slip(E=(E_minus_factor * base.E[0], E_plus_factor * base.E[1])).scene


def _efgm_springs_limit():
    """The layered closed form with its − layer softened until the springs
    are half the most EFGM carries under Coulomb friction (α = k_N h/E₋ =
    EFGM_FRICTION_SPRINGS / 2 at the scene's h), where its tractions
    oscillate most among the cases it answers."""
    from contactcore import tolerances as core_tol
    from verification.closed_forms import layered_slip

    base = layered_slip()
    scene = base.scene
    return _layered(E_minus_factor=scene.law.kN * scene.h / (0.5 * core_tol.EFGM_FRICTION_SPRINGS["N"] * base.E[0]))


def _shifted():
    from contactcore import Support

    scene = _layered()
    top = scene.supports[1]
    path = ((0, tol.RIGID_SHIFT),) + tuple((k, tol.RIGID_SHIFT + f * top.value[0]) for k, f in top.path)
    return scene.with_changes(supports=(Support("bottom", "xy", (tol.RIGID_SHIFT, 0.0), ((0, 1.0),)),
                                        Support("top", "x", (1.0, 0.0), path)))


def _exact_coulomb():
    from contactcore import load_scene, make_law

    scene = load_scene("C-coulomb")
    return scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu, "enforcement": "exact"}))


def _exact_stiff_layer():
    from verification.closed_forms import layered_slip

    base = layered_slip()
    return layered_slip(E=(tol.EXACT_STIFF_LAYER * base.E[0], base.E[1]), exact=True).scene


def _exact_inclined():
    from contactcore import make_law
    from placements import inclined_A

    return inclined_A(*tol.EXACT_INCLINED_PLACEMENT).with_changes(
        law=make_law({"type": "unilateral", "enforcement": "exact"}))


def _released(law: str):
    """tests/scenes/presspull.toml (a layered block, contrast 100, exact
    unilateral contact) pressed by its top's displacement over one
    increment, then released to exactly zero over one: at rest every margin
    of Newton's decisions is round-off (contactcore.tolerances.REST_ROUNDOFF);
    ``law`` "coulomb" puts exact Coulomb friction (μ = 0.3) on Γ."""
    from contactcore import Support, load_scene, make_law

    scene = load_scene(str(HERE / "scenes" / "presspull.toml"))
    top = scene.supports[2]
    released = Support(top.boundary, top.fix, top.value, ((1, 1.0), (2, 0.0)))
    scene = scene.with_changes(increments=2, supports=scene.supports[:2] + (released,))
    if law == "coulomb":
        scene = scene.with_changes(law=make_law({"type": "coulomb", "mu": tol.RELEASED_MU, "enforcement": "exact"}))
    return scene


def _tie():
    """tests/scenes/shearslide.toml (two layers, contrast 100, exact
    Coulomb μ = 0.35) cut at its fourth increment, where the top's
    displacement drives the shear to exactly μp: every point of Γ at the
    slip limit, to EFGM's discretisation error (±1.6e-4 of μp at h = 0.05)."""
    from contactcore import Support, load_scene

    scene = load_scene(str(HERE / "scenes" / "shearslide.toml"))
    bottom, top = scene.supports
    (k0, f0), (k1, f1) = top.path
    at = tol.TIE_INCREMENT  # the top's factor there, and its path to it
    factor = f0 + (f1 - f0) * (at - k0) / (k1 - k0)
    tied = Support(top.boundary, top.fix, tuple(factor * v for v in top.value), ((k0, 0.0), (at, 1.0)))
    return scene.with_changes(increments=at, supports=(bottom, tied))


def _unloaded():
    """tests/scenes/unloaded.toml: scene A's blocks on Coulomb springs
    (μ = 0.3), loaded, unloaded to zero and held: at zero load every slip
    limit is zero and the upper block, held by Γ alone, is where the
    unloading leaves it (docs/newton.md, "A load back to zero")."""
    from contactcore import load_scene

    return load_scene(str(HERE / "scenes" / "unloaded.toml"))


def _disc(pulled: bool):
    import free_disc

    return free_disc.disc(pulled)


def _squeezed(enforcement: str):
    import free_disc

    return free_disc.squeezed(enforcement)


#: The stiff friction cases, by name: (scene factory, h or None for the
#: scene's[, the method's options, such as its degree]).
#: The soft layers are beyond the springs efgm carries under Coulomb
#: friction (it refuses them before any solve); "efgm-springs-limit" is
#: within, at half the limit.
#: Three enforce the law exactly (Nitsche): a rod held by friction alone, a
#: layer 1000x stiffer than its neighbour, and an inclined Γ that opens part
#: of the way; then a disc held by Γ alone (tests/free_disc.py), pulled
#: (refused) and pressed (solved), and squeezed from its sides, exact and on
#: springs, where Newton passes maps that leave it free to turn, pins a
#: point nearest its stick window and takes a whole step out of a cycle
#: (xfem on springs refuses it).  Last, a block pressed and released to
#: exactly zero, at degree 2 (efgm P2's round-off is the largest there),
#: without and with friction: every point at rest; and a shear driven to
#: exactly the friction limit, where Newton moves EFGM's points from stick
#: to slip a few per iteration, at h = 0.05 and at h = 0.025 (360 points,
#: 171 iterations: docs/newton.md, "A tie").
def _small_mu():
    """The layered cycle at μ = 1e-6 across a contrast of 1e3 (grader5 #1)."""
    from contactcore import load_scene
    return load_scene(HERE / "scenes" / "cycle_mu1e-06.toml")


CASES = {
    "soft-layer": (lambda: _layered(E_minus_factor=tol.SOFT_LAYER), None),
    "efgm-springs-limit": (_efgm_springs_limit, None),
    "contrast-1e-6": (lambda: _layered(E_minus_factor=1e-6), None),
    "contrast+1e-6": (lambda: _layered(E_plus_factor=1e-6), None),
    "shifted": (_shifted, None),
    "C-coulomb-10x": (lambda: _scaled_springs(10.0), tol.ROUNDOFF_C_H),
    "C-coulomb-100x": (lambda: _scaled_springs(100.0), tol.ROUNDOFF_C_H),
    "C-coulomb-exact": (_exact_coulomb, tol.ROUNDOFF_C_H),
    "stiff-layer-exact": (_exact_stiff_layer, None),
    "inclined-exact": (_exact_inclined, tol.ROUNDOFF_C_H),
    "disc-pulled": (lambda: _disc(True), tol.ROUNDOFF_DISC_H),
    "disc-pressed": (lambda: _disc(False), tol.ROUNDOFF_DISC_H),
    "disc-squeezed-exact": (lambda: _squeezed("exact"), tol.ROUNDOFF_SQUEEZED_H),
    "disc-squeezed-penalty": (lambda: _squeezed("penalty"), tol.ROUNDOFF_SQUEEZED_H),
    "tie-exact": (_tie, tol.ROUNDOFF_TIE_H, {"displacement_scale": True}),
    "tie-exact-fine": (_tie, tol.ROUNDOFF_TIE_FINE_H, {"displacement_scale": True}),
    "released-exact": (lambda: _released("unilateral"), tol.ROUNDOFF_RELEASED_H, {"degree": 2, "displacement_scale": True}),
    "released-coulomb-exact": (lambda: _released("coulomb"), tol.ROUNDOFF_RELEASED_H, {"degree": 2, "displacement_scale": True}),
    "unloaded": (_unloaded, None),
    # grader5 #1: μ = 1e-6 across a contrast of 1e3, μp below DECISION_FLOOR under load
    "small-mu-cycle": (_small_mu, None),
}


def _perturbed(scene, perturbation: str):
    """The scene with its loads and prescribed values scaled (``load=EPS``)."""
    if not perturbation.startswith("load="):
        return scene
    factor = 1.0 + float(perturbation.split("=")[1])
    loads = tuple(dataclasses.replace(ld, value=tuple(factor * np.asarray(ld.value, float)))
                  if isinstance(ld.value, (tuple, list)) else dataclasses.replace(ld, value=factor * ld.value)
                  for ld in scene.loads)
    supports = tuple(dataclasses.replace(s, value=tuple(factor * np.asarray(s.value, float))) for s in scene.supports)
    return scene.with_changes(loads=loads, supports=supports)


def _options(perturbation: str) -> dict:
    """The method's options for an ``ordering=K`` perturbation."""
    if perturbation.startswith("ordering="):
        return {"petsc_options": {"mat_mumps_icntl_7": perturbation.split("=")[1]}}
    return {}


@contextmanager
def _renumbered(perturbation: str):
    """For ``renumber``, EFGM's grid of nodes in a shuffled order, its
    spacing unchanged (the same discretisation, numbered otherwise)."""
    if perturbation != "renumber":
        yield
        return
    import efgm.method as efgm_method

    grid = efgm_method.node_set

    def shuffled(scene, resolution, given=None):
        nodes = grid(scene, resolution, given)
        order = np.random.default_rng(tol.ROUNDOFF_SEED).permutation(len(nodes.x))
        return dataclasses.replace(nodes, x=nodes.x[order])

    efgm_method.node_set = shuffled
    try:
        yield
    finally:
        efgm_method.node_set = grid


def fingerprint(case: str, method: str, perturbation: str = "none") -> dict:
    """What must not change under ``perturbation``: the statuses (steps ×
    points), tractions and jumps of every converged step, in Γ's canonical
    order (and the scale the jumps are measured against, where it is not
    their own); or the refusal's message."""
    from contactcore import SolverError
    from verification import methods

    factory, h, *given = CASES[case]
    given = dict(given[0]) if given else {}
    scene = _perturbed(factory(), perturbation)
    # a case whose jumps may be round-off (a point at rest or sticking
    # exactly) measures them against the scene's displacement
    # (its largest prescribed value), not against their own round-off
    at_rest = given.pop("displacement_scale", False)
    jump_scale = max(abs(v) for s in scene.supports for v in s.value) if at_rest else 0.0
    try:
        with _renumbered(perturbation):
            result = methods.solver(method)(scene, h, estimate_condition=False, **_options(perturbation), **given)
    except SolverError as exc:
        return {"refused": str(exc).split(";")[0]}
    steps = result.interface.steps
    return {"step": np.array([s.step for s in steps]),
            "status": np.array([s.status for s in steps]),
            "traction": np.array([s.traction for s in steps]),
            "jump": np.array([s.jump for s in steps]), "jump_scale": np.array(jump_scale)}


def _file(folder: Path, case: str, method: str, perturbation: str) -> Path:
    return folder / f"{case}-{method}-{perturbation}.npz"


def in_child(probes: list[tuple[str, str]], perturbation: str, folder: Path) -> dict:
    """:func:`fingerprint` of every ``(case, method)`` of ``probes`` in one
    child process (``coretype=NAME`` sets OPENBLAS_CORETYPE there)."""
    env = dict(os.environ)
    if perturbation.startswith("coretype="):
        env["OPENBLAS_CORETYPE"] = perturbation.split("=")[1]
    subprocess.run([sys.executable, __file__, str(folder), perturbation] + [f"{c}:{m}" for c, m in probes],
                   env=env, check=True, cwd=HERE.parent, capture_output=True)
    out = {}
    for case, method in probes:
        with np.load(_file(folder, case, method, perturbation), allow_pickle=False) as data:
            out[case, method] = {k: (str(data[k]) if k == "refused" else data[k]) for k in data.files}
    return out


def differences(a: dict, b: dict, bound: float) -> list[str]:
    """Where two fingerprints differ beyond round-off: a refusal against an
    answer, another refusal, another step sequence or status map, or a
    traction or jump more than ``bound`` of its scale apart."""
    if "refused" in a or "refused" in b:
        return [] if a.get("refused") == b.get("refused") else [f"{a.get('refused', 'answer')} / {b.get('refused', 'answer')}"]
    if not np.array_equal(a["step"], b["step"]) or a["status"].shape != b["status"].shape:
        return [f"steps {a['step'].tolist()} / {b['step'].tolist()}"]
    out = []
    for i in np.flatnonzero(np.any(a["status"] != b["status"], axis=1)):
        out.append(f"step {a['step'][i]:g}: {int(np.sum(a['status'][i] != b['status'][i]))} points change status")
    for key in ("traction", "jump"):
        scale = max(np.max(np.abs(a[key])), float(a.get(f"{key}_scale", 0.0)), np.finfo(float).tiny)
        worst = np.max(np.abs(a[key] - b[key])) / scale
        if worst > bound:
            out.append(f"{key} differs by {worst:.2e} of its scale")
    return out


if __name__ == "__main__":
    folder, perturbation = Path(sys.argv[1]), sys.argv[2]
    for probe in sys.argv[3:]:
        case, method = probe.split(":")
        np.savez(_file(folder, case, method, perturbation), **fingerprint(case, method, perturbation))
