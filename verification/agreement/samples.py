"""Which samples are compared: those at least ``exclude`` from every
singular point of the scene (a corner of the domain, an end of a straight
Γ), where no method resolves the stresses (:func:`kept_samples`); the
default distance (:func:`default_exclusion`) and its check
(:func:`check_exclusion`)."""
from __future__ import annotations

import numpy as np

from contactcore import ProfileData, Scene, SceneError
from contactcore.estimate.singular import far_from_singular, singular_points
from contactcore.profiles import sample_points
from contactcore.tolerances import EXCLUDE_FRACTION, EXCLUDE_KEEP_SHARE


def default_exclusion(scene: Scene) -> float:
    """The distance from singular points inside which samples are left out:
    ``EXCLUDE_FRACTION`` of the scene's diameter L, at most
    ``EXCLUDE_KEEP_SHARE`` of the distance from the singular points of each
    profile's farthest sample, so that every profile keeps samples (its
    middle, where both its ends are singular points)."""
    sing = singular_points(scene)
    if len(sing) == 0:
        return EXCLUDE_FRACTION * scene.length_scale
    reach = min((float(np.max(np.min(np.linalg.norm(points[:, None, :] - sing[None], axis=-1), axis=1)))
                 for points in (sample_points(scene, p)[1] for p in scene.profiles)), default=np.inf)
    return min(EXCLUDE_FRACTION * scene.length_scale, EXCLUDE_KEEP_SHARE * reach)


def check_exclusion(scene: Scene, exclude: float, name: str = "exclude") -> None:
    """Refuse, before any solve, an exclusion (the argument ``name``) that is
    not a finite distance >= 0, or that leaves every sample of a profile out
    (its agreement would have nothing to measure)."""
    if not (exclude >= 0 and np.isfinite(exclude)):
        raise SceneError(name, f"must be a finite distance >= 0 (got {exclude:g})")
    for profile in scene.profiles:
        if not far_from_singular(scene, sample_points(scene, profile)[1], exclude).any():
            raise SceneError(name, f"{exclude:g} leaves out every sample of profile {profile.id}: "
                             f"give less (the default is {default_exclusion(scene):.3g})")


def kept_samples(scene: Scene, profile: ProfileData, exclude: float) -> np.ndarray:
    """Mask of the samples at least ``exclude`` from every singular point
    (:func:`contactcore.estimate.singular_points`)."""
    xy = np.column_stack([profile.columns["x"], profile.columns["y"]])
    return far_from_singular(scene, xy, exclude)
