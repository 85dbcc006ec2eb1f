"""``python -m verification shapes``: EFGM's shape functions with gradients,
points per second.

The node set is an ``n × n`` grid on the unit square, whose supports
(``dmax · c_I``, :func:`efgm.nodes.support_radii`) are larger along the
edges; the points are uniformly random (a fixed seed).  For each basis, one
warm-up evaluation of a few points (it fills the neighbour tables), then
``repeats`` timed evaluations of all points; the median rate is reported.
Each row also carries the evaluation's largest partition-of-unity and
linear-reproduction defects, ``max |Σ Φ_I − 1|`` and ``max |Σ Φ_I x_I − x|``
(and their gradients'), so that no rate stands for a wrong evaluation.
Threads: :func:`efgm.shape.threads` (``OMP_NUM_THREADS``, else one per
core; one per rank under mpirun).  Under ``mpirun -n K`` each rank
evaluates its contiguous share of the points, as EFGM's ranks evaluate
their own cells (:mod:`efgm.distributed`): every rank starts together, an
evaluation lasts as long as its slowest rank, and the defects are the
largest of any rank's.  Writes ``DIR/shapes.csv``, ``DIR/shapes.md`` and
``DIR/run.json``.
"""
from __future__ import annotations

import logging
import time
from pathlib import Path

import numpy as np

from contactcore.budget import MEMORY_SHARE, TooLargeError, machine_memory
from contactcore.collective import SERIAL, Collective
from efgm.nodes import NodeSet, support_radii
from efgm.shape import MLS, threads

from . import files, pool

log = logging.getLogger("verification")

#: The support factor of each basis: the methods' defaults (EFGM's options).
DMAX = {"linear": 2.0, "quadratic": 3.0}

#: Seed of the random points.
SEED = 0

#: Points of the warm-up evaluation.
WARM_UP = 1000

#: Resident bytes per evaluated point, by basis (the values and gradients
#: of its neighbours, the previous evaluation's kept while the next is
#: computed): measured peaks of ``shapes --points 400000`` over 100000,
#: 1.4 kB (linear, one repeat) and 3.7 kB (quadratic, three repeats) a
#: point; rounded up.
BYTES_PER_POINT = {"linear": 2_500, "quadratic": 5_000}

#: Resident bytes per grid node (its support and neighbour tables):
#: measured 0.34 kB (``--grid 801`` over ``--grid 201``, quadratic); rounded up.
BYTES_PER_NODE = 500


def check_budget(bases: list[str], grid: int, count: int) -> None:
    """Refuse, before any evaluation, a ``--grid``/``--points`` whose
    estimated memory (:data:`BYTES_PER_POINT`, :data:`BYTES_PER_NODE`)
    exceeds :data:`~contactcore.budget.MEMORY_SHARE` of this machine's, as
    ``run`` refuses a too-small h (:func:`contactcore.budget.check_budget`)."""
    need = max(BYTES_PER_POINT[b] for b in bases) * count + BYTES_PER_NODE * grid * grid
    have = MEMORY_SHARE * machine_memory()
    if need > have:
        raise TooLargeError(f"--grid {grid} and --points {count}: about {need / 1e9:.3g} GB, against "
                            f"{have / 1e9:.3g} GB usable on this machine; use a smaller grid or fewer points, "
                            "or pass --allow-large to try anyway")


COLUMNS = ["basis", "grid", "points", "ranks", "threads", "median_s", "points_per_s", "unity", "reproduction",
           "gradient_unity", "gradient_reproduction"]


def defects(values, nodes: np.ndarray, points: np.ndarray) -> dict:
    """The partition-of-unity and linear-reproduction defects of shape
    ``values`` (:class:`efgm.shape.ShapeValues`) at ``points``: largest
    ``|Σ Φ_I − 1|``, ``|Σ Φ_I x_I − x|``, ``|Σ ∇Φ_I|`` and ``|Σ ∇Φ_I x_Iᵀ − I|``."""
    x = nodes[np.maximum(values.index, 0)]  # (P, K, 2); padded entries have Φ = 0
    gx = np.einsum("pkd,pke->pde", values.grad, x)
    return {"unity": float(np.max(np.abs(values.phi.sum(axis=1) - 1.0))),
            "reproduction": float(np.max(np.abs(np.einsum("pk,pkd->pd", values.phi, x) - points))),
            "gradient_unity": float(np.max(np.abs(values.grad.sum(axis=1)))),
            "gradient_reproduction": float(np.max(np.abs(gx - np.eye(2))))}


def _ranks() -> Collective:
    """mpirun's ranks (module doc), or one process."""
    if not pool.distributed():
        return SERIAL
    from mpi4py import MPI
    return Collective(MPI.COMM_WORLD)


def measure(basis: str, grid: int, count: int, repeats: int) -> dict:
    """One row of the table (module doc)."""
    ranks = _ranks()
    axis = np.linspace(0.0, 1.0, grid)
    nodes = np.column_stack([a.ravel() for a in np.meshgrid(axis, axis, indexing="ij")])
    degree = {"linear": 1, "quadratic": 2}[basis]
    mls = MLS(nodes, support_radii(NodeSet(nodes, 1.0 / (grid - 1)), DMAX[basis], False), degree=degree,
              dilation=DMAX[basis])
    points = np.random.default_rng(SEED).random((count, 2))[ranks.share(count)]  # this rank's share
    mls.evaluate(points[:WARM_UP])
    seconds = []
    for _ in range(repeats):
        ranks.all(True)  # every rank starts together
        start = time.perf_counter()
        values = mls.evaluate(points)
        seconds.append(ranks.max(time.perf_counter() - start))
    median = float(np.median(seconds))
    size = 1 if ranks.comm is None else ranks.comm.size
    row = {"basis": basis, "grid": grid, "points": count, "ranks": size, "threads": threads(), "median_s": median,
           "points_per_s": count / median,
           **{k: ranks.max(v) for k, v in defects(values, nodes, points).items()}}
    log.info("shapes, %s basis, %d² grid, %d points on %d rank(s) of %d thread(s): %.3g points/s (median of %d); "
             "unity %.1e, reproduction %.1e", basis, grid, count, size, row["threads"], row["points_per_s"], repeats,
             row["unity"], row["reproduction"])
    return row


def shapes(bases: list[str], grid: int, count: int, repeats: int, out: Path, argv=(),
           allow_large: bool = False) -> list[dict]:
    """The table of every basis, in this one process; unless
    ``allow_large``, it must fit the machine (:func:`check_budget`)."""
    if not allow_large:
        check_budget(bases, grid, count)
    rows = [measure(basis, grid, count, repeats) for basis in bases]
    out = Path(out)
    files.write_csv(out / "shapes.csv", rows, COLUMNS)
    files.write_text(out / "shapes.md", "# EFGM shape functions with gradients\n\n" + files.markdown_table(
        rows, COLUMNS, ["basis", "grid", "points", "ranks", "threads per rank", "median (s)", "points/s", "max |ΣΦ − 1|",
                        "max |ΣΦx − x|", "max |Σ∇Φ|", "max |Σ∇Φ xᵀ − I|"]))
    files.write_json(out / "run.json", files.provenance(list(argv)))
    return rows
