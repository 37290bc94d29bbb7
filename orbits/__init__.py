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
    "Orbit": "orbits.twobody.orbit",
    "Binary": "orbits.encounters.binary",
    "SpectroscopicBinary": "orbits.encounters.binary",
    "Star": "orbits.encounters.binary",
    "Flyby": "orbits.encounters.flyby",
    "RestrictedThreeBody": "orbits.threebody.lagrange",
    "PeriodicOrbit": "orbits.periodic.family",
    "PeriodicFamily": "orbits.periodic.family",
    "SecularOrbit": "orbits.perturb.secular",
    "sun_synchronous": "orbits.perturb.secular",
    "frozen": "orbits.perturb.secular",
    "repeat_ground_track": "orbits.perturb.secular",
    "DragDecay": "orbits.perturb.secular",
    "KozaiLidov": "orbits.perturb.secular",
    "relativistic_periapsis_advance": "orbits.perturb.secular",
    "Ring": "orbits.threebody.rings",
    "CosmicVelocities": "orbits.encounters.escape",
    "SynchronousOrbit": "orbits.encounters.escape",
    "escape_speed": "orbits.encounters.escape",
    "max_elongation": "orbits.encounters.escape",
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
    "elastic_collision": "orbits.mechanics.collisions",
    "lambert": "orbits.manoeuvres.lambert",
    "LambertTransfer": "orbits.manoeuvres.lambert",
    "Porkchop": "orbits.manoeuvres.porkchop",
    "Collision": "orbits.mechanics.collisions",
    "energy_transfer": "orbits.mechanics.collisions",
    "slingshot": "orbits.mechanics.collisions",
    "Rotation": "orbits.mechanics.rotation",
    "RigidBody": "orbits.mechanics.rotation",
    "Rolling": "orbits.mechanics.rotation",
    "Projectile": "orbits.mechanics.projectile",
    "EffectiveGravity": "orbits.mechanics.projectile",
    "ConicalPendulum": "orbits.mechanics.projectile",
    "Pendulum": "orbits.mechanics.oscillations",
    "DampedOscillator": "orbits.mechanics.oscillations",
    "DrivenOscillator": "orbits.mechanics.oscillations",
    "VerticalCircle": "orbits.mechanics.oscillations",
    "Cosmology": "orbits.cosmology.models",
    "ExpandingSphere": "orbits.cosmology.models",
    "anomalies": "orbits.twobody.kepler",
    "BODIES": "orbits._common.constants",
    "G": "orbits._common.constants",
    "Body": "orbits._common.constants",
    "body": "orbits._common.constants",
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
