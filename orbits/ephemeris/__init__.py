"""The solar system at a date, with units: where the Sun, the planets and the Moon are (positions, JPL DE421 or
astropy's built-in ephemeris), the published orbits of the bodies the planetary elements leave out (catalogue),
and the picture of the solar system (plot).

`from orbits import ephemeris` then `ephemeris.where("Mars", "2026-11-26")`: the public names of `positions` are
read here on first use (PEP 562), so that importing the catalogue alone loads no ephemeris.
"""

import importlib

_SUBMODULES = ("positions", "catalogue", "plot")


def __getattr__(name: str):
    """A public name of orbits.ephemeris.positions, or a submodule of this package, imported on first use."""
    if not name.startswith("_") and name not in _SUBMODULES:  # a submodule is the import system's to load
        positions = importlib.import_module("orbits.ephemeris.positions")
        if hasattr(positions, name):
            return getattr(positions, name)
    raise AttributeError(f"module 'orbits.ephemeris' has no attribute {name!r}")
