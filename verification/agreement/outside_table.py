"""The verdict on an outside answer as a table (docs/api.md, "An outside
code's answer"): :class:`OutsideTable`, one :class:`OutsideRow` per
profile and quantity with its regions along ``s``
(:class:`~verification.agreement.outside_verdicts.Region`).

Contract: the table holds what
:func:`~verification.agreement.outside.judge` found and computes nothing
but its own text: :meth:`OutsideTable.markdown` (what ``against`` writes
as outside.md) and :meth:`OutsideTable.csv_rows` (outside.csv's rows); it
writes no file.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from contactcore.scene import Units

from .outside_budget import ESTIMATE_WINDOW_CELLS
from .outside_verdicts import VERDICTS, WARNED_MULTIPLE, Region
from .records import Agreement


@dataclass(frozen=True)
class OutsideRow:
    """One profile quantity of the outside answer against the project's.
    ``agreement`` holds the agreement's figures (worst sample, RMS, where,
    both values there: :class:`~verification.agreement.records.Agreement`);
    ``estimate`` the RMS of the project's estimated error over the kept
    samples, in the quantity's unit, ``ratio`` RMS(difference) / that;
    ``regions`` the verdicts along ``s``; ``warnings`` what makes the
    project's estimate untrusted (empty: trusted); ``hints`` what the
    verdict adds about the input (what ``s`` was taken as where it was
    given alone; where ``outside`` spans most of the profile, what to check
    first); ``columns`` per outside
    sample (in ``s`` order): ``s, x, y, outside, project, estimate,
    difference, verdict``."""

    agreement: Agreement
    estimate: float
    ratio: float
    regions: tuple[Region, ...]
    warnings: tuple[str, ...]
    columns: dict = field(repr=False, compare=False, default_factory=dict)
    hints: tuple[str, ...] = ()

    @property
    def profile(self) -> str:
        return self.agreement.profile

    @property
    def quantity(self) -> str:
        return self.agreement.quantity

    def verdicts(self) -> dict[str, list[tuple[float, float]]]:
        """Verdict -> the ``(s_from, s_to)`` of its regions."""
        out: dict[str, list[tuple[float, float]]] = {}
        for r in self.regions:
            out.setdefault(r.verdict, []).append((r.s_from, r.s_to))
        return out


def _warned_lines(rows) -> list[str]:
    """Each estimate warning of ``rows`` once, as a list item: the warning
    as the estimate wrote it where it names every quantity it is given
    for, else after those quantities (newuser35: "G:tT: G:tN, G:tT: an
    exact law's traction …" repeated the key the warning names)."""
    keys: dict[str, list[str]] = {}
    for r in rows:
        for w in r.warnings:
            keys.setdefault(w, []).append(f"{r.profile}:{r.quantity}")
    return [f"- {w}" if all(k in w for k in ks) else f"- {', '.join(ks)}: {w}" for w, ks in keys.items()]


@dataclass(frozen=True)
class OutsideTable:
    """The outside answer against ``method``'s finest run (at ``hs[-1]``;
    ``hs`` the runs estimated, coarse to fine): one :class:`OutsideRow`
    per profile and quantity given; samples within ``exclude`` of the
    singular ``regions`` left out; ``multiple`` is :data:`BLAME_MULTIPLE`."""

    scene: str
    method: str
    hs: tuple[float, ...]
    exclude: float
    multiple: float
    regions: tuple
    rows: tuple[OutsideRow, ...]
    warnings: tuple[str, ...] = ()
    units: Units = Units()

    def row(self, profile: str, quantity: str) -> OutsideRow:
        """The row of ``profile``'s ``quantity``."""
        return next(r for r in self.rows if (r.profile, r.quantity) == (profile, quantity))

    def markdown(self, conventions: str = "") -> str:
        """The verdict in Markdown (what ``against`` writes as outside.md,
        its ``conventions`` paragraph ``run``'s summary.md's,
        :func:`verification.run_summary.conventions`, after the title)."""
        from ..files import column_unit
        from .measures import percent
        length = self.units.length
        where = ("; ".join(f"{name} " + ", ".join(f"({x:.4g}, {y:.4g})" for x, y in pts) for name, pts in self.regions)
                 if self.regions else "")
        left = (f"samples within {self.exclude:.3g} {length} of these singular points are left out: {where}"
                if self.regions else "no sample is left out (the scene has no singular point)")
        opening = ([conventions.rstrip("\n") + " s is a profile's parameter: the arc length from its start, or "
                    "Γ's polar angle in rad on a circle (docs/scenes.md, \"Profiles and their samples\").", ""]
                   if conventions else [])
        lines = [f"# An outside answer against {self.method} on scene {self.scene}", "", *opening,
                 f"The project's answer: {self.method} at h = {self.hs[-1]:g} {length}, its error estimated from "
                 f"the runs at h = {', '.join(f'{h:g}' for h in self.hs)} {length} (Richardson, "
                 "docs/error-estimates.md), taken at each sample as the largest `q_err` within "
                 f"{ESTIMATE_WINDOW_CELLS:g} coarse cells either side along the profile in the same body among the "
                 "samples compared (none within the exclusion distance of a singular point), plus the "
                 f"error of interpolating the project's samples to the outside's; {left}.", "",
                 "Verdicts: " + "; ".join(f"`{k}`: {v}" for k, v in VERDICTS.items()) + ".", "",
                 "| profile | quantity | worst | RMS | project's estimated error (RMS) | difference / estimate "
                 "(RMS) | verdicts along s |", "|---|---|---|---|---|---|---|"]
        for r in self.rows:
            a, unit = r.agreement, column_unit(r.quantity, self.units) or ""
            s_unit = f" {a.s_unit}" if a.s_unit else ""
            regions = "; ".join(f"{g.verdict} {g.s_from:.4g}–{g.s_to:.4g}{s_unit} ({g.samples}"
                                + ("" if math.isnan(g.ratio) else f", {g.ratio:.3g}×") + ")" for g in r.regions)
            lines.append(f"| {a.profile} | {a.quantity} | {percent(a.worst)} at s = {a.s:.4g}{s_unit} | "
                         f"{percent(a.rms)} | {r.estimate:.3g} {unit} | {r.ratio:.3g} | {regions} |")
        hints = [f"- {r.profile}:{r.quantity}: {h}" for r in self.rows for h in r.hints]
        if hints:
            lines += ["", "About the input:", *hints]
        warned = _warned_lines(self.rows)
        if warned:
            lines += ["", f"The project's estimate is warned (a verdict there only beyond {WARNED_MULTIPLE:.3g} × "
                      "the estimate):", *warned]
        lines += ["", "worst: the largest |difference| over the project's largest scale (the agreement table's, "
                  "docs/api.md); RMS: the RMS difference over the RMS scale; a region's figure: RMS(difference) / "
                  "RMS(the project's estimated error) over its samples."]
        return "\n".join(lines) + "\n"

    def csv_rows(self) -> list[dict]:
        """One dict per outside sample: ``profile, quantity, s, s_unit, x,
        y, outside, project, estimate, difference, unit, verdict``
        (``s_unit``: s's, m or rad by profile; ``unit``: the quantity's, of
        outside, project, estimate and difference)."""
        from ..files import column_unit
        names = ("s", "x", "y", "outside", "project", "estimate", "difference", "verdict")
        return [{"profile": r.profile, "quantity": r.quantity, "s_unit": r.agreement.s_unit or self.units.length,
                 "unit": column_unit(r.quantity, self.units) or "", **{n: r.columns[n][i] for n in names}}
                for r in self.rows for i in range(len(r.columns["s"]))]
