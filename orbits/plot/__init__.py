"""Pictures, one module per subject. matplotlib is imported only when drawing.

Every function draws on a given Axes (or a new Figure) and returns (fig, ax), so the result can be restyled; axis
labels carry units. `save(fig, path)` writes PNG, SVG or PDF atomically. Every picture is importable from here
(`orbits.plot.orbits`, `orbits.plot.porkchop`, ...), loaded on first use (PEP 562); each is drawn by the `plot` module
of its subject, over the frame every picture shares (orbits._common.frame: figures and axes, the length unit of an
axis with the factor into it, titles wrapped to the room they have, labels beside points that stay apart, legends
off the data, save):

- twobody.plot: Kepler orbits about their primary (orbit_plane, orbits, which Orbit.plot draws with);
- ephemeris.plot: the solar system at a date (solar_system) and the sky seen from a planet (sky_chart);
- encounters.plot: flybys and binaries (flyby_plane, binary_plane, binary_sky, radial_velocity_curves);
- cosmology.plot: Friedmann universes (scale_factor_curves, hubble_diagram, distance_curves, cosmology_overview);
- threebody.plot: the rotating frame of three bodies and rings (lagrange_plane, lagrange_departure,
  coorbital_plane, ring_breakup, ring_snapshots);
- periodic.plot: periodic orbits of the restricted problem and their families (periodic_orbit, periodic_family,
  stability_diagram);
- validate.plot: the cross-checks (validation_residuals, validation_tracks, validation_overview, work_precision);
- manoeuvres.plot: launch windows (porkchop);
- mechanics.plot: collisions, projectiles, pendulums, damped motion, the vertical circle, rolling;
- perturb.plot: perturbed orbits (secular_elements, frozen_eccentricity, ground_track, kozai_cycles, drag_decay).

A picture takes what it draws (arrays, numbers, or the object to draw, read through its properties) and never
imports the classes that draw themselves with it; a new picture goes into the module of its subject. Every picture
has a title naming what it draws (and when: a date, or t0, the time of an orbit's elements), each legend entry
once, and no text over other text or outside the figure; numbers and units come typeset from orbits._common.display
(number_math, unit_math, quantity_math), Greek letters in mathtext (tests/picture_checks.py checks all of it).
"""

import importlib

#: public picture -> the module of its subject that draws it
_HOMES = {
    "save": "orbits._common.frame",
    "cosmology_overview": "orbits.cosmology.plot",
    "distance_curves": "orbits.cosmology.plot",
    "hubble_diagram": "orbits.cosmology.plot",
    "scale_factor_curves": "orbits.cosmology.plot",
    "binary_plane": "orbits.encounters.plot",
    "binary_sky": "orbits.encounters.plot",
    "collision_note": "orbits.encounters.plot",
    "flyby_plane": "orbits.encounters.plot",
    "radial_velocity_curves": "orbits.encounters.plot",
    "SOLAR_SYSTEM": "orbits.ephemeris.plot",
    "solar_system": "orbits.ephemeris.plot",
    "solar_system_part": "orbits.ephemeris.plot",
    "solar_system_points": "orbits.ephemeris.plot",
    "sky_chart": "orbits.ephemeris.plot",
    "porkchop": "orbits.manoeuvres.plot",
    "collision_velocities": "orbits.mechanics.plot",
    "damped_motion": "orbits.mechanics.plot",
    "pendulum_periods": "orbits.mechanics.plot",
    "projectile_paths": "orbits.mechanics.plot",
    "rolling_race": "orbits.mechanics.plot",
    "vertical_circle_forces": "orbits.mechanics.plot",
    "periodic_family": "orbits.periodic.plot",
    "periodic_orbit": "orbits.periodic.plot",
    "stability_diagram": "orbits.periodic.plot",
    "drag_decay": "orbits.perturb.plot",
    "frozen_eccentricity": "orbits.perturb.plot",
    "ground_track": "orbits.perturb.plot",
    "kozai_cycles": "orbits.perturb.plot",
    "secular_elements": "orbits.perturb.plot",
    "coorbital_plane": "orbits.threebody.plot",
    "lagrange_departure": "orbits.threebody.plot",
    "lagrange_plane": "orbits.threebody.plot",
    "ring_breakup": "orbits.threebody.plot",
    "ring_snapshots": "orbits.threebody.plot",
    "PROJECTIONS": "orbits.twobody.plot",
    "InsideBodyWarning": "orbits.twobody.plot",
    "catalogue_body": "orbits.twobody.plot",
    "orbit_plane": "orbits.twobody.plot",
    "orbits": "orbits.twobody.plot",
    "TRACK_MARKERS": "orbits.validate.plot",
    "validation_overview": "orbits.validate.plot",
    "validation_residuals": "orbits.validate.plot",
    "validation_tracks": "orbits.validate.plot",
    "work_precision": "orbits.validate.plot",
}

__all__ = list(_HOMES)


def __getattr__(name: str):
    """Import the picture's home module on first use and cache the name here."""
    if name not in _HOMES:
        raise AttributeError(f"module 'orbits.plot' has no attribute {name!r}")
    value = getattr(importlib.import_module(_HOMES[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
