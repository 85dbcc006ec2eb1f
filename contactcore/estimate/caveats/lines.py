"""What every estimate warning's line shares: the page that explains it, its
advice, and the names of Γ's quantities and of the energy estimate's entry.

A warning is one short line: the quantities, what was found with its
numbers in their units, and the row of :data:`WARNINGS_PAGE`'s table,
"The warnings", that explains it (:func:`see`)."""
from __future__ import annotations

from ..orders import GAPS, TRACTIONS


#: Γ's quantities: the gaps and the tractions.
GAMMA = GAPS + TRACTIONS


#: The page whose table, "The warnings", explains each estimate warning:
#: a row per warning, its first words the name a line points to (:func:`see`).
WARNINGS_PAGE = "docs/error-estimates.md"


#: What a warning of a two-run estimate advises: a third run observes the order.
OBSERVE = "try --estimate 3"


#: The key under which
#: :func:`~contactcore.estimate.caveats.quadrature.quadrature_energy` or
#: :func:`~contactcore.estimate.caveats.recovery.recovery_floor` marks the energy estimate in
#: :attr:`~contactcore.estimate.runs.Estimate.unsettled` (a profile id
#: ``energy``, quantity ``‖σ‖_E``, as the effectivity table names it).
ENERGY_KEY = "energy:‖σ‖_E"


def see(row: str) -> str:
    """The end of a warning's line: where its explanation lives, the row
    of :data:`WARNINGS_PAGE`'s table that begins with ``row``."""
    return f" ({WARNINGS_PAGE}: {row})"


def with_cosines(found: dict[str, float]) -> str:
    """The quantities ``PID:Q`` of a cosine line (``unlike differences``,
    ``unlike runs``), each with its cosine to two decimals:
    ``"G:tT (0.17), D:ux (-0.22)"``."""
    return ", ".join(f"{k} ({v:.2f})" for k, v in found.items())
