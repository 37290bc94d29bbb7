"""`orbits orbit`: build an Orbit from a named body, elements or a state vector."""

import astropy.units as u
import typer

from orbits import Orbit, body
from orbits.core.anomalies import true_from_mean
from orbits_cli import params


def build(body_name, primary, a, p, q, e, inc, raan, argp, nu, r, v, mass):
    """(Orbit, title) from the command's options; BadParameter for inconsistent combinations."""
    mass_q = None if mass is None else params.quantity(mass, "mass", "--mass")
    if body_name is not None:
        return _named(body_name), f"{body(body_name).name}'s mean orbit"
    center = params.primary(primary)
    if (r is None) != (v is None):
        raise typer.BadParameter("give both --r and --v for a state vector")
    if r is not None:
        if any(x is not None for x in (a, p, q)):
            raise typer.BadParameter("give either a state vector (--r, --v) or elements (--a/--p/--q), not both")
        orbit = Orbit.from_vectors(center, params.vector(r, "length", "--r"), params.vector(v, "speed", "--v"),
                                   mass=mass_q)
        return orbit, "Orbit from a state vector"
    if all(x is None for x in (a, p, q)):
        raise typer.BadParameter("give a size (--a, --p or --q), a state vector (--r and --v), or a BODY name")
    sizes = {k: (None if x is None else params.quantity(x, "length", f"--{k}")) for k, x in (("a", a), ("p", p), ("q", q))}
    orbit = Orbit.from_elements(
        center, e=e, inc=params.angle(inc, "--inc"), raan=params.angle(raan, "--raan"),
        argp=params.angle(argp, "--argp"), nu=params.angle(nu, "--nu"), mass=mass_q, **sizes,
    )
    return orbit, "Orbit from elements"


def _named(name):
    """The named body's J2000 mean orbit about its primary, with its mass."""
    target = body(name)
    if target.orbit is None:
        raise typer.BadParameter(f"{target.name} has no orbit in the catalogue; give elements instead")
    el = target.orbit
    nu = float(true_from_mean(el.mean_anomaly, el.e))
    return Orbit.from_elements(
        el.primary, a=el.a * u.m, e=el.e, inc=el.inc * u.rad, raan=el.raan * u.rad, argp=el.argp * u.rad,
        nu=nu * u.rad, mass=target.mass * u.kg,
    )
