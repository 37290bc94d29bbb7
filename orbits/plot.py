"""Pictures: orbits in their plane and validation residuals. matplotlib is imported only when drawing.

Every function draws on a given Axes (or a new Figure) and returns (fig, ax), so the result can be
restyled; axis labels carry units. `save(fig, path)` writes PNG, SVG or PDF atomically.
"""

import io
import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import astropy.units as u
import numpy as np

from orbits import display, inputs, units
from orbits.core.errors import OrbitsWarning
from orbits.core.lagrange import point_index
from orbits.io import write_atomic

if TYPE_CHECKING:
    from orbits.binary import Binary
    from orbits.cosmology import Cosmology
    from orbits.flyby import Flyby
    from orbits.lagrange import RestrictedThreeBody
    from orbits.orbit import Orbit


def _axes(ax, figsize=(6.4, 5.6)):
    """(figure, axes): those of `ax`, or a new figure of `figsize` inches with one axes."""
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=figsize, layout="constrained")
        return fig, ax
    return ax.figure, ax


def _finish_plane(ax, unit, x_label, legend_below=False):
    """Equal aspect, labelled axes with the length unit, grid and legend (inside where there is room, or below
    the axes): the end of every in-plane picture."""
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"{x_label} [{display.unit_text(unit)}]")
    ax.set_ylabel(f"y [{display.unit_text(unit)}]")
    ax.grid(alpha=0.3)
    if legend_below:
        _legend_outside(ax)
    else:
        ax.legend(loc="best", fontsize="small")


def _length_unit(size_m):
    """The natural length unit of a picture spanning size_m metres (orbits.display: km, AU, pc, ...)."""
    return display.axis_unit(size_m << u.m)


def _conic_points(p, e, r_max, samples=721):
    """(x, y) in the perifocal frame (m) of the drawn part of the conic: the whole ellipse, or the arc of
    an open orbit within r_max of the star."""
    if e < 1:
        nu = np.linspace(-np.pi, np.pi, samples)
    else:
        # 1 + e cos nu = p / r_max gives the true anomaly where the arc leaves the picture
        limit = np.arccos(np.clip((p / r_max - 1) / e, -1, 1))
        nu = np.linspace(-limit, limit, samples)
    r = p / (1 + e * np.cos(nu))
    return r * np.cos(nu), r * np.sin(nu)


def orbit_plane(
    orbit: "Orbit",
    times: u.Quantity | None = None,
    ax: Any = None,
    unit: u.UnitBase | None = None,
    label: str | None = None,
    primary: Any = None,
) -> tuple[Any, Any]:
    """Draw a single Orbit face on, in its own plane (perifocal frame: periapsis along +x, primary at the origin).

    The picture of `orbits` (the primary to scale and named, apsides where e > 1e-3, open and very long orbits
    within a window, a warning for a closest approach inside the primary, the legend outside) for the same conic
    turned into the xy plane, with the centre and empty focus of an ellipse drawn whole and the body's positions
    at `times` (a time Quantity array) later, when given.
    """
    import dataclasses

    if orbit.shape != ():
        raise ValueError(f"orbit_plane draws one orbit; this Orbit holds {orbit.shape} orbits: index it first")
    flat = dataclasses.replace(orbit, inc=np.zeros(()), raan=np.zeros(()), argp=np.zeros(()))
    later = [] if times is None else [flat.at(t).r.to_value(u.m) for t in np.atleast_1d(times)]
    furthest = 1.05 * max((float(np.linalg.norm(r)) for r in later), default=0.0)  # the arc runs past each dot
    size = _extent([("", flat)], furthest)
    unit = unit or _length_unit(size)
    fig, ax = orbits(flat, ax=ax, labels=None if label is None else [label], unit=unit, primary=primary,
                     window=size << u.m if later else None)
    scale = u.m.to(unit)
    p, e = float(orbit.p), float(orbit.e)
    whole = e < 1 and p / (1 - e) <= _LONG * p / (1 + e)
    if _CIRCULAR < e < 1 and whole:
        c = e * p / (1 - e * e)
        ax.plot(-c * scale, 0, marker="+", ms=10, color="gray", ls="none", label="centre")
        ax.plot(-2 * c * scale, 0, marker="x", color="gray", ls="none", label="empty focus")
    if later:
        points = np.array(later) * scale
        ax.plot(points[:, 0], points[:, 1], marker=".", color="k", ls="none", alpha=0.6, label="body at given times")
    ax.set_xlabel(f"x toward periapsis [{display.unit_text(unit)}]")
    ax.set_ylabel(f"y, along the motion at periapsis [{display.unit_text(unit)}]")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


# ---- several orbits and trajectories in one frame ----------------------------------------------------------

PROJECTIONS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2), "3d": (0, 1, 2)}
_CIRCULAR = 1e-3  # below this eccentricity the apsides are not marked: they mean nothing on a near-circle
_LONG = 100.0  # an ellipse with Q > _LONG q is drawn, like an open orbit, only within the picture's window
_AXES = "xyz"


class InsideBodyWarning(OrbitsWarning):
    """A drawn closest approach lies inside the primary (or inside both bodies' radii): a collision."""


def catalogue_body(gm: Any) -> Any:
    """The catalogue Body drawn as the primary of orbits with this mu (m3/s2): its own GM within 2 %, so that the
    Sun is found under a Sun-Jupiter mu G (M_Sun + M_Jupiter) too (orbits.constants.body_with_gm); else None."""
    from orbits.constants import body_with_gm

    return body_with_gm(gm, tolerance=0.02)


def _primary_body(primary, gm):
    """The Body drawn at the origin: `primary` (a Body or a catalogue name) or the catalogue body of GM."""
    if primary is None:
        return catalogue_body(gm)
    if isinstance(primary, str):
        from orbits.constants import body

        return body(primary)
    return primary


def _conic_track(orbit, window):
    """(points (n, 3) in m, closed) of one Orbit: the whole ellipse, or the arc within `window` m of the focus
    for an open orbit or a very long ellipse (Q > 100 q)."""
    from orbits.core import elements

    p, e = float(orbit.p), float(orbit.e)
    q = p / (1 + e)
    whole = e < 1 and p / (1 - e) <= max(_LONG * q, window)
    if whole:
        nu = np.linspace(-np.pi, np.pi, 721)
    else:
        limit = np.arccos(np.clip((p / window - 1) / e, -1, 1))  # 1 + e cos nu = p / window
        if e >= 1:
            limit = min(limit, np.arccos(-1 / e) * (1 - 1e-9))  # inside the asymptotes
        nu = np.linspace(-limit, limit, 721)
    r, _ = elements.elements_to_state(p, e, float(orbit.inc), float(orbit.raan), float(orbit.argp), nu,
                                      float(orbit.mu))
    return r, whole


def _apsides(orbit):
    """{"periapsis": r (3,), "apoapsis": r (3,) for an ellipse} in m."""
    from orbits.core import elements

    p, e = float(orbit.p), float(orbit.e)
    angles = [0.0, np.pi] if e < 1 else [0.0]
    r, _ = elements.elements_to_state(p, e, float(orbit.inc), float(orbit.raan), float(orbit.argp),
                                      np.array(angles), float(orbit.mu))
    return dict(zip(("periapsis", "apoapsis"), r))


def _items(items, labels):
    """[(label, Orbit or (n, 3) array in m)]: arrays of orbits split, Quantities of positions converted."""
    from orbits.orbit import Orbit

    out = []
    for k, item in enumerate(items):
        given = None if labels is None else labels[k]
        if isinstance(item, Orbit):
            flat = [item] if item.shape == () else [_one_orbit(item, idx) for idx in np.ndindex(item.shape)]
            for j, one in enumerate(flat):
                name = given if len(flat) == 1 else f"{given or 'orbit'} [{j}]: {_size_text(one)}"
                out.append((name or f"orbit, e = {_eccentricity_text(float(one.e))}", one))
        else:
            track = np.asarray(units.to_si(item, units.M, "trajectory positions"), dtype=float)
            if track.ndim != 2 or track.shape[1] != 3:
                raise ValueError(f"a trajectory is a length Quantity of shape (n, 3); got shape {track.shape}")
            out.append((given or f"trajectory {k + 1}", track))
    return out


def _one_orbit(orbit, idx):
    """Element `idx` of an array of orbits, as an Orbit of shape ()."""
    import dataclasses

    values = {f.name: getattr(orbit, f.name) for f in dataclasses.fields(orbit)}
    return type(orbit)(**{name: None if v is None else np.broadcast_to(v, orbit.shape)[idx]
                          for name, v in values.items()})


def _size_text(orbit):
    """"a = 7000 km, e = 0.1" (q for an open orbit): what tells one orbit of an array from the others."""
    e = float(orbit.e)
    size = orbit.semi_major_axis if e < 1 else orbit.periapsis_distance
    return f"{'a' if e < 1 else 'q'} = {display.quantity_text(size, digits=4)}, e = {_eccentricity_text(e)}"


def _eccentricity_text(e):
    """e with the digits that matter: "1 + 6.4e-07" or "1 - 1e-06" near a parabola, else 4 digits."""
    if e != 1 and abs(e - 1) < 1e-3:
        return f"1 {'+' if e > 1 else '-'} {abs(e - 1):.2g}"
    return f"{e:.4g}"


def _extent(entries, times_window):
    """The picture's half-size (m): the largest whole ellipse, trajectory or current position, and at least
    10 q of every open or very long orbit."""
    from orbits.orbit import Orbit

    size = 0.0
    for _, item in entries:
        if isinstance(item, Orbit):
            p, e = float(item.p), float(item.e)
            q = p / (1 + e)
            closed = e < 1 and p / (1 - e) <= _LONG * q
            size = max(size, p / (1 - e) if closed else 10 * q, float(item.radius.to_value(u.m)))
        else:
            size = max(size, float(np.max(np.linalg.norm(item, axis=1))))
    return max(size, times_window)


def orbits(
    *items: Any,
    ax: Any = None,
    projection: str = "xy",
    primary: Any = None,
    labels: Sequence[str] | None = None,
    unit: u.UnitBase | None = None,
    window: u.Quantity | None = None,
) -> tuple[Any, Any]:
    """Draw any number of Orbits (arrays of orbits included) and trajectories ((n, 3) length Quantities, e.g.
    from an integrator) about one primary, in its inertial frame, each in its own colour.

    The primary is a disc to scale (a Body or a catalogue name, else the catalogue body of the first orbit's GM;
    a star marks it where the disc would be too small to see). projection: "xy", "xz", "yz" or "3d" (then `ax`,
    if given, must be a 3D Axes). Ellipses are drawn whole, open orbits (and ellipses with Q > 100 q) only out to
    the picture's half-size `window` (default: the largest closed orbit or trajectory, or 10 q). Periapsis
    (and apoapsis) are marked where e > 1e-3; each body's current position is a dot. A closest approach inside
    the primary gives an InsideBodyWarning and a note in the title. The legend sits outside the axes.
    """
    from orbits.orbit import Orbit

    if projection not in PROJECTIONS:
        raise ValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")
    entries = _items(items, labels)
    if not entries:
        raise ValueError("give at least one Orbit or trajectory to draw")
    axes_index = PROJECTIONS[projection]
    fig, ax = _axes_for(ax, projection)
    gm = next((float(item.mu) for _, item in entries if isinstance(item, Orbit)), None)
    body = _primary_body(primary, gm)
    size = _extent(entries, 0.0 if window is None else units.to_si(window, units.M, "window"))
    unit = unit or _length_unit(size)
    scale = u.m.to(unit)
    colors = _colors(len(entries))
    marked, notes = set(), []
    for (label, item), color in zip(entries, colors):
        whole = False
        if isinstance(item, Orbit):
            track, whole = _conic_track(item, size)
            closest = float(item.periapsis_distance.to_value(u.m))
        else:
            track = item
            closest = float(np.min(np.linalg.norm(item, axis=1)))
        ax.plot(*(track[:, i] * scale for i in axes_index), color=color, lw=1.4, label=label)
        if isinstance(item, Orbit):
            _mark_orbit(ax, item, color, axes_index, scale, marked, whole)
        if body is not None and closest < body.radius:
            notes.append(f"{label}: closest approach {display.quantity_text(closest << u.m, digits=4)} is inside "
                         f"{body.name} (radius {display.quantity_text(body.radius << u.m, digits=4)})")
    _draw_primary(ax, body, axes_index, scale, size, unit)
    _marker_legend(ax, marked, len(axes_index))
    _finish_frame(ax, projection, unit, body)
    if notes:
        import warnings

        for note in notes:
            warnings.warn(note, InsideBodyWarning, stacklevel=2)
        ax.set_title("\n".join(notes), color="C3", fontsize="small")
    return fig, ax


def _axes_for(ax, projection):
    """A new Figure and Axes (3D for projection "3d"), or the given Axes."""
    import matplotlib.pyplot as plt

    if ax is not None:
        return ax.figure, ax
    if projection == "3d":
        fig = plt.figure(figsize=(8.4, 6.4), layout="constrained")
        return fig, fig.add_subplot(projection="3d")
    fig, ax = plt.subplots(figsize=(8.4, 6.0), layout="constrained")
    return fig, ax


def _colors(n):
    """n distinct colours: matplotlib's ten, then tab20's twenty; beyond, a sequence along viridis (first and last
    as far apart as it goes, none repeated), which reads as the order of the orbits."""
    import matplotlib

    if n <= 10:
        return [f"C{k}" for k in range(n)]
    if n <= 20:
        return list(matplotlib.colormaps["tab20"].colors[:n])
    return [matplotlib.colormaps["viridis"](k / (n - 1)) for k in range(n)]


def _mark_orbit(ax, orbit, color, axes_index, scale, marked, whole):
    """Apsides (where e > 1e-3; the apoapsis only on a whole ellipse) and the body's current position, in the
    orbit's colour."""
    if float(orbit.e) > _CIRCULAR:
        for name, point in _apsides(orbit).items():
            if name == "apoapsis" and not whole:
                continue
            marked.add(name)
            ax.plot(*([point[i] * scale] for i in axes_index), marker=_MARKERS[name], ms=6, mfc="none", color=color,
                    ls="none", gid=name)
    now = orbit.r.to_value(u.m)
    marked.add("body now")
    ax.plot(*([now[i] * scale] for i in axes_index), marker=_MARKERS["body now"], ms=9, color=color, ls="none",
            gid="body now")


_MARKERS = {"periapsis": "o", "apoapsis": "s", "body now": "."}


def _marker_legend(ax, marked, dimensions):
    """One gray legend entry per kind of marker drawn (the markers themselves take their orbit's colour)."""
    for name in ("periapsis", "apoapsis", "body now"):
        if name in marked:
            ax.plot(*([] for _ in range(dimensions)), marker=_MARKERS[name], ms=6, color="0.3", ls="none",
                    mfc="none" if name != "body now" else "0.3", label=name)


def _primary_color(body):
    """gold for a star, silver for a planet or moon (or an unnamed primary): colours outside matplotlib's cycle,
    so the primary never looks like one of the orbits (the cycle's C1 is orange)."""
    return "gold" if body is not None and body.kind == "star" else "silver"


def _draw_primary(ax, body, axes_index, scale, size, unit):
    """The primary at the origin: a disc (a sphere's outline in 3D) of its radius, and a star if that is tiny."""
    name = body.name if body is not None else "primary"
    radius = body.radius * scale if body is not None else 0.0
    tiny = radius < 0.01 * size * scale
    color = _primary_color(body)
    if len(axes_index) == 3:
        if not tiny:
            angle = np.linspace(0, 2 * np.pi, 97)
            for i, j in ((0, 1), (0, 2), (1, 2)):
                circle = np.zeros((3, angle.size))
                circle[i], circle[j] = radius * np.cos(angle), radius * np.sin(angle)
                ax.plot(*circle, color=color, lw=1)
        ax.plot([0], [0], [0], marker="*", ms=12, color=color, mec="0.3", ls="none", label=f"{name}")
        return
    import matplotlib.patches as mpatches

    if radius > 0:
        ax.add_patch(mpatches.Circle((0, 0), radius, facecolor=color, edgecolor="0.4", alpha=0.8, zorder=0.5,
                                     label=f"{name} (to scale)" if not tiny else None))
    if tiny:
        ax.plot(0, 0, marker="*", ms=12, color=color, mec="0.3", ls="none", zorder=4,
                label=f"{name} (star not to scale; radius {display.quantity_text(body.radius << u.m, digits=3)})"
                if radius > 0 else name)


def _finish_frame(ax, projection, unit, body):
    """Axis labels with the unit, equal scales, grid, and the legend outside the axes on the right."""
    names = [_AXES[i] for i in PROJECTIONS[projection]]
    text = display.unit_text(unit)
    ax.set_xlabel(f"{names[0]} [{text}]")
    ax.set_ylabel(f"{names[1]} [{text}]")
    if projection == "3d":
        ax.set_zlabel(f"{names[2]} [{text}]")
        ax.set_box_aspect((1, 1, 1))
        _equal_3d(ax)
    else:
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)


def _equal_3d(ax):
    """Give the three axes of a 3D view the same span, centred on the data."""
    limits = np.array([ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d()])
    centre, half = limits.mean(axis=1), (limits[:, 1] - limits[:, 0]).max() / 2
    ax.set_xlim3d(centre[0] - half, centre[0] + half)
    ax.set_ylim3d(centre[1] - half, centre[1] + half)
    ax.set_zlim3d(centre[2] - half, centre[2] + half)


# ---- the solar system at a date (issue 16, item 5) -----------------------------------------------------------

SOLAR_SYSTEM = {
    "inner": ("Mercury", "Venus", "Earth", "Mars"),
    "outer": ("Jupiter", "Saturn", "Uranus", "Neptune", "Pluto"),
}
SOLAR_SYSTEM["all"] = SOLAR_SYSTEM["inner"] + SOLAR_SYSTEM["outer"]
#: points of the ephemeris drawn as the planet they stay next to at this scale
_DRAWN_AS = {"Moon": "Earth", "Earth-Moon barycentre": "Earth", "solar system barycentre": "Sun"}


def solar_system_part(body: str) -> str:
    """The part of solar_system that shows `body` (a planet, Pluto, the Moon or a barycentre): "inner" for
    Mercury-Mars and the Earth-Moon pair, "all" for Jupiter-Pluto (so the Earth is in the picture too)."""
    from orbits import ephemeris

    name = _DRAWN_AS.get(ephemeris.point_name(body), ephemeris.point_name(body))
    return "all" if name in SOLAR_SYSTEM["outer"] else "inner"


def solar_system(
    epoch: Any,
    ax: Any = None,
    which: str = "inner",
    projection: str = "xy",
    *,
    highlight: str | None = None,
    observer: str | None = None,
    source: str = "auto",
) -> tuple[Any, Any]:
    """Draw the planets (and Pluto for "outer" and "all") on their osculating heliocentric orbits at `epoch`, in
    the ecliptic frame of J2000, each body's position a dot with its name beside it and the Sun at the centre.

    Parameters
    ----------
    epoch : astropy Time or ISO string (read as UTC unless it names its scale; see orbits.ephemeris.epoch)
    which : "inner" (Mercury-Mars), "outer" (Jupiter-Pluto) or "all"
    projection : "xy" (the ecliptic seen from its north pole), "xz", "yz" or "3d"
    highlight : a body drawn with a thick orbit and a bold label (the Moon and the Earth-Moon barycentre are
        drawn as the Earth)
    observer : with `highlight`, a body from which a dashed line of sight is drawn to it
    source : the ephemeris, "auto", "de421" or "builtin" (astropy's, which has no Pluto: Pluto is then left out
        and the title says so)

    The orbits are `Orbit.from_body(name, epoch)` drawn by `orbits` (the first time each orbit passes through the
    body's position); the title gives the date in TDB and the ephemeris that answered. DE421 gives Jupiter-Pluto
    as system barycentres, and their legend entries say so. Tested in tests/api/test_plot_and_display.py (the
    dots equal astropy's reading of DE421, rotated to the ecliptic, to 1e-9 AU).
    """
    from orbits import ephemeris
    from orbits.orbit import Orbit

    if which not in SOLAR_SYSTEM:
        raise ValueError(f"which {which!r} is not one of {', '.join(SOLAR_SYSTEM)}")
    when = ephemeris.epoch(epoch)
    names = list(SOLAR_SYSTEM[which])
    first = ephemeris.state(names[0], when, "Sun", source=source)
    missing = []
    if first.source == ephemeris.BUILTIN and "Pluto" in names:
        names.remove("Pluto")
        missing.append("Pluto (not in astropy's built-in ephemeris)")
    states = {name: ephemeris.state(name, when, "Sun", source=source) for name in names}
    drawn = [Orbit.from_body(name, when, source=source) for name in names]
    fig, ax = orbits(*drawn, ax=ax, projection=projection, primary="Sun", labels=[s.point for s in states.values()])
    axes_index = PROJECTIONS[projection]
    scale = _axis_scale(ax)
    target = None if highlight is None else _DRAWN_AS.get(ephemeris.point_name(highlight),
                                                          ephemeris.point_name(highlight))
    if target is not None and target not in (*names, "Sun"):
        raise ValueError(f"{highlight} is not drawn in the {which} solar system ({', '.join(names)})")
    positions = {name: orbit.r.to_value(u.m) * scale for name, orbit in zip(names, drawn)}
    shown = None if highlight is None else ephemeris.point_name(highlight)
    for name in _uncrowded(positions, axes_index, target):
        text = f"{shown} (at {name})" if name == target and shown != target else name  # "Moon (at Earth)"
        _label_point(ax, positions[name], axes_index, text, bold=name == target)
    if target in names:
        curve = next(line for line in ax.get_lines() if line.get_label() == states[target].point)
        curve.set_linewidth(3.0)
    if target is not None and observer is not None and ephemeris.point_name(observer) != target:
        positions["Sun"] = np.zeros(3)
        _line_of_sight(ax, when, observer, target, positions, axes_index, scale, source)
    title = f"The {'' if which == 'all' else which + ' '}solar system on {when.tdb.iso[:16]} TDB (ecliptic J2000)"
    title += f"\npositions: {first.source}"
    if missing:
        title += f"\nleft out: {', '.join(missing)}"
    notes = ax.get_title()  # a closest approach inside the Sun, if any, stays in the title
    ax.set_title(title + (f"\n{notes}" if notes else ""), fontsize="medium")
    return fig, ax


def _axis_scale(ax):
    """Metres to the unit in the x label of a picture drawn by `orbits` ("x [AU]" -> 1 / 1.496e11)."""
    text = ax.get_xlabel().rsplit("[", 1)[1].rstrip("]")
    return u.m.to(u.Unit(text))


def _uncrowded(positions, axes_index, first, spacing=0.04):
    """The bodies whose names fit: the highlighted one first, then each whose dot is more than `spacing` of the
    picture's half-size from the Sun and from every dot named already (the inner planets of the whole solar
    system crowd round the Sun; the legend names them)."""
    seen = {name: np.array([point[i] for i in axes_index]) for name, point in positions.items()}
    size = max(np.linalg.norm(point) for point in seen.values())
    named, taken = [], [np.zeros(len(axes_index))]
    for name in sorted(seen, key=lambda n: n != first):
        if name == first or all(np.linalg.norm(seen[name] - other) > spacing * size for other in taken):
            named.append(name)
            taken.append(seen[name])
    return named


def _label_point(ax, point, axes_index, text, bold):
    """The body's name beside its dot."""
    weight = "bold" if bold else "normal"
    if len(axes_index) == 3:
        ax.text(*(point[i] for i in axes_index), f"  {text}", fontsize="small", fontweight=weight, gid="name")
        return
    ax.annotate(text, tuple(point[i] for i in axes_index), textcoords="offset points", xytext=(5, 5),
                fontsize="small", fontweight=weight, gid="name")


def _line_of_sight(ax, when, observer, target, positions, axes_index, scale, source):
    """A dashed line from the observer (drawn or not) to the target."""
    from orbits import ephemeris
    from orbits.core import frames

    seer = ephemeris.point_name(observer)
    if seer in positions:
        start = positions[seer]
    else:
        seen = ephemeris.state(seer, when, "Sun", source=source)
        start = frames.equatorial_to_ecliptic(seen.r_si) * scale
    ends = np.stack([start, positions[target]])
    ax.plot(*(ends[:, i] for i in axes_index), color="0.3", ls="--", lw=1.0, gid="line of sight",
            label=f"line of sight from {seer}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)


def flyby_plane(flyby: "Flyby", ax: Any = None, unit: u.UnitBase | None = None) -> tuple[Any, Any]:
    """Draw a single Flyby in its plane: the hyperbola about the focus within 4 max(b, q) of it, both asymptotes
    there, the impact parameter b (the focus's distance from the incoming asymptote), the closest approach, and
    the primary as a disc to scale; the title gives the deflection. A closest approach inside the bodies (the
    primary's radius, plus the secondary's for Flyby.between) gives an InsideBodyWarning and a red note."""
    if flyby.shape != ():
        raise ValueError(f"flyby_plane draws one flyby; this Flyby holds {flyby.shape}: index it first")
    fig, ax = _axes_for(ax, "xy")
    orbit = flyby.orbit
    p, e = float(orbit.p), float(orbit.e)
    q, b = p / (1 + e), float(flyby.impact_parameter.si.value)
    r_max = 4 * max(b, q)
    unit = unit or _length_unit(r_max)
    scale = u.m.to(unit)
    x, y = _conic_points(p, e, r_max)
    ax.plot(x * scale, y * scale, color="C0", lw=1.5, label=f"trajectory, e = {_eccentricity_text(e)}")
    ax.plot(q * scale, 0, marker="o", color="C3", ls="none",
            label=f"closest approach {display.quantity_text(q << u.m, digits=4)}")
    nu_inf = float(flyby.asymptote_true_anomaly.to_value(u.rad))
    reach = np.sqrt(r_max**2 - b**2)  # the asymptotes pass b from the focus; draw them within r_max of it
    centre = np.array([p / (e * e - 1) * e, 0.0])  # the hyperbola's centre, a e beyond the focus
    feet = {}
    for sign, name in ((-1, "incoming asymptote"), (1, "outgoing asymptote")):
        direction = np.array([np.cos(nu_inf), sign * np.sin(nu_inf)])  # outward along the asymptote
        feet[name] = centre + direction * np.dot(-centre, direction)  # its nearest point to the focus
        line = feet[name][:, None] + direction[:, None] * np.array([-reach, reach])
        ax.plot(line[0] * scale, line[1] * scale, ls="--", color="gray", lw=1, label=name)
    foot = feet["incoming asymptote"]
    ax.plot([0, foot[0] * scale], [0, foot[1] * scale], color="C2", lw=1.5,
            label=f"impact parameter b = {b * scale:.4g} {unit}")
    bodies = [catalogue_body(flyby.gm1 if flyby.gm1 is not None else flyby.mu)]
    if flyby.gm2 is not None:
        bodies.append(catalogue_body(flyby.gm2))
    _draw_primary(ax, bodies[0], (0, 1), scale, r_max, unit)
    semi_axis = p / (e * e - 1)
    if semi_axis > r_max:  # the arc drawn here is still far from its asymptotes
        ax.plot([], [], ls="none", label=f"(the track meets its asymptotes only beyond |a| = "
                                          f"{display.quantity_text(semi_axis << u.m, digits=3)})")
    radius = sum(body.radius for body in bodies if body is not None)
    if 5 * max(q, radius) < 0.05 * r_max:
        _periapsis_inset(ax, p, e, q, bodies[0], radius)
    title = f"deflection {np.degrees(float(flyby.deflection_angle.to_value(u.rad))):.2f} deg"
    note = _collision_note(q, bodies)
    if note:
        import warnings

        warnings.warn(note, InsideBodyWarning, stacklevel=2)
        title += "\n" + note.replace(" is inside", "\nis inside")
    ax.set_title(title, color="C3" if note else "k", fontsize="medium")
    _finish_plane(ax, unit, "x toward closest approach")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


def _periapsis_inset(ax, p, e, q, body, radius):
    """An inset (top right, above the outgoing asymptote) around the closest approach, where the main picture is
    too coarse to show it: the track within 5 max(q, R) of the focus, the primary to scale and the closest
    approach, in the natural unit of that size."""
    half = 5 * max(q, radius)
    unit = _length_unit(half)
    scale, unit_text = u.m.to(unit), display.unit_text(unit)
    if body is not None:  # in radii of the primary: small numbers, and its size read off at once
        scale, unit_text = 1.0 / body.radius, f"{body.name} radii"
    inset = ax.inset_axes([0.66, 0.66, 0.31, 0.31])
    x, y = _conic_points(p, e, 1.5 * half)
    inset.plot(x * scale, y * scale, color="C0", lw=1.2)
    if body is not None:
        import matplotlib.patches as mpatches

        inset.add_patch(mpatches.Circle((0, 0), body.radius * scale, facecolor=_primary_color(body),
                                        edgecolor="0.4", alpha=0.8))
    inset.plot(q * scale, 0, marker="o", ms=4, color="C3", ls="none")
    inset.set_xlim(-half * scale, half * scale)
    inset.set_ylim(-half * scale, half * scale)
    inset.set_aspect("equal")
    inset.tick_params(labelsize="x-small")
    inset.set_title(f"near closest approach [{unit_text}]", fontsize="x-small")


def collision_note(flyby: "Flyby") -> str | None:
    """A sentence when the flyby's closest approach is inside the bodies (catalogue radii; the two radii added for
    Flyby.between), else None. E.g. "closest approach 8.4e+04 km is inside the Sun (radius 6.957e+05 km)"."""
    if flyby.shape != ():
        raise ValueError(f"collision_note checks one flyby; this Flyby holds {flyby.shape}: index it first")
    bodies = [catalogue_body(flyby.gm1 if flyby.gm1 is not None else flyby.mu)]
    if flyby.gm2 is not None:
        bodies.append(catalogue_body(flyby.gm2))
    return _collision_note(float(flyby.periapsis_distance.to_value(u.m)), bodies)


def _collision_note(q, bodies):
    """The note for closest approach q (m) among the known `bodies` (None for unknown ones), or None."""
    known = [body for body in bodies if body is not None]
    if not known:
        return None
    reach = sum(body.radius for body in known)
    if q >= reach:
        return None
    names = " and ".join(body.name for body in known)
    what = f"inside {names}" if len(known) == 1 else f"inside the radii of {names} added"
    return (f"closest approach {display.quantity_text(q << u.m, digits=4)} is {what} "
            f"({display.quantity_text(reach << u.m, digits=4)}): they collide")


def binary_plane(binary: "Binary", ax: Any = None, unit: u.UnitBase | None = None) -> tuple[Any, Any]:
    """Draw a single Binary in its orbital plane: both stars' ellipses about the centre of mass, the stars at
    their current positions and the line joining them."""
    if binary.shape != ():
        raise ValueError(f"binary_plane draws one binary; this Binary holds {binary.shape}: index it first")
    fig, ax = _axes(ax)
    relative = binary.relative
    p, e, nu = float(relative.p), float(relative.e), float(relative.nu)
    share2 = float(binary.mass_fraction.to_value(u.one))  # star 2 sits at (1 - x2) r, star 1 at -x2 r
    unit = unit or _length_unit(p / (1 - e))
    scale = u.m.to(unit)
    x, y = _conic_points(p, e, np.inf)
    r_now = p / (1 + e * np.cos(nu)) * np.array([np.cos(nu), np.sin(nu)])
    masses = (binary.mass1, binary.mass2)
    for k, (share, color) in enumerate(((-share2, "C0"), (1 - share2, "C1"))):
        mass = display.quantity_text(masses[k].to(display.natural_unit(masses[k])), digits=4)
        ax.plot(share * x * scale, share * y * scale, color=color, lw=1.5, label=f"star {k + 1} ({mass}) orbit")
        ax.plot(share * r_now[0] * scale, share * r_now[1] * scale, marker="o", color=color, ls="none",
                label=f"star {k + 1} now (nu = {math.degrees(nu):.4g} deg)")
    ax.plot(
        [-share2 * r_now[0] * scale, (1 - share2) * r_now[0] * scale],
        [-share2 * r_now[1] * scale, (1 - share2) * r_now[1] * scale],
        color="gray",
        lw=1,
        label="joining line",
    )
    ax.plot(0, 0, marker="+", ms=12, color="k", ls="none", label="centre of mass")
    _finish_plane(ax, unit, "x toward periapsis", legend_below=True)
    return fig, ax


def _sky_unit(size_m, distance_m):
    """(unit, metres -> unit factor) of a sky picture: a length unit, or with a distance an angle (arcsec or mas,
    small angles: offset / distance rad)."""
    if distance_m is None:
        unit = _length_unit(size_m)
        return unit, u.m.to(unit)
    unit = u.mas if size_m / distance_m < 1 * u.arcsec.to(u.rad) else u.arcsec
    return unit, u.rad.to(unit) / distance_m


def binary_sky(binary: "Binary", ax: Any = None, distance: u.Quantity | None = None,
               samples: int = 721) -> tuple[Any, Any]:
    """The apparent orbit of star 2 about star 1 on the sky, north up and east to the LEFT (as the sky is seen): the
    relative orbit r2 - r1 projected along the line of sight, star 1 at the origin, star 2 now with an arrow along
    its motion across the sky (none where it moves along the line of sight), periastron, the line of nodes (position
    angle Omega) with the ascending node (where star 2 recedes) and the descending node. Offsets in a length unit,
    or in arcsec (mas) given the `distance`.

    Elements in the sky frame of orbits.binary (x north, y east, z away from the observer). The projected ellipse
    has area pi a b |cos i| (tests/api/test_binary_observables.py).
    """
    from orbits.core import elements

    if binary.shape != ():
        raise ValueError(f"binary_sky draws one binary; this Binary holds {binary.shape}: index it first")
    rel = binary.relative
    rel._require_ellipse("an apparent orbit")
    fig, ax = _axes(ax)
    p, e, inc, raan, argp = (float(x) for x in (rel.p, rel.e, rel.inc, rel.raan, rel.argp))
    mu = float(rel.mu)

    def sky(nu):
        r, v = elements.elements_to_state(p, e, inc, raan, argp, np.asarray(nu, dtype=float), mu)
        return r, v

    distance_m = None if distance is None else float(inputs.positive(distance, units.M, "distance"))
    unit, scale = _sky_unit(p / (1 - e), distance_m)
    track, _ = sky(np.linspace(-np.pi, np.pi, samples))
    east, north = track[..., 1] * scale, track[..., 0] * scale
    ax.plot(east, north, color="C0", lw=1.5, label="apparent orbit of star 2")
    ax.plot(0, 0, marker="*", ms=14, color="gold", mec="0.3", ls="none", label="star 1")
    reach = 1.15 * np.max(np.hypot(east, north))
    node = np.array([np.sin(raan), np.cos(raan)]) * reach  # (east, north) along position angle Omega
    ax.plot([-node[0], node[0]], [-node[1], node[1]], color="gray", ls="--", lw=1, gid="line of nodes",
            label=f"line of nodes, position angle {np.degrees(raan) % 360:.4g} deg")
    nodes, _ = sky(np.array([-argp, np.pi - argp]))
    ax.plot(nodes[0, 1] * scale, nodes[0, 0] * scale, marker="^", ms=8, color="C3", ls="none",
            gid="ascending node", label="ascending node (receding)")
    ax.plot(nodes[1, 1] * scale, nodes[1, 0] * scale, marker="v", ms=8, color="C2", ls="none",
            gid="descending node", label="descending node (approaching)")
    if e > _CIRCULAR:
        peri, _ = sky(0.0)
        ax.plot(peri[1] * scale, peri[0] * scale, marker="o", mfc="none", color="C0", ls="none", gid="periastron",
                label="periastron")
    now_r, now_v = sky(float(rel.nu))
    across = np.hypot(*now_v[:2])
    along_the_line_of_sight = across <= 1e-9 * np.linalg.norm(now_v)  # edge on at a node: no direction to draw
    ax.plot(now_r[1] * scale, now_r[0] * scale, marker="o", color="k", ls="none", gid="star 2 now",
            label="star 2 now (moving along the line of sight)" if along_the_line_of_sight else "star 2 now")
    if not along_the_line_of_sight:
        arrow = now_v[:2] / across * 0.12 * reach
        ax.annotate("", xy=(now_r[1] * scale + arrow[1], now_r[0] * scale + arrow[0]),
                    xytext=(now_r[1] * scale, now_r[0] * scale), arrowprops=dict(arrowstyle="->", color="k"))
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_xaxis()  # east to the left, as the sky is seen
    text = display.unit_text(unit)
    ax.set_xlabel(f"east offset [{text}] (east to the left)")
    ax.set_ylabel(f"north offset [{text}]")
    ax.set_title(f"i = {np.degrees(inc):.4g} deg, Omega = {np.degrees(raan):.4g} deg, "
                 f"omega = {np.degrees(argp):.4g} deg, e = {e:.4g}", fontsize="medium")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


def radial_velocity_curves(binary: "Binary", ax: Any = None, cycles: float = 1.25, samples: int = 600
                           ) -> tuple[Any, Any]:
    """Both stars' radial velocities (> 0 receding) against orbital phase from periastron, over `cycles` periods,
    with the systemic velocity gamma and each star's semi-amplitude K in the legend."""
    if binary.shape != ():
        raise ValueError(f"radial_velocity_curves draws one binary; this Binary holds {binary.shape}: "
                         f"index it first")
    fig, ax = _axes(ax, figsize=(9.5, 4.8))
    period = binary.period.to_value(u.s)
    phase = np.linspace(0.0, cycles, samples)
    dt = (phase * period - binary.time_since_periapsis.to_value(u.s)) << u.s
    v1, v2 = binary.radial_velocities(dt)
    k1, k2 = binary.rv_semi_amplitude1, binary.rv_semi_amplitude2
    unit = display.axis_unit(max(k1, k2, np.abs(binary.center_of_mass_velocity[2])))
    text = display.unit_text(unit)
    for v, k, name, color in ((v1, k1, "star 1", "C0"), (v2, k2, "star 2", "C1")):
        ax.plot(phase, v.to_value(unit), color=color, lw=1.5,
                label=f"{name}, K = {display.quantity_text(k, digits=4)}")
    gamma = binary.center_of_mass_velocity[2].to_value(unit)
    ax.axhline(gamma, color="gray", ls="--", lw=1, label=f"systemic velocity {gamma:.4g} {text}")
    ax.set_xlabel(f"orbital phase from periastron [periods of {display.quantity_text(binary.period, digits=5)}]")
    ax.set_ylabel(f"radial velocity [{text}] (> 0 receding)")
    ax.set_xlim(0, cycles)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


def scale_factor_curves(
    models: dict[str, "Cosmology"], t_max: u.Quantity, ax: Any = None, samples: int = 400, log: bool = False
) -> tuple[Any, Any]:
    """a(t) against cosmic time for {label: Cosmology}, from the big bang to t_max (time Quantity).

    Each model has its own colour and line style (solid, dashed, dash-dotted, dotted), so two models that nearly
    coincide both show. A universe that recollapses is drawn through its turnaround (a dot) down to its big crunch
    (a cross) when they fall before t_max, each named with its model; today (a = 1) is the dotted grey line.
    `log` puts a on a log scale (from 1e-2), for models whose a(t) spans decades by t_max.
    """
    fig, ax = _axes(ax)
    unit = display.axis_unit(t_max)
    end = t_max.to_value(unit)
    styles = ("-", "--", "-.", ":")
    for k, (label, model) in enumerate(models.items()):
        color, style = f"C{k % 10}", styles[k % len(styles)]
        crunch = model.big_crunch_time.to_value(unit)
        last = min(end, crunch)
        times = np.linspace(0.0, last, samples) * unit
        ax.plot(times.to_value(unit), model.scale_factor(times).to_value(u.one), color=color, ls=style, lw=1.6,
                label=label)
        turnaround = model.turnaround_time.to_value(unit)
        if turnaround <= end:
            ax.plot(turnaround, model.model.max_scale_factor, marker="o", color=color, ls="none", clip_on=False,
                    label=f"{label}: turnaround, t = {turnaround:.4g} {display.unit_text(unit)}")
        if crunch <= end:
            ax.plot(crunch, 1e-2 if log else 0.0, marker="X", ms=9, color=color, ls="none", clip_on=False,
                    label=f"{label}: big crunch, t = {crunch:.4g} {display.unit_text(unit)}")
    ax.axhline(1.0, color="gray", lw=0.8, ls=":", label="today, a = 1")
    ax.set_xlim(0, end)
    if log:
        ax.set_yscale("log")
        ax.set_ylim(bottom=1e-2)
    else:
        ax.set_ylim(bottom=0)
    ax.set_xlabel(f"time since the big bang [{display.unit_text(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3, which="major")
    _legend_outside(ax)
    return fig, ax


def _legend_outside(ax):
    """The legend below the axes, off the data, in as many columns as fit."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), fontsize="small", ncol=min(2, len(handles)),
                  frameon=False)


def _redshift_grid(z_max, samples):
    """Redshifts from 1e-3 to z_max, evenly spaced in log z (for a log z axis)."""
    return np.geomspace(1e-3, z_max, samples)


def hubble_diagram(
    models: dict[str, "Cosmology"], z_max: float = 10.0, ax: Any = None, samples: int = 300,
    emphasis: str | None = None,
) -> tuple[Any, Any]:
    """The Hubble diagram: distance modulus mu = 5 log10(D_L / 10 pc) against redshift (log axis) for
    {label: Cosmology}, from z = 1e-3 to z_max; the model labelled `emphasis` is drawn last, thick and black, so
    that no reference curve hides it."""
    fig, ax = _axes(ax)
    z = _redshift_grid(z_max, samples)
    order = [label for label in models if label != emphasis] + ([emphasis] if emphasis in models else [])
    for k, label in enumerate(order):
        style = dict(color="k", lw=2.6, zorder=3) if label == emphasis else dict(color=f"C{k}", lw=1.4)
        ax.plot(z, models[label].distance_modulus(z).to_value(u.one), label=label, **style)
    ax.set_xscale("log")
    ax.set_xlabel("redshift z")
    ax.set_ylabel("distance modulus m - M [mag]")
    ax.grid(alpha=0.3, which="both")
    _legend_outside(ax)
    return fig, ax


def distance_curves(cosmology: "Cosmology", z_max: float = 10.0, ax: Any = None, samples: int = 300
                    ) -> tuple[Any, Any]:
    """Luminosity, transverse comoving and angular-diameter distances of one Cosmology against redshift (log-log);
    D_A peaks (objects look smallest) and then falls, D_L = (1 + z)**2 D_A."""
    fig, ax = _axes(ax)
    z = _redshift_grid(z_max, samples)
    curves = {
        "luminosity distance D_L": cosmology.luminosity_distance(z),
        "transverse comoving distance D_M": cosmology.transverse_comoving_distance(z),
        "angular-diameter distance D_A": cosmology.angular_diameter_distance(z),
    }
    unit = u.Mpc
    for k, (label, distance) in enumerate(curves.items()):
        ax.loglog(z, distance.to_value(unit), color=f"C{k}", label=label)
    ax.set_xlabel("redshift z")
    ax.set_ylabel(f"distance [{display.unit_text(unit)}]")
    ax.grid(alpha=0.3, which="both")
    _legend_outside(ax)
    return fig, ax


def cosmology_overview(cosmology: "Cosmology", label: str, z_max: float = 10.0) -> tuple[Any, np.ndarray]:
    """Three panels for one universe: a(t) (to its big crunch if it recollapses, else to twice its age), its
    distances against z, and its Hubble diagram beside those of Planck 2018 and of Einstein-de Sitter with the
    same H0. The figure title is `label`."""
    import matplotlib.pyplot as plt

    from orbits.cosmology import Cosmology

    fig, axes = plt.subplots(1, 3, figsize=(15, 5.2), layout="constrained")
    crunch = cosmology.big_crunch_time
    if np.isfinite(cosmology.age()):
        t_max = crunch if np.isfinite(crunch) else 2 * cosmology.age()
        scale_factor_curves({"a(t)": cosmology}, t_max.to(display.axis_unit(t_max)), ax=axes[0])
    else:  # no big bang (de Sitter): a against the time from today, from z_max to a = 10
        _scale_factor_from_today(cosmology, z_max, axes[0])
    distance_curves(cosmology, z_max, ax=axes[1])
    references = {
        "Planck 2018 (flat, no radiation)": Cosmology.planck18(),
        "Einstein-de Sitter, same H0": Cosmology.einstein_de_sitter(cosmology.hubble_constant),
    }
    same = [name for name, other in references.items() if _same_universe(other, cosmology)]
    models = {"this universe" + (f" = {same[0]}" if same else ""): cosmology,
              **{name: other for name, other in references.items() if name not in same}}
    hubble_diagram(models, z_max, ax=axes[2], emphasis=next(iter(models)))
    fig.suptitle(label)
    return fig, axes


def _same_universe(one: "Cosmology", other: "Cosmology") -> bool:
    """Whether two Cosmology objects have the same H0 and density parameters (to 1e-12)."""
    fields = ("h0", "omega_m", "omega_r", "omega_k", "omega_l")
    return all(math.isclose(getattr(one, f), getattr(other, f), rel_tol=1e-12, abs_tol=1e-15) for f in fields)


def _scale_factor_from_today(cosmology: "Cosmology", z_max: float, ax: Any) -> None:
    """a = 1 / (1 + z) against t - t0 = -lookback time(z), from z_max to a = 10 (z = -0.9): the a(t) panel of a
    universe with no big bang, whose age is infinite."""
    z = np.concatenate([np.geomspace(z_max, 1e-3, 200), [0.0], -np.geomspace(1e-3, 0.9, 200)])
    time = -cosmology.lookback_time(z)
    unit = display.axis_unit(np.max(np.abs(time)))
    ax.plot(time.to_value(unit), 1.0 / (1.0 + z), color="C0", label="a(t): no big bang, infinite age")
    ax.axhline(1.0, color="gray", lw=0.8, ls=":", label="today, a = 1")
    ax.axvline(0.0, color="gray", lw=0.8, ls=":")
    ax.set_yscale("log")
    ax.set_xlabel(f"time from today [{display.unit_text(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3, which="both")
    _legend_outside(ax)


def lagrange_plane(
    system: "RestrictedThreeBody",
    ax: Any = None,
    extent: float = 1.5,
    points: int = 401,
    trajectories: dict[str, u.Quantity] | None = None,
    shade: bool = True,
    center: tuple[float, float] = (0.0, 0.0),
    jacobi_constants: dict[str, u.Quantity] | None = None,
) -> tuple[Any, Any]:
    """Rotating-frame view of a RestrictedThreeBody (axes in units of the separation r, x from M to m): the
    primaries, L1..L5, the zero-velocity curves at the Jacobi constants of L1, L2 and L3 (solid, dash-dotted,
    dashed), and, with `shade`, the regions they forbid (a particle of Jacobi constant C cannot enter where
    C(x, y) = -2 Phi < C): lightest where only a particle of C(L1) is kept out, darkest where even one of C(L3)
    is. `trajectories` {label: rotating-frame positions (K, 3) length Quantity} are drawn over them, e.g.
    RestrictedThreeBody.rotating_track of an integration (a tadpole about L4, a horseshoe through L3).
    `jacobi_constants` {label: C (m2/s2), e.g. RestrictedThreeBody.jacobi_constant of the start} gives a
    trajectory its own zero-velocity curve, dashed in its colour, and the region forbidden to it, tinted; these
    replace the shading at C(L1..L3), which is about other particles. The window spans `extent` r on each side
    of `center` (units of r; the barycentre by default).
    """
    from orbits.display import body_name

    trajectories, own = trajectories or {}, jacobi_constants or {}
    if set(own) - set(trajectories):
        raise ValueError(f"jacobi_constants for {sorted(set(own) - set(trajectories))}: no trajectory of that "
                         f"label; trajectories: {sorted(trajectories)}")

    fig, ax = _axes(ax, figsize=(9.6, 6.4))
    x, y, c = system.zero_velocity_grid(extent=extent, points=points, center=center)
    r = float(system.separation.to_value(u.m))
    xs, ys = x.to_value(u.m) / r, y.to_value(u.m) / r
    values = np.where(np.isfinite(c.value), c.value, np.finfo(float).max)
    constants = system.jacobi_constants.to_value(c.unit)
    levels = np.sort(constants[:3])  # C(L3) < C(L2) < C(L1)
    bottom = min(float(values.min()), constants[3]) - 1.0
    import matplotlib.patches as mpatches

    if shade and not own:
        ax.contourf(xs, ys, values, levels=[bottom, *levels], colors=["0.55", "0.72", "0.88"], zorder=0)
        for shade_color, k in (("0.88", 1), ("0.72", 2), ("0.55", 3)):
            ax.add_patch(mpatches.Rectangle((0, 0), 0, 0, color=shade_color, label=f"forbidden at C(L{k})"))
    contours = ax.contour(xs, ys, values, levels=levels, colors=["C2", "C1", "C0"], linestyles=["--", "-.", "-"],
                          linewidths=1.0, zorder=1)
    ax.clabel(contours, fmt={level: f"C(L{k + 1})" for k, level in enumerate(constants[:3])}, fontsize="x-small")
    mu = float(system.mass_ratio.to_value(u.one))
    primary, secondary = catalogue_body(system.gm_primary), catalogue_body(system.gm_secondary)
    ax.plot([-mu], [0], marker="o", ms=11, color=_primary_color(primary), mec="0.3", ls="none", zorder=3,
            label=f"{body_name(system.gm_primary)} (M)")
    ax.plot([1 - mu], [0], marker="o", ms=6, color=_primary_color(secondary), mec="0.3", ls="none", zorder=3,
            label=f"{body_name(system.gm_secondary)} (m), mu = {mu:.4g}")
    xy = system.positions.to_value(u.m)[:, :2] / r
    for k, (px, py) in enumerate(xy):
        ax.plot(px, py, marker="x", color="C3", ls="none", zorder=3, label="Lagrange points" if k == 0 else None)
        ax.annotate(f"L{k + 1}", (px, py), textcoords="offset points", xytext=(4, 4), fontsize="small")
    for k, (label, track) in enumerate(trajectories.items()):
        color = f"C{(k + 4) % 10}"
        shown = units.to_si(track, units.M, f"trajectory {label!r}") / r
        ax.plot(shown[:, 0], shown[:, 1], color=color, lw=1.0, zorder=2, label=label, gid="trajectory")
        if label in own:
            c0 = float(units.to_si(own[label], units.M_PER_S**2, f"Jacobi constant of {label!r}"))
            ax.contourf(xs, ys, values, levels=[bottom, c0], colors=[color], alpha=0.2, zorder=0)
            ax.contour(xs, ys, values, levels=[c0], colors=[color], linestyles=["--"], linewidths=1.2, zorder=1)
            ax.add_patch(mpatches.Rectangle((0, 0), 0, 0, color=color, alpha=0.2,
                                            label=f"forbidden to the {label.split(',')[0]} (its C)"))
    ax.set_aspect("equal")
    ax.set_xlim(center[0] - extent, center[0] + extent)
    ax.set_ylim(center[1] - extent, center[1] + extent)
    ax.set_xlabel(f"x (rotating frame) [separation r = {display.quantity_text(system.separation, digits=6)}]")
    ax.set_ylabel("y (rotating frame) [separation r]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


def lagrange_departure(system: "RestrictedThreeBody", point: str, offset: u.Quantity, times: u.Quantity,
                       track: u.Quantity) -> tuple[Any, np.ndarray]:
    """A particle leaving an unstable Lagrange point (started `offset` from it along the growing mode, e.g. by
    RestrictedThreeBody.departure_state): on the left the rotating frame about the point and the track, with the
    zero-velocity curves (lagrange_plane, framed on the track); on the right its distance from the point against
    time on a log scale, over the linear prediction offset * exp(lambda t) and the e-folding time 1 / lambda.
    `times` (K,) time Quantity from the start, `track` (K, 3) rotating-frame positions (rotating_track).
    Returns (figure, [plane, distance])."""
    import matplotlib.pyplot as plt

    k = point_index(point)
    r = float(system.separation.to_value(u.m))
    where = system.positions.to_value(u.m)[k, :2] / r
    shown = units.to_si(track, units.M, "track")[:, :2] / r
    corners = np.vstack([shown, where])
    middle = (corners.max(axis=0) + corners.min(axis=0)) / 2
    half = max(0.6 * float(np.max(corners.max(axis=0) - corners.min(axis=0))), 0.02)
    fig, (plane, distance) = plt.subplots(1, 2, figsize=(13.0, 5.6), layout="constrained",
                                          gridspec_kw={"width_ratios": (1.25, 1)})
    lagrange_plane(system, ax=plane, extent=half, center=(float(middle[0]), float(middle[1])),
                   trajectories={f"departure from {point}": track})
    plane.set_title(f"leaving {point}, started {display.quantity_text(offset, digits=3)} off along the growing mode",
                    fontsize="medium")
    seconds = units.to_si(times, units.S, "times")
    unit = display.natural_unit(times[-1])
    elapsed = (seconds << u.s).to_value(unit)
    rate = float(system.growth_rates[k].to_value(1 / u.s))
    start = float(units.to_si(offset, units.M, "offset"))
    gone = np.hypot(*(shown - where).T) * r
    distance.semilogy(elapsed, gone / r, color="C4", lw=1.3, label="integrated", gid="trajectory")
    predicted = start * np.exp(rate * seconds) / r
    e_folding = display.quantity_text(1 / rate * u.s, digits=3)
    distance.semilogy(elapsed, np.where(predicted <= 1.0, predicted, np.nan), color="C3", ls="--",
                      label=f"offset x exp(t / {e_folding}) (linear prediction)", gid="prediction")
    distance.set_xlabel(f"time [{display.unit_text(unit)}]")
    distance.set_ylabel(f"distance from {point} [separation r]")
    distance.grid(alpha=0.3, which="major")
    _legend_outside(distance)
    return fig, np.array([plane, distance])


def coorbital_plane(system: "RestrictedThreeBody", trajectories: dict[str, u.Quantity], ax: Any = None
                    ) -> tuple[Any, Any]:
    """Co-orbital motion unrolled: each trajectory's longitude from the secondary as seen from the primary (deg,
    -180 to 180) against its distance from the primary minus r (units of r), with L3 (at +-180 deg), L4 (+60),
    L5 (-60) and the secondary (0) marked. A tadpole stays on one side of the secondary; a horseshoe crosses
    +-180 deg and turns back before reaching the secondary. `trajectories` as for lagrange_plane."""
    fig, ax = _axes(ax)
    r = float(system.separation.to_value(u.m))
    mu = float(system.mass_ratio.to_value(u.one))
    for k, (label, track) in enumerate(trajectories.items()):
        shown = units.to_si(track, units.M, f"trajectory {label!r}") / r
        x, y = shown[:, 0] + mu, shown[:, 1]  # from the primary, at (-mu, 0)
        longitude = np.degrees(np.arctan2(y, x))
        offset = np.hypot(x, y) - 1.0
        jumps = np.flatnonzero(np.abs(np.diff(longitude)) > 180) + 1  # no line across the +-180 deg seam
        longitude, offset = np.insert(longitude, jumps, np.nan), np.insert(offset, jumps, np.nan)
        ax.plot(longitude, offset, color=f"C{(k + 4) % 10}", lw=1.0, label=label, gid="trajectory")
    for name, where in (("L3", -180.0), ("L5", -60.0), ("secondary", 0.0), ("L4", 60.0), ("L3", 180.0)):
        ax.axvline(where, color="0.6" if name != "secondary" else "C7", lw=0.8, ls=":" if name != "secondary" else "-")
        ax.annotate(name, (where, 1.0), xycoords=("data", "axes fraction"), textcoords="offset points",
                    xytext=(2, -10), fontsize="small")
    ax.set_xlim(-180, 180)
    ax.set_xticks(np.arange(-180, 181, 60))
    ax.set_xlabel("longitude from the secondary, seen from the primary [deg]")
    ax.set_ylabel("distance from the primary - r [separation r]")
    ax.grid(alpha=0.3)
    _legend_outside(ax)
    return fig, ax


def ring_breakup(
    times: np.ndarray,
    deviations: np.ndarray,
    growth_rate: float,
    breakup_time: float,
    ax: Any = None,
    seed: float = 1e-16,
    period: u.Quantity | None = None,
) -> tuple[Any, Any]:
    """Shape deviation of a ring against time (log), with the linear prediction seed * exp(rate t), the 1e-3
    break-up level and the predicted break-up time. `times`, 1 / `growth_rate` and `breakup_time` are in the
    ring's code unit 1 / omega; the axis counts ring periods 2 pi / omega, and says what one is when `period`
    (a time Quantity, e.g. Ring.period) is given."""
    fig, ax = _axes(ax)
    periods = np.asarray(times, dtype=float) / (2 * np.pi)
    shown = np.where(np.asarray(deviations) > 0, deviations, np.nan)
    ax.semilogy(periods, shown, color="C0", label="integrated ring")
    e_folding = 1 / (2 * np.pi * growth_rate) if growth_rate > 0 else math.inf  # in periods
    ax.semilogy(
        periods,
        seed * np.exp(growth_rate * np.asarray(times)),
        color="C3",
        ls="--",
        label=f"round-off x exp(t / {e_folding:.3g} periods)" if growth_rate > 0 else "round-off, linearly stable",
    )
    if np.isfinite(breakup_time):
        ax.axvline(breakup_time / (2 * np.pi), color="gray", ls=":",
                   label=f"predicted break-up, {breakup_time / (2 * np.pi):.3g} periods")
    ax.axhline(BREAKUP_LEVEL, color="C3", lw=0.8, ls="-.", gid="break-up level",
               label=f"break-up level {BREAKUP_LEVEL:g} of the radius")
    ax.set_ylim(1e-17, 10)
    one = f", 1 period = {display.quantity_text(period, digits=4)}" if period is not None else ""
    ax.set_xlabel(f"time [ring periods 2 pi / omega{one}]")
    ax.set_ylabel("largest chord error [ring radius]")
    ax.grid(alpha=0.3, which="major")
    _legend_outside(ax)
    return fig, ax


#: the shape deviation called break-up (orbits.rings.BREAKUP_DEVIATION, repeated to keep plot's imports light)
BREAKUP_LEVEL = 1e-3


def ring_snapshots(times: np.ndarray, positions: np.ndarray, growth_rate: float, breakup_time: float,
                   first_body: int = 0, moments: Sequence[float] = (0.0, 1.0, 1.25, 1.5),
                   period: u.Quantity | None = None) -> tuple[Any, np.ndarray]:
    """A ring breaking up: its shape deviation against time on top (ring_breakup, with the 1e-3 break-up level,
    time in ring periods), and below it the bodies at the outputs nearest `moments` x the predicted break-up
    time, in the frame turning with the ring (x, y in ring radii), each panel with the regular n-gon it started
    as. Code units of orbits.validate.builders.ring_problem: `positions` (K, N, 3) in ring radii (ring bodies from
    index `first_body`; a central mass before them is drawn as a star), times in 1 / omega; `period` as for
    ring_breakup."""
    import matplotlib.pyplot as plt

    from orbits.core import rings

    times, positions = np.asarray(times, dtype=float), np.asarray(positions, dtype=float)
    ring = positions[:, first_body:]
    deviations = rings.shape_deviation(ring, 1.0)
    fig = plt.figure(figsize=(11, 7.2), layout="constrained")
    grid = fig.add_gridspec(2, len(moments), height_ratios=(1.3, 1))
    top = fig.add_subplot(grid[0, :])
    ring_breakup(times, deviations, growth_rate, breakup_time, ax=top, period=period)
    top.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", frameon=False)
    n = ring.shape[1]
    angle = np.linspace(0, 2 * np.pi, n + 1)
    panels = []
    for column, moment in enumerate(moments):
        ax = fig.add_subplot(grid[1, column])
        target = moment * breakup_time if np.isfinite(breakup_time) else moment / max(moments) * times[-1]
        k = int(np.argmin(np.abs(times - target)))
        ax.plot(np.cos(angle), np.sin(angle), color="0.7", lw=0.8, ls="--", label="regular n-gon")
        c, s = np.cos(times[k]), np.sin(times[k])  # into the frame turning with the ring (omega = 1)
        x, y = c * ring[k, :, 0] + s * ring[k, :, 1], -s * ring[k, :, 0] + c * ring[k, :, 1]
        ax.plot(x, y, marker="o", ms=5, ls="none", color="C0", gid="bodies")
        if first_body:
            ax.plot(positions[k, 0, 0], positions[k, 0, 1], marker="*", ms=10, color="gold", mec="0.3", ls="none")
        top.plot(times[k] / (2 * np.pi), max(deviations[k], 1e-17), marker="v", color="k", ls="none",
                 gid="snapshot")
        ax.set_title(f"t = {times[k] / (2 * np.pi):.3g} periods\ndeviation {deviations[k]:.1e}", fontsize="small")
        ax.set_aspect("equal")
        reach = max(1.6, 1.1 * float(np.max(np.hypot(x, y))))
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
        ax.set_xlabel("x, turning with the ring [radius]", fontsize="x-small")
        if column == 0:
            ax.set_ylabel("y [ring radius]", fontsize="x-small")
        ax.tick_params(labelsize="x-small")
        panels.append(ax)
    return fig, np.array([top, *panels])


def validation_residuals(report: Any, figure: Any = None) -> tuple[Any, np.ndarray]:
    """Position error |dr| / L against time (a ValidationReport), one colour per scene and one line style per
    backend, errors on a log scale and each panel's legend below it.

    Scenes that run for at least one period of their first orbit (SceneReport.period) share the left panel, on
    log-log axes with time in that period (a 100-period scene ends at 100); the others (a flyby, an encounter,
    one passage of a near-parabolic comet, the expanding sphere) the right one, against the fraction of their run
    on a linear axis (a symmetric flyby's periapsis in the middle). Only the panels with something to show are
    drawn; an exact match (zero error) and t = 0 have no place on log axes and are left out. `figure` may be a
    Figure or SubFigure to draw into. Returns (figure, array of the panels).
    """
    figure = _figure(figure, (10.0, 5.0))
    shown = [scene for scene in report.scenes if scene.residuals]
    colors = dict(zip((scene.name for scene in shown), _colors(len(shown)), strict=True))
    backends = list(dict.fromkeys(backend for scene in shown for backend in scene.residuals))
    styles = dict(zip(backends, ("-", "--", ":", "-.")))
    orbiting = [s for s in shown if s.period and s.residual_times[-1] >= s.period]
    groups = {"closed": orbiting, "open": [s for s in shown if s not in orbiting]}
    groups = {kind: scenes for kind, scenes in groups.items() if scenes}
    if not groups:
        return figure, _nothing_to_draw(figure, "no scene here predicts positions: nothing to plot against time")
    panels = np.atleast_1d(figure.subplots(1, len(groups), sharey=True))
    for ax, (kind, scenes) in zip(panels, groups.items(), strict=True):
        for scene in scenes:
            times = np.asarray(scene.residual_times, dtype=float)
            elapsed = times / scene.period if kind == "closed" else times / times[-1]
            for backend, series in scene.residuals.items():
                ax.plot(elapsed, np.where((series > 0) & (elapsed > 0), series, np.nan), color=colors[scene.name],
                        ls=styles.get(backend, "-"), lw=1.3, label=f"{scene.name}: {backend}")
        ax.set_yscale("log")
        if kind == "closed":
            ax.set_xscale("log")
            ax.set_xlabel("time [periods of the scene's first orbit]")
            ax.set_title("runs of whole orbits", fontsize="medium")
        else:
            ax.set_xlim(0.0, 1.0)
            ax.set_xlabel("time [fraction of the run]")
            ax.set_title("single passages and open orbits", fontsize="medium")
        ax.grid(alpha=0.3, which="major")
        _legend_outside(ax)
    panels[0].set_ylabel("position error |dr| / L [dimensionless]")
    return figure, panels


def validation_tracks(report: Any, figure: Any = None, columns: int = 4) -> tuple[Any, np.ndarray]:
    """The integrated trajectories over the analytic ones (a ValidationReport): one panel per scene that predicts
    positions, each body relative to the first (the primary) and seen face on (the plane of largest spread of
    the predicted tracks), the closed form as a grey curve (over one period, SceneReport.outline) with open circles
    at the output times and each backend's positions as small markers in them (at most TRACK_MARKERS outputs per
    body, evenly spaced); the title gives each backend's worst |dr| / L; the legend sits in the first empty cell,
    or below the panels. Axes in the scene's natural length unit (code units for a model scene). Returns (figure,
    array of the panels).
    """
    shown = [scene for scene in report.scenes if scene.expected is not None and scene.positions]
    rows = max(1, math.ceil(len(shown) / columns))
    figure = _figure(figure, (3.0 * min(columns, max(1, len(shown))) + 1.0, 3.2 * rows + 0.6))
    if not shown:
        return figure, _nothing_to_draw(figure, "no scene here predicts positions: no tracks to draw")
    panels = np.atleast_1d(figure.subplots(rows, min(columns, len(shown)), squeeze=False)).ravel()
    markers = ("x", "+", "1", "2")
    for ax, scene in zip(panels, shown, strict=False):
        relative = scene.expected[:, 1:] - scene.expected[:, :1]
        curve = relative if scene.outline is None else scene.outline[:, 1:] - scene.outline[:, :1]
        basis = _face_on_basis(np.concatenate([curve, relative]).reshape(-1, 3))
        size = float(np.max(np.abs(relative)))
        unit = u.one if scene.in_code_units else _length_unit(size)
        factor = 1.0 if scene.in_code_units else (1 * u.m).to_value(unit)
        every = slice(None, None, math.ceil(len(relative) / TRACK_MARKERS) | 1)  # odd: outputs every half period
        # land on both of the points they alternate between
        for body in range(relative.shape[1]):
            ax.plot(*(curve[:, body] @ basis.T * factor).T, color="0.6", lw=0.8, zorder=1,
                    label="closed form" if body == 0 else None)
            ax.plot(*(relative[every, body] @ basis.T * factor).T, color="0.45", ls="none", marker="o", ms=5,
                    mfc="none", mew=0.7, zorder=1, label="closed form at the outputs" if body == 0 else None)
        for k, (backend, positions) in enumerate(scene.positions.items()):
            moving = positions[every, 1:] - positions[every, :1]
            for body in range(moving.shape[1]):
                x, y = (moving[:, body] @ basis.T * factor).T
                ax.plot(x, y, ls="none", marker=markers[k % len(markers)], ms=3.5, color=f"C{k}", zorder=2,
                        label=backend if body == 0 else None, gid=f"integrated {backend}")
        ax.plot([0.0], [0.0], marker="*", ms=9, color="gold", mec="0.3", ls="none", zorder=3,
                label="first body (the origin)")
        worst = ", ".join(f"{b} {float(np.max(r)):.1e}" for b, r in scene.residuals.items())
        ax.set_title(f"{scene.name}\nworst |dr|/L: {worst}", fontsize="small")
        where = "code length" if scene.in_code_units else display.unit_text(unit)
        ax.set_xlabel(f"in-plane x [{where}]", fontsize="small")
        ax.set_ylabel(f"in-plane y [{where}]", fontsize="small")
        ax.set_aspect("equal", adjustable="datalim")
        ax.tick_params(labelsize="x-small")
        ax.grid(alpha=0.3)
    for ax in panels[len(shown):]:
        ax.set_axis_off()
    handles, labels = panels[0].get_legend_handles_labels()
    if len(panels) > len(shown):  # in the first empty cell
        panels[len(shown)].legend(handles, labels, loc="center", fontsize="small", frameon=False)
    else:
        figure.legend(handles, labels, loc="outside lower center", ncol=len(labels), fontsize="small", frameon=False)
    return figure, panels[:len(shown)]


#: at most this many outputs of each body are marked in validation_tracks (every k-th), so the markers stay apart
TRACK_MARKERS = 50


def _nothing_to_draw(figure: Any, text: str) -> np.ndarray:
    """One blank panel of `figure` saying why nothing is drawn; returned as the array of panels."""
    ax = figure.subplots()
    ax.text(0.5, 0.5, text, ha="center", transform=ax.transAxes)
    ax.set_axis_off()
    return np.array([ax])


def _face_on_basis(points: np.ndarray) -> np.ndarray:
    """(2, 3) orthonormal rows spanning the plane of largest spread of (M, 3) points about the origin (their
    first two right singular vectors): an orbit seen face on, whatever its inclination."""
    _, _, rows = np.linalg.svd(points, full_matrices=False)
    return rows[:2]


def validation_overview(report: Any) -> tuple[Any, np.ndarray]:
    """The picture of `orbits validate --plot`: residuals against time on top (validation_residuals), the
    integrated trajectories over the analytic ones below (validation_tracks); one panel saying so when no scene
    of the report predicts positions. Returns (figure, all panels)."""
    import matplotlib.pyplot as plt

    tracks = sum(1 for scene in report.scenes if scene.expected is not None and scene.positions)
    if not tracks:  # nothing over time either: one panel says so
        fig = plt.figure(figsize=(8.0, 2.0), layout="constrained")
        names = ", ".join(scene.name for scene in report.scenes)
        return fig, _nothing_to_draw(fig, f"no positions are predicted in {names}: the report's checks are all")
    rows = max(1, math.ceil(tracks / 4))
    fig = plt.figure(figsize=(13.0, 5.4 + 3.3 * rows), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=(5.4, 3.3 * rows))
    _, residual_panels = validation_residuals(report, top)
    _, track_panels = validation_tracks(report, bottom)
    return fig, np.concatenate([residual_panels, track_panels])


def _figure(figure: Any, size: tuple[float, float]) -> Any:
    """`figure` (a Figure or SubFigure), or a new constrained-layout Figure of `size` inches."""
    if figure is not None:
        return figure
    import matplotlib.pyplot as plt

    return plt.figure(figsize=size, layout="constrained")


def work_precision(rows: Sequence[Any], columns: int = 3) -> tuple[Any, np.ndarray]:
    """Error against wall time (log-log), one panel per problem and one line per method (orbits.tools.precision rows).

    The closed-form answer is a star; runs whose error is zero sit on the bottom edge at 1e-17.
    """
    import matplotlib.pyplot as plt

    problems = list(dict.fromkeys(r.problem for r in rows))
    columns = min(columns, len(problems))
    n_rows = -(-len(problems) // columns)
    fig, axes = plt.subplots(
        n_rows, columns, figsize=(4.2 * columns + 2.2, 3.4 * n_rows), layout="constrained", squeeze=False
    )
    methods = list(dict.fromkeys(r.method for r in rows))
    for ax, problem in zip(axes.flat, problems):
        for k, method in enumerate(methods):
            runs = [r for r in rows if r.problem == problem and r.method == method and np.isfinite(r.error)]
            if not runs:
                continue
            seconds = [max(r.seconds, 1e-6) for r in runs]
            errors = [max(r.error, 1e-17) for r in runs]
            style = dict(marker="*", ms=12, ls="none") if method == "orbits analytic" else dict(marker="o", ms=3)
            ax.loglog(seconds, errors, color=f"C{k}", label=method, **style)
        ax.set_title(problem, fontsize="medium")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("position error / orbit size")
        ax.grid(alpha=0.3, which="major")
    for ax in list(axes.flat)[len(problems) :]:
        ax.set_visible(False)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside right upper", fontsize="small")
    return fig, axes


#: matplotlib's date numbers count days from 1970-01-01 (Julian date 2440587.5)
_UNIX_EPOCH_JD = 2440587.5


def _contour_levels(values: np.ndarray, factors: Sequence[float]) -> np.ndarray:
    """Contour levels at `factors` times the least value, each rounded to two significant digits."""
    least = float(np.min(values))
    levels = [float(f"{least * f:.2g}") for f in factors]
    return np.unique([level for level in levels if level > least])


def porkchop(p: Any, ax: Any = None) -> tuple[Any, Any]:
    """Draw a Porkchop: contours of departure C3 [km2/s2] (solid, labelled), of arrival v_inf [km/s] (dashed) and
    of the time of flight [d] (grey, dotted), launch date on x and arrival date on y (TDB), the cells of least C3,
    least arrival v_inf and least total v_inf marked. Cells whose arrival is not after the launch are left blank.

    Each contour set carries a gid ("C3", "arrival v_inf", "time of flight") and each marker the gid "minimum";
    tested in tests/api/test_porkchop.py (the marker sits on the minimum's dates, the levels bracket the grid).
    """
    import matplotlib.dates as mdates

    fig, ax = _axes(ax, figsize=(8.0, 7.2))
    x = p.launch_dates.tdb.jd - _UNIX_EPOCH_JD
    y = p.arrival_dates.tdb.jd - _UNIX_EPOCH_JD
    blank = ~p.valid
    c3 = np.ma.masked_array(p.c3.unmasked.to_value(u.km**2 / u.s**2), blank)
    v_inf = np.ma.masked_array(p.arrival_v_inf.unmasked.to_value(u.km / u.s), blank)
    tof = np.ma.masked_array(p.time_of_flight.unmasked.to_value(u.day), blank)
    c3_lines = ax.contour(x, y, c3, levels=_contour_levels(c3.compressed(), (1.02, 1.1, 1.25, 1.5, 2, 3, 5, 8)),
                          colors="C0", linewidths=1.2)
    ax.clabel(c3_lines, fontsize="x-small", fmt="%.3g")
    c3_lines.set_gid("C3")
    v_lines = ax.contour(x, y, v_inf, levels=_contour_levels(v_inf.compressed(), (1.05, 1.2, 1.5, 2, 3, 4)),
                         colors="C3", linewidths=1.0, linestyles="--")
    ax.clabel(v_lines, fontsize="x-small", fmt="%.3g")
    v_lines.set_gid("arrival v_inf")
    span = tof.compressed()
    step = max(25.0, float(f"{(span.max() - span.min()) / 6:.1g}"))
    days = np.arange(np.ceil(span.min() / step) * step, span.max(), step)
    tof_lines = ax.contour(x, y, tof, levels=days, colors="0.55", linewidths=0.8, linestyles=":")
    ax.clabel(tof_lines, fontsize="xx-small", fmt="%d d")
    tof_lines.set_gid("time of flight")
    marks = {"C3": ("*", "C0", 16, p.minimum_c3), "arrival v_inf": ("D", "C3", 9, p.minimum_arrival_v_inf),
             "total v_inf": ("o", "k", 9, p.minimum_total)}
    for kind, (marker, color, size, best) in marks.items():
        label = (f"least {kind}: {best.launch.tdb.iso[:10]} to {best.arrival.tdb.iso[:10]}, "
                 f"C3 = {best.c3.to_value(u.km**2 / u.s**2):.2f} km2/s2, "
                 f"v_inf = {best.arrival_v_inf.to_value(u.km / u.s):.2f} km/s")
        ax.plot(best.launch.tdb.jd - _UNIX_EPOCH_JD, best.arrival.tdb.jd - _UNIX_EPOCH_JD, marker=marker, ms=size,
                color=color, mec="k", mew=0.8, ls="none", label=label, gid="minimum", zorder=5)
    ax.plot([], [], color="C0", label="departure C3 [km2/s2]")
    ax.plot([], [], color="C3", ls="--", label="arrival v_inf [km/s]")
    ax.plot([], [], color="0.55", ls=":", label="time of flight [d]")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(mdates.AutoDateLocator(maxticks=8))
        axis.set_major_formatter(mdates.DateFormatter("%Y-%m-%d"))
    ax.tick_params(axis="x", labelrotation=30)
    ax.set_xlabel("launch date [TDB]")
    ax.set_ylabel("arrival date [TDB]")
    ax.grid(alpha=0.25)
    ax.set_title(f"{p.departure} to {p.target}: zero-revolution prograde transfers\n"
                 f"positions: {p.source}", fontsize="medium")
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize="small", ncol=1,
               frameon=False)
    return fig, ax


def save(fig: Any, path: str | Path) -> None:
    """Write the figure to `path` atomically; the format follows the suffix (.png, .svg or .pdf)."""
    suffix = str(path).rsplit(".", 1)[-1].lower()
    if suffix not in ("png", "svg", "pdf"):
        raise ValueError(f"plot file {path!r} must end in .png, .svg or .pdf")
    buffer = io.BytesIO()
    fig.savefig(buffer, format=suffix, dpi=150)
    write_atomic(path, buffer.getvalue())
