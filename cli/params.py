"""Command-line spellings of the library's input rules (orbits.inputs): the options' names, nothing more."""

from orbits.inputs import parse_angle


def orientation(inc, raan, argp, nu):
    """{inc, raan, argp, nu} as angle Quantities from the shared element options (bare numbers are degrees)."""
    return {
        "inc": parse_angle(inc, "--inc"),
        "raan": parse_angle(raan, "--raan"),
        "argp": parse_angle(argp, "--argp"),
        "nu": parse_angle(nu, "--nu"),
    }
