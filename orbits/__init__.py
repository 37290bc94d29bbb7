"""orbits: celestial mechanics to the last float64 digit, cross-checked against rebound and heyoka.

Public API (loaded on first use, PEP 562, so that `import orbits` is instant and `import orbits.core.<any>`
never loads astropy): Orbit, Binary and Star, Flyby, RestrictedThreeBody, PeriodicOrbit and PeriodicFamily, Ring,
CosmicVelocities, SynchronousOrbit, escape_speed, max_elongation, Cosmology, ExpandingSphere, anomalies, the named
bodies and constants, and the errors. The float64 numeric core lives in orbits.core and takes no units; the N-body
cross-checks live in orbits.validate and the benchmarks in orbits.tools.
"""

import importlib

__version__ = "0.1.0"

#: public name -> the module that defines it
_HOMES = {
    "Orbit": "orbits.orbit",
    "Binary": "orbits.binary",
    "SpectroscopicBinary": "orbits.binary",
    "Star": "orbits.binary",
    "Flyby": "orbits.flyby",
    "RestrictedThreeBody": "orbits.lagrange",
    "PeriodicOrbit": "orbits.periodic",
    "PeriodicFamily": "orbits.periodic",
    "SecularOrbit": "orbits.perturbations",
    "sun_synchronous": "orbits.perturbations",
    "frozen": "orbits.perturbations",
    "repeat_ground_track": "orbits.perturbations",
    "DragDecay": "orbits.perturbations",
    "KozaiLidov": "orbits.perturbations",
    "relativistic_periapsis_advance": "orbits.perturbations",
    "Ring": "orbits.rings",
    "CosmicVelocities": "orbits.escape",
    "SynchronousOrbit": "orbits.escape",
    "escape_speed": "orbits.escape",
    "max_elongation": "orbits.escape",
    "Rocket": "orbits.manoeuvres.rocket",
    "velocity_change": "orbits.manoeuvres.rocket",
    "propellant_mass": "orbits.manoeuvres.rocket",
    "Hohmann": "orbits.manoeuvres.impulsive",
    "BiElliptic": "orbits.manoeuvres.impulsive",
    "PlaneChange": "orbits.manoeuvres.impulsive",
    "combined_plane_change": "orbits.manoeuvres.impulsive",
    "Phasing": "orbits.manoeuvres.impulsive",
    "Departure": "orbits.manoeuvres.impulsive",
    "GravityAssist": "orbits.manoeuvres.assist",
    "elastic_collision": "orbits.collisions",
    "lambert": "orbits.manoeuvres.lambert",
    "LambertTransfer": "orbits.manoeuvres.lambert",
    "Porkchop": "orbits.manoeuvres.porkchop",
    "Collision": "orbits.collisions",
    "energy_transfer": "orbits.collisions",
    "slingshot": "orbits.collisions",
    "Rotation": "orbits.rotation",
    "RigidBody": "orbits.rotation",
    "Rolling": "orbits.rotation",
    "Projectile": "orbits.projectile",
    "EffectiveGravity": "orbits.projectile",
    "ConicalPendulum": "orbits.projectile",
    "Pendulum": "orbits.oscillations",
    "DampedOscillator": "orbits.oscillations",
    "DrivenOscillator": "orbits.oscillations",
    "VerticalCircle": "orbits.oscillations",
    "Cosmology": "orbits.cosmology",
    "ExpandingSphere": "orbits.cosmology",
    "anomalies": "orbits.kepler",
    "BODIES": "orbits.constants",
    "G": "orbits.constants",
    "Body": "orbits.constants",
    "body": "orbits.constants",
    "ConvergenceError": "orbits.core.errors",
    "DegenerateOrbitError": "orbits.core.errors",
    "OrbitDomainError": "orbits.core.errors",
    "OrbitsError": "orbits.core.errors",
    "OrbitsWarning": "orbits.core.errors",
    "InsideBodyWarning": "orbits.core.errors",
    "IllConditionedWarning": "orbits.core.errors",
    "OutputError": "orbits.core.errors",
    "ParameterError": "orbits.core.errors",
    "SceneError": "orbits.core.errors",
    "UnknownNameError": "orbits.core.errors",
}

__all__ = [*_HOMES, "__version__"]


def __getattr__(name: str):
    """Import the public name's home module on first use and cache the name here."""
    if name not in _HOMES:
        raise AttributeError(f"module 'orbits' has no attribute {name!r}")
    value = getattr(importlib.import_module(_HOMES[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
