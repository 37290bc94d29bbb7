"""`orbits bench propagate`: two-body propagation of elliptic and mixed-conic states, throughput and worst
relative position and velocity error against mpmath (orbits.tools.reference), for orbits (compiled kernels on
one thread and on every core, and the NumPy fallback), heyoka's lagrange_prop cfunc, a plain NumPy f-and-g +
Newton baseline, pykep and hapsira.
"""

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from orbits.tools.bench.harness import (
    Method,
    best_time,
    check_sizes,
    cores,
    load_methods,
    machine,
    newton_elliptic,
    orbits_name,
    orbits_note,
    orbits_threads,
)
from orbits.tools.bench.table import RATIO_LEGEND, WIDTH, by_dataset, notes, plain_table, wrap
from orbits.validate import peers

MU_EARTH = 3.986004418e14
#: States on which slow or per-state methods are timed (their throughput is per state, so it scales).
PROPAGATE_SUBSET = 100_000


@dataclass(frozen=True)
class PropagateRow:
    """One propagator on one data set: best of the repeats for n states; worst relative position and
    velocity errors against mpmath over the first n_ref states with a finite result; NaN count."""

    method: str
    dataset: str
    n: int
    seconds: float
    throughput_per_s: float
    max_position_error: float
    max_velocity_error: float
    n_nan: int
    status: str
    note: str = ""
    setup_seconds: float = 0.0


@dataclass(frozen=True)
class _States:
    """Initial states (m, m/s) about MU_EARTH and times of flight (s)."""

    name: str
    r0: np.ndarray
    v0: np.ndarray
    dt: np.ndarray


def _propagation_sets(n, seed):
    """ "elliptic": e ~ U[0, 0.95]; "mixed": a third each of those ellipses, hyperbolas with
    e - 1 = 10**U(-6, 0.5) and near-parabolic orbits with |1 - e| < 1e-3. p = 7000-21000 km, random
    orientation, true anomaly in [-1, 1] rad, time of flight U(-10, 10) periods (2 pi sqrt(p**3 / mu) for
    open orbits)."""
    rng = np.random.default_rng(seed)
    third = n // 3
    mixed = np.concatenate(
        [
            rng.uniform(0, 0.95, third),
            1 + 10 ** rng.uniform(-6, 0.5, third),
            1 + rng.uniform(-1e-3, 1e-3, n - 2 * third),
        ]
    )
    elliptic = _conic_states("elliptic", rng, rng.uniform(0, 0.95, n))
    return [elliptic, _conic_states("mixed", rng, rng.permutation(mixed))]


def _conic_states(name, rng, e):
    from orbits.core.twobody.elements import elements_to_state

    n = e.size
    p = 7e6 * rng.uniform(1, 3, n)
    angles = rng.uniform(0, np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(-1, 1, n)
    r0, v0 = elements_to_state(p, e, *angles, MU_EARTH)
    with np.errstate(divide="ignore", invalid="ignore"):
        period = 2 * np.pi * np.sqrt(np.where(e < 1, p / np.abs((1 - e) * (1 + e)), p) ** 3 / MU_EARTH)
    return _States(name, r0, v0, rng.uniform(-10, 10, n) * period)


def _propagation_references(states, n_ref):
    """[(r, v)] as mpf lists from orbits.tools.reference.propagate for the first n_ref states."""
    from orbits.tools.reference import propagate

    return [propagate(states.r0[i], states.v0[i], MU_EARTH, states.dt[i]) for i in range(min(n_ref, states.dt.size))]


def _propagation_errors(r, v, refs):
    """(worst |r - r_ref| / |r_ref|, worst |v - v_ref| / |v_ref|) over the finite rows; NaN if none."""
    worst = [[], []]
    with mpmath.workdps(40):
        for i, ref in enumerate(refs):
            for k, (x, exact) in enumerate(zip((r[i], v[i]), ref)):
                if np.all(np.isfinite(x)):
                    diff = mpmath.sqrt(sum((mpmath.mpf(float(a)) - b) ** 2 for a, b in zip(x, exact)))
                    worst[k].append(float(diff / mpmath.sqrt(sum(b**2 for b in exact))))
    return max(worst[0], default=math.nan), max(worst[1], default=math.nan)


def _orbits_propagator(threads):
    from orbits.core.twobody.propagate import propagate

    def solve(states):
        with orbits_threads(threads):
            return propagate(states.r0, states.v0, MU_EARTH, states.dt)

    start = time.perf_counter()
    with orbits_threads(threads):
        propagate(np.array([7e6, 0.0, 0.0]), np.array([0.0, 7.5e3, 0.0]), MU_EARTH, 100.0)
    setup = time.perf_counter() - start
    subset = PROPAGATE_SUBSET if threads == 0 else None
    return Method(orbits_name(threads), solve, _as_states, setup, orbits_note(threads), subset)


def _as_states(states):
    return states


def _heyoka_propagator(threads):
    """heyoka's lagrange_prop (heyoka >= 7.11) compiled as a cfunc; elliptic only."""
    start = time.perf_counter()
    cf = peers.heyoka_lagrange_propagator(threads)
    setup = time.perf_counter() - start

    def prepare(states):
        mu = np.full(states.dt.size, MU_EARTH)
        return np.ascontiguousarray(np.vstack([states.r0.T, states.v0.T, mu, states.dt]))

    def solve(inputs):
        out = cf(inputs)
        return out[:3].T, out[3:].T

    name = "heyoka lagrange_prop" if threads == 1 else "heyoka lagrange_prop (all cores)"
    return Method(name, solve, prepare, setup, f"cfunc, {threads} thread(s); elliptic only")


def _numpy_fg_propagator():
    return Method(
        "numpy f-and-g + Newton", _fg_newton, _as_states, note="plain baseline, elliptic only", subset=PROPAGATE_SUBSET
    )


def _fg_newton(states):
    """Plain vectorised f and g on ellipses: Newton on Kepler's equation from E = M (abs step tol 1e-15),
    no period reduction, no care for cancellation; NaN for open orbits."""
    r0, v0, dt, mu = states.r0, states.v0, states.dt, MU_EARTH
    r = np.linalg.norm(r0, axis=-1)
    rv = np.sum(r0 * v0, axis=-1)
    with np.errstate(all="ignore"):
        a = 1.0 / (2.0 / r - np.sum(v0 * v0, axis=-1) / mu)
        a = np.where(a > 0, a, np.nan)
        n = np.sqrt(mu / a**3)
        e_cos, e_sin = 1.0 - r / a, rv / np.sqrt(mu * a)
        E0 = np.arctan2(e_sin, e_cos)
        e = np.hypot(e_cos, e_sin)
        M = E0 - e_sin + n * dt
        E = newton_elliptic(e, M)
        dE = E - E0
        f, g = 1.0 - a / r * (1.0 - np.cos(dE)), dt - (dE - np.sin(dE)) / n
        r1 = f[:, None] * r0 + g[:, None] * v0
        r1_norm = np.linalg.norm(r1, axis=-1)
        f_dot, g_dot = -np.sqrt(mu * a) * np.sin(dE) / (r * r1_norm), 1.0 - a / r1_norm * (1.0 - np.cos(dE))
        return r1, f_dot[:, None] * r0 + g_dot[:, None] * v0


def _pykep_propagator():
    import pykep

    def solve(states):
        pairs = [pykep.propagate_lagrangian(r, v, t, MU_EARTH) for r, v, t in zip(states.r0, states.v0, states.dt)]
        return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])

    return Method(
        "pykep propagate_lagrangian", solve, _as_states, note="per-state Python API", subset=PROPAGATE_SUBSET
    )


def _hapsira_propagator():
    from hapsira.core.propagation.farnocchia import farnocchia_rv

    def solve(states):
        pairs = [farnocchia_rv(MU_EARTH, r, v, t) for r, v, t in zip(states.r0, states.v0, states.dt)]
        return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])

    return Method("hapsira farnocchia", solve, _as_states, note="per-state Python API", subset=PROPAGATE_SUBSET)


_PROPAGATORS = [
    ("orbits", lambda: _orbits_propagator(1)),
    ("orbits (all cores)", lambda: _orbits_propagator(cores())),
    ("orbits (NumPy)", lambda: _orbits_propagator(0)),
    ("heyoka lagrange_prop", lambda: _heyoka_propagator(1)),
    ("heyoka lagrange_prop (all cores)", lambda: _heyoka_propagator(cores())),
    ("numpy f-and-g + Newton", _numpy_fg_propagator),
    ("pykep propagate_lagrangian", _pykep_propagator),
    ("hapsira farnocchia", _hapsira_propagator),
]


def _subset(states, n):
    return _States(states.name, states.r0[:n], states.v0[:n], states.dt[:n])


def _measure_propagator(method, states, refs, repeats):
    """Time method on states (best of repeats, inputs prepared outside the timing) and check its results."""
    n = states.dt.size if method.subset is None else min(states.dt.size, method.subset)
    inputs = method.prepare(_subset(states, n))
    try:
        seconds, (r, v) = best_time(lambda: method.solve(inputs), repeats)
    except Exception as exc:  # a peer failing on some input is a benchmark result, not a crash
        return _failed_propagation(method, states, n, exc)
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    position, velocity = _propagation_errors(r, v, refs)
    n_nan = int(np.count_nonzero(~np.all(np.isfinite(np.concatenate([r, v], axis=-1)), axis=-1)))
    return PropagateRow(
        method.name,
        states.name,
        n,
        seconds,
        n / seconds,
        position,
        velocity,
        n_nan,
        "ok",
        method.note,
        method.setup_seconds,
    )


def _failed_propagation(method, states, n, exc):
    note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
    nan = math.nan
    return PropagateRow(method.name, states.name, n, nan, nan, nan, nan, 0, "raised", note, method.setup_seconds)


def bench_propagate(n: int = 1_000_000, n_ref: int = 200, seed: int = 0, repeats: int = 3) -> list[PropagateRow]:
    """Time and check every available two-body propagator on the "elliptic" and "mixed" sets (see
    _propagation_sets). Errors are relative to |r| and |v| of the mpmath reference (orbits.tools.reference);
    timings exclude preparing the inputs in the form each library takes.
    Returns one PropagateRow per (method, data set)."""
    check_sizes(n=n, n_ref=n_ref, repeats=repeats)
    loaded = load_methods(_PROPAGATORS)
    rows = []
    for states in _propagation_sets(n, seed):
        refs = _propagation_references(states, n_ref)
        for name, method, note in loaded:
            if method is None:
                rows.append(PropagateRow(name, states.name, 0, *[math.nan] * 4, 0, "skipped", note))
            else:
                rows.append(_measure_propagator(method, states, refs, repeats))
    return rows


def format_propagate(rows: Sequence[PropagateRow]) -> str:
    """Plain-text table of bench_propagate, at most 80 columns: a section per data set, M states/s, ratio to
    orbits on one thread on the same set, worst relative position and velocity errors, NaN count; the notes
    in a numbered list under the table."""
    reference = {r.dataset: r.throughput_per_s for r in rows if r.method == "orbits" and r.status == "ok"}
    table, texts = by_dataset(rows, reference, _propagation_stats)
    lines = plain_table(["method", "M/s", "ratio", "|dr|/r", "|dv|/v", "NaN"], table)
    legend = (
        f"M/s: millions of states propagated per second. {RATIO_LEGEND} |dr|/r, |dv|/v: max |dr|/r and max |dv|/v, "
        "the worst relative position and velocity errors against mpmath. NaN: non-finite results."
    )
    return "\n".join(lines + [""] + wrap(legend, WIDTH) + notes(texts) + ["", f"Machine: {machine()}"])


def _propagation_stats(row):
    return [f"{row.max_position_error:.2e}", f"{row.max_velocity_error:.2e}"]
