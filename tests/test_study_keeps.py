"""A study keeps a built system only while a later case can reuse it
(review6's fault 1: a serial fe P2 study of four h values held the three
systems before beside the one it solved, 822 MB against 379 MB for one)."""
from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

from contactcore import load_scene
from contactcore.discretisation import Resolution, Reuse, Timings
from verification import study


def _kept_after_each(monkeypatch, points, method="efgm"):
    monkeypatch.setattr(study, "_REUSE", Reuse())
    cases = study.shared([study.Case("A", point, method, 1, 0.2, None) for point in points])
    kept = []
    try:
        for case in cases:
            row = study.solve_case(case)
            assert row["status"] != "failed", row
            kept.append(len(study._REUSE))
    finally:
        study._REUSE.close()
    return [c.keep for c in cases], kept


def test_a_study_of_h_keeps_no_system(monkeypatch):
    keep, kept = _kept_after_each(monkeypatch, [(("h", 0.2),), (("h", 0.25),), (("h", 0.3),)])
    assert keep == [False, False, False] and kept == [0, 0, 0]


def test_a_study_of_the_law_keeps_its_system_until_its_last_case(monkeypatch):
    points = [(("h", h), ("kN", k)) for h in (0.2, 0.25) for k in (1e9, 1e10)]
    keep, kept = _kept_after_each(monkeypatch, points)
    assert keep == [True, False, True, False] and kept == [1, 0, 1, 0]


@dataclass
class _Counting:
    """A discretisation (no options) whose build records how many systems are open then."""

    def __post_init__(self):
        self.open, self.seen = [], []

    def build(self, scene, resolution, timings):
        self.seen.append(len(self.open))
        system = SimpleNamespace(close=lambda: self.open.remove(system))
        self.open.append(system)
        return SimpleNamespace(system=system)


def test_reuse_makes_room_before_it_builds():
    """A full Reuse releases the system used longest ago before the new
    one is built, not after: never ``size`` kept beside the one building;
    with ``keep`` False a new system is not kept at all."""
    scene, counting, reuse = load_scene("A"), _Counting(), Reuse(size=2)
    for h in (0.1, 0.2, 0.3, 0.4):
        reuse.build(scene, counting, Resolution(h), Timings())
    assert counting.seen == [0, 1, 1, 1] and len(reuse) == 2 == len(counting.open)
    reuse.keep = False
    built = reuse.build(scene, counting, Resolution(0.5), Timings())
    assert counting.seen[-1] == 2 and len(reuse) == 2 and not reuse.owns(built)
    built.system.close()  # as the solve does with a system its Reuse does not own
    reuse.close()
    assert not counting.open
