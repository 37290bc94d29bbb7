"""Compiling the numba kernels ahead of use: `orbits info --compile`.

Under ORBITS_JIT=auto a kernel whose machine code is in the disk cache runs for a batch of any size, and an absent
one compiles only for a batch of orbits.core._fast.AUTO_MIN_BATCH elements or more, so a first query never waits
for a compile. This module compiles the absent ones now, each through the solver that starts it on a one-element
input (the same argument types as every later call, so the cached signature is the one they load), and times each.
"""

import time
from collections.abc import Callable

import numpy as np

from orbits.core import _fast

#: a low Earth orbit in SI: the one state every warm-up call starts from
_R0, _V0, _MU = np.array([7.0e6, 1.0e5, 0.0]), np.array([0.0, 7.5e3, 1.0e3]), 3.986004418e14


def _kepler(name: str) -> Callable[[], object]:
    from orbits.core.twobody import kepler

    calls = {"elliptic": lambda: kepler.eccentric_anomaly(1.0, 0.5),
             "hyperbolic": lambda: kepler.hyperbolic_anomaly(1.0, 2.0),
             "parabolic": lambda: kepler.parabolic_anomaly(1.0)}
    return calls[name]


def _propagate() -> object:
    from orbits.core.twobody import propagate

    return propagate.propagate(_R0, _V0, _MU, 600.0)


def _transition() -> object:
    from orbits.core.twobody import transition

    return transition.transition_matrix(_R0, _V0, _MU, 600.0)


def _lambert() -> object:
    from orbits.core.manoeuvres import lambert

    return lambert.solve(_R0, np.array([0.0, 7.2e6, 1.0e5]), 1500.0, _MU)


def _cr3bp() -> object:
    from orbits.core.periodic import cr3bp, shooting

    flow = shooting.Flow(0.01215058560962404, cr3bp.origin(0.01215058560962404, "L1"), compiled=True)
    return flow.arc(np.array([0.01, 0.0, 0.0, 0.0, 0.01, 0.0]), 0.1, transition=True)


#: the call that starts each entry kernel of orbits.core._fast.ENTRY_KERNELS
STARTERS = {
    "twobody._fast_kepler.elliptic": _kepler("elliptic"),
    "twobody._fast_kepler.hyperbolic": _kepler("hyperbolic"),
    "twobody._fast_kepler.parabolic": _kepler("parabolic"),
    "twobody._fast_propagate.propagate": _propagate,
    "twobody._fast_transition.transition": _transition,
    "manoeuvres._fast_lambert.solve": _lambert,
    "periodic._fast_cr3bp.integrate": _cr3bp,
}


def compile_all(report: Callable[[str, float | None], None] = lambda kernel, seconds: None) -> dict[str, float]:
    """Compile (or load) every entry kernel that is not ready, in this process and into the disk cache; returns
    {kernel: seconds} for those compiled, calling report(kernel, None) before each and report(kernel, seconds)
    after. Nothing is done without numba or with ORBITS_JIT=0 (orbits.core._fast.enabled)."""
    if not _fast.enabled():
        return {}
    previous = _fast.set_enabled(True)
    spent = {}
    try:
        for kernel in _fast.entry_kernels():
            if _fast.ready(kernel):
                continue
            report(kernel, None)
            start = time.perf_counter()
            STARTERS[kernel]()
            spent[kernel] = time.perf_counter() - start
            report(kernel, spent[kernel])
    finally:
        _fast.set_enabled(previous)
    return spent
