"""Cosmology and ExpandingSphere: the notes' numbers, units, errors, and astropy.cosmology as an independent reference.

astropy.cosmology (8.0.2 here) is imported only in these tests. It is exact where it uses closed forms or
elliptic integrals (Tcmb0 = 0) and integrates otherwise with scipy's quad at its default tolerance: its ages
above z ~ 100 are off by 1e-8 .. 1e-2 (checked against mpmath in tests/core/test_cosmology.py), and its EdS
comoving distance is 8.9e-5 off at z = 1e-12 (EDGE 58), so it is compared only where it is exact.
"""

import doctest
import math
import re
import subprocess
import sys

import astropy.units as u
import numpy as np
import pytest
from astropy.cosmology import FlatLambdaCDM, LambdaCDM, Planck18

import orbits.cosmology.models
from orbits import Cosmology, ExpandingSphere, OrbitDomainError

KM_S_MPC = u.km / u.s / u.Mpc
#: astropy's own numerical error sets how close it comes (ours is within 4e-16 of mpmath: tests/core/test_cosmology.py):
#: bounds 10x the worst measured over Z, per model - EdS 6.3e-14 (its lookback time), flat matter + Lambda 6.3e-13
#: (its comoving distance), Planck 2018 with massless neutrinos 1.4e-13 (its age), curved 3.4e-12 (its age quadrature)
ASTROPY_RTOL = {"eds": 7e-13, "flat": 7e-12, "planck": 1.5e-12, "curved": 4e-11}
Z = np.array([1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0, 1e3, 1e4])


def test_notes_hubble_constant_gives_1_33e10_years():
    """XXIV.iv: H = 0.5e-10 / yr, t = 2 / (3 H) = 1.33e10 yr; ERRATA #84: H = 48.89 km/s/Mpc."""
    notes = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    age = notes.age().to_value(u.yr)
    assert math.isclose(age, 4e10 / 3, rel_tol=4e-16) and round(age / 1e10, 2) == 1.33
    assert round(notes.hubble_constant.to_value(KM_S_MPC), 2) == 48.89
    assert notes.method == "matter_only" and notes.density_parameter(3.0) == 1.0


def test_hubble_constant_in_any_rate_unit():
    per_year = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    per_second = Cosmology.einstein_de_sitter(per_year.hubble_constant.to(1 / u.s))
    per_mpc = Cosmology.einstein_de_sitter(per_year.hubble_constant.to(KM_S_MPC))
    for other in (per_second, per_mpc):
        assert math.isclose(other.age().to_value(u.s), per_year.age().to_value(u.s), rel_tol=4e-16)


@pytest.mark.parametrize(
    "H0, error, fragment",
    [
        (70, TypeError, "has no unit; pass a Quantity such as 70 * u.km / u.s / u.Mpc"),
        (70 * u.km / u.s, u.UnitConversionError, "cannot be converted"),  # EDGE 59
        (0 * KM_S_MPC, OrbitDomainError, "H0 = 0.0 km / (Mpc s) is outside the allowed range (0, inf) 1 / s"),
        (-70 * KM_S_MPC, OrbitDomainError, "H0 = -70.0 km / (Mpc s) is outside"),  # EDGE 57: astropy gives -9.3 Gyr
        (np.nan * KM_S_MPC, OrbitDomainError, "H0 = nan km / (Mpc s)"),
        (np.inf / u.yr, OrbitDomainError, "H0 = inf 1 / yr"),
    ],
)
def test_bad_hubble_constants_are_rejected(H0, error, fragment):
    with pytest.raises(error, match=re.escape(fragment)):
        Cosmology.einstein_de_sitter(H0)


def test_densities_are_completed_by_the_friedmann_constraint():
    flat = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3)
    assert (flat.omega_m, flat.omega_k, flat.omega_l) == (0.3, 0.0, 0.7) and flat.method == "flat_matter_lambda"
    by_lambda = Cosmology.from_densities(70 * KM_S_MPC, Ol0=0.7)
    assert by_lambda.omega_m == 1 - 0.7 and by_lambda.omega_k == 0.0
    open_ = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3, Ol0=0.6)
    assert math.isclose(open_.omega_k, 0.1, rel_tol=1e-15) and open_.method == "quadrature"
    derived = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3, Ok0=0.1, Or0=1e-4)
    assert math.isclose(derived.omega_l, 0.6 - 1e-4, rel_tol=1e-15)
    with pytest.raises(TypeError, match="give Om0 or Ol0"):
        Cosmology.from_densities(70 * KM_S_MPC, Ok0=0.1)
    with pytest.raises(OrbitDomainError, match="sum to"):
        Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3, Ol0=0.6, Ok0=0.0)
    with pytest.raises(OrbitDomainError, match=r"Omega_Lambda = -0.5 follows from Om0 = 1.5 in a flat universe"):
        Cosmology.from_densities(70 * KM_S_MPC, Om0=1.5)  # a density the user never gave: the message says so


# ---- astropy.cosmology as the reference -------------------------------------------------------------------


def relative_errors(ours, reference, z):
    """Worst |ours / astropy - 1| of H, age, lookback time and comoving distance at z."""
    pairs = {
        "H": (ours.hubble_parameter(z), reference.H(z)),
        "age": (ours.age(z), reference.age(z)),
        "lookback_time": (ours.lookback_time(z), reference.lookback_time(z)),
        "comoving_distance": (ours.comoving_distance(z), reference.comoving_distance(z)),
    }
    return {name: float(np.max(np.abs((a / b).to_value(u.one) - 1))) for name, (a, b) in pairs.items()}


def test_eds_matches_astropy_flat_lambda_cdm_with_om0_1():
    H0 = 67.66 * KM_S_MPC
    errors = relative_errors(Cosmology.einstein_de_sitter(H0), FlatLambdaCDM(H0, Om0=1.0, Tcmb0=0), Z)
    assert max(errors.values()) <= ASTROPY_RTOL["eds"], errors


def test_flat_matter_lambda_matches_astropy():
    H0, om = 67.66 * KM_S_MPC, 0.30966
    ours = Cosmology.from_densities(H0, Om0=om)
    errors = relative_errors(ours, FlatLambdaCDM(H0, Om0=om, Tcmb0=0), Z)
    assert ours.method == "flat_matter_lambda" and max(errors.values()) <= ASTROPY_RTOL["flat"], errors


def test_planck18_with_massless_neutrinos_matches_astropy():
    """Planck18's H0, Om0, Tcmb0, Neff with m_nu = 0: photons and neutrinos are pure radiation, Or0 = Ogamma0 +
    Onu0, so both codes solve the same model. astropy's age integral is compared only up to z = 10."""
    planck = Planck18.clone(m_nu=0 * u.eV)
    ours = Cosmology.from_densities(
        planck.H0, Om0=planck.Om0, Ol0=planck.Ode0, Or0=planck.Ogamma0 + planck.Onu0, Ok0=planck.Ok0
    )
    errors = relative_errors(ours, planck, Z[Z <= 10])
    assert ours.method == "quadrature" and max(errors.values()) <= ASTROPY_RTOL["planck"], errors
    distances = relative_errors(ours, planck, Z)
    assert max(distances["comoving_distance"], distances["lookback_time"]) <= ASTROPY_RTOL["planck"], distances
    assert round(ours.age().to_value(u.Gyr), 3) == round(planck.age(0).to_value(u.Gyr), 3) == 13.804


def test_planck18_ages_quoted_in_the_readme():
    """Without radiation 13.8095 Gyr, astropy's FlatLambdaCDM with Tcmb0 = 0 to 2.2e-16 (its closed form); with
    photons and massless neutrinos 13.8039; astropy's Planck18 with its 0.06 eV neutrino, which orbits does not
    model, 13.7869. The README rounds them to 13.810, 13.804 and 13.787."""
    flat = FlatLambdaCDM(67.66 * KM_S_MPC, Om0=0.30966, Tcmb0=0)
    age = Cosmology.planck18().age().to_value(u.Gyr)
    assert age == pytest.approx(flat.age(0).to_value(u.Gyr), rel=2e-15) and age == pytest.approx(13.8095, abs=1e-4)
    assert Cosmology.planck18(radiation=True).age().to_value(u.Gyr) == pytest.approx(13.8039, abs=1e-4)
    assert Planck18.age(0).to_value(u.Gyr) == pytest.approx(13.7869, abs=1e-4)


@pytest.mark.parametrize("ode0", [0.6, 0.8])
def test_curved_lambda_cdm_matches_astropy(ode0):
    H0 = 70 * KM_S_MPC
    ours = Cosmology.from_densities(H0, Om0=0.3, Ol0=ode0)
    errors = relative_errors(ours, LambdaCDM(H0, Om0=0.3, Ode0=ode0, Tcmb0=0), Z[Z <= 10])
    assert max(errors.values()) <= ASTROPY_RTOL["curved"], errors


def distance_errors(ours, reference, z):
    """Worst |ours / astropy - 1| of D_L, D_A, D_M and V_C at z, and the worst |mu - mu_astropy| (mag)."""
    pairs = {
        "luminosity_distance": (ours.luminosity_distance(z), reference.luminosity_distance(z)),
        "angular_diameter_distance": (ours.angular_diameter_distance(z), reference.angular_diameter_distance(z)),
        "transverse_comoving_distance": (
            ours.transverse_comoving_distance(z), reference.comoving_transverse_distance(z)
        ),
        "comoving_volume": (ours.comoving_volume(z), reference.comoving_volume(z)),
    }
    errors = {name: float(np.max(np.abs((a / b).to_value(u.one) - 1))) for name, (a, b) in pairs.items()}
    errors["distance_modulus"] = float(np.max(np.abs(ours.distance_modulus(z).value - reference.distmod(z).value)))
    return errors


def test_planck18_distances_equal_astropy_flat_lambda_cdm():
    """Cosmology.planck18() is astropy's FlatLambdaCDM(67.66, 0.30966, Tcmb0=0). astropy's hypergeometric D_C
    loses digits at small z (6e-13 at z = 1e-3, 2e-14 at z = 0.01, against mpmath in
    tests/core/test_cosmology.py), so z >= 0.01 here."""
    ours = Cosmology.planck18()
    assert (ours.omega_m, ours.omega_l, ours.omega_r, ours.omega_k) == (0.30966, 1 - 0.30966, 0.0, 0.0)
    assert math.isclose(ours.hubble_constant.to_value(KM_S_MPC), 67.66, rel_tol=1e-15)
    errors = distance_errors(ours, FlatLambdaCDM(67.66 * KM_S_MPC, Om0=0.30966, Tcmb0=0), Z[Z >= 0.01])
    assert max(errors.values()) <= 1e-12, errors  # measured 6.7e-14 (V_C at z = 0.01), 2.2e-14 for D_L and D_A


def test_planck18_with_radiation_is_astropys_planck18_with_massless_neutrinos():
    """Photons at 2.7255 K and Neff = 3.046 massless neutrinos: Omega_r = Ogamma0 + Onu0 of astropy's model."""
    ours, reference = Cosmology.planck18(radiation=True), Planck18.clone(m_nu=0 * u.eV)
    assert math.isclose(ours.omega_r, reference.Ogamma0 + reference.Onu0, rel_tol=4e-12)  # measured 4.3e-13
    errors = distance_errors(ours, reference, Z)
    assert max(errors.values()) <= 1e-12, errors  # measured 1.0e-14
    full = Planck18  # its 0.06 eV neutrino is neither matter nor radiation: 0.09 % in D_L at z = 1 (docstring)
    assert abs(ours.luminosity_distance(1).to_value(u.Mpc) / full.luminosity_distance(1).to_value(u.Mpc) - 1) < 1e-3


@pytest.mark.parametrize("ode0", [0.6, 0.8])
def test_curved_distances_match_astropy(ode0):
    """Open (Ode0 = 0.6) and closed (0.8) universes: sinh and sin of D_C / R. astropy's V_C cancels below
    z = 0.1 (1.8e-9 at z = 1e-3; ours agrees with mpmath to 1e-15), so V_C is compared from z = 0.1."""
    ours = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3, Ol0=ode0)
    reference = LambdaCDM(70 * KM_S_MPC, Om0=0.3, Ode0=ode0, Tcmb0=0)
    errors = distance_errors(ours, reference, Z)
    errors.pop("comoving_volume")
    assert max(errors.values()) <= 4e-12, errors  # measured 3.4e-13 (astropy's elliptic integrals)
    volumes = distance_errors(ours, reference, Z[Z >= 0.1])["comoving_volume"]
    assert volumes <= 2e-12, volumes  # measured 2.2e-13


def test_distances_at_zero_and_infinite_redshift():
    eds = Cosmology.einstein_de_sitter(70 * KM_S_MPC)
    assert eds.luminosity_distance(0) == 0 and eds.distance_modulus(0) == -np.inf and eds.comoving_volume(0) == 0
    assert eds.angular_diameter_distance(np.inf) == 0 and eds.luminosity_distance(np.inf) == np.inf
    d_h = eds.hubble_distance
    assert math.isclose(eds.comoving_volume(np.inf) / (4 / 3 * np.pi * (2 * d_h) ** 3), 1.0, rel_tol=4e-16)


def test_closed_universe_through_its_big_crunch():
    """Omega_m = 2, Omega_k = -1: t_crunch = pi Omega_m / (H0 (Omega_m - 1)**1.5) = 2 pi / H0; the expansion rate
    is negative after the turnaround at pi / H0, and a(t) mirrors itself about it."""
    closed = Cosmology.from_densities(70 * KM_S_MPC, Om0=2.0, Ok0=-1.0)
    t_h = closed.hubble_time
    assert math.isclose((closed.big_crunch_time / t_h).to_value(u.one), 2 * math.pi, rel_tol=4e-16)
    assert math.isclose((closed.turnaround_time / t_h).to_value(u.one), math.pi, rel_tol=4e-16)
    times = closed.turnaround_time + [-1, 1] * u.Gyr
    a = closed.scale_factor(times)
    assert math.isclose(a[0], a[1], rel_tol=1e-14)
    rates = closed.expansion_rate(times)
    assert rates[0] > 0 and math.isclose(rates[1].value, -rates[0].value, rel_tol=1e-13)
    assert closed.scale_factor(closed.big_crunch_time) == 0
    with pytest.raises(OrbitDomainError, match="recollapses to a big crunch"):
        closed.scale_factor(closed.big_crunch_time * 1.001)
    late = closed.quantities(t=closed.turnaround_time + 1 * u.Gyr)
    assert "comoving_distance" not in late and late["hubble_parameter"] < 0 and late["lookback_time"] < 0
    with pytest.raises(OrbitDomainError, match="after the turnaround.*luminosity_distance"):
        closed.quantities(t=closed.turnaround_time + 1 * u.Gyr, only=["luminosity_distance"])
    assert Cosmology.planck18().big_crunch_time == np.inf * u.s


def test_library_does_not_import_astropy_cosmology():
    code = (
        "import sys, astropy.units as u; from orbits import Cosmology; "
        "c = Cosmology.from_densities(70 * u.km / u.s / u.Mpc, Om0=0.3, Ol0=0.6); c.comoving_distance(1.0); "
        "print('astropy.cosmology' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


# ---- units, broadcasting, errors --------------------------------------------------------------------------


def test_quantities_broadcast_and_carry_si_units():
    cosmo = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3)
    z = np.array([[0.1], [1.0]]) * np.ones(3)
    assert cosmo.comoving_distance(z).shape == (2, 3) and cosmo.comoving_distance(z).unit == u.m
    assert cosmo.age(z).unit == u.s and cosmo.hubble_parameter(z).unit == 1 / u.s
    assert cosmo.critical_density().unit == u.kg / u.m**3
    assert math.isclose(cosmo.hubble_distance.to_value(u.Mpc), 299792.458 / 70, rel_tol=1e-15)


def test_scale_factor_and_redshift_invert_the_age():
    cosmo = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3, Ol0=0.6, Or0=1e-4)
    z = np.array([0.01, 0.5, 2.0, 1100.0])
    np.testing.assert_allclose(cosmo.redshift(cosmo.age(z)).to_value(u.one), z, rtol=1e-13)
    assert cosmo.scale_factor(cosmo.age()).to_value(u.one) == pytest.approx(1.0, rel=1e-15)
    assert cosmo.scale_factor(0 * u.s) == 0 and cosmo.redshift(0 * u.s) == np.inf


@pytest.mark.parametrize(
    "call, error, fragment",
    [
        (lambda c: c.age(-1.0), OrbitDomainError, "z = -1.0 is outside (-1, inf]"),
        (lambda c: c.comoving_distance(-2.0), OrbitDomainError, "would be negative"),
        (lambda c: c.lookback_time(np.nan), OrbitDomainError, "z = nan is not a number"),
        (lambda c: c.age(1 * u.km), u.UnitConversionError, "must be dimensionless"),
        (lambda c: c.scale_factor(-1 * u.Gyr), OrbitDomainError, "t = -1.0 Gyr is outside the allowed range [0, inf)"),
        (lambda c: c.scale_factor(3.0), TypeError, "has no unit"),
        (lambda c: c.quantities(z=1, t=1 * u.Gyr), TypeError, "not both"),
        (lambda c: c.quantities(only=["age", "agee"]), KeyError, "unknown quantities ['agee']"),
    ],
)
def test_bad_epochs_raise_clear_errors(call, error, fragment):
    with pytest.raises(error) as raised:
        call(Cosmology.einstein_de_sitter(70 * KM_S_MPC))
    assert fragment in str(raised.value)


def test_quantities_today_at_a_redshift_and_at_a_time():
    cosmo = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    today = cosmo.quantities()
    assert today["age"] == cosmo.age() and today["lookback_time"] == 0 and today["scale_factor"] == 1
    at_z = cosmo.quantities(z=[0.5, 1.0], only=["comoving_distance", "scale_factor"])
    assert list(at_z) == ["comoving_distance", "scale_factor"] and at_z["scale_factor"][1] == 0.5
    at_t = cosmo.quantities(t=1 * u.Gyr)
    assert at_t["age"] == 1 * u.Gyr
    assert math.isclose(at_t["scale_factor"].value, (1 / 13.333333333333334) ** (2 / 3), rel_tol=1e-15)
    assert math.isclose(at_t["lookback_time"].to_value(u.Gyr), 4e10 / 3 / 1e9 - 1, rel_tol=1e-15)


def test_hubbles_law():
    """v = H r (XXIV.iv): 70 km/s at 1 Mpc today for H0 = 70 km/s/Mpc, and H(z) r at redshift z."""
    cosmo = Cosmology.from_densities(70 * KM_S_MPC, Om0=0.3)
    assert math.isclose(cosmo.recession_speed(1 * u.Mpc).to_value(u.km / u.s), 70.0, rel_tol=1e-15)
    at_z = cosmo.recession_speed([1, 2] * u.Mpc, z=1.0)
    hubble = cosmo.hubble_parameter(1.0).to_value(KM_S_MPC)
    np.testing.assert_allclose(at_z.to_value(u.km / u.s), [hubble, 2 * hubble], rtol=1e-15)


def test_de_sitter_has_infinite_age():
    de_sitter = Cosmology.de_sitter(70 * KM_S_MPC)
    assert de_sitter.age() == np.inf * u.s and de_sitter.hubble_parameter(5.0) == de_sitter.hubble_constant
    with pytest.raises(OrbitDomainError, match="no big bang"):
        de_sitter.scale_factor(1 * u.Gyr)


# ---- the Newtonian sphere (XXIV) and its agreement with Einstein-de Sitter --------------------------------


def test_sphere_from_hubble_reproduces_the_notes():
    """The shell at r with v = H r at zero energy started 2 / (3 H) ago: 1.33e10 yr for H = 0.5e-10 / yr."""
    shell = ExpandingSphere.from_hubble(0.5e-10 / u.yr, 1 * u.Mpc)
    t0 = shell.time_at_radius(1 * u.Mpc)
    assert math.isclose(t0.to_value(u.yr), 4e10 / 3, rel_tol=1e-15)
    assert math.isclose(shell.hubble_parameter(t0).to_value(1 / u.yr), 0.5e-10, rel_tol=1e-15)
    assert math.isclose(shell.radius(t0).to_value(u.Mpc), 1.0, rel_tol=1e-15)
    v = shell.speed(t0)
    assert math.isclose(v.to_value(u.m / u.s), (shell.hubble_parameter(t0) * shell.radius(t0)).si.value, rel_tol=1e-15)


def test_sphere_is_critical_and_matches_einstein_de_sitter():
    """Omega = 1 (to 4 ulp); the relativistic EdS scale factor equals the Newtonian shell's r(t) / r(t0)."""
    H0, r0 = 67.66 * KM_S_MPC, 10 * u.Mpc
    shell, eds = ExpandingSphere.from_hubble(H0, r0), Cosmology.einstein_de_sitter(H0)
    times = np.geomspace(1e-6, 10, 8) * eds.age()
    np.testing.assert_allclose(shell.density_parameter(times).to_value(u.one), 1.0, rtol=4 * 2**-52)
    np.testing.assert_allclose((shell.radius(times) / r0).to_value(u.one), eds.scale_factor(times), rtol=1e-15)
    np.testing.assert_allclose(shell.density(times), eds.critical_density(eds.redshift(times)), rtol=1e-14)
    np.testing.assert_allclose(shell.hubble_parameter(times), eds.hubble_parameter(eds.redshift(times)), rtol=1e-15)


def test_sphere_from_mass_and_its_errors():
    sun = ExpandingSphere.from_mass(1.98847e30 * u.kg)
    by_gm = ExpandingSphere.from_mass(1.3271244e20 * u.m**3 / u.s**2)
    assert math.isclose(sun.radius(1 * u.yr).value, by_gm.radius(1 * u.yr).value, rel_tol=1e-4)
    assert set(sun.quantities(1 * u.yr)) == {"radius", "speed", "hubble_parameter", "density", "density_parameter"}
    with pytest.raises(OrbitDomainError, match="enclosed mass M = -"):
        ExpandingSphere.from_mass(-1 * u.kg)
    with pytest.raises(OrbitDomainError, match=r"t = -1.0 s is outside \[0, inf\) s"):
        sun.radius(-1 * u.s)
    with pytest.raises(OrbitDomainError, match="v and H are infinite at the big bang"):
        sun.speed(0 * u.s)
    with pytest.raises(KeyError, match="unknown quantities"):
        sun.quantities(1 * u.yr, only=["age"])


def test_docstring_examples_run():
    assert doctest.testmod(orbits.cosmology.models).failed == 0


# ---- values beyond float64, and times beyond z = -1 -----------------------------------------------------------


@pytest.mark.parametrize("model", [Cosmology.einstein_de_sitter(0.5e-10 / u.yr),
                                   Cosmology.from_densities(67.66 * KM_S_MPC, Om0=0.3)])
def test_a_finite_value_beyond_float64_is_an_error_not_inf(model):
    """luminosity_distance(1e300) returned inf with an overflow warning; H and rho_c read inf at finite z."""
    with pytest.raises(OrbitDomainError, match=r"the luminosity distance D_L at z = 1e\+300 is larger than float64"):
        model.luminosity_distance(1e300)
    with pytest.raises(OrbitDomainError, match=r"the Hubble parameter H at z = 1e\+300 is larger than float64"):
        model.hubble_parameter(1e300)
    with pytest.raises(OrbitDomainError, match=r"the critical density rho_c at z = 1e\+200 is larger than float64"):
        model.critical_density(1e200)
    assert model.luminosity_distance(np.inf).value == np.inf and model.hubble_parameter(np.inf).value == np.inf
    assert model.density_parameter(1e200).value == 1.0  # matter dominates; no overflow in the unused branch


def test_the_distance_modulus_stays_finite_where_the_luminosity_distance_does_not():
    import mpmath

    model = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    for z in (1.0, 1e10, 1e300):
        transverse = model.comoving_distance(z).to_value(u.m)  # flat: D_M = D_C
        with mpmath.workdps(40):
            ten_parsecs = mpmath.mpf(orbits.cosmology.models.TEN_PARSECS)
            exact = 5 * mpmath.log10((1 + mpmath.mpf(z)) * mpmath.mpf(transverse) / ten_parsecs)
        assert model.distance_modulus(z).value == pytest.approx(float(exact), rel=4e-16, abs=0)  # measured 1 ulp


def test_a_time_so_late_that_z_rounds_to_minus_one_names_the_time():
    """--t '1e30 Gyr' blamed a redshift z = -1 the user never gave."""
    model = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    with pytest.raises(OrbitDomainError, match=r"t = 1e\+30 Gyr is so late that the scale factor a = 1\.77845e\+19 "
                                               r"leaves z = 1 / a - 1 = -1"):
        model.quantities(t=1e30 * u.Gyr)
    late = model.quantities(t=1e30 * u.Gyr, only=["scale_factor", "hubble_parameter"])
    expected = 2 / (3 * (1e30 * u.Gyr).to_value(u.s))  # Einstein-de Sitter: H = 2 / (3 t)
    assert late["hubble_parameter"].to_value(1 / u.s) == pytest.approx(expected, rel=4e-16)  # measured 1.1e-16
