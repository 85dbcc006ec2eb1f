"""Closed-form solutions of interface problems, usable by every method.

Each case builds its :class:`~contactcore.Scene` in code and offers the exact
solution as :class:`~contactcore.result.Fields` (displacement and stress per
body at arbitrary points), so the profiles of the exact solution are sampled
by the same code as every method's.  numpy only.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from contactcore import (BodyForce, CircleInterface, Disc, InterfaceProfile, LineInterface, LinearLaw, LineProfile,
                         Material, Pin, Pressure, Rectangle, Scene, Support, Torque, Traction)
from contactcore.elasticity import compliance, lame
from contactcore.tolerances import GEOMETRY, NITSCHE_STABILISATION, STICK_ROUNDOFF

_ROT = np.array([[0.0, -1.0], [1.0, 0.0]])  # infinitesimal rotation generator


def _tensor(voigt_strain: np.ndarray) -> np.ndarray:
    exx, eyy, gxy = voigt_strain
    return np.array([[exx, gxy / 2], [gxy / 2, eyy]])


@dataclass
class InterfacePatch:
    """Uniform stress across an inclined straight Γ with two materials.

    Both bodies carry the same uniform stress σ (so tractions balance on Γ).
    The strains ``ε± = C± σ`` differ; a piecewise-affine field with a
    constant jump exists only if the tangential strains agree (Hadamard):
    ``t·ε⁺t = t·ε⁻t``, which fixes ``σ_tt`` from ``σ_nn`` when the
    materials differ.  The jump is ``g = (σ_nn/k_N) n + (σ_nt/k_T) t``
    (traction on + is ``−σn = −(t_N n + t_T t)``), plus the rotation
    ``Δω = −n·Δε t`` that makes ``(Δε + Δω J) t = 0``.  Held by the tractions
    ``σ n_out`` on the four edges and two pins in the − body (``p`` fixed,
    and one component of ``u(q)``).  Any P1 (or higher) method must reproduce it
    to round-off.
    """

    scene: Scene
    sigma: np.ndarray
    strains: tuple[np.ndarray, np.ndarray]
    rotations: tuple[float, float]
    jump: np.ndarray
    origin: np.ndarray

    def displacement(self, points, bodies) -> np.ndarray:
        x = np.asarray(points, float)[:, :2]
        p = np.asarray(self.scene.pins[0].point)
        um = (x - p) @ (self.strains[0] + self.rotations[0] * _ROT).T
        up = um + (x - self.origin) @ (self.strains[1] - self.strains[0]
                                       + (self.rotations[1] - self.rotations[0]) * _ROT).T + self.jump
        return np.where(np.asarray(bodies)[:, None] == 1, up, um)

    def stress(self, points, bodies) -> np.ndarray:
        s = self.sigma
        return np.tile([s[0, 0], s[1, 1], s[0, 1]], (len(points), 1))


def interface_patch(angle_deg: float = 30.0, *, minus=Material(2e11, 0.3), plus=Material(7e10, 0.2),
                    kN: float = 1e12, kT: float = 5e10, sigma_nn: float = -3e6, sigma_nt: float = 1e6,
                    sigma_tt: float = 2e6, plane: str = "stress", pins=None) -> InterfacePatch:
    """The patch test on ``[0,1]²`` with Γ through the centre at ``angle_deg``
    to the x axis (``σ_tt`` is used only when the materials are equal).
    ``pins``: two points of the − body to hold (default: on a parallel to Γ;
    a method that needs pins at mesh nodes gives its own)."""
    a = np.radians(angle_deg)
    n = np.array([-np.sin(a), np.cos(a)])
    t = np.array([n[1], -n[0]])
    C = [compliance(m.E, m.nu, plane) for m in (minus, plus)]
    dc11, dc12 = C[0][0, 0] - C[1][0, 0], C[1][0, 1] - C[0][0, 1]
    if abs(dc11) > 1e-12 * C[0][0, 0]:
        sigma_tt = sigma_nn * dc12 / dc11
    Q = np.column_stack([n, t])
    sigma = Q @ np.array([[sigma_nn, sigma_nt], [sigma_nt, sigma_tt]]) @ Q.T
    voigt = np.array([sigma[0, 0], sigma[1, 1], sigma[0, 1]])
    eps = tuple(_tensor(c @ voigt) for c in C)
    d_eps = eps[1] - eps[0]
    origin = np.array([0.5, 0.5])
    # both pins in the − body, on a parallel to Γ; q fixes the component
    # along which q − p is the longer, which determines the rotation
    p, q = (origin - 0.3 * n - 0.2 * t, origin - 0.3 * n + 0.2 * t) if pins is None else map(np.asarray, pins)
    if max(n @ (p - origin), n @ (q - origin)) > -GEOMETRY:
        raise ValueError("interface_patch: both pins must lie in the − body, off Γ")
    d, ed = q - p, eps[0] @ (q - p)
    q_fix = "y" if abs(d[0]) >= abs(d[1]) else "x"
    w_minus = -ed[1] / d[0] if q_fix == "y" else ed[0] / d[1]
    w_plus = w_minus - n @ d_eps @ t
    edges = {"left": (-1, 0), "right": (1, 0), "bottom": (0, -1), "top": (0, 1)}
    scene = Scene(
        name=f"patch{angle_deg:g}", title="interface patch test", plane=plane,
        domain=Rectangle((0.0, 0.0), (1.0, 1.0)), interface=LineInterface(tuple(origin), tuple(n)),
        materials={"minus": minus, "plus": plus}, law=LinearLaw(kN, kT),
        loads=tuple(Traction(e, tuple(sigma @ np.array(v, float))) for e, v in edges.items()),
        pins=(Pin(tuple(p), "xy"), Pin(tuple(q), q_fix)),
    ).validated()
    return InterfacePatch(scene, sigma, eps, (w_minus, w_plus), (sigma_nn / kN) * n + (sigma_nt / kT) * t, origin)


@dataclass
class PressurisedRod:
    """A disc of radius ``b`` under outer pressure ``p``, with a rod of radius
    ``a`` bonded by normal springs ``k_N`` (a normal jump on a curved Γ).

    Lamé: ``u_r = A r`` in the rod, ``u_r = B r + C/r`` around it, with
    ``σ_rr = 2(λ+μ)A`` (rod) and ``σ_rr = 2(λ+μ)B − 2μC/r²``,
    ``σ_θθ = 2(λ+μ)B + 2μC/r²`` (annulus).  The three conditions are the
    radial traction balance on Γ, the spring ``σ_rr(a) = k_N (u_r⁺ − u_r⁻)``
    (the traction on + is ``−σ_rr n = −t_N n``) and ``σ_rr(b) = −p``.  No
    tangential jump: ``k_T`` plays no role.  Pins at the centre (x, y) and at
    ``(a/2, 0)`` (y) remove rigid modes without disturbing the solution.
    """

    scene: Scene
    coeffs: np.ndarray  # A, B, C
    lames: tuple[tuple[float, float], tuple[float, float]]

    def _radial(self, r, bodies):
        A, B, C = self.coeffs
        (lm, mm), (lp, mp) = self.lames
        rod = np.asarray(bodies) == 0
        ur = np.where(rod, A * r, B * r + C / r)
        srr = np.where(rod, 2 * (lm + mm) * A, 2 * (lp + mp) * B - 2 * mp * C / r ** 2)
        stt = np.where(rod, 2 * (lm + mm) * A, 2 * (lp + mp) * B + 2 * mp * C / r ** 2)
        return ur, srr, stt

    def displacement(self, points, bodies) -> np.ndarray:
        x = np.asarray(points, float)[:, :2]
        r = np.maximum(np.hypot(x[:, 0], x[:, 1]), 1e-300)
        ur, _, _ = self._radial(r, bodies)
        return x * (ur / r)[:, None]

    def stress(self, points, bodies) -> np.ndarray:
        x = np.asarray(points, float)[:, :2]
        r = np.maximum(np.hypot(x[:, 0], x[:, 1]), 1e-300)
        c, s = x[:, 0] / r, x[:, 1] / r
        _, srr, stt = self._radial(r, bodies)
        return np.column_stack([srr * c * c + stt * s * s, srr * s * s + stt * c * c, (srr - stt) * c * s])


def pressurised_rod(*, a: float = 0.4, b: float = 1.0, p: float = 1e6, kN: float = 1e11, kT: float = 1e10,
                    rod=Material(2e11, 0.3), matrix=Material(7e10, 0.25), plane: str = "stress") -> PressurisedRod:
    """The closed form of :class:`PressurisedRod` and its scene."""
    (lm, mm), (lp, mp) = lame(rod.E, rod.nu, plane), lame(matrix.E, matrix.nu, plane)
    M = np.array([
        [2 * (lm + mm), -2 * (lp + mp), 2 * mp / a ** 2],                 # σ_rr continuous on Γ
        [kN * a, 2 * (lp + mp) - kN * a, -2 * mp / a ** 2 - kN / a],       # σ_rr(a) = k_N [[u_r]]
        [0.0, 2 * (lp + mp), -2 * mp / b ** 2],                           # σ_rr(b) = −p
    ])
    coeffs = np.linalg.solve(M, np.array([0.0, 0.0, -p]))
    scene = Scene(
        name="pressurised_rod", title="rod in a pressurised disc (normal jump on a circle)", plane=plane,
        domain=Disc((0.0, 0.0), b), interface=CircleInterface((0.0, 0.0), a),
        materials={"minus": rod, "plus": matrix}, law=LinearLaw(kN, kT),
        loads=(Pressure("outer", p),), pins=(Pin((0.0, 0.0), "xy"), Pin((a / 2, 0.0), "y")),
        profiles=(LineProfile("radial", (0.0, 0.0), (b, 0.0), ("sxx", "syy", "ux")),),
    ).validated()
    return PressurisedRod(scene, coeffs, ((lm, mm), (lp, mp)))


@dataclass
class TwistedRod:
    """A rod of radius ``a`` twisted by a torque ``T`` inside a disc of radius
    ``b`` clamped on its rim, bonded by tangential springs ``k_T`` (a
    tangential jump on a curved Γ; scene B's load on a disc).

    Only ``u_θ(r)`` is non-zero and ``σ_rθ = μ(u_θ' − u_θ/r)`` the only
    stress (polar coordinates).  The rod carries scene B's body force
    ``b_θ = (T/J) r``, ``J = πa⁴/2``, so ``dσ_rθ/dr + 2σ_rθ/r + b_θ = 0``
    gives ``u_θ = A r + D r³`` with ``D = −T/(8 μ⁻ J)``; around it
    ``u_θ = B r + C/r``, ``σ_rθ = −2μ⁺C/r²``.  Shear balance on Γ fixes C,
    the clamp ``u_θ(b) = 0`` fixes B, and the spring fixes the rod's rigid
    rotation A: with ``n = e_r``, ``t = −e_θ`` (docs/scenes.md) the traction on +
    is ``−t_T t = t_T e_θ = −σ_rθ e_θ``, so ``σ_rθ(a) = k_T [[u_θ]]``.  The
    exact t_N is zero and the mean of t_T is ``T/(2πa²)``.
    """

    scene: Scene
    coeffs: np.ndarray  # A, D (rod), B, C (annulus)
    shear: tuple[float, float]  # μ⁻, μ⁺

    def _polar(self, x, bodies):
        A, D, B, C = self.coeffs
        r = np.maximum(np.hypot(x[:, 0], x[:, 1]), 1e-300)
        rod = np.asarray(bodies) == 0
        ut = np.where(rod, A * r + D * r ** 3, B * r + C / r)
        srt = np.where(rod, 2 * self.shear[0] * D * r ** 2, -2 * self.shear[1] * C / r ** 2)
        return r, ut, srt

    def displacement(self, points, bodies) -> np.ndarray:
        x = np.asarray(points, float)[:, :2]
        r, ut, _ = self._polar(x, bodies)
        return np.column_stack([-x[:, 1], x[:, 0]]) * (ut / r)[:, None]

    def stress(self, points, bodies) -> np.ndarray:
        x = np.asarray(points, float)[:, :2]
        r, _, srt = self._polar(x, bodies)
        c, s = x[:, 0] / r, x[:, 1] / r
        return np.column_stack([-2 * s * c * srt, 2 * s * c * srt, (c * c - s * s) * srt])


def twisted_rod(*, a: float = 0.4, b: float = 1.0, torque: float = 1e4, kN: float = 1e12, kT: float = 1e10,
                rod=Material(2e11, 0.3), matrix=Material(2e10, 0.2), plane: str = "stress") -> TwistedRod:
    """The closed form of :class:`TwistedRod` and its scene (scene B's
    materials and springs, a clamped circular rim)."""
    mm, mp = lame(rod.E, rod.nu, plane)[1], lame(matrix.E, matrix.nu, plane)[1]
    D = -torque / (8 * mm * np.pi * a ** 4 / 2)
    C = -mm * D * a ** 4 / mp
    B = -C / b ** 2
    A = (B * a + C / a - D * a ** 3 - 2 * mm * D * a ** 2 / kT) / a
    scene = Scene(
        name="twisted_rod", title="rod twisted in a clamped disc (tangential jump on a circle)", plane=plane,
        domain=Disc((0.0, 0.0), b), interface=CircleInterface((0.0, 0.0), a),
        materials={"minus": rod, "plus": matrix}, law=LinearLaw(kN, kT),
        supports=(Support("outer", "xy"),), loads=(Torque("minus", torque),),
        profiles=(InterfaceProfile("gamma", ("tN", "tT", "gT")),),
    ).validated()
    return TwistedRod(scene, np.array([A, D, B, C]), (mm, mp))


@dataclass
class QuadraticLayers:
    """Two layers whose displacement is quadratic in each (a test that
    degree 2 reproduces a quadratic field).

    On ``[0, 1]²`` with Γ at ``y = y_Γ`` (n = e_y, − below), one component
    ``j`` of u depends on y alone: the shear ``u = (w(y), 0)`` held by
    rollers ``u_y = 0`` on the sides, or the stretch ``u = (0, w(y))`` held
    by rollers ``u_x = 0``.  With the modulus ``M = μ`` (shear) or
    ``E/(1 − ν²)`` (stretch, plane stress with ε_xx = 0), equilibrium is
    ``(M w′)′ + b = 0`` with a constant body force ``b±`` in each layer, so
    ``M w′`` is linear and w quadratic.  The bottom is clamped, the top
    carries the traction τ in component j, and on Γ the stress ``s = M w′``
    is continuous and carried by the spring: ``s = k [[w]]`` (``k = k_T`` or
    ``k_N``; the + layer's traction is ``−s e_j = −(t_N n + t_T t)``)::

        M⁺ w⁺′(y) = τ + b⁺ (1 − y),     M⁻ w⁻′(y) = s + b⁻ (y_Γ − y),
        s = τ + b⁺ (1 − y_Γ),   w⁻(0) = 0,   w⁺(y_Γ) = w⁻(y_Γ) + s/k.

    Every method of degree ≥ 2 holds it exactly (EFGM to its quadrature).
    """

    scene: Scene
    component: int
    moduli: tuple[float, float]
    body: tuple[float, float]
    traction: float
    spring: float
    y_gamma: float

    def _profile(self, y, bodies):
        """``w`` and ``M w′`` at heights y for the given bodies."""
        (Mm, Mp), (bm, bp), tau, yg = self.moduli, self.body, self.traction, self.y_gamma
        s = tau + bp * (1 - yg)
        wm = (s * y + bm * (yg * y - y * y / 2)) / Mm
        w_gamma = (s * yg + bm * yg * yg / 2) / Mm + s / self.spring
        wp = w_gamma + (tau * (y - yg) + bp * ((y - yg) - (y * y - yg * yg) / 2)) / Mp
        plus = np.asarray(bodies) == 1
        return np.where(plus, wp, wm), np.where(plus, tau + bp * (1 - y), s + bm * (yg - y))

    def displacement(self, points, bodies) -> np.ndarray:
        w, _ = self._profile(np.asarray(points, float)[:, 1], bodies)
        out = np.zeros((len(w), 2))
        out[:, self.component] = w
        return out

    def stress(self, points, bodies) -> np.ndarray:
        _, s = self._profile(np.asarray(points, float)[:, 1], bodies)
        if self.component == 0:
            return np.column_stack([0 * s, 0 * s, s])
        nu = np.where(np.asarray(bodies) == 1, self.scene.materials["plus"].nu, self.scene.materials["minus"].nu)
        return np.column_stack([nu * s, s, 0 * s])


def quadratic_layers(kind: str = "shear", *, y_gamma: float = 0.53, minus=Material(2e11, 0.3),
                     plus=Material(7e10, 0.2), kN: float = 1e12, kT: float = 5e10, traction: float = 1e6,
                     body_force: tuple[float, float] = (4e6, -3e6)) -> QuadraticLayers:
    """The closed form of :class:`QuadraticLayers` ("shear" or "stretch")
    and its scene; ``body_force`` is (b⁻, b⁺) in the moving component."""
    j = {"shear": 0, "stretch": 1}[kind]
    moduli = tuple(m.E / (2 * (1 + m.nu)) if j == 0 else m.E / (1 - m.nu ** 2) for m in (minus, plus))
    value = lambda v: (v, 0.0) if j == 0 else (0.0, v)  # noqa: E731
    roller = "y" if j == 0 else "x"
    scene = Scene(
        name=f"quadratic_{kind}", title=f"two layers, quadratic {kind} in each", plane="stress",
        domain=Rectangle((0.0, 0.0), (1.0, 1.0)), interface=LineInterface((0.0, y_gamma), (0.0, 1.0)),
        materials={"minus": minus, "plus": plus}, law=LinearLaw(kN, kT),
        supports=(Support("bottom", "xy"), Support("left", roller), Support("right", roller)),
        loads=(Traction("top", value(traction)), BodyForce("minus", value(body_force[0])),
               BodyForce("plus", value(body_force[1]))),
    ).validated()
    return QuadraticLayers(scene, j, moduli, body_force, traction, kT if j == 0 else kN, y_gamma)


@dataclass
class LayerState:
    """The exact state of the layered block at one increment."""

    p: float  # contact pressure (Pa)
    delta: float  # prescribed u_x of the top edge (m)
    tau: float  # σ_xy everywhere = t_T on Γ (Pa)
    slip: float  # accumulated slip s (m)
    status: str  # "stick" or "slip"


@dataclass
class LayeredSlipFields:
    """Displacement and stress of the layered block in one state: with ν = 0
    every field is uniform in x, σ = (0, −p, τ),
    ``u = (τ y/G₋, −p y/E₋)`` below Γ (y < h₁) and above it
    ``u = (τ h₁/G₋ + g_T + τ (y − h₁)/G₊, −p h₁/E₋ + g_N − p (y − h₁)/E₊)``,
    ``g_N = −p/k_N``, ``g_T = τ/k_T + s``."""

    case: "LayeredSlip"
    state: LayerState

    def displacement(self, points, bodies) -> np.ndarray:
        c, st = self.case, self.state
        y = np.asarray(points, float)[:, 1] - c.y0
        gN, gT = -st.p / c.kN, st.tau / c.kT + st.slip
        below = np.column_stack([st.tau * y / c.G[0], -st.p * y / c.E[0]])
        above = np.column_stack([st.tau * c.h1 / c.G[0] + gT + st.tau * (y - c.h1) / c.G[1],
                                 -st.p * c.h1 / c.E[0] + gN - st.p * (y - c.h1) / c.E[1]])
        return np.where((np.asarray(bodies) == 0)[:, None], below, above)

    def stress(self, points, bodies) -> np.ndarray:
        return np.tile([0.0, -self.state.p, self.state.tau], (len(points), 1))


class LayeredSlip:
    """Friction in closed form: the built-in scene ``layered-slip``
    (two layers, ν = 0, pressed by p, then sheared by a prescribed top
    displacement δ to and fro; its TOML file explains the inputs), with its
    coulomb law or any frictional law that can open (the law's
    ``slip_bound``, contactcore.laws' module doc).

    One interface point stands for the whole of Γ: the layers and the
    tangential spring act in series with compliance
    ``C = h₁/G₋ + h₂/G₊ + 1/k_T``, so the trial shear is ``τ* = (δ − s)/C``;
    the point sticks while ``|τ*| <= b(p)``, the law's slip bound at
    ``t_N = −p`` (Coulomb's ``μp``), otherwise ``τ = b(p) sign τ*`` and
    ``s = δ − τ C`` (the return map of the coulomb law, docs/scenes.md).
    """

    def __init__(self, scene: Scene):
        law, itf, dom = scene.law, scene.interface, scene.domain
        if not (law.frictional and law.unilateral) or any(m.nu != 0 for m in scene.materials.values()):
            raise ValueError("the layered closed form needs a frictional law that can open (as coulomb) and ν = 0 "
                             "in both layers")
        # enforced exactly, the springs are infinitely stiff: g_N = 0, g_T = s
        self.kN, self.kT = getattr(law, "kN", np.inf), getattr(law, "kT", np.inf)
        self.scene, self.law, self.mu = scene, law, getattr(law, "mu", None)  # mu: Coulomb's (None for another law)
        self.y0 = dom.corner[1]
        self.h1, self.h2 = itf.point[1] - self.y0, dom.corner[1] + dom.size[1] - itf.point[1]
        self.E = [scene.materials[b].E for b in ("minus", "plus")]
        self.G = [E / 2 for E in self.E]
        self.compliance = self.h1 / self.G[0] + self.h2 / self.G[1] + 1 / self.kT

    def history(self) -> list[LayerState]:
        """The state after every increment 1 … n."""
        scene, s, states = self.scene, 0.0, []
        pressure, top = scene.loads[0], scene.supports[1]
        for k in range(1, scene.increments + 1):
            loads, supports = scene.factors(k)
            p, delta = -loads[0] * pressure.value[1], supports[1] * top.value[0]
            trial = (delta - s) / self.compliance
            limit = self.limit(p)
            if abs(trial) <= limit * (1 + STICK_ROUNDOFF):
                states.append(LayerState(p, delta, trial, s, "stick"))
            else:
                tau = limit * np.sign(trial)
                s = delta - tau * self.compliance
                states.append(LayerState(p, delta, tau, s, "slip"))
        return states

    def limit(self, p: float) -> float:
        """The slip limit at the pressure ``p``: the law's slip bound at
        ``t_N = −p`` (Coulomb's ``μp``)."""
        return float(np.asarray(self.law.slip_bound(np.array([-p])), float).reshape(-1)[0])

    def fields(self, state: LayerState) -> LayeredSlipFields:
        return LayeredSlipFields(self, state)


def layered_slip(kN: float | None = None, kT: float | None = None, E: tuple[float, float] | None = None,
                 exact: bool = False) -> LayeredSlip:
    """The closed form of the built-in scene ``layered-slip``; with other
    springs, or other Young's moduli ``E`` (of the − and + layers), or the
    law enforced ``exact``-ly (no spring: ``C = h₁/G₋ + h₂/G₊``), the
    top's displacement is rescaled so that its path still switches between
    stick and slip at the same increments (δ_stick = μpC): τ's path, and with
    it the scene's side tractions, stay the closed form's."""
    from contactcore import load_scene
    from contactcore.exact import ExactCoulomb
    from contactcore.laws import CoulombLaw

    case = LayeredSlip(load_scene("layered-slip"))
    if kN is None and kT is None and E is None and not exact:
        return case
    scene, law = case.scene, case.scene.law
    law = ExactCoulomb(mu=law.mu, stabilisation=NITSCHE_STABILISATION) if exact else CoulombLaw(
        kN or law.kN, kT or law.kT, law.mu)
    materials = scene.materials if E is None else {
        body: dataclasses.replace(scene.materials[body], E=value) for body, value in zip(("minus", "plus"), E)}
    G = [materials[body].E / 2 for body in ("minus", "plus")]
    top = scene.supports[1]
    p = -scene.loads[0].value[1]
    stick = law.mu * p * (case.h1 / G[0] + case.h2 / G[1] + 1 / getattr(law, "kT", np.inf))
    supports = (scene.supports[0], dataclasses.replace(top, value=(stick, 0.0)))
    return LayeredSlip(scene.with_changes(law=law, materials=materials, supports=supports))
