"""XFEM's snap is local (contactcore.tolerances.XFEM_SNAP of the node's own
cells), and a boundary load follows the snapped Γ.

- A graded mesh (tensor grid, cells 20 times smaller at a node line than the
  largest): the bonded bi-material bar of tests/scenes/nodeline_bar.toml with
  Γ on that node line and 1e-7 … 1e-4 of the small cells' size off it.
  With the mesh's largest diameter as the scale, the snap was 2e-4 of the
  small cells: Γ 1e-4 of them off the line was snapped, and u moved 7
  times what the local snap allows.  Now σ and Γ's tractions are the
  closed form's to round-off, and u moves only where Γ was snapped, by at
  most XFEM_SNAP of the local diameter times the strain jump.
- A layered bar pulled along Γ (Γ cuts the loaded edge; equal E, ν 0.3
  below and 0.1 above: σxx = P exact): the load was split at the exact Γ,
  and the piece between Γ and the snapped node loaded the other side's
  enrichment: σ off by 0.8 and Γ's traction by 4.8 times Γ's offset over h.

``python tests/test_xfem_graded.py CASE ...`` prints each case's worst
errors as JSON (the child process of the two-kernel test)."""
from __future__ import annotations

import functools
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import tolerances as tol  # noqa: E402

SCENE = HERE / "scenes" / "nodeline_bar.toml"
#: The graded mesh: rows of the bar's height, the largest cells' size over the smallest.
ROWS, RATIO = 50, 20
#: Γ's node line, as a share of the bar's length (x = 1.2 of 3 m).
LINE = 0.4
#: Γ's place off that line, in units of the small cells' size (XFEM_SNAP of
#: their diameter is 1.41e-5 of it: the last two offsets are not snapped).
OFFSETS = [0.0, 1e-7, -1e-6, 1e-5, -1e-5, 1e-4, -1e-4]


def graded_axis(lo: float, hi: float, at: float, small: float, big: float, grow: float = 1.5,
                band: int = 3) -> np.ndarray:
    """Node coordinates on [lo, hi] with a node at ``at``: ``band`` cells
    of ``small`` on either side of it, then cells growing by ``grow`` up to
    ``big``, the last cell of each side stretched to its end."""
    def side(length: float) -> np.ndarray:
        xs, x, step = [], 0.0, small
        while x < length * (1 - 1e-12):
            step = small if len(xs) < band else min(big, step * grow)
            x = length if x + 1.5 * step > length else x + step
            xs.append(x)
        return np.array(xs)
    return np.concatenate([at - side(at - lo)[::-1], [at], at + side(hi - at)])


def abrupt_axis(lo: float, hi: float, at: float, small: float, big: float) -> np.ndarray:
    """Node coordinates on [lo, hi] with a node at ``at``: cells of
    ``small`` before it, of about ``big`` after it (the size jumps at ``at``)."""
    n = max(1, round((hi - at) / big))
    return np.concatenate([np.arange(at, lo - small / 2, -small)[:0:-1], at + (hi - at) * np.arange(n + 1) / n])


def graded_mesh(scene, h: float, cell: str, counts=None, comm=None, order: int = 1, cut_on_one_rank: bool = False,
                axis=graded_axis, ratio: float = RATIO):
    """xfem's background mesh replaced (the signature of
    :func:`xdolfinx.xfem.cells.background_mesh`; one process, so
    ``cut_on_one_rank`` plays no part): the (dimensionless) bar's
    rectangle as a tensor grid, ROWS rows of size s, columns of s at the
    node line LINE of its length growing to ``ratio``·s away from it
    (``axis``); quads, or each split along its diagonal."""
    import ufl
    from dolfinx import mesh
    from mpi4py import MPI

    (x0, y0), (a, b) = scene.domain.corner, scene.domain.size
    small = b / ROWS
    xs = axis(x0, x0 + a, x0 + LINE * a, small, ratio * small)
    xs[0], xs[-1] = x0, x0 + a
    ys = y0 + b * np.arange(ROWS + 1) / ROWS
    X, Y = np.meshgrid(xs, ys)
    nx = len(xs) - 1
    i, j = (g.ravel() for g in np.meshgrid(np.arange(nx), np.arange(ROWS)))
    v00, v10, v01, v11 = j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i, (j + 1) * (nx + 1) + i + 1
    if cell == "quad":
        topology, name = np.column_stack([v00, v10, v01, v11]), "quadrilateral"
    else:
        topology, name = np.vstack([np.column_stack([v00, v10, v11]), np.column_stack([v00, v11, v01])]), "triangle"
    return mesh.create_mesh(MPI.COMM_SELF, topology.astype(np.int64), np.column_stack([X.ravel(), Y.ravel()]),
                            ufl.Mesh(ufl.VectorElement("Lagrange", name, 1)))


def _bar(offset: float):
    from contactcore import LineInterface, load_scene

    scene = load_scene(str(SCENE))
    small = scene.domain.size[1] / ROWS
    a = scene.domain.corner[0] + LINE * scene.domain.size[0] + offset * small
    return scene.with_changes(interface=LineInterface((a, 0.0), (1.0, 0.0))).validated(), small


def graded_errors(offset: float, cell: str, degree: int, axis=graded_axis, ratio: float = RATIO,
                  snapped_by: float = 1.0) -> dict:
    """The bar on the graded mesh against its closed form: σ and Γ's
    tractions over |P|, u over its scale, and the move of u that the snap
    allows (XFEM_SNAP of ``snapped_by`` times the small cells' diameter,
    times the strain jump, where Γ is within it)."""
    import xdolfinx.xfem as xfem
    from contactcore.tolerances import XFEM_SNAP

    scene, small = _bar(offset)
    real = xfem.background_mesh
    xfem.background_mesh = functools.partial(graded_mesh, axis=axis, ratio=ratio)
    try:
        r = xfem.solve(scene, RATIO * small, degree=degree, cell=cell)
    finally:
        xfem.background_mesh = real
    (E0, E1), nu0 = (scene.materials[k].E for k in ("minus", "plus")), scene.materials["minus"].nu
    P, a = scene.loads[0].value[0], scene.interface.point[0]
    x, y = np.meshgrid(np.linspace(0.05, 2.95, 59), np.linspace(0.0, 0.5, 6))
    x, y = x.ravel(), y.ravel()
    keep = np.abs(x - a) > small / 2
    x, y = x[keep], y[keep]
    bodies = (x > a).astype(int)
    pts = np.column_stack([x, y])
    u_exact = np.column_stack([np.where(bodies == 0, P * x / E0, P * a / E0 + P * (x - a) / E1), -nu0 * P * y / E0])
    u_scale = float(np.max(np.abs(u_exact)))
    moved = abs(offset) * small
    diameter = small * (np.sqrt(2.0) if cell == "quad" else np.sqrt(5.0) * 2 / 3)  # cells.diameters of a small cell
    return {"sigma": float(np.max(np.abs(r.fields.stress(pts, bodies) - [P, 0.0, 0.0]))) / abs(P),
            "traction": float(np.max(np.abs(np.asarray(r.interface.final.traction) - [P, 0.0]))) / abs(P),
            "u": float(np.max(np.abs(r.fields.displacement(pts, bodies) - u_exact))) / u_scale,
            "u_allowed": (moved * abs(P / E0 - P / E1) / u_scale if moved <= XFEM_SNAP * snapped_by * diameter else 0.0),
            "residual": float(r.solver.residual)}


#: Triangles P2 with Γ just beyond the snap: Γ clips the triangles' corners,
#: the far edge-midpoint node's stiffness share there (≈ d⁴) falls below
#: xdolfinx.xfem.space.MIN_CUT_FRACTION and it is left unenriched; Γ's
#: point tractions are then off by ≈ 8 d² (5.3e-8 at d = 1e-4), σ and u
#: stay exact (reports/nodeline.md, "still wrong"; not fixed here).
KNOWN_TRACTION_GAP = {("triangle", 2, 1e-4), ("triangle", 2, -1e-4)}


def _check(e: dict, case) -> None:
    assert e["sigma"] <= tol.NODELINE_ROUNDOFF, (case, e)
    assert e["u"] <= tol.NODELINE_ROUNDOFF + e["u_allowed"], (case, e)
    if (case[1], case[2], case[0]) not in KNOWN_TRACTION_GAP:
        assert e["traction"] <= tol.NODELINE_ROUNDOFF, (case, e)


#: The default suite: Γ 1e-4 of the small cells off the line, which the
#: mesh-wide snap moved (quads P2, triangles P1); the rest under --runslow.
FAST = {(1e-4, "quad", 2), (-1e-4, "triangle", 1)}
CASES = [pytest.param(off, cell, deg, marks=[] if (off, cell, deg) in FAST else [pytest.mark.slow],
                      id=f"{off:+g}s-{cell}-P{deg}")
         for off in OFFSETS for cell in ("quad", "triangle") for deg in (1, 2)]


@pytest.mark.parametrize("offset, cell, degree", CASES)
def test_a_uniform_stress_is_exact_on_a_graded_mesh(offset, cell, degree):
    _check(graded_errors(offset, cell, degree), (offset, cell, degree))


@pytest.mark.slow
@pytest.mark.parametrize("offset", [1e-4, -1e-4])
def test_triangles_p2_just_beyond_the_snap_keep_a_traction_gap(offset):
    """KNOWN_TRACTION_GAP, measured: σ and u exact, Γ's tractions off by
    more than round-off.  When this fails, the gap is closed: remove the
    cases from KNOWN_TRACTION_GAP."""
    e = graded_errors(offset, "triangle", 2)
    assert e["sigma"] <= tol.NODELINE_ROUNDOFF and e["u"] <= tol.NODELINE_ROUNDOFF, e
    assert e["traction"] > tol.NODELINE_ROUNDOFF, e


@pytest.mark.slow
@pytest.mark.parametrize("cell", ["quad", "triangle"])
@pytest.mark.parametrize("offset", [2e-5, -3e-5])
def test_a_node_between_small_and_large_cells_takes_the_large_cells_snap(offset, cell):
    """Cells of s left of Γ's node line, 90 s right of it, Γ 2e-5 s or
    3e-5 s off the line: beyond the small cells' snap, 2e-7 to 3e-7 of the
    large ones.  The node takes the largest cell's snap, so Γ is snapped and
    the large cells keep no sliver.  With the smallest cell's snap instead
    (measured, /tmp/snapfix/abrupt.py), triangles P2 met a null pivot at
    2e-5 s and Γ's tractions were off by 1.5e-9 (quads) and 4.8e-9
    (triangles) at 2e-5 s and −3e-5 s."""
    e = graded_errors(offset, cell, 2, axis=abrupt_axis, ratio=100.0, snapped_by=100.0)
    _check(e, (offset, cell, 2))


def test_the_snap_is_the_node_s_own_cells():
    """On the graded mesh, a node's snap distance is XFEM_SNAP of the
    largest cell holding it: the small cells' at the node line, the large
    cells' far from it (the mesh-wide largest was 20 times the small cells')."""
    from contactcore.tolerances import XFEM_SNAP
    from xdolfinx.xfem.cells import CellBasis, diameters

    scene, small = _bar(0.0)
    for cell in ("quad", "triangle"):
        cells = CellBasis(graded_mesh(scene, RATIO * small, cell), 1, scene)
        d = diameters(cells.corners)
        coords = cells.V.tabulate_dof_coordinates()[:, 0]
        line = np.abs(coords - scene.interface.point[0]) < small / 2
        assert np.max(d) / np.min(d) > RATIO / 2
        assert cells.node_snap[line] == pytest.approx(XFEM_SNAP * np.min(d), rel=tol.NODELINE_ROUNDOFF)
        assert np.max(cells.node_snap) == pytest.approx(XFEM_SNAP * np.max(d), rel=tol.NODELINE_ROUNDOFF)


def _layers(offset: float, h: float):
    """The layered bar: Γ horizontal at y = 0.2 + offset·h, cutting the
    loaded right edge; E equal, ν 0.3 below and 0.1 above; σxx = P."""
    from contactcore import LineInterface, load_scene

    scene = load_scene(str(SCENE))
    mats = dict(scene.materials)
    mats["plus"] = type(mats["plus"])(**{**mats["plus"].__dict__, "E": mats["minus"].E})
    return scene.with_changes(interface=LineInterface((0.0, 0.2 + offset * h), (0.0, 1.0)), materials=mats).validated()


def layered_errors(offset: float, cell: str, degree: int, h: float = 0.1) -> dict:
    from xdolfinx import xfem

    scene = _layers(offset, h)
    r = xfem.solve(scene, h, degree=degree, cell=cell)
    E, P, a = scene.materials["minus"].E, scene.loads[0].value[0], scene.interface.point[1]
    nu0, nu1 = scene.materials["minus"].nu, scene.materials["plus"].nu
    x, y = (g.ravel() for g in np.meshgrid(np.linspace(0.0, 3.0, 61), np.linspace(0.0, 0.5, 26)))
    keep = np.abs(y - a) > tol.NODELINE_CLEARANCE / 2
    x, y = x[keep], y[keep]
    bodies = (y > a).astype(int)
    pts = np.column_stack([x, y])
    uy = np.where(bodies == 0, -nu0 * P * y / E, -nu0 * P * a / E - nu1 * P * (y - a) / E)
    u_exact = np.column_stack([P * x / E, uy])
    u_scale = float(np.max(np.abs(u_exact)))
    return {"sigma": float(np.max(np.abs(r.fields.stress(pts, bodies) - [P, 0.0, 0.0]))) / abs(P),
            "traction": float(np.max(np.abs(np.asarray(r.interface.final.traction)))) / abs(P),
            "u": float(np.max(np.abs(r.fields.displacement(pts, bodies) - u_exact))) / u_scale,
            # Γ snapped onto the node line: u_y moves by the offset times the jump of ε_yy
            "u_allowed": abs(offset) * h * abs(nu0 - nu1) * abs(P) / E / u_scale,
            "residual": float(r.solver.residual)}


LAYER_CASES = [pytest.param(off, cell, deg, marks=[] if (off, cell, deg) == (1e-5, "quad", 2) else [pytest.mark.slow],
                            id=f"{off:+g}h-{cell}-P{deg}")
               for off in (0.0, 1e-7, -1e-6, 1e-5) for cell in ("quad", "triangle") for deg in (1, 2)]


@pytest.mark.parametrize("offset, cell, degree", LAYER_CASES)
def test_a_load_on_an_edge_that_gamma_cuts_follows_the_snapped_gamma(offset, cell, degree):
    """Before, Γ 1e-5 h off the node line gave σ 8e-6 and Γ's traction
    4.8e-5 (quads P2), 0.8 and 4.8 times the offset over h."""
    e = layered_errors(offset, cell, degree)
    assert e["sigma"] <= tol.NODELINE_ROUNDOFF, e
    assert e["traction"] <= tol.NODELINE_ROUNDOFF, e
    assert e["u"] <= tol.NODELINE_ROUNDOFF + e["u_allowed"], e


def _in_child(coretype: str, args: list[str]) -> list[dict]:
    env = dict(os.environ, OPENBLAS_CORETYPE=coretype)
    out = subprocess.run([sys.executable, __file__, *args], env=env, cwd=HERE.parent, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


#: Every graded case and the layered bar 1e-5 h off, in child processes.
KERNEL_CASES = ([f"graded:{off!r}:{cell}:{deg}" for off in OFFSETS for cell in ("quad", "triangle") for deg in (1, 2)]
                + [f"layers:{off!r}:{cell}:{deg}" for off in (1e-5, -1e-6) for cell in ("quad", "triangle")
                   for deg in (1, 2)])


@pytest.mark.slow
def test_the_answers_do_not_follow_the_blas_kernel():
    """Under OpenBLAS's Haswell and Nehalem kernels, every case holds, and
    the two kernels' errors agree to round-off."""
    runs = {core: _in_child(core, KERNEL_CASES) for core in ("Haswell", "Nehalem")}
    for arg, h, n in zip(KERNEL_CASES, runs["Haswell"], runs["Nehalem"]):
        kind, off, cell, deg = arg.split(":")
        for e in (h, n):
            if kind == "graded":
                _check(e, (float(off), cell, int(deg)))
            else:
                assert max(e["sigma"], e["traction"]) <= tol.NODELINE_ROUNDOFF, (arg, e)
        for key in ("sigma", "traction", "u"):
            assert abs(h[key] - n[key]) <= tol.NODELINE_ROUNDOFF, (arg, key, h, n)


if __name__ == "__main__":
    out = []
    for arg in sys.argv[1:]:
        kind, off, cell, deg = arg.split(":")
        out.append((graded_errors if kind == "graded" else layered_errors)(float(off), cell, int(deg)))
    print(json.dumps(out))
