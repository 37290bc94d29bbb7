"""Input rules, in one home: what the API, the scene loader and the command line accept, and the one error.

Every rule raises OrbitDomainError (a ValueError) whose message names the quantity, the value, what is allowed
and the unit; a bare number where a dimensional Quantity is expected is a TypeError (orbits._common.units.to_si).
The rules on plain float arrays (finiteness, positivity) live one floor down, in orbits.core.checks.

- Quantity strings: "VALUE UNIT" ("7000 km", "1 AU", "3.986e14 m3 / s2"), checked against a kind of quantity
  ("length", "speed", ...); vectors "X,Y,Z UNIT"; angles, where a bare number means degrees.
- Primaries: a catalogue body (or its name, any case), a mass or a GM, to G M in m**3/s**2.
- Size elements: exactly one of a, p, q with e, to the semi-latus rectum p in m.
"""

import warnings
from collections.abc import Callable
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import units
from orbits._common.constants import BODIES, STANDARD_GRAVITY, Body, G, body
from orbits.core.checks import (
    broadcast,
    check_finite,
    first_where,
    require_magnitude,
    require_no_underflow,
    require_positive,
)
from orbits.core.errors import InsideBodyWarning, OrbitDomainError
from orbits.core.twobody import elements, kepler

#: the SI unit of each kind of quantity a string may hold, and a unit to suggest when the unit is missing
KINDS = {
    "length": (units.M, "km"),
    "mass": (units.KG, "kg"),
    "time": (units.S, "s"),
    "angle": (units.RAD, "deg"),
    "speed": (units.M_PER_S, "km/s"),
    "acceleration": (units.M / units.S**2, "m/s2"),
    "force": (u.N, "kN"),
    "density": (units.KG / units.M**3, "kg/m3"),
    "area": (units.M**2, "m2"),
    "area per mass": (units.M**2 / units.KG, "m2/kg"),
    "gravitational parameter": (units.M3_PER_S2, "m3 / s2"),
    "rate": (units.S**-1, "km / s / Mpc"),
    "dimensionless": (u.one, ""),
}


def _kind(kind: str):
    try:
        return KINDS[kind]
    except KeyError:
        raise ValueError(f"unknown kind of quantity {kind!r}; known: {', '.join(KINDS)}") from None


def parse_quantity(text: str, kind: str, name: str, bare_unit: u.UnitBase | None = None) -> u.Quantity:
    """Quantity read from "VALUE UNIT" and checked to be a finite `kind` ("length", "speed", ... see KINDS).

    A bare number takes `bare_unit` when one is given (angles: degrees) and is an error otherwise; a
    dimensionless kind takes plain numbers only.
    """
    si, example = _kind(kind)
    if not isinstance(text, str):
        raise OrbitDomainError(f"{name} = {text!r} must be a string like '1.5 {example or 1}'")
    try:
        with warnings.catch_warnings():  # "km/s/Mpc" reads as km / (s Mpc), as meant; astropy warns of the slashes
            warnings.simplefilter("ignore", u.UnitsWarning)
            value = u.Quantity(text)
    except (TypeError, ValueError):
        if find_body(text) is not None:
            raise OrbitDomainError(f"{name}: {text!r} is a body, not a {kind}; write e.g. "
                                   f"'1.5 {example or 1}'") from None
        raise OrbitDomainError(f"{name}: cannot read {text!r} as a quantity; write e.g. '7000 km'") from None
    if value.unit == u.one and si != u.one:
        if bare_unit is None:
            raise OrbitDomainError(f"{name}: {text!r} has no unit; write e.g. '{text} {example}'")
        value = value.value * bare_unit
    if not value.unit.is_equivalent(si):
        if si == u.one:
            raise OrbitDomainError(f"{name}: {text!r} must be a plain number")
        raise OrbitDomainError(f"{name}: {text!r} is a {value.unit.physical_type}, not a {kind}")
    check_finite(value.value, name, value.unit.to_string())
    require_no_underflow(text.strip().split(" ")[0], value.value, name)
    return value


def parse_angle(text: str, name: str) -> u.Quantity:
    """Angle from "30 deg" or "0.5 rad"; a bare number is read as degrees (the calculator's convention)."""
    return parse_quantity(text, "angle", name, bare_unit=u.deg)


def parse_direction(text: str, name: str) -> np.ndarray:
    """A direction 'X,Y,Z' (plain numbers; a length unit is accepted and ignored) as a float64 (3,) array, finite
    and not zero."""
    numbers, _, unit = str(text).strip().partition(" ")
    direction = parse_vector(f"{numbers} {unit or 'm'}", "length", name).value
    if not np.any(direction):
        raise OrbitDomainError(f"{name} = {text!r} is the zero vector; a direction needs a non-zero component")
    return direction


def parse_vector(text: str, kind: str, name: str) -> u.Quantity:
    """3-vector Quantity from "X,Y,Z UNIT" (e.g. "7000,0,0 km"), finite and of the given kind."""
    if not isinstance(text, str):
        raise OrbitDomainError(f"{name} = {text!r} must be a string 'X,Y,Z UNIT', e.g. '7000,0,0 km'")
    numbers, _, unit_text = text.strip().partition(" ")
    try:
        values = np.array([float(x) for x in numbers.split(",")])
    except ValueError:
        raise OrbitDomainError(f"{name}: cannot read {text!r}; write e.g. '7000,0,0 km'") from None
    if values.shape != (3,):
        raise OrbitDomainError(f"{name}: {text!r} needs three comma-separated components, e.g. '7000,0,0 km'")
    check_finite(values, name, unit_text)
    for literal, value in zip(numbers.split(","), values):
        require_no_underflow(literal.strip(), value, name)
    if not unit_text.strip():
        raise OrbitDomainError(f"{name}: {text!r} has no unit; write e.g. '{text.strip()} {_kind(kind)[1]}'")
    return parse_quantity(f"1 {unit_text}", kind, name) * values


def parse_primary(text: str) -> Body | u.Quantity:
    """A primary from a string: a catalogue body name (any case), a mass ("5.97e24 kg") or a GM ("3.986e14 m3 / s2")."""
    named = find_body(text)
    if named is not None:
        return named
    try:
        value = u.Quantity(text)
    except (TypeError, ValueError):
        raise OrbitDomainError(
            f"primary: {text!r} is neither a known body ({', '.join(BODIES)}) nor a mass or GM with units"
        ) from None
    if not (value.unit.is_equivalent(units.KG) or value.unit.is_equivalent(units.M3_PER_S2)):
        raise OrbitDomainError(f"primary: {text!r} must be a mass (kg) or a GM (m3 / s2)")
    return value


def find_body(name: str) -> Body | None:
    """The catalogue body called `name` (any case), or None."""
    try:
        return body(name)
    except KeyError:
        return None


def named_body(primary: Body | str | u.Quantity) -> Body | None:
    """The catalogue body a primary names (a Body or a body name), or None for a mass or a GM."""
    if isinstance(primary, str):
        return body(primary)
    return primary if isinstance(primary, Body) else None


def orbit_radius(primary: Body | str | u.Quantity, value: u.Quantity, name: str) -> np.ndarray:
    """A circular orbit's radius (m): positive and, about a catalogued body, above its equatorial radius."""
    r = positive(value, units.M, name)
    named = named_body(primary)
    if named is not None and np.any(r <= named.radius):
        bad, = first_where(r <= named.radius, r)
        raise OrbitDomainError(
            f"{name} = {bad!r} m is inside {named.name} (allowed: above its radius {named.radius!r} m); an orbit "
            f"radius counts from the centre: add the radius to an altitude")
    return r


def exact_body(gm: np.ndarray) -> Body | None:
    """The catalogue body whose own GM every element of `gm` (m3/s2) is, exactly, else None: the primary an orbit
    names ("about Earth"), found without sorting a large array."""
    gm = np.asarray(gm, dtype=float)
    if gm.size == 0:
        return None
    first = float(gm.flat[0])
    named = next((b for b in BODIES.values() if b.gm == first), None)
    return named if named is not None and (gm.size == 1 or bool(np.all(gm == first))) else None


def warn_if_inside(periapsis: np.ndarray, bodies: "list[Body | None]", what: str) -> None:
    """Warn (InsideBodyWarning) when a closest approach (m, array) lies below the radius of the catalogue body met,
    or for two bodies meeting below their radii added: the conic passes through the body, or the two collide.
    Bodies that are None (a mass or GM, not a catalogue body) have no radius and are left out."""
    known = [b for b in bodies if b is not None]
    if not known:
        return
    reach = sum(b.radius for b in known)
    inside = np.asarray(periapsis) < reach
    if not inside.any():
        return
    q, = first_where(inside, np.asarray(periapsis, dtype=float))
    names = " and ".join(f"the {b.name}" if b.name in ("Sun", "Earth", "Moon") else b.name for b in known)
    if len(known) == 1:
        size, verdict = f"equatorial radius {reach / 1e3:.7g} km", f"it passes through {names}"
    else:
        size, verdict = f"radii added: {reach / 1e3:.7g} km", "they collide"
    count = f" ({int(inside.sum())} of {inside.size})" if inside.size > 1 else ""
    warnings.warn(f"{what}{count}: closest approach {q / 1e3:.7g} km is inside {names} ({size}): {verdict}",
                  InsideBodyWarning, stacklevel=2)


def gravitational_parameter(value: Body | str | u.Quantity, name: str = "primary mass M") -> np.ndarray:
    """G M (m3/s2) of a mass given as a Body, a body name, a mass (kg) or a GM (m3/s2) Quantity; finite, > 0."""
    if isinstance(value, str):
        value = body(value)
    if isinstance(value, Body):
        return np.asarray(value.gm, dtype=float)
    if isinstance(value, u.Quantity) and value.unit.is_equivalent(units.M3_PER_S2):
        return positive(value, units.M3_PER_S2, name)
    return G * positive(value, units.KG, name)


def one(values: np.ndarray, name: str) -> float:
    """The value of an argument that takes a single one (a number, a 0-d or one-element array) as a float, after
    its rules were checked; OrbitDomainError naming it and how many were given otherwise (an empty array, a list)."""
    values = np.asarray(values, dtype=float)
    if values.size != 1:
        raise OrbitDomainError(f"{name} takes one value; got {values.size} (shape {values.shape})")
    return float(values.reshape(()))


def single(rule: Callable[..., np.ndarray], value: Any, *arguments: Any) -> float:
    """rule(value, *arguments) for an argument that takes a single value, whose name is the last of `arguments`:
    its rules, then `one`. E.g. single(positive, altitude, units.M, "altitude")."""
    return one(rule(value, *arguments), arguments[-1])


def positive(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of a Quantity in `unit` (SI), checked finite, > 0 and within MAGNITUDE_RANGE (so that what is
    computed from it neither overflows nor underflows)."""
    si = units.to_si(value, unit, name)
    require_positive(si, name, unit.to_string())
    require_magnitude(si, name, unit.to_string())
    return si


def angle(value: u.Quantity, name: str) -> np.ndarray:
    """float64 array of an angle Quantity in rad, checked finite."""
    si = units.to_si(value, units.RAD, name)
    check_finite(si, name, "rad")
    return si


def periodic_angle(value: u.Quantity, name: str) -> np.ndarray:
    """float64 array of an angle that counts modulo a full turn (an anomaly, a node, an argument), in rad and
    reduced to (-pi, pi], with its value kept however large it is given.

    In a unit of which a turn is a whole number (deg, arcmin, arcsec, hourangle) the whole turns come off in that
    unit, exactly (fmod is exact in float64), before the one rounding of the conversion: 1e15 deg is -80 deg, where
    converting to rad first left -79.954 deg. In rad the reduction is the exact double-double one of Kepler's
    equation, up to 2**50 turns (OrbitDomainError beyond, as for the mean anomaly)."""
    si = angle(value, name)  # the unit and finiteness rules; the value in rad is used only for rad-like units
    given = np.asarray(value.value, dtype=float)
    turn = float((1 * u.cycle).to_value(value.unit))
    if turn == round(turn):
        reduced = np.fmod(given, turn)
        reduced = np.where(reduced > 0.5 * turn, reduced - turn, np.where(reduced <= -0.5 * turn, reduced + turn,
                                                                          reduced))
        return units.to_si(reduced << value.unit, units.RAD, name)
    if np.any(np.abs(si) > kepler.MAX_MEAN_ANOMALY):
        bad = float(si[np.abs(si) > kepler.MAX_MEAN_ANOMALY].flat[0])
        raise OrbitDomainError(f"{name} = {bad!r} rad is too large for an exact reduction modulo 2 pi; allowed "
                               f"|{name.split()[-1]}| <= {kepler.MAX_MEAN_ANOMALY:.6g} rad (2**50 turns)")
    reduced = kepler.reduce_two_pi(si, 0.0)[0]
    return np.where(reduced <= -np.pi, np.pi, reduced)


def position(value: u.Quantity, name: str = "position r") -> np.ndarray:
    """A position (m, (..., 3)) relative to a primary: a finite vector (`vector`) away from the primary's centre."""
    r = vector(value, units.M, name)
    if np.any(np.all(r == 0.0, axis=-1)):
        raise OrbitDomainError(f"{name} = (0, 0, 0) m coincides with the primary; |r| must be positive")
    return r


def inclination(value: u.Quantity) -> np.ndarray:
    """Inclination i (rad), finite and in [0, pi]."""
    return angle_in(value, "inclination i", 0.0, np.pi, "[0, pi]")


def vector(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array (..., 3) of a vector Quantity in `unit` (SI): finite, each nonzero length within
    MAGNITUDE_RANGE."""
    si = units.to_si(value, unit, name)
    check_finite(si, name, unit.to_string())
    if si.shape[-1:] != (3,):
        raise OrbitDomainError(f"{name} must have a last axis of length 3; got shape {si.shape}")
    length = np.hypot(np.hypot(si[..., 0], si[..., 1]), si[..., 2])  # no underflow: |(1e-297, 0, 0)| is not 0
    require_magnitude(length[length > 0], f"|{name}|", unit.to_string())
    return si


def conic_elements(
    primary: Body | str | u.Quantity, e: float | np.ndarray | u.Quantity, *, a: u.Quantity | None = None,
    p: u.Quantity | None = None, q: u.Quantity | None = None, inc: u.Quantity, raan: u.Quantity, argp: u.Quantity,
    nu: u.Quantity
) -> list[np.ndarray]:
    """The fields (mu, p, e, i, Omega, omega, nu) of an orbit given by elements: float64 SI arrays of one shape,
    each owning its data (orbits.core.twobody.elements.conic_fields). Each value is read once, in this order: the
    primary (gravitational_parameter), exactly one size element (a, p or q: size_element), the angles (i in
    [0, pi], the others reduced modulo a turn), then e; they must broadcast together (an error names each
    argument's shape), and e's own rules and those that join e to a size or to nu come last."""
    mu = gravitational_parameter(primary, "primary mass or gravitational parameter")
    element, size = size_element(a=a, p=p, q=q)
    inc_si = inclination(inc)
    raan_si = elements.wrap_two_pi(periodic_angle(raan, "longitude of the ascending node Omega"))
    argp_si = elements.wrap_two_pi(periodic_angle(argp, "argument of periapsis omega"))
    nu_si = periodic_angle(nu, "true anomaly nu")
    ecc = units.to_number(e, "eccentricity e")
    fields = broadcast(**{"e": ecc, element: size, "inc": inc_si, "raan": raan_si, "argp": argp_si, "nu": nu_si,
                          "primary": mu})
    return elements.conic_fields(element, *fields)


def size_element(
    a: u.Quantity | None = None, p: u.Quantity | None = None, q: u.Quantity | None = None
) -> tuple[str, np.ndarray]:
    """("a", "p" or "q", its value in m) of exactly one size element given: p and q positive within
    MAGNITUDE_RANGE, a finite with |a| there or 0 (its sign is checked against e: elements.semi_latus_rectum)."""
    given = {name: value for name, value in (("a", a), ("p", p), ("q", q)) if value is not None}
    if len(given) != 1:
        raise TypeError(f"give exactly one size element of a, p, q; got {list(given) or 'none'}")
    if p is not None:
        return "p", positive(p, units.M, "semi-latus rectum p")
    if q is not None:
        return "q", positive(q, units.M, "periapsis distance q")
    value = units.to_si(a, units.M, "semi-major axis a")
    check_finite(value, "semi-major axis a", "m")
    require_magnitude(np.abs(value[value != 0]), "semi-major axis |a|", "m")
    return "a", value


def semi_latus_rectum(
    e: np.ndarray, a: u.Quantity | None = None, p: u.Quantity | None = None, q: u.Quantity | None = None
) -> np.ndarray:
    """p (m) from a checked e and exactly one size element (size_element, elements.semi_latus_rectum)."""
    element, size = size_element(a=a, p=p, q=q)
    return elements.semi_latus_rectum(element, *broadcast(size=size, e=e))


def eccentricity(e: float | np.ndarray | u.Quantity) -> np.ndarray:
    """float64 array of eccentricities (plain numbers or dimensionless Quantities), each finite and in
    [0, MAX_ECCENTRICITY] (elements.require_eccentricity)."""
    e = units.to_number(e, "eccentricity e")
    elements.require_eccentricity(e)
    return e


def names(text: str | None) -> list[str] | None:
    """Comma-separated names ("period,semi_major_axis") as a list; None for None; an error if none is given."""
    if text is None:
        return None
    listed = [n.strip() for n in text.split(",") if n.strip()]
    if not listed:
        raise OrbitDomainError(f"names = {text!r}: give at least one comma-separated name")
    return listed


# ---- rules of the mechanics objects (collisions, rotation, projectiles, oscillations) -------------------------


def gravity(g: u.Quantity | None) -> np.ndarray:
    """g (m/s2): the standard 9.80665 m/s2 of the notes (XIX.vii) when None, else a positive acceleration."""
    if g is None:
        return np.asarray(STANDARD_GRAVITY)
    return positive(g, units.ACCELERATION, "gravitational acceleration g")


def signed(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of a Quantity in `unit` (SI) of either sign, checked finite."""
    si = units.to_si(value, unit, name)
    check_finite(si, name, unit.to_string())
    return si


def non_negative(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array of a Quantity in `unit` (SI), checked finite and >= 0."""
    si = signed(value, unit, name)
    if np.any(si < 0):
        bad = float(np.asarray(si)[np.asarray(si) < 0].flat[0])
        raise OrbitDomainError(f"{name} = {bad!r} {unit.to_string()} is outside the allowed range [0, inf) "
                               f"{unit.to_string()}")
    return si


def planar_vector(value: u.Quantity, unit: u.UnitBase, name: str) -> np.ndarray:
    """float64 array (..., 2) or (..., 3) of a vector Quantity in `unit` (SI), finite: a velocity in a plane or in
    space (`vector` takes 3-vectors only)."""
    si = signed(value, unit, name)
    if si.ndim == 0 or si.shape[-1] not in (2, 3):
        raise OrbitDomainError(f"{name} must have a last axis of length 2 or 3; got shape {si.shape}")
    return si


def angle_in(value: u.Quantity, name: str, low: float, high: float, text: str) -> np.ndarray:
    """float64 array of an angle Quantity in rad (`angle`), checked to lie in the range `text` says:
    "[low, high]", with "(" or ")" for an open end (so "[0, pi/2)" refuses pi/2 itself)."""
    si = angle(value, name)
    below = (si <= low) if text.startswith("(") else (si < low)
    above = (si >= high) if text.endswith(")") else (si > high)
    bad = below | above
    if np.any(bad):  # said in the unit the value came in: "inclination i = 200 deg is outside [0, 180] deg"
        unit = value.unit if isinstance(value, u.Quantity) and value.unit.physical_type == "angle" else u.rad
        shown = float(np.asarray((si << u.rad).to_value(unit))[bad].flat[0])
        low_shown, high_shown = ((x * u.rad).to_value(unit) for x in (low, high))
        raise OrbitDomainError(f"{name} = {shown:.10g} {unit} is outside the allowed range {text[0]}{low_shown:.10g}, "
                               f"{high_shown:.10g}{text[-1]} {unit}")
    return si
