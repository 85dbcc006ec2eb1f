"""A scene's interface law from its table: the law its ``type`` names,
enforced as its ``enforcement`` says — by the law's springs (the penalty
laws of :mod:`contactcore.laws`) or exactly (:mod:`contactcore.exact`,
which builds on them).  The one place that knows both."""
from __future__ import annotations

from . import exact
from .errors import SceneError
from .laws import LAWS

#: How a scene's ``[interface.law]`` may be enforced (``enforcement``).
ENFORCEMENTS = ("penalty", "exact")


def make_law(params: dict, path: str = "interface.law"):
    """The law named by ``params["type"]`` built from the other entries,
    enforced as ``params["enforcement"]`` says (penalty by default; exact
    laws and ``bonded``: :mod:`contactcore.exact`)."""
    if not isinstance(params, dict):
        raise SceneError(path, "must be a table with a 'type' and the law's parameters")
    known = [*LAWS, *exact.BONDED]
    kind = params.get("type")
    if kind is None:
        raise SceneError(f"{path}.type", f"missing (one of: {', '.join(known)})")
    if kind not in known:
        raise SceneError(f"{path}.type", f"unknown interface law {kind!r} (known: {', '.join(known)})")
    enforcement = params.get("enforcement", exact.default_enforcement(kind))
    if enforcement not in ENFORCEMENTS:
        raise SceneError(f"{path}.enforcement", f"must be one of {', '.join(ENFORCEMENTS)} (got {enforcement!r})")
    params = {k: v for k, v in params.items() if k != "enforcement"}
    if enforcement == "exact" or kind in exact.BONDED:
        return exact.make_law(kind, enforcement, params, path)
    if "stabilisation" in params:
        raise SceneError(f"{path}.stabilisation", 'applies to enforcement = "exact" only (the penalty\'s springs '
                         "are k_N, k_T)")
    return LAWS[kind].from_params(params, path)

