"""The estimate's warnings are short (newuser32: twelve lines of 250-520
characters on a 600-DOF run, "within 6 of a singular point … (lengths in
mm)"): each at most ESTIMATE_WARNING_CHARS, its lengths each with its
unit, and each ending with the row of docs/error-estimates.md, "The
warnings", that explains it, a row the table has."""
import re
from pathlib import Path

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore import estimate as est
from contactcore.discretisation import solve
from contactcore.estimate.caveats import WARNINGS_PAGE
from contactcore.estimate.energy import EnergyEstimate
from verification import methods
from verification.agreement import default_exclusion

ROOT = Path(__file__).resolve().parent.parent
#: newuser32's scene: a 20 x 10 mm bimaterial block, inclined Γ, exact Coulomb, h = 1 mm.
BLOCK = ROOT / "tests" / "scenes" / "estimate_warnings_block.toml"
#: A pointer at a warning's end: the page and the row's first words.
POINTER = re.compile(rf" \({re.escape(WARNINGS_PAGE)}: ([^)]+)\)$")


def _rows() -> list[str]:
    """The first cells of the page's table of warnings ("The warnings")."""
    text = (ROOT / WARNINGS_PAGE).read_text()
    table = text.split("### The warnings", 1)[1].split("\n\n")[2]
    return [line.split("|")[1].strip() for line in table.splitlines()[2:]]


def _pointed(line: str) -> str:
    """The row a warning points to; fails if it points to none of the page's."""
    m = POINTER.search(line)
    assert m, f"no pointer to {WARNINGS_PAGE} at the end of: {line}"
    assert any(row.startswith(m.group(1) + " ") for row in _rows()), (m.group(1), _rows())
    return m.group(1)


def test_newuser32s_block_gives_several_short_warnings_each_pointing_to_its_row():
    """Every method at h = 1 mm → 0.5 mm on the block: at least eight
    warnings (exact tractions, status, coarse stencils, EFGM P1's Γ,
    cell scale), each at most ESTIMATE_WARNING_CHARS, pointing to a row of
    the table, no length without its unit (mm)."""
    scene = load_scene(BLOCK)
    exclude = default_exclusion(scene)
    lines = []
    for name in ("fe", "xfem", "efgm"):
        disc = methods.discretisation(name)(degree=1)
        lines += est.estimate_runs(scene, [solve(scene, disc, h) for h in est.levels_of(scene.h, 2)], exclude,
                                   energy=False).warnings
    rows = {_pointed(line) for line in lines}
    assert len(lines) >= 8 and {"exact tractions", "status", "stencil", "fast Γ", "cell scale"} <= rows, lines
    too_long = [(len(line), line) for line in lines if len(line) > tol.ESTIMATE_WARNING_CHARS]
    assert not too_long, too_long
    bare = [m.group(0) for line in lines for m in re.finditer(r"(?:h = |within |stencils of |feature \(|across Γ \()([-+.\de]+)(?![-+.\de]| mm)", line)]
    assert not bare, bare


def _quantity(order: float, measured: float | None = None):
    return est.QuantityEstimate(np.zeros(3), order, (order, order), measured=measured)


#: Two quantities named, each line's usual (newuser32's block: one to six).
NAMES = ["G:gN", "G:gT"]


def _every_warning() -> list[str]:
    """Each warning maker's line with two quantities named (each with its
    figure where the line gives one) and figures of the width they come
    in: lengths to three digits in metres, h from 0.05 m."""
    unsettled = {cause: {k: (0.125, 0.0417) for k in NAMES} for cause in ("reach", "coarse", "thin")}
    change = {"coarse": {"open": 0.123, "stick": 0.5, "slip": 0.377}, "fine": {"open": 0.2, "stick": 0.45,
                                                                                "slip": 0.35},
              "differ": 12, "samples": 101, "h": [0.05, 0.025]}
    return (est.order_warnings({"A1": {"sxy": _quantity(2.0, 0.51)}})
            + est.pollution_warning(load_scene("B"), {"G": {q.split(":")[1]: _quantity(3) for q in NAMES}})
            + est.exact_traction_warning(NAMES) + est.exact_traction_warning(NAMES, three=True)
            + est.steady_exact_traction_warning(NAMES) + est.enforced_gap_warning(NAMES)
            + est.fast_gamma_warning(dict(zip(NAMES, (1.698, 2.0))), "efgm", 1)
            + est.fast_gamma_warning(dict(zip(NAMES, (1.698, 2.0))), "efgm", 1, observed=True)
            + est.unsettled_warnings(unsettled, 0.05, 0.123, "m", 0.0456)
            + est.curved_layer_warning(NAMES, 0.05, "m")
            + est.split_cell_share_warning({k: 0.545 for k in NAMES})
            + est.cell_scale_warnings({k: (3.83, 2.21) for k in NAMES}, (0.05, 0.025), length="m")
            + est.residue_warnings({k: (0.00031, "A1:sxy") for k in NAMES})
            + est.status_warning(change, "m")
            + est.status_change_warnings({k: (0.125, False) for k in NAMES}, "m")
            + est.recovery_floor(EnergyEstimate(1.0, 10.0, 0.1, recovery=0.523))
            + est.quadrature_energy("efgm", 1, methods.discretisation("efgm")(degree=1).facts(),
                                    EnergyEstimate(1.23e-5, 1.0, 0.1)))


@pytest.mark.parametrize("k", range(19))
def test_each_warning_is_short_with_two_quantities_named(k):
    """Each of the nineteen kinds of line (the three causes of a coarse
    stencil, the two of EFGM P1's Γ), with two quantities named, is at
    most ESTIMATE_WARNING_CHARS and points to its row (each further
    quantity adds its name, 6-8 characters, or 14-24 with its figure)."""
    lines = _every_warning()
    assert len(lines) == 19
    _pointed(lines[k])
    assert len(lines[k]) <= tol.ESTIMATE_WARNING_CHARS, (len(lines[k]), lines[k])
