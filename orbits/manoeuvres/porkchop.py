"""Porkchop plots: departure C3 and arrival v_inf of the ballistic transfers on a grid of launch and arrival dates.

    >>> import astropy.units as u
    >>> from orbits import Porkchop
    >>> p = Porkchop.between("Earth", "Mars", launch=("2026-09-01", "2027-01-31"),
    ...                      arrival=("2027-06-01", "2028-03-01"), step=5 * u.day)
    >>> best = p.minimum_c3
    >>> best.launch.tdb.iso[:10], round(float(best.c3.to_value(u.km**2 / u.s**2)), 2)
    ('2026-10-31', 9.18)

Each cell (launch date t1, arrival date t2 > t1) is one zero-revolution Lambert problem about the Sun from the
departure body's heliocentric position at t1 to the arrival body's at t2 (orbits.lambert, the whole grid in one
vectorised call), on the prograde solution: the transfer's angular momentum on the north side of the ecliptic of
J2000, the side the planets' orbits turn to. Then

    C3 = |v1 - v_departure_body(t1)|**2,   v_inf at arrival = |v2 - v_arrival_body(t2)|,

the patched-conic hyperbolic excess energy at launch and speed at arrival (the planets' own gravity ignored).
Positions and velocities are heliocentric ICRF from orbits.ephemeris.positions (JPL DE421, or astropy's built-in
ephemeris
without the extra); the frame does not change C3 or v_inf. The Sun's GM is DE430's (Folkner et al. 2014), the mass
that goes with the ephemeris: orbits.ephemeris.positions.DE430_GM["Sun"]. Cells whose arrival is not after the launch,
and cells whose transfer would reach 1 % of the speed of light (dates hours apart: two-body Newtonian gravity no
longer holds), are invalid: masked in every grid, never a number.

The C3 of NASA's Earth-to-Mars mission design handbook matches departures from the Earth-Moon barycentre ("EMB"
here), not from the Earth's centre, which moves 12.5 m/s about it: from the Earth C3 differs by up to
2 v_inf x 12.5 m/s (0.8 % of a 9 km2/s2 C3).

Tests (tests/api/test_porkchop.py): the eight transfers NASA/TM-2010-216764 (Burke, Falck and McGuire 2010,
"Earth-to-Mars Mission Opportunities 2026 to 2045") tabulates for 2026, 2028 and 2031, recomputed from the
Earth-Moon barycentre on their dates, have its C3 to 0.10 % and its arrival v_inf to 0.03 %, and a 1-day grid of
each window finds its least C3 within two days of the table's dates (its figures as transcribed: see the tests);
the returned v1, propagated by the mpmath reference (orbits.tools.reference), reaches the arrival body as astropy
reads it from DE421 to 1.1e-14 of its distance; C3 and v_inf recomputed from astropy's DE421 velocities; coarser
grids miss the least C3 by more as their step grows.
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import astropy.units as u
import numpy as np
from astropy.time import Time, TimeDelta
from astropy.utils.masked import Masked

from orbits._common import display, inputs, units
from orbits._common.tables import quantity_table
from orbits.core.errors import OrbitDomainError
from orbits.ephemeris import positions as ephemeris
from orbits.manoeuvres.lambert import ECLIPTIC_POLE, SUN_GM, newtonian_transfers, transfer_ends

#: the largest grid computed (cells): 4 million cells take about 0.5 GB of float64 arrays
MAX_CELLS = 4_000_000
KM2_PER_S2 = u.km**2 / u.s**2


def _window(value: Any, name: str) -> tuple[Time, Time]:
    """(start, end) as TDB Times from a pair of dates (Time or ISO strings), start not after end."""
    try:
        start, end = value
    except (TypeError, ValueError):
        raise OrbitDomainError(f"{name} window: give (start, end) dates, e.g. ('2026-09-01', '2027-01-31'); "
                               f"got {value!r}") from None
    start, end = (Time(*ephemeris.tdb_julian_dates(ephemeris.epoch(d)), format="jd", scale="tdb")
                  for d in (start, end))
    if not (start.isscalar and end.isscalar):
        raise OrbitDomainError(f"{name} window: start and end must each be one date")
    if end < start:
        raise OrbitDomainError(f"{name} window: the end {end.iso[:16]} TDB is before the start {start.iso[:16]} TDB")
    return start, end


def _date_count(start: Time, end: Time, step_days: float) -> int:
    """How many dates start, start + step, ... reach up to end (within a microsecond): counted, not made."""
    span = float((end - start).to_value(u.day))
    return int(np.floor(span / step_days + 1e-9)) + 1


def _count(n: int) -> str:
    """A count with thousands separators, or to 3 digits beyond 1e15 (where a float's span / step has no more)."""
    return f"{n:,}" if n < 1e15 else f"{n:.3g}"


def _dates(start: Time, count: int, step_days: float) -> Time:
    """start, start + step, ... (`count` dates), TDB."""
    return start + TimeDelta(np.arange(count) * step_days, format="jd", scale="tdb")


def _masked(values: np.ndarray, valid: np.ndarray, unit: u.UnitBase) -> Masked:
    """A masked Quantity: the invalid cells masked (their NaN never shown)."""
    return Masked(values << unit, mask=~valid)


def _date_text(when: Time) -> str:
    return f"{when.tdb.iso[:10]}"


def _edges(row: int, col: int, shape: tuple[int, int]) -> tuple[str, ...]:
    """The sides of an (arrival, launch) grid the cell (row, col) lies on, along axes of more than one date."""
    sides = []
    for index, size, axis in ((col, shape[1], "launch"), (row, shape[0], "arrival")):
        if size > 1 and index in (0, size - 1):
            sides.append(f"{'first' if index == 0 else 'last'} {axis} date")
    return tuple(sides)


@dataclass(frozen=True, eq=False, repr=False)
class PorkchopMinimum(display.Displayed):
    """The grid cell where one figure of merit (`kind`: C3, arrival v_inf or total v_inf) is least: its dates and
    the transfer's C3 (m2/s2), departure and arrival v_inf (m/s) and time of flight (s), SI floats. `edges` names
    the sides of the grid the cell lies on ("first launch date", ...; only along an axis of more than one date):
    a least value there may be no minimum at all, the merit still falling outside the windows."""

    kind: str
    launch: Time
    arrival: Time
    c3_si: float
    departure_v_inf_si: float
    arrival_v_inf_si: float
    tof_si: float
    edges: tuple[str, ...] = ()

    @property
    def edge_note(self) -> str | None:
        """A sentence when the cell lies on the grid's edge, else None."""
        if not self.edges:
            return None
        return (f"least {self.kind} on the grid's edge ({' and '.join(self.edges)}): the minimum may lie outside "
                f"the windows")

    @property
    def c3(self) -> u.Quantity:
        """C3 = v_inf**2 at departure (m2/s2)."""
        return self.c3_si << units.M**2 / units.S**2

    @property
    def departure_v_inf(self) -> u.Quantity:
        """|v1 - v_departure_body| (m/s)."""
        return self.departure_v_inf_si << units.M_PER_S

    @property
    def arrival_v_inf(self) -> u.Quantity:
        """|v2 - v_arrival_body| (m/s)."""
        return self.arrival_v_inf_si << units.M_PER_S

    @property
    def total_v_inf(self) -> u.Quantity:
        """Departure plus arrival v_inf (m/s)."""
        return self.departure_v_inf_si + self.arrival_v_inf_si << units.M_PER_S

    @property
    def time_of_flight(self) -> u.Quantity:
        """Arrival minus launch date (s)."""
        return self.tof_si << units.S

    @property
    def launch_jd_tdb(self) -> u.Quantity:
        """The launch date as a TDB Julian date (d): for machines (JSON)."""
        return float(self.launch.tdb.jd) << u.day

    @property
    def arrival_jd_tdb(self) -> u.Quantity:
        """The arrival date as a TDB Julian date (d): for machines (JSON)."""
        return float(self.arrival.tdb.jd) << u.day

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} of MINIMUM_NAMES (or `only` those)."""
        return quantity_table(lambda name: getattr(self, name), MINIMUM_NAMES, only)

    def _display_quantities(self) -> dict[str, u.Quantity]:
        return {k: v for k, v in self.quantities().items() if not k.endswith("_jd_tdb")}

    def __repr__(self) -> str:
        """E.g. "PorkchopMinimum(C3, launch 2026-11-05, arrival 2027-09-02, C3 = 8.86 km2 / s2, ...)"."""
        return display.one_line(
            "PorkchopMinimum", self.kind, f"launch {_date_text(self.launch)}", f"arrival {_date_text(self.arrival)}",
            "C3 = " + display.summary(self.c3, digits=4), "v_inf arrival = " + display.summary(self.arrival_v_inf,
                                                                                            digits=4),
            "tof = " + display.summary(self.time_of_flight, digits=4),
            f"on the grid's edge ({', '.join(self.edges)})" if self.edges else "")


#: what PorkchopMinimum.quantities() lists
MINIMUM_NAMES = ("c3", "departure_v_inf", "arrival_v_inf", "total_v_inf", "time_of_flight", "launch_jd_tdb",
                 "arrival_jd_tdb")
#: the minima a Porkchop reports, by the prefix of their names in Porkchop.quantities()
MINIMA = {"min_c3_": "minimum_c3", "min_arrival_v_inf_": "minimum_arrival_v_inf", "min_total_": "minimum_total"}
#: the names of a Porkchop's quantities: each minimum's, after its prefix
QUANTITY_NAMES = [prefix + name for prefix in MINIMA for name in MINIMUM_NAMES]


@dataclass(frozen=True, eq=False, repr=False)
class Porkchop(display.Displayed):
    """Ballistic transfers from `departure` to `target` on a grid: rows are arrival dates, columns launch dates.

    SI float64 fields: r/v of the departure body at each launch date (n, 3) and of the target at each arrival date
    (m, 3), the transfer velocities v1_si, v2_si (m, n, 3) (NaN where invalid), valid (m, n) and the Sun's GM.
    Build with Porkchop.between.
    """

    departure: str
    target: str
    launch_dates: Time
    arrival_dates: Time
    r_departure: np.ndarray
    v_departure: np.ndarray
    r_target: np.ndarray
    v_target: np.ndarray
    v1_si: np.ndarray
    v2_si: np.ndarray
    valid: np.ndarray
    mu: float
    source: str

    @classmethod
    def between(cls, departure: str, target: str, launch: tuple[Any, Any], arrival: tuple[Any, Any],
                step: u.Quantity = 1 * u.day, *, source: str = "auto") -> "Porkchop":
        """Solve the zero-revolution prograde Lambert transfer of every (launch, arrival) pair on the grid.

        Parameters
        ----------
        departure, target : ephemeris points (orbits.ephemeris.positions.points()), different, neither the Sun nor the
            solar-system barycentre (any case: "earth", "Mars").
        launch, arrival : (start, end) dates, astropy Times or ISO strings (UTC unless they name a scale).
        step : Quantity ['time'] > 0, the spacing of both date axes (default 1 d).
        source : the ephemeris: "auto", "de421" or "builtin".

        Raises OrbitDomainError when no arrival date follows a launch date, a date is outside the ephemeris, the
        grid exceeds MAX_CELLS, or a body is not a planet-like point (UnknownNameError for an unknown name).
        """
        names = transfer_ends(departure, target, "porkchop")
        step_days = inputs.single(inputs.positive, step, units.S, "date step") / 86400.0
        launch_window, arrival_window = _window(launch, "launch"), _window(arrival, "arrival")
        if arrival_window[1] <= launch_window[0]:
            raise OrbitDomainError(
                f"porkchop: the arrival window ends ({arrival_window[1].iso[:16]} TDB) before the launch window "
                f"starts ({launch_window[0].iso[:16]} TDB): no transfer has a positive time of flight")
        counts = _date_count(*launch_window, step_days), _date_count(*arrival_window, step_days)
        if counts[0] * counts[1] > MAX_CELLS:  # before any date is made
            raise OrbitDomainError(f"porkchop: {_count(counts[0])} launch x {_count(counts[1])} arrival dates = "
                                   f"{_count(counts[0] * counts[1])} cells; at most {MAX_CELLS:,}: take a longer "
                                   f"step or shorter windows")
        launches, arrivals = _dates(launch_window[0], counts[0], step_days), _dates(arrival_window[0], counts[1],
                                                                                     step_days)
        start = ephemeris.state(names[0], launches, "Sun", source=source)
        end = ephemeris.state(names[1], arrivals, "Sun", source=source)
        return cls._solved(names, launches, arrivals, start, end)

    @classmethod
    def _solved(cls, names, launches, arrivals, start, end) -> "Porkchop":
        """Solve the valid cells in one lambert call and lay the velocities out on the (arrival, launch) grid."""
        tof = (arrivals.tdb.jd1[:, None] - launches.tdb.jd1[None, :]) + (
            arrivals.tdb.jd2[:, None] - launches.tdb.jd2[None, :])
        tof = tof * 86400.0
        valid = tof > 0
        rows, cols = np.nonzero(valid)
        transfer, newtonian = newtonian_transfers(start.r_si[cols], end.r_si[rows], tof[valid], SUN_GM,
                                                  ECLIPTIC_POLE)
        valid[rows[~newtonian], cols[~newtonian]] = False
        if not np.any(valid):
            raise OrbitDomainError("porkchop: every transfer on the grid would need 1 % of the speed of light or "
                                   "more, where two-body Newtonian gravity no longer holds: give arrival dates "
                                   "at least a day after the launch dates")
        v1 = np.full(valid.shape + (3,), np.nan)
        v2 = np.full(valid.shape + (3,), np.nan)
        v1[valid], v2[valid] = transfer.v1_si, transfer.v2_si
        source, accuracy = ephemeris.provenance(start, end)
        return cls(names[0], names[1], launches, arrivals, start.r_si, start.v_si, end.r_si, end.v_si, v1, v2,
                   valid, SUN_GM, source + (f"; {accuracy}" if accuracy else ""))

    @property
    def shape(self) -> tuple[int, int]:
        """(arrival dates, launch dates)."""
        return self.valid.shape

    def _grid(self, values: np.ndarray, unit: u.UnitBase) -> Masked:
        return _masked(np.where(self.valid, values, np.nan), self.valid, unit)

    @cached_property
    def _departure_v_inf(self) -> np.ndarray:
        return np.linalg.norm(self.v1_si - self.v_departure[None, :, :], axis=-1)

    @cached_property
    def _arrival_v_inf(self) -> np.ndarray:
        return np.linalg.norm(self.v2_si - self.v_target[:, None, :], axis=-1)

    @cached_property
    def _tof(self) -> np.ndarray:
        days = (self.arrival_dates.tdb.jd1[:, None] - self.launch_dates.tdb.jd1[None, :]) + (
            self.arrival_dates.tdb.jd2[:, None] - self.launch_dates.tdb.jd2[None, :])
        return days * 86400.0

    @property
    def c3(self) -> Masked:
        """C3 = |v1 - v_departure|**2 (m2/s2), (arrival, launch) grid, invalid cells masked."""
        return self._grid(self._departure_v_inf**2, units.M**2 / units.S**2)

    @property
    def departure_v_inf(self) -> Masked:
        """|v1 - v_departure| (m/s) on the grid."""
        return self._grid(self._departure_v_inf, units.M_PER_S)

    @property
    def arrival_v_inf(self) -> Masked:
        """|v2 - v_target| (m/s) on the grid."""
        return self._grid(self._arrival_v_inf, units.M_PER_S)

    @property
    def total_v_inf(self) -> Masked:
        """Departure plus arrival v_inf (m/s) on the grid."""
        return self._grid(self._departure_v_inf + self._arrival_v_inf, units.M_PER_S)

    @property
    def time_of_flight(self) -> Masked:
        """Arrival minus launch date (s) on the grid; invalid cells masked."""
        return self._grid(self._tof, units.S)

    @property
    def v1(self) -> Masked:
        """Heliocentric ICRF velocity on departure (m/s), (arrival, launch, 3)."""
        return Masked(self.v1_si << units.M_PER_S, mask=np.broadcast_to(~self.valid[..., None], self.v1_si.shape))

    @property
    def v2(self) -> Masked:
        """Heliocentric ICRF velocity on arrival (m/s), (arrival, launch, 3)."""
        return Masked(self.v2_si << units.M_PER_S, mask=np.broadcast_to(~self.valid[..., None], self.v2_si.shape))

    def _minimum(self, kind: str, merit: np.ndarray) -> PorkchopMinimum:
        """The valid cell where `merit` is least (the first such cell in row-major order on ties)."""
        flat = int(np.argmin(np.where(self.valid, merit, np.inf)))
        row, col = np.unravel_index(flat, self.shape)
        return PorkchopMinimum(kind, self.launch_dates[col], self.arrival_dates[row],
                               float(self._departure_v_inf[row, col] ** 2), float(self._departure_v_inf[row, col]),
                               float(self._arrival_v_inf[row, col]), float(self._tof[row, col]),
                               _edges(row, col, self.shape))

    @cached_property
    def minimum_c3(self) -> PorkchopMinimum:
        """The cell of least launch energy C3."""
        return self._minimum("C3", self._departure_v_inf)

    @cached_property
    def minimum_arrival_v_inf(self) -> PorkchopMinimum:
        """The cell of least arrival v_inf."""
        return self._minimum("arrival v_inf", self._arrival_v_inf)

    @cached_property
    def minimum_total(self) -> PorkchopMinimum:
        """The cell of least departure plus arrival v_inf."""
        return self._minimum("total v_inf", self._departure_v_inf + self._arrival_v_inf)

    def minima(self) -> dict[str, PorkchopMinimum]:
        """{name prefix ("min_c3_", ...): PorkchopMinimum} of the three figures of merit."""
        return {prefix: getattr(self, attribute) for prefix, attribute in MINIMA.items()}

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{prefix + name: Quantity} of each minimum (prefixes min_c3_, min_arrival_v_inf_, min_total_; names
        MINIMUM_NAMES), or `only` those."""
        table = {prefix + name: q for prefix, best in self.minima().items() for name, q in best.quantities().items()}
        return quantity_table(table.__getitem__, list(table), only)

    def _display_quantities(self) -> dict[str, u.Quantity]:
        return {k: v for k, v in self.quantities().items() if not k.endswith("_jd_tdb")}

    def __repr__(self) -> str:
        """E.g. "Porkchop(Earth to Mars, launch 2026-09-01..2027-01-31 x arrival 2027-06-01..2028-03-01, 31 x 56
        cells, min C3 = 8.86 km2 / s2 on 2026-11-05 -> 2027-09-02, ...)" on one line."""
        best, slow = self.minimum_c3, self.minimum_arrival_v_inf
        return display.one_line(
            "Porkchop", f"{self.departure} to {self.target}",
            f"launch {_date_text(self.launch_dates[0])}..{_date_text(self.launch_dates[-1])} x arrival "
            f"{_date_text(self.arrival_dates[0])}..{_date_text(self.arrival_dates[-1])}",
            f"{self.launch_dates.size} x {self.arrival_dates.size} dates",
            f"min C3 = {display.summary(best.c3, digits=4)} ({_date_text(best.launch)} -> "
            f"{_date_text(best.arrival)})",
            f"min arrival v_inf = {display.summary(slow.arrival_v_inf, digits=4)} ({_date_text(slow.launch)} -> "
            f"{_date_text(slow.arrival)})")
