"""Nitsche's consistent traction ``S`` and stabilisation ``γ₀`` of efgm,
xfem and fe (contactcore.traction, efgm.traction, xdolfinx.xfem.traction,
xdolfinx.conforming._nitsche_rows).

The patch test of ``S``: with a polynomial field on each side that the
basis reproduces (linear, and quadratic at degree 2), ``S u`` at every Γ
point is ``w₋ τ(σ₋) + w₊ τ(σ₊)`` with the exact stresses and weights
in [0, 1] summing to 1 — on a straight, an inclined and a circular Γ.  On
a horizontal Γ a fraction θ up a row of cells the weights and ``γ₀`` are
known in closed form (Annavarapu et al. 2012): every cell holding Γ has
parts θh² and (1 − θ)h²; a sliver side's weight → 0 with θ while γ₀ stays
bounded.

fe's Γ facets are never cut: a facet's weights are those of its two
whole cells, ``w_k = (|Ω_k|/E_k) / Σ_j |Ω_j|/E_j``, and
``γ₀ = 2|Γ^e| / Σ_j |Ω_j|/E_j`` (docs/contact-enforcement.md), checked
against the mesh's cells.  fe's traction is ``σ n_h`` with the mesh's
own normal (the chord's on a P1 circle), so its exact tractions here take
``n_h`` (nitsche_fields.fe_mesh_normals; on a straight Γ ``n_h = n``).
On the circle fe P2's cells are curved: a quadratic field is not in their
(isoparametric) space, so fe P2 is tested there with a linear field,
which is (with the quadratic one its worst point is 1.0e-3 off the
weighted form at H = 0.1: a discretisation error, not round-off).

Both fail when fe's rows are broken (checked 2026-11-29 by editing
xdolfinx/conforming.py, then reverting): the + body's rows dropped, or
the normal's components swapped, fail all 6 fe patch tests and all 5
weight tests; the level set's normal taken for the mesh's fails both
circle patch tests (P1, P2) and the circle's weight test; the two
weights swapped (still in [0, 1], so the patch test passes) fail all 5
weight tests.
"""
import dataclasses
import json

import numpy as np
import pytest

import tolerances as tol
from contactcore import BODIES, CircleInterface, LineInterface, load_scene
from contactcore.traction import nitsche_weights
from nitsche_fields import PolynomialFields, build, exact, fe_facet_curves, fe_mesh_normals, frame_traction, unknowns
from xdolfinx.conforming import INTERFACE_GAUSS
from placements import inclined_A

#: Coarse: the operators are exact on any mesh.
H = 0.1

#: Moduli of the − and + bodies: unequal, so the weights are not ½.
MODULI = (2e11, 5e10)

METHODS = [("efgm", 1, {}), ("efgm", 2, {}), ("xfem", 1, {"cell": "quad"}), ("xfem", 2, {"cell": "quad"}),
           ("xfem", 1, {"cell": "triangle"}), ("xfem", 2, {"cell": "triangle"}), ("fe", 1, {}), ("fe", 2, {})]
IDS = [f"{m}-P{d}{'-' + o['cell'] if o else ''}" for m, d, o in METHODS]


def _bimaterial(scene):
    materials = {b: dataclasses.replace(scene.materials[b], E=E) for b, E in zip(BODIES, MODULI)}
    return exact(scene.with_changes(materials=materials))


def _horizontal(height: float):
    return _bimaterial(load_scene("A").with_changes(interface=LineInterface((0.0, height), (0.0, 1.0)), profiles=()))


GAMMAS = {"horizontal": lambda: _horizontal(0.53), "inclined": lambda: _bimaterial(inclined_A(10.0, 0.47)),
          "circle": lambda: _bimaterial(load_scene("C").with_changes(interface=CircleInterface((1.0, 1.5), 0.45)))}


def _split(method, degree, options, scene, seed=0, field_degree=None, read=None):
    """The interface, and for a seeded field per side (of ``field_degree``,
    else ``degree``): ``S u`` and the exact tractions of the − and + sides
    at Γ's points (σ on fe's mesh normal, in the level set's frame); with
    ``read``, also ``read(built, scene, itf, degree)`` before the system closes."""
    built = build(method, scene, degree, H, **options)
    itf = built.system.interface
    fields = PolynomialFields(field_degree or degree, seed)
    tau = (itf.S @ unknowns(method, built, fields)).reshape(-1, 2)
    D = scene.voigt_matrices()
    normals = scene.interface.normals(itf.points)
    acting = fe_mesh_normals(itf.points, normals, INTERFACE_GAUSS[degree], degree) if method == "fe" else None
    sides = [frame_traction(fields.stress(b, itf.points, D), normals, acting) for b in (0, 1)]
    extra = None if read is None else read(built, scene, itf, degree)
    built.system.close()
    return (itf, tau, sides) if read is None else (itf, tau, sides, extra)


def _weights(tau, sides):
    """The weight w₋ (P,) that best writes ``tau`` as ``w₋ τ₋ + (1 − w₋) τ₊``,
    and what is left over relative to the largest |τ|."""
    minus, plus = sides
    w = np.sum((tau - plus) * (minus - plus), axis=1) / np.sum((minus - plus) ** 2, axis=1)
    rest = tau - (w[:, None] * minus + (1 - w[:, None]) * plus)
    return w, float(np.max(np.abs(rest)) / np.max(np.abs(tau)))


@pytest.mark.parametrize("gamma", list(GAMMAS))
@pytest.mark.parametrize("method, degree, options", METHODS, ids=IDS)
def test_traction_patch_test(method, degree, options, gamma):
    """``S u`` is the weighted exact traction at every point, the weights in
    [0, 1] (fe P2 on the circle: a linear field, module doc)."""
    curved = method == "fe" and degree == 2 and gamma == "circle"
    itf, tau, sides = _split(method, degree, options, GAMMAS[gamma](), field_degree=1 if curved else None)
    assert itf.S.shape == itf.G.shape and len(itf.stabilisation) == itf.size > 0
    w, rest = _weights(tau, sides)
    assert rest <= tol.PATCH_ROUNDOFF
    assert np.all((w >= -tol.PATCH_ROUNDOFF) & (w <= 1 + tol.PATCH_ROUNDOFF)), (w.min(), w.max())
    assert np.all(itf.stabilisation > 0)


def _closed_form(theta: float, plus: float | None = None) -> tuple[float, float]:
    """w₋ and γ₀ of a cell of side H whose − part is θH² (module doc), its
    + part ``plus``·H² (1 − θ unless given: two cells taken as one)."""
    compliance = np.array([theta, 1 - theta if plus is None else plus]) * H ** 2 / np.array(MODULI)
    return compliance[0] / compliance.sum(), 2 * H / compliance.sum()


@pytest.mark.parametrize("theta", [0.3, 1.0])
@pytest.mark.parametrize("method, degree, options", METHODS[:3], ids=IDS[:3])
def test_weights_and_stabilisation_on_a_horizontal_gamma(method, degree, options, theta):
    """Γ θ up a row of cells (xfem's cut cells, efgm's background cells):
    ``w₋`` and ``γ₀`` in closed form; θ = 1 puts Γ on the cells' edges,
    whose points belong in xfem to the cell below (wholly −) and are read
    with the cell above (wholly +) as fe reads a facet's two cells (the
    cell below alone until grader16 F2), in efgm to the cells on both
    sides (wholly − and wholly +)."""
    itf, tau, sides = _split(method, degree, options, _horizontal(0.5 + (theta - 1) * H))
    w, rest = _weights(tau, sides)
    w_minus, gamma = _closed_form(theta, 1.0 if theta == 1.0 else None)
    assert rest <= tol.PATCH_ROUNDOFF
    assert np.max(np.abs(w - w_minus)) <= tol.PATCH_ROUNDOFF
    assert np.max(np.abs(itf.stabilisation / gamma - 1)) <= tol.PATCH_ROUNDOFF


@pytest.mark.parametrize("method, degree, options", [METHODS[2], METHODS[4]], ids=[IDS[2], IDS[4]])
def test_a_sliver_side_gets_no_weight_and_gamma_stays_bounded(method, degree, options):
    """xfem, Γ θ = 1e-2 … 1e-4 of a cell above a row of nodes (closer, Γ is
    snapped onto the row: contactcore.tolerances.XFEM_SNAP): the − side's
    weight falls as θ (a cut triangle's − part is at most 2θ of it, so
    ``w₋ <= 2θ (E₊/E₋)/(1 − 2θ)``), and γ₀ stays below twice (a triangle's
    half area) its θ → 0 limit on a square, ``2H E₊/H²``, times 1 + 2θ."""
    for theta in (1e-2, 1e-3, 1e-4):
        itf, tau, sides = _split(method, degree, options, _horizontal(0.5 + theta * H))
        w, rest = _weights(tau, sides)
        assert rest <= tol.PATCH_ROUNDOFF
        assert np.all(w >= -tol.PATCH_ROUNDOFF) and np.max(w) <= 2 * theta * MODULI[1] / MODULI[0] / (1 - 2 * theta)
        assert np.max(itf.stabilisation) <= 2 * (1 + 2 * theta) * _closed_form(0.0)[1]


def _fe_cells(built, scene, itf, degree):
    """Each Γ point's facet's two cells in fe's mesh, as (|Ω₋|, |Ω₊|) (m, 2)
    of their vertex triangles, and the facet's length (m,) (its points'
    weights summed).  A facet's ends (its curve at ξ = 0, 1) are the
    nearest mesh vertices, its cells the two holding both."""
    from scipy.spatial import cKDTree
    P = INTERFACE_GAUSS[degree]
    msh = built.fields(np.zeros(built.system.size)).displacements[0].function_space.mesh
    xg = msh.geometry.x[:, :2]
    triangles = msh.geometry.dofmap.array.reshape(msh.topology.index_map(2).size_local, -1)[:, :3]
    coef = fe_facet_curves(itf.points, P, degree)
    ends = cKDTree(xg).query(np.stack([coef[:, 0], coef.sum(axis=1)], axis=1).reshape(-1, 2))[1].reshape(-1, 2)
    areas = []
    for a, b in ends:
        cells = np.flatnonzero(np.isin(triangles, [a, b]).sum(axis=1) == 2)
        assert len(cells) == 2
        v = xg[triangles[cells]]  # (2, 3, 2)
        area = 0.5 * np.abs(np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]))
        body = scene.body_of(v.mean(axis=1))
        assert sorted(body) == [0, 1]
        areas.append(area[np.argsort(body)])  # − then +
    return np.repeat(areas, P, axis=0), np.repeat(itf.weights.reshape(-1, P).sum(axis=1), P)


@pytest.mark.parametrize("gamma, degree", [("horizontal", 1), ("horizontal", 2), ("inclined", 1), ("inclined", 2),
                                           ("circle", 1)])
def test_fe_weights_and_stabilisation_are_its_two_cells(gamma, degree):
    """fe's Γ facets are never cut: at each point ``w₋`` and ``γ₀`` are
    the closed form of the facet's two whole cells (module doc), their
    areas and the facet's length read from the mesh (P1 cells, and P2 on
    a straight Γ: straight cells; a curved P2 cell's weight takes its
    vertex triangle, xdolfinx.conforming._nitsche_rows, so it is left out)."""
    itf, tau, sides, (areas, length) = _split("fe", degree, {}, GAMMAS[gamma](), read=_fe_cells)
    w, rest = _weights(tau, sides)
    compliance = areas / np.array(MODULI)
    assert rest <= tol.PATCH_ROUNDOFF
    assert np.max(np.abs(w - compliance[:, 0] / compliance.sum(axis=1))) <= tol.PATCH_ROUNDOFF
    assert np.max(np.abs(itf.stabilisation / (2 * length / compliance.sum(axis=1)) - 1)) <= tol.PATCH_ROUNDOFF


def test_weights_sum_to_one_and_a_sliver_gets_none():
    """nitsche_weights: the weights sum to 1; as one part's area θ → 0,
    its weight is at most θ (E₊/E₋)/(1 − θ) and γ₀ stays below its limit
    2|Γ|E₊/((1 − θ)|Ω|)."""
    theta = np.array([0.5, 1e-3, 1e-6, 1e-9, 0.0])
    areas = np.column_stack([theta, 1 - theta])
    w, gamma = nitsche_weights(areas, np.array(MODULI), np.ones(len(theta)))
    assert np.allclose(w.sum(axis=1), 1.0, rtol=0, atol=tol.NITSCHE_WEIGHT_ROUNDOFF)
    assert np.all(w[:, 0] <= theta * MODULI[1] / MODULI[0] / (1 - theta))
    assert np.all(gamma <= 2 * MODULI[1] / (1 - theta))
    assert gamma[-1] == pytest.approx(2 * MODULI[1], rel=tol.NITSCHE_WEIGHT_ROUNDOFF)


#: Builds scene A with Γ inclined, its law exact, by argv[1] (efgm, xfem or fe)
#: at degree argv[2] serially (COMM_SELF) and spread over the ranks, and
#: prints on rank 0 the largest relative differences of ``S u`` and ``γ₀``
#: at Γ's points (in the canonical order along Γ), and the points' largest
#: difference (Γ's length is 1).  ``u``: a smooth field of the nodes' coordinates, its
#: enriched values another (so the numbering of neither run enters).
PROBE = """
import json, sys
import numpy as np
from mpi4py import MPI
sys.path.insert(0, "tests")
from contactcore.collective import Collective
from contactcore.interface_path import canonical_order
from nitsche_fields import build, exact, unknowns
from placements import inclined_A

method, degree = sys.argv[1], int(sys.argv[2])
scene = exact(inclined_A(20.0, 0.4))
f = lambda b, x: np.column_stack([np.sin(3 * x[:, 0] + b), np.cos(2 * x[:, 1] - x[:, 0] * b)]) * 1e-3
ranks = Collective(MPI.COMM_WORLD)

def traction(comm, serial_unknowns=None):
    built = build(method, scene, degree, 0.1, comm=comm)
    itf = built.system.interface
    if method == "efgm" and serial_unknowns is not None:  # the serial numbering's, at this rank's columns
        x = serial_unknowns[itf.exchange.indices]
    elif method == "fe" and comm is None:  # the owned values, forwarded to this rank's ghosts (S's columns)
        x = itf.exchange.forward(unknowns(method, built, f))
    else:  # xfem: this rank's local unknowns; fe serial: its unknowns
        x = unknowns(method, built, f)
    out = ((itf.S @ x).reshape(-1, 2), itf.stabilisation, itf.points, x)
    built.system.close()
    return out

serial = traction(MPI.COMM_SELF)
spread = [ranks.gather(a) for a in traction(None, serial[3])[:3]]
o_s, o_p = canonical_order(scene.interface, serial[2]), canonical_order(scene.interface, spread[2])
worst = lambda a, b: float(np.max(np.abs(a - b)) / np.max(np.abs(a)))
out = {"traction": worst(serial[0][o_s], spread[0][o_p]), "stabilisation": worst(serial[1][o_s], spread[1][o_p]),
       "points": float(np.max(np.abs(serial[2][o_s] - spread[2][o_p])))}
if ranks.rank == 0:
    print("PROBE", json.dumps(out), flush=True)
"""


@pytest.mark.parametrize("method, degree", [("efgm", 1), ("fe", 1), pytest.param("xfem", 2, marks=pytest.mark.slow),
                                            pytest.param("fe", 2, marks=pytest.mark.slow)])
def test_traction_on_two_ranks_is_the_serial_one(method, degree):
    """Under mpirun -n 2, ``S u`` and ``γ₀`` at Γ's points (each rank its
    own, gathered) are the serial ones."""
    from test_mpi import mpirun

    out = mpirun(2, "-c", PROBE, method, degree, timeout=180)
    lines = [line for line in out.stdout.splitlines() if line.startswith("PROBE")]
    assert out.returncode == 0 and len(lines) == 1, out.stdout + out.stderr
    probe = json.loads(lines[0].split(" ", 1)[1])
    assert probe["points"] <= tol.COORDINATE_ROUNDOFF, probe  # fe's facet points: from either end of a facet
    assert probe["traction"] <= tol.EFGM_DISTRIBUTED_ASSEMBLY and probe["stabilisation"] <= tol.EFGM_DISTRIBUTED_ASSEMBLY, probe
