"""Shared parsers for the calculator: unit strings ("1 AU", "5.97e24 kg"), vectors and body names."""

import astropy.units as u
import numpy as np
import typer

from orbits.constants import BODIES, body


def quantity(text, physical_type, name):
    """Quantity parsed from "VALUE UNIT"; BadParameter naming the option if it is not of physical_type."""
    try:
        value = u.Quantity(text)
    except (TypeError, ValueError):
        raise typer.BadParameter(f"{name}: cannot read {text!r} as a quantity; write e.g. '7000 km'") from None
    if physical_type == "dimensionless":
        if value.unit.physical_type != "dimensionless":
            raise typer.BadParameter(f"{name}: {text!r} must be a plain number")
        return value
    if value.unit == u.one:
        raise typer.BadParameter(f"{name}: {text!r} has no unit; write e.g. '{text} {_EXAMPLE_UNITS[physical_type]}'")
    if value.unit.physical_type != physical_type:
        raise typer.BadParameter(f"{name}: {text!r} is a {value.unit.physical_type}, not a {physical_type}")
    return value


_EXAMPLE_UNITS = {"length": "km", "mass": "kg", "time": "s", "angle": "deg", "speed": "km/s"}


def angle(text, name):
    """Angle from "30 deg" or "0.5 rad"; a bare number is read as degrees (the calculator's convention)."""
    try:
        return float(text) * u.deg
    except ValueError:
        return quantity(text, "angle", name)


def orientation(inc, raan, argp, nu):
    """{inc, raan, argp, nu} as angle Quantities from the shared element options."""
    return {
        "inc": angle(inc, "--inc"),
        "raan": angle(raan, "--raan"),
        "argp": angle(argp, "--argp"),
        "nu": angle(nu, "--nu"),
    }


def vector(text, physical_type, name):
    """3-vector Quantity from "X,Y,Z UNIT" (e.g. "7000,0,0 km")."""
    numbers, _, unit = text.strip().partition(" ")
    try:
        values = np.array([float(x) for x in numbers.split(",")])
    except ValueError:
        raise typer.BadParameter(f"{name}: cannot read {text!r}; write e.g. '7000,0,0 km'") from None
    if values.shape != (3,):
        raise typer.BadParameter(f"{name}: {text!r} needs three comma-separated components")
    return quantity(f"1 {unit}", physical_type, name) * values


def primary(text):
    """A primary body: a known name, a mass ("5.97e24 kg") or a GM ("3.986e14 m3 / s2")."""
    if text.lower() in (name.lower() for name in BODIES):
        return body(text)
    try:
        value = u.Quantity(text)
    except (TypeError, ValueError):
        raise typer.BadParameter(
            f"primary: {text!r} is neither a known body ({', '.join(BODIES)}) nor a mass or GM with units"
        ) from None
    if value.unit.physical_type not in ("mass",) and not value.unit.is_equivalent(u.m**3 / u.s**2):
        raise typer.BadParameter(f"primary: {text!r} must be a mass (kg) or a GM (m3 / s2)")
    return value


def names(text):
    """Comma-separated snake_case names ("period,semi_major_axis") as a list, or None."""
    return None if text is None else [n.strip() for n in text.split(",") if n.strip()]
