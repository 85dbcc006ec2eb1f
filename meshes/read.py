"""A user's gmsh mesh of a scene, read and checked before fe solves on it.

The file must carry the physical groups of :mod:`meshes.tags` by name
(``body_minus``, ``body_plus``, ``interface``, ``boundary_NAME``), as
``python -m meshes`` writes them; their numbers may be anything (gmsh
renumbers a group the user edits).  :func:`read_mesh_file` reads it into
plain arrays in the file's (the user's) coordinates (cached by path, size
and modification time); :func:`check_mesh` holds it to the scene, each
problem one :class:`DiscretisationError` line; :func:`load_model` puts it
in the current gmsh model, moved to the dimensionless scene's
coordinates and its groups renumbered to :mod:`meshes.tags`, for
dolfinx's ``model_to_mesh`` (as :func:`meshes.build.build_model` does for
fe's own mesh).

The mesh's spacing ``h`` is its largest cell diameter (a triangle's
longest side, between its corners): the size gmsh's ``Mesh.MeshSizeMax``
bounds, the ``h`` of ``python -m meshes --h`` with or without ``--grade``.
"""
from __future__ import annotations

import hashlib
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from contactcore import DiscretisationError
from contactcore import tolerances as tol
from contactcore.geometry import CircleInterface, Disc
from contactcore.scene import EDGE, place_of

from .tags import BODY, BOUNDARY, INTERFACE, NAMES

#: gmsh's element types fe takes, by geometry order: 3- and 6-node triangles, 2- and 3-node lines.
TRIANGLES = {2: 1, 9: 2}
LINES = {1: 1, 8: 2}

#: What the measure of ``h`` is called in records and messages.
H_MEASURE = "largest cell diameter (a triangle's longest side)"

#: The extension of gmsh's own format, the one whose physical groups carry
#: names (VTK, STL, INP... written by gmsh keep none).
MSH = ".msh"

#: The physical groups every mesh needs (dimension, name).
REQUIRED = ((2, NAMES[BODY["minus"]]), (2, NAMES[BODY["plus"]]), (1, NAMES[INTERFACE]))


@dataclass(frozen=True)
class MeshFile:
    """A gmsh mesh file's content, in the file's coordinates.

    ``nodes`` (n, 2); ``groups`` (dimension, physical name) -> the node
    indices of its elements ((m, k), corners first, gmsh's order);
    ``cells`` every triangle (m, k) and ``cell_groups`` how many body
    groups hold each; ``others`` the 2D element types that are no
    triangle; ``order`` the geometry order of its triangles."""

    path: str
    sha256: str
    nodes: np.ndarray
    groups: dict
    cells: np.ndarray
    cell_groups: np.ndarray
    others: tuple
    order: int

    @property
    def name(self) -> str:
        return Path(self.path).name

    def group(self, name: str, dim: int) -> np.ndarray | None:
        return self.groups.get((dim, name))

    @property
    def h(self) -> float:
        """The largest cell diameter (:data:`H_MEASURE`), in the file's unit."""
        return float(_side_lengths(self.nodes, self.cells[:, :3]).max())

    def record(self) -> dict:
        """summary.json's and run.json's ``"mesh"``: the file, its content's hash, its h and what h measures."""
        return {"file": self.name, "path": self.path, "sha256": self.sha256, "h": self.h, "h_measure": H_MEASURE,
                "cells": int(len(self.cells)), "geometry_order": self.order}


def _side_lengths(nodes: np.ndarray, tri: np.ndarray) -> np.ndarray:
    """Each triangle's longest side (between corners)."""
    p = nodes[tri]
    return np.max(np.linalg.norm(p - np.roll(p, -1, axis=1), axis=2), axis=1)


_cache: dict = {}


def _problem(path, text: str) -> DiscretisationError:
    return DiscretisationError(f"fe: mesh {path}: {text}")


def read_mesh_file(path) -> MeshFile:
    """The mesh file ``path`` (:class:`MeshFile`), read with gmsh; a file
    that is missing, unreadable, of no 2D cells or of cells fe does not
    take (quadrilaterals, order above 2) is refused by name."""
    path = str(path)
    try:
        st = os.stat(path)
        data = Path(path).read_bytes()
    except OSError as exc:
        raise _problem(path, f"cannot read it ({exc.strerror or exc})") from None
    key = (os.path.abspath(path), st.st_size, st.st_mtime_ns)
    if key not in _cache:
        _cache.clear()  # one mesh at a time: a run reads one file
        _cache[key] = _read(path, hashlib.sha256(data).hexdigest())
    return _cache[key]


def _read(path: str, sha256: str) -> MeshFile:
    from .build import gmsh, gmsh_session
    with gmsh_session():
        gmsh.model.add("user_mesh")
        try:
            gmsh.open(path)
        except Exception as exc:  # noqa: BLE001 - gmsh raises a bare Exception with its message
            raise _problem(path, f"gmsh cannot read it ({str(exc).strip() or 'no message'})") from None
        try:
            tags, coords, _ = gmsh.model.mesh.getNodes()
            index = {int(t): i for i, t in enumerate(tags)}
            nodes = np.asarray(coords, float).reshape(-1, 3)[:, :2]
            lookup = np.vectorize(index.__getitem__, otypes=[np.int64])
            cells, others, orders, cell_tags = [], set(), set(), []
            for etype, etags, enodes in zip(*gmsh.model.mesh.getElements(2)):
                if int(etype) not in TRIANGLES:
                    others.add(gmsh.model.mesh.getElementProperties(int(etype))[0])
                    continue
                orders.add(TRIANGLES[int(etype)])
                k = len(enodes) // len(etags)
                cells.append(lookup(np.asarray(enodes, np.int64)).reshape(-1, k) if len(etags) else np.zeros((0, k)))
                cell_tags.append(np.asarray(etags, np.int64))
            groups, in_bodies = {}, []
            body_names = {NAMES[t] for t in BODY.values()}
            for dim, ptag in gmsh.model.getPhysicalGroups():
                name = gmsh.model.getPhysicalName(dim, ptag)
                rows, body_tags = [], []
                for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, ptag):
                    for etype, etags, enodes in zip(*gmsh.model.mesh.getElements(dim, entity)):
                        if len(etags):
                            rows.append(lookup(np.asarray(enodes, np.int64)).reshape(len(etags), -1))
                            body_tags.append(np.asarray(etags, np.int64))
                width = min((r.shape[1] for r in rows), default=dim + 1)  # corners first: a mix keeps them
                joined = np.concatenate([r[:, :width] for r in rows]) if rows else np.zeros((0, width), np.int64)
                if (dim, name) in groups:
                    joined = np.concatenate([groups[dim, name][:, :joined.shape[1]], joined])
                groups[dim, name] = joined
                if dim == 2 and name in body_names:
                    in_bodies += body_tags
        finally:
            gmsh.model.remove()
    if others:
        raise _problem(path, f"has {', '.join(sorted(others))} cells: fe takes triangles only (3 or 6 nodes; "
                             "gmsh recombines into quadrilaterals only when asked: leave Mesh.RecombineAll off)")
    if not cells:
        raise _problem(path, "holds no triangles (a 2D mesh of the scene's domain is needed)")
    if len(orders) > 1:
        raise _problem(path, "mixes straight (3-node) and curved (6-node) triangles: give one geometry order")
    width = min(c.shape[1] for c in cells)
    cells_all, tags_all = np.concatenate([c[:, :width] for c in cells]), np.concatenate(cell_tags)
    counted = np.concatenate(in_bodies) if in_bodies else np.zeros(0, np.int64)
    order_of = {t: i for i, t in enumerate(tags_all.tolist())}
    count = np.zeros(len(tags_all), np.int64)
    np.add.at(count, np.array([order_of[t] for t in counted.tolist() if t in order_of], np.int64), 1)
    return MeshFile(path, sha256, nodes, groups, cells_all, count, (), orders.pop())


def _names(scene) -> dict[str, str]:
    """The boundary groups the scene's supports and edge loads need, each with the first that needs it."""
    needed = {}
    for i, s in enumerate(scene.supports):
        needed.setdefault(s.boundary, f"supports[{i}]")
    for i, ld in enumerate(scene.loads):
        if place_of(ld) == EDGE:
            needed.setdefault(ld.boundary, f"loads[{i}]")
    return needed


def _edges(tri: np.ndarray) -> np.ndarray:
    """Each triangle's three sides as sorted corner pairs (3m, 2)."""
    c = tri[:, :3]
    return np.sort(np.stack([c[:, [0, 1]], c[:, [1, 2]], c[:, [2, 0]]], axis=1).reshape(-1, 2), axis=1)


def _uncovered(params: np.ndarray, start: float, end: float, gap: float) -> tuple[float, float] | None:
    """The first stretch of ``[start, end]`` longer than ``gap`` that no
    interval (rows of ``params``, in either order) covers, or None."""
    if not len(params):
        return start, end
    iv = np.sort(params, axis=1)
    iv = iv[np.argsort(iv[:, 0])]
    reach = start
    for lo, hi in iv:
        if lo > reach + gap:
            return reach, lo
        reach = max(reach, hi)
    return (reach, end) if reach < end - gap else None


def check_mesh(scene, mesh: MeshFile, degree: int) -> list[str]:
    """Refuse ``mesh`` for the user's ``scene`` (its coordinates the
    scene's) with one line naming the first problem, in this order:
    physical groups missing by name; cells in no body or in both; a mesh
    that reaches past the domain or short of it (another domain's mesh);
    Γ's facets not on the scene's Γ (a node farther than ``NODE_MATCH`` of the
    scene's length from it, the mesher's own test of a point on a curve),
    not between a − and a + cell, or not covering Γ end to end (and a −/+
    side that is no Γ facet); body cells on Γ's other side (body_minus and
    body_plus swapped: :func:`_check_bodies`); a support's or edge load's boundary group
    missing, off its boundary or not covering it; a pin that is no mesh
    vertex.  Returns the warnings of a mesh that solves: straight cells on
    a circular Γ (:func:`meshes.build.polygon_warnings`, at the size of
    the mesh's Γ facets; and at ``degree`` 2, where fe's own mesh is
    curved, that the file's is not)."""
    near = tol.NODE_MATCH * scene.length_scale
    unit = scene.units.length
    where = f"{mesh.path}"
    names = [NAMES[t] for t in BODY.values()] + [NAMES[INTERFACE]]
    missing = [name for dim, name in REQUIRED if mesh.group(name, dim) is None]
    if missing and not mesh.groups and Path(mesh.path).suffix.lower() != MSH:
        raise _problem(where, f"has no physical groups: its format ({Path(mesh.path).suffix or 'no extension'}) "
                              f"carries no physical names, and fe reads {', '.join(names)} and boundary_NAME by "
                              "name: write the mesh as .msh (python -m meshes SCENE --out FILE.msh)")
    if missing:
        held = sorted({n for _, n in mesh.groups}) or ["none"]
        raise _problem(where, f"no physical group named {', '.join(missing)} (it has {', '.join(held)}); fe needs "
                              f"{', '.join(names)} and boundary_NAME for each boundary a support or load acts on, "
                              "by name (meshes/tags.py; python -m meshes writes them)")
    none, both = int(np.sum(mesh.cell_groups == 0)), int(np.sum(mesh.cell_groups > 1))
    if none or both:
        what = (f"{none} of its {len(mesh.cells)} cells are in no body group" if none else
                f"{both} of its {len(mesh.cells)} cells are in both body_minus and body_plus")
        raise _problem(where, f"{what}: every triangle must be in exactly one of body_minus, body_plus")
    _check_extent(scene, mesh, where, near, unit)
    _check_sides(scene, mesh, where, near, unit)
    _check_interface(scene, mesh, where, near, unit)
    _check_bodies(scene, mesh, where, near)
    for boundary, user in _names(scene).items():
        _check_boundary(scene, mesh, where, boundary, user, near, unit)
    corners = np.unique(mesh.cells[:, :3])
    for i, pin in enumerate(scene.pins):
        d = np.hypot(*(mesh.nodes[corners] - np.asarray(pin.point)).T)
        if d.min() > near:
            raise _problem(where, f"pins[{i}] at ({pin.point[0]:g}, {pin.point[1]:g}) {unit} is no vertex of the mesh "
                                  f"(the nearest is {d.min():.3g} {unit} away, more than {near:.3g}): fe holds a "
                                  "pin at a vertex; embed the point in gmsh (python -m meshes does)")
    return _order_warnings(scene, mesh, degree)


def _span(lo, hi, unit: str) -> str:
    return f"x {lo[0]:.6g} to {hi[0]:.6g}, y {lo[1]:.6g} to {hi[1]:.6g} {unit}"


def _check_extent(scene, mesh: MeshFile, where: str, near: float, unit: str) -> None:
    """The mesh's nodes against the scene's domain: a node farther than
    ``near`` outside it, or the nodes' extent short of the domain's by more
    than ``near`` (a rectangle's bounding box side by side; a disc's
    largest distance from the centre, its boundary nodes on the circle):
    the mesh of another domain (newuser34: scene A's 1 × 1 mesh on a 2 × 1
    scene was called a hole), or cells left out at the boundary."""
    dom, corners = scene.domain, mesh.nodes[np.unique(mesh.cells[:, :3])]
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    if isinstance(dom, Disc):
        reach = float(np.hypot(*(corners - np.asarray(dom.centre, float)).T).max())
        theirs, wanted = f"reach {reach:.6g} {unit} from the disc's centre", f"its radius is {dom.radius:g} {unit}"
        short, past = reach < dom.radius - near, reach > dom.radius + near
    else:
        d_lo, d_hi = np.asarray(dom.corner, float), np.add(dom.corner, dom.size)
        theirs, wanted = f"span {_span(lo, hi, unit)}", f"the domain {_span(d_lo, d_hi, unit)}"
        short = bool(np.any(lo > d_lo + near) or np.any(hi < d_hi - near))
        past = bool(np.any(lo < d_lo - near) or np.any(hi > d_hi + near))
    if past:
        raise _problem(where, f"it reaches past the scene's domain: its nodes {theirs}, {wanted} (the mesh of "
                              "another domain, or in another length unit?)")
    if short:
        raise _problem(where, f"it does not cover the scene's domain: its nodes {theirs}, {wanted} (the mesh of "
                              "another domain, or cells left out: gmsh writes only cells in a physical group "
                              "unless Mesh.SaveAll is 1)")


def _check_bodies(scene, mesh: MeshFile, where: str, near: float) -> None:
    """Each body's cells on its own side of the scene's Γ: the signed
    distance (φ, positive on the + side, where the normal points:
    contactcore.geometry) at each cell's centroid (of its corners) at most
    ``slack`` on the wrong side.  ``slack`` is ``near`` and the farthest a
    Γ facet's midpoint lies off Γ (a chord's sagitta on a curved Γ, 0 on a
    line): a + cell on a chord of a circle may reach that far inside it.
    Every cell of both on the wrong side: the groups are swapped (newuser34:
    accepted, and fe answered with Γ opened and the materials exchanged)."""
    itf = scene.interface
    facets = mesh.group(NAMES[INTERFACE], 1)
    mid = mesh.nodes[facets[:, :2]].mean(axis=1)
    slack = near + float(np.abs(itf.signed_distance(mid)).max())
    wrong = {}
    for side, sign in (("minus", -1.0), ("plus", 1.0)):
        cells = mesh.group(NAMES[BODY[side]], 2)
        phi = itf.signed_distance(mesh.nodes[cells[:, :3]].mean(axis=1))
        wrong[side] = (int(np.sum(sign * phi < -slack)), len(cells))
    if all(n == total for n, total in wrong.values()):
        (m, _), (p, _) = wrong["minus"], wrong["plus"]
        raise _problem(where, f"all {m} cells of body_minus lie on Γ's + side and all {p} of body_plus on its − "
                              "side (the scene's normal points from − into +): are body_minus and body_plus swapped?")
    for side, (n, total) in wrong.items():
        if n:
            other = "+" if side == "minus" else "−"
            raise _problem(where, f"{n} of the {total} cells of {NAMES[BODY[side]]} lie on Γ's {other} side (the "
                                  "scene's normal points from − into +): each body's cells must lie on its own side "
                                  "of Γ")


def _check_sides(scene, mesh: MeshFile, where: str, near: float, unit: str) -> None:
    """A side of one cell only off the domain's boundary (a hole: cells
    missing, e.g. a surface in no physical group, which gmsh does not
    write unless Mesh.SaveAll is set), and a facet of a group fe reads that
    is no side of a cell (dolfinx's import fails on it without a word)."""
    sides, count = np.unique(_edges(mesh.cells), axis=0, return_counts=True)
    free = sides[count == 1]
    inside = free[(scene.domain.distance_to_boundary(mesh.nodes[free.ravel()]) > near).reshape(-1, 2).any(axis=1)]
    if len(inside):
        x, y = mesh.nodes[inside[0]].mean(axis=0)
        raise _problem(where, f"its cells leave a hole inside the domain: {len(inside)} sides of one cell only lie "
                              f"off the domain's boundary (one at ({x:.6g}, {y:.6g}) {unit}); are some cells in no "
                              "physical group (gmsh writes only grouped cells unless Mesh.SaveAll is 1)?")
    known = {tuple(e) for e in sides.tolist()}
    for (dim, name), facets in mesh.groups.items():
        if dim != 1 or name not in NAMES.values():
            continue
        loose = [f for f in np.sort(facets[:, :2], axis=1).tolist() if tuple(f) not in known]
        if loose:
            x, y = mesh.nodes[loose[0]].mean(axis=0)
            raise _problem(where, f"{len(loose)} facets of its group {name} are no side of a cell (one at "
                                  f"({x:.6g}, {y:.6g}) {unit}): are the cells beside them in no body group?")


def _check_interface(scene, mesh: MeshFile, where: str, near: float, unit: str) -> None:
    itf = scene.interface
    facets = mesh.group(NAMES[INTERFACE], 1)
    if not len(facets):
        raise _problem(where, "its interface group holds no facets: Γ must be a curve of the mesh")
    on_gamma = tol.USER_MESH_ON_GAMMA * scene.length_scale
    dist = np.abs(itf.signed_distance(mesh.nodes[facets.ravel()]))
    off = dist.reshape(len(facets), -1).max(axis=1) > on_gamma
    if off.any():
        k = int(np.argmax(dist))
        x, y = mesh.nodes[facets.ravel()[k]]
        raise _problem(where, f"{int(off.sum())} of Γ's {len(facets)} facets are off the scene's Γ (a node at "
                              f"({x:.6g}, {y:.6g}) {unit} lies {dist[k]:.3g} {unit} from it, more than "
                              f"{on_gamma:.3g}, {tol.USER_MESH_ON_GAMMA:g} of the scene's size): the interface group "
                              "must lie on the scene's interface to round-off (a node farther off moves a profile "
                              "sample there to the other body)")
    e_minus = {tuple(e) for e in _edges(mesh.group(NAMES[BODY["minus"]], 2)).tolist()}
    e_plus = {tuple(e) for e in _edges(mesh.group(NAMES[BODY["plus"]], 2)).tolist()}
    shared = e_minus & e_plus
    on_gamma = {tuple(sorted(f[:2])) for f in facets.tolist()}
    between = [f for f in on_gamma if f not in shared]
    if between:
        x, y = mesh.nodes[list(between[0])].mean(axis=0)
        raise _problem(where, f"{len(between)} of Γ's facets do not lie between a body_minus and a body_plus cell "
                              f"(one at ({x:.6g}, {y:.6g}) {unit}): the two bodies must share Γ's nodes, each "
                              "body on its own side")
    unmarked = shared - on_gamma
    if unmarked:
        x, y = mesh.nodes[list(next(iter(unmarked)))].mean(axis=0)
        raise _problem(where, f"{len(unmarked)} sides between a body_minus and a body_plus cell are not in the "
                              f"interface group (one at ({x:.6g}, {y:.6g}) {unit}): Γ must be every side the two "
                              "bodies share")
    params, span = _along_interface(scene, mesh.nodes[facets[:, :2]])
    gap = _uncovered(params, *span, near)
    if gap is not None:
        raise _problem(where, f"the interface group does not cover Γ end to end: {_stretch(scene, gap, unit)} of Γ "
                              "has no facet")


def _along_interface(scene, ends: np.ndarray) -> tuple[np.ndarray, tuple[float, float]]:
    """Γ's facets (m, 2 ends, 2) as intervals of Γ's parameter (arc length
    along a line's chord; the polar angle times R on a circle) and Γ's span."""
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        c = np.asarray(itf.centre, float)
        ang = np.arctan2(ends[..., 1] - c[1], ends[..., 0] - c[0]) % (2 * math.pi)
        wraps = np.abs(ang[:, 1] - ang[:, 0]) > math.pi  # the facet across angle 0
        lo = np.where(wraps, np.max(ang, axis=1) - 2 * math.pi, np.min(ang, axis=1))
        hi = np.where(wraps, np.min(ang, axis=1), np.max(ang, axis=1))
        iv = np.column_stack([lo, hi]) * itf.radius
        iv = np.concatenate([iv, iv + 2 * math.pi * itf.radius])  # covered from 0 to 2πR, wrapped once
        return iv, (0.0, 2 * math.pi * itf.radius)
    a, b = itf.chord(scene.domain)
    t = (b - a) / np.linalg.norm(b - a)
    return (ends - a) @ t, (0.0, float(np.linalg.norm(b - a)))


def _stretch(scene, gap: tuple[float, float], unit: str) -> str:
    itf = scene.interface
    if isinstance(itf, CircleInterface):
        lo, hi = (np.degrees(g / itf.radius) % 360 for g in gap)
        return f"the arc from {lo:.4g}° to {hi:.4g}°"
    a, b = itf.chord(scene.domain)
    t = (b - a) / np.linalg.norm(b - a)
    p, q = a + gap[0] * t, a + gap[1] * t
    return f"the stretch from ({p[0]:.6g}, {p[1]:.6g}) to ({q[0]:.6g}, {q[1]:.6g}) {unit}"


def _check_boundary(scene, mesh: MeshFile, where: str, boundary: str, user: str, near: float, unit: str) -> None:
    name = NAMES[BOUNDARY[boundary]]
    facets = mesh.group(name, 1)
    if facets is None or not len(facets):
        raise _problem(where, f"{user} acts on boundary '{boundary}', and the mesh has no facets in a physical "
                              f"group named {name}")
    dom = scene.domain
    on = dom.on_boundary(boundary, mesh.nodes[facets.ravel()], near)
    if not on.all():
        x, y = mesh.nodes[facets.ravel()[int(np.argmin(on))]]
        raise _problem(where, f"{name} holds a facet off the domain's {boundary} boundary (a node at ({x:.6g}, "
                              f"{y:.6g}) {unit}): {user} acts there")
    ends = mesh.nodes[facets[:, :2]]
    if isinstance(dom, Disc):
        c = np.asarray(dom.centre, float)
        ang = np.arctan2(ends[..., 1] - c[1], ends[..., 0] - c[0]) % (2 * math.pi)
        wraps = np.abs(ang[:, 1] - ang[:, 0]) > math.pi
        lo = np.where(wraps, np.max(ang, axis=1) - 2 * math.pi, np.min(ang, axis=1))
        hi = np.where(wraps, np.min(ang, axis=1), np.max(ang, axis=1))
        iv = np.column_stack([lo, hi]) * dom.radius
        params, span = np.concatenate([iv, iv + 2 * math.pi * dom.radius]), (0.0, 2 * math.pi * dom.radius)
    else:
        k = 1 if boundary in ("left", "right") else 0  # the coordinate along the edge
        params, span = ends[..., k] - dom.corner[k], (0.0, float(dom.size[k]))
    if _uncovered(params, *span, near) is not None:
        raise _problem(where, f"{name} does not cover the domain's {boundary} boundary end to end: {user} acts on "
                              "all of it")


def _order_warnings(scene, mesh: MeshFile, degree: int) -> list[str]:
    """Straight cells (geometry order 1) on a circular Γ: the polygon
    warning of fe's own mesh, at the length of the file's longest Γ facet;
    at degree 2 also that fe's own mesh would be curved there."""
    if mesh.order != 1 or not isinstance(scene.interface, CircleInterface):
        return []
    from .build import polygon_warnings
    facets = mesh.group(NAMES[INTERFACE], 1)
    on_gamma = float(np.linalg.norm(mesh.nodes[facets[:, 0]] - mesh.nodes[facets[:, 1]], axis=1).max())
    warnings = polygon_warnings(scene, on_gamma)
    if degree == 2:
        n = len(facets)
        short = 1 - math.sin(math.pi / n) / (math.pi / n)
        warnings.append(f"the mesh {mesh.name} has straight cells (geometry order 1) on the circular Γ at degree 2: "
                        f"Γ is a polygon of {n} facets, {short:.2%} shorter than Γ, so degree 2 converges no faster "
                        "than that polygon lets it; fe's own mesh at degree 2 is curved: write yours with geometry "
                        "order 2 (python -m meshes --order 2, or gmsh's Mesh.ElementOrder 2 / setOrder(2))")
    return warnings


def load_model(mesh: MeshFile, to_model) -> None:
    """Open ``mesh`` in the current gmsh session (inside
    :func:`meshes.build.gmsh_session`), every node moved by ``to_model``
    (points (m, 2) in the file's coordinates to the model's) and the
    physical groups fe reads renumbered to :mod:`meshes.tags` by name (the
    others dropped: dolfinx imports only what is in a group)."""
    from .build import gmsh
    gmsh.model.add("user_mesh")
    gmsh.open(mesh.path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xy = to_model(np.asarray(coords, float).reshape(-1, 3))
    for tag, (x, y) in zip(tags, xy):
        gmsh.model.mesh.setNode(int(tag), [float(x), float(y), 0.0], [])
    by_name = {name: tag for tag, name in NAMES.items()}
    groups = [(dim, gmsh.model.getPhysicalName(dim, tag), list(gmsh.model.getEntitiesForPhysicalGroup(dim, tag)))
              for dim, tag in gmsh.model.getPhysicalGroups()]
    gmsh.model.removePhysicalGroups()
    merged: dict = {}
    for dim, name, entities in groups:
        if name in by_name and dim == (2 if by_name[name] in BODY.values() else 1):
            merged.setdefault((dim, by_name[name]), []).extend(entities)
    for (dim, tag), entities in merged.items():
        gmsh.model.addPhysicalGroup(dim, sorted(set(entities)), tag)
        gmsh.model.setPhysicalName(dim, tag, NAMES[tag])
