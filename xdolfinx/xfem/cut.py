"""XFEM's cut integration (GetFEM's ``MeshIm('levelset', …)``): each cell
that Γ cuts is split along the exact Γ into the parts of either body
(:mod:`contactcore.cutcell`), and Γ itself gets a rule with the level set's
own normal (chord normals would create a false normal traction of
(k_N/k_T)(h/2R)|t_T| on a circle).  Also how deep each part reaches from Γ,
and the checks that the rules found all of Γ."""
from __future__ import annotations

import basix
import numpy as np

from contactcore import DiscretisationError, Scene
from contactcore import tolerances as tol
from contactcore.bodies import Body, index_of_sign, sign_of
from contactcore.cutcell import cut_polygon, gauss01, interface_rule_in, polygon_rule
from contactcore.geometry import LevelSetInterface, polygon_area
from contactcore.scaling import user_points

from .cells import CellBasis, on_gamma

#: Gauss points per direction in each (sub-)cell and on each piece of Γ, by
#: degree: a fan maps a square onto a triangle or curved sector, so n points
#: integrate the polynomial part of degree 2n − 2 (stiffness of P_k: 2k − 2
#: in 2D, plus the curved-map factor); n = k + 2 leaves a margin.
GAUSS_POINTS = {1: 3, 2: 4}

#: Cells whose centre lies within NEAR_FACTOR·|∇φ|·(circumradius) of Γ are
#: examined for cuts: the φ of a line or a circle is the signed distance, so
#: a cell farther than its circumradius cannot meet Γ (1, plus the round-off
#: allowance contactcore.tolerances.NEAR_ROUNDOFF); 2 leaves room for the
#: curvature of a general φ.
NEAR_FACTOR = {"distance": 1.0 + tol.NEAR_ROUNDOFF, "level set": 2.0}

#: Points per direction at which φ is sampled in a cell near a general
#: level set that its corners and edges leave on one side, to find a piece
#: of Γ inside it (:meth:`CutIntegration._check_no_hidden_piece`).
HIDDEN_PIECE_SAMPLES = 16


class CutIntegration:
    """The quadrature of every cell given Γ: ``regions[c]`` the parts
    ``[(side, points, weights, N, dN)]`` of a cell Γ cuts (N, dN the basis
    at the points), ``gamma_rules[c]`` Γ's ``(points, weights, normals)``
    in a cell it crosses, ``cell_side`` the side (±1) of every other cell,
    ``depth[c]`` how far the − and + parts of a cut cell reach from Γ and
    ``cell_size`` each cell's diameter.

    Γ is snapped to the nodes within their snap distance of it
    (``cells.node_snap``, :data:`contactcore.tolerances.XFEM_SNAP` of the
    largest cell at the node): a cell whose corners off Γ all lie on one
    side is whole on that side, and Γ along an edge whose two ends are on
    Γ, between a whole − cell and a whole + cell (or a cell another branch
    of Γ cuts), is that edge, its rule held by the − cell alone
    (:func:`_edge_rules`); a cell with corners off
    Γ on both sides is cut along the exact Γ.  So no part of a cell is
    thinner than XFEM_SNAP of the cell.

    Each node's stiffness ``∫|∇N_J|²`` over the parts on either side of Γ,
    in the cells near Γ that this rank owns, is summed as
    ``stiffness[index of the side]``: what the enriched space decides its
    enrichment from."""

    def __init__(self, cells: CellBasis, scene: Scene, gauss: int):
        self.cells, self.scene, self.gauss = cells, scene, gauss
        self.reference_rule = polygon_rule(_reference_cell(cells), gauss)
        self.reference_values = cells.element.tabulate(0, self.reference_rule[0])[0, :, :, 0]
        itf, corners = scene.interface, cells.corners
        centre = corners.mean(axis=1)
        radius = np.max(np.linalg.norm(corners - centre[:, None], axis=2), axis=1)
        self.cell_size = 2 * radius
        phi_c = itf.phi(centre)
        self.cell_side = sign_of(phi_c)
        self.regions, self.gamma_rules = {}, {}
        self.depth = np.zeros((len(centre), 2))  # of each body's part of a cut cell (distance from Γ, φ/|∇φ|)
        self.stiffness = np.zeros((2, len(cells.node_side)))  # of each node's function on the − and + parts
        corner_phi = itf.phi(corners.reshape(-1, 2)).reshape(len(centre), -1)
        snapped = [c for c in self._near_cells(centre, radius, phi_c, corner_phi) if self._integrate(c, corner_phi[c])]
        _edge_rules(self, snapped)

    def _near_cells(self, centre, radius, phi_c, corner_phi) -> np.ndarray:
        """The cells Γ may reach: whose centre is within |∇φ|·radius of it
        (φ/|∇φ| is the distance to first order; exactly so for lines and
        circles), or whose corners differ in sign, or differ from the
        centre's (a general φ may have |∇φ| = 0 there: a small disc's centre)."""
        itf = self.scene.interface
        general = isinstance(itf, LevelSetInterface)
        grad = np.linalg.norm(itf.grad_fn(centre), axis=1) if general else 1.0
        factor = NEAR_FACTOR["level set" if general else "distance"]
        corner_sides = sign_of(corner_phi)
        return np.flatnonzero((np.abs(phi_c) <= factor * grad * radius)
                              | (corner_sides.min(axis=1) != corner_sides.max(axis=1))
                              | (corner_sides[:, 0] != self.cell_side))

    def _integrate(self, c: int, corner_phi: np.ndarray) -> bool:
        """Rules of cell ``c`` near Γ: its regions if Γ cuts it, else its
        side (Γ snapped to its corners within their snap distance); its
        nodes' stiffness on either side if this rank owns it.  Whether the
        cell is whole on the − side with Γ snapped to two of its corners
        (an edge of it may then carry Γ's rule: :func:`_edge_rules`)."""
        itf, cells = self.scene.interface, self.cells
        general = isinstance(itf, LevelSetInterface)
        corners = cells.corners[c]
        on = cells.node_on[cells.corner_nodes[c]]
        off = sign_of(corner_phi)[~on]
        gamma, pieces = interface_rule_in(itf, corners, self.gauss), cut_polygon(itf, corners, self.gauss)
        snapped = False
        if on.any() and len(off) and off.min() == off.max() and self._within_snap(c, pieces, int(off[0])):
            # Γ snapped to the corners on it: the cell is whole on the side of the others
            side = int(off[0])
            gamma, snapped = _NO_RULE, side < 0 and int(np.count_nonzero(on)) > 1
            pieces = [(side, *polygon_rule(corners, self.gauss))]
        if general:
            self._check_rules_found(c, [*gamma, *(a for _, p, w in pieces for a in (p, w))])
        if len(gamma[1]):
            self.gamma_rules[c] = gamma
        parts = [(s, p, w, *cells.tabulate(c, p)) for s, p, w in pieces if np.sum(w) > 0]
        if len({part[0] for part in parts}) > 1:
            self.regions[c] = parts
            self.depth[c] = self._depths(parts, corners, corner_phi)
        elif parts:
            self.cell_side[c] = parts[0][0]
            if general:
                self._check_no_hidden_piece(c, parts[0][0])
        if c < cells.owned_cells:  # a ghost cell: its owner counts it
            dofs = cells.cell_dofs[c]
            for side, pts, w, N, dN in parts:
                self.stiffness[index_of_sign(side), dofs] += w @ np.sum(dN ** 2, axis=-1)
        return snapped

    def snap_of(self, c: int) -> float:
        """The distance within which Γ is snapped in cell ``c``: XFEM_SNAP
        of its own diameter, or its corners' on Γ snap distance if larger
        (:attr:`CellBasis.node_snap`, the largest cell at that node's)."""
        cells = self.cells
        nodes = cells.corner_nodes[c]
        return max(float(cells.cell_snap[c]), float(np.max(cells.node_snap[nodes][cells.node_on[nodes]], initial=0.0)))

    def _within_snap(self, c: int, pieces, side: int) -> bool:
        """Whether every part of cell ``c`` off ``side`` lies within the
        snap distance of Γ (its quadrature points do): a sliver beside a
        corner on Γ, which snapping removes; a circle's cap deeper than
        that, cut off an edge away from the corner, stays a part."""
        snap, itf = self.snap_of(c), self.scene.interface
        return all(np.all(np.abs(itf.signed_distance(p)) <= snap) for s, p, w in pieces if s != side and len(w))

    def _check_rules_found(self, c: int, arrays) -> None:
        """A clear error where cell ``c``'s rules of Γ and of its parts hold
        non-finite values: a general φ whose projection onto φ = 0 divides
        by ∇φ·m = 0 (a kink, a flat φ) would reach the solver as NaN."""
        if all(np.all(np.isfinite(a)) for a in arrays):
            return
        centre = self.cells.corners[c].mean(axis=0)
        raise DiscretisationError(f"xfem: Γ could not be followed through the cell at ({centre[0]:.6g}, "
                                  f"{centre[1]:.6g}): projecting onto φ = 0 met ∇φ perpendicular to the way "
                                  "(a kink or a flat part of the level set); give a smooth φ, or refine h")

    def _check_no_hidden_piece(self, c: int, side: int) -> None:
        """A clear error where a general level set changes sign inside cell
        ``c`` whose corners and edges it leaves on ``side`` (a closed piece
        of Γ, or a fold, smaller than the cell): the cut-cell quadrature,
        which finds Γ through the cell's edges, would leave it out and read
        its inside as the body around it.  φ is sampled on
        HIDDEN_PIECE_SAMPLES² points of the cell: a piece smaller than
        that spacing can still go unseen."""
        t = (np.arange(HIDDEN_PIECE_SAMPLES) + 0.5) / HIDDEN_PIECE_SAMPLES
        u, v = (g.reshape(-1, 1) for g in np.meshgrid(t, t))
        corners = self.cells.corners[c]  # counter-clockwise: a bilinear map of the unit square (a triangle repeats one)
        q = corners if len(corners) == 4 else np.vstack([corners, corners[-1:]])
        x = (1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3]
        itf = self.scene.interface
        other = (sign_of(itf.phi(x)) != side) & ~on_gamma(self.scene, x, self.snap_of(c))
        if other.any():
            p = user_points(self.scene, x[np.flatnonzero(other)[0]])  # named in the user's terms
            raise DiscretisationError(f"xfem: the level set changes sign inside a cell without crossing its edges, "
                                      f"near ({p[0]:.6g}, {p[1]:.6g}): a piece of Γ smaller than a cell, which the "
                                      "cut-cell quadrature would leave out; refine h")

    def _depths(self, parts, corners: np.ndarray, corner_phi: np.ndarray) -> np.ndarray:
        """(2,): how far the − and + parts of a cut cell reach from Γ,
        ``max s·φ/|∇φ|`` over the part's corners and quadrature points (the
        corners give it exactly for a straight Γ, the points for a cap of a
        curve that enters the cell through one edge)."""
        itf = self.scene.interface
        out = np.zeros(2)
        for side, pts, *_ in parts:
            x = np.vstack([pts, corners[sign_of(corner_phi) == side]])
            out[index_of_sign(side)] = max(out[index_of_sign(side)], float(np.max(side * itf.signed_distance(x))))
        return out

    def cell_values(self, cell: int):
        """[(side, points, weights, N)] of a cell, N the basis values (P, n)
        at the points: its regions if cut, else the whole cell on its side
        (the reference rule, mapped affinely)."""
        if cell in self.regions:
            return [part[:4] for part in self.regions[cell]]
        X, w = self.reference_rule
        cells = self.cells
        points = cells.origin[cell] + X @ cells.jacobian[cell].T
        return [(self.cell_side[cell], points, w * abs(np.linalg.det(cells.jacobian[cell])), self.reference_values)]

    def cut_share(self, body: Body) -> float:
        """The share of ``body``'s area that lies in cut cells, over every
        rank: 1 for a body no cell of the mesh lies wholly inside."""
        owned, ranks = self.cells.owned_cells, self.cells.ranks
        area = polygon_area(self.cells.corners[:owned])
        cut = np.zeros(owned, bool)
        cut[[c for c in self.regions if c < owned]] = True
        whole = float(np.sum(area[~cut & (self.cell_side[:owned] == body.sign)]))
        in_cut = float(sum(np.sum(w) for c, parts in self.regions.items() if c < owned
                           for s, _, w, *_ in parts if s == body.sign))
        in_cut, whole = ranks.sum(in_cut), ranks.sum(whole)
        return in_cut / (in_cut + whole) if in_cut + whole > 0 else 0.0

    def thin_body_warnings(self) -> list[str]:
        """A warning for each body more than tol.THIN_BODY_CUT_SHARE of
        whose area lies in cut cells (:meth:`cut_share`): a body thinner
        than about two cells, resolved across its thickness by one cell's
        polynomial."""
        return [f"{share:.0%} of body {body.label}'s area lies in cells that Γ cuts: the body is about two cells "
                "across or less, its field there one cell's polynomial, and its tractions on Γ converge slowly (a "
                "thin wedge with 79 % in cut cells had its mean t_N 23 % below fe's); refine h until the share falls "
                f"below {tol.THIN_BODY_CUT_SHARE:.0%}, or use fe"
                for body in Body for share in [self.cut_share(body)] if share > tol.THIN_BODY_CUT_SHARE]


def _edge_rules(cut: CutIntegration, snapped: list[int]) -> None:
    """Γ's rule along each edge that Γ was snapped to: an edge of a
    ``snapped`` cell of ``cut`` (whole on the − side) whose two ends are on Γ and
    whose cell across is whole on the + side, or cut by another branch of
    Γ (:func:`_beside_another_branch`).  Γ is then that edge:
    Gauss points on it with the level set's normals there, held by the
    − cell alone, so no edge is counted twice (two − cells beside it
    would each have held it) and the edge carries Γ exactly where the
    two bodies' cells meet.  Where the cell across is cut (a curved Γ
    through the edge's two ends that bows off it by more than the snap,
    by about h²/8R), that cell holds Γ's rule along the arc, and the
    edge none (counted twice, a circle's Γ was 15 % too long).  Under
    mpirun the cell across an owned cell's edge is a ghost on its rank
    (dolfinx's shared-facet ghosts, the default of ``create_rectangle`` and
    ``create_mesh``); an owned edge inside the domain without one is refused."""
    if not snapped:
        return
    cells = cut.cells
    nodes = cells.corner_nodes
    k = nodes.shape[1]
    ends = np.stack([nodes, np.roll(nodes, -1, axis=1)], axis=-1)         # (cells, k, 2): edge i, corner i to i + 1
    keys = (np.min(ends, axis=-1).astype(np.int64) * len(cells.node_on) + np.max(ends, axis=-1)).ravel()
    order = np.argsort(keys, kind="stable")
    sorted_keys = keys[order]
    whole_plus = cut.cell_side > 0
    whole_plus[list(cut.regions)] = False
    g, gw = gauss01(cut.gauss)
    for c in snapped:
        on = cells.node_on[nodes[c]]
        rules = []
        for i in np.flatnonzero(on & np.roll(on, -1)):
            lo, hi = np.searchsorted(sorted_keys, keys[c * k + i], side="left"), \
                np.searchsorted(sorted_keys, keys[c * k + i], side="right")
            across = [int(j) // k for j in order[lo:hi] if int(j) // k != c]
            a, b = cells.corners[c, i], cells.corners[c, (i + 1) % k]
            if not across and c < cells.owned_cells and not _on_domain_boundary(cut.scene, np.array([a, b])):
                raise DiscretisationError("xfem: the cell across an edge on Γ is missing on this rank; the mesh "
                                          "must ghost the cells that share a facet (dolfinx's shared_facet)")
            pts = a + g[:, None] * (b - a)
            if len(across) == 1 and (whole_plus[across[0]] or _beside_another_branch(cut, across[0], a, b, pts)):
                rules.append((pts, gw * float(np.linalg.norm(b - a))))
        if rules:
            pts = np.vstack([p for p, _ in rules])
            rule = (pts, np.concatenate([w for _, w in rules]), cut.scene.interface.normals(pts))
            if isinstance(cut.scene.interface, LevelSetInterface):
                cut._check_rules_found(c, rule)
            cut.gamma_rules[c] = rule


def _beside_another_branch(cut: CutIntegration, d: int, a: np.ndarray, b: np.ndarray, pts: np.ndarray) -> bool:
    """Whether the edge from ``a`` to ``b`` (Gauss points ``pts``) of a snapped − cell is
    Γ's only rule there though cell ``d`` across it is cut: ``d`` is cut by
    another branch of Γ (a level set with two, φ = (x − 1.2)(1.25 − x)), Γ
    runs along the edge (every Gauss point within ``d``'s snap) and ``d``'s
    own rule has no point on the edge.  Without it that stretch of Γ was
    integrated nowhere (half of Γ's length; a review, 2026-11-27).  A
    curved Γ through the edge's ends bows off it by more than the snap,
    so its arc in ``d`` stays the only rule there."""
    snap = cut.snap_of(d)
    if d not in cut.regions or not on_gamma(cut.scene, pts, snap).all():
        return False
    rule = cut.gamma_rules.get(d)
    if rule is None or not len(rule[1]):
        return True
    length = float(np.linalg.norm(b - a))
    t = (b - a) / length
    rel = rule[0] - a
    along, off = rel @ t, np.abs(rel @ np.array([-t[1], t[0]]))
    return not np.any((off <= snap) & (along >= -snap) & (along <= length + snap))


def _on_domain_boundary(scene: Scene, ends: np.ndarray) -> bool:
    """Whether both ``ends`` (2, 2) of an edge lie on the scene's outer
    boundary (to NODE_MATCH of its length; a disc's rim chord has its ends
    on the rim)."""
    return bool(np.all(np.abs(scene.domain.distance_to_boundary(ends)) <= tol.NODE_MATCH * scene.length_scale))


#: Γ's rule in a cell it does not cross: no points.
_NO_RULE = (np.zeros((0, 2)), np.zeros(0), np.zeros((0, 2)))


def _reference_cell(cells: CellBasis) -> np.ndarray:
    """The reference cell's vertices counter-clockwise (basix orders a
    quadrilateral's as 0, 1, 3, 2)."""
    X = basix.geometry(cells.element.cell_type)
    return X[[0, 1, 3, 2]] if len(X) == 4 else X
