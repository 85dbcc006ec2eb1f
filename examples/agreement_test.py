"""A three-method agreement test
===============================

Do fe, xfem and efgm tell the same story on a scene of your own?  This is
the pytest check an engineer writes for that, with the public helper
:func:`verification.agreement.assert_methods_agree`: it solves the scene
with each method and with a reference (fe at degree 2 by default), samples
every profile, and fails with the method, profile, quantity and sample
that differ most.  Samples next to the domain's corners and the ends of Γ
are left out: the exact stresses are singular there.

Run it as a test (``.venv/bin/python -m pytest examples/agreement_test.py``)
or as a script, which prints the whole agreement table.
"""
from pathlib import Path

from contactcore import load_scene
from verification.agreement import assert_methods_agree, compare

HERE = Path(__file__).resolve().parent

#: The methods compared with the reference, fe at degree 2.
METHODS = ["xfem:2", "efgm:2"]
#: The resolution of every method: None takes the scene's own (h = 0.05).
H = None
#: The agreement asked for: 5 % of each profile's largest value, at the
#: worst sample (degree 2 on the wedge agrees far better at h = 0.05).
RTOL = 0.05


def test_the_three_methods_agree_on_the_wedge():
    assert_methods_agree(load_scene(HERE / "wedge.toml"), METHODS, H, rtol=RTOL)


def main(h=H):
    table = compare(load_scene(HERE / "wedge.toml"), METHODS, h)
    print(table.markdown())
    worst = table.worst()
    print("worst:", worst.describe(table.reference))
    return table


if __name__ == "__main__":
    main()
