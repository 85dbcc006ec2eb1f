"""xfem's and efgm's β-free exact enforcement: a multiplier mesh on Γ and
the least-squares reaction as Nitsche's flux (``XFEM(flux="reaction")``,
``EFGM(flux="reaction")``; contactcore/reaction_flux.py,
docs/contact-enforcement.md, "A β-free exact enforcement for xfem and efgm").

On docs/scenes/self_weight_beta.toml (a block under its own weight, stuck
on an exact Coulomb Γ at 10°, closed form σxx = 0, σxy = T,
σyy = S0 + B(H − y)) and tests/scenes/stick_slip_crossing.toml (exact
Coulomb, Γ partly sticking, partly slipping) the answer of xfem P1 and
efgm P1 does not move with β, where the default flux's does; the block's
closed form holds within the methods' discretisation error; under mpirun
xfem's gives the serial run's numbers (the cells within two layers of the
cut cells on one rank) and efgm's is refused before any mesh, in one
line."""
import functools
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import scipy.sparse as sp

import tolerances as tol
from contactcore import DiscretisationError, discretisation, load_scene, make_law
from contactcore.reaction_flux import MultiplierChain, multiplier_operator, serial_refusal
from contactcore.system import InterfaceOperator
from efgm.options import EFGM
from self_weight_block import SCENE as BLOCK, closed_error, exact_profiles, scales
from xdolfinx.options import XFEM

ROOT = Path(__file__).resolve().parent.parent
STICK_SLIP = str(ROOT / "tests" / "scenes" / "stick_slip_crossing.toml")
METHODS = {"xfem": XFEM, "efgm": EFGM}
H = 0.1


@functools.lru_cache(maxsize=None)
def _profiles(path: str, method: str, flux: str, beta: float) -> dict:
    """(profile id, quantity) -> (x, y, values) of the scene at ``path``
    with its Coulomb law exact at ``beta``, at h = H."""
    return exact_profiles(path, METHODS[method](degree=1, flux=flux), beta, H)


def _beta_move(path: str, method: str, flux: str) -> float:
    """The largest move of any profile value between β = 0.3 and 30, as a
    share of its family's scale at β = 0.3."""
    low, high = _profiles(path, method, flux, 0.3), _profiles(path, method, flux, 30.0)
    scale = scales(low)
    return max(np.max(np.abs(high[k][2] - low[k][2])) / scale[k] for k in low)


@pytest.mark.parametrize("path", (BLOCK, STICK_SLIP), ids=("block", "stick_slip"))
@pytest.mark.parametrize("method", tuple(METHODS))
def test_the_reaction_flux_does_not_move_with_beta(method, path):
    """Every profile at β = 0.3 and 30 within REACTION_FLUX_BETA_ROUNDOFF."""
    assert _beta_move(path, method, "reaction") <= tol.REACTION_FLUX_BETA_ROUNDOFF


@pytest.mark.parametrize("method", tuple(METHODS))
def test_the_default_flux_moves_with_beta(method):
    """The check above can fail, and the default is the cells' stress as
    before: it moves by more than REACTION_FLUX_DEFAULT_BETA_MOVE on the
    stick-slip scene."""
    assert _beta_move(STICK_SLIP, method, "stress") > tol.REACTION_FLUX_DEFAULT_BETA_MOVE


def _closed_error(method: str, flux: str) -> float:
    """The largest error of any profile value against the block's closed
    form at β = 0.3, as a share of its family's largest exact value."""
    return closed_error(_profiles(BLOCK, method, flux, 0.3))


@pytest.mark.parametrize("method", tuple(METHODS))
def test_the_reaction_flux_holds_the_closed_form(method):
    """The block's closed form within the method's own error: no more than
    REACTION_FLUX_CLOSED_RATIO times the default flux's, every profile."""
    assert _closed_error(method, "reaction") <= tol.REACTION_FLUX_CLOSED_RATIO * _closed_error(method, "stress")


def test_efgms_mpirun_is_refused_before_any_mesh():
    """efgm's own check (every driver's first) refuses the reaction flux of
    an exact law on two processes in one line; a penalty law, which reads
    no flux, and the default flux are not refused; xfem's is not refused
    (:func:`test_xfem_on_two_ranks_gives_the_serial_profiles`)."""
    exact, two = load_scene(BLOCK), SimpleNamespace(size=2)
    with pytest.raises(DiscretisationError) as err:
        EFGM(flux="reaction", comm=two).check(exact)
    assert str(err.value) == serial_refusal("efgm") and "\n" not in str(err.value)
    EFGM(flux="stress", comm=two).check(exact)
    EFGM(flux="reaction", comm=two).check(
        exact.with_changes(law=make_law({"type": "coulomb", "mu": 0.5, "kN": 1e10, "kT": 1e10})))
    XFEM(flux="reaction", comm=two).check(exact)


def test_xfem_on_two_ranks_gives_the_serial_profiles(tmp_path):
    """``mpirun -n 2 … --method xfem --flux reaction``: every profile and
    interface.csv within PARALLEL_PARITY of the serial run's, and every
    increment's iterations and open/stick counts the same (refused until
    2026-11-30), on a Γ that partly opens, xfem P1 at h = 0.1 (measured
    1.6e-14)."""
    from test_mpi import _parity
    scene = str(Path(BLOCK).with_name("partial_opening_exact.toml"))
    _parity(tmp_path, scene, 2, 1, 0.1, methods=("xfem",), timeout=120,
            options=("--flux", "reaction", "--reference", "none"))


@pytest.mark.slow
@pytest.mark.parametrize("ranks", (2, 3))
@pytest.mark.parametrize("cell", ("quad", "triangle"))
def test_xfems_exact_coulomb_on_more_ranks_gives_the_serial_profiles(tmp_path, cell, ranks):
    """The same on docs/scenes/C-coulomb-exact.toml (Γ partly open and
    slipping), xfem P1 at h = 0.1, on quadrilaterals and triangles."""
    from test_mpi import _parity
    scene = str(Path(BLOCK).with_name("C-coulomb-exact.toml"))
    _parity(tmp_path, scene, ranks, 1, 0.1, methods=("xfem",), timeout=300,
            options=("--flux", "reaction", "--reference", "none", "--cell", cell))


@pytest.mark.parametrize("method", tuple(METHODS))
def test_an_unknown_flux_is_refused(method):
    """``flux`` is one of contactcore.reaction_flux.FLUXES."""
    with pytest.raises(DiscretisationError, match="flux must be one of stress, reaction"):
        METHODS[method](flux="nodal")


def _two_node_chain(count: int):
    """A straight Γ from (0, 0) to (1, 0) with ``count`` multiplier nodes,
    and a Gauss-point operator on it: four points, each jump the linear
    interpolation of two end pairs of unknowns (0, 1 at x = 0; 2, 3 at
    x = 1) in (g_N, g_T)."""
    x = np.array([0.125, 0.375, 0.625, 0.875])
    G = np.zeros((8, 4))
    for p, a in enumerate(x):
        for c in range(2):
            G[2 * p + c, c], G[2 * p + c, 2 + c] = 1.0 - a, a
    operator = InterfaceOperator(sp.csr_matrix(G), np.full(4, 0.25), np.column_stack([x, 0 * x]),
                                 stabilisation=np.ones(4))
    chain = MultiplierChain(0.0, 1.0 / (count - 1), count, None, np.zeros(2), np.array([1.0, 0.0]))
    return operator, chain, sp.identity(4, format="csr")


def test_a_component_held_on_both_sides_leaves_the_law():
    """A g_T row whose unknowns are all prescribed is dropped (Ĝ and L rows
    zero), and on the rows kept L inverts −B_fᵀ: the flux of the
    multipliers' answer is the multiplier."""
    operator, chain, A = _two_node_chain(2)
    held = multiplier_operator(operator, A, np.array([1, 3]), chain, "test")
    assert np.all(held.G.toarray()[1::2] == 0.0) and np.all(held.load_flux.toarray()[1::2] == 0.0)
    B = held.weights.repeat(2)[:, None] * held.G.toarray()
    kept = B[0::2][:, [0, 2]]
    assert np.allclose(held.load_flux.toarray()[0::2][:, [0, 2]] @ kept.T, -np.eye(2),
                       atol=tol.REACTION_FLUX_BETA_ROUNDOFF)


def test_undetermined_multipliers_are_refused_naming_a_node():
    """Three multiplier nodes on jumps that hold two values per component
    leave B_f B_fᵀ rank-deficient: refused, naming a node on Γ."""
    operator, chain, A = _two_node_chain(3)
    with pytest.raises(DiscretisationError, match=r'^test: flux = "reaction": the multipliers on Γ are not '
                                                  r'determined near \((0|0\.5|1), 0\)'):
        multiplier_operator(operator, A, np.zeros(0, int), chain, "test")


def test_run_passes_the_flux_to_every_method():
    """``run --flux reaction`` reaches xfem and efgm by the one path that
    reaches fe (:func:`verification.methods.options_for`), and no method
    refuses it as meaning nothing."""
    from verification import methods
    assert all(methods.options_for(m, flux="reaction") == {"flux": "reaction"} for m in methods.METHODS)
    methods.check_options(list(methods.METHODS), flux="reaction")


def test_quadrilaterals_are_ghosted_across_their_facets():
    """xfem's quadrilaterals (dolfinx's vertex order (0, 0), (1, 0), (0, 1),
    (1, 1)) under the near-Γ partition: two sharing the facet (1, 4) are
    ghosted on each other's rank; two sharing a vertex only are not."""
    from xdolfinx.gamma_partition import _facet_ghosts
    owners = np.array([0, 1])
    assert _facet_ghosts(np.array([[0, 1, 3, 4], [1, 2, 4, 5]]), owners) == [[1], [0]]
    assert _facet_ghosts(np.array([[0, 1, 3, 4], [4, 5, 7, 8]]), owners) == [[], []]


def test_a_refusal_on_one_rank_is_raised_on_every_rank(tmp_path):
    """``Collective.alike``, which guards the reaction operators' building
    (xdolfinx/reaction.py, xdolfinx/nodal.py: only the rank holding Γ can
    refuse): rank 0's DiscretisationError is raised on rank 1 too, which
    then does not wait in the next collective call (a barrier here)."""
    from test_mpi import mpirun
    code = ("from mpi4py import MPI\n"
            "from contactcore import DiscretisationError\n"
            "from contactcore.collective import Collective\n"
            "def make():\n"
            "    if MPI.COMM_WORLD.rank == 0:\n"
            "        raise DiscretisationError('refused on rank 0')\n"
            "try:\n"
            "    Collective(MPI.COMM_WORLD).alike(make)\n"
            "except DiscretisationError as exc:\n"
            f"    open(r'{tmp_path}' + f'/{{MPI.COMM_WORLD.rank}}.txt', 'w').write(str(exc))\n"
            "MPI.COMM_WORLD.Barrier()\n")
    out = mpirun(2, "-c", code, timeout=60)
    assert out.returncode == 0, out.stderr
    assert [(tmp_path / f"{r}.txt").read_text() for r in (0, 1)] == ["refused on rank 0"] * 2


@pytest.mark.parametrize("cell, degree, cells", (("quad", 1, 1), ("triangle", 1, 2), ("triangle", 2, 1)))
def test_xfem_spaces_its_multipliers_by_cell_and_degree(cell, degree, cells):
    """Γ's multiplier nodes are MULTIPLIER_SPACING_TRIANGLES_P1 (2) cells
    apart for xfem P1 on triangles (at one cell t_N alternated at 2 of 24
    inclined placements), one cell apart otherwise: the block's Γ, of
    chord c, gets round(c / (cells · h)) + 1 nodes at h = 0.1."""
    scene = load_scene(BLOCK)
    chord = np.linalg.norm(np.subtract(*scene.interface.chord(scene.domain)))
    result = discretisation.solve(scene.with_changes(law=make_law({"type": "coulomb", "mu": scene.law.mu,
                                                                   "enforcement": "exact"})),
                                  XFEM(degree=degree, cell=cell, flux="reaction"), H)
    assert len(result.interface.points) == round(chord / (cells * H)) + 1
