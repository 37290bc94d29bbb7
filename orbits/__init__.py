from orbits.errors import ConvergenceError, DegenerateOrbitError, OrbitDomainError, OrbitsError

__version__ = "0.1.0"
