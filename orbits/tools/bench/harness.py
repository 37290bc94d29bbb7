"""What the benchmarks share to time orbits and its peers: the peer adapter (Method) and its lazy loading, the
best-of timing, the thread settings of orbits' compiled kernels and of heyoka, and the plain NumPy Newton
baselines for Kepler's equation.

Every benchmark module may import this one; it imports none of them. orbits' kernels and heyoka are imported
inside the functions that need them, so that a benchmark whose peer is absent still runs.
"""

import contextlib
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.tools import profiles

NEWTON_TOL = 1e-15  # absolute step tolerance of the plain NumPy Newton baseline
NEWTON_MAX_ITER = 50
#: best_time repeats a quick call past its `repeats` while the calls fit in this many seconds, up to BEST_OF_CALLS
#: calls: on a shared machine the best of 3 calls of 10 ms missed the quiet moments (58 M/s against 100 in a
#: second run, same kernel)
BEST_OF_SECONDS, BEST_OF_CALLS = 0.3, 30
#: the most elements a benchmark set may hold: 1e7 Kepler pairs take about 1 GB over their inputs and results
MAX_SET = 10_000_000
#: the most elements checked against the mpmath reference (a few milliseconds each)
MAX_REFERENCE = 100_000
#: the most timing repeats, or fresh processes per command
MAX_REPEATS = 1000


def check_count(value: int, name: str, high: int) -> int:
    """`value` if it is an integer in [1, high], else OrbitDomainError naming it and the range: every size of a
    benchmark is checked here before anything is allocated (an empty set would time nothing and print nan)."""
    from orbits.core.errors import OrbitDomainError

    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 1 <= value <= high:
        raise OrbitDomainError(f"{name} = {value!r} is outside [1, {high:,}]")
    return int(value)


def check_sizes(**counts: int) -> None:
    """check_count for each size a benchmark is given, by its argument name: `n_ref` against MAX_REFERENCE,
    `repeats` and `runs` against MAX_REPEATS, every other (n, n_easy, sizes' elements ...) against MAX_SET; called
    first in every bench_* function, so the library refuses what the command line refuses (bench_kepler(n_easy=
    10**13) would have asked for 73 TiB)."""
    limits = {"n_ref": MAX_REFERENCE, "repeats": MAX_REPEATS, "runs": MAX_REPEATS}
    for name, value in counts.items():
        check_count(value, name, limits.get(name, MAX_SET))


def _as_pair(e, M):
    """Default input preparation: the two arrays as they are."""
    return e, M


@dataclass(frozen=True)
class Method:
    """A peer adapter.  prepare(...) puts the inputs in the form the library takes (not timed); for
    Kepler solvers prepare(e, M) and solve(prepared, hyperbolic), which returns the anomalies or None
    if the equation is unsupported; for propagators prepare(states) and solve(prepared) -> (r, v)."""

    name: str
    solve: Callable[..., object]
    prepare: Callable[[np.ndarray, np.ndarray], object] = _as_pair
    setup_seconds: float = 0.0
    note: str = ""
    subset: int | None = None  # time only this many pairs (per-call APIs)


def load_methods(factories):
    """[(name, Method or None, skip note)] for every (name, factory), importing peers lazily."""
    loaded = []
    for name, factory in factories:
        try:
            loaded.append((name, factory(), ""))
        except ImportError as exc:
            loaded.append((name, None, f"not installed ({exc.name or exc})"))
    return loaded


def best_time(call, repeats):
    """(best time of `repeats` calls, or of as many more as fit in BEST_OF_SECONDS (at most BEST_OF_CALLS), the last
    result): each call's wall time, or its process CPU time where that is the smaller. Work on one thread then
    counts the CPU it got, not the time other processes held the core (on a shared 2-core machine at load 4-7,
    heyoka's lagrange_prop took 4.2 to 11.7 M states/s of wall time in three runs, 21.7 to 22.6 of CPU time in
    four); work on several threads adds up more CPU than wall time and keeps the wall time."""
    check_count(repeats, "repeats", MAX_REPEATS)
    best, result, calls, begin = math.inf, None, 0, time.perf_counter()
    while calls < repeats or (calls < BEST_OF_CALLS and time.perf_counter() - begin < BEST_OF_SECONDS):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = call()
        best = min(best, time.perf_counter() - start, time.process_time() - start_cpu)
        calls += 1
    return best, result


# --- threads ----------------------------------------------------------------------------------------


def cores():
    """Threads the 'all cores' rows use: orbits.core._fast.num_threads() (ORBITS_NUM_THREADS or the cores)."""
    from orbits.core import _fast

    return _fast.num_threads()


@contextlib.contextmanager
def orbits_threads(threads):
    """Run orbits' compiled kernels on `threads` threads (threads=0: the NumPy fallback) inside the block."""
    from orbits.core import _fast

    previous_threads = _fast.num_threads()
    _fast.set_num_threads(max(threads, 1))
    previous_mode = _fast.set_enabled(threads > 0)  # every batch size: the benchmark measures the kernels
    try:
        yield
    finally:
        _fast.set_num_threads(previous_threads)
        _fast.set_enabled(previous_mode)


def orbits_name(threads):
    """The row name of orbits run on `threads` threads (0: the NumPy fallback)."""
    return {0: "orbits (NumPy)", 1: "orbits"}.get(threads, "orbits (all cores)")


def orbits_note(threads):
    """The row note of orbits run on `threads` threads (0: the NumPy fallback)."""
    if threads == 0:
        return "NumPy fallback (ORBITS_JIT=0)"
    return "compiled, 1 thread" if threads == 1 else f"compiled, {threads} threads"


# --- plain NumPy baselines --------------------------------------------------------------------------


def newton_elliptic(e, M):
    """Plain vectorised Newton on E - e sin E = M from E0 = M + e sin M."""
    E = M + e * np.sin(M)
    with np.errstate(all="ignore"):
        for _ in range(NEWTON_MAX_ITER):
            step = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
            E = E - step
            if np.all(np.abs(step) <= NEWTON_TOL):
                break
    return E


def newton_hyperbolic(e, M):
    """Plain vectorised Newton on e sinh H - H = M from H0 = asinh(M / e)."""
    H = np.arcsinh(M / e)
    with np.errstate(all="ignore"):
        for _ in range(NEWTON_MAX_ITER):
            step = (e * np.sinh(H) - H - M) / (e * np.cosh(H) - 1.0)
            H = H - step
            if np.all(np.abs(step) <= NEWTON_TOL):
                break
    return H


# --- the machine ------------------------------------------------------------------------------------


def machine() -> str:
    """One line naming this machine's CPU and its widest vector unit, read from the machine itself
    (/proc/cpuinfo on Linux, the platform module elsewhere), e.g. "AMD EPYC, 2 cores, AVX-512 (512-bit vectors)",
    and the CPU profile the run computes under, if any (orbits.tools.profiles: ", under the AVX2 profile")."""
    import os
    import platform

    name, flags = profiles.cpu_info()
    name = name or platform.processor() or platform.machine()
    vectors = next((f"{label} ({bits}-bit vectors)" for flag, label, bits in
                    (("avx512f", "AVX-512", 512), ("avx2", "AVX2", 256), ("avx", "AVX", 256), ("sse2", "SSE2", 128))
                    if flag in flags), "vector width unknown")
    count = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return f"{name}, {count} cores, {vectors}{profiles.describe()}"
