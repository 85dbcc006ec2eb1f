"""Three runs whose two differences share no pattern are named, not too
small (contactcore.estimate.caveats.unlike_differences, est3_37;
docs/error-estimates.md, "The warnings", "unlike differences").

Richardson's premise, an error ``C(x) h^p`` sample by sample, makes the
last difference the first scaled down (cosine 1).  Where each run's error
has a pattern of its own (scene B's fe P1 σxy, a stress constant per cell
read at points that fall elsewhere in their cells at each h: 2.09 and 2.19
of its error from three runs, unwarned before), the differences add the
runs' errors rather than cancel them, and the estimate over-reads."""
import numpy as np

from contactcore import estimate as est
from contactcore import load_scene
from contactcore import tolerances as core_tol
from contactcore.profiles import ProfileData
from contactcore.scaling import Sizes
from test_estimate_warning_lines import _pointed
import tolerances as tol

#: The three runs' h, coarse to fine.
HS = (0.1, 0.05, 0.025)


def _levels(own: bool, p: float = 1.0) -> tuple[list[np.ndarray], np.ndarray]:
    """Three runs of a quantity with error ``h^p`` times a pattern along 41
    samples: the same smooth pattern in every run, or (``own``) a sign
    that alternates over cells of width h, placed where a sample falls in
    its cell at each h (each run's pattern its own); and the finest run's
    error."""
    x = np.linspace(0.0, 1.0, 41)
    exact = np.sin(3 * x)
    pattern = lambda h: np.where(np.floor(x / h + 0.3) % 2 == 0, 1.0, -1.0) if own else 1.0 + x ** 2  # noqa: E731
    errors = [h ** p * pattern(h) for h in HS]
    return [exact + e for e in errors], errors[-1]


def test_differences_that_share_no_pattern_are_named_and_over_read():
    """Unlike differences: cosine at most UNLIKE_COSINE, the estimate (at
    theory's order, observed order within it) over the error by about
    (2^{2p} + 1)^½ / (2^p − 1) (√5 at p = 1), and named with the cosine in
    a short line that points to its row; alike ones (the same pattern at
    every h) have cosine 1, are estimated exactly and not named.  The old
    code had no cosine and no line: these entries went unwarned."""
    (levels, error), (smooth, smooth_error) = _levels(True), _levels(False)
    unlike, alike = (est.richardson(v, theory=(1.0, 1.0)) for v in (levels, smooth))
    assert unlike.alike <= core_tol.UNLIKE_COSINE and alike.alike > 1 - tol.UNLIKE_ALIKE_SLACK
    assert unlike.rms / est.rms(error) > tol.UNLIKE_OVER_READ and np.isclose(alike.rms, est.rms(smooth_error))
    assert unlike.record()["alike"] == unlike.alike
    found = est.unlike_differences({"B1": {"sxy": unlike, "ux": alike}})
    assert list(found) == ["B1:sxy"]
    line, = est.unlike_differences_warning({**found, "B4:sxy": found["B1:sxy"]})
    _pointed(line)
    assert len(line) <= tol.ESTIMATE_WARNING_CHARS and "not always" in line and line.startswith("B1:sxy (")
    assert not est.unlike_differences_warning({})


def test_an_entry_another_line_names_is_left_to_it():
    """unlike_differences leaves to other lines the entries they name (its
    direction holds only over the entries no other line named), and a
    two-run estimate has no cosine."""
    levels, _ = _levels(True)
    three, two = est.richardson(levels, theory=(1.0, 1.0)), est.richardson(levels[1:], theory=(1.0, 1.0))
    assert two.alike is None and "alike" not in two.record()
    assert not est.unlike_differences({"B1": {"sxy": three}}, named={"B1:sxy"})
    assert not est.unlike_differences({"B1": {"sxy": two}})


def _roundoff_runs(size: float) -> list[list[ProfileData]]:
    """Three runs of a stress along a line of 41 samples whose first sample
    is a singular point at :data:`tolerances.UNLIKE_SINGULAR_PEAK` times
    the scene's ``size`` of stress (the same in every run), the rest of
    order ``size`` with :func:`_levels`' own-pattern error at
    :data:`tolerances.UNLIKE_ROUNDOFF_ERROR` times it."""
    x = np.linspace(0.0, 1.0, 41)
    runs = []
    for h in HS:
        pattern = np.where(np.floor(x / h + 0.3) % 2 == 0, 1.0, -1.0)
        sxx = size * (np.sin(3 * x) + tol.UNLIKE_ROUNDOFF_ERROR * h * pattern)
        sxx[0] = size * tol.UNLIKE_SINGULAR_PEAK
        runs.append([ProfileData("D", "arclength", {"s": x, "x": x, "y": np.zeros_like(x), "sxx": sxx})])
    return runs


def test_runs_that_differ_only_at_round_off_are_not_named():
    """fix38: a quantity whose two finest runs differ only at round-off at
    every sample (:func:`contactcore.estimate.caveats.roundoff_runs`, which
    every other line skips) is not named, though the order and cosine,
    taken over the kept samples against their own scale, are computed: here
    the largest value lies at a singular point left out.  The old code
    named it (its ``unlike_differences`` took no runs)."""
    scene = load_scene("tests/scenes/tilt_unil_exact.toml")
    size = Sizes.of(scene).stress
    levels = _roundoff_runs(size)
    kept = np.arange(41) > 0
    e = est.richardson([run[0].columns["sxx"] for run in levels], theory=(1.0, 1.0), kept=kept,
                       floor=est.roundoff_floor(Sizes.of(scene), "sxx"))
    assert e.measured is not None and e.alike <= core_tol.UNLIKE_COSINE
    assert est.caveats.roundoff_runs(scene, levels) == {"D:sxx"}
    profiles = {"D": {"sxx": e}}
    assert est.unlike_differences(profiles) == {"D:sxx": e.alike}
    assert est.unlike_differences(profiles, roundoff=est.caveats.roundoff_runs(scene, levels)) == {}
