"""fe's exact enforcement at Γ's nodes with the nodal reaction as Nitsche's
flux (``FE(flux="reaction")``, xdolfinx/nodal.py; docs/contact-enforcement.md,
"A β-free exact enforcement for fe").

On docs/scenes/self_weight_beta.toml (a block under its own weight on a
stuck exact Coulomb Γ at 10°, closed form σxx = 0, σxy = T,
σyy = S0 + B(H − y)) the answer does not move with β in P1 or P2, where
the default flux's P1 answer does; it holds the closed form within fe's
discretisation error; under mpirun (the cells within two layers of Γ on
one rank, xdolfinx/gamma_partition.py) it gives the serial run's numbers."""
import functools
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import DiscretisationError, discretisation, load_scene, make_law
from self_weight_block import SCENE, closed_error, exact_profiles, scales
from xdolfinx.options import FE

BETAS = (0.3, 3.0, 30.0)
H = 0.05


@functools.lru_cache(maxsize=None)
def _profiles(degree: int, flux: str, beta: float, h: float = H) -> dict:
    """(profile id, quantity) -> (x, y, values) of the block at ``beta``."""
    return exact_profiles(SCENE, FE(degree=degree, flux=flux), beta, h)


def _beta_move(degree: int, flux: str) -> float:
    """The largest move of any profile value, β = 0.3 or 30 against 3, as a
    share of its family's scale."""
    ref = _profiles(degree, flux, 3.0)
    scale = scales(ref)
    return max(np.max(np.abs(_profiles(degree, flux, b)[k][2] - ref[k][2])) / scale[k]
               for b in (0.3, 30.0) for k in ref)


@pytest.mark.parametrize("degree", (1, 2))
def test_the_reaction_flux_does_not_move_with_beta(degree):
    """Every profile at β = 0.3 and 30 within NODAL_BETA_ROUNDOFF of β = 3's."""
    assert _beta_move(degree, "reaction") <= tol.NODAL_BETA_ROUNDOFF


def test_the_default_flux_moves_with_beta_in_p1():
    """The check above can fail: the cells' stress flux moves fe P1 by more
    than NODAL_DEFAULT_BETA_MOVE on the same block (2.4e-3 of the scale)."""
    assert _beta_move(1, "stress") > tol.NODAL_DEFAULT_BETA_MOVE


def _closed_error(degree: int, flux: str) -> float:
    """The largest error of any profile value against the closed form at
    β = 3, as a share of its family's largest exact value."""
    return closed_error(_profiles(degree, flux, 3.0))


@pytest.mark.parametrize("degree, bound", ((1, tol.NODAL_P1_CLOSED_ERROR), (2, tol.NODAL_P2_CLOSED_ERROR)))
def test_the_reaction_flux_holds_the_closed_form(degree, bound):
    """The block's closed form within fe's own discretisation error: P1's
    constant stress against a linear σyy (NODAL_P1_CLOSED_ERROR), P2 exact
    (NODAL_P2_CLOSED_ERROR), at β = 3, every profile."""
    assert _closed_error(degree, "reaction") <= bound


def test_p1_reaction_flux_error_is_the_default_flux_error():
    """P1's error against the closed form is the discretisation's, not the
    flux's: the reaction flux's is within NODAL_P1_ERROR_RATIO of the
    default flux's at β = 3."""
    assert _closed_error(1, "reaction") <= tol.NODAL_P1_ERROR_RATIO * _closed_error(1, "stress")


@pytest.mark.parametrize("degree", (1, pytest.param(2, marks=pytest.mark.slow)))
def test_two_ranks_give_the_serial_profiles(tmp_path, degree):
    """``mpirun -n 2 … --flux reaction``: every profile and interface.csv
    within PARALLEL_PARITY of the serial run's, and every increment's
    iterations and open/stick counts the same (refused until 2026-11-30),
    on a Γ that partly opens, fe P1 (P2 in the slow stage) at h = 0.1
    (measured ≤ 1.3e-13; C-coulomb exact, P2: 2.6e-12)."""
    from test_mpi import _parity
    scene = str(Path(SCENE).with_name("partial_opening_exact.toml"))
    _parity(tmp_path, scene, 2, degree, 0.1, timeout=120, options=("--flux", "reaction", "--reference", "none"))


@pytest.mark.slow
@pytest.mark.parametrize("ranks", (2, 3))
@pytest.mark.parametrize("degree", (1, 2))
def test_exact_coulomb_on_more_ranks_gives_the_serial_profiles(tmp_path, degree, ranks):
    """The same on docs/scenes/C-coulomb-exact.toml (20 increments, Γ
    partly open and slipping), h = 0.1: measured ≤ 2.6e-12 (P2, 2 ranks)."""
    from test_mpi import _parity
    scene = str(Path(SCENE).with_name("C-coulomb-exact.toml"))
    _parity(tmp_path, scene, ranks, degree, 0.1, timeout=300, options=("--flux", "reaction", "--reference", "none"))


def test_the_cells_near_gamma_go_to_one_rank_with_facet_ghosts():
    """A strip of 2 × 4 squares (two triangles each) with Γ its bottom
    row of vertices: two layers reach every cell of the first two rows
    of squares and none beyond; a cell across a facet from another rank's
    is ghosted there, one that only touches it at a vertex is not."""
    from xdolfinx.gamma_partition import _facet_ghosts, _near
    nx, ny = 2, 4
    vertex = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    cells = np.array([tri for j in range(ny) for i in range(nx) for tri in (
        (vertex[j, i], vertex[j, i + 1], vertex[j + 1, i + 1]), (vertex[j, i], vertex[j + 1, i + 1], vertex[j + 1, i]))])
    near = _near(cells, vertex[0], 2)
    assert near.tolist() == [True] * 8 + [False] * 8
    owners = np.array([0, 1])
    two = np.array([[0, 1, 2], [1, 3, 2]])  # sharing the facet (1, 2)
    assert _facet_ghosts(two, owners) == [[1], [0]]
    corner = np.array([[0, 1, 2], [2, 3, 4]])  # sharing the vertex 2 only
    assert _facet_ghosts(corner, owners) == [[], []]


def test_a_gamma_row_not_held_whole_is_refused():
    """A Γ node's row reaching an unknown this rank does not hold (a
    partition that did not keep Γ's two layers on one rank) is refused
    with NOT_ON_ONE_RANK, not read short."""
    import scipy.sparse as sp
    from xdolfinx.nodal import NOT_ON_ONE_RANK, reaction_rows
    owned = sp.csr_matrix(np.array([[2.0, -1.0, 0.0, -1.0], [-1.0, 2.0, -1.0, 0.0]]))  # 2 owned rows, 4 global columns
    L = sp.csr_matrix(np.array([[1.0, 0.0, 0.0]]))  # reads row 0; the local unknowns are global 0, 1, 2
    with pytest.raises(DiscretisationError) as err:
        reaction_rows(owned, np.array([0, 1, 2]), np.array([0, 1, -1]), L.indices)
    assert str(err.value) == NOT_ON_ONE_RANK
    held = reaction_rows(owned, np.array([0, 1, 3]), np.array([0, 1, -1]), L.indices).toarray()
    assert held.tolist() == [[2.0, -1.0, -1.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]


def test_an_unknown_flux_is_refused():
    """``flux`` is one of FE_FLUXES."""
    with pytest.raises(DiscretisationError, match="flux must be one of stress, reaction"):
        FE(flux="nodal")


def test_the_reference_fe_solves_with_the_runs_flux(monkeypatch, tmp_path):
    """``run --method fe xfem --flux reaction`` compares the runs with fe P2,
    solved apart at degree 1: that fe solve takes the runs' flux, as the fe
    P2 reference of ``--degree 2`` (one of the runs) does, so the reference
    is the same kind of fe answer at either degree (it took the default
    flux until 2026-11-30)."""
    from verification import methods, run
    asked = []
    solver = methods.solver

    def recording(name):
        solve = solver(name)
        return lambda *a, **kw: asked.append((name, kw.get("degree"), kw.get("flux"))) or solve(*a, **kw)

    monkeypatch.setattr(methods, "solver", recording)
    scene = str(Path(SCENE).with_name("partial_opening_exact.toml"))
    run.run(scene, ["fe", "xfem"], tmp_path / "out", h=0.25, flux="reaction", draw=False)
    assert ("fe", 2, "reaction") in asked and ("fe", 2, None) not in asked


def test_summary_names_fes_flux_of_an_exact_law(tmp_path):
    """summary.md's law line says fe solved with the reaction flux (its
    answer then does not move with the β it names); with the default flux,
    or a penalty law, which reads no flux, it says nothing of a flux."""
    from verification import run
    exact = str(Path(SCENE).with_name("partial_opening_exact.toml"))
    said = {(scene, flux): "flux" in run.run(scene, ["fe"], tmp_path / f"{len(scene)}{flux}", h=0.25, flux=flux,
                                             draw=False).split("\n\n")[2]
            for scene, flux in ((exact, "reaction"), (exact, None), ("A", "reaction"))}
    assert said == {(exact, "reaction"): True, (exact, None): False, ("A", "reaction"): False}


def test_the_ties_refusal_offers_the_default_flux():
    """Where the unilateral law has no consistent open/closed map with the
    reaction flux (which has no partial search), the refusal offers the
    default flux, whose partial search may settle it (scene C made exact
    unilateral, fe P1, h = 0.05: refused with the reaction, solved with the
    default flux, 2026-11-30); the default flux's refusal does not."""
    from contactcore import SolverError
    from contactcore.newton.refusals import NODAL_TIE_HINT
    base = load_scene(str(Path(__file__).resolve().parent / "scenes" / "shear_unilateral.toml"))
    scene = base.with_changes(law=make_law({"type": "unilateral", "enforcement": "exact"}))
    said = {}
    for flux in ("reaction", "stress"):
        with pytest.raises(SolverError) as err:
            discretisation.solve(scene, FE(flux=flux), 0.1)
        said[flux] = NODAL_TIE_HINT in str(err.value)
    assert said == {"reaction": True, "stress": False}


def test_a_refusal_on_the_rank_holding_gamma_ends_every_rank(tmp_path):
    """A refusal that only the rank holding Γ meets (here a Γ node on
    the rollers of both sides, x held along neither Γ's normal nor its
    tangent: docs/scenes/inclined_stick_weight_exact.toml) ends
    ``mpirun -n 2`` with the serial run's error line and exit status 2;
    the other rank waited for ever in the next collective call before
    (2026-11-30: still running after 9 minutes)."""
    from test_mpi import mpirun
    scene = Path(SCENE).with_name("inclined_stick_weight_exact.toml")
    out = mpirun(2, "-m", "verification", "run", scene, "--method", "fe", "--h", 0.1, "--flux", "reaction",
                 "--reference", "none", "--no-plots", "-q", "--out", tmp_path / "out", timeout=60)
    assert out.returncode == 2, out.stderr
    assert "along neither Γ's normal nor its tangent there; use flux = \"stress\"" in out.stderr


def test_a_mesh_whose_cells_are_all_near_gamma_is_refused_on_ranks(tmp_path):
    """At h = 0.5 every cell of the partial opening lies within two layers
    of Γ, all on rank 0: ``mpirun -n 2`` refuses in one line, exit status
    2, where rank 1, holding no cell, crashed before (a segmentation fault
    in dolfinx 0.5.2's ``DofMap.collapse``, exit 139; 2026-11-30)."""
    from test_mpi import mpirun
    scene = Path(SCENE).with_name("partial_opening_exact.toml")
    out = mpirun(2, "-m", "verification", "run", scene, "--method", "fe", "--h", 0.5, "--flux", "reaction",
                 "--reference", "none", "--no-plots", "-q", "--out", tmp_path / "out", timeout=60)
    assert out.returncode == 2, out.stderr
    assert "leaves 1 of the 2 ranks no cell; run on fewer ranks or at a smaller h" in out.stderr
