"""`orbits bench api`: the unit-aware API (orbits.Orbit) against the float64 core on the same inputs, time per
call for scalars and for arrays.
"""

import math
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from orbits.tools.bench.harness import best_time, check_sizes
from orbits.tools.bench.table import WIDTH, fixed, plain_table, wrap


@dataclass(frozen=True)
class ApiRow:
    """One API call against the core call it wraps, on the same inputs: seconds per call (best of the
    repeats) and the overhead, absolute and as a fraction of the core time."""

    case: str
    n: int
    core_seconds: float
    api_seconds: float
    overhead_seconds: float
    overhead_fraction: float


def _per_call(call, n, repeats):
    """Best over repeats of the mean time per call, over enough calls to last about 20 ms."""
    call()
    number = max(1, int(0.02 / max(best_time(call, 1)[0], 1e-7))) if n < 1000 else 1
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(number):
            call()
        best = min(best, (time.perf_counter() - start) / number)
    return best


def _api_cases(n, rng):
    """[(case name, core call, API call)] on n orbits (scalars for n = 1)."""
    import astropy.units as u

    from orbits import Orbit
    from orbits.core.twobody import elements
    from orbits.core.twobody.propagate import propagate

    shape = () if n == 1 else (n,)
    # periapses of 7000 km and up: every orbit clears the Earth (an orbit through it would warn)
    a, e, nu = 14000 + rng.uniform(0, 2000, shape), rng.uniform(0, 0.5, shape), rng.uniform(-np.pi, np.pi, shape)
    a_q, nu_q, dt = a * u.km, nu * u.rad, rng.uniform(0, 1e4, shape)
    dt_q = dt * u.s
    orbit = Orbit.from_elements("Earth", a=a_q, e=e, nu=nu_q)
    r, v = orbit._state  # the state the API call uses, computed once (cached) as in any repeated use
    p, zero = a * 1e3 * (1 - e) * (1 + e), np.zeros(shape)
    return [
        ("Orbit.propagate vs core propagate", lambda: propagate(r, v, orbit.mu, dt), lambda: orbit.propagate(dt_q)),
        (
            "Orbit.from_elements vs elements_to_state",
            lambda: elements.elements_to_state(p, e, zero, zero, zero, nu, orbit.mu),
            lambda: Orbit.from_elements("Earth", a=a_q, e=e, nu=nu_q),
        ),
    ]


def bench_api(sizes: Iterable[int] = (1, 100_000, 1_000_000), seed: int = 0, repeats: int = 5) -> list[ApiRow]:
    """Overhead of the unit-aware API (orbits.Orbit) over the float64 core on the same inputs, per call,
    for scalars and arrays of the given sizes. Returns one ApiRow per (case, size)."""
    sizes = list(sizes)
    check_sizes(**{f"sizes[{i}]": size for i, size in enumerate(sizes)}, repeats=repeats)
    rows = []
    rng = np.random.default_rng(seed)
    for n in sizes:
        for case, core, api in _api_cases(n, rng):
            core_s, api_s = _per_call(core, n, repeats), _per_call(api, n, repeats)
            rows.append(ApiRow(case, n, core_s, api_s, api_s - core_s, (api_s - core_s) / core_s))
    return rows


def format_api(rows: Sequence[ApiRow]) -> str:
    """Plain-text table of bench_api, at most 80 columns: a section per case, a row per size; times per call
    in microseconds (4 significant digits), overhead in microseconds and as a percentage of the core time."""
    table = []
    for case in dict.fromkeys(r.case for r in rows):
        table.append(case)
        for r in (r for r in rows if r.case == case):
            times = (fixed(t * 1e6, 4) for t in (r.core_seconds, r.api_seconds, r.overhead_seconds))
            table.append([str(r.n), *times, fixed(r.overhead_fraction * 100, 3) + "%"])
    lines = plain_table(["n", "core us", "API us", "overhead us", "overhead"], table, first=">")
    legend = "us: microseconds per call, best of the repeats. overhead: API minus core, in us and as a share of core."
    return "\n".join(lines + [""] + wrap(legend, WIDTH))
