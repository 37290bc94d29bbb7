"""Rotations, rigid bodies' inertia and rolling (notes XI), with astropy units.

    >>> import astropy.units as u
    >>> from orbits import RigidBody, Rotation
    >>> turn = Rotation.from_axis_angle([0, 0, 1], 90 * u.deg)
    >>> turn.apply([1, 0, 0] * u.m).round(12)
    <Quantity [0., 1., 0.] m>
    >>> ball = RigidBody.solid_sphere(2 * u.kg, 0.1 * u.m)
    >>> ball.principal_moments
    <Quantity [0.008, 0.008, 0.008] m2 kg>
    >>> ball.rolling_down(30 * u.deg).acceleration.round(4)  # 5/7 g sin(30 deg)
    <Quantity 3.5024 m / s2>

Rotation matrices act on column vectors; axis-angle (Euler's theorem) and the principal angles R = Rz Ry Rx round
trip. A RigidBody holds its mass and inertia tensor about its centre of mass; the parallel-axis theorem moves it.
The numbers come from orbits.core.mechanics.rotation (accuracy stated there).
"""

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.inputs import angle_in, gravity, signed
from orbits._common.tables import attribute_table
from orbits._common.units import DIMENSIONLESS
from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import rotation as core

INERTIA = units.KG * units.M**2


def _direction(value, name):
    """A direction as a float array (..., 3): plain numbers or a Quantity of any unit (only its direction counts)."""
    array = np.asarray(value.value if isinstance(value, u.Quantity) else value, dtype=float)
    return core.unit_axis(array) if array.size else array


@dataclass(frozen=True, eq=False, repr=False)
class Rotation(display.Displayed):
    """A rotation: `matrix` (..., 3, 3), proper orthogonal, acting on column vectors (XI.ii)."""

    matrix: np.ndarray

    @classmethod
    def from_axis_angle(cls, axis, angle: u.Quantity) -> "Rotation":
        """The right-handed turn by `angle` (angle) about `axis` (a direction) (Euler's theorem, XI.ii)."""
        return cls(core.rotation_matrix(_direction(axis, "axis"), inputs.angle(angle, "rotation angle")))

    @classmethod
    def from_principal_angles(cls, x: u.Quantity, y: u.Quantity, z: u.Quantity) -> "Rotation":
        """R = Rz(z) Ry(y) Rx(x): about the fixed x axis first, then y, then z (XI.iii)."""
        return cls(core.from_principal_angles(inputs.angle(x, "x angle"), inputs.angle(y, "y angle"),
                                              inputs.angle(z, "z angle")))

    @classmethod
    def from_matrix(cls, matrix) -> "Rotation":
        """From a 3x3 matrix (plain numbers), checked to be a rotation (R^T R = 1 and det R = 1 within 1e-12)."""
        m = np.asarray(matrix, dtype=float)
        if m.shape[-2:] != (3, 3) or not np.all(np.isfinite(m)):
            raise OrbitDomainError(f"a rotation matrix must be finite with shape (..., 3, 3); got {m.shape}")
        error = np.max(np.abs(np.swapaxes(m, -1, -2) @ m - np.eye(3)))
        if error > 1e-12 or np.any(np.abs(np.linalg.det(m) - 1) > 1e-12):
            raise OrbitDomainError(f"matrix is not a rotation: |R^T R - 1| = {error:.3g} (allowed 1e-12) or det R "
                                   "is not 1")
        return cls(m)

    @cached_property
    def _axis_angle(self):
        return core.axis_angle(self.matrix)

    @cached_property
    def angle(self) -> u.Quantity:
        """The rotation angle in [0, pi] (rad) of Euler's theorem."""
        return self._axis_angle[1] << units.RAD

    @cached_property
    def axis(self) -> u.Quantity:
        """The unit rotation axis (dimensionless); z for the identity."""
        return self._axis_angle[0] << DIMENSIONLESS

    @cached_property
    def _principal(self):
        return core.principal_angles(self.matrix)

    @cached_property
    def x_angle(self) -> u.Quantity:
        """Angle about x (rad), first of R = Rz Ry Rx (XI.iii)."""
        return self._principal[0] << units.RAD

    @cached_property
    def y_angle(self) -> u.Quantity:
        """Angle about y (rad) in [-pi/2, pi/2]."""
        return self._principal[1] << units.RAD

    @cached_property
    def z_angle(self) -> u.Quantity:
        """Angle about z (rad), last of R = Rz Ry Rx."""
        return self._principal[2] << units.RAD

    def apply(self, vector: u.Quantity) -> u.Quantity:
        """R v for vectors (..., 3) of any unit."""
        value = np.asarray(vector.value if isinstance(vector, u.Quantity) else vector, dtype=float)
        turned = np.einsum("...ij,...j->...i", self.matrix, value)
        return turned << vector.unit if isinstance(vector, u.Quantity) else turned

    @property
    def inverse(self) -> "Rotation":
        """R^T."""
        return Rotation(np.swapaxes(self.matrix, -1, -2))

    def __matmul__(self, other: "Rotation") -> "Rotation":
        """self after other: (R1 @ R2) v = R1 (R2 v)."""
        return Rotation(self.matrix @ other.matrix)

    def __repr__(self) -> str:
        """E.g. "Rotation(angle = 90 deg, axis = 0, 0, 1)"."""
        return display.one_line("Rotation", "angle = " + display.summary(self.angle),
                                "axis = " + display.values_text(self._axis_angle[0], 6))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ROTATION_NAMES, only)


ROTATION_NAMES = ["angle", "axis", "x_angle", "y_angle", "z_angle"]


@dataclass(frozen=True, eq=False, repr=False)
class RigidBody(display.Displayed):
    """A rigid body: mass (kg), inertia tensor about its centre of mass (kg m2, (3, 3)), the centre of mass (m,
    (3,)), a rolling radius (m, or None) and a name."""

    mass: float
    inertia_cm: np.ndarray
    center: np.ndarray
    radius: float | None = None
    kind: str = "body"

    @classmethod
    def _standard(cls, kind, mass, moments, radius=None):
        m = inputs.positive(mass, units.KG, "mass m")
        if m.ndim:
            raise OrbitDomainError("a RigidBody holds one body: give a scalar mass")
        return cls(float(m), np.diag(moments), np.zeros(3), radius, kind)

    @classmethod
    def solid_sphere(cls, mass: u.Quantity, radius: u.Quantity) -> "RigidBody":
        """A uniform ball: (2/5) m r**2 about every axis."""
        r = inputs.single(inputs.positive, radius, units.M, "radius r")
        return cls._standard("solid sphere", mass, core.solid_sphere(units.to_si(mass, units.KG, "mass m"), r), r)

    @classmethod
    def spherical_shell(cls, mass: u.Quantity, radius: u.Quantity) -> "RigidBody":
        """A thin spherical shell: (2/3) m r**2."""
        r = inputs.single(inputs.positive, radius, units.M, "radius r")
        return cls._standard("spherical shell", mass, core.spherical_shell(units.to_si(mass, units.KG, "mass m"), r),
                             r)

    @classmethod
    def solid_cylinder(cls, mass: u.Quantity, radius: u.Quantity, height: u.Quantity) -> "RigidBody":
        """A uniform cylinder with its axis along z (height 0: a disc)."""
        r = inputs.single(inputs.positive, radius, units.M, "radius r")
        h = float(np.asarray(signed(height, units.M, "height h")))
        if h < 0:
            raise OrbitDomainError(f"height h = {h!r} m is outside the allowed range [0, inf) m")
        return cls._standard("solid cylinder", mass,
                             core.solid_cylinder(units.to_si(mass, units.KG, "mass m"), r, h), r)

    @classmethod
    def thin_hoop(cls, mass: u.Quantity, radius: u.Quantity) -> "RigidBody":
        """A thin ring in the xy plane: m r**2 about z, m r**2 / 2 about a diameter."""
        r = inputs.single(inputs.positive, radius, units.M, "radius r")
        return cls._standard("thin hoop", mass, core.thin_hoop(units.to_si(mass, units.KG, "mass m"), r), r)

    @classmethod
    def thin_rod(cls, mass: u.Quantity, length: u.Quantity) -> "RigidBody":
        """A thin rod along z: m L**2 / 12 about a perpendicular axis through its centre."""
        length_m = inputs.single(inputs.positive, length, units.M, "length L")
        return cls._standard("thin rod", mass, core.thin_rod(units.to_si(mass, units.KG, "mass m"), length_m))

    @classmethod
    def cuboid(cls, mass: u.Quantity, a: u.Quantity, b: u.Quantity, c: u.Quantity) -> "RigidBody":
        """A uniform box of edges a, b, c along x, y, z."""
        edges = [inputs.single(inputs.positive, x, units.M, f"edge {n}")
                 for x, n in ((a, "a"), (b, "b"), (c, "c"))]
        return cls._standard("cuboid", mass, core.cuboid(units.to_si(mass, units.KG, "mass m"), *edges))

    @classmethod
    def point_masses(cls, masses: u.Quantity, positions: u.Quantity) -> "RigidBody":
        """Point masses (n,) at positions (n, 3) (XI.vi): centre of mass and inertia tensor about it."""
        m = inputs.positive(masses, units.KG, "masses m")
        r = inputs.vector(positions, units.M, "positions r")
        if m.ndim != 1 or r.shape != (m.size, 3):
            raise OrbitDomainError(f"give n masses and n positions (n, 3); got {m.shape} and {r.shape}")
        center = (m[:, None] * r).sum(0) / m.sum()
        return cls(float(m.sum()), core.point_inertia_tensor(m, r - center), center, None, f"{m.size} point masses")

    @cached_property
    def inertia_tensor(self) -> u.Quantity:
        """I about the centre of mass (kg m2, (3, 3)) (XI.vi)."""
        return self.inertia_cm << INERTIA

    @cached_property
    def _principal(self):
        return core.principal_axes(self.inertia_cm)

    @cached_property
    def principal_moments(self) -> u.Quantity:
        """I1 <= I2 <= I3 (kg m2) about the principal axes through the centre of mass."""
        return self._principal[0] << INERTIA

    @cached_property
    def principal_axes(self) -> u.Quantity:
        """The principal axes as the columns of a rotation matrix (dimensionless)."""
        return self._principal[1] << DIMENSIONLESS

    @cached_property
    def center_of_mass(self) -> u.Quantity:
        """The centre of mass (m)."""
        return self.center << units.M

    @cached_property
    def total_mass(self) -> u.Quantity:
        """m (kg)."""
        return self.mass << units.KG

    def inertia_about(self, point: u.Quantity) -> u.Quantity:
        """The tensor about another point (kg m2): I_cm + m (|d|**2 1 - d d^T) (XI.xiii, parallel axes)."""
        offset = self.center - inputs.vector(point, units.M, "point")
        return core.parallel_axis(self.inertia_cm, self.mass, offset) << INERTIA

    def moment_about(self, axis, point: u.Quantity | None = None) -> u.Quantity:
        """n^T I n (kg m2) about the axis n (a direction) through `point` (length; default the centre of mass)."""
        tensor = self.inertia_cm if point is None else self.inertia_about(point).to_value(INERTIA)
        return core.moment_about_axis(tensor, _direction(axis, "axis")) << INERTIA

    def angular_momentum(self, omega: u.Quantity) -> u.Quantity:
        """L = I omega (kg m2 / s) about the centre of mass (XI.vii)."""
        w = inputs.vector(omega, units.RAD_PER_S, "angular velocity omega")
        return np.einsum("ij,...j->...i", self.inertia_cm, w) << units.KG_M2_PER_S

    def rotational_kinetic_energy(self, omega: u.Quantity) -> u.Quantity:
        """K_r = omega^T I omega / 2 (J) (XI.ix)."""
        w = inputs.vector(omega, units.RAD_PER_S, "angular velocity omega")
        return 0.5 * np.einsum("...i,ij,...j->...", w, self.inertia_cm, w) << units.J

    def rolling_down(self, incline: u.Quantity, radius: u.Quantity | None = None, axis=(0, 0, 1),
                     g: u.Quantity | None = None) -> "Rolling":
        """Rolling without slipping down an incline (angle in (0, 90) deg) on `radius` (default: the body's)
        about `axis` (default z: a cylinder's or a hoop's axis; any axis of a sphere)."""
        name = "rolling radius r"
        r = self.radius if radius is None else inputs.single(inputs.positive, radius, units.M, name)
        if r is None:
            raise OrbitDomainError(f"a {self.kind} has no rolling radius: give radius=... m")
        moment = float(core.moment_about_axis(self.inertia_cm, _direction(axis, "axis")))
        return Rolling.down(incline, core.rolling_inertia_factor(moment, self.mass, r), g)

    def __repr__(self) -> str:
        """E.g. "RigidBody(solid sphere, m = 2 kg, I = 0.008, 0.008, 0.008 kg m2)"."""
        return display.one_line("RigidBody", self.kind, "m = " + display.summary(self.total_mass, unit=u.kg),
                                "I = " + display.values_text(self._principal[0], 6) + " kg m2")

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, BODY_NAMES, only)


BODY_NAMES = ["total_mass", "center_of_mass", "principal_moments", "inertia_tensor"]


@dataclass(frozen=True, eq=False, repr=False)
class Rolling(display.Displayed):
    """Rolling without slipping down an incline: incline (rad), k = I / (m r**2) and g (m/s2)."""

    incline: np.ndarray
    factor: np.ndarray
    g: np.ndarray

    @classmethod
    def down(cls, incline: u.Quantity, inertia_factor: float, g: u.Quantity | None = None) -> "Rolling":
        """From the incline angle and k = I / (m r**2) (2/5 ball, 1/2 cylinder, 1 hoop)."""
        angle = angle_in(incline, "incline angle", 0.0, np.pi / 2, "[0, pi/2)")
        k = units.to_number(inertia_factor, "inertia factor k")
        if np.any(~np.isfinite(k) | (k < 0)):
            raise OrbitDomainError(f"inertia factor k = I / (m r**2) = {k!r} is outside the allowed range [0, inf)")
        return cls(angle, k, gravity(g))

    @cached_property
    def inertia_factor(self) -> u.Quantity:
        """k = I / (m r**2) (dimensionless)."""
        return self.factor << DIMENSIONLESS

    @cached_property
    def acceleration(self) -> u.Quantity:
        """a = g sin(theta) / (1 + k) (m/s2)."""
        return core.rolling_acceleration(self.g, self.incline, self.factor) << units.M / units.S**2

    @cached_property
    def friction_coefficient(self) -> u.Quantity:
        """The least static friction coefficient, tan(theta) k / (1 + k) (dimensionless)."""
        return core.rolling_friction_coefficient(self.incline, self.factor) << DIMENSIONLESS

    def speed_after(self, height: u.Quantity) -> u.Quantity:
        """v = sqrt(2 g h / (1 + k)) (m/s) after a drop h (length) from rest."""
        return core.rolling_speed(self.g, inputs.positive(height, units.M, "height h"), self.factor) << units.M_PER_S

    def __repr__(self) -> str:
        """E.g. "Rolling(incline = 30 deg, k = 0.4, a = 3.502375 m / s2)"."""
        return display.one_line("Rolling", "incline = " + display.summary(self.incline << units.RAD),
                                "k = " + display.values_text(self.factor, 6),
                                "a = " + display.summary(self.acceleration))

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} (or `only` those)."""
        return attribute_table(self, ["inertia_factor", "acceleration", "friction_coefficient"], only)
