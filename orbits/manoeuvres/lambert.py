"""Lambert's problem with astropy units: the transfer orbit from r1 to r2 in a given time of flight.

    >>> import astropy.units as u
    >>> from orbits import lambert
    >>> transfer = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    >>> transfer.v1.to(u.km / u.s).round(3)
    <Quantity [14.727, 27.069,  0.   ] km / s>
    >>> transfer.transfer_angle.to(u.deg).round(6), transfer.eccentricity.round(4)
    (<Quantity 90. deg>, <Quantity 0.4819>)

Izzo's algorithm with the cancellation-free forms of orbits.core.manoeuvres.lambert (which says how a solution is
chosen:
revolutions, branch, prograde and the plane normal). Every argument broadcasts: arrays of positions, times of
flight and revolution counts give arrays of transfers. The arrival point of the returned v1, propagated at 60
digits, is within 1e-13 |r2| on the hard cases of tests/core/test_lambert.py.

Between two bodies on two dates, the positions come from the ephemeris (orbits.ephemeris.positions, heliocentric
ICRF) and
the transfer adds the patched-conic C3 and v_inf at both ends, exactly as orbits.Porkchop computes a cell:

    >>> trip = lambert("Earth", "Mars", depart="2026-11-26", arrive="2027-08-15")
    >>> round(float(trip.c3.to_value(u.km**2 / u.s**2)), 2), round(float(trip.arrival_v_inf.to_value(u.km / u.s)), 3)
    (15.33, 2.939)
"""

import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import SPEED_OF_LIGHT, Body
from orbits._common.tables import quantity_table
from orbits.core import frames
from orbits.core.checks import broadcast_shape
from orbits.core.errors import ILL_CONDITIONED, IllConditionedWarning, OrbitDomainError
from orbits.core.manoeuvres import lambert as lambert_core
from orbits.core.twobody import elements
from orbits.ephemeris import positions as ephemeris

if TYPE_CHECKING:
    from orbits.twobody.orbit import Orbit

#: the Sun's GM (m3/s2) of transfers between bodies: JPL DE430's, the mass that goes with the ephemeris
SUN_GM = ephemeris.DE430_GM["Sun"]
#: the north pole of the ecliptic of J2000 in the ICRF: a prograde transfer's angular momentum points to its side
ECLIPTIC_POLE = frames.ecliptic_to_equatorial(np.array([0.0, 0.0, 1.0]))


@dataclass(frozen=True, eq=False, repr=False)
class LambertTransfer(display.Displayed):
    """A solved Lambert transfer; float64 SI fields that broadcast (vectors on the last axis).

    r1, r2 (m), tof (s), mu (m3/s2): the problem; revolutions and branch: which solution; v1, v2 (m/s),
    angle (rad, in (0, 2 pi), not counting complete revolutions), x (Izzo's variable) and a (m): the solution;
    kappa: its conditioning (orbits.core.manoeuvres.lambert.arrival_conditioning).
    departure, arrival: the bodies' ephemeris states (heliocentric ICRF) for a transfer between bodies, else None.
    """

    r1: np.ndarray
    r2: np.ndarray
    tof: np.ndarray
    mu: np.ndarray
    revolutions: np.ndarray
    branch: str
    v1_si: np.ndarray
    v2_si: np.ndarray
    angle: np.ndarray
    x: np.ndarray
    a: np.ndarray
    kappa: np.ndarray
    departure: "ephemeris.BodyState | None" = None
    arrival: "ephemeris.BodyState | None" = None

    @property
    def shape(self) -> tuple[int, ...]:
        """The batch shape (() for one transfer)."""
        return self.tof.shape

    @cached_property
    def v1(self) -> u.Quantity:
        """Velocity at r1 (m/s) on departure."""
        return self.v1_si << units.M_PER_S

    @cached_property
    def v2(self) -> u.Quantity:
        """Velocity at r2 (m/s) on arrival."""
        return self.v2_si << units.M_PER_S

    @cached_property
    def departure_speed(self) -> u.Quantity:
        """|v1| (m/s)."""
        return np.linalg.norm(self.v1_si, axis=-1) << units.M_PER_S

    @cached_property
    def arrival_speed(self) -> u.Quantity:
        """|v2| (m/s)."""
        return np.linalg.norm(self.v2_si, axis=-1) << units.M_PER_S

    @cached_property
    def transfer_angle(self) -> u.Quantity:
        """theta in (0, 2 pi) (rad): the angle swept from r1 to r2 after the complete revolutions."""
        return self.angle << units.RAD

    @cached_property
    def total_angle(self) -> u.Quantity:
        """theta + 2 pi N (rad): the whole angle swept."""
        return self.angle + 2.0 * np.pi * self.revolutions << units.RAD

    @cached_property
    def semi_major_axis(self) -> u.Quantity:
        """a = s / (2 (1 - x**2)) (m): > 0 on ellipses, < 0 on hyperbolas, inf on the parabola."""
        return self.a << units.M

    @cached_property
    def eccentricity(self) -> u.Quantity:
        """|e| = |(v1 x h) / mu - r1 / |r1|| (dimensionless) of the transfer conic."""
        e = elements.eccentricity_vector(self.r1, self.v1_si, self.mu)
        return np.linalg.norm(e, axis=-1) << u.one

    @cached_property
    def conditioning(self) -> u.Quantity:
        """kappa (dimensionless): how far the arrival point may lie from r2, as a fraction of |r2|: the larger of
        its shift when r1, v1 and the time of flight move by their float64 rounding and the answer's own miss
        (orbits.core.manoeuvres.lambert.arrival_conditioning). v1 reaches r2 within 20 kappa plus 1e-12; past 1e-8
        its digits cannot all be flown, and solving it warned."""
        return self.kappa << u.one

    @cached_property
    def time_of_flight(self) -> u.Quantity:
        """tof (s)."""
        return self.tof << units.S

    # ---- between bodies: patched conics -------------------------------------------------------------------
    def _bodies(self, quantity):
        if self.departure is None:
            raise OrbitDomainError(f"{quantity} needs the bodies at both ends: lambert('Earth', 'Mars', depart=..., "
                                   f"arrive=...)")
        return self.departure, self.arrival

    @cached_property
    def departure_v_inf(self) -> u.Quantity:
        """|v1 - v_departure body| (m/s): the hyperbolic excess speed at launch."""
        start, _ = self._bodies("the departure v_inf")
        return np.linalg.norm(self.v1_si - start.v_si, axis=-1) << units.M_PER_S

    @cached_property
    def c3(self) -> u.Quantity:
        """C3 = |v1 - v_departure body|**2 (m2/s2): the launch energy."""
        return self.departure_v_inf**2

    @cached_property
    def arrival_v_inf(self) -> u.Quantity:
        """|v2 - v_arrival body| (m/s): the hyperbolic excess speed on arrival."""
        _, end = self._bodies("the arrival v_inf")
        return np.linalg.norm(self.v2_si - end.v_si, axis=-1) << units.M_PER_S

    # ---- the transfer's elements ------------------------------------------------------------------------------
    @cached_property
    def orbit(self) -> "Orbit":
        """The transfer conic as an Orbit at departure: in the ecliptic of J2000 between bodies (their ICRF states
        turned), else in the frame of r1 and r2."""
        from orbits.twobody.orbit import Orbit

        r, v = self.r1, self.v1_si
        if self.departure is not None:
            r, v = frames.equatorial_to_ecliptic(r), frames.equatorial_to_ecliptic(v)
        return Orbit.from_vectors(self.mu << units.M3_PER_S2, r << units.M, v << units.M_PER_S)

    @cached_property
    def inclination(self) -> u.Quantity:
        """i (rad) of the transfer plane (to the ecliptic of J2000 between bodies)."""
        return self.orbit.inclination

    @cached_property
    def ascending_node(self) -> u.Quantity:
        """Omega (rad) of the transfer conic."""
        return self.orbit.ascending_node

    @cached_property
    def argument_of_periapsis(self) -> u.Quantity:
        """omega (rad) of the transfer conic."""
        return self.orbit.argument_of_periapsis

    @cached_property
    def periapsis_distance(self) -> u.Quantity:
        """q (m) of the transfer conic."""
        return self.orbit.periapsis_distance

    @cached_property
    def departure_true_anomaly(self) -> u.Quantity:
        """nu (rad) at departure."""
        return self.orbit.true_anomaly

    def __repr__(self) -> str:
        """E.g. "LambertTransfer(|v1| = 30.81575 km / s, |v2| = 18.92596 km / s, theta = 90 deg, a = 1.075769 AU,
        e = 0.481889, tof = 200 d, about Sun)" (on one line)."""
        parts = ["|v1| = " + display.summary(self.departure_speed, unit=u.km / u.s),
                 "|v2| = " + display.summary(self.arrival_speed, unit=u.km / u.s),
                 "theta = " + display.summary(self.transfer_angle, unit=u.deg),
                 "a = " + display.summary(self.semi_major_axis),
                 "e = " + display.summary(self.eccentricity),
                 "tof = " + display.summary(self.time_of_flight),
                 f"about {display.body_name(self.mu)}"]
        if np.any(self.revolutions > 0):
            parts.insert(-1, f"N = {display.values_text(self.revolutions)} ({self.branch})")
        if self.departure is not None:
            start, end = (f"{s.body} {ephemeris.tdb_iso(s.epoch)[:10]}" for s in (self.departure, self.arrival))
            parts[-1] = f"{start} -> {end}, about the Sun"
            parts.insert(0, "C3 = " + display.summary(self.c3, digits=4))
        return display.one_line("LambertTransfer", *parts)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), NAMES, only)


NAMES = ["c3", "departure_v_inf", "arrival_v_inf", "v1", "v2", "departure_speed", "arrival_speed", "transfer_angle",
         "total_angle", "semi_major_axis", "eccentricity", "inclination", "ascending_node", "argument_of_periapsis",
         "periapsis_distance", "departure_true_anomaly", "time_of_flight", "conditioning"]


def lambert(
    r1: u.Quantity | str,
    r2: u.Quantity | str,
    tof: u.Quantity | None = None,
    primary: Body | str | u.Quantity = "Sun",
    revolutions: int | np.ndarray = 0,
    branch: str | None = None,
    prograde: bool | None = None,
    normal: np.ndarray | u.Quantity | None = None,
    *,
    depart: Any = None,
    arrive: Any = None,
    source: str = "auto",
) -> LambertTransfer:
    """Solve Lambert's problem: the conic about `primary` from r1 (length, (..., 3)) to r2 in the time tof (time).

    Parameters
    ----------
    r1, r2 : Quantity ['length'], (..., 3), positions relative to the primary's centre; or two ephemeris bodies
        by name ("Earth", "Mars", see orbits.ephemeris.positions.points()), with `depart` and `arrive` instead of `tof`.
    tof : Quantity ['time'] > 0, time of flight.
    primary : a catalogue body (or its name), a mass or a GM (Quantity); default the Sun. Between bodies it is
        the Sun with DE430's GM (SUN_GM), the mass that goes with the ephemeris.
    revolutions : int >= 0 (or an array), complete revolutions before arrival.
    branch : "left" or "right": which of the two solutions when revolutions > 0 (Izzo's branches; "right", the
        default, is lamberthub's and hapsira's low_path=True). Given with no revolution at all, an error: a
        zero-revolution transfer has one solution.
    prograde : motion counterclockwise about +z (True, the default) or clockwise (False); between bodies, about
        the ecliptic pole of J2000. Given with `normal`, an error: the normal sets the sense of motion.
    normal : 3-vector (any unit, or plain numbers), optional: the direction the orbit's angular momentum points
        to (its side of the r1, r2 plane). Required when r1 and r2 are opposite (transfer angle exactly pi).
    depart, arrive : dates (astropy Time or ISO strings, UTC unless they name a scale) of a transfer between
        bodies; the time of flight is their difference.
    source : the ephemeris between bodies: "auto", "de421" or "builtin".

    Returns
    -------
    LambertTransfer; between bodies it also has c3, departure_v_inf and arrival_v_inf, the patched-conic excess
    energy and speeds, and its elements are in the ecliptic of J2000.

    Raises OrbitDomainError for an infeasible revolution count (naming the minimum time) or bad input, and
    DegenerateOrbitError for collinear r1 and r2 without a usable normal. Accuracy: see orbits.core.manoeuvres.lambert.
    """
    branch, prograde = _sense(revolutions, branch, prograde, normal)
    if isinstance(r1, str) or isinstance(r2, str):
        return _between_bodies(r1, r2, tof, primary, revolutions, branch, prograde, normal, depart, arrive, source)
    if depart is not None or arrive is not None:
        raise OrbitDomainError("depart and arrive are dates of a transfer between bodies: give r1 and r2 as body "
                               "names ('Earth', 'Mars'), or positions with tof")
    if tof is None:
        raise OrbitDomainError("give the time of flight tof (or bodies with depart and arrive dates)")
    start = inputs.vector(r1, units.M, "position r1")
    end = inputs.vector(r2, units.M, "position r2")
    mu = inputs.gravitational_parameter(primary, "primary mass M")
    direction = None if normal is None else np.asarray(getattr(normal, "value", normal), dtype=float)
    return _solve(start, end, inputs.positive(tof, units.S, "time of flight"), mu, revolutions, branch, prograde,
                  direction)


def _solve(start, end, seconds, mu, revolutions, branch, prograde, direction, departure=None, arrival=None):
    _refuse_relativistic(_chord_speed(start, end, seconds), "at least")  # before the solver meets such a flight
    solution = lambert_core.solve(start, end, seconds, mu, revolutions, branch, prograde, direction)
    _refuse_relativistic(_fastest(solution), "")
    return _transfer(solution, start, end, seconds, mu, revolutions, branch, departure, arrival)


def _refuse_relativistic(speeds: np.ndarray, bound: str) -> None:
    """OrbitDomainError where a transfer's speed (m/s; `bound` "at least" for the chord's) is not Newtonian."""
    if np.any(~_newtonian(speeds)):
        fastest = float(np.max(speeds))
        raise OrbitDomainError(f"the transfer needs {bound + ' ' if bound else ''}{fastest / 1e3:.4g} km/s, "
                               f"{fastest / SPEED_OF_LIGHT:.3g} of the speed of light, where two-body Newtonian "
                               f"gravity no longer holds: a longer flight")


def _chord_speed(start, end, seconds) -> np.ndarray:
    """|r2 - r1| / tof (m/s): the mean speed along the chord, which the transfer's path reaches at some point."""
    start, end = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    broadcast_shape(r1=start.shape[:-1], r2=end.shape[:-1], tof=np.shape(seconds))  # the core's names for them
    with np.errstate(over="ignore"):
        return np.linalg.norm(end - start, axis=-1) / np.asarray(seconds)


def newtonian_transfers(start: np.ndarray, end: np.ndarray, seconds: np.ndarray, mu: float,
                        direction: np.ndarray) -> tuple["LambertTransfer", np.ndarray]:
    """The zero-revolution transfers of a batch (r1, r2 (n, 3) in m, tof (n,) in s > 0, the side `direction` of the
    angular momentum) that Newtonian two-body gravity describes, and which of the n they are (a boolean mask): a
    flight whose speed reaches 1 % of the speed of light (two dates hours apart across the solar system) is left
    out, where `lambert` refuses the whole batch."""
    kept = _newtonian(_chord_speed(start, end, seconds))  # before the solver meets such a flight
    solution = lambert_core.solve(start[kept], end[kept], seconds[kept], mu, 0, "right", True, direction)
    newtonian = _newtonian(_fastest(solution))
    kept[kept] = newtonian
    solution = lambert_core.Solution(*(np.asarray(field)[newtonian] for field in solution))
    return _transfer(solution, start[kept], end[kept], seconds[kept], mu, 0, "right"), kept


def _fastest(solution) -> np.ndarray:
    """max(|v1|, |v2|) (m/s) of each transfer."""
    return np.max(np.linalg.norm(np.stack([solution.v1, solution.v2]), axis=-1), axis=0)


def _newtonian(speeds: np.ndarray) -> np.ndarray:
    """Where Newtonian two-body gravity describes a transfer: speeds below 0.01 c, (v / c)**2 < 1e-4."""
    return speeds < 0.01 * SPEED_OF_LIGHT


def _transfer(solution, start, end, seconds, mu, revolutions, branch, departure=None, arrival=None):
    """The LambertTransfer of a core solution, with its conditioning (and a warning where it is poor)."""
    shape = solution.x.shape
    vector_shape = (*shape, 3)
    r1, r2 = np.broadcast_to(start, vector_shape), np.broadcast_to(end, vector_shape)
    tof, mu = np.broadcast_to(seconds, shape), np.broadcast_to(mu, shape)
    kappa = lambert_core.arrival_conditioning(r1, solution.v1, r2, tof, mu)
    _warn_if_ill_conditioned(kappa)
    return LambertTransfer(r1, r2, tof, mu, np.broadcast_to(np.asarray(revolutions), shape), branch, solution.v1,
                           solution.v2, solution.angle, solution.x, solution.semi_major_axis, kappa, departure,
                           arrival)


def _warn_if_ill_conditioned(kappa):
    """IllConditionedWarning (one line) when a transfer's conditioning makes the digits of v1 unflyable."""
    worst = float(np.max(kappa, initial=0.0))
    if worst > ILL_CONDITIONED:
        which = "" if np.ndim(kappa) == 0 else f" ({int(np.sum(kappa > ILL_CONDITIONED))} of " \
                                                f"{np.size(kappa)} transfers)"
        digits = (f"v1 has about {max(0, int(-np.log10(worst)))} meaningful digits" if np.isfinite(worst) else
                  "a rounding sends the flight through the focus: no digit of v1 means anything")
        warnings.warn(f"ill-conditioned transfer{which}: float64 rounding, of the inputs or of the answer, moves the "
                      f"arrival by up to {worst:.2g} of |r2|; {digits}", IllConditionedWarning, stacklevel=4)


def transfer_ends(departure: str, target: str, what: str) -> list[str]:
    """The ephemeris names of the two ends of a transfer about the Sun (for `what`, "lambert" or "porkchop"): any
    point of the ephemeris or a body of ephemeris.PROPAGATED, but not the Sun, the barycentre, or one body twice."""
    names = [ephemeris.point_name(b) for b in (departure, target)]
    for name in names:
        if name in ("Sun", "solar system barycentre"):
            raise OrbitDomainError(f"{what}: {name} cannot be an end of a transfer about the Sun; give planets, "
                                   f"Pluto, the Moon, {', '.join(ephemeris.PROPAGATED[:-1])} or "
                                   f"{ephemeris.PROPAGATED[-1]}")
    if names[0] == names[1]:
        raise OrbitDomainError(f"{what}: both ends are {names[0]}")
    return names


def _between_bodies(departure, target, tof, primary, revolutions, branch, prograde, normal, depart, arrive, source):
    """The transfer from body `departure` on the date `depart` to body `target` on `arrive`, about the Sun."""
    if not (isinstance(departure, str) and isinstance(target, str)):
        raise OrbitDomainError("give both ends as body names ('Earth', 'Mars') or both as positions")
    if tof is not None:
        raise OrbitDomainError("between bodies the time of flight is arrive - depart: give the dates, not tof")
    if depart is None or arrive is None:
        raise OrbitDomainError(f"a transfer from {departure} to {target} needs the dates depart=... and arrive=...")
    if not (isinstance(primary, str) and primary.strip().lower() == "sun"):
        raise OrbitDomainError("a transfer between bodies is about the Sun (their states are heliocentric)")
    names = transfer_ends(departure, target, "lambert")
    start = ephemeris.state(names[0], depart, "Sun", source=source)
    end = ephemeris.state(names[1], arrive, "Sun", source=source)
    if not (start.epoch.isscalar and end.epoch.isscalar):
        raise OrbitDomainError("lambert between bodies takes one departure and one arrival date")
    seconds = ((end.epoch.jd1 - start.epoch.jd1) + (end.epoch.jd2 - start.epoch.jd2)) * 86_400.0
    if not seconds > 0:
        raise OrbitDomainError(f"arrive ({ephemeris.tdb_iso(end.epoch)} TDB) must be after depart "
                               f"({ephemeris.tdb_iso(start.epoch)} TDB)")
    direction = (ECLIPTIC_POLE if prograde else -ECLIPTIC_POLE) if normal is None else np.asarray(
        getattr(normal, "value", normal), dtype=float)
    return _solve(start.r_si, end.r_si, np.asarray(seconds, dtype=float), np.asarray(SUN_GM), revolutions, branch,
                  prograde, direction, start, end)


def _sense(revolutions, branch, prograde, normal) -> tuple[str, bool]:
    """(branch, prograde) with their defaults, refusing what cannot apply: a branch when no transfer makes a
    revolution (it has one solution), and prograde (or retrograde) together with a normal, which sets the sense."""
    if branch is not None and not np.any(np.asarray(revolutions) > 0):
        raise OrbitDomainError(f"branch = {branch!r} chooses between the two solutions of a transfer with revolutions "
                               f"> 0; with revolutions = 0 there is one: leave branch out")
    if prograde is not None and normal is not None:
        sense = "prograde" if prograde else "retrograde"
        raise OrbitDomainError(f"{sense} and a normal both set the sense of motion; give one (the normal's side of "
                               f"the r1, r2 plane is where the angular momentum points)")
    return ("right" if branch is None else branch), (True if prograde is None else bool(prograde))
