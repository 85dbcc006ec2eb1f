"""Meshes of scene A (the unit square, Γ at y = 0.5) made with gmsh's API
as a user would: the physical groups named as meshes/tags.py names them,
numbered otherwise (from 101), and the faults a user's mesh may have."""
from pathlib import Path

from meshes import keeping_sigint

with keeping_sigint():
    import gmsh

#: Two floats on one line of the unit square's geometry within this are one.
SAME_LINE = 1e-9


def scene_a_mesh(path, h, factor=1.0, distance=0.2, untag_top=False, drop=(), shift_gamma=0.0, save_all=False,
                 untag=None):
    """Write scene A's mesh to ``path`` with gmsh's API: size ``h``, graded
    to ``h·factor`` on Γ over ``distance`` (factor < 1); faults: the groups
    named in ``drop`` left out, the + body above y = 0.75 in no group
    (``untag_top``; written with ``save_all``, else gmsh leaves its cells
    out), or its band between ``untag`` = (y0, y1) (a hole inside the
    domain), Γ's nodes moved by ``shift_gamma`` in y."""
    if untag_top:
        untag = (0.75, 1.0)
    with keeping_sigint():
        gmsh.initialize(["-noenv"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("user")
        occ = gmsh.model.occ
        box = occ.addRectangle(0, 0, 0, 1, 1)
        cuts = [(1, occ.addLine(occ.addPoint(0, 0.5, 0), occ.addPoint(1, 0.5, 0)))]
        for y in () if untag is None else [y for y in untag if y < 1.0]:
            cuts.append((1, occ.addLine(occ.addPoint(0, y, 0), occ.addPoint(1, y, 0))))
        occ.fragment([(2, box)], cuts)
        occ.synchronize()
        surfaces = {}
        for _, s in gmsh.model.getEntities(2):
            y = occ.getCenterOfMass(2, s)[1]
            name = "body_minus" if y < 0.5 else "top" if untag and untag[0] < y < untag[1] else "body_plus"
            surfaces.setdefault(name, []).append(s)
        curves = {}
        for _, c in gmsh.model.getEntities(1):
            x, y, _ = occ.getCenterOfMass(1, c)
            cut = untag is not None and min(abs(y - u) for u in untag) < SAME_LINE and SAME_LINE < y < 1 - SAME_LINE
            name = ("interface" if abs(y - 0.5) < SAME_LINE else "cut" if cut else
                    "boundary_left" if x < SAME_LINE else "boundary_right" if x > 1 - SAME_LINE else
                    "boundary_bottom" if y < SAME_LINE else "boundary_top")
            curves.setdefault(name, []).append(c)
        tag = 100
        for dim, groups in ((2, surfaces), (1, curves)):
            for name, ents in groups.items():
                if name in drop or name in ("top", "cut"):
                    continue
                tag += 1
                gmsh.model.addPhysicalGroup(dim, ents, tag)
                gmsh.model.setPhysicalName(dim, tag, name)
        gmsh.option.setNumber("Mesh.MeshSizeMax", h)
        gmsh.option.setNumber("Mesh.MeshSizeMin", h * factor)
        if factor < 1.0:
            f = gmsh.model.mesh.field
            d = f.add("Distance")
            f.setNumbers(d, "CurvesList", curves["interface"])
            t = f.add("Threshold")
            f.setNumber(t, "InField", d)
            f.setNumber(t, "SizeMin", h * factor)
            f.setNumber(t, "SizeMax", h)
            f.setNumber(t, "DistMin", 0.0)
            f.setNumber(t, "DistMax", distance)
            f.setAsBackgroundMesh(t)
            for opt in ("Mesh.MeshSizeExtendFromBoundary", "Mesh.MeshSizeFromPoints", "Mesh.MeshSizeFromCurvature"):
                gmsh.option.setNumber(opt, 0)
        gmsh.model.mesh.generate(2)
        if shift_gamma:
            tags, coords, _ = gmsh.model.mesh.getNodes(1, curves["interface"][0], includeBoundary=True)
            for t, (x, y, z) in zip(tags, coords.reshape(-1, 3)):
                gmsh.model.mesh.setNode(int(t), [x, y + shift_gamma, z], [])
        gmsh.option.setNumber("Mesh.SaveAll", int(save_all))
        gmsh.write(str(path))
    finally:
        with keeping_sigint():
            gmsh.finalize()
    return path


def swap_bodies(src, dst):
    """Copy the gmsh file ``src`` (ASCII, as ``python -m meshes`` writes it)
    to ``dst`` with the names body_minus and body_plus exchanged in its
    $PhysicalNames (newuser34's a_swapped.msh); returns ``dst``."""
    head, rest = Path(src).read_text().split("$PhysicalNames", 1)
    names, tail = rest.split("$EndPhysicalNames", 1)
    names = names.replace('"body_minus"', '"@"').replace('"body_plus"', '"body_minus"').replace('"@"', '"body_plus"')
    Path(dst).write_text(head + "$PhysicalNames" + names + "$EndPhysicalNames" + tail)
    return dst
