"""The rest of the notes' mechanics, with astropy units: collisions (IX), rotation (XI), motion under uniform
effective gravity (XX) and oscillations (XXV). Rockets (X) live in orbits.rocket.

Each object is a frozen dataclass of float64 SI fields built by classmethods from Quantities, with cached
properties, `quantities()` and a one-line repr; the numbers come from orbits.core.collisions, rotation, projectile
and oscillations, each checked against heyoka integrations of its equations and against mpmath.
"""

from orbits.mechanics.collisions import Collision, energy_transfer, slingshot
from orbits.mechanics.oscillations import DampedOscillator, DrivenOscillator, Pendulum, VerticalCircle
from orbits.mechanics.projectile import ConicalPendulum, EffectiveGravity, Projectile
from orbits.mechanics.rotation import RigidBody, Rolling, Rotation

__all__ = [
    "Collision", "energy_transfer", "slingshot",
    "Rotation", "RigidBody", "Rolling",
    "Projectile", "EffectiveGravity", "ConicalPendulum",
    "Pendulum", "DampedOscillator", "DrivenOscillator", "VerticalCircle",
]
