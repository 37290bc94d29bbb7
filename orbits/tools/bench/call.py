"""`orbits bench call`: what a call costs where users are: one element, and batches of a thousand and ten thousand,
as the library runs them by default (ORBITS_JIT=auto, where a kernel in the disk cache serves any size), warm, on
one thread, beside heyoka's compiled cfuncs (kepE, lagrange_prop) called on the same inputs in the same process.

Kernels absent from the cache are compiled first (orbits.tools.kernels), not timed: the benchmark measures the path
a user meets once the cache holds them. Each figure is the best over the repeats of
the mean time of a loop of calls lasting about 20 ms, the lesser of wall and CPU time.
"""

import math
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from orbits.tools.bench.harness import check_sizes, machine
from orbits.tools.bench.table import WIDTH, fixed, plain_table, sig, wrap

#: Earth's GM (m**3/s**2): every propagation of the benchmark is about it
MU_EARTH = 3.986004418e14
#: how long one timed loop of calls lasts, about (seconds)
LOOP_SECONDS = 0.02


@dataclass(frozen=True)
class CallRow:
    """One call of orbits on n elements beside its yardstick on the same inputs: seconds per call (best of the
    repeats), the yardstick's name ("" when there is none) and its seconds per call (None when absent)."""

    case: str
    n: int
    orbits_seconds: float
    peer: str
    peer_seconds: float | None


def per_call(call: Callable[[], object], repeats: int) -> float:
    """Best over `repeats` loops of the mean seconds per call, each loop lasting about LOOP_SECONDS; wall time, or
    the process's CPU time where that is less (what the one thread got on a shared machine)."""
    call()
    start = time.perf_counter()
    call()
    number = max(1, int(LOOP_SECONDS / max(time.perf_counter() - start, 1e-7)))
    best = math.inf
    for _ in range(repeats):
        wall, cpu = time.perf_counter(), time.process_time()
        for _ in range(number):
            call()
        best = min(best, time.perf_counter() - wall, time.process_time() - cpu)
    return best / number


def _elliptic_states(n: int, rng: np.random.Generator):
    """(r0 (n, 3) m, v0 (n, 3) m/s, dt (n,) s): Earth orbits of 7,000 to 42,000 km, e < 0.7, any orientation, flown
    for up to a day; shapes (3,), (3,) and () for n = 1."""
    from orbits.core.twobody import elements

    a = rng.uniform(7.0e6, 4.2e7, n)
    e = rng.uniform(0.0, 0.7, n) * np.minimum(1.0, 1.0 - 6.6e6 / a)  # periapsis above 6,600 km
    angles = rng.uniform(0.0, np.pi, (4, n)) * np.array([[1.0], [2.0], [2.0], [2.0]])
    r0, v0 = elements.elements_to_state(a * (1 - e) * (1 + e), e, angles[0], angles[1], angles[2],
                                        angles[3] - np.pi, MU_EARTH)
    dt = rng.uniform(0.0, 86400.0, n)
    return (r0[0], v0[0], dt[0]) if n == 1 else (r0, v0, dt)


def _kepler_case(n, rng, heyoka):
    from orbits.core.twobody import kepler

    M, e = rng.uniform(-np.pi, np.pi, n), rng.uniform(0.0, 0.99, n)
    if n == 1:
        M, e = float(M[0]), float(e[0])
    pairs = np.ascontiguousarray(np.vstack([np.atleast_1d(e), np.atleast_1d(M)]))
    return ("Kepler E", lambda: kepler.eccentric_anomaly(M, e), "heyoka kepE",
            None if heyoka is None else (lambda: heyoka[0].bare(pairs)))


def _propagation_case(n, rng, heyoka):
    from orbits.core.twobody import propagate

    r0, v0, dt = _elliptic_states(n, rng)
    inputs = np.ascontiguousarray(np.vstack([np.atleast_2d(r0).T, np.atleast_2d(v0).T,
                                             np.full(np.size(dt), MU_EARTH), np.atleast_1d(dt)]))
    return ("propagation", lambda: propagate.propagate(r0, v0, MU_EARTH, dt), "heyoka lagrange_prop",
            None if heyoka is None else (lambda: heyoka[1].bare(inputs)))


def _transition_case(n, rng, heyoka):
    from orbits.core.twobody import transition

    r0, v0, dt = _elliptic_states(n, rng)
    return "STM", lambda: transition.transition_matrix(r0, v0, MU_EARTH, dt), "", None


def _lambert_case(n, rng, heyoka):
    from orbits.core.manoeuvres import lambert

    r1, _, _ = _elliptic_states(n, rng)
    r2, _, tof = _elliptic_states(n, rng)
    tof = tof + 600.0
    return "Lambert", lambda: lambert.solve(r1, r2, tof, MU_EARTH), "", None


def _orbit_case(n, rng, heyoka, stm=False):
    import astropy.units as u

    from orbits import Orbit

    r0, v0, dt = _elliptic_states(n, rng)
    orbit = Orbit.from_vectors("Earth", r0 * u.m, v0 * u.m / u.s)
    dt_q = dt * u.s
    return (f"Orbit.propagate{', stm=True' if stm else ''}", lambda: orbit.propagate(dt_q, stm=stm), "", None)


CASES = (_kepler_case, _propagation_case, _transition_case, _lambert_case, _orbit_case,
         lambda n, rng, heyoka: _orbit_case(n, rng, heyoka, stm=True))


def _heyoka_cfuncs():
    """(kepE, lagrange_prop) cfuncs, or None without heyoka; each one's `bare` call is timed, inside
    _heyoka_single_thread."""
    try:
        from orbits.validate import peers

        return peers.heyoka_kepler_solver(1), peers.heyoka_lagrange_propagator(1)
    except ImportError:
        return None


def _heyoka_single_thread(heyoka):
    """heyoka's cfuncs pinned to one thread for the whole run (a no-op without heyoka)."""
    import contextlib

    if heyoka is None:
        return contextlib.nullcontext()
    from orbits.validate import peers

    return peers.heyoka_threads(1)


def bench_call(sizes: Iterable[int] = (1, 1000, 10_000), repeats: int = 5, seed: int = 0,
               compile_first: bool = True) -> list[CallRow]:
    """Seconds per call of orbits' solvers and of Orbit.propagate on n elements for each n of `sizes`, with heyoka's
    cfunc on the same inputs where it has one, one thread each. Compiles the absent kernels first unless not
    `compile_first` (their calls then run as the cache is: NumPy below AUTO_MIN_BATCH)."""
    from orbits.core import _fast
    from orbits.tools.kernels import compile_all

    sizes = list(sizes)
    check_sizes(**{f"sizes[{i}]": size for i, size in enumerate(sizes)}, repeats=repeats)
    if compile_first:
        compile_all()
    heyoka = _heyoka_cfuncs()
    rng = np.random.default_rng(seed)
    previous = _fast.set_num_threads(1)
    rows = []
    try:
        with _heyoka_single_thread(heyoka):
            for make in CASES:
                for n in sizes:
                    case, ours, peer, theirs = make(n, rng, heyoka)
                    rows.append(CallRow(case, n, per_call(ours, repeats), peer if theirs else "",
                                        None if theirs is None else per_call(theirs, repeats)))
    finally:
        _fast.set_num_threads(previous)
    return rows


def format_call(rows: Sequence[CallRow]) -> str:
    """Plain-text table of bench_call, at most 80 columns: a section per case, a row per size; microseconds per call,
    the yardstick's, and how many times faster orbits is (its time over orbits')."""
    table = []
    for case in dict.fromkeys(r.case for r in rows):
        peer = next((r.peer for r in rows if r.case == case and r.peer), "")
        table.append(f"{case} (beside {peer})" if peer else case)
        for r in (r for r in rows if r.case == case):
            theirs = "-" if r.peer_seconds is None else fixed(r.peer_seconds * 1e6, 3)
            ratio = "-" if r.peer_seconds is None else sig(r.peer_seconds / r.orbits_seconds, 3) + "x"
            table.append([f"{r.n:,}", fixed(r.orbits_seconds * 1e6, 3), theirs, ratio])
    lines = [*wrap(machine(), WIDTH), ""]
    lines += plain_table(["n", "orbits us", "yardstick us", "speed-up"], table, first=">")
    legend = ("us: microseconds per call, one thread, best of the repeats; orbits with its default settings "
              "(ORBITS_JIT=auto). speed-up: the yardstick's time over orbits' (above 1: orbits is faster).")
    return "\n".join(lines + [""] + wrap(legend, WIDTH))
