"""Backend-neutral N-body problem and result records used by the validation adapters (numpy only), and the one
home of how big a run may be.

Code units throughout: G = 1, so ``gm`` holds the masses. Nothing here imports rebound or heyoka. The size
rules (check_bodies, check_states, check_span) hold in any consistent units (SI with gm = G M, or code units), so
the scene loader applies them to a file before building anything, and NBodyProblem to every run.
"""

from __future__ import annotations

import contextlib
import contextvars
import math
import operator
import signal
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import OrbitDomainError

# ---- how big a run may be: estimated and refused before anything is allocated or integrated ----------------

#: bodies squared: the pair forces one integration step sums (1000 bodies)
MAX_BODIES_SQUARED = 1_000_000
#: outputs x bodies: the states a trajectory stores (a position and a velocity, 48 bytes each, per backend)
MAX_STATES = 10_000_000
#: the length of a run in periods of its fastest orbit, each counted at the integrator steps it takes (see
#: step_weight): a million periods of a circular orbit take IAS15 6 minutes on one core
MAX_PERIODS = 1_000_000


def check_bodies(n_bodies: int) -> None:
    """OrbitDomainError unless n_bodies**2 <= MAX_BODIES_SQUARED (every step of a run sums the forces of all
    pairs; the loader's checks go over pairs too)."""
    if n_bodies**2 > MAX_BODIES_SQUARED:
        raise OrbitDomainError(f"{n_bodies} bodies: a step sums {n_bodies}**2 = {n_bodies**2:.3g} pair forces; at "
                               f"most {MAX_BODIES_SQUARED:.0e} ({math.isqrt(MAX_BODIES_SQUARED)} bodies) are allowed")


def check_states(n_outputs: int, n_bodies: int) -> None:
    """OrbitDomainError unless outputs x bodies <= MAX_STATES, the states one trajectory stores."""
    if n_outputs * n_bodies > MAX_STATES:
        raise OrbitDomainError(f"outputs x bodies = {n_outputs} x {n_bodies} = {n_outputs * n_bodies:.3g} stored "
                               f"states; at most {MAX_STATES:.0e} are allowed: ask for fewer outputs")


def step_weight(e: np.ndarray) -> np.ndarray:
    """The integrator steps one period of an orbit of eccentricity e takes, in periods of a circular orbit:
    1 + 1.7 log10(1 / (1 - e)). IAS15 (epsilon 1e-9) measured 36, 51, 97, 159, 221, 283 and 343 steps per
    period at e = 0, 0.5, 0.9, 0.99, 0.999, 0.9999 and 0.99999, which this fits within 7 %; 1 - e is taken at
    least 1e-16 (a radial orbit)."""
    return 1.0 + 1.7 * np.log10(1.0 / np.maximum(1.0 - np.asarray(e, dtype=float), 1e-16))


def fastest_orbit(gm: np.ndarray, positions: np.ndarray, velocities: np.ndarray, n_active: int):
    """(i, j, period T, eccentricity e, weighted periods per unit time w / T) of the bound pair of bodies whose
    relative two-body orbit (mu = gm_i + gm_j) costs the most integrator steps per unit time, or None when no
    pair is bound. Every pair with a massive body counts (two test particles do not interact), whatever gave the
    states: orbit elements or Cartesian vectors. T = 2 pi sqrt(a**3 / mu) with a = -mu / (2 energy); e from the
    Laplace-Runge-Lenz vector; call check_bodies first (the pairs number n_active x N)."""
    i, j = np.triu_indices(len(gm), 1)
    keep = i < n_active
    i, j = i[keep], j[keep]
    dr, dv = positions[j] - positions[i], velocities[j] - velocities[i]
    mu = gm[i] + gm[j]
    with np.errstate(all="ignore"):  # coincident or extreme pairs give inf or nan, counted as endless below
        r = np.linalg.norm(dr, axis=-1)
        v2 = np.einsum("ij,ij->i", dv, dv)
        energy = 0.5 * v2 - mu / r
        bound = (energy < 0) & (mu > 0)
        a = -mu / (2.0 * energy)
        period = 2.0 * np.pi * np.sqrt(a**3 / mu)
        lrl = ((v2 - mu / r)[:, None] * dr - np.einsum("ij,ij->i", dr, dv)[:, None] * dv) / mu[:, None]
        e = np.linalg.norm(lrl, axis=-1)
        rate = np.where(bound, step_weight(np.minimum(e, 1.0)) / period, 0.0)
    rate = np.where(np.isnan(rate), np.inf, rate)
    if not np.any(rate > 0):
        return None
    k = int(np.argmax(rate))
    return int(i[k]), int(j[k]), float(period[k]), float(min(e[k], 1.0)), float(rate[k])


def check_span(span: float, gm: np.ndarray, positions: np.ndarray, velocities: np.ndarray, n_active: int,
               names: list[str] | None = None, unit: str = "time units") -> None:
    """OrbitDomainError unless a run over `span` lasts at most MAX_PERIODS periods of its fastest orbit
    (fastest_orbit), each period weighted by step_weight(e); `names` name the bodies and `unit` the time unit in
    the message."""
    fastest = fastest_orbit(gm, positions, velocities, n_active)
    if fastest is None:
        return
    if fastest[2] == 0.0:
        raise OrbitDomainError(f"bodies {fastest[0]} and {fastest[1]} start at the same point: the force between "
                               f"them is infinite; move one")
    i, j, period, e, rate = fastest
    if span * rate <= MAX_PERIODS:
        return
    pair = f"{names[i]!r} and {names[j]!r}" if names else f"bodies {i} and {j}"
    count, weight = span / period, float(step_weight(e))
    weighted = "" if weight < 1.05 else (f", which count as {count * weight:.3g}: an e = {e:.6g} period takes "
                                         f"{weight:.3g} times the integrator steps of a circular one")
    raise OrbitDomainError(f"a run of {span:.6g} {unit} is {count:.3g} periods of the fastest orbit ({pair}, "
                           f"period {period:.6g} {unit}){weighted}; at most {MAX_PERIODS:.0e} are allowed: too "
                           f"long a run")


def _frozen_float_array(name: str, value, shape: tuple[int, ...] | None = None) -> np.ndarray:
    """Return a read-only float64 copy of ``value`` (long double kept as long double, for extended-precision
    runs); raise if it has the wrong shape or a non-finite entry."""
    dtype = np.longdouble if getattr(value, "dtype", None) == np.longdouble else np.float64
    try:
        array = np.array(value, dtype=dtype)
    except (TypeError, ValueError) as exc:
        raise OrbitDomainError(f"{name} cannot be read as a float64 array: {exc}") from None
    if shape is not None and array.shape != shape:
        raise OrbitDomainError(f"{name} has shape {array.shape}; expected {shape}")
    bad = np.argwhere(~np.isfinite(array))
    if bad.size:
        index = tuple(int(i) for i in bad[0])
        raise OrbitDomainError(f"{name}{list(index)} = {array[index]} is not finite; every entry must be finite")
    array.setflags(write=False)
    return array


def _check_masses(gm: np.ndarray, n_active: int) -> None:
    """Raise unless active bodies have gm > 0 and test particles have gm == 0."""
    for i, value in enumerate(gm):
        if i < n_active and not value > 0.0:
            raise OrbitDomainError(
                f"gm[{i}] = {value} but body {i} is active (index < n_active = {n_active}); active bodies need gm > 0"
            )
        if i >= n_active and value != 0.0:
            raise OrbitDomainError(
                f"gm[{i}] = {value} but body {i} is a test particle (index >= n_active = "
                f"{n_active}); test particles need gm = 0"
            )


def _check_times(times: np.ndarray) -> None:
    """Raise unless ``times`` is a non-empty, non-negative, strictly increasing 1-D array."""
    if times.ndim != 1 or times.size == 0:
        raise OrbitDomainError(f"times has shape {times.shape}; expected a non-empty 1-D array of output times")
    if times[0] < 0.0:
        raise OrbitDomainError(
            f"times[0] = {times[0]} is negative; output times must be >= 0 (the initial state is at t = 0)"
        )
    steps = np.diff(times)
    if np.any(steps <= 0.0):
        i = int(np.argmax(steps <= 0.0)) + 1
        raise OrbitDomainError(
            f"times is not strictly increasing at index {i}: times[{i}] = {times[i]} <= times[{i - 1}] = {times[i - 1]}"
        )


@dataclass(frozen=True)
class ZonalHarmonics:
    """Body `source`'s zonal harmonics, felt by every other body: J2, J3 and J4 at the reference radius `radius`
    (code units), axis of symmetry z, in the potential -(G m / r) [1 - sum_n J_n (R / r)**n P_n(z / r)]. The
    source feels the reaction -(m_i / m_source) of each body's acceleration, as REBOUNDx's
    "gravitational_harmonics" effect applies it (that effect has J2 and J4; J3 is a force of the adapter's)."""

    j2: float
    radius: float
    j4: float = 0.0
    source: int = 0
    j3: float = 0.0

    def check(self, problem: NBodyProblem) -> None:
        """Raise OrbitDomainError unless the values are finite, R > 0 and the source is a massive body."""
        _check_force_numbers(self, ("j2", "radius", "j4", "j3"))
        if not self.radius > 0.0:
            raise OrbitDomainError(f"ZonalHarmonics.radius = {self.radius!r} must be > 0 (code units)")
        _check_source(self, problem)


@dataclass(frozen=True)
class ExponentialDrag:
    """Drag on every test particle relative to body `source`: a = -(1/2) rho(r) B |v| v, with B the particle's
    C_D A / m and rho(r) B = `reference` exp(-(r - base) / scale_height), r and v relative to the source (an
    atmosphere that does not turn with the body). Code units: `reference` is rho0 B (1 / length)."""

    reference: float
    base: float
    scale_height: float
    source: int = 0

    def check(self, problem: NBodyProblem) -> None:
        """Raise OrbitDomainError unless the values are finite and positive, the source massive, and the problem
        has test particles to slow down."""
        _check_force_numbers(self, ("reference", "base", "scale_height"))
        for name in ("reference", "base", "scale_height"):
            if not getattr(self, name) > 0.0:
                raise OrbitDomainError(f"ExponentialDrag.{name} = {getattr(self, name)!r} must be > 0 (code units)")
        _check_source(self, problem)
        if problem.n_active == problem.n_bodies:
            raise OrbitDomainError("ExponentialDrag acts on test particles, and this problem has none "
                                   "(n_active = N)")


#: the extra forces an NBodyProblem may list, each realised by both adapters
FORCES = (ZonalHarmonics, ExponentialDrag)


def _check_force_numbers(force, names) -> None:
    for name in names:
        value = getattr(force, name)
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) or not math.isfinite(value):
            raise OrbitDomainError(f"{type(force).__name__}.{name} = {value!r} must be a finite number")


def _check_source(force, problem) -> None:
    source = force.source
    if isinstance(source, bool) or not isinstance(source, (int, np.integer)) or not 0 <= source < problem.n_active:
        raise OrbitDomainError(f"{type(force).__name__}.source = {source!r} must index a massive body, in "
                               f"[0, n_active = {problem.n_active})")


@dataclass(frozen=True, eq=False)
class Kick:
    """An impulse: body `body`'s velocity changes by `delta_v` (code units, (3,)) at `time` (code units).

    A kick at an output time acts before that output, so the output shows the kicked state; a kick at t = 0 acts
    on the initial state.
    """

    time: float
    body: int
    delta_v: np.ndarray

    def __post_init__(self) -> None:
        """Freeze delta_v as a finite (3,) float64 array and the time as a finite float >= 0."""
        if isinstance(self.time, bool) or not (math.isfinite(self.time) and self.time >= 0.0):
            raise OrbitDomainError(f"kick time = {self.time!r} must be a finite number >= 0 (code units)")
        object.__setattr__(self, "time", float(self.time))
        object.__setattr__(self, "delta_v", _frozen_float_array("kick delta_v", self.delta_v, (3,)))


@dataclass(frozen=True)
class Arc:
    """One stretch of a run between impulses: the kicks applied at `start`, then a coast to `end` (code units),
    with the outputs `outputs` (indices into the problem's times) in [start, end), or [start, end] for the last."""

    start: float
    end: float
    kicks: tuple[Kick, ...]
    outputs: np.ndarray


def _check_kicks(kicks: tuple, n_bodies: int, last_time: float) -> tuple[Kick, ...]:
    """Raise unless every kick is a Kick on a body in [0, N) at a time in [0, last output time], in time order."""
    kicks = tuple(kicks)
    for i, kick in enumerate(kicks):
        if not isinstance(kick, Kick):
            raise OrbitDomainError(f"kicks[{i}] = {kick!r} is not an orbits.validate.nbody.Kick")
        if isinstance(kick.body, bool) or not isinstance(kick.body, (int, np.integer)) or not 0 <= kick.body < n_bodies:
            raise OrbitDomainError(f"kicks[{i}].body = {kick.body!r} must be a body index in [0, N = {n_bodies})")
        if kick.time > last_time:
            raise OrbitDomainError(f"kicks[{i}].time = {kick.time!r} is after the last output time {last_time!r}")
        if i and kick.time < kicks[i - 1].time:
            raise OrbitDomainError(f"kicks[{i}].time = {kick.time!r} is before kicks[{i - 1}].time = "
                                   f"{kicks[i - 1].time!r}; list kicks in time order")
    return kicks


@dataclass(frozen=True, eq=False)
class NBodyProblem:
    """Initial Cartesian state at t = 0 of N point masses (G = 1) and the times at which the state is wanted.

    Bodies [0, n_active) are massive; bodies [n_active, N) are massless test particles (gm = 0) that feel the
    massive bodies but do not act on anything. Arrays are copied to read-only float64 on construction (arrays
    given in long double stay long double, for heyoka's fp_type="long double"; rebound reads them as float64);
    equality is identity (eq=False), since elementwise array comparison has no single truth value.
    """

    gm: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    n_active: int
    times: np.ndarray
    #: the speed of light in code units to add body 0's first post-Newtonian (1PN) field on every other body,
    #: in the single-dominant-mass form of Anderson et al. (1975) that REBOUNDx's "gr" effect implements; None for
    #: Newtonian gravity alone
    speed_of_light: float | None = None
    #: instant velocity changes (impulsive manoeuvres), in time order; each backend coasts between them
    kicks: tuple[Kick, ...] = ()
    #: extra forces (FORCES: ZonalHarmonics, ExponentialDrag), each with its parameters in code units
    forces: tuple = ()

    def __post_init__(self) -> None:
        """Validate and freeze every field; raise OrbitDomainError naming the offending value."""
        gm = _frozen_float_array("gm", self.gm)
        if gm.ndim != 1 or gm.size < 2:
            raise OrbitDomainError(f"gm has shape {gm.shape}; expected (N,) with N >= 2 bodies")
        n = gm.size
        try:
            n_active = operator.index(self.n_active)
        except TypeError:
            raise OrbitDomainError(f"n_active = {self.n_active!r} is not an integer") from None
        if isinstance(self.n_active, bool) or not 1 <= n_active <= n:
            raise OrbitDomainError(f"n_active = {self.n_active!r} must be an integer in [1, N = {n}]")
        check_bodies(n)
        _check_masses(gm, n_active)
        times = _frozen_float_array("times", self.times)
        _check_times(times)
        check_states(times.size, n)
        object.__setattr__(self, "gm", gm)
        object.__setattr__(self, "positions", _frozen_float_array("positions", self.positions, (n, 3)))
        object.__setattr__(self, "velocities", _frozen_float_array("velocities", self.velocities, (n, 3)))
        object.__setattr__(self, "n_active", n_active)
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "kicks", _check_kicks(self.kicks, n, float(times[-1])))
        check_span(float(times[-1]), gm, self.positions, self.velocities, n_active)
        if self.speed_of_light is not None:
            c = self.speed_of_light
            if isinstance(c, bool) or not isinstance(c, (int, float, np.floating)) or not (math.isfinite(c) and c > 0):
                raise OrbitDomainError(f"speed_of_light = {c!r} must be a finite number > 0 (code units) or None")
            if n_active != n:
                raise OrbitDomainError("the post-Newtonian term needs every body massive (n_active = N): "
                                       f"n_active = {n_active}, N = {n}")
            object.__setattr__(self, "speed_of_light", float(c))
        forces = tuple(self.forces)
        for force in forces:
            if not isinstance(force, FORCES):
                raise OrbitDomainError(f"forces holds {force!r}; each must be one of "
                                       f"{', '.join(f.__name__ for f in FORCES)}")
            force.check(self)
        object.__setattr__(self, "forces", forces)

    @property
    def n_bodies(self) -> int:
        """Total number of bodies N, massive and test particles."""
        return self.gm.size

    def arcs(self) -> list[Arc]:
        """The run split at its kick times; without kicks, one arc from 0 to the last output holding every output."""
        starts = sorted({0.0, *(kick.time for kick in self.kicks)})
        last = float(self.times[-1])
        arcs = []
        for i, start in enumerate(starts):
            end = starts[i + 1] if i + 1 < len(starts) else last
            inside = (self.times >= start) & ((self.times < end) if i + 1 < len(starts) else (self.times <= end))
            kicks = tuple(kick for kick in self.kicks if kick.time == start)
            arcs.append(Arc(start, end, kicks, np.flatnonzero(inside)))
        return arcs


@dataclass(frozen=True, eq=False)
class NBodyResult:
    """States produced by one backend for an NBodyProblem, with the settings and timings of the run.

    ``times`` are the times the states are actually at (for WHFast, steps x dt, which can differ from the
    requested times by up to dt/2); compare against references evaluated at these times.
    """

    backend: str
    integrator: str
    positions: np.ndarray
    velocities: np.ndarray
    times: np.ndarray
    wall_time: float
    setup_time: float
    settings: dict
    version: str
    time_mode: str


# ---- progress of a running integration -------------------------------------------------------------------

_progress: contextvars.ContextVar = contextvars.ContextVar("orbits_nbody_progress", default=None)


@contextlib.contextmanager
def reporting(callback: Callable[[float], None]) -> Iterator[None]:
    """While inside, integrations report the fraction of the problem's time span done to `callback` (at most
    ten times a second, and once at the end)."""
    token = _progress.set((callback, [0.0]))
    try:
        yield
    finally:
        _progress.reset(token)


def report(done: float, total: float) -> None:
    """Called by the adapters as they go: tell the current `reporting` callback done / total (throttled)."""
    hook = _progress.get()
    if hook is None or total <= 0:
        return
    callback, last = hook
    now = time.perf_counter()
    if done >= total or now - last[0] >= 0.1:
        last[0] = now
        callback(min(1.0, float(done) / float(total)))


@contextlib.contextmanager
def python_sigint() -> Iterator[None]:
    """Run a call into an integrator library with Python's own Ctrl-C handler installed, and install it again
    after the call, whatever the library did.

    rebound's ``integrate`` installs a C handler for SIGINT of its own (it stops its loop, and the call raises
    KeyboardInterrupt) and leaves it installed when it returns, so a Ctrl-C later in the process, in Python
    code or during a heyoka run, only set rebound's flag and was lost. Python's handler is re-installed by
    setting the Python-level handler again (signal.signal re-registers the C function). Signal handlers belong
    to the main thread; elsewhere (a dask worker thread) the block runs unchanged."""
    handler = signal.getsignal(signal.SIGINT)
    guard = handler is not None and threading.current_thread() is threading.main_thread()
    if guard:
        signal.signal(signal.SIGINT, handler)
    try:
        yield
    finally:
        if guard:
            signal.signal(signal.SIGINT, handler)
