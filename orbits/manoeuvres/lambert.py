"""Lambert's problem with astropy units: the transfer orbit from r1 to r2 in a given time of flight.

    >>> import astropy.units as u
    >>> from orbits import lambert
    >>> transfer = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    >>> transfer.v1.to(u.km / u.s).round(3)
    <Quantity [14.727, 27.069,  0.   ] km / s>
    >>> transfer.transfer_angle.to(u.deg).round(6), transfer.eccentricity.round(4)
    (<Quantity 90. deg>, <Quantity 0.4819>)

Izzo's algorithm with the cancellation-free forms of orbits.core.lambert (which says how a solution is chosen:
revolutions, branch, prograde and the plane normal). Every argument broadcasts: arrays of positions, times of
flight and revolution counts give arrays of transfers. The arrival point of the returned v1, propagated at 60
digits, is within 1e-13 |r2| on the hard cases of tests/core/test_lambert.py.
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits import display, inputs, units
from orbits.constants import Body
from orbits.core import elements
from orbits.core import lambert as lambert_core
from orbits.tables import quantity_table


@dataclass(frozen=True, eq=False, repr=False)
class LambertTransfer(display.Displayed):
    """A solved Lambert transfer; float64 SI fields that broadcast (vectors on the last axis).

    r1, r2 (m), tof (s), mu (m3/s2): the problem; revolutions and branch: which solution; v1, v2 (m/s),
    angle (rad, in (0, 2 pi), not counting complete revolutions), x (Izzo's variable) and a (m): the solution.
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
    def time_of_flight(self) -> u.Quantity:
        """tof (s)."""
        return self.tof << units.S

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
        return display.one_line("LambertTransfer", *parts)

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), NAMES, only)


NAMES = ["v1", "v2", "departure_speed", "arrival_speed", "transfer_angle", "total_angle", "semi_major_axis",
         "eccentricity", "time_of_flight"]


def lambert(
    r1: u.Quantity,
    r2: u.Quantity,
    tof: u.Quantity,
    primary: Body | str | u.Quantity = "Sun",
    revolutions: int | np.ndarray = 0,
    branch: str = "right",
    prograde: bool = True,
    normal: np.ndarray | u.Quantity | None = None,
) -> LambertTransfer:
    """Solve Lambert's problem: the conic about `primary` from r1 (length, (..., 3)) to r2 in the time tof (time).

    Parameters
    ----------
    r1, r2 : Quantity ['length'], (..., 3), positions relative to the primary's centre.
    tof : Quantity ['time'] > 0, time of flight.
    primary : a catalogue body (or its name), a mass or a GM (Quantity); default the Sun.
    revolutions : int >= 0 (or an array), complete revolutions before arrival.
    branch : "left" or "right": which of the two solutions when revolutions > 0 (Izzo's branches; "right" is
        lamberthub's and hapsira's low_path=True).
    prograde : motion counterclockwise about +z (True) or clockwise; ignored when `normal` is given.
    normal : 3-vector (any unit, or plain numbers), optional: the direction the orbit's angular momentum points
        to (its side of the r1, r2 plane). Required when r1 and r2 are opposite (transfer angle exactly pi).

    Returns
    -------
    LambertTransfer

    Raises OrbitDomainError for an infeasible revolution count (naming the minimum time) or bad input, and
    DegenerateOrbitError for collinear r1 and r2 without a usable normal. Accuracy: see orbits.core.lambert.
    """
    start = inputs.vector(r1, units.M, "position r1")
    end = inputs.vector(r2, units.M, "position r2")
    seconds = inputs.positive(tof, units.S, "time of flight")
    mu = inputs.gravitational_parameter(primary, "primary mass M")
    direction = None if normal is None else np.asarray(getattr(normal, "value", normal), dtype=float)
    solution = lambert_core.solve(start, end, seconds, mu, revolutions, branch, prograde, direction)
    shape = solution.x.shape
    vector_shape = (*shape, 3)
    return LambertTransfer(
        np.broadcast_to(start, vector_shape), np.broadcast_to(end, vector_shape), np.broadcast_to(seconds, shape),
        np.broadcast_to(mu, shape), np.broadcast_to(np.asarray(revolutions), shape), branch,
        solution.v1, solution.v2, solution.angle, solution.x, solution.semi_major_axis,
    )

