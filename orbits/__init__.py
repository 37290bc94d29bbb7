"""orbits: celestial mechanics to the last float64 digit, cross-checked against rebound and heyoka.

Public API: Orbit (orbits.orbit), named bodies and constants (orbits.constants), errors
(orbits.errors). The float64 numeric core lives in orbits.core and takes no units.
"""

from orbits.constants import BODIES, Body, G, body
from orbits.errors import ConvergenceError, DegenerateOrbitError, OrbitDomainError, OrbitsError
from orbits.orbit import Orbit

__version__ = "0.1.0"

__all__ = [
    "BODIES",
    "G",
    "Body",
    "body",
    "Orbit",
    "ConvergenceError",
    "DegenerateOrbitError",
    "OrbitDomainError",
    "OrbitsError",
    "__version__",
]
