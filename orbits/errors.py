"""Exceptions raised by orbits: every message names the quantity, its value and what is allowed."""


class OrbitsError(Exception):
    """Base class of every error orbits raises on purpose."""


class OrbitDomainError(OrbitsError, ValueError):
    """A value lies outside the range where the requested quantity is defined."""


class DegenerateOrbitError(OrbitDomainError):
    """The orbit has no well-defined plane or orientation (radial orbit, h = 0)."""


class ConvergenceError(OrbitsError, RuntimeError):
    """An iterative solver hit its iteration cap; the message carries the inputs and last iterate."""
