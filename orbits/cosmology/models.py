"""The expanding universe of section XXIV and the Friedmann models around it, with astropy units.

    >>> import astropy.units as u
    >>> from orbits import Cosmology, ExpandingSphere
    >>> notes = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)  # XXIV.iv: H = 0.5e-10 per year
    >>> notes.age().to(u.yr)
    <Quantity 1.33333333e+10 yr>
    >>> notes.hubble_constant.to(u.km / u.s / u.Mpc).round(2)
    <Quantity 48.89 km / (Mpc s)>
    >>> flat = Cosmology.from_densities(67.66 * u.km / u.s / u.Mpc, Om0=0.30966)  # flat: Ol0 = 1 - Om0
    >>> flat.method, flat.age().to(u.Gyr).round(3)
    ('flat_matter_lambda', <Quantity 13.81 Gyr>)
    >>> shell = ExpandingSphere.from_hubble(0.5e-10 / u.yr, 1 * u.Mpc)  # XXIV's Newtonian shell
    >>> shell.time_at_radius(1 * u.Mpc).to(u.yr)
    <Quantity 1.33333333e+10 yr>

Cosmology stores H0 (1/s) and today's density parameters as floats; like astropy.cosmology it multiplies the
dimensionless E(z) and its integrals by one scale, t_H = 1 / H0 or d_H = c / H0, and it chooses its method
(closed form or quadrature, orbits.core.cosmology.friedmann.Friedmann) once, at construction. astropy.cosmology itself
is never imported (its import is heavy); the tests use it as an independent reference.

ExpandingSphere is the notes' Newtonian model: a shell enclosing G M moves at the zero-energy speed
sqrt(2 G M / r), so r(t) = (9 G M t**2 / 2)**(1/3), v(t) = (4 G M / (3 t))**(1/3), H = 2 / (3 t); its mean
density is exactly critical (Omega = 1), which is why it agrees with Cosmology.einstein_de_sitter.
The matching N-body problem for rebound and heyoka is built in orbits.validate.builders.
"""

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from functools import cached_property

import astropy.constants as const
import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import SPEED_OF_LIGHT, Body, G
from orbits._common.tables import check_names
from orbits.core.checks import require_positive
from orbits.core.cosmology import friedmann, sphere
from orbits.core.errors import OrbitDomainError

PER_S = u.s**-1
STEFAN_BOLTZMANN = const.sigma_sb.si.value  # W / (m2 K4), CODATA 2018 (exact in the 2019 SI)
KG_PER_M3 = u.kg / u.m**3
_HUBBLE_EXAMPLE = "70 * u.km / u.s / u.Mpc or 0.5e-10 / u.yr"


def _hubble(value, name="Hubble constant H0"):
    """H (1/s) from a Quantity in any unit of 1/time (km/s/Mpc, 1/yr, 1/s); finite and > 0."""
    if not isinstance(value, u.Quantity):
        raise TypeError(f"{name} = {value!r} has no unit; pass a Quantity such as {_HUBBLE_EXAMPLE}")
    hubble = units.to_si(value, PER_S, name)
    if not np.all(np.isfinite(hubble) & (hubble > 0)):
        bad = np.ravel(value)[~np.ravel(np.isfinite(hubble) & (hubble > 0))][0]
        raise OrbitDomainError(f"{name} = {bad} is outside the allowed range (0, inf) 1 / s: it must be positive")
    return hubble


def _densities(Om0, Ol0, Or0, Ok0):
    """(Omega_m, Omega_r, Omega_k, Omega_Lambda) today from those given; see Cosmology.from_densities."""
    given = {"Om0": Om0, "Ol0": Ol0, "Or0": Or0, "Ok0": Ok0}
    om, ol, orad, ok = (None if v is None else inputs.single(units.to_number, v, k) for k, v in given.items())
    orad = 0.0 if orad is None else orad
    if om is None and ol is None:
        raise TypeError("give Om0 or Ol0 (or both); Ok0 alone does not fix the model")
    if ok is None and (om is None or ol is None):
        ok = 0.0  # one of Om0, Ol0: a flat universe
    if om is None:
        om = _derived("Omega_m", 1.0 - ol - orad - ok, given)
    elif ol is None:
        ol = _derived("Omega_Lambda", 1.0 - om - orad - ok, given)
    elif ok is None:
        ok = 1.0 - om - ol - orad
    return om, orad, ok, ol


def _derived(name: str, value: float, given: dict) -> float:
    """A density that follows from the others (they sum to 1), OrbitDomainError naming what was given if it comes
    out negative: the user never gave it, so the message says where it came from."""
    if value < 0:
        shown = ", ".join(f"{key} = {float(units.to_number(v, key))!r}" for key, v in given.items() if v is not None)
        flat = " in a flat universe (Ok0 = 0 unless given)" if given["Ok0"] is None else ""
        other = "Ol0" if name == "Omega_Lambda" else "Om0"
        raise OrbitDomainError(f"{name} = {value!r} follows from {shown}{flat}, as the densities sum to 1, and a "
                               f"density cannot be negative: give {other} too (the curvature Ok0 then follows), or "
                               f"densities that leave room for it")
    return value


#: the model each closed form or the quadrature stands for (Cosmology.method)
MODEL_NAMES = {
    "matter_only": "Einstein-de Sitter",
    "lambda_only": "de Sitter",
    "radiation_only": "Radiation only",
    "curvature_only": "Milne (empty, open)",
    "flat_matter_lambda": "Flat matter + Lambda",
    "quadrature": "Friedmann (quadrature)",
}


@dataclass(frozen=True, eq=False, repr=False)
class Cosmology(display.Displayed):
    """A Friedmann universe: H0 (1/s) and today's density parameters (dimensionless, summing to 1).

    Build it with Cosmology.einstein_de_sitter, Cosmology.de_sitter or Cosmology.from_densities. Redshifts z
    are plain numbers (or dimensionless Quantities) in (-1, inf] and broadcast; times are Quantities.
    """

    h0: float
    omega_m: float
    omega_r: float = 0.0
    omega_k: float = 0.0
    omega_l: float = 0.0
    #: a published model's name ("Planck 2018"), shown before the kind of model; None for a model of one's own
    name: str | None = None
    model: friedmann.Friedmann = field(init=False, repr=False)

    def __post_init__(self):
        require_positive(self.h0, "Hubble constant H0", "1 / s")
        model = friedmann.Friedmann(self.omega_m, self.omega_r, self.omega_k, self.omega_l)
        object.__setattr__(self, "h0", float(self.h0))
        object.__setattr__(self, "model", model)
        for name in ("omega_m", "omega_r", "omega_k", "omega_l"):
            object.__setattr__(self, name, getattr(model, name))

    # ---- constructors -------------------------------------------------------------------------
    @classmethod
    def einstein_de_sitter(cls, H0: u.Quantity) -> "Cosmology":
        """Flat, matter only (Omega_m = 1): the relativistic twin of the notes' Newtonian sphere (XXIV)."""
        return cls(float(_hubble(H0)), 1.0)

    @classmethod
    def de_sitter(cls, H0: u.Quantity) -> "Cosmology":
        """Flat, cosmological constant only (Omega_Lambda = 1): E = 1 and no big bang."""
        return cls(float(_hubble(H0)), 0.0, omega_l=1.0)

    @classmethod
    def from_densities(
        cls,
        H0: u.Quantity,
        Om0: float | u.Quantity | None = None,
        Ol0: float | u.Quantity | None = None,
        Or0: float | u.Quantity | None = None,
        Ok0: float | u.Quantity | None = None,
    ) -> "Cosmology":
        """Any Friedmann universe. Or0 defaults to 0. Of Om0, Ol0 and Ok0 give two and the third follows from
        Om0 + Or0 + Ok0 + Ol0 = 1; give only Om0 or only Ol0 for a flat universe (Ok0 = 0); or give all three,
        which must then sum to 1 with Or0 (within 1e-12)."""
        return cls(float(_hubble(H0)), *_densities(Om0, Ol0, Or0, Ok0))

    @classmethod
    def planck18(cls, radiation: bool = False) -> "Cosmology":
        """The Planck 2018 flat Lambda-CDM model: H0 = 67.66 km/s/Mpc, Omega_m = 0.30966, Omega_k = 0.

        Planck Collaboration 2020, A&A 641, A6 (paper VI), table 2, TT,TE,EE+lowE+lensing+BAO, with the values
        astropy.cosmology.Planck18 uses. Without `radiation`, Omega_Lambda = 1 - Omega_m: astropy's
        FlatLambdaCDM(67.66, 0.30966, Tcmb0=0) to 1e-13 (tests/api/test_cosmology_api.py). With it, photons at
        Tcmb0 = 2.7255 K and Neff = 3.046 neutrinos as radiation (Omega_r = 9.139e-5), which is astropy's Planck18
        with massless neutrinos (m_nu = 0). Planck's one 0.06 eV neutrino, neither radiation nor matter, is left
        out either way: astropy's Planck18 has an age 13.787 Gyr and D_L(z = 1) = 6791.3 Mpc, this model 13.810
        Gyr and 6797.4 Mpc without radiation, 13.804 Gyr and 6796.8 Mpc with it.
        """
        hubble = PLANCK18_H0 * u.km / u.s / u.Mpc
        orad = _radiation_density(float(_hubble(hubble)), PLANCK18_TCMB, PLANCK18_NEFF) if radiation else 0.0
        model = cls.from_densities(hubble, Om0=PLANCK18_OM0, Or0=orad)
        return replace(model, name="Planck 2018" + (" with radiation" if radiation else ""))

    # ---- scales -------------------------------------------------------------------------------
    @cached_property
    def method(self) -> str:
        """How distances and times are computed, chosen at construction (orbits.core.cosmology.friedmann.METHODS)."""
        return self.model.method

    @cached_property
    def hubble_constant(self) -> u.Quantity:
        """H0 (1/s)."""
        return self.h0 << PER_S

    @cached_property
    def hubble_time(self) -> u.Quantity:
        """t_H = 1 / H0 (s)."""
        return self._t_h << units.S

    @cached_property
    def hubble_distance(self) -> u.Quantity:
        """d_H = c / H0 (m)."""
        return self._d_h << units.M

    @cached_property
    def turnaround_time(self) -> u.Quantity:
        """t (s) after the big bang at which a recollapsing universe stops expanding (a = a_max); inf otherwise."""
        return self.model.turnaround_age * self._t_h << units.S

    @cached_property
    def big_crunch_time(self) -> u.Quantity:
        """t (s) of the big crunch (a = 0 again), twice the turnaround time; inf if the universe never recollapses.

        Matter and curvature only (Omega_m > 1): pi Omega_m / (H0 (Omega_m - 1)**1.5) in closed form, to 1.7e-16
        (tests/core/test_cosmology.py)."""
        return self.model.crunch_age * self._t_h << units.S

    @cached_property
    def _t_h(self):
        return 1.0 / self.h0

    @cached_property
    def _d_h(self):
        return SPEED_OF_LIGHT / self.h0

    # ---- quantities at a redshift -------------------------------------------------------------
    def hubble_parameter(self, z: float | np.ndarray | u.Quantity = 0.0) -> u.Quantity:
        """H(z) = H0 E(z) (1/s), E**2 = Omega_r x**4 + Omega_m x**3 + Omega_k x**2 + Omega_Lambda, x = 1 + z; inf at
        z = inf, OrbitDomainError where a finite z gives an H beyond float64."""
        z = _redshift(z)
        with np.errstate(over="ignore"):
            return _representable(self.h0 * self.model.efunc(z), "Hubble parameter H", "1 / s", "z", z) << PER_S

    def age(self, z: float | np.ndarray | u.Quantity = 0.0) -> u.Quantity:
        """t(z) (s) since the big bang: (2/3) / H0 (1 + z)**-1.5 for Einstein-de Sitter (XXIV.iv); inf for de Sitter."""
        return self.model.age(_redshift(z), self._t_h) << units.S

    def lookback_time(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """t0 - t(z) (s): how long ago light left redshift z."""
        return self.model.lookback_time(_redshift(z), self._t_h) << units.S

    def comoving_distance(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """Line-of-sight comoving distance D_C = (c / H0) int_0^z dz' / E(z') (m); 2 c / H0 at z = inf for EdS."""
        return self.model.comoving_distance(_redshift(z), self._d_h) << units.M

    def transverse_comoving_distance(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """D_M (m): D_C if flat, R sinh(D_C / R) if open, R sin(D_C / R) if closed, R = (c / H0) / sqrt(|Omega_k|)."""
        return self.model.transverse_comoving_distance(_redshift(z), self._d_h) << units.M

    def luminosity_distance(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """D_L = (1 + z) D_M (m): a source of luminosity L has flux L / (4 pi D_L**2). Equal to astropy's to 1e-13;
        inf at z = inf, OrbitDomainError where a finite z gives a D_L beyond float64 (z above about 1e281)."""
        z = _redshift(z)
        with np.errstate(over="ignore"):
            distance = (1.0 + z) * self.model.transverse_comoving_distance(z, self._d_h)
        return _representable(distance, "luminosity distance D_L", "m", "z", z) << units.M

    def angular_diameter_distance(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """D_A = D_M / (1 + z) (m): a proper length l at z spans the angle l / D_A. 0 at z = inf."""
        z = _redshift(z)
        with np.errstate(invalid="ignore"):
            ratio = self.model.transverse_comoving_distance(z, self._d_h) / (1.0 + z)
        return np.where(np.isinf(z), 0.0, ratio) << units.M

    def distance_modulus(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """mu = m - M = 5 log10(|D_L| / 10 pc) = 5 [log10(1 + z) + log10(|D_M| / 10 pc)] (mag, as astropy gives it);
        -inf at z = 0. Formed from the logarithms, so it stays finite where D_L itself leaves float64.

        |D_L|: beyond the antipode of a closed universe D_M = R sin(D_C / R) < 0, and the flux goes as 1 / D_L**2."""
        z = _redshift(z)
        transverse = np.abs(self.model.transverse_comoving_distance(z, self._d_h))
        with np.errstate(divide="ignore"):
            return 5.0 * (np.log10(1.0 + z) + np.log10(transverse / TEN_PARSECS)) << u.mag

    def comoving_volume(self, z: float | np.ndarray | u.Quantity) -> u.Quantity:
        """V_C (m3): the comoving volume of the whole sky out to z; 4 pi D_C**3 / 3 if flat."""
        return self.model.comoving_volume(_redshift(z), self._d_h) << u.m**3

    def critical_density(self, z: float | np.ndarray | u.Quantity = 0.0) -> u.Quantity:
        """rho_c(z) = 3 H(z)**2 / (8 pi G) (kg/m3); inf at z = inf, OrbitDomainError where a finite z gives a
        density beyond float64."""
        z = _redshift(z)
        with np.errstate(over="ignore"):
            density = sphere.critical_density(self.hubble_parameter(z).to_value(PER_S), G)
        return _representable(density, "critical density rho_c", "kg / m3", "z", z) << KG_PER_M3

    def density_parameter(self, z: float | np.ndarray | u.Quantity = 0.0) -> u.Quantity:
        """Omega_m(z) = rho_m(z) / rho_c(z) (dimensionless): 1 at every z for Einstein-de Sitter."""
        return self.model.matter_density_parameter(_redshift(z)) << u.one

    def recession_speed(self, distance: u.Quantity, z: float | np.ndarray | u.Quantity = 0.0) -> u.Quantity:
        """Hubble's law v = H(z) r (m/s) for a proper distance r (length) at redshift z (XXIV.iv)."""
        r = units.to_si(distance, units.M, "distance r")
        return r * self.hubble_parameter(z).to_value(PER_S) << units.M_PER_S

    # ---- quantities at a time -----------------------------------------------------------------
    def scale_factor(self, t: u.Quantity) -> u.Quantity:
        """a(t) (dimensionless) at time t (time) after the big bang; (1.5 H0 t)**(2/3) for Einstein-de Sitter."""
        return self.model.scale_factor(self._time(t), self._t_h) << u.one

    def _time(self, t):
        """t (s) after the big bang (_cosmic_time), refused, quoted in the unit it was given, after a big crunch."""
        seconds = _cosmic_time(t)
        crunch = self.big_crunch_time
        late = seconds > crunch.to_value(units.S) * (1 + 4 * np.finfo(float).eps)  # the crunch itself is a = 0
        if np.any(late):
            value = np.ravel(t)[np.ravel(late)][0]
            at = f"{crunch.to(value.unit):.7g}"
            raise OrbitDomainError(
                f"time since the big bang t = {value} is outside [0, {at}]: this universe stops expanding at a = "
                f"{self.model.max_scale_factor:.7g} and recollapses to a big crunch at t = {at}")
        return seconds

    def redshift(self, t: u.Quantity) -> u.Quantity:
        """z = 1 / a(t) - 1 (dimensionless) of light emitted at time t (time) after the big bang."""
        return _redshift_of(self.scale_factor(t))

    def expansion_rate(self, t: u.Quantity) -> u.Quantity:
        """H(t) = (da/dt) / a (1/s) at time t (time) after the big bang: negative while a universe recollapses."""
        seconds = self._time(t)
        a = self.scale_factor(t).to_value(u.one)
        with np.errstate(over="ignore"):  # infinite at the big bang and the crunch (a = 0), finite elsewhere
            h = _representable(self.h0 * self.model.efunc_at_scale_factor(a), "expansion rate H", "1 / s",
                               "t (s)", seconds, a > 0)
        return np.where(seconds > self.turnaround_time.to_value(units.S), -h, h) << PER_S

    # ---- tables -------------------------------------------------------------------------------
    @property
    def description(self) -> str:
        """E.g. "Einstein-de Sitter, H0 = 48.8896 km/s/Mpc, Om = 1", or "Planck 2018: flat matter + Lambda, H0 = ...":
        the model's name if it has one, its kind, H0 and the nonzero densities."""
        h0 = self.hubble_constant.to_value(u.km / u.s / u.Mpc)
        labels = ("Om", "Or", "Ok", "Ol")
        values = (self.omega_m, self.omega_r, self.omega_k, self.omega_l)
        densities = "".join(f", {label} = {value:.6g}" for label, value in zip(labels, values) if value != 0)
        kind = MODEL_NAMES[self.method]
        named = kind if self.name is None else f"{self.name}: {kind[0].lower()}{kind[1:]}"
        return f"{named}, H0 = {h0:.6g} km/s/Mpc{densities}"

    def __repr__(self) -> str:
        return f"Cosmology({self.description})"

    def quantities(
        self,
        z: float | np.ndarray | u.Quantity | None = None,
        t: u.Quantity | None = None,
        only: Iterable[str] | None = None,
    ) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} at redshift z or at time t after the big bang (default: today, z = 0),
        or `only` those names (QUANTITY_NAMES)."""
        if z is not None and t is not None:
            raise TypeError("give the epoch as a redshift z or a time t, not both")
        contracting = t is not None and np.any(self._time(t) > self.turnaround_time.to_value(units.S))
        if only is None:
            names = [name for name in (CONTRACTING_NAMES if contracting else QUANTITY_NAMES)
                     if name not in FATE_NAMES or np.isfinite(getattr(self, name).value)]  # only a closed one's
        else:
            names = list(only)
        check_names(names, QUANTITY_NAMES)
        if contracting and set(names) - set(CONTRACTING_NAMES):
            raise OrbitDomainError(
                f"t = {t} is after the turnaround at {self.turnaround_time.to(u.Gyr):.6g}, while this universe "
                f"recollapses, and {', '.join(sorted(set(names) - set(CONTRACTING_NAMES)))} are computed only while "
                f"it expands; ask for {', '.join(CONTRACTING_NAMES)}"
            )
        if t is None:
            z = _redshift(0.0 if z is None else z)
            with np.errstate(divide="ignore"):
                epoch = {"redshift": z << u.one, "scale_factor": 1.0 / (1.0 + z) << u.one}
        else:
            a = self.scale_factor(t)
            epoch = {"scale_factor": a, "redshift": _redshift_of(a), "age": _cosmic_time(t) << units.S}
            epoch["lookback_time"] = self.age() - epoch["age"]
            epoch["hubble_parameter"] = self.expansion_rate(t)
            z = epoch["redshift"].to_value(u.one)
            _require_past_z(t, a, z, [name for name in names if name not in epoch and name in REDSHIFT_NAMES])
        return {name: epoch[name] if name in epoch else self._at(name, z) for name in names}

    def _at(self, name, z):
        """One QUANTITY_NAMES entry at redshift z."""
        if name in ("hubble_time", "hubble_distance", *FATE_NAMES):
            return getattr(self, name)
        return getattr(self, name)(z)


QUANTITY_NAMES = [
    "redshift",
    "scale_factor",
    "hubble_parameter",
    "age",
    "lookback_time",
    "comoving_distance",
    "luminosity_distance",
    "angular_diameter_distance",
    "distance_modulus",
    "comoving_volume",
    "critical_density",
    "density_parameter",
    "hubble_time",
    "hubble_distance",
    "turnaround_time",
    "big_crunch_time",
]
#: the quantities that are functions of the redshift, which a time after a = 2**53 leaves at -1
REDSHIFT_NAMES = ["comoving_distance", "luminosity_distance", "angular_diameter_distance", "distance_modulus",
                  "comoving_volume", "critical_density", "density_parameter"]
#: the times of a recollapsing universe's turnaround and big crunch: listed by default only when finite
FATE_NAMES = ("turnaround_time", "big_crunch_time")
#: what quantities(t=...) gives after the turnaround of a recollapsing universe (functions of a and t alone)
CONTRACTING_NAMES = ["scale_factor", "redshift", "age", "lookback_time", "hubble_parameter", "critical_density",
                     "density_parameter", "hubble_time", "hubble_distance", *FATE_NAMES]

#: Planck 2018 (A&A 641, A6, table 2, TT,TE,EE+lowE+lensing+BAO), as in astropy.cosmology.Planck18
PLANCK18_H0 = 67.66  # km/s/Mpc
PLANCK18_OM0 = 0.30966
PLANCK18_TCMB = 2.7255  # K, the CMB temperature today (Fixsen 2009)
PLANCK18_NEFF = 3.046  # effective number of neutrino species
TEN_PARSECS = (10 * u.pc).to_value(u.m)


def _radiation_density(h0, tcmb, neff):
    """Omega_r = Omega_gamma (1 + (7/8) (4/11)**(4/3) Neff) today, Omega_gamma = (4 sigma / c**3) T**4 / rho_c,
    rho_c = 3 H0**2 / (8 pi G): photons at tcmb (K) plus neff massless neutrino species; h0 in 1/s."""
    photons = 4.0 * STEFAN_BOLTZMANN / SPEED_OF_LIGHT**3 * tcmb**4 / sphere.critical_density(h0, G)
    return photons * (1.0 + 0.875 * (4.0 / 11.0) ** (4.0 / 3.0) * neff)


def _redshift(z):
    """z as a float64 array; a length or other dimensional Quantity is a UnitConversionError."""
    return units.to_number(z, "redshift z")


def _require_past_z(t, a, z, needing: list[str]) -> None:
    """OrbitDomainError when a time so late that z = 1 / a - 1 rounds to -1 (a >= 2**53) asks for quantities that
    are functions of z: the message names the time and the scale factor, not a redshift the user never gave."""
    late = np.broadcast_to(z <= -1.0, np.shape(a))
    if needing and np.any(late):
        when = np.broadcast_to(t, np.shape(a), subok=True)[late].ravel()[0]
        scale = float(np.ravel(a.to_value(u.one))[np.ravel(late)][0])
        raise OrbitDomainError(f"t = {when} is so late that the scale factor a = {scale:.6g} leaves z = 1 / a - 1 = -1 "
                               f"in float64, and {', '.join(needing)} are functions of z > -1; ask for scale_factor, "
                               f"age, lookback_time or hubble_parameter at that time, or an earlier t")


def _representable(values: np.ndarray, name: str, unit: str, label: str, coordinate: np.ndarray,
                   finite: np.ndarray | None = None) -> np.ndarray:
    """`values` (at the redshifts or times `coordinate`, named `label`), unless one is infinite where its true value
    is finite (`finite`, default: where the coordinate is): there it lies beyond float64, and inf would read as a
    true infinity, so OrbitDomainError names the quantity and where."""
    values = np.asarray(values, dtype=float)
    where = np.broadcast_to(coordinate, values.shape)
    finite = np.isfinite(where) if finite is None else np.broadcast_to(finite, values.shape)
    beyond = np.isinf(values) & finite
    if np.any(beyond):
        bad = float(where[beyond].flat[0])
        raise OrbitDomainError(f"the {name} at {label} = {bad:g} is larger than float64 holds (about 1.8e308 {unit}); "
                               f"it is computed where it is smaller (and as the limit inf where it is infinite)")
    return values


def _redshift_of(a):
    """z = 1 / a - 1 (dimensionless) for a scale factor Quantity a; inf at a = 0."""
    with np.errstate(divide="ignore"):
        return 1.0 / a.to_value(u.one) - 1.0 << u.one


def _cosmic_time(t):
    """t (s) since the big bang from a time Quantity; OrbitDomainError, quoting t as given, if negative or NaN."""
    seconds = units.to_si(t, units.S, "time since the big bang t")
    bad = np.isnan(seconds) | (seconds < 0)
    if np.any(bad):
        value = np.ravel(t)[np.ravel(bad)][0]
        raise OrbitDomainError(
            f"time since the big bang t = {value} is outside the allowed range [0, inf) s: it is before the big bang"
            if value < 0 * units.S
            else f"time since the big bang t = {value} is not a number; allowed [0, inf) s"
        )
    return seconds


# ---- the Newtonian sphere of XXIV ---------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class ExpandingSphere(display.Displayed):
    """A shell of the notes' uniform, pressureless sphere (XXIV), at zero energy; gm = G M (m3/s2) of the mass
    it encloses, a float64 array that broadcasts. Times t are measured from the big bang."""

    gm: np.ndarray

    @classmethod
    def from_mass(cls, mass: Body | str | u.Quantity) -> "ExpandingSphere":
        """The shell enclosing mass M (a mass in kg, or G M in m3/s2)."""
        return cls(inputs.gravitational_parameter(mass, "enclosed mass M"))

    @classmethod
    def from_hubble(cls, hubble: u.Quantity, radius: u.Quantity) -> "ExpandingSphere":
        """The shell at `radius` (length) when the Hubble parameter is H (1/time): v = H r = sqrt(2 G M / r)
        gives G M = H**2 r**3 / 2."""
        h = _hubble(hubble, "Hubble parameter H")
        r = inputs.positive(radius, units.M, "shell radius r")
        return cls(0.5 * h * h * r**3)

    def _time(self, t):
        return units.to_si(t, units.S, "time since the big bang t")

    def radius(self, t: u.Quantity) -> u.Quantity:
        """r(t) = (9 G M t**2 / 2)**(1/3) (m) at time t (time) after the big bang (XXIV.iii)."""
        return sphere.sphere_radius(self._time(t), self.gm) << units.M

    def speed(self, t: u.Quantity) -> u.Quantity:
        """v(t) = (4 G M / (3 t))**(1/3) (m/s), t > 0 (XXIV.iv)."""
        return sphere.sphere_speed(self._time(t), self.gm) << units.M_PER_S

    def hubble_parameter(self, t: u.Quantity) -> u.Quantity:
        """H = v / r = 2 / (3 t) (1/s), t > 0 (XXIV.iv); the same for every shell."""
        return sphere.sphere_hubble_parameter(self._time(t)) << PER_S

    def time_at_radius(self, r: u.Quantity) -> u.Quantity:
        """t = sqrt(2 r**3 / (9 G M)) (s) at which the shell reaches r (length), inverting r(t)."""
        r_si = units.to_si(r, units.M, "shell radius r")
        if np.any(r_si < 0) or not np.all(np.isfinite(r_si)):
            bad = float(r_si[~(np.isfinite(r_si) & (r_si >= 0))].flat[0])
            raise OrbitDomainError(f"shell radius r = {bad!r} m is outside the allowed range [0, inf) m")
        return sphere.sphere_time(r_si, self.gm) << units.S

    def density(self, t: u.Quantity) -> u.Quantity:
        """rho = 1 / (6 pi G t**2) (kg/m3), t > 0: the mean density M / (4 pi r**3 / 3) inside every shell."""
        return np.broadcast_to(sphere.sphere_density(self._time(t), G), np.shape(self.radius(t))) << KG_PER_M3

    def density_parameter(self, t: u.Quantity) -> u.Quantity:
        """Omega = (mean density inside the shell) / rho_c = 2 G M / (H**2 r**3) (dimensionless), t > 0.

        1 to rounding: a sphere expanding at the zero-energy speed has exactly the critical density.
        """
        hubble = self.hubble_parameter(t).to_value(PER_S)
        r = self.radius(t).to_value(units.M)
        return 2.0 * self.gm / (hubble * hubble * r**3) << u.one

    def __repr__(self) -> str:
        return display.one_line("ExpandingSphere", "GM = " + display.summary(self.gm << units.M3_PER_S2),
                                "zero energy, r = (9 GM t**2 / 2)**(1/3)")

    def _display_quantities(self) -> dict:
        return {"gravitational_parameter": self.gm << units.M3_PER_S2}

    def quantities(self, t: u.Quantity, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{snake_case name: Quantity} at time t (time) after the big bang, or `only` those (SPHERE_NAMES)."""
        names = SPHERE_NAMES if only is None else list(only)
        check_names(names, SPHERE_NAMES)
        return {name: getattr(self, name)(t) for name in names}


SPHERE_NAMES = ["radius", "speed", "hubble_parameter", "density", "density_parameter"]
