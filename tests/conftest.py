"""Shared test setup: floating-point exceptions raise, heyoka compiles into a temporary cache, sweeps draw fresh
seeds."""

import os

import numpy as np
import pytest
import seeds
from hypothesis import settings

settings.register_profile("ci", max_examples=200, derandomize=True, deadline=None)
settings.register_profile("thorough", max_examples=5000, derandomize=False, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(params=["numpy", "compiled"])
def path(request):
    """Run a test on the NumPy specification and on the compiled kernel (every batch size), restoring the mode."""
    if request.param == "compiled":
        pytest.importorskip("numba")
    from orbits.core import _fast

    previous = _fast.set_enabled(request.param == "compiled")
    yield request.param
    _fast.set_enabled(previous)


@pytest.fixture
def fresh_seed(request) -> int:
    """A new seed each run (tests/seeds.py: ORBITS_TEST_SEED replays one)."""
    return seeds.draw(request.node.nodeid)


def pytest_terminal_summary(terminalreporter):
    if seeds.DRAWN:
        terminalreporter.section("fresh seeds (ORBITS_TEST_SEED=N replays one)")
        for who, seed in sorted(seeds.DRAWN.items()):
            terminalreporter.write_line(f"{seed:>20d}  {who}")


@pytest.fixture(autouse=True)
def _floating_point_errors_raise():
    """Overflow, division by zero and invalid operations are bugs unless the code handles them (underflow to
    subnormals or zero is legitimate)."""
    with np.errstate(over="raise", divide="raise", invalid="raise", under="ignore"):
        yield


@pytest.fixture(autouse=True, scope="session")
def _heyoka_cache(tmp_path_factory):
    os.environ["HEYOKA_CACHE_DIR"] = str(tmp_path_factory.mktemp("heyoka-cache"))
    yield


@pytest.fixture(autouse=True)
def _close_figures():
    """Close the figures a test leaves open (pyplot keeps every one), so that later tests, and the commands they
    run in this process, never see matplotlib's too-many-figures warning (which the commands treat as an error)."""
    yield
    import sys

    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")


@pytest.fixture(scope="session")
def em():
    """The Earth-Moon restricted three-body problem, shared by the periodic-orbit tests."""
    from orbits import RestrictedThreeBody

    return RestrictedThreeBody.from_primaries("Earth", "Moon")


@pytest.fixture(scope="session")
def se():
    """The Sun-Earth restricted three-body problem, shared by the periodic-orbit tests."""
    from orbits import RestrictedThreeBody

    return RestrictedThreeBody.from_primaries("Sun", "Earth")
