"""The perturbing accelerations of orbits.core.forces.accelerations, each against what did not come from its formula:
the gradient of the zonal potential taken by mpmath, the direct difference of two pulls at 40 digits, the area of two
overlapping discs integrated by mpmath, the textbook J2 components, and the relativistic periapsis advance flown by
the project's DOP853."""

import math

import mpmath
import numpy as np
import pytest

from orbits._common.constants import body
from orbits.core import dop853
from orbits.core.forces import accelerations as forces

MU_EARTH, R_EARTH = 3.986004418e14, 6_378_136.6
#: the Earth's J2 ... J6 from the catalogue
EARTH_J = [getattr(body("Earth"), f"j{n}") for n in range(2, 7)]
GM_SUN, GM_MOON = 1.32712440041e20, 4.9028e12


@pytest.fixture
def rng(fresh_seed):
    return np.random.default_rng(fresh_seed)


def _relative(a, b):
    return float(np.max(np.linalg.norm(np.asarray(a) - np.asarray(b), axis=-1) / np.linalg.norm(b, axis=-1)))


def _zonal_gradient(point, mu, radius, j):
    """a = grad V of V = -(mu / r) sum Jn (R / r)**n Pn(z / r), differentiated by mpmath at 40 digits."""
    with mpmath.workdps(40):
        def potential(x, y, z):
            r = mpmath.sqrt(x * x + y * y + z * z)
            return -mu / r * mpmath.fsum(jn * (radius / r) ** n * mpmath.legendre(n, z / r)
                                         for n, jn in enumerate(j, start=2))

        x = [mpmath.mpf(float(c)) for c in point]
        return [float(mpmath.diff(potential, x, tuple(int(i == k) for i in range(3)))) for k in range(3)]


def test_zonal_harmonics_are_the_gradient_of_their_potential(rng):
    """Each degree alone (J = 1e-3) and the Earth's J2-J6 together, at 30 random points from 1.02 to 6 Earth radii
    over every latitude and at both poles: within 3e-14 of |a| of mpmath's gradient (measured 5.9e-15 over 40 seeds,
where a degree's terms partly cancel)."""
    directions = rng.normal(size=(30, 3))
    directions[:2] = [[0, 0, 1], [0, 0, -1]]
    points = directions / np.linalg.norm(directions, axis=1)[:, None] * rng.uniform(1.02, 6, (30, 1)) * R_EARTH
    sets = [[0.0] * (n - 2) + [1e-3] for n in range(2, 7)] + [EARTH_J]
    worst = 0.0
    for j in sets:
        ours = forces.zonal(points, MU_EARTH, R_EARTH, j)
        reference = np.array([_zonal_gradient(p, MU_EARTH, R_EARTH, j) for p in points])
        worst = max(worst, _relative(ours, reference))
    assert worst <= 3e-14, worst


def test_j2_matches_its_textbook_components(rng):
    """a = -(3/2) J2 mu R**2 / r**5 [x (1 - 5 z**2/r**2), y (1 - 5 z**2/r**2), z (3 - 5 z**2/r**2)] (measured 1.5e-15
    of |a| over 200 seeds, where 1 - 5 z**2 / r**2 cancels in the textbook form itself)."""
    r = rng.normal(size=(200, 3)) * 8e6
    x, y, z = r.T
    d = np.linalg.norm(r, axis=1)
    k = -1.5 * EARTH_J[0] * MU_EARTH * R_EARTH**2 / d**5
    flat = 1 - 5 * z**2 / d**2
    textbook = np.stack([k * x * flat, k * y * flat, k * z * (flat + 2)], 1)
    assert _relative(forces.zonal(r, MU_EARTH, R_EARTH, EARTH_J[:1]), textbook) <= 1e-14


def _direct_third_body(r, p, mu):
    with mpmath.workdps(40):
        r, p = [mpmath.mpf(float(c)) for c in r], [mpmath.mpf(float(c)) for c in p]
        d = [pi - ri for pi, ri in zip(p, r)]
        nd, np_ = mpmath.sqrt(sum(c * c for c in d)), mpmath.sqrt(sum(c * c for c in p))
        return [float(mu * (di / nd**3 - pi / np_**3)) for di, pi in zip(d, p)]


@pytest.mark.parametrize("distance, mu, scale", [(1.496e11, GM_SUN, 7e6), (3.844e8, GM_MOON, 7e6),
                                                 (3.844e8, MU_EARTH, 2e6), (3.844e8, GM_MOON, 4.2e7)])
def test_a_third_bodys_pull_keeps_its_digits_where_the_two_pulls_cancel(rng, distance, mu, scale):
    """A LEO with the Sun (the two pulls agree to 1e-9), the Moon on a LEO and on a GEO, the Earth on a lunar orbit:
    Battin's form within 1e-14 of |a| of the 40-digit difference (measured 1.3e-15 over 40 seeds); the plain
    difference loses up to 9 digits on the first."""
    r = rng.normal(size=(50, 3)) * scale
    p = rng.normal(size=(50, 3))
    p *= distance / np.linalg.norm(p, axis=1)[:, None]
    reference = np.array([_direct_third_body(a, b, mu) for a, b in zip(r, p)])
    assert _relative(forces.third_body(r, p, mu), reference) <= 1e-14


def _lens_fraction(a, b, c):
    """The visible fraction of a disc of radius a whose centre is c from that of an occulting disc of radius b, by
    integrating the overlap of their vertical chords (mpmath.quad)."""
    with mpmath.workdps(30):
        a, b, c = mpmath.mpf(a), mpmath.mpf(b), mpmath.mpf(c)

        def overlap(x):
            chord_a = mpmath.sqrt(max(a * a - (x - c) ** 2, 0))
            chord_b = mpmath.sqrt(max(b * b - x * x, 0))
            return 2 * min(chord_a, chord_b)

        low, high = max(c - a, -b), min(c + a, b)
        crossing = (c * c + b * b - a * a) / (2 * c) if c else low  # where the circles cross: the kink of min()
        points = sorted({low, high, *[t for t in (c - a, c + a, -b, b, crossing) if low < t < high]})
        covered = mpmath.quad(overlap, points) if high > low else 0
        return float(1 - covered / (mpmath.pi * a * a))


def _geometry(a, b, c):
    """A satellite and a Sun such that the apparent radii are a (Sun) and b (Earth), c apart."""
    distance = R_EARTH / math.sin(b)
    sun_distance = forces.SUN_RADIUS / math.sin(a)
    r = np.array([-distance, 0.0, 0.0])  # the Earth seen along +x from the satellite
    sun = r + sun_distance * np.array([math.cos(c), math.sin(c), 0.0])
    return r, sun


@pytest.mark.parametrize("a, b", [(4.65e-3, 0.9), (4.65e-3, 0.3), (4.65e-3, 4.0e-3), (4.65e-3, 2.0e-3),
                                  (4.65e-3, 4.65e-3), (4.65e-3, 4.7e-3)])
def test_the_conical_shadow_is_the_visible_share_of_the_suns_disc(a, b):
    """Over c from 0 to a + b + 1e-3 (umbra, annulus, partial, full light), and within 1e-14 to 1e-2 of the contacts,
    for a low orbit (the Earth far wider than the Sun), distant ones, and equal discs: within 1e-13 of mpmath's
    integral of the overlapping discs (measured 1.4e-14, the rounding of the geometry built for the test: b's
    1e-16 moves the fraction by up to 1 / a of it), and continuous where the cases meet."""
    cs = np.concatenate([np.linspace(0.0, a + b + 1e-3, 61)[1:], (a + b) * (1 - np.logspace(-14, -2, 7)),
                         abs(a - b) * (1 + np.logspace(-14, -2, 7))])
    cs = cs[cs > 0]
    ours = [float(forces.shadow_fraction(*_geometry(a, b, c), R_EARTH)) for c in cs]
    reference = [_lens_fraction(a, b, c) for c in cs]
    assert max(abs(x - y) for x, y in zip(ours, reference)) <= 1e-13
    for edge in (a + b, abs(b - a)):  # either side of a boundary: the two cases agree there
        near = [float(forces.shadow_fraction(*_geometry(a, b, edge * (1 + s)), R_EARTH)) for s in (-1e-9, 1e-9)]
        assert abs(near[0] - near[1]) <= 1e-4


def test_the_cylindrical_shadow_is_the_cylinder_behind_the_body():
    sun = np.array([1.496e11, 0.0, 0.0])
    inside = forces.shadow_fraction(np.array([[-7e6, 0, 6.3e6], [-7e6, 6.4e6, 0], [7e6, 0, 0]]), sun, R_EARTH,
                                    "cylindrical")
    assert inside.tolist() == [0.0, 1.0, 1.0]
    with pytest.raises(ValueError, match="conical or cylindrical"):
        forces.shadow_fraction(np.ones(3), sun, R_EARTH, "umbra")


def test_radiation_pressure_is_the_solar_constant_over_c_at_one_au():
    """S / c = 4.54e-6 N/m2 at 1 au (S = 1361 W/m2), away from the Sun, falling as 1 / d**2, scaled by C_R A / m and
    the lit fraction."""
    sun = np.array([forces.AU, 0.0, 0.0])
    a = forces.radiation_pressure(np.zeros(3), sun, area_per_mass=0.02, reflectivity=1.3, lit=0.5)
    assert np.allclose(a, [-0.5 * 1.3 * 0.02 * 1361.0 / 299_792_458.0, 0, 0], rtol=1e-15, atol=0)
    far = forces.radiation_pressure(np.zeros(3), 2 * sun, 0.02, 1.3, 0.5)
    assert np.allclose(far, a / 4, rtol=1e-15, atol=0)


def test_relativity_advances_mercurys_perihelion_by_the_classical_amount():
    """One orbit of Mercury (a = 0.387 au, e = 0.2056) with the 1PN term, flown by DOP853 from perihelion: the
    eccentricity vector turns by 6 pi mu / (c**2 a (1 - e**2)) = 5.02e-7 rad within 5e-5 of it (measured 7.3e-6:
    the angle is read from the osculating vector after one Keplerian period, not at the next perihelion)."""
    a, e = 0.387098 * forces.AU, 0.205630
    q, vq = a * (1 - e), math.sqrt(GM_SUN * (1 + e) / (a * (1 - e)))

    def field(y):
        r, v = y[:3], y[3:]
        gravity = -GM_SUN * r / np.linalg.norm(r) ** 3
        return np.concatenate([v, gravity + forces.relativity(r, v, GM_SUN)])

    period = 2 * math.pi * math.sqrt(a**3 / GM_SUN)
    arc = dop853.integrate(field, np.array([q, 0, 0, 0, vq, 0]), period, rtol=1e-13, atol=1e-3)
    r, v = arc.end[:3], arc.end[3:]
    e_vector = np.cross(v, np.cross(r, v)) / GM_SUN - r / np.linalg.norm(r)
    turned = math.atan2(e_vector[1], e_vector[0])
    expected = 6 * math.pi * GM_SUN / (forces.C**2 * a * (1 - e * e))
    assert abs(turned / expected - 1) <= 5e-5, turned / expected


def test_drag_opposes_the_wind_and_grows_as_its_square():
    """A prograde equatorial LEO in an atmosphere turning with the Earth: the air meets it at v - omega r, and
    a = -(1/2) rho C_D (A/m) |w| w exactly; the bands give their own densities at their bases."""
    omega = 7.2921159e-5
    r, v = np.array([6.778e6, 0, 0]), np.array([0, 7668.6, 0])
    a = forces.drag(r, v, 3.725e-12, area_per_mass=0.01, drag_coefficient=2.2, rotation_rate=omega)
    wind = 7668.6 - omega * 6.778e6
    assert a[1] == pytest.approx(-0.5 * 3.725e-12 * 2.2 * 0.01 * wind * wind, rel=1e-15) and a[0] == a[2] == 0
    bases, densities, heights = [1e5, 1.1e5, 1.2e5], [5.297e-7, 9.661e-8, 2.438e-8], [5877.0, 7263.0, 9473.0]
    assert forces.exponential_density(np.array(bases), bases, densities, heights).tolist() == densities
    above = forces.exponential_density(1.5e5, bases, densities, heights)
    assert above == pytest.approx(2.438e-8 * math.exp(-3e4 / 9473.0), rel=1e-15)


def test_thrust_points_where_it_is_told():
    v = np.array([[3.0, 4.0, 0.0], [0.0, 0.0, 2.0]])
    assert np.allclose(forces.thrust(v, 500.0, 0.1, "along"), 0.1 / 500 * v / np.linalg.norm(v, axis=1)[:, None])
    assert np.allclose(forces.thrust(v, np.array([500.0, 250.0]), 0.1, "against")[1], [0, 0, -0.1 / 250])
    assert np.allclose(forces.thrust(v, 500.0, 0.1, [0, 2.0, 0]), [[0, 2e-4, 0]] * 2)
    with pytest.raises(ValueError, match="along, against or a vector"):
        forces.thrust(v, 500.0, 0.1, "up")
