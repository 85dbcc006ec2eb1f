"""Methods against a reference on one scene: the :class:`AgreementTable`
(its worst row, what it left out, its Markdown as ``run`` writes it into
summary.md) and :func:`table`, which builds it from sampled profiles."""
from __future__ import annotations

from dataclasses import dataclass

from contactcore import ContactError, Scene
from contactcore.estimate.singular import singular_regions
from contactcore.labels import reference_text
from contactcore.scene import Units
from contactcore.tolerances import EXACT_GAP_FLOOR, NEGLIGIBLE_SHARE, STATUS_ALLOWANCE_CELLS, STATUS_TOLERATED_SHARE

from .measures import first_largest, percent
from .records import Agreement, profile_agreements
from .samples import check_exclusion, default_exclusion
from .sizes import measured_floor, user_floors
from .status import StatusAgreement, status_agreements


@dataclass(frozen=True)
class AgreementTable:
    """Methods against a reference on one scene: one :class:`Agreement` per
    method, profile and quantity; samples within ``exclude`` of the named
    singular ``regions`` left out.  ``statuses``: one
    :class:`~verification.agreement.status.StatusAgreement` per method and Γ
    profile, Γ's status map against the reference's over all of Γ (none
    where the law is linear or the runs' maps were not given)."""

    scene: str
    reference: str
    exclude: float
    regions: tuple[tuple[str, tuple[tuple[float, float], ...]], ...]
    rows: tuple[Agreement, ...]
    gap_floor: float = 0.0  # an exact law's gaps' floor (measured_against), in length; 0 for a penalty law
    floors: tuple[tuple[str, float], ...] = ()  # the floors given (quantity, value in its unit): table's floors
    units: Units = Units()  # the names of the scene's units, which the floors are in
    statuses: tuple[StatusAgreement, ...] = ()  # Γ's status maps against the reference's (status.py)

    def status_failures(self, tolerated: float | None = None) -> list[StatusAgreement]:
        """The :attr:`statuses` whose share of Γ differing beyond the
        allowance exceeds ``tolerated`` (default :data:`STATUS_TOLERATED_SHARE`),
        the largest first."""
        limit = STATUS_TOLERATED_SHARE if tolerated is None else tolerated
        return sorted((a for a in self.statuses if a.share > limit), key=lambda a: -a.share)

    def worst(self, measure: str = "worst") -> Agreement:
        """The row with the largest ``measure`` (``"worst"`` or ``"rms"``;
        the first of those within :data:`WORST_TIE`)."""
        return first_largest(self.rows, key=lambda a: getattr(a, measure))

    def sizes(self, profile: str) -> dict[str, tuple[float, str]]:
        """Quantity -> ``(size, against)`` of ``profile``: what its worst
        samples are shares of (:class:`Agreement`'s ``size``, the
        reference's largest scale over the kept samples, the same for every
        method) and what that scale is the size of (``against``:
        ``|(tN, tT)|``; "" the quantity itself).  The plots' Δ panels divide
        by it, so a plot and this table say one figure."""
        return {a.quantity: (a.size, a.against) for a in self.rows if a.profile == profile}

    def excluded(self) -> str:
        """Which samples were left out, in words."""
        if not self.regions:
            return "no sample was left out (the scene has no singular point)"
        where = "; ".join(f"{name} " + ", ".join(f"({x:.4g}, {y:.4g})" for x, y in pts)
                          for name, pts in self.regions)
        return (f"samples within {self.exclude:.3g} {self.units.length} of these singular points were left out: "
                f"{where}")

    def _below_gap_floor(self, quantity: str, value: float) -> bool:
        """Whether a floor given for ``quantity`` is one of the gaps' and no
        larger than the exactly enforced law's own (:func:`floors` keeps the larger)."""
        return bool(self.gap_floor) and quantity in ("gN", "gT") and value <= self.gap_floor

    def markdown(self) -> str:
        """The table in Markdown, worst sample and RMS in % of the reference's scale."""
        from ..files import column_unit
        floor = (f" Γ's gaps (an exactly enforced law: zero where Γ is closed and sticking, up to Nitsche's residue, which β and h set) are measured "
                 f"against sqrt(g² + ({self.gap_floor:.3g} {self.units.length})²), {EXACT_GAP_FLOOR:g} of the "
                 "displacement scale." if self.gap_floor else "")
        floor += "".join(f" {q}'s floor given ({v:.3g} {column_unit(q, self.units)}) lies below the law's own "
                         "and is not used." if self._below_gap_floor(q, v) else
                         f" {q} is measured against sqrt({q}² + ({v:.3g} {column_unit(q, self.units)})²) "
                         "(a floor given)." for q, v in self.floors)
        floor += (" Each quantity is measured against the size of its vector or tensor in the reference (t_N and "
                  "t_T against |t|, a stress against the stresses its profile samples), at least "
                  f"{NEGLIGIBLE_SHARE:g} of the scene's own scale (round-off): the worst sample is the largest "
                  "|difference| over the largest size on the profile (not over the size at that sample), the RMS "
                  "the RMS difference over the RMS size. A quantity's class names what it is: `zero` (exactly zero in "
                  "a paper scene: scene B's g_N and t_N on B6), `interface` (Γ's "
                  "gaps and tractions under a linear law), `contact` (g_N, g_T, t_N of a law that opens: kinks where "
                  "Γ opens), `contact edge` (t_T of such a law, which jumps where Γ closes), `edge` (a stress on "
                  "the outer boundary), `interior` (any other); `at s (x, y)` is the worst sample's parameter "
                  f"along its profile, the arc length in {self.units.length} (on a circular Γ the polar angle in "
                  "rad, unless the profile asks for the arc length), and its point.")
        if self.statuses:
            floor += (" A `status` row compares Γ's status map (stick/slip/open, at each sample the status its "
                      "tractions follow) with the reference's over all of Γ, no sample left out (a status has no "
                      "singularity): its worst is the share of Γ's length whose status differs farther than "
                      f"{STATUS_ALLOWANCE_CELLS:g} cell (the coarser run's h) from a status change of either run, "
                      "at the largest such stretch (its s range, its middle point, the method's status against "
                      "the reference's); its RMS column the share that differs at all.")
        lines = [f"Each run against the {reference_text(self.reference)}; {self.excluded()}.{floor}", "",
                 "| method | profile | quantity | class | worst sample | at s (x, y) | RMS |",
                 "|---|---|---|---|---|---|---|"]
        lines += [f"| {a.method} | {a.profile} | {a.quantity} | {a.kind} | {percent(a.worst)} | {a.s:.4g} "
                  f"({a.x:.4g}, {a.y:.4g}) | {percent(a.rms)} |" for a in self.rows]
        lines += [f"| {a.method} | {a.profile} | status | status | {percent(a.share)} of Γ | "
                  + (f"{a.start:.4g} to {a.end:.4g} ({a.x:.4g}, {a.y:.4g}): {a.status} against {a.reference}"
                     if a.share > 0 else "—") + f" | {percent(a.differs)} differ |" for a in self.statuses]
        return "\n".join(lines) + "\n"


def table(scene: Scene, runs: dict[str, dict], reference: str, exclude: float | None = None,
          floors: dict | None = None, statuses: dict | None = None) -> AgreementTable:
    """The :class:`AgreementTable` of sampled profiles ``runs`` (label ->
    id -> ProfileData), ``runs[reference]`` the reference.  ``floors``
    (quantity -> value in its unit) measures a quantity against
    ``sqrt(q_ref² + floor²)``: the size below which a difference does not
    count, for a quantity that is zero in the reference (a patch test's
    σxy), where its own round-off would be its scale.  ``reference`` is a
    label among ``runs``' keys; anything else is refused with a
    :class:`ContactError` naming the labels.  ``statuses`` (label ->
    :class:`~verification.agreement.status.StatusMap`, or None for a run
    without one: :func:`~verification.agreement.status.status_map`) adds
    each method's status map against the reference's (the table's
    ``statuses``), where both are given."""
    if not isinstance(runs, dict):
        raise ContactError(f"runs: a dict of label -> {{profile id: ProfileData}} (got {type(runs).__name__})")
    labels = ", ".join(map(repr, runs))
    if not isinstance(reference, str):
        raise ContactError(f"reference: the label of one of runs ({labels}), not its profiles (got a "
                           f"{type(reference).__name__})")
    if reference not in runs:
        raise ContactError(f"reference: {reference!r} is not a label of runs (they are {labels})")
    exclude = default_exclusion(scene) if exclude is None else exclude
    check_exclusion(scene, exclude)
    ref, given = runs[reference], user_floors(floors)
    rows = [row for label, got in runs.items() if label != reference
            for row in profile_agreements(scene, label, got, ref, exclude, floors=given)]
    maps = statuses or {}
    compared = [row for label in runs if label != reference and maps.get(label) and maps.get(reference)
                for row in status_agreements(scene, label, maps[label], maps[reference], ref)]
    regions = tuple((name, tuple(map(tuple, pts.tolist()))) for name, pts in singular_regions(scene))
    return AgreementTable(scene.name, reference, exclude, regions, tuple(rows), measured_floor(scene, "gN"),
                          tuple(given.items()), scene.units, tuple(compared))
