"""The stability suite records the worst error of each family and prints a summary at the end of the run."""


import pytest
import sizes

WORST = {}


@pytest.fixture
def slow_scale():
    """Size factor of the `slow` tests (tests/sizes.py: ORBITS_SLOW_SCALE, 0.05 when unset, 1 = full size)."""
    return sizes.slow_scale()


@pytest.fixture
def record():
    """record(family, cases, worst, unit): keep the worst error seen for a family of checks."""

    def keep(family, cases, worst, unit):
        old = WORST.get(family, (0, 0.0, unit))
        WORST[family] = (old[0] + cases, max(old[1], worst), unit)

    return keep


def pytest_terminal_summary(terminalreporter):
    if not WORST:
        return
    terminalreporter.section("stability suite: worst error per family")
    for family, (cases, worst, unit) in sorted(WORST.items()):
        terminalreporter.write_line(f"{family:55s} {cases:9d} cases   worst {worst:.3g} {unit}")
