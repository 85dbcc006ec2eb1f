"""``python -m verification study``: one input varied, every method solved.

    python -m verification study SCENE --param NAME --values V1 V2 ... [--method ...] [--degree 1] [--h H] --out DIR

Parameters (:data:`PARAMETERS`): the mesh size ``h``; the springs ``kN``,
``kT``; the materials ``E_minus``, ``nu_minus``, ``E_plus``, ``nu_plus``;
and the geometry of Γ — ``radius`` of a circular Γ, ``offset`` of a straight
Γ along its normal, ``angle`` of a straight Γ (degrees from the x axis,
turned about the middle of its chord).  A geometry change is a new scene,
so the conforming method meshes it afresh through gmsh (and XFEM with
``--cell gmsh`` too); the scene's own profiles may no longer lie on the moved
Γ, so the study samples Γ itself: for each point it records DOFs, wall
time, solver health, and the largest |g_N|, |g_T|, |t_N|, |t_T| on Γ with
the mean t_N and t_T.  Every point is logged as it ends; a point that fails
(bad value, refused solve) is recorded with its message and the study goes
on.  Writes ``DIR/study.csv``, ``DIR/study.md`` and ``DIR/study.png``.
"""
from __future__ import annotations

import dataclasses
import logging
from pathlib import Path

import numpy as np

from contactcore import CircleInterface, ContactError, LineInterface, SceneError, load_scene, sample_profile
from contactcore.scene import InterfaceProfile

from . import files, methods
from .outcomes import attempt, health

log = logging.getLogger("verification")

#: Γ sampled by the study (the scene's profiles may not survive a change of Γ).
GAMMA = InterfaceProfile("gamma", ("gN", "gT", "tN", "tT"), parameter="arclength")
OUTPUTS = ["max_gN", "max_gT", "max_tN", "max_tT", "mean_tN", "mean_tT"]


def _material(scene, body: str, key: str, value: float):
    mats = dict(scene.materials)
    mats[body] = dataclasses.replace(mats[body], **{key: value})
    return {"materials": mats}


def _law(scene, key: str, value: float):
    if key not in scene.law.parameters:
        raise SceneError(f"--param {key}", f"the '{scene.law.name}' law has no parameter {key}")
    return {"law": dataclasses.replace(scene.law, **{key: value})}


def _radius(scene, value: float):
    if not isinstance(scene.interface, CircleInterface):
        raise SceneError("--param radius", "needs a circular interface")
    return {"interface": CircleInterface(scene.interface.centre, value)}


def _line(scene, name: str):
    if not isinstance(scene.interface, LineInterface):
        raise SceneError(f"--param {name}", "needs a straight interface")
    return scene.interface


def _offset(scene, value: float):
    itf = _line(scene, "offset")
    n = np.asarray(itf.normal, float) / np.linalg.norm(itf.normal)
    return {"interface": LineInterface(tuple(np.asarray(itf.point) + value * n), tuple(n))}


def _angle(scene, value: float):
    mid = _line(scene, "angle").chord(scene.domain).mean(axis=0)
    a = np.radians(value)
    return {"interface": LineInterface(tuple(mid), (-np.sin(a), np.cos(a)))}


#: What each parameter changes in a scene: name -> (description, changes(scene, value) -> dict).
PARAMETERS = {
    "h": ("cell size or node spacing (m)", None),
    "kN": ("normal spring k_N (Pa/m)", lambda s, v: _law(s, "kN", v)),
    "kT": ("tangential spring k_T (Pa/m)", lambda s, v: _law(s, "kT", v)),
    "E_minus": ("Young's modulus of the − body (Pa)", lambda s, v: _material(s, "minus", "E", v)),
    "nu_minus": ("Poisson's ratio of the − body", lambda s, v: _material(s, "minus", "nu", v)),
    "E_plus": ("Young's modulus of the + body (Pa)", lambda s, v: _material(s, "plus", "E", v)),
    "nu_plus": ("Poisson's ratio of the + body", lambda s, v: _material(s, "plus", "nu", v)),
    "radius": ("radius of a circular Γ (m)", _radius),
    "offset": ("shift of a straight Γ along its normal (m)", _offset),
    "angle": ("angle of a straight Γ to the x axis (degrees)", _angle),
}


def scene_at(scene, param: str, value: float):
    """``scene`` with ``param`` set to ``value``, sampled on Γ, validated."""
    if param not in PARAMETERS:
        raise SceneError("--param", f"unknown parameter {param!r} (known: {', '.join(PARAMETERS)})")
    change = PARAMETERS[param][1]
    return scene.with_changes(profiles=(GAMMA,), **(change(scene, value) if change else {}))


def _outputs(scene, result) -> dict:
    prof = sample_profile(scene, result.fields, GAMMA).columns
    return {"max_gN": float(np.max(np.abs(prof["gN"]))), "max_gT": float(np.max(np.abs(prof["gT"]))),
            "max_tN": float(np.max(np.abs(prof["tN"]))), "max_tT": float(np.max(np.abs(prof["tT"]))),
            "mean_tN": float(np.mean(prof["tN"])), "mean_tT": float(np.mean(prof["tT"]))}


COLUMNS = ["value", "method", "degree", "status", "dofs", "total", "condition", "backward_error", *OUTPUTS,
           "message"]


def study(scene_name: str, param: str, values: list[float], method_names: list[str], out: Path, *, degree: int = 1,
          h: float | None = None, cell: str | None = None, argv=()) -> str:
    """Run the study and write its table and plot; return the Markdown section."""
    base = load_scene(scene_name)
    scene_at(base, param, values[0])  # an unknown or inapplicable parameter ends here, before any solve
    names = methods.expand(method_names)
    rows, total = [], len(values) * len(names)
    for i, value in enumerate(values):
        for j, name in enumerate(names):
            k = i * len(names) + j + 1
            row = {"value": value, "method": name, "degree": degree}
            try:
                scene = scene_at(base, param, value)
            except ContactError as exc:
                rows.append({**row, "status": "failed", "message": str(exc)})
                log.warning("[%d/%d] %s = %g, %s: failed: %s", k, total, param, value, name, exc)
                continue
            options = methods.options_for(name, cell=cell)
            tried = attempt(methods.solver(name), scene, value if param == "h" else h, degree=degree, **options)
            row.update(health(tried))
            if tried.refused:
                rows.append({**row, "status": "failed", "message": tried.message})
                log.warning("[%d/%d] %s = %g, %s: failed: %s", k, total, param, value, name, tried.message)
                continue
            status = "warned" if tried.result.solver.warnings else "ok"
            rows.append({**row, "status": status, "message": "; ".join(tried.result.solver.warnings),
                         **_outputs(scene, tried.result)})
            log.info("[%d/%d] %s = %g, %s: %s, %d DOFs, %.2f s", k, total, param, value, name, status,
                     tried.result.dofs, tried.result.timings.total)
    out = Path(out)
    files.write_csv(out / "study.csv", rows, COLUMNS)
    _plot(out / "study.png", base.name, param, rows)
    text = markdown(base.name, param, rows)
    files.write_text(out / "study.md", text)
    files.write_json(out / "run.json", {**files.provenance(list(argv)), "scene": scene_name, "param": param,
                                        "values": values, "methods": names, "degree": degree, "h": h})
    return text


def markdown(scene_name: str, param: str, rows: list[dict]) -> str:
    """The study's section: its plot and its table."""
    failed = [r for r in rows if r["status"] == "failed"]
    return (f"## Study: scene {scene_name}, {param} ({PARAMETERS[param][0]})\n\n![study](study.png)\n\n"
            + files.markdown_table(rows, ["value", "method", "status", "dofs", "total", *OUTPUTS, "message"],
                                   [param, "method", "status", "DOFs", "total (s)", "max |g_N|", "max |g_T|",
                                    "max |t_N|", "max |t_T|", "mean t_N", "mean t_T", "message"])
            + (f"\n{len(failed)} of {len(rows)} points failed; the study went on.\n" if failed else ""))


def _plot(path: Path, scene_name: str, param: str, rows: list[dict]) -> None:
    from .plots import UNITS, pyplot, save

    fig, axes = pyplot().subplots(2, 2, figsize=(9, 6.5), squeeze=False)
    values = [r["value"] for r in rows]
    logx = min(values) > 0 and max(values) / min(values) > 100
    for ax, q in zip(axes.ravel(), ("gN", "gT", "tN", "tT")):
        for name in dict.fromkeys(r["method"] for r in rows):
            pts = [(r["value"], r[f"max_{q}"]) for r in rows if r["method"] == name and r["status"] != "failed"]
            if pts:
                ax.plot(*zip(*pts), "o-", label=name)
        ax.set_ylabel("max |" + UNITS[q].split(" ")[0] + "| " + UNITS[q].split(" ")[1])
        ax.set_xlabel(param)
        if logx:
            ax.set_xscale("log")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Scene {scene_name}: interface response against {param}")
    save(fig, path)
