"""Integrations the pictures of perturbed orbits draw (orbits.perturb.plot): an orbit's secular motion
under J2 and J4 (secular_history), a frozen design's eccentricity vector (frozen_history), a repeat ground track
(ground_track), drag decay (decay_history) and Kozai-Lidov cycles (kozai_history), each with rebound and heyoka,
each run bounded before it starts. The problems and the mean elements come from orbits.validate.perturb, whose
scenes test the same closed forms.
"""

import math
from dataclasses import dataclass

import numpy as np

from orbits._common.constants import body
from orbits.core.perturb import oblateness, third_body
from orbits.validate import models
from orbits.validate.nbody import NBodyProblem, ZonalHarmonics
from orbits.validate.perturb import (
    DAY,
    SAMPLES,
    block_averages,
    drag_problem,
    grid,
    kozai_problem,
    mean_series,
    oblate_problem,
    orbit_elements,
    osculating,
    particle,
    scene_decay,
    scene_orbit,
)

# ---- shared ---------------------------------------------------
#: the argument of periapsis is drawn when the orbit's e exceeds this many J2 (R/p)**2: J2's short-period terms give
#: a circular orbit an osculating e of that order, whose periapsis then turns with the body, not secularly
DEFINED_PERIAPSIS_IN_K = 10.0
#: the longest decay the drag picture integrates (revolutions of the starting orbit)
MAX_DECAY_REVOLUTIONS = 500
#: outputs per revolution of the pictures' J2 runs: the osculating curves resolved near periapsis at e = 0.74, and
#: revolution averages free of the aliasing 16 samples leave there (their scatter about the line was 5 arcsec)
HISTORY_SAMPLES = 64
#: outputs per orbit of the perturber in the picture's Kozai-Lidov run (9.3 such orbits a Kozai timescale)
KOZAI_SAMPLES = 20
#: the longest Kozai-Lidov run a picture integrates (revolutions of the inner orbit): 2 cycles of the scene's triple
#: are 3,900
MAX_KOZAI_REVOLUTIONS = 20_000


def _picture_backends(backends, forces: bool) -> list[str]:
    """The backends to integrate with: those given, or each of rebound and heyoka that is installed (rebound's
    extra forces need REBOUNDx); a one-line error when none is."""
    import importlib.util

    from orbits.validate.backends import available

    if backends is not None:
        return list(backends)
    names = [name for name in ("rebound", "heyoka") if available(name)
             and not (name == "rebound" and forces and importlib.util.find_spec("reboundx") is None)]
    if not names:
        raise ModuleNotFoundError("the picture integrates with rebound (with REBOUNDx) or heyoka; neither is "
                                  "installed: pip install heyoka")
    return names


def _checked(rule, value, name: str):
    """`value` checked by one of orbits.validate.models' parameter rules; its ValueError becomes a one-line
    OrbitDomainError naming the parameter."""
    from orbits.core.errors import OrbitDomainError

    try:
        return rule(value)
    except ValueError as err:
        raise OrbitDomainError(f"{name} = {err}") from None


def _integrate(backends, problem):
    from orbits.validate.backends import integrate

    return {name: integrate(name, problem) for name in backends}


@dataclass(frozen=True, eq=False)
class SecularHistory:
    """The node (and, for an eccentric orbit, the argument of periapsis) of one orbit about an oblate body as each
    backend integrates it under the body's J2 and J4, beside the first-order closed form's secular lines: what
    orbits.plot.secular_elements draws.

    Times in days, angles in degrees, unwrapped and kept within 180 deg of the orbit's elements at t = 0.
    `osculating[backend][element]` holds the (K,) osculating values at `times`; `mean[backend][element]` the (B,)
    averages over each revolution, at `mean_times`; `lines[element]` = (value at t = 0, rate in deg/day), the
    closed form's rate (at the mean a, e, i) drawn through the first revolution's mean; `accuracy` = J2 (R/p)**2,
    the rates' relative error order.
    """

    title: str
    times: np.ndarray
    osculating: dict
    mean_times: np.ndarray
    mean: dict
    lines: dict
    accuracy: float


def secular_history(orbit, revolutions: int = 30, backends=None) -> SecularHistory:
    """Integrate `orbit` (an orbits.Orbit about a catalogue body with J2, one orbit; or the name of a J2 scene,
    J2_SCENES) under the body's J2 and J4 for `revolutions` (1 to 2000) with rebound and heyoka, and measure its
    node and periapsis: a SecularHistory. The orbit's elements are used as mean elements at t = 0."""
    from orbits._common.constants import body_with_gm
    from orbits.core.errors import OrbitDomainError
    from orbits.perturb.secular import oblate_body

    if isinstance(orbit, str):
        orbit = scene_orbit(orbit)
    if orbit.shape != ():
        raise OrbitDomainError(f"the history follows one orbit; this Orbit holds {orbit.shape} of them")
    revolutions = _checked(models._count(1, 2000), revolutions, "revolutions")
    orbit._require_ellipse("J2's secular history")
    primary = oblate_body(body_with_gm(orbit.mu) or "an unknown primary")
    a_m, e, inc, argp = orbit_elements(orbit)
    problem = oblate_problem(a_m, e, inc, argp, revolutions, samples=HISTORY_SAMPLES, primary=primary,
                              raan=float(orbit.raan), nu=float(orbit.nu))
    runs = _integrate(_picture_backends(backends, forces=True), problem)
    k = float(oblateness.oblateness_factor(a_m * (1 - e) * (1 + e), primary.j2, primary.j2_radius))
    names = ("node", "periapsis") if e > DEFINED_PERIAPSIS_IN_K * k else ("node",)
    day = math.sqrt(a_m**3 / primary.gm) / DAY
    starts = {"node": math.degrees(float(orbit.raan)), "periapsis": math.degrees(argp)}
    states, means = {}, {}
    for backend, run in runs.items():
        _, _, _, node, periapsis, _ = osculating(run.positions, run.velocities, 1, 1.0)
        series = mean_series(run.times, run.positions, run.velocities, samples=HISTORY_SAMPLES)
        both = {"node": (node, series.node), "periapsis": (periapsis, series.periapsis)}
        states[backend], means[backend] = {}, {}
        for name in names:
            instant, averaged = (np.degrees(x) for x in both[name])
            turns = 360.0 * round((starts[name] - instant[0]) / 360.0)
            states[backend][name], means[backend][name] = instant + turns, averaged + turns
    first = next(iter(runs.values()))
    series = mean_series(first.times, first.positions, first.velocities, samples=HISTORY_SAMPLES)
    mean_elements = (float(series.a.mean()), float(series.e.mean()), float(series.inc.mean()), 1.0, primary.j2,
                     primary.j2_radius / a_m)
    rates = {"node": oblateness.node_rate(*mean_elements), "periapsis": oblateness.periapsis_rate(*mean_elements)}
    mean_times = series.times * day
    lines = {}
    for name in names:
        rate = math.degrees(float(rates[name])) / day
        lines[name] = (float(means[next(iter(runs))][name][0] - rate * mean_times[0]), rate)
    title = (f"{primary.name}: a = {a_m / 1e3:.0f} km, e = {e:.3g}, i = {math.degrees(inc):.2f} deg; "
             f"{revolutions} revolutions ({float(problem.times[-1]) * day:.3g} d)")
    return SecularHistory(title, problem.times * day, states, mean_times, means, lines, k)


@dataclass(frozen=True, eq=False)
class FrozenHistory:
    """The mean eccentricity vector (e cos omega, e sin omega), averaged over each revolution, of two orbits of a
    frozen design as each backend integrates them under J2, J3 and J4: one started at the frozen e and omega
    (`frozen`), one started circular (`circular`), each {backend: (xi, eta)}; the design's `e` and `argp` (deg),
    the apsidal `period` (days) in which the circular start's vector circles the frozen point, `revolutions`
    integrated, `title`, and `short_period` J2 R / a, the order of J2's short-period terms by which the mean
    vector of an osculating start stands off the closed form's."""

    title: str
    frozen: dict
    circular: dict
    e: float
    argp: float
    period: float
    revolutions: int
    short_period: float


#: the longest frozen-orbit run a picture integrates (revolutions)
MAX_FROZEN_REVOLUTIONS = 4000


def frozen_revolutions(design) -> int:
    """Revolutions of one apsidal period 2 pi / (domega/dt) of a frozen design (orbits.perturb.secular.Design): what
    the circular start's eccentricity vector takes to circle the frozen point once."""
    primary, a_m = design.primary, design.semi_major_axis.to_value("m")
    e, inc = float(design.eccentricity.value), design.inclination.to_value("rad")
    rate = float(oblateness.periapsis_rate(1.0, e, inc, 1.0, primary.j2, primary.j2_radius / a_m))
    return math.ceil(2.0 * math.pi / abs(rate) / (2.0 * math.pi)) if rate != 0.0 else MAX_FROZEN_REVOLUTIONS + 1


def frozen_history(design, revolutions: int | None = None, backends=None) -> FrozenHistory:
    """Integrate a frozen design (orbits.perturb.secular.frozen) and a circular orbit of the same size and inclination
    under the body's J2, J3 and J4 with rebound and heyoka for `revolutions` (default: one apsidal period; at most
    MAX_FROZEN_REVOLUTIONS), and average their eccentricity vectors over each revolution: a FrozenHistory. Both
    start where their first revolution's mean elements are the design's (the frozen e and omega) and the circle's
    (e = 0): mean elements are what the closed form speaks of (_mean_start)."""
    from orbits.core.errors import OrbitDomainError

    primary, a_m = design.primary, design.semi_major_axis.to_value("m")
    e, inc = float(design.eccentricity.value), design.inclination.to_value("rad")
    argp = design.extra["argument_of_periapsis"].to_value("rad")
    needed = frozen_revolutions(design)
    revolutions = needed if revolutions is None else _checked(models._count(1, MAX_FROZEN_REVOLUTIONS), revolutions,
                                                              "revolutions")
    if revolutions > MAX_FROZEN_REVOLUTIONS:
        raise OrbitDomainError(f"one apsidal period is {needed} revolutions, more than the "
                               f"{MAX_FROZEN_REVOLUTIONS} a picture integrates: ask for at most that many revolutions")
    harmonics = ZonalHarmonics(primary.j2, primary.j2_radius / a_m, primary.j4 or 0.0, 0, primary.j3)
    names = _picture_backends(backends, forces=True)
    starts = [particle(1.0, *_mean_start(np.array([x * math.cos(argp), x * math.sin(argp)]), inc, argp, harmonics,
                                         names[0])) for x in (e, 0.0)]
    problem = NBodyProblem([1.0, 0.0, 0.0], [np.zeros(3)] + [x[0] for x in starts],
                           [np.zeros(3)] + [x[1] for x in starts], 1, grid(revolutions), forces=(harmonics,))
    runs = _integrate(names, problem)
    vectors = {index: {} for index in (1, 2)}
    for name, run in runs.items():
        for index in (1, 2):
            series = mean_series(run.times, run.positions, run.velocities, index)
            vectors[index][name] = (series.xi, series.eta)
    rate = float(oblateness.periapsis_rate(1.0, e, inc, 1.0, primary.j2, primary.j2_radius / a_m))
    day = math.sqrt(a_m**3 / primary.gm) / DAY
    title = (f"{design.altitude.to_value('km'):.6g} km at i = {math.degrees(inc):.6g} deg about "
             f"{primary.name}, {revolutions} revolutions ({revolutions * 2.0 * math.pi * day:.4g} d)")
    return FrozenHistory(title, vectors[1], vectors[2], e, math.degrees(argp), 2.0 * math.pi / abs(rate) * day,
                         revolutions, primary.j2 * primary.j2_radius / a_m)


#: corrections of an osculating start toward a given mean eccentricity vector (each a one-revolution integration)
MEAN_START_ITERATIONS = 3


def _mean_start(target: np.ndarray, inc: float, argp: float, harmonics, backend: str) -> tuple:
    """(e, inc, node, argp, true anomaly) of the osculating start, at the ascending node, whose first revolution's
    mean eccentricity vector (e cos omega, e sin omega) is `target`: the short-period terms of J2 (of order
    J2 R / a) shift the mean from the osculating start, so the start is corrected by that shift, measured by
    integrating one revolution, MEAN_START_ITERATIONS times (each halves the residual by orders of magnitude)."""
    start = target.copy()
    for _ in range(MEAN_START_ITERATIONS):
        e, w = float(np.hypot(*start)), float(np.arctan2(start[1], start[0])) if start.any() else argp
        r, v = particle(1.0, e, inc, 0.0, w, -w)
        problem = NBodyProblem([1.0, 0.0], [np.zeros(3), r], [np.zeros(3), v], 1, grid(1), forces=(harmonics,))
        series = mean_series(*(getattr(_integrate([backend], problem)[backend], k)
                               for k in ("times", "positions", "velocities")), 1)
        start = start + (target - np.array([series.xi[0], series.eta[0]]))
    e, w = float(np.hypot(*start)), float(np.arctan2(start[1], start[0]))
    return e, inc, 0.0, w, -w


@dataclass(frozen=True, eq=False)
class GroundTrack:
    """A repeat-ground-track design's track over one cycle as each backend integrates it under J2 and J4: per
    backend the geodetic-free (spherical) `longitude` and `latitude` (deg) at `times` (days), and the longitudes
    (deg, east of the first) of each ascending node, `nodes`; `closure_km` per backend, the distance along the
    equator from the first node to the one a cycle later (0 for an exact repeat), `revolutions`, `days`, `title`
    `accuracy` J2 (R/p)**2, the order of the first-order theory's error in the rates, and `equator_km_per_deg`."""

    title: str
    times: np.ndarray
    longitude: dict
    latitude: dict
    nodes: dict
    closure_km: dict
    revolutions: int
    days: int
    accuracy: float
    equator_km_per_deg: float


#: outputs per revolution of the ground-track picture's runs, and the most revolutions it integrates
TRACK_SAMPLES = 64
MAX_TRACK_REVOLUTIONS = 2000


def _ascending_nodes(times: np.ndarray, z: np.ndarray, longitude_unwrapped: np.ndarray) -> np.ndarray:
    """Longitudes (deg, unwrapped) where z crosses zero upward, by linear interpolation between outputs."""
    k = np.flatnonzero((z[:-1] < 0.0) & (z[1:] >= 0.0))
    share = -z[k] / (z[k + 1] - z[k])
    return longitude_unwrapped[k] + share * (longitude_unwrapped[k + 1] - longitude_unwrapped[k])


def ground_track(design, backends=None) -> GroundTrack:
    """Integrate a repeat-ground-track design (orbits.perturb.secular.repeat_ground_track), started at its ascending
    node on its mean orbit (oblateness.osculating_semi_major_axis), under the body's J2 and J4 with rebound and
    heyoka for its cycle (k nodal periods, at most MAX_TRACK_REVOLUTIONS), and follow it over the turning body: a
    GroundTrack."""
    from orbits.core.errors import OrbitDomainError

    primary, a_m = design.primary, design.semi_major_axis.to_value("m")
    e, inc = float(design.eccentricity.value), design.inclination.to_value("rad")
    revolutions, days = int(design.extra["revolutions"].value), int(design.extra["days"].value)
    if revolutions > MAX_TRACK_REVOLUTIONS:
        raise OrbitDomainError(f"a cycle of {revolutions} revolutions is more than the {MAX_TRACK_REVOLUTIONS} a "
                               f"picture integrates")
    time_unit = math.sqrt(a_m**3 / primary.gm)
    nodal = design.secular.nodal_period.to_value("s") / time_unit
    # started on the mean orbit: its osculating a at the node carries Brouwer's short-period term
    start = design.extra["osculating_semi_major_axis_at_node"].to_value("m") / a_m
    start_r, start_v = particle(start, e, inc, 0.0, 0.0, 0.0)
    harmonics = ZonalHarmonics(primary.j2, primary.j2_radius / a_m, primary.j4 or 0.0)
    times = np.arange(1, revolutions * TRACK_SAMPLES + TRACK_SAMPLES // 4 + 1) * nodal / TRACK_SAMPLES
    problem = NBodyProblem([1.0, 0.0], [np.zeros(3), start_r], [np.zeros(3), start_v], 1, times,
                           forces=(harmonics,))
    runs = _integrate(_picture_backends(backends, forces=True), problem)
    spin = 2.0 * math.pi / primary.rotation_period * (-1.0 if primary.retrograde else 1.0) * time_unit
    all_times = np.concatenate([[0.0], times])
    longitude, latitude, nodes, closure = {}, {}, {}, {}
    for name, run in runs.items():
        r = np.concatenate([[start_r], run.positions[:, 1] - run.positions[:, 0]])
        unwrapped = np.degrees(np.unwrap(np.arctan2(r[:, 1], r[:, 0])) - spin * all_times)
        crossings = np.concatenate([[0.0], _ascending_nodes(all_times, r[:, 2], unwrapped)])
        if crossings.size <= revolutions:
            raise OrbitDomainError(f"the integrated orbit crossed the equator northward {crossings.size - 1} times, "
                                   f"fewer than the cycle's {revolutions}")
        longitude[name] = (unwrapped + 180.0) % 360.0 - 180.0
        latitude[name] = np.degrees(np.arcsin(r[:, 2] / np.linalg.norm(r, axis=-1)))
        nodes[name] = crossings
        drift = (crossings[revolutions] + 180.0) % 360.0 - 180.0
        closure[name] = math.radians(drift) * primary.radius / 1e3
    title = (f"{revolutions} revolutions in {days} day{'s' if days > 1 else ''}: a = "
             f"{a_m / 1e3:.7g} km, i = {math.degrees(inc):.6g} deg, about {primary.name}")
    return GroundTrack(title, all_times * time_unit / DAY, longitude, latitude, nodes, closure, revolutions, days,
                       float(oblateness.oblateness_factor(a_m * (1 - e) * (1 + e), primary.j2, primary.j2_radius)),
                       math.radians(1.0) * primary.radius / 1e3)


@dataclass(frozen=True, eq=False)
class DecayHistory:
    """A circular orbit decaying by drag as each backend integrates it, until the closed form's end (the band's
    base or the breakdown altitude): what orbits.plot.drag_decay draws over the closed form. `decay` is the
    orbits.perturb.secular.DragDecay integrated; `times` (K,) in days; `altitude[backend]` (K,) the radius less the
    body's equatorial radius, in km; `mean_times` (B,) and `mean_altitude[backend]` (B,) the same averaged over
    each revolution of the starting orbit (which removes the small eccentricity drag keeps)."""

    decay: object
    times: np.ndarray
    altitude: dict
    mean_times: np.ndarray
    mean_altitude: dict


def decay_history(decay=None, backends=None) -> DecayHistory:
    """Integrate the circular orbit of `decay` (an orbits.perturb.secular.DragDecay; by default the drag_decay scene's)
    in its exponential band with rebound and heyoka from the start to the end of its lifetime, at most
    MAX_DECAY_REVOLUTIONS revolutions: a DecayHistory."""
    from orbits.core.errors import OrbitDomainError

    decay = decay or scene_decay()
    time_unit = math.sqrt(decay.a0**3 / decay.mu)
    end = decay.lifetime.to_value("s") / time_unit
    revolutions = end / (2.0 * math.pi)
    if not revolutions <= MAX_DECAY_REVOLUTIONS:
        raise OrbitDomainError(f"the decay lasts {revolutions:.4g} revolutions, more than the "
                               f"{MAX_DECAY_REVOLUTIONS} a picture integrates: draw the closed form alone")
    times = grid(math.floor(revolutions))
    times = np.append(times, end) if times.size == 0 or times[-1] < end else times
    runs = _integrate(_picture_backends(backends, forces=True), drag_problem(decay, times))
    radius = body(decay.primary).radius
    altitude = {name: (np.linalg.norm(run.positions[:, 1] - run.positions[:, 0], axis=-1) * decay.a0 - radius) / 1e3
                for name, run in runs.items()}
    days = times * time_unit / DAY
    return DecayHistory(decay, days, altitude, block_averages(days, SAMPLES),
                        {name: block_averages(values, SAMPLES) for name, values in altitude.items()})


@dataclass(frozen=True, eq=False)
class KozaiHistory:
    """The Kozai-Lidov cycles of the kozai_lidov scene's triple as each backend integrates them, with the
    quadrupole theory's marks: what orbits.plot.kozai_cycles draws.

    `times` (K,) in units of the Kozai timescale tau; per backend the osculating `eccentricity`, `inclination` (deg)
    and `constant` sqrt(1 - e**2) cos i, and that constant averaged over each orbit of the perturber
    (`mean_constant`, at `mean_times`), which removes the outer orbit's short-period terms; the theory's `e_max`,
    `inclination_at_e_max` (deg), the `start` value of sqrt(1 - e**2) cos i (which it conserves), the
    oscillation's `period` (tau) and `accuracy` eps_sa (the relative size of the terms it drops), the time of the
    `first_peak` of e (tau; None where the start is not a turning point of e); `title` names the triple and the
    span.
    """

    title: str
    times: np.ndarray
    eccentricity: dict
    inclination: dict
    constant: dict
    mean_times: np.ndarray
    mean_constant: dict
    e_max: float
    inclination_at_e_max: float
    start: float
    period: float
    accuracy: float
    first_peak: float | None = None


def _first_peak(e0: float, argp: float, e_range: tuple[float, float], period: float) -> float | None:
    """The time of the first e_max when the start is a turning point of e (sin 2 omega = 0, where de/dt vanishes):
    half a period from e_min, none from e_max (it is the start); None when the start is between the two, whose
    phase the picture does not mark."""
    e_min, e_max = e_range
    if abs(math.sin(2.0 * argp)) > 1e-12:
        return None
    if abs(e0 - e_min) <= 1e-9 * max(e0, 1e-300):
        return 0.5 * period
    return period if abs(e0 - e_max) <= 1e-9 * max(e0, 1e-300) else None


def kozai_history(inc_deg: float = 65.0, cycles: float = 2.0, backends=None, triple=None) -> KozaiHistory:
    """Integrate a hierarchical triple for `cycles` (0.1 to 4) oscillations of e with rebound and heyoka, output
    KOZAI_SAMPLES times an orbit of the perturber: a KozaiHistory. The triple is the kozai_lidov scene's (a test
    particle at a = 1, e0 = 0.01, omega = 90 deg, inclined inc_deg (45 to 80) to an equal mass's circular orbit
    at 12) or `triple`, an orbits.perturb.secular.KozaiLidov, in units of its inner a and G m0. A triple whose run
    would exceed MAX_KOZAI_REVOLUTIONS inner revolutions, or last less than one orbit of the perturber, is a
    one-line OrbitDomainError."""
    from orbits.core.errors import OrbitDomainError

    cycles = _checked(models._positive(4.0, "cycles", low=0.1), cycles, "cycles")
    if triple is None:
        inc_deg = _checked(models._positive(80.0, "deg", low=45.0), inc_deg, "inc_deg")
        e0, argp, a_out, mass_ratio, e_out = 0.01, 0.5 * math.pi, 12.0, 1.0, 0.0
        title = (f"a test particle at a = 1, e0 = {e0:g}, i0 = {inc_deg:g} deg, and an equal mass at {a_out:g} "
                 f"(circular), for {cycles:g} cycles")
    else:
        e0, inc_deg, argp = triple.e, math.degrees(triple.inc), triple.argp
        a_out, mass_ratio, e_out = triple.a_out / triple.a, triple.mass_ratio, triple.e_out
        title = (f"e0 = {e0:.4g}, i0 = {inc_deg:.4g} deg, omega0 = {math.degrees(argp):.4g} deg; m3 / m0 = "
                 f"{mass_ratio:.4g} at a_out / a = {a_out:.4g}, e_out = {e_out:.4g}; {cycles:g} cycles")
    tau = float(third_body.timescale(1.0, 1.0, mass_ratio, a_out, e_out))
    period = float(third_body.oscillation_period(e0, math.radians(inc_deg), argp, tau))
    revolutions = cycles * period / (2.0 * math.pi)  # bounded before any problem is built
    outer = 2.0 * math.pi * math.sqrt(a_out**3 / (1.0 + mass_ratio))
    if not revolutions <= MAX_KOZAI_REVOLUTIONS:
        raise OrbitDomainError(f"{cycles:g} Kozai-Lidov cycles last {revolutions:.4g} revolutions of the inner "
                               f"orbit, more than the {MAX_KOZAI_REVOLUTIONS} a picture integrates: a nearer or "
                               f"heavier perturber, or fewer cycles")
    if not cycles * period >= outer:
        raise OrbitDomainError(f"{cycles:g} Kozai-Lidov cycles last less than one orbit of the perturber, where "
                               f"the doubly averaged theory does not hold: more cycles or a farther perturber")
    problem, e_max, _, _ = kozai_problem(inc_deg, e0=e0, a_out=a_out, mass_ratio=mass_ratio, cycles=cycles,
                                         argp=argp, e_out=e_out)
    times = grid(math.floor(cycles * period / outer), outer, KOZAI_SAMPLES)
    problem = NBodyProblem(problem.gm, problem.positions, problem.velocities, problem.n_active, times)
    runs = _integrate(_picture_backends(backends, forces=False), problem)
    start = math.sqrt((1 - e0) * (1 + e0)) * math.cos(math.radians(inc_deg))
    eccentricity, inclination, constant = {}, {}, {}
    for name, run in runs.items():
        _, e, i, *_ = osculating(run.positions, run.velocities, 2, 1.0)
        eccentricity[name], inclination[name] = e, np.degrees(i)
        constant[name] = np.sqrt((1 - e) * (1 + e)) * np.cos(i)
    e_range = tuple(float(x) for x in third_body.eccentricity_range(e0, math.radians(inc_deg), argp))
    peak = _first_peak(e0, argp, e_range, period)
    return KozaiHistory(title, times / tau, eccentricity, inclination, constant,
                        block_averages(times / tau, KOZAI_SAMPLES),
                        {name: block_averages(values, KOZAI_SAMPLES) for name, values in constant.items()}, e_max,
                        math.degrees(math.acos(start / math.sqrt((1 - e_max) * (1 + e_max)))), start,
                        period / tau, float(third_body.averaging_parameter(1.0, a_out, e_out, mass_ratio)),
                        None if peak is None else peak / tau)
