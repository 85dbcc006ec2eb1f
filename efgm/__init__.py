"""Element-free Galerkin method with Heaviside-enriched interfaces (numpy, scipy).

``efgm.method`` exposes ``METHOD`` and ``solve(scene, h=None, *, degree=1,
paper=False, ...) -> contactcore.Result``.
"""
