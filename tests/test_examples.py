"""Every script of examples/ runs, at a coarse h, and prints and returns what
its text says.  Each is imported from its file, as a reader would run it."""
import importlib.util
import re
from pathlib import Path

import numpy as np

import tolerances as tol
from contactcore.tolerances import STICK_ROUNDOFF

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
#: Coarse enough for a second or two per example, fine enough to resolve Γ.
H = 0.1
#: The error estimate's example at the wedge's own h (0.05 → 0.025): at 0.1
#: fe P1's gap estimate is pre-asymptotic (effectivity 0.51 for gT,
#: measured 2026-11-26), at 0.05 it is 0.83-1.19 (docs/error-estimates.md).
ESTIMATE_H = 0.05


def example(name: str):
    """The example script ``name`` imported as a module."""
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_example_is_tested():
    assert {p.stem for p in EXAMPLES.glob("*.py")} == {
        "scene_from_toml", "scene_in_python", "coulomb_wedge", "agreement_test", "read_vtu_fields",
        "two_parameter_study", "exact_contact", "error_estimate"}


def test_the_examples_page_lists_every_script():
    """examples/README.md's table is the examples' index: a row a script,
    linked by its file name, and no row for a script that is gone."""
    listed = set(re.findall(r"^\| \[(\w+\.py)\]\(\1\) \|", (EXAMPLES / "README.md").read_text(), re.MULTILINE))
    assert listed == {p.name for p in EXAMPLES.glob("*.py")}


def test_scene_from_toml(capsys):
    out = example("scene_from_toml").main(h=H)
    printed = capsys.readouterr().out
    assert "scene wedge: A block pressed onto an inclined plane" in printed
    assert "Γ closed everywhere: True" in printed
    assert np.all(out["tN"] < 0)
    assert abs(out["mean_tN"] / out["estimate"] - 1) <= tol.EXAMPLE_WEDGE_ESTIMATE


def test_scene_in_python(capsys):
    out = example("scene_in_python").main(h=H)
    printed = capsys.readouterr().out
    assert "largest tension anywhere: 0 Pa" in printed
    opened = out["gN"] > 0
    assert opened.any() and not opened.all()
    assert np.all(out["tN"][opened] == 0.0) and np.all(out["tN"] <= 0.0)   # the unilateral law: no tension
    assert opened[out["side"]].sum() > opened[~out["side"]].sum()           # Γ opens at the rod's sides
    assert abs(out["resultant"] / -1e6 - 1) <= tol.EXAMPLE_SECTION_BALANCE


def test_coulomb_wedge(capsys):
    module = example("coulomb_wedge")
    rows = module.main(h=H)
    printed = capsys.readouterr().out
    answered = [mu for mu in module.FRICTION if rows[mu] is not None]
    assert rows[min(module.FRICTION)] is None and "refused: scene wedge: increment 1 of" in printed
    for mu in answered:
        row = rows[mu]
        assert np.all(np.abs(row["tT"]) <= mu * -row["tN"] * (1 + STICK_ROUNDOFF))
        assert row["counts"]["open"] == 0
    slips = [rows[mu]["counts"]["slip"] for mu in sorted(answered, reverse=True)]
    assert slips[0] == 0 and slips == sorted(slips) and slips[-1] > 0   # less friction, more slip


def test_agreement_test(capsys, monkeypatch):
    module = example("agreement_test")
    monkeypatch.setattr(module, "H", H)
    module.test_the_three_methods_agree_on_the_wedge()
    table = module.main(h=H)
    printed = capsys.readouterr().out
    assert "| method | profile | quantity |" in printed and f"worst: {table.worst().method} against fe P2" in printed
    assert {a.method for a in table.rows} == {"xfem P2", "efgm P2"}
    assert table.worst().worst <= module.RTOL


def test_exact_contact(capsys):
    module = example("exact_contact")
    out = module.main(h=H)
    printed = capsys.readouterr().out
    assert "exact: t_N moves by" in printed
    exact, penalty = out["exact"], out["penalty"]
    assert max(exact["moved"].values()) <= tol.EXACT_INDEPENDENCE          # no spring decides it
    assert penalty["moved"]["tT"] > tol.EXAMPLE_PENALTY_MOVES               # the springs decide the penalty's
    for columns, counts in exact["runs"]:
        assert counts["slip"] > 0 and counts["open"] == 0
        assert np.all(np.abs(columns["tT"]) <= module.MU * -columns["tN"] * (1 + STICK_ROUNDOFF))
    soft, stiff = penalty["runs"]
    assert soft[1]["slip"] < stiff[1]["slip"]                               # soft springs stick where it slips


def test_error_estimate(capsys):
    out = example("error_estimate").main(h=ESTIMATE_H)
    printed = capsys.readouterr().out
    assert "effectivity" in printed and not out["warnings"]
    low, high = tol.EFFECTIVITY
    for q, row in out["quantities"].items():
        assert low <= row["estimated"] / row["true"] <= high, q
    assert 0.0 < out["energy"] < 1.0


def test_read_vtu_fields(capsys):
    out = example("read_vtu_fields").main(h=H)
    printed = capsys.readouterr().out
    assert out["files"] == ["interface.pvd", "interface_0000.vtu", "minus.vtu", "plus.vtu"]
    assert "minus:" in printed and "plus:" in printed
    assert out["counts"] == {"open": 0, "stick": out["counts"]["stick"], "slip": 0}
    assert abs(out["mean_tN"] / -1e5 - 1) <= tol.EXAMPLE_BALANCE


def test_two_parameter_study(capsys):
    module = example("two_parameter_study")
    rows = module.main(h=H)
    printed = capsys.readouterr().out
    assert len(rows) == len(module.RADII) * len(module.FRICTION) and "failed" not in printed
    for row in rows:
        p = -row["tN"]
        assert np.all(np.abs(row["tT"]) <= row["mu"] * np.maximum(p, 0) * (1 + STICK_ROUNDOFF))
        assert row["open"] > 0 and row["stick"] > 0
