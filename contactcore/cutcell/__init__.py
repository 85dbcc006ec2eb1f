"""Integration on cells cut by Γ, on Γ, and on the outer boundary (exact geometry).

Shared by the methods that integrate on cells that ignore Γ (EFGM's
background cells, XFEM's mesh cells).  numpy only.

Every region is integrated as a set of *fans*: from a vertex ``V`` over a
boundary curve ``C(τ)``, ``τ ∈ [0, 1]``, the map ``P(s, τ) = V + s (C(τ) − V)``
covers the region between them, with ``det J = s (C − V) × C′``.  A straight
side gives a triangle (Duffy's collapsed square); an arc of the circle gives
the curved sector between ``V`` and the arc, exactly.  Gauss–Legendre rules
of ``n`` points in ``s`` and ``τ`` (numpy's, the same as basix's interval
rules — a test checks it).  A cell that Γ cuts into more than two pieces,
or whose pieces are not star-shaped from a corner, is split in four (up to
:data:`MAX_DEPTH` times) — this only happens when Γ bends sharply inside one
cell.  Cells are convex polygons given counter-clockwise: rectangles and
triangles.

One idea a module:

- :mod:`~contactcore.cutcell.gauss`: Gauss–Legendre rules on [0, 1] and
  rectangles (:func:`gauss01`, :func:`tensor_cells`) and :class:`Rule`;
- :mod:`~contactcore.cutcell.crossings`: where Γ crosses a cell's edge
  (:func:`edge_crossings`);
- :mod:`~contactcore.cutcell.curves`: Γ between two of its points, and a
  straight side, as a curve;
- :mod:`~contactcore.cutcell.fans`: a region fanned from a vertex;
- :mod:`~contactcore.cutcell.polygons`: an uncut polygon's rule
  (:func:`polygon_rule`), the rectangle test, the split in four
  (:data:`MAX_DEPTH`);
- :mod:`~contactcore.cutcell.regions`: the two regions of a polygon Γ
  crosses twice;
- :mod:`~contactcore.cutcell.touch`: whether Γ cuts a polygon or only
  touches it;
- :mod:`~contactcore.cutcell.polygon_cut`: a polygon's rule on each side
  of Γ (:func:`cut_polygon`, :func:`cut_cell`);
- :mod:`~contactcore.cutcell.lines`: Γ's rule inside a polygon
  (:func:`interface_rule_in`) and a curve's (:func:`curve_rule`);
- :mod:`~contactcore.cutcell.batch`: many squares cut at once
  (:func:`cut_squares`), bit for bit as :func:`cut_cell`.

Their public names are imported here, as ``contactcore.cutcell.NAME``.
"""
from .gauss import Rule, gauss01, tensor_cells
from .crossings import BISECTIONS, EDGE_SAMPLES, edge_crossings
from .curves import PROJECTIONS
from .polygons import MAX_DEPTH, polygon_rule
from .touch import SLIVER_GAUSS
from .polygon_cut import cut_cell, cut_polygon
from .lines import curve_rule, interface_rule_in
from .batch import cut_squares

__all__ = [
    "Rule", "gauss01", "tensor_cells", "BISECTIONS", "EDGE_SAMPLES", "edge_crossings", "PROJECTIONS", "MAX_DEPTH",
    "polygon_rule", "SLIVER_GAUSS", "cut_cell", "cut_polygon", "curve_rule", "interface_rule_in", "cut_squares",
]
