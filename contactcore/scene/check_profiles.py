"""The rules of a scene's profiles: unique, file-safe ids none of
:data:`RESERVED_PROFILE_IDS`, known quantities, a segment of non-zero
length inside the domain (on Γ for Γ's quantities), or Γ's own parameter."""
from __future__ import annotations

import math

import numpy as np

from .. import tolerances as tol
from ..errors import SceneError
from ..geometry import CircleInterface, LevelSetInterface
from .profiles import LineProfile
from .values import check_file_name, check_point_inside
from .vocabulary import INTERFACE_QUANTITIES, MEAN_SIDE, PROFILE_SIDES, QUANTITIES


#: Names a profile may not take: they sit beside the profiles' ids in a
#: run's estimate record (summary.json's ``"estimate"``: the ZZ estimate,
#: the runs' h, Γ's status, the warnings and the worst estimated error),
#: where a profile of that name would be overwritten.
RESERVED_PROFILE_IDS = ("energy", "h", "status", "warnings", "worst")


def check_profiles(scene: "Scene") -> None:
    """Each profile's id, quantities, side, and its segment or parameter."""
    seen = set()
    L = scene.length_scale
    for i, prof in enumerate(scene.profiles):
        path = f"profiles[{i}]"
        if not prof.id or prof.id in seen:
            raise SceneError(f"{path}.id", f"must be a unique, non-empty name (got {prof.id!r})")
        if prof.id in RESERVED_PROFILE_IDS:
            raise SceneError(f"{path}.id", f"{prof.id!r} is reserved (a run's estimate record keeps "
                             f"{', '.join(RESERVED_PROFILE_IDS)} beside the profiles); choose another name")
        check_file_name(prof.id, f"{path}.id")
        seen.add(prof.id)
        if not prof.quantities:
            raise SceneError(f"{path}.quantities", "must name at least one quantity")
        for q in prof.quantities:
            if q not in QUANTITIES:
                raise SceneError(f"{path}.quantities", f"unknown quantity {q!r} (known: {', '.join(QUANTITIES)})")
        if prof.side not in PROFILE_SIDES:
            raise SceneError(f"{path}.side", f"unknown side {prof.side!r} (a body, 'minus' or 'plus', or "
                             f"'{MEAN_SIDE}', the two sides' mean on Γ)")
        if isinstance(prof, LineProfile):
            check_point_inside(scene, prof.start, f"{path}.start")
            check_point_inside(scene, prof.end, f"{path}.end")
            if math.dist(prof.start, prof.end) <= tol.GEOMETRY * L:
                raise SceneError(f"{path}.end", "the segment has zero length")
            if set(prof.quantities) & set(INTERFACE_QUANTITIES):
                ends = np.array([prof.start, prof.end, np.add(prof.start, prof.end) / 2])
                if np.max(np.abs(scene.interface.phi(ends))) > tol.GEOMETRY * L:
                    raise SceneError(f"{path}.quantities", "interface quantities (tN, tT, gN, gT) need a "
                                     "segment that lies on the interface")
        else:
            if prof.parameter not in ("angle", "arclength"):
                raise SceneError(f"{path}.parameter", f"must be 'angle' or 'arclength' (got {prof.parameter!r})")
            if prof.parameter == "angle" and not isinstance(scene.interface, CircleInterface):
                raise SceneError(f"{path}.parameter", "a polar angle needs a circular interface; use 'arclength'")
            if isinstance(scene.interface, LevelSetInterface):
                raise SceneError(f"{path}.type", "profiles along a general level set are not supported; "
                                 "use line profiles")
