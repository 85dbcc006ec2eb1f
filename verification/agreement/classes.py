"""The class a quantity is labelled with in a table: ``zero`` for a known
zero of the paper's scenes (:func:`is_zero`), else ``interface``,
``contact``, ``contact edge``, ``edge`` or ``interior``
(:func:`quantity_class`).  A label only: every quantity is measured the
same way."""
from __future__ import annotations

import numpy as np

from contactcore import Scene

from .groups import components


def quantity_class(scene: Scene, profile, quantity: str) -> str:
    """``interface`` (gaps, tractions), ``contact`` (g_N, g_T, t_N of a law
    that opens: they have kinks where Γ opens, which cost a P2 method its
    higher order there), ``contact edge`` (t_T of such a law, which jumps from
    0 to k_T(g_T − s) where Γ closes: methods whose contact edges lie O(h)
    apart differ there by the whole jump), ``edge`` (a stress on a segment of
    the outer boundary) or ``interior`` (any other stress or displacement)."""
    if quantity in ("tN", "tT", "gN", "gT") and not scene.law.is_linear:
        return "contact edge" if quantity == "tT" else "contact"
    if quantity in ("tN", "tT", "gN", "gT"):
        return "interface"
    if hasattr(profile, "start"):
        ends = np.array([profile.start, profile.end])
        if np.all(np.abs(scene.domain.distance_to_boundary(ends)) <= 1e-12 * scene.length_scale):
            mid = ends.mean(axis=0, keepdims=True)
            if abs(scene.domain.distance_to_boundary(mid)[0]) <= 1e-12 * scene.length_scale:
                return "edge"
    return "interior"


#: The paper's scenes' quantities whose exact value is zero, by scene name:
#: the class ``zero`` they are labelled with (tests/test_agreement.py bounds
#: them by tolerances.FALSE_TN).  A label only: every quantity, these too,
#: is measured against its group's size (:func:`scale_of`); the numbers
#: cannot tell a zero by symmetry from a small component (scene B's fe P2
#: t_N is 0.42 % of |t| at h = 0.1, scene C's C4 t_T, not zero, 0.94 %).
KNOWN_ZEROS = {"B": {("B6", "tN"), ("B6", "gN")}}


def is_zero(scene: Scene, pid: str, q: str, profiles: dict) -> bool:
    """Whether ``pid``'s ``q`` is one of :data:`KNOWN_ZEROS` of ``scene``
    and ``profiles`` hold another component of its group at its samples
    (class ``zero``)."""
    return (pid, q) in KNOWN_ZEROS.get(scene.name, ()) and len(components(pid, q, profiles)) > 1
