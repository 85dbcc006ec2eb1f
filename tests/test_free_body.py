"""A body held by nothing but a unilateral Γ (tests/free_disc.py: a stiff
disc in scene C's plate).  Pulled away from, Γ opens all round and the
disc's position is not determined: every method refuses in one line that
says so, decided by Newton's status map (contactcore.health.check_held),
never by whether a factorisation finds a null pivot.  Pressed, Γ closes
all round and holds it: every method solves, exact and penalty, with the
same contact pressure.  On springs that carry tension (``linear``) the
pulled disc is held and solves too."""
import functools

import numpy as np
import pytest

import free_disc
import registered
import tolerances as tol
from contactcore import health
from contactcore.geometry import tangent_of
from contactcore.laws import OPEN, STICK
from contactcore.scene_files import scene_toml
from verification import methods
from verification.__main__ import main

#: Every registered method (tests/registered.py): one that refuses the disc
#: (a circular Γ) by its documented check is skipped by name and reason.
METHODS = registered.names()

#: Coarse enough for a fraction of a second per solve; h = 0.055 is where
#: xfem P1 once returned the pulled disc at a position set by round-off.
H = 0.1

#: The refusal's words, after "scene NAME: increment 1 of 1: ".
REFUSAL = (r"body − can [^:]+ \(3 rigid-body modes are free\): no support or pin holds it that way and Γ is open at every "
           r"point, so its position is not determined; hold it with a support or pin, or with springs that carry "
           r"tension \(type = \"linear\"\)$")


def _skip_unless_solvable(method: str, pulled: bool, law: str = "exact", h: float = H, degree: int = 1) -> None:
    registered.skip_unless_solvable(free_disc.disc(pulled, law), registered.options(method, degree), h,
                                    what="the free disc (a circular Γ)")


@functools.lru_cache(maxsize=None)
def _solved(method: str, pulled: bool, law: str, h: float = H, degree: int = 1):
    _skip_unless_solvable(method, pulled, law, h, degree)
    return methods.solver(method)(free_disc.disc(pulled, law), h, degree=degree)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("law, h, degree", [("exact", H, 1), ("penalty", H, 1), ("exact", 2 * H, 2)])
def test_a_disc_pulled_away_from_is_refused_in_one_line(method, law, h, degree):
    scene = free_disc.disc(True, law)
    _skip_unless_solvable(method, True, law, h, degree)
    with pytest.raises(health.FreeBody) as caught:
        methods.solver(method)(scene, h, degree=degree)
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith(f"scene {scene.name}: increment 1 of 1: ")
    assert caught.match(REFUSAL)


def test_the_disc_xfem_once_placed_by_round_off_is_refused():
    with pytest.raises(health.FreeBody, match=REFUSAL):
        methods.solver("xfem")(free_disc.disc(True), 0.055)


@pytest.mark.parametrize("method", METHODS)
def test_a_disc_pulled_on_springs_that_carry_tension_solves(method):
    """The same pull held by ``linear`` springs: the disc is stretched
    (tension at its centre) and every point of Γ carries tension."""
    result = _solved(method, True, "linear")
    assert np.all(result.interface.final.traction[:, 0] > 0)
    stress = result.fields.stress(np.array([free_disc.disc(True, "linear").interface.centre]), np.zeros(1, int))[0]
    assert stress[0] > 0 and stress[1] > 0


def _resultant(scene, result) -> tuple[np.ndarray, float]:
    """The force Γ's tractions exert on the disc, ``Σ w (t_N n + t_T t)``,
    and the scale ``Σ w |t|``."""
    itf = result.interface
    points, weights, t = np.asarray(itf.points), np.asarray(itf.weights), itf.final.traction
    n = scene.interface.normals(points)
    force = (weights[:, None] * (t[:, :1] * n + t[:, 1:] * tangent_of(n))).sum(axis=0)
    return force, float(np.sum(weights * np.hypot(t[:, 0], t[:, 1])))


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("law", ["exact", "penalty"])
def test_a_disc_pressed_into_its_plate_solves(method, law):
    """Γ closes all round (every point sticks, in compression) and its
    tractions hold the unloaded disc in balance."""
    result = _solved(method, False, law)
    final = result.interface.final
    assert np.all(final.status == STICK) and np.all(final.traction[:, 0] < 0)
    force, scale = _resultant(free_disc.disc(False, law), result)
    assert np.linalg.norm(force) <= tol.PRESSED_DISC_BALANCE * scale


@pytest.mark.parametrize("law", ["exact", "penalty"])
def test_the_pressed_disc_carries_the_same_pressure_in_every_method(law):
    means = []
    for method in [m for m in METHODS if m in registered.SOLVE_EVERY_SHAPE
                   or registered.refusal(free_disc.disc(False, law), registered.options(m), H) is None]:
        itf = _solved(method, False, law).interface
        means.append(-np.sum(itf.weights * itf.final.traction[:, 0]) / np.sum(itf.weights))
    assert np.ptp(means) <= tol.PRESSED_DISC_AGREE * np.mean(means), means


def _points(count: int) -> tuple[np.ndarray, np.ndarray]:
    """``count`` points evenly round the disc's Γ and equal weights."""
    scene = free_disc.disc(True)
    angle = 2 * np.pi * np.arange(count) / count
    points = np.asarray(scene.interface.centre) + scene.interface.radius * np.column_stack([np.cos(angle),
                                                                                            np.sin(angle)])
    return points, np.full(count, 2 * np.pi * scene.interface.radius / count)


@pytest.mark.parametrize("law", ["exact", "penalty"])
def test_a_status_map_lets_the_disc_go_by_its_closed_points(law):
    """Every point open: the disc's three modes are free; one closed
    point: it turns about it; two far apart: it is held.  The plate's
    support holds the plate throughout.  Read from the map alone."""
    scene = free_disc.disc(True, law)
    points, weights = _points(12)
    status = np.full(12, OPEN, np.int8)
    assert health.lets_go(scene, points, weights, status)
    status[0] = STICK
    assert health.lets_go(scene, points, weights, status)
    with pytest.raises(health.FreeBody, match=r"^here: body − can rotate: no support or pin holds it that way and only 1 of "
                                              r"12 points of Γ stay closed"):
        health.check_held(scene, points, weights, status, "here")
    status[6] = STICK
    assert not health.lets_go(scene, points, weights, status)
    health.check_held(scene, points, weights, status, "here")


def test_the_cli_refuses_the_pulled_disc_in_one_line(tmp_path, capsys):
    path = tmp_path / "pulled.toml"
    path.write_text(scene_toml(free_disc.disc(True)))
    assert main(["run", str(path), "--method", "fe", "--h", str(H), "--no-plots", "--quiet",
                 "--out", str(tmp_path / "out")]) == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: scene disc-pulled-exact: increment 1 of 1: body − can")
    assert not (tmp_path / "out").exists()


@pytest.mark.slow
@pytest.mark.parametrize("method", METHODS)
def test_two_ranks_refuse_the_pulled_disc_as_one_does_and_solve_the_pressed_one(method, tmp_path):
    """Under mpirun -n 2: the serial refusal's line, and the pressed disc's
    serial profiles and interface history (tests/test_mpi.py's parity)."""
    from test_mpi import _errors, _parity, mpirun
    _skip_unless_solvable(method, True)
    pulled = tmp_path / "pulled.toml"
    pulled.write_text(scene_toml(free_disc.disc(True)))
    args = ["run", pulled, "--method", method, "--h", H, "--no-plots", "--out", tmp_path / "o"]
    out = mpirun(2, "-m", "verification", *args, timeout=120)
    with pytest.raises(health.FreeBody) as serial:
        methods.solver(method)(free_disc.disc(True), H)
    assert out.returncode == 2 and set(_errors(out)) == {f"error: {serial.value}"}, out.stderr
    pressed = tmp_path / "pressed.toml"
    pressed.write_text(scene_toml(free_disc.disc(False)))
    _parity(tmp_path, pressed, 2, 1, H, methods=(method,))
