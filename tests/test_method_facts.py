"""The facts a method's options class declares for the shared core
(contactcore.discretisation.Discretisation: ``recovered_stress``,
``meshfree``, ``field_copies``, ``nodes_per_cell``, ...; docs/
architecture.md, "A new method") against what each method's run does,
through the class: a fact that drifted from its method would estimate
the wrong error (one recovery against two, a cell's stencil against a
support's) with no other test failing.  The core reads these facts from
the options or the Result, never by a method's name
(tests/test_layout.py::test_the_core_names_no_method)."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from contactcore.budget import estimate
from contactcore.estimate import energy
from contactcore.result import MethodFacts
from meshes.__main__ import fe_solve
from verification import methods

#: Coarse: the facts do not depend on the size.
H = 0.2


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("method", list(methods.METHODS))  # a new method is held to its facts too
def test_each_method_declares_what_its_run_does(method, degree):
    """Options that say ``recovered_stress`` report a stress that differs
    from the stress of their own displacement (its ``direct_stress``) by
    more than round-off, and only they; options that say ``meshfree``
    record a support (``dmax``) and no cells, and only they.  The Result
    carries the options' facts (``Result.facts``), unchanged by a pickle
    (a pool's workers send their Results back so)."""
    options = methods.discretisation(method)(degree=degree)
    scene = load_scene("A")
    result = methods.solver(method)(scene, H, degree=degree)
    x = np.linspace(0.05, 0.95, 7)
    points = np.array([(a, b) for a in x for b in (0.2, 0.3, 0.7, 0.8)])
    bodies = (points[:, 1] > 0.5).astype(int)
    reported = result.fields.stress(points, bodies)
    direct = energy.direct_stress(result.fields, points, bodies)
    apart = float(np.max(np.abs(reported - direct)) / np.max(np.abs(direct)))
    assert (apart > tol.FACT_STRESS_ROUNDOFF) == options.recovered_stress, apart
    assert ("dmax" in result.discretisation) == options.meshfree
    assert result.facts == options.facts() == pickle.loads(pickle.dumps(result.facts))


@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("method", list(methods.METHODS))
def test_the_budget_reads_the_options_facts(method, degree):
    """contactcore.budget counts ``2 · field_copies · nodes_per_cell · A / h²``
    unknowns (+ 4) from the options; a peer (one field, ``degree²`` nodes
    a cell, the base class's defaults) is counted as options that declare
    nothing."""
    options = methods.budgeted(method, degree)
    scene = load_scene("A")
    want = 2 * options.field_copies * (scene.domain.area / H / H * options.nodes_per_cell) + 4
    assert estimate(scene, H, options).unknowns == want  # the same arithmetic
    peer = methods.budgeted("getfem", degree)
    assert (peer.field_copies, peer.nodes_per_cell) == (1, degree ** 2)


@pytest.mark.parametrize("degree", [1, 2])
def test_the_meshes_command_counts_fe_as_fe_declares(degree):
    """``python -m meshes`` may not import xdolfinx's options (xdolfinx
    imports meshes), so it states fe's budget facts itself: they are FE's."""
    fe, stated = methods.discretisation("fe")(degree=degree), fe_solve(degree)
    assert (stated.name, stated.degree, stated.field_copies, stated.nodes_per_cell) == \
        (fe.name, fe.degree, fe.field_copies, fe.nodes_per_cell)


def test_a_result_without_options_has_the_defaults():
    """A peer's Result, built without options, carries the base class's
    facts: none of the estimate's rules for a recovered stress or a
    meshfree method apply to it."""
    from contactcore.discretisation import Discretisation
    assert MethodFacts() == MethodFacts(recovered_stress=Discretisation.recovered_stress.fget(None),
                                        meshfree=Discretisation.meshfree,
                                        quadrature_energy=Discretisation.quadrature_energy.fget(None),
                                        fast_gamma=Discretisation.fast_gamma.fget(None))



def _closed_form(case_name: str, method: str, degree: int):
    """``(rows, estimate)``: verification.effectivity's rows of closed form
    ``case_name`` for the variant at its rungs, and the estimate they
    came from; a method not yet in its ``VARIANTS`` fails here by name:
    add it there, with its rungs."""
    from contactcore import estimate as est
    from contactcore import sample_profiles
    from contactcore.discretisation import solve
    from verification.agreement import default_exclusion
    from verification.effectivity import CASES, VARIANTS, energy_row, exact_profiles, profile_rows, rungs
    assert (method, degree) in VARIANTS, f"add ({method!r}, {degree}) to verification.effectivity.VARIANTS"
    case = CASES[case_name]()
    options = methods.discretisation(method)(degree=degree, **VARIANTS[(method, degree)][0])
    exclude = default_exclusion(case.scene)
    results = [solve(case.scene, options, h) for h in rungs(case_name, (method, degree))]
    estimate = est.estimate_runs(case.scene, results, exclude)
    got = {p.id: p for p in sample_profiles(case.scene, results[-1].fields, results[-1].interface)}
    exact = case.fields(case.history()[-1]) if hasattr(case, "history") else case
    return (profile_rows(estimate, got, exact_profiles(case))
            + [energy_row(case.scene, results[-1], estimate, exact, exclude)]), estimate


@pytest.mark.slow
@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("method", list(methods.METHODS))
def test_quadrature_energy_says_whose_tiny_energy_estimate_reads_too_small(method, degree):
    """Options that say ``quadrature_energy`` are those whose Zienkiewicz–
    Zhu estimate on the layered slip (a piecewise-linear exact field) lies
    below QUADRATURE_ENERGY_SHARE of the run's energy and reads below
    EFFECTIVITY's lower end (EFGM P1: 1.8e-5, 0.41; EFGM P2: 1.9e-5 but
    0.77; fe and xfem reproduce the field to round-off, 3e-15 to 1.3e-14)."""
    from contactcore import tolerances as core_tol
    rows, estimate = _closed_form("layered_slip", method, degree)
    energy, = [r for r in rows if r["profile"] == "energy"]
    small = energy["effectivity"] is not None and energy["effectivity"] < tol.EFFECTIVITY[0]
    tiny = estimate.energy.relative < core_tol.QUADRATURE_ENERGY_SHARE
    assert methods.discretisation(method)(degree=degree).quadrature_energy == (tiny and small), energy


#: The smooth closed forms fast_gamma is measured on (two on a circular Γ, one layered).
FAST_GAMMA_CASES = ("pressurised_rod", "twisted_rod", "quadratic_layers")


@pytest.mark.slow
@pytest.mark.parametrize("degree", [1, 2])
@pytest.mark.parametrize("method", list(methods.METHODS))
def test_fast_gamma_says_whose_gamma_quantities_converge_faster_than_taken(method, degree):
    """Options that say ``fast_gamma`` are those whose gaps and tractions
    on Γ, estimated from two runs at order degree + 1, read above
    FAST_GAMMA_EFFECTIVITY on each smooth closed form (the rods, the
    quadratic layers): their runs' differences shrink faster than that
    order (EFGM P1: 2.02-2.33; every other variant at most 1.24)."""
    import registered
    from verification.effectivity import CASES
    for case in FAST_GAMMA_CASES:  # a method refusing a curved Γ or a disc: docs/architecture.md, "A new method"
        registered.skip_unless_solvable(CASES[case]().scene, registered.options(method, degree),
                                        what=f"the {case.replace('_', ' ')} (fast_gamma's measurement)")
    least = min(r["effectivity"] for case in FAST_GAMMA_CASES
                for r in _closed_form(case, method, degree)[0]
                if r["quantity"] in ("gN", "gT", "tN", "tT") and r["kind"] == "error")
    assert methods.discretisation(method)(degree=degree).fast_gamma == (least > tol.FAST_GAMMA_EFFECTIVITY), least
