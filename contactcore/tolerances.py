"""Every tolerance and threshold of the project, named, scaled and justified.

Keep them here: a method that needs a new one adds it here with its reason.
Lengths are relative to the scene's characteristic length ``L`` (the domain's
diameter) unless said otherwise.
"""

#: A point is on the interface Γ when ``|φ(x)| <= ON_INTERFACE * L``.  Profile
#: points on Γ are generated in floating point from exact formulas (a circle
#: point has |φ| ~ 1e-16 L), so 1e-10 L catches them and nothing else: the
#: closest non-Γ profile point is ~1e-9 L away (the end-point shift below).
ON_INTERFACE = 1e-10

#: Profile end points are moved inside the domain by this fraction of the
#: segment length (SCENES.md) so that every sample point lies in a cell.
PROFILE_END_SHIFT = 1e-9

#: Number of samples of a profile (SCENES.md).
PROFILE_POINTS = 101

#: Geometric tolerance of the scene validation (points inside the domain, an
#: interface that "only touches" the domain), relative to L.  Larger than
#: round-off of the inputs (1e-15) but far below any mesh size in use (1e-3 L).
GEOMETRY = 1e-9

#: A mesh node (or a point gmsh computes on a curve) matches a point of the
#: scene within this distance, relative to L.  gmsh places embedded points and
#: boundary curves to ~1e-15 L; the finest mesh in use has h ~ 1e-3 L, so
#: 1e-6 L cannot match a neighbouring node.
NODE_MATCH = 1e-6

#: The smaller of the two bodies must cover at least this fraction of the
#: domain's area, otherwise the interface "only touches" the domain.
MIN_BODY_AREA_FRACTION = 1e-8

#: Normwise backward error ||b - A x|| / (||A|| ||x|| + ||b||) (infinity
#: norms) above which a direct solve is reported as failed.  A backward-stable
#: LU gives O(eps) = 1e-16 whatever the penalty; measured on scene A with
#: springs up to 1e13 E/h: at most 1e-15.  1e-10 leaves room for that and
#: catches a factorisation gone wrong (O(1)).  The plain relative residual
#: ||r||/||b|| is reported too, but it grows with ||A|| ~ k for a perfectly
#: good solve, so it cannot be the criterion.
BACKWARD_ERROR_FAIL = 1e-10

#: MUMPS condition estimate (its error analysis, RINFOG(10)) above which the
#: answer is flagged as not to be trusted: with eps = 2.2e-16 the forward error
#: bound cond * eps reaches 1e-4 at 5e11, i.e. four digits may be lost.
CONDITION_WARN = 5e11

#: Above this many unknowns the condition estimate is skipped by default: the
#: MUMPS error analysis costs a few extra solves and dominates small runs
#: only; large runs are timed, so they should not pay for it.
CONDITION_ESTIMATE_MAX_DOFS = 200_000

#: Pivot threshold of MUMPS's null-pivot detection (CNTL(3)), relative to the
#: matrix norm: a pivot below it marks the matrix as singular (a rigid-body
#: mode that the supports do not remove).  Penalty springs up to 1e8 E/h keep
#: every genuine pivot far above 1e-14 ||A||.
NULL_PIVOT = 1e-14
