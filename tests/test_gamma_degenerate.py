"""Γ placed degenerately on the cells that integrate it: through mesh
vertices, tangent to a grid line at a vertex, and along a line of EFGM
nodes and background-cell edges.

Γ through a vertex only touches the cells beside it; round-off then cut
them along a piece of length ~1e-17 h (a line) or ~1e-8 h (a circle
tangent to the grid line there), whose points carried garbage tractions
into the profile's piece means (contactcore.cutcell).  Γ along a line of
background-cell edges put EFGM's Γ points in a cell whose Γ rule held Γ or
not by round-off, and γ₀ = 0 where it did not (efgm.traction).
"""
import itertools
import tomllib
import warnings

import numpy as np
import pytest

import tolerances as tol
from contactcore import sample_profiles
from contactcore import tolerances as core_tol
from contactcore.cutcell import cut_polygon, interface_rule_in
from contactcore.geometry import CircleInterface, LineInterface
from contactcore.interface_path import merged_pieces
from contactcore.scene_files import scene_from_dict, scene_toml
from placements import exclusion
from verification import methods
from verification.agreement import kept_samples, relative_rms

#: Cells of the tests (h) and Gauss points per direction.
H, GAUSS = 0.1, 3

#: Lines ((point), (normal)) through vertices of the 0.1 grid: the user's
#: (slope 1/2 through (0.5, 0.5)), 45° along a vertex diagonal, 45° the
#: other way, slope 2 and slope −1/3 each through three vertices.
VERTEX_LINES = [((0.5, 0.5), (-0.5, 1.0)), ((0.3, 0.3), (-1.0, 1.0)), ((0.2, 0.8), (1.0, 1.0)),
                ((0.4, 0.6), (-2.0, 1.0)), ((0.7, 0.2), (1.0, 3.0))]


def _grid(lo, hi, triangles: bool):
    """Cells of side H over [lo, hi]² counter-clockwise: squares, or each
    square cut along its rising diagonal and (shifted by one) its falling one."""
    edges = lo + H * np.arange(round((hi - lo) / H) + 1)
    cells = []
    for i, (x0, x1) in enumerate(zip(edges[:-1], edges[1:])):
        for j, (y0, y1) in enumerate(zip(edges[:-1], edges[1:])):
            a, b, c, d = (x0, y0), (x1, y0), (x1, y1), (x0, y1)
            if not triangles:
                cells.append(np.array([a, b, c, d]))
            elif (i + j) % 2:
                cells += [np.array([a, b, c]), np.array([a, c, d])]
            else:
                cells += [np.array([a, b, d]), np.array([b, c, d])]
    return cells


def _pieces_and_areas(itf, cells):
    """Γ's pieces' lengths (relative to their cell's diameter), Γ's length,
    each side's area, and the smallest region relative to its cell's area."""
    pieces, areas, smallest = [], np.zeros(2), np.inf
    for cell in cells:
        size = float(np.linalg.norm(cell.max(axis=0) - cell.min(axis=0)))
        w = interface_rule_in(itf, cell, GAUSS)[1]
        if len(w):
            pieces.append((float(np.sum(w)), size))
        regions = cut_polygon(itf, cell, GAUSS)
        for side, _, wts in regions:
            areas[(side + 1) // 2] += np.sum(wts)
        if len(regions) > 1:
            smallest = min(smallest, min(float(np.sum(r[2])) for r in regions) / size ** 2)
    lengths = np.array(pieces)
    return lengths[:, 0] / lengths[:, 1], float(lengths[:, 0].sum()), areas, smallest


def _line_through_unit_square(point, normal) -> tuple[float, float]:
    """Γ's length in [0, 1]² and the area of its − side, in closed form
    (the square clipped by the half-plane)."""
    from contactcore.geometry import clip_halfplane, polygon_area

    square = np.array([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)])
    minus = clip_halfplane(square, LineInterface(point, normal))  # φ <= 0
    on = np.abs(LineInterface(point, normal).phi(minus)) <= 1e-12
    return float(np.linalg.norm(np.ptp(minus[on], axis=0))), float(polygon_area(minus))


@pytest.mark.parametrize("triangles", [False, True], ids=["quads", "triangles"])
@pytest.mark.parametrize("point, normal", VERTEX_LINES)
@pytest.mark.parametrize("ulps", [-2, 2])
def test_a_line_through_vertices_has_no_piece_shorter_than_the_tolerance(point, normal, triangles, ulps):
    """Every piece of Γ is longer than GAMMA_PIECE_MIN of its cell and no
    region is a sliver; Γ's length and each side's area are exact; and
    moving Γ by a few ulps (the round-off that put its vertices on one side
    or the other) changes neither the pieces nor the regions."""
    shifted = tuple(np.asarray(point) + ulps * np.spacing(1.0) * np.asarray(normal))
    itf = LineInterface(shifted, normal)
    relative, length, areas, smallest = _pieces_and_areas(itf, _grid(0.0, 1.0, triangles))
    want_length, want_minus = _line_through_unit_square(point, normal)
    assert relative.min() > core_tol.GAMMA_PIECE_MIN, relative.min()
    assert smallest > core_tol.GAMMA_PIECE_MIN, smallest
    assert length == pytest.approx(want_length, rel=tol.CUT_RULE_ROUNDOFF)
    assert areas == pytest.approx([want_minus, 1.0 - want_minus], rel=tol.CUT_RULE_ROUNDOFF)
    exact, *_ = _pieces_and_areas(LineInterface(point, normal), _grid(0.0, 1.0, triangles))
    assert np.sort(relative) == pytest.approx(np.sort(exact), rel=tol.CUT_RULE_ROUNDOFF)


@pytest.mark.parametrize("radius", [0.4, 0.4 * (1 + 4 * np.spacing(1.0)), 0.4 * (1 - 4 * np.spacing(1.0))])
def test_a_circle_tangent_to_grid_lines_at_vertices_only_touches_the_cells_there(radius):
    """Radius 0.4 about (1, 1) on cells of 0.1: the circle passes through
    four vertices tangent to the grid line, on one side of it or the other
    by round-off.  The cells beyond it get no cap: every piece of Γ is at
    least TOUCH_CHORD of its cell, and Γ's length is 2πR."""
    itf = CircleInterface((1.0, 1.0), radius)
    relative, length, _, smallest = _pieces_and_areas(itf, _grid(0.4, 1.6, False))
    assert relative.min() > core_tol.TOUCH_CHORD, relative.min()
    assert smallest > core_tol.GAMMA_PIECE_MIN, smallest
    assert length == pytest.approx(2 * np.pi * radius, rel=tol.CUT_RULE_CIRCLE)


# ----- solves ----------------------------------------------------------------

def _scene(interface: dict, law: dict, loads: list, profile: str = "gamma", moduli=(2e11, 2e10)):
    """A unit square, bottom fixed, with Γ and its law, and an interface profile."""
    text = f"""
name = "degenerate"
plane = "strain"
[domain]
type = "rectangle"
size = [1.0, 1.0]
[materials.minus]
E = {moduli[0]}
nu = 0.3
[materials.plus]
E = {moduli[1]}
nu = 0.25
[[supports]]
boundary = "bottom"
fix = "xy"
[[profiles]]
id = "{profile}"
type = "interface"
quantities = ["gN", "gT", "tN", "tT"]
"""
    data = tomllib.loads(text)
    data["interface"] = {**interface, "law": law}
    data["loads"] = loads
    return scene_from_dict(data)


#: The user's scene: bonded bimaterial, Γ through (0.5, 0.5) with normal
#: (−0.5, 1), through the vertex (0.7, 0.6) of every grid of 0.1, 0.05, ….
TOP_TRACTION = (1e5, -3e5)


def _bonded(height: float):
    return _scene({"type": "line", "point": [0.5, height], "normal": [-0.5, 1.0]}, {"type": "bonded"},
                  [{"type": "traction", "boundary": "top", "value": list(TOP_TRACTION)}])


XFEM_CASES = [(1, "quad"), (1, "triangle"), (2, "quad"), (2, "triangle")]

#: Heights at x = 0.5 of the same Γ through no vertex: a quarter cell below
#: and above it (its pieces no shorter than a quarter of a cell).
OFF_VERTEX = (0.475, 0.525)

_FE = {}


def _fe_profiles(scene):
    """fe P2's profiles at h/2, once per scene."""
    key = scene_toml(scene)
    if key not in _FE:
        fe = methods.solver("fe")(scene, H / 2, degree=2, estimate_condition=False)
        _FE[key] = {p.id: p for p in sample_profiles(scene, fe.fields, fe.interface)}
    return _FE[key]


def _xfem_profile(scene, degree: int, cell: str):
    """xfem's Γ profile at h = H, and its pieces' lengths."""
    result = methods.solver("xfem")(scene, H, degree=degree, cell=cell, estimate_condition=False)
    path = result.interface
    centres, which = np.unique(path.pieces, axis=0, return_inverse=True)
    return sample_profiles(scene, result.fields, path)[0], np.bincount(which.ravel(), path.weights, len(centres))


@pytest.mark.parametrize("degree, cell", XFEM_CASES, ids=[f"P{d}-{c}" for d, c in XFEM_CASES])
def test_xfem_profile_of_a_gamma_through_a_vertex_keeps_equilibrium_and_agrees_with_fe(degree, cell):
    """The user's bonded Γ through a vertex, xfem at h = 0.1: no piece of Γ
    shorter than GAMMA_PIECE_MIN of a cell; the profile's mean traction
    (piece means along Γ) is the top load carried across Γ, (n·F, t·F)/|Γ|
    with F the top's resultant; and t_N, t_T agree with fe P2 at h/2
    in RMS (away from Γ's ends and the corners) within VERTEX_VS_OFF_VERTEX
    of the same Γ moved off the vertices (the worst sample lies at Γ's end,
    where the piece means resolve the end's singularity as the pieces fall)."""
    scene = _bonded(0.5)
    profile, lengths = _xfem_profile(scene, degree, cell)
    assert lengths.min() > core_tol.GAMMA_PIECE_MIN * H, lengths.min()
    s, tN, tT = (profile.columns[q] for q in ("s", "tN", "tT"))
    n = np.array([-0.5, 1.0]) / np.hypot(0.5, 1.0)
    want = np.array([n @ TOP_TRACTION, np.array([n[1], -n[0]]) @ TOP_TRACTION]) / np.hypot(1.0, 0.5)
    got = np.array([np.trapz(tN, s), np.trapz(tT, s)]) / (s[-1] - s[0])
    assert got == pytest.approx(want, rel=tol.PROFILE_MEAN_EQUILIBRIUM), (got, want)
    usual = max(_rms(off, _xfem_profile(off, degree, cell)[0], _fe_profiles(off)["gamma"])
                for off in map(_bonded, OFF_VERTEX))
    rms = _rms(scene, profile, _fe_profiles(scene)["gamma"])
    assert rms <= tol.VERTEX_VS_OFF_VERTEX * usual, (rms, usual)


def _rms(scene, got, ref) -> float:
    """The larger RMS difference of t_N and t_T, relative to the reference's
    RMS, away from the corners and Γ's ends (verification.agreement)."""
    return max(relative_rms(scene, got, ref, q, exclusion(scene)) for q in ("tN", "tT"))


def _worst(scene, got, ref, quantities) -> tuple[float, str]:
    """The worst sample of ``quantities`` relative to the reference's
    largest, away from the corners and Γ's ends (placements.worst_sample)."""
    keep = kept_samples(scene, ref, exclusion(scene))
    return max((float(np.max(np.abs(got.columns[q][keep] - ref.columns[q][keep]))
                      / np.max(np.abs(ref.columns[q][keep]))), q) for q in quantities)


# ----- EFGM: Γ along a line of nodes and cell edges --------------------------

def _vertical(x: float, law: dict):
    """Γ vertical at ``x`` (on a node line and cell edge of h = 0.1 at
    x = 0.3, 0.6, 0.8), pressed by a pressure on the top."""
    return _scene({"type": "line", "point": [x, 0.0], "normal": [1.0, 0.0]}, law,
                  [{"type": "pressure", "boundary": "top", "value": 1e6}], profile="g", moduli=(2e11, 2e11))


EXACT = {"type": "unilateral", "enforcement": "exact"}
PENALTY = {"type": "unilateral", "kN": 1e12, "kT": 1e12}
LAWS = {"exact": EXACT, "penalty": PENALTY}


def _efgm_profile(scene, degree: int):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        result = methods.solver("efgm")(scene, H, degree=degree, estimate_condition=False)
    return sample_profiles(scene, result.fields, result.interface)[0]


#: Γ on the node line x = 0.3 and 1e-9 either side of it (x = 0.6 and 0.8
#: also lie on node lines; the user's failing placements), and off every
#: node line.
ON_LINE = [0.3, 0.3 + 1e-9, 0.3 - 1e-9, 0.6, 0.8]
OFF_LINE = [0.25, 0.35, 0.45]


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("law", list(LAWS))
def test_efgm_gamma_on_a_node_line_agrees_with_itself_off_it_and_with_fe(law, degree):
    """EFGM at h = 0.1 with a vertical Γ on a line of nodes and background
    cell edges, or 1e-9 off it: solved without a RuntimeWarning (γ₀ = 0
    divided by), its g_N and t_N within VERTEX_VS_OFF_VERTEX of fe P2 at
    h/2 as the placements off the node lines are, and the three placements
    about x = 0.3 within that of each other."""
    usual = max(_worst(_vertical(x, LAWS[law]), _efgm_profile(_vertical(x, LAWS[law]), degree),
                       _fe_profiles(_vertical(x, LAWS[law]))["g"], ("gN", "tN"))[0] for x in OFF_LINE)
    bound = tol.VERTEX_VS_OFF_VERTEX * usual
    profiles = {}
    for x in ON_LINE:
        scene = _vertical(x, LAWS[law])
        profiles[x] = _efgm_profile(scene, degree)
        assert _worst(scene, profiles[x], _fe_profiles(scene)["g"], ("gN", "tN"))[0] <= bound, x
    near = _vertical(0.3, LAWS[law])
    for a, b in itertools.combinations(ON_LINE[:3], 2):
        assert _worst(near, profiles[a], profiles[b], ("gN", "tN"))[0] <= bound, (a, b)


def test_clipped_corners_make_no_spike_in_the_exact_traction_profile():
    """Γ 0.0039 h below a row of vertices clips a corner of a cell at each:
    pieces 0.008 of the others, whose own mean t_T was up to 3.6 times t_T.
    Merged into their neighbours (contactcore.interface_path.merged_pieces),
    xfem P1's t_T agrees with fe P2 at h/2 in RMS as off the vertices, and
    the force across Γ (Σ length × piece mean) is the points' ∫ t ds."""
    scene = _bonded(0.5 - 0.0039 * H)
    result = methods.solver("xfem")(scene, H, degree=1, cell="quad", estimate_condition=False)
    path = result.interface
    profile = sample_profiles(scene, result.fields, path)[0]
    ref = _fe_profiles(scene)[profile.id]
    keep = kept_samples(scene, ref, exclusion(scene))
    assert relative_rms(scene, profile, ref, "tT", exclusion(scene)) < tol.CLIPPED_CORNER_RMS
    assert np.abs(profile.columns["tT"][keep]).max() < tol.CLIPPED_CORNER_PEAK * np.abs(ref.columns["tT"][keep]).max()
    centres, which = np.unique(path.pieces, axis=0, return_inverse=True)
    lengths = np.bincount(which.ravel(), path.weights, len(centres))
    means = np.column_stack([np.bincount(which.ravel(), path.weights * t, len(centres)) for t in path.final.traction.T])
    _, merged_lengths, merged = merged_pieces(scene.interface, centres, lengths, means / lengths[:, None])
    assert len(merged_lengths) < len(lengths)
    assert merged_lengths @ merged == pytest.approx(path.weights @ path.final.traction, rel=tol.PROFILE_MEAN_EQUILIBRIUM)
