"""Pictures, one module per subject. matplotlib is imported only when drawing.

Every function draws on a given Axes (or a new Figure) and returns (fig, ax), so the result can be restyled; axis
labels carry units. `save(fig, path)` writes PNG, SVG or PDF atomically. Every picture is importable from here
(`orbits.plot.orbits`, `orbits.plot.porkchop`, ...); the modules are

- frame: the frame they share (figures and axes, the length unit of an axis with the factor into it, titles
  wrapped to the room they have, labels beside points that stay apart, legends off the data, save); it imports
  no other module of this package;
- conics: Kepler orbits about their primary (orbit_plane, orbits, which Orbit.plot draws with);
- planets: the solar system at a date (solar_system);
- encounters: flybys and binaries (flyby_plane, binary_plane, binary_sky, radial_velocity_curves);
- cosmology: Friedmann universes (scale_factor_curves, hubble_diagram, distance_curves, cosmology_overview);
- threebody: the rotating frame of three bodies and rings (lagrange_plane, lagrange_departure, coorbital_plane,
  ring_breakup, ring_snapshots);
- periodic: periodic orbits of the restricted problem and their families (periodic_orbit, periodic_family,
  stability_diagram);
- validation: the cross-checks (validation_residuals, validation_tracks, validation_overview, work_precision);
- manoeuvres: launch windows (porkchop);
- mechanics: collisions, projectiles, pendulums, damped motion, the vertical circle, rolling;
- perturbations: perturbed orbits (secular_elements, frozen_eccentricity, ground_track, kozai_cycles,
  drag_decay).

A picture takes what it draws (arrays, numbers, or the object to draw, read through its properties) and never
imports the classes that draw themselves with it; a new picture goes into the module of its subject. Every picture
has a title naming what it draws (and when: a date, or t0, the time of an orbit's elements), each legend entry
once, and no text over other text or outside the figure; numbers and units come typeset from orbits.display
(number_math, unit_math, quantity_math), Greek letters in mathtext (tests/picture_checks.py checks all of it).
"""

from orbits.plot.conics import PROJECTIONS, InsideBodyWarning, catalogue_body, orbit_plane, orbits
from orbits.plot.cosmology import cosmology_overview, distance_curves, hubble_diagram, scale_factor_curves
from orbits.plot.encounters import binary_plane, binary_sky, collision_note, flyby_plane, radial_velocity_curves
from orbits.plot.frame import save
from orbits.plot.manoeuvres import porkchop
from orbits.plot.mechanics import (
    collision_velocities,
    damped_motion,
    pendulum_periods,
    projectile_paths,
    rolling_race,
    vertical_circle_forces,
)
from orbits.plot.periodic import periodic_family, periodic_orbit, stability_diagram
from orbits.plot.perturbations import drag_decay, frozen_eccentricity, ground_track, kozai_cycles, secular_elements
from orbits.plot.planets import SOLAR_SYSTEM, solar_system, solar_system_part, solar_system_points
from orbits.plot.threebody import coorbital_plane, lagrange_departure, lagrange_plane, ring_breakup, ring_snapshots
from orbits.plot.validation import (
    TRACK_MARKERS,
    validation_overview,
    validation_residuals,
    validation_tracks,
    work_precision,
)

__all__ = [
    "save",
    "PROJECTIONS", "InsideBodyWarning", "catalogue_body", "orbit_plane", "orbits",
    "SOLAR_SYSTEM", "solar_system", "solar_system_part", "solar_system_points",
    "flyby_plane", "collision_note", "binary_plane", "binary_sky", "radial_velocity_curves",
    "scale_factor_curves", "hubble_diagram", "distance_curves", "cosmology_overview",
    "lagrange_plane", "lagrange_departure", "coorbital_plane", "ring_breakup", "ring_snapshots",
    "periodic_orbit", "periodic_family", "stability_diagram",
    "validation_residuals", "validation_tracks", "validation_overview", "TRACK_MARKERS", "work_precision",
    "porkchop",
    "collision_velocities", "projectile_paths", "pendulum_periods", "damped_motion", "vertical_circle_forces",
    "rolling_race",
    "secular_elements", "frozen_eccentricity", "ground_track", "kozai_cycles", "drag_decay",
]
