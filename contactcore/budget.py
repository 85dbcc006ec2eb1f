"""What a run will cost, estimated before any work, so that a size the
machine cannot hold is refused in a second instead of exhausting it.

For a resolution ``h`` on a domain of area ``A`` a method has about
``A n / h²`` nodes, ``n`` the nodes a cell holds that its options declare
(``nodes_per_cell``: ``k²`` at degree k, vertices and edge and cell nodes
for k = 2, by default; the EFGM grid's one whatever the basis); each
carries two displacement components per field, of which its options
declare ``field_copies`` (fe keeps one field per body on the whole mesh,
2; xfem one standard field plus a few enriched nodes, and EFGM one, 1:
:class:`contactcore.discretisation.Discretisation`).  The direct solver's factors dominate memory: measured
:data:`BYTES_PER_UNKNOWN` at up to ~2.4e5 unknowns (2D nested dissection
grows as N log N, so larger runs need somewhat more).  The interface history
keeps, per increment, a few numbers per quadrature point of Γ (about
``3 |Γ| / h`` points).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass

from .errors import ContactError

#: Resident bytes per unknown of a run, factors included: run C-coulomb, fe
#: P2, h = 0.02 (2.4e5 unknowns) peaks at 1.0 GB: 4.2 kB; rounded up for the N log N growth of the factors.
BYTES_PER_UNKNOWN = 6_000

#: Bytes kept per increment and Γ point (jump, traction, status, residuals).
BYTES_PER_HISTORY_POINT = 64

#: Fraction of the machine's memory a run may plan to use.
MEMORY_SHARE = 0.8

#: Resident bytes of one process before its cases' own sizes: a Python
#: that has imported every method (dolfinx, PETSc, gmsh) and solved scene A
#: at h = 0.2 with each peaks at 0.19 GB (2026-11-28, ``/usr/bin/time -f
#: %M``); rounded up.  A pool of ``--workers K`` or mpirun's K ranks holds
#: K of them (:func:`check_processes`, and with their cases
#: :func:`check_together`, :func:`check_spread`).
BYTES_PER_PROCESS = 250e6


class TooLargeError(ContactError):
    """A run that would not fit in the machine's memory."""


@dataclass(frozen=True)
class Counted:
    """What :func:`estimate` reads of a solve (as of a method's options,
    :class:`contactcore.discretisation.Discretisation`), stated where no
    options class is at hand: a peer's solve (one field, ``degree²``
    nodes a cell, the defaults), or fe's on the mesh ``python -m meshes``
    writes (``meshes`` may not import the options of ``xdolfinx``)."""

    name: str
    degree: int
    field_copies: int = 1
    nodes_per_cell: int | None = None  # None: degree², as Discretisation's

    def __post_init__(self):
        if self.nodes_per_cell is None:
            object.__setattr__(self, "nodes_per_cell", self.degree ** 2)


@dataclass(frozen=True)
class Estimate:
    """What a run will cost (:func:`estimate`): about ``unknowns`` unknowns,
    ``memory`` resident bytes, factors included, and ``solves`` linear solves."""

    unknowns: float
    memory: float  # bytes
    solves: float

    def describe(self) -> str:
        return f"about {self.unknowns:.2g} unknowns, {self.memory / 1e9:.3g} GB and {self.solves:.3g} solves"


def machine_memory() -> float:
    """Physical memory of this machine in bytes."""
    return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def estimate(scene, h: float, options) -> Estimate:
    """The :class:`Estimate` (unknowns, memory in bytes, linear solves) of
    solving ``scene`` with a method's ``options`` (a
    :class:`~contactcore.discretisation.Discretisation`, or a
    :class:`Counted`: their ``degree``, ``field_copies`` and
    ``nodes_per_cell``) at element size ``h``, in the same length unit as
    ``scene``'s domain (module doc for the model).  Nothing is refused
    here: a tiny ``h`` gives a huge estimate, which :func:`check_budget`
    refuses."""
    nodes = scene.domain.area / h / h * options.nodes_per_cell  # h ** 2 underflows to 0 at 1e-300
    unknowns = 2 * options.field_copies * nodes + 4  # a one-cell mesh still has a few
    gamma_points = 3 * scene.length_scale * math.pi / h
    # every increment is solved, and its history kept, for a nonlinear law
    # or a followed path: Newton's ~3 solves an increment, one for a linear law
    followed = scene.follow_path or not scene.law.is_linear
    solves = scene.increments * (1 if scene.law.is_linear else 3) if followed else 1
    memory = BYTES_PER_UNKNOWN * unknowns + BYTES_PER_HISTORY_POINT * gamma_points * solves
    return Estimate(unknowns, memory, solves)


def check_processes(count: int, field: str, offer_allow_large: bool = True) -> None:
    """A :class:`TooLargeError` when ``count`` processes (a pool's workers,
    mpirun's ranks; ``field`` the option that asked for them) would hold
    more than MEMORY_SHARE of this machine's memory at
    :data:`BYTES_PER_PROCESS` each, before any case's own memory (the
    message offers ``--allow-large`` where the command has it)."""
    have = MEMORY_SHARE * machine_memory()
    if count * BYTES_PER_PROCESS > have:
        raise TooLargeError(f"{field} {count}: about {count * BYTES_PER_PROCESS / 1e9:.3g} GB for the processes "
                            f"alone ({BYTES_PER_PROCESS / 1e9:.2g} GB each, before any solve), against "
                            f"{have / 1e9:.3g} GB usable on this machine ({os.cpu_count()} cores); use fewer"
                            + (", or pass --allow-large to try anyway" if offer_allow_large else ""))


def check_budget(scene, h: float, options, field: str = "--h", offer_allow_large: bool = True) -> Estimate:
    """The :func:`estimate` of the run with ``options`` (``h`` in ``scene``'s length unit),
    or a :class:`TooLargeError` when its memory exceeds MEMORY_SHARE of
    this machine's physical memory; the message names ``field`` (the
    option or scene field that set ``h``, ``--h`` by default), the
    estimate in GB and what to do (a larger h, fewer increments, or
    ``--allow-large`` where the command has it)."""
    est = estimate(scene, h, options)
    have = MEMORY_SHARE * machine_memory()
    if est.memory > have:
        raise TooLargeError(f"{field} {h:g} with {options.name} (degree {options.degree}, "
                            f"{scene.increments} increments): "
                            f"{est.describe()}, against {have / 1e9:.3g} GB usable on this machine; use a larger h "
                            "or fewer increments" + (", or pass --allow-large to try anyway" if offer_allow_large
                                                     else ""))
    return est


def together(memories, count: int | None, kept=(), systems: int = 1) -> float:
    """Bytes that ``count`` processes (a pool's workers; None or 1: one,
    serially) hold at worst when they solve the cases of ``memories``
    (each case's resident bytes, :func:`estimate`'s memory) and the cases
    of ``kept`` (below).

    Each process solves one case at a time, so at most ``at_once =
    min(count, cases)`` run at once (a pool starts no more processes than
    it has cases): the ``at_once`` largest cases together, not ``at_once``
    copies of the largest (review6's fault 2), and :data:`BYTES_PER_PROCESS`
    for each process when there are several.  One process alone is counted
    as :func:`check_budget` counts ``run``'s, without it: BYTES_PER_UNKNOWN
    was measured on one whole process's peak (review6's fault 3).

    A process may also keep built systems between its cases for reuse
    (:class:`contactcore.discretisation.Reuse`): ``kept`` gives, for each
    system several cases share, ``(bytes, cases)``; the cases of
    ``memories`` are those whose system nobody keeps.  A process holds at
    most ``systems`` systems, the one it solves in included, at most one
    of them not kept, and each process keeps its own copy of a shared one.
    So at most the ``at_once × systems`` largest of: the cases of
    ``memories`` (at most ``at_once`` of them), and each shared system
    ``min(at_once, cases)`` times (review6's fault 1)."""
    memories, kept = [float(m) for m in memories], [(float(m), int(c)) for m, c in kept]
    at_once = min(max(count or 1, 1), len(memories) + sum(c for _, c in kept))
    if at_once == 0:
        return 0.0
    slots = at_once * max(systems, 1)
    units = [(m, False) for m in memories] + [(m, True) for m, cases in kept for _ in range(min(at_once, cases))]
    alone, need, taken = 0, 0.0, 0
    for m, shared in sorted(units, key=lambda u: -u[0]):
        if taken == slots:
            break
        if not shared:
            if alone == at_once:
                continue
            alone += 1
        need, taken = need + m, taken + 1
    return need + (at_once * BYTES_PER_PROCESS if at_once > 1 else 0.0)


def check_together(memories, count: int | None, field: str = "--workers", offer_allow_large: bool = True,
                   kept=(), systems: int = 1) -> None:
    """A :class:`TooLargeError` when ``count`` processes (``field`` the
    option that asked for them; None or 1: one process, serially) solving
    the cases of ``memories`` (each case's resident bytes,
    :func:`estimate`'s memory), and keeping the shared systems of ``kept``
    (:func:`together`), would hold more than MEMORY_SHARE of this
    machine's memory, though each case alone fits (:func:`check_budget`)
    and the processes alone fit (:func:`check_processes`): review5's fault
    2, two cases of 11.5 GB on ``--workers 2`` against 20.2 GB usable.  The
    message names the count (``field`` only for several processes: one is
    the default, which the user may not have given), the largest case and
    the sum, and what to do."""
    memories, kept = list(memories), list(kept)
    cases, largest = len(memories) + sum(c for _, c in kept), max([*memories, *(m for m, _ in kept)], default=0.0)
    need, have = together(memories, count, kept, systems), MEMORY_SHARE * machine_memory()
    if need > have:
        at_once = min(max(count or 1, 1), cases)
        reuse = " and the systems kept for reuse" if kept and systems > 1 else ""
        advice = ("use fewer workers or a larger h" if at_once > 1 else
                  "use a larger h" + (", or one method a study" if reuse else ""))
        where = (f"{field} {count}: {at_once} of the {cases} cases at once{reuse}, the largest about "
                 f"{largest / 1e9:.3g} GB (+{BYTES_PER_PROCESS / 1e9:.2g} GB for each process)"
                 if at_once > 1 else
                 f"the {cases} cases one at a time{reuse}, the largest about {largest / 1e9:.3g} GB")
        raise TooLargeError(f"{where}, about {need / 1e9:.3g} GB together, against {have / 1e9:.3g} GB usable on "
                            f"this machine; {advice}" + (", or pass --allow-large to try anyway" if offer_allow_large
                                                         else ""))


def spread(memory: float, ranks: int) -> float:
    """Bytes that one case of ``memory`` resident bytes holds spread over
    ``ranks`` mpirun ranks: the case's own (its factors are split over the
    ranks, not copied) and :data:`BYTES_PER_PROCESS` for each rank."""
    return memory + ranks * BYTES_PER_PROCESS


def check_spread(memories, ranks: int, field: str = "--ranks", offer_allow_large: bool = True) -> None:
    """A :class:`TooLargeError` when the largest case of ``memories``
    (each case's resident bytes), solved on ``ranks`` mpirun ranks one case
    after another, would hold more than MEMORY_SHARE of this machine's
    memory (:func:`spread`)."""
    largest = max(memories, default=0.0)
    need, have = spread(largest, ranks), MEMORY_SHARE * machine_memory()
    if need > have:
        raise TooLargeError(f"{field} {ranks}: the largest case, about {largest / 1e9:.3g} GB, on {ranks} ranks "
                            f"(+{BYTES_PER_PROCESS / 1e9:.2g} GB each) needs about {need / 1e9:.3g} GB, against "
                            f"{have / 1e9:.3g} GB usable on this machine; use fewer ranks or a larger h"
                            + (", or pass --allow-large to try anyway" if offer_allow_large else ""))
