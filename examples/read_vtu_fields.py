"""Reading the field files with meshio
=====================================

``.venv/bin/python -m verification run SCENE --fields --out DIR`` writes, per
method, each body's mesh with its displacement and stress
(``DIR/<method>/fields/minus.vtu``, ``plus.vtu``) and the interface's
state at every increment (``interface_NNNN.vtu``, gathered by
``interface.pvd``).  ParaView opens them; so does meshio, in a script.
This one runs scene A through the same driver into a temporary folder
and reads the files back.

Run it with ``.venv/bin/python examples/read_vtu_fields.py``.
"""
import tempfile
from pathlib import Path

import meshio
import numpy as np

from verification.run import run

STATUS = ("open", "stick", "slip")


def main(h=0.05):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "A"
        run("A", ["fe"], out, h=h, fields=True, draw=False)
        fields = out / "fe" / "fields"
        print("files:", ", ".join(sorted(p.name for p in fields.iterdir())))

        # Each body's mesh: points (x, y, 0), the displacement u as point data
        # at the vertices, the stress at each cell's centroid as cell data.
        for body in ("minus", "plus"):
            mesh = meshio.read(fields / f"{body}.vtu")
            u = mesh.point_data["u"]
            syy = mesh.cell_data["sigma_yy_cell"][0]
            print(f"{body}: {len(mesh.points)} points, {sum(len(c.data) for c in mesh.cells)} cells, "
                  f"largest |u| = {np.max(np.linalg.norm(u, axis=1)):.3e} m, "
                  f"mean σyy = {np.mean(syy):.4g} Pa")

        # The interface at the last increment: the points of Γ where the
        # method integrates the law, with gN, gT, tN, tT and the status
        # (0 open, 1 stick, 2 slip).
        steps = sorted(fields.glob("interface_*.vtu"))
        gamma = meshio.read(steps[-1])
        tN, status = gamma.point_data["tN"], gamma.point_data["status"]
        counts = {name: int(np.sum(status == k)) for k, name in enumerate(STATUS)}
        print(f"Γ at the last of {len(steps)} step(s): {len(gamma.points)} points, mean t_N = "
              f"{np.mean(tN):.4g} Pa, {counts}")
        return {"files": sorted(p.name for p in fields.iterdir()), "mean_tN": float(np.mean(tN)),
                "counts": counts, "plus_syy": float(np.mean(meshio.read(fields / "plus.vtu")
                                                           .cell_data["sigma_yy_cell"][0]))}


if __name__ == "__main__":
    main()
