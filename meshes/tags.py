"""Physical tags of every fitted mesh, by name.

Cells carry the body tag; facets carry the interface tag or the tag of the
named outer boundary they lie on.
"""

#: Cells of the − and + bodies.
BODY = {"minus": 1, "plus": 2}

#: Cells of a mesh of the outer domain that ignores Γ (XFEM's background).
OUTER = 3

#: Facets on Γ.
INTERFACE = 10

#: Facets on each named outer boundary (rectangle edges, or a disc's circle).
BOUNDARY = {"left": 21, "right": 22, "bottom": 23, "top": 24, "outer": 25}

#: The name gmsh files carry for each tag.
NAMES = {**{tag: f"body_{b}" for b, tag in BODY.items()}, OUTER: "outer_domain", INTERFACE: "interface",
         **{tag: f"boundary_{b}" for b, tag in BOUNDARY.items()}}
