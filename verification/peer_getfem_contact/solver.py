"""The peer's entry point: a scene solved by GetFEM's contact, increment by increment.

:func:`solve` checks the scene (:mod:`.reach`), builds the two bodies
(:mod:`.bodies`) and the model (:mod:`.bricks`), then for each increment
of the scene's load path (:meth:`Scene.factors`) sets the loads, runs
GetFEM's Newton (:mod:`.newton`) and records Γ's jump, traction and
status (:mod:`.gamma`).  Under Coulomb's law the increment's displacements
become the next one's ``w`` (the slip increment's origin); under the tied
``unilateral`` law a point that slips all the same is refused by name:
the tie did not hold.

Contract: the common entry point of a method, ``solve(scene, h, *,
degree, paper, estimate_condition) -> Result``, with
:class:`GetFEMContactFields`, the interface record and the timings of
``mesh`` (the two bodies), ``assembly`` (the bricks) and ``solve`` (the
increments); ``discretisation`` names h, the degrees, the augmentation
and the points per facet.
"""
from __future__ import annotations

import time

import numpy as np

from contactcore import DiscretisationError, Result, Scene, Timings
from contactcore.interface_path import Increment, InterfacePath
from contactcore.laws import SLIP
from contactcore.result import SolverReport
from contactcore.scene import check_resolution
from verification.peer_getfem import getfem_module

from .bodies import MULTIPLIER_DEGREE, _Bodies
from .bricks import TIE_FRICTION, _bricks, _set_loads
from .fields import GetFEMContactFields
from .gamma import FACET_POINTS, _Gamma
from .newton import _newton
from .reach import METHOD, _check


def solve(scene: Scene, h: float | None = None, *, degree: int = 2, paper: bool = False,
          estimate_condition: bool | None = None) -> Result:
    """Solve ``scene`` (an exact unilateral or Coulomb law) with GetFEM's
    Alart–Curnier contact between the two bodies' meshes of size h, over
    the scene's increments (``estimate_condition`` is accepted for the
    common entry point; GetFEM gives no estimate)."""
    _check(scene, degree, paper)
    h = check_resolution(scene, scene.h if h is None else h, "h")
    gf = getfem_module()
    start, timings = time.perf_counter(), Timings()
    with timings.measure("mesh"):
        bodies = _Bodies(gf, scene, h, degree)
    with timings.measure("assembly"):
        md = gf.Model("real")
        _bricks(gf, md, scene, bodies, degree)
    fields, gamma = GetFEMContactFields(md, bodies, scene), _Gamma(scene, bodies, degree)
    path = InterfacePath(gamma.points, gamma.weights, pieces=gamma.pieces)
    report = SolverReport(solver="getfem Alart–Curnier (MUMPS)", increments=scene.increments)
    r, mu = md.variable("r")[0], md.variable("friction")[0]
    g_before = np.zeros((len(gamma.points), 2))
    with timings.measure("solve"):
        for k in range(1, scene.increments + 1):
            _set_loads(md, scene, bodies, k)
            iterations, history = _newton(md, scene, k, r)
            g, t = gamma.jump(fields), gamma.traction(fields)
            status = gamma.status(t, g, g - g_before if scene.law.name == "coulomb" else g, r, mu)
            path.steps.append(Increment(k, scene.factors(k), iterations, history, g, t, status))
            report.iterations.append(iterations)
            report.residual = history[-1]
            if scene.law.name == "coulomb":
                for var in _Bodies.VARS.values():
                    md.set_variable(f"w_{var}", md.variable(var))
            elif np.any(status == SLIP):
                raise DiscretisationError(f"{METHOD}: scene {scene.name}, increment {k}: a closed point slipped at "
                                          f"μ = {TIE_FRICTION:g}; the unilateral law's tie did not hold")
            g_before = g
    timings.total = time.perf_counter() - start
    return Result(method=METHOD, scene=scene, degree=degree, dofs=bodies.dofs(), timings=timings, solver=report,
                  fields=fields, interface=path,
                  discretisation={"h": h, "degree": degree, "multiplier_degree": MULTIPLIER_DEGREE,
                                  "augmentation": float(r), "facet_points": FACET_POINTS})
