"""orbits: celestial mechanics to the last float64 digit, cross-checked against rebound and heyoka.

Public API: Orbit (orbits.orbit), named bodies and constants (orbits.constants), errors
(orbits.errors). The float64 numeric core lives in orbits.core and takes no units.
"""

from orbits.binary import Binary, Star
from orbits.constants import BODIES, Body, G, body
from orbits.cosmology import Cosmology, ExpandingSphere
from orbits.errors import ConvergenceError, DegenerateOrbitError, OrbitDomainError, OrbitsError
from orbits.escape import CosmicVelocities, SynchronousOrbit, escape_speed, max_elongation
from orbits.flyby import Flyby
from orbits.lagrange import RestrictedThreeBody
from orbits.orbit import Orbit
from orbits.rings import Ring

__version__ = "0.1.0"

__all__ = [
    "BODIES",
    "G",
    "Body",
    "body",
    "Orbit",
    "Binary",
    "Star",
    "Flyby",
    "RestrictedThreeBody",
    "Ring",
    "CosmicVelocities",
    "SynchronousOrbit",
    "escape_speed",
    "max_elongation",
    "Cosmology",
    "ExpandingSphere",
    "ConvergenceError",
    "DegenerateOrbitError",
    "OrbitDomainError",
    "OrbitsError",
    "__version__",
]
