"""Perturbing accelerations (m/s**2) of a body about a central one, on float64 arrays in SI.

Positions r (m) and velocities v (m/s) are relative to the central body, shape (..., 3), in an inertial frame whose
z axis is the central body's spin axis where a term needs one (zonal harmonics, the rotating atmosphere). Every term
broadcasts over leading axes and returns an array of r's shape.

- zonal: the zonal harmonics J2 ... Jn of an axisymmetric body.
- third_body: a third body's pull relative to the central body's (Battin's cancellation-free form).
- drag: an exponential atmosphere in bands, rotating with the body.
- radiation_pressure and shadow_fraction: the Sun's light, dimmed by a cylindrical or conical shadow.
- relativity: the first post-Newtonian (1PN) correction of a test body about a non-rotating mass.
- thrust: a constant thrust along a chosen direction.

Accuracy (tests/core/test_forces.py, against independent constructions): the zonal terms within 3e-14 of |a| of
mpmath's gradient of their potential, the third body within 1e-14 of |a| of the 40-digit difference of the two pulls,
the shadow fraction within 1e-13 of mpmath's integral of two overlapping discs; the 1PN term advances Mercury's
perihelion by the classical amount.
"""

import numpy as np
from numpy.typing import ArrayLike

#: the speed of light (m/s), exact
C = 299_792_458.0
#: the total solar irradiance at 1 au (W/m**2): IAU 2015 Resolution B3 nominal value
SOLAR_IRRADIANCE = 1361.0
#: the astronomical unit (m), exact (IAU 2012 Resolution B2)
AU = 149_597_870_700.0
#: the Sun's nominal radius (m): IAU 2015 Resolution B3
SUN_RADIUS = 6.957e8


def _norm(x: np.ndarray) -> np.ndarray:
    return np.sqrt(np.sum(x * x, axis=-1))


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.sum(a * b, axis=-1)


def zonal(r: ArrayLike, mu: float, radius: float, j: ArrayLike) -> np.ndarray:
    """Acceleration of the zonal harmonics J2 ... Jn (j = [J2, J3, ..., Jn], unnormalised, at the reference radius
    R = `radius`) of a body of GM `mu`, from the potential

        V = -(mu / r) sum_n Jn (R / r)**n Pn(s),   s = z / r,

    whose gradient, term by term, is a_n = (mu Jn R**n / r**(n + 2)) [((n + 1) Pn(s) + s Pn'(s)) r_hat - Pn'(s) z_hat],
    with Pn and Pn' by the three-term recurrences (n + 1) P_{n+1} = (2n + 1) s Pn - n P_{n-1} and
    P'_{n+1} = P'_{n-1} + (2n + 1) Pn (no division by 1 - s**2: exact at the poles)."""
    r = np.asarray(r, dtype=float)
    j = np.asarray(j, dtype=float)
    distance = _norm(r)
    s = r[..., 2] / distance
    unit = r / distance[..., None]
    p_before, p = np.ones_like(s), s  # P0, P1
    dp_before, dp = np.zeros_like(s), np.ones_like(s)  # P0', P1'
    radial = np.zeros_like(s)
    polar = np.zeros_like(s)
    ratio = radius / distance
    power = ratio  # (R / r)**n, from n = 1
    for n in range(1, len(j) + 1):  # P_{n+1} from P_n, P_{n-1}
        p_before, p = p, ((2 * n + 1) * s * p - n * p_before) / (n + 1)
        dp_before, dp = dp, dp_before + (2 * n + 1) * p_before
        power = power * ratio
        degree = n + 1
        radial = radial + j[n - 1] * power * ((degree + 1) * p + s * dp)
        polar = polar + j[n - 1] * power * dp
    scale = mu / (distance * distance)
    along = (scale * radial)[..., None] * unit
    return along - (scale * polar)[..., None] * np.array([0.0, 0.0, 1.0])


def third_body(r: ArrayLike, position: ArrayLike, mu: float) -> np.ndarray:
    """Acceleration of the body at r by a third body of GM `mu` at `position` (both from the central body), less
    the pull that body gives the central one: mu [(p - r) / |p - r|**3 - p / |p|**3], in Battin's form

        a = -(mu / |r - p|**3) (r + f(q) p),   q = r . (r - 2 p) / |p|**2,
        f(q) = (1 + q)**1.5 - 1 = q (3 + 3 q + q**2) / (1 + (1 + q)**1.5),

    which keeps its digits when |r| << |p| (an Earth satellite and the Sun), where the two pulls nearly cancel."""
    r = np.asarray(r, dtype=float)
    p = np.asarray(position, dtype=float)
    q = _dot(r, r - 2.0 * p) / _dot(p, p)
    f = q * (3.0 + q * (3.0 + q)) / (1.0 + (1.0 + q) ** 1.5)
    separation = _norm(r - p)
    return -(mu / separation**3)[..., None] * (r + f[..., None] * p)


def exponential_density(altitude: ArrayLike, bases: ArrayLike, densities: ArrayLike,
                        scale_heights: ArrayLike) -> np.ndarray:
    """rho (kg/m**3) of an exponential atmosphere in bands: rho_k exp(-(h - h_k) / H_k) in the band k whose base h_k
    (m, increasing) is the highest below h; 0 below the first base is never asked (the caller stops there), and the
    last band extends upwards."""
    h = np.asarray(altitude, dtype=float)
    bases = np.asarray(bases, dtype=float)
    k = np.clip(np.searchsorted(bases, h, side="right") - 1, 0, len(bases) - 1)
    return np.asarray(densities, dtype=float)[k] * np.exp(-(h - bases[k]) / np.asarray(scale_heights, dtype=float)[k])


def drag(r: ArrayLike, v: ArrayLike, density: ArrayLike, area_per_mass: float, drag_coefficient: float,
         rotation_rate: float) -> np.ndarray:
    """Aerodynamic drag -(1/2) rho C_D (A / m) |w| w, with w = v - Omega x r the velocity relative to an atmosphere
    rotating with the body at `rotation_rate` (rad/s, about z; negative for a retrograde rotator) and rho the
    density (kg/m**3) at r."""
    r = np.asarray(r, dtype=float)
    v = np.asarray(v, dtype=float)
    wind = np.stack([-rotation_rate * r[..., 1], rotation_rate * r[..., 0], np.zeros_like(r[..., 0])], axis=-1)
    relative = v - wind
    scale = -0.5 * np.asarray(density, dtype=float) * drag_coefficient * area_per_mass * _norm(relative)
    return scale[..., None] * relative


def shadow_fraction(r: ArrayLike, sun: ArrayLike, body_radius: float, model: str = "conical",
                    sun_radius: float = SUN_RADIUS) -> np.ndarray:
    """The fraction of the Sun's disc seen from r (0 in umbra, 1 in full light) past a spherical body of radius
    `body_radius` at the origin, the Sun at `sun` (m).

    conical: the discs of apparent radii a = asin(R_sun / |sun - r|) and b = asin(R / |r|), their centres c apart
    (the angle between sun - r and -r, by atan2): full light for c >= a + b, umbra for c <= b - a, an annulus
    1 - b**2 / a**2 for c <= a - b, else 1 - A / (pi a**2) with A = a**2 alpha + b**2 beta - c y the lens where the
    flat discs overlap: y the half-chord (Heron: 2 c y = sqrt((a + b + c)(b + c - a)(a + c - b)(a + b - c))),
    alpha = atan2(y, x) and beta = atan2(y, c - x) the half-angles it subtends at each centre,
    x = (c**2 + a**2 - b**2) / (2 c). These forms keep the fraction's absolute error near 1e-16 even where the discs
    barely touch (acos(x / a) would lose half the digits there).
    cylindrical: 0 behind the body (r . s < 0) within the cylinder of radius R along the Sun's direction s, else 1.
    """
    r = np.asarray(r, dtype=float)
    sun = np.asarray(sun, dtype=float)
    if model == "cylindrical":
        direction = sun / _norm(sun)[..., None]
        along = _dot(r, direction)
        across = _norm(r - along[..., None] * direction)
        return np.where((along < 0.0) & (across < body_radius), 0.0, 1.0)
    if model != "conical":
        raise ValueError(f"shadow model {model!r}: choose conical or cylindrical")
    to_sun = sun - r
    distance, sun_distance = _norm(r), _norm(to_sun)
    a = np.arcsin(np.minimum(sun_radius / sun_distance, 1.0))
    b = np.arcsin(np.minimum(body_radius / distance, 1.0))
    c = np.arctan2(_norm(np.cross(r, to_sun)), -_dot(r, to_sun))  # not acos: exact to an ulp at small angles
    return np.select([c >= a + b, c <= b - a, c <= a - b], [1.0, 0.0, 1.0 - (b * b) / (a * a)],
                     1.0 - _lens(a, b, c) / (np.pi * a * a))


def _lens(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Area where discs of radii a and b, centres c apart, overlap (meaningful for |a - b| < c < a + b; 0 elsewhere,
    where shadow_fraction does not use it)."""
    product = (a + b + c) * (b + c - a) * (a + c - b) * (a + b - c)
    with np.errstate(divide="ignore", invalid="ignore"):
        y = np.where(product > 0.0, np.sqrt(np.maximum(product, 0.0)) / (2.0 * c), 0.0)
        x = np.where(c > 0.0, (c * c + a * a - b * b) / (2.0 * c), 0.0)
    return a * a * np.arctan2(y, x) + b * b * np.arctan2(y, c - x) - c * y


def radiation_pressure(r: ArrayLike, sun: ArrayLike, area_per_mass: float, reflectivity: float,
                       lit: ArrayLike = 1.0) -> np.ndarray:
    """Solar radiation pressure on a cannonball: lit C_R (A / m) (S / c) (au / d)**2 d_hat, with d = r - sun the
    direction away from the Sun, S the solar irradiance at 1 au, C_R the reflectivity coefficient (1 absorbing,
    2 a perfect mirror) and `lit` the fraction of the Sun seen (shadow_fraction)."""
    away = np.asarray(r, dtype=float) - np.asarray(sun, dtype=float)
    distance = _norm(away)
    scale = np.asarray(lit, dtype=float) * reflectivity * area_per_mass * (SOLAR_IRRADIANCE / C) * (AU / distance)**2
    return (scale / distance)[..., None] * away


def relativity(r: ArrayLike, v: ArrayLike, mu: float) -> np.ndarray:
    """The 1PN correction for a test body about a non-rotating mass of GM `mu` (Schwarzschild, harmonic
    coordinates): (mu / (c**2 r**3)) [(4 mu / r - v**2) r + 4 (r . v) v]. It advances the periapsis by
    6 pi mu / (c**2 a (1 - e**2)) a revolution."""
    r = np.asarray(r, dtype=float)
    v = np.asarray(v, dtype=float)
    distance = _norm(r)
    scale = mu / (C * C * distance**3)
    return scale[..., None] * ((4.0 * mu / distance - _dot(v, v))[..., None] * r + 4.0 * _dot(r, v)[..., None] * v)


def thrust(v: ArrayLike, mass: ArrayLike, force: float, direction: str | ArrayLike = "along") -> np.ndarray:
    """A thrust of `force` (N) on a body of `mass` (kg): along the velocity ("along"), against it ("against"), or
    along a fixed direction (a 3-vector, normalised here); F / m in that direction."""
    v = np.asarray(v, dtype=float)
    if isinstance(direction, str):
        if direction not in ("along", "against"):
            raise ValueError(f"thrust direction {direction!r}: choose along, against or a vector")
        unit = v / _norm(v)[..., None] * (1.0 if direction == "along" else -1.0)
    else:
        fixed = np.asarray(direction, dtype=float)
        unit = np.broadcast_to(fixed / _norm(fixed)[..., None], v.shape)
    return (force / np.asarray(mass, dtype=float))[..., None] * unit
