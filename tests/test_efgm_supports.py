"""EFGM's supports: a uniform stress at a roller edge and at a clamped edge
(the patch test of the essential conditions, efgm.method.support_multipliers).

A bar of two materials across a frictionless vertical Γ, pressed by a
uniform traction on its right edge and held on its left one: the exact
stress is uniform, σxx = P, and the exact displacement linear in each body,
which both bases reproduce.  The supports' rows were once collocation at the
boundary nodes, and a basis that does not interpolate then missed σxx at the
roller edge by 1.1 % (linear) and 3.8 % (quadratic) at h = 0.1, whatever the
quadrature (measured 2026-11-27).  What is left now is the Gauss quadrature of
the rational shape functions: it falls with more points per direction."""
import numpy as np
import pytest

import tolerances as tol
from contactcore import load_scene
from efgm import method

P, E, NU = -5e8, (2.1e11, 7e10), 0.3
LENGTH, HEIGHT, GAMMA = 3.0, 0.5, 1.25


def _bar(tmp_path, clamped: bool):
    """The bar: left edge on x-rollers (ν = 0.3), or clamped (ν = 0, so the
    uniform state holds u_y = 0 there too); y-pins at both bottom corners
    (the one at the origin lies on the clamped edge, which holds it)."""
    nu = 0.0 if clamped else NU
    text = f"""
name = "{'barclamp' if clamped else 'barroller'}"
plane = "stress"
[domain]
type = "rectangle"
size = [{LENGTH}, {HEIGHT}]
[interface]
type = "line"
point = [{GAMMA}, 0.0]
normal = [1.0, 0.0]
[interface.law]
type = "coulomb"
enforcement = "exact"
mu = 0.0
kN = 1.0
kT = 1.0
[materials.minus]
E = {E[0]}
nu = {nu}
[materials.plus]
E = {E[1]}
nu = {nu}
[[supports]]
boundary = "left"
fix = "{'xy' if clamped else 'x'}"
[[pins]]
point = [0.0, 0.0]
fix = "y"
[[pins]]
point = [{LENGTH}, 0.0]
fix = "y"
[[loads]]
type = "traction"
boundary = "right"
value = [{P}, 0.0]
"""
    path = tmp_path / "bar.toml"
    path.write_text(text)
    return load_scene(path), nu


def _errors(scene, nu, degree, gauss=None):
    """Largest |σ − σ_exact| / |P| and |u − u_exact| / (|P| L / E₊) over a
    grid of points that holds every edge, the supported one included."""
    result = method.solve(scene, 0.1, degree=degree, gauss=gauss)
    x, y = np.meshgrid(np.linspace(0.0, LENGTH, 61), np.linspace(0.0, HEIGHT, 11))
    pts = np.column_stack([x.ravel(), y.ravel()])
    pts = pts[np.abs(pts[:, 0] - GAMMA) > tol.ON_GAMMA * LENGTH]  # Γ's own points belong to either body
    bodies = scene.body_of(pts)
    exact_s = np.tile([P, 0.0, 0.0], (len(pts), 1))
    left = pts[:, 0] <= GAMMA
    Ex = np.where(left, E[0], E[1])
    ux = np.where(left, P * pts[:, 0] / E[0], P * GAMMA / E[0] + P * (pts[:, 0] - GAMMA) / E[1])
    exact_u = np.column_stack([ux, -nu * P * pts[:, 1] / Ex])
    s = result.fields.stress(pts, bodies)
    u = result.fields.displacement(pts, bodies)
    return np.max(np.abs(s - exact_s)) / abs(P), np.max(np.abs(u - exact_u)) / (abs(P) * LENGTH / E[1])


@pytest.mark.parametrize("clamped", [False, True], ids=["roller", "clamped"])
@pytest.mark.parametrize("degree", [1, 2])
def test_uniform_stress_at_a_supported_edge(tmp_path, degree, clamped):
    scene, nu = _bar(tmp_path, clamped)
    sigma, u = _errors(scene, nu, degree)
    assert sigma <= tol.EFGM_SUPPORT_PATCH_SIGMA, sigma
    assert u <= tol.EFGM_SUPPORT_PATCH_U, u


@pytest.mark.parametrize("degree", [1, 2])
def test_the_supported_edges_error_is_the_quadratures(tmp_path, degree):
    """Twice the points per direction: the error falls (collocation's did not:
    1.12e-2 and 3.77e-2 of P with 8 and 16 points alike)."""
    scene, nu = _bar(tmp_path, False)
    n = method.GAUSS_POINTS[degree]
    coarse, fine = (_errors(scene, nu, degree, gauss)[0] for gauss in (n, 2 * n))
    assert fine * tol.EFGM_SUPPORT_PATCH_GAIN[degree] <= coarse, (coarse, fine)
