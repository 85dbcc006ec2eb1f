"""EFGM under mpirun: its cells, Γ's points and rows split over the ranks
give the serial system and the serial run's files.  Each parity case is a
real ``mpirun`` of the command line (``tests/test_mpi.py``'s helpers; scene
A on two ranks is its test_every_method_on_two_ranks_gives_the_serial_profiles);
the system itself is compared, gathered, in a probe run under mpirun."""
import json

import pytest

import tolerances as tol
from test_mpi import _errors, _parity, mpirun

#: h of every case: coarse, so that a case takes a few seconds.
H = 0.1


@pytest.mark.slow
@pytest.mark.parametrize("ranks, scene", [(2, "C-coulomb"), (3, "A"), (3, "C-coulomb"), (2, "C")])
def test_efgm_parity(tmp_path, ranks, scene):
    """Profiles, and for C-coulomb the interface history and every
    increment's iterations and open/stick/slip counts (increments.csv).
    Not the quadratic basis: on scene A at this h its profiles on 2 ranks
    differ from the serial ones by 2.2e-10 (measured), as much as two serial
    factorisations of the same matrix do (MUMPS LU against LDLᵀ: 2.7e-10;
    the system gathered from the ranks equals the serial one to 2e-16), so
    PARALLEL_PARITY is below what its conditioning lets any solver repeat."""
    _parity(tmp_path, scene, ranks, 1, H, methods=("efgm",))


#: Builds scene argv[1] at h = argv[2] serially (COMM_SELF) and spread over
#: the ranks, and prints, on rank 0, the largest relative differences of the
#: gathered matrix, loads, A u and Γ's jumps of a random u (Γ's points put in
#: the canonical order along Γ), and whether Γ's points are the same.
PROBE = """
import json, sys
import numpy as np
import scipy.sparse as sp
from mpi4py import MPI
from contactcore import load_scene, discretisation as d
from contactcore.interface_path import canonical_order
from contactcore.result import Timings
from contactcore.scaling import Scales
from efgm.options import EFGM

scene = load_scene(sys.argv[1]); s = Scales.of(scene); scene = s.scene(scene)
res = d.Resolution(float(sys.argv[2]) / s.length)
serial = EFGM(comm=MPI.COMM_SELF).build(scene, res, Timings()).system
spread = EFGM().build(scene, res, Timings()).system
ranks = spread.collective
indptr, cols, vals = spread.A.getValuesCSR()
first = spread.A.getOwnershipRange()[0]
rows = np.repeat(np.arange(first, first + len(indptr) - 1), np.diff(indptr))
A = sp.csr_matrix((ranks.gather(vals), (ranks.gather(rows), ranks.gather(cols))), shape=serial.A.shape)
u = np.random.default_rng(0).standard_normal(serial.size)
mine = slice(first, first + spread.size)
factors = ([1.0] * len(scene.loads), [1.0] * len(scene.supports))
points = ranks.gather(spread.interface.points)
o_s, o_p = canonical_order(scene.interface, serial.interface.points), canonical_order(scene.interface, points)

def worst(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(a)))

out = {"matrix": float(abs(A - serial.A).max() / abs(serial.A).max()),
       "loads": worst(serial.external(*factors), ranks.gather(spread.external(*factors))),
       "internal": worst(serial.internal(u), ranks.gather(spread.internal(u[mine]))),
       "jumps": worst(serial.interface.jumps(u)[o_s], ranks.gather(spread.interface.jumps(u[mine]))[o_p]),
       "same_points": bool(np.array_equal(serial.interface.points[o_s], points[o_p])),
       "owned": [int(n) for n in ranks.comm.allgather(spread.size)]}
serial.close()
spread.close()
if ranks.rank == 0:
    print("PROBE", json.dumps(out), flush=True)
"""


@pytest.mark.parametrize("ranks, scene", [(2, "A"), pytest.param(3, "C-coulomb", marks=pytest.mark.slow)])
def test_distributed_system_equals_the_serial_one(ranks, scene):
    """The MPIAIJ matrix gathered from the ranks equals the serial saddle
    point, and so do the loads, ``A u`` and Γ's jumps: every cell, boundary
    point, Γ point and collocation row counted once, on the right rows."""
    out = mpirun(ranks, "-c", PROBE, scene, H, timeout=120)
    lines = [line for line in out.stdout.splitlines() if line.startswith("PROBE")]
    assert out.returncode == 0 and len(lines) == 1, out.stdout + out.stderr
    probe = json.loads(lines[0].split(" ", 1)[1])
    assert probe["same_points"], probe
    assert len(probe["owned"]) == ranks and min(probe["owned"]) > 0, probe
    for key in ("matrix", "loads", "internal", "jumps"):
        assert probe[key] <= tol.EFGM_DISTRIBUTED_ASSEMBLY, (key, probe)


def test_a_too_small_dilation_ends_in_one_line_under_mpirun(tmp_path):
    """A dilation too small for the nodes (the moment matrix is singular at
    points of several ranks' cells, each rank finding its own first point):
    every rank raises rank 0's error, one line, exit 2, nothing written."""
    out = mpirun(2, "-m", "verification", "run", "A", "--method", "efgm", "--h", H, "--dmax", "1.0",
                 "--out", tmp_path / "o", timeout=120)
    assert out.returncode == 2 and len(_errors(out)) == 1, out.stderr
    assert "is too small here" in _errors(out)[0], out.stderr
    assert not (tmp_path / "o").exists()


#: The command line with EFGM's stiffness failing on rank 1 alone (an
#: error injected where a rank evaluates its own cells).
ONE_RANK_FAILS = """
import sys
from mpi4py import MPI
from contactcore import DiscretisationError
from efgm.operators import Approximation
stiffness = Approximation.stiffness_and_forces
def failing(self, *args, **kwargs):
    if MPI.COMM_WORLD.rank == 1:
        raise DiscretisationError("efgm: injected on rank 1 alone")
    return stiffness(self, *args, **kwargs)
Approximation.stiffness_and_forces = failing
from verification.__main__ import main
sys.exit(main(sys.argv[1:]))
"""


def test_an_error_one_rank_meets_is_raised_on_every_rank(tmp_path):
    """An error met by one rank in its own share of the work is raised on
    every rank alike: one line from rank 0, exit 2, no rank left waiting
    in a collective (the timeout would fail the test)."""
    out = mpirun(2, "-c", ONE_RANK_FAILS, "run", "A", "--method", "efgm", "--h", H, "--out", tmp_path / "o",
                 timeout=120)
    assert out.returncode == 2 and _errors(out) == ["error: efgm: injected on rank 1 alone"], out.stderr
    assert not (tmp_path / "o").exists()


@pytest.mark.slow
def test_shapes_benchmark_splits_its_points_over_the_ranks(tmp_path):
    """``mpirun -n 2 … shapes``: one row per basis for 2 ranks, the points
    split between them (each evaluation as long as its slowest rank), and
    the defects of every rank's shape functions at round-off."""
    import csv

    out = mpirun(2, "-m", "verification", "shapes", "--grid", "11", "--points", "3000", "--repeats", "1",
                 "--out", tmp_path / "s", timeout=120)
    assert out.returncode == 0, out.stderr
    with open(tmp_path / "s" / "shapes.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert [(r["basis"], r["ranks"], r["threads"], r["points"]) for r in rows] == [
        ("linear", "2", "1", "3000"), ("quadratic", "2", "1", "3000")]
    for row in rows:
        assert max(float(row[k]) for k in ("unity", "reproduction")) <= tol.SHAPE_ROUNDOFF
        assert max(float(row[k]) for k in ("gradient_unity", "gradient_reproduction")) <= tol.SHAPE_GRADIENT_ROUNDOFF
