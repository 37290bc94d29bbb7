"""Command-line spellings of the library's input rules (orbits._common.inputs): the options' names, nothing more."""

from typing import TYPE_CHECKING

from orbits._common.inputs import parse_angle

if TYPE_CHECKING:
    from astropy.units import Quantity


def orientation(inc: str, raan: str, argp: str, nu: str) -> "dict[str, Quantity]":
    """{inc, raan, argp, nu} as angle Quantities from the shared element options (bare numbers are degrees)."""
    return {
        "inc": parse_angle(inc, "--inc"),
        "raan": parse_angle(raan, "--raan"),
        "argp": parse_angle(argp, "--argp"),
        "nu": parse_angle(nu, "--nu"),
    }
