"""Pictures: orbits in their plane and validation residuals. matplotlib is imported only when drawing.

Every function draws on a given Axes (or a new Figure) and returns (fig, ax), so the result can be
restyled; axis labels carry units. `save(fig, path)` writes PNG, SVG or PDF atomically.
"""

import io
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import astropy.units as u
import numpy as np

from orbits import display, units
from orbits.io import write_atomic

if TYPE_CHECKING:
    from orbits.binary import Binary
    from orbits.cosmology import Cosmology
    from orbits.flyby import Flyby
    from orbits.lagrange import RestrictedThreeBody
    from orbits.orbit import Orbit


def _axes(ax):
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(6.4, 5.6), layout="constrained")
        return fig, ax
    return ax.figure, ax


def _finish_plane(ax, unit, x_label):
    """Equal aspect, labelled axes with the length unit, grid and legend: the end of every in-plane picture."""
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"{x_label} [{unit.to_string()}]")
    ax.set_ylabel(f"y [{unit.to_string()}]")
    ax.grid(alpha=0.3)
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
) -> tuple[Any, Any]:
    """Draw a single Orbit in its own plane (perifocal frame: periapsis along +x, star at the origin).

    Marks the star (focus), periapsis, apoapsis, the centre and empty focus of an ellipse, the body's
    current position, and its positions at `times` (time Quantity array) later, when given.
    """
    if orbit.shape != ():
        raise ValueError(f"orbit_plane draws one orbit; this Orbit holds {orbit.shape} orbits: index it first")
    fig, ax = _axes(ax)
    p, e = float(orbit.p), float(orbit.e)
    q = p / (1 + e)
    nus = _true_anomalies(orbit, times)
    radii = p / (1 + e * np.cos(nus))
    r_max = max(10 * q, 1.3 * radii.max())
    unit = unit or _length_unit(p / (1 - e) if e < 1 else r_max)
    scale = u.m.to(unit)
    x, y = _conic_points(p, e, r_max)
    ax.plot(x * scale, y * scale, color="C0", lw=1.5, label=label or f"orbit, e = {e:.6g}")
    ax.plot(0, 0, marker="*", ms=14, color="orange", ls="none", label="star (focus)")
    ax.plot(q * scale, 0, marker="o", color="C3", ls="none", label="periapsis")
    if e < 1:
        c = e * p / (1 - e * e)
        ax.plot(-p / (1 - e) * scale, 0, marker="o", color="C2", ls="none", label="apoapsis")
        ax.plot(-c * scale, 0, marker="+", ms=10, color="gray", ls="none", label="centre")
        ax.plot(-2 * c * scale, 0, marker="x", color="gray", ls="none", label="empty focus")
    _mark_positions(ax, nus, radii, scale)
    _finish_plane(ax, unit, "x toward periapsis")
    return fig, ax


def _true_anomalies(orbit, times):
    """The body's true anomaly now, then at each of `times` later (rad)."""
    later = [] if times is None else [float(orbit.at(t).nu) for t in np.atleast_1d(times)]
    return np.array([float(orbit.nu), *later])


def _mark_positions(ax, nus, radii, scale):
    """The body now, and at the later times, as dots on the conic."""
    x, y = radii * np.cos(nus) * scale, radii * np.sin(nus) * scale
    ax.plot(x[0], y[0], marker="o", color="k", ls="none", label="body now")
    if len(nus) > 1:
        ax.plot(x[1:], y[1:], marker=".", color="k", ls="none", alpha=0.6, label="body at given times")


# ---- several orbits and trajectories in one frame ----------------------------------------------------------

PROJECTIONS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2), "3d": (0, 1, 2)}
_CIRCULAR = 1e-3  # below this eccentricity the apsides are not marked: they mean nothing on a near-circle
_LONG = 100.0  # an ellipse with Q > _LONG q is drawn, like an open orbit, only within the picture's window
_AXES = "xyz"


class InsideBodyWarning(UserWarning):
    """A drawn closest approach lies inside the primary (or inside both bodies' radii): a collision."""


def catalogue_body(gm: Any) -> Any:
    """The catalogue Body whose GM is exactly `gm` (m3/s2, every element the same), else None."""
    from orbits.constants import BODIES

    values = np.unique(np.asarray(gm, dtype=float))
    if values.size != 1:
        return None
    return next((known for known in BODIES.values() if known.gm == values[0]), None)


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
                name = given if len(flat) == 1 else f"{given or 'orbit'} [{j}]"
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
    """n distinct colours: matplotlib's ten, then tab20's twenty, then evenly spaced hues."""
    import matplotlib

    if n <= 10:
        return [f"C{k}" for k in range(n)]
    if n <= 20:
        return list(matplotlib.colormaps["tab20"].colors[:n])
    return [matplotlib.colormaps["hsv"](k / n) for k in range(n)]


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


def _draw_primary(ax, body, axes_index, scale, size, unit):
    """The primary at the origin: a disc (a sphere's outline in 3D) of its radius, and a star if that is tiny."""
    name = body.name if body is not None else "primary"
    radius = body.radius * scale if body is not None else 0.0
    tiny = radius < 0.01 * size * scale
    if len(axes_index) == 3:
        if not tiny:
            angle = np.linspace(0, 2 * np.pi, 97)
            for i, j in ((0, 1), (0, 2), (1, 2)):
                circle = np.zeros((3, angle.size))
                circle[i], circle[j] = radius * np.cos(angle), radius * np.sin(angle)
                ax.plot(*circle, color="orange", lw=1)
        ax.plot([0], [0], [0], marker="*", ms=12, color="orange", ls="none", label=f"{name}")
        return
    import matplotlib.patches as mpatches

    if radius > 0:
        ax.add_patch(mpatches.Circle((0, 0), radius, color="orange", alpha=0.6, zorder=0.5,
                                     label=f"{name} (to scale)" if not tiny else None))
    if tiny:
        ax.plot(0, 0, marker="*", ms=12, color="orange", ls="none", zorder=4,
                label=f"{name} (star not to scale; radius {display.quantity_text(body.radius << u.m, digits=3)})"
                if radius > 0 else name)


def _finish_frame(ax, projection, unit, body):
    """Axis labels with the unit, equal scales, grid, and the legend outside the axes on the right."""
    names = [_AXES[i] for i in PROJECTIONS[projection]]
    text = unit.to_string()
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
    for share, name, color in ((-share2, "star 1", "C0"), (1 - share2, "star 2", "C1")):
        ax.plot(share * x * scale, share * y * scale, color=color, lw=1.5, label=f"{name} orbit")
        ax.plot(share * r_now[0] * scale, share * r_now[1] * scale, marker="o", color=color, ls="none")
    ax.plot(
        [-share2 * r_now[0] * scale, (1 - share2) * r_now[0] * scale],
        [-share2 * r_now[1] * scale, (1 - share2) * r_now[1] * scale],
        color="gray",
        lw=1,
        label="joining line",
    )
    ax.plot(0, 0, marker="+", ms=12, color="k", ls="none", label="centre of mass")
    _finish_plane(ax, unit, "x toward periapsis")
    return fig, ax


def scale_factor_curves(
    models: dict[str, "Cosmology"], t_max: u.Quantity, ax: Any = None, samples: int = 400
) -> tuple[Any, Any]:
    """a(t) against cosmic time for {label: Cosmology}, from the big bang to t_max (time Quantity).

    A universe that recollapses is drawn through its turnaround (a dot) down to its big crunch (a cross) when
    they fall before t_max; today (a = 1) is the dotted line.
    """
    fig, ax = _axes(ax)
    unit = display.axis_unit(t_max)
    end = t_max.to_value(unit)
    for k, (label, model) in enumerate(models.items()):
        crunch = model.big_crunch_time.to_value(unit)
        last = min(end, crunch)
        times = np.linspace(0.0, last, samples) * unit
        ax.plot(times.to_value(unit), model.scale_factor(times).to_value(u.one), color=f"C{k}", label=label)
        turnaround = model.turnaround_time.to_value(unit)
        if turnaround <= end:
            ax.plot(turnaround, model.model.max_scale_factor, marker="o", color=f"C{k}", ls="none", clip_on=False,
                    label=f"turnaround, t = {turnaround:.4g} {display.unit_text(unit)}")
        if crunch <= end:
            ax.plot(crunch, 0.0, marker="X", ms=9, color=f"C{k}", ls="none", clip_on=False,
                    label=f"big crunch, t = {crunch:.4g} {display.unit_text(unit)}")
    ax.axhline(1.0, color="gray", lw=0.8, ls=":", label="today, a = 1")
    ax.set_xlim(0, end)
    ax.set_ylim(bottom=0)
    ax.set_xlabel(f"time since the big bang [{display.unit_text(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3)
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
    models: dict[str, "Cosmology"], z_max: float = 10.0, ax: Any = None, samples: int = 300
) -> tuple[Any, Any]:
    """The Hubble diagram: distance modulus mu = 5 log10(D_L / 10 pc) against redshift (log axis) for
    {label: Cosmology}, from z = 1e-3 to z_max."""
    fig, ax = _axes(ax)
    z = _redshift_grid(z_max, samples)
    for k, (label, model) in enumerate(models.items()):
        ax.plot(z, model.distance_modulus(z).to_value(u.one), color=f"C{k}", label=label)
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
        "comoving distance D_M": cosmology.transverse_comoving_distance(z),
        "angular-diameter distance D_A": cosmology.angular_diameter_distance(z),
    }
    unit = u.Mpc
    for k, (label, distance) in enumerate(curves.items()):
        ax.loglog(z, distance.to_value(unit), color=f"C{k}", label=label)
    ax.set_xlabel("redshift z")
    ax.set_ylabel(f"distance [{unit.to_string()}]")
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
    t_max = crunch if np.isfinite(crunch) else 2 * cosmology.age()
    scale_factor_curves({"a(t)": cosmology}, t_max.to(display.axis_unit(t_max)), ax=axes[0])
    distance_curves(cosmology, z_max, ax=axes[1])
    references = {
        "Planck 2018 (flat, no radiation)": Cosmology.planck18(),
        "Einstein-de Sitter, same H0": Cosmology.einstein_de_sitter(cosmology.hubble_constant),
    }
    hubble_diagram({"this universe": cosmology, **references}, z_max, ax=axes[2])
    fig.suptitle(label)
    return fig, axes


def lagrange_plane(
    system: "RestrictedThreeBody", ax: Any = None, extent: float = 1.5, points: int = 401
) -> tuple[Any, Any]:
    """Rotating-frame view of a RestrictedThreeBody: the primaries, L1..L5, and the zero-velocity curves at the
    Jacobi constants of L1, L2 and L3 (a particle with that constant cannot enter where C(x, y) < C)."""
    fig, ax = _axes(ax)
    x, y, c = system.zero_velocity_grid(extent=extent, points=points)
    r = float(system.separation.to_value(u.m))
    levels = np.sort(system.jacobi_constants.to_value(c.unit)[:3])
    contours = ax.contour(
        x.to_value(u.m) / r, y.to_value(u.m) / r, c.value, levels=levels, colors=["C2", "C1", "C0"], linewidths=1.2
    )
    ax.clabel(
        contours,
        fmt={level: f"C(L{k + 1})" for k, level in enumerate(system.jacobi_constants.value[:3])},
        fontsize="x-small",
    )
    mu = float(system.mass_ratio.to_value(u.one))
    ax.plot([-mu], [0], marker="o", ms=12, color="C0", ls="none", label=f"primary (1 - mu), mu = {mu:.4g}")
    ax.plot([1 - mu], [0], marker="o", ms=6, color="C7", ls="none", label="secondary")
    xy = system.positions.to_value(u.m)[:, :2] / r
    for k, (px, py) in enumerate(xy):
        ax.plot(px, py, marker="x", color="C3", ls="none", label="Lagrange points" if k == 0 else None)
        ax.annotate(f"L{k + 1}", (px, py), textcoords="offset points", xytext=(4, 4), fontsize="small")
    ax.set_aspect("equal")
    ax.set_xlabel("x (rotating frame) [separation r]")
    ax.set_ylabel("y (rotating frame) [separation r]")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower left", fontsize="small")
    return fig, ax


def ring_breakup(
    times: np.ndarray,
    deviations: np.ndarray,
    growth_rate: float,
    breakup_time: float,
    ax: Any = None,
    seed: float = 1e-16,
) -> tuple[Any, Any]:
    """Shape deviation of a ring against time (log), with the linear prediction seed * exp(rate t) and the
    predicted break-up time (times in the ring's time unit)."""
    fig, ax = _axes(ax)
    shown = np.where(np.asarray(deviations) > 0, deviations, np.nan)
    ax.semilogy(times, shown, color="C0", label="integrated ring")
    ax.semilogy(
        times,
        seed * np.exp(growth_rate * np.asarray(times)),
        color="C3",
        ls="--",
        label=f"round-off x exp({growth_rate:.3g} t)",
    )
    ax.axvline(breakup_time, color="gray", ls=":", label=f"predicted break-up t = {breakup_time:.3g}")
    ax.set_ylim(1e-17, 10)
    ax.set_xlabel("time [1 / angular velocity]")
    ax.set_ylabel("largest chord error [ring radius]")
    ax.grid(alpha=0.3, which="major")
    ax.legend(loc="best", fontsize="small")
    return fig, ax


def validation_residuals(report: Any, ax: Any = None) -> tuple[Any, Any]:
    """Position error |dr| / r_max against time in orbits, per scene (a colour) and backend (a line style), on
    log-log axes (a 100-orbit scene and a flyby of a tenth of one side by side), with the legend outside on the
    right (a ValidationReport).

    One orbit is 2 pi sqrt(L**3 / GM) for the scene's length scale L and GM (its code units): the period of a
    circular orbit of radius L. An exact match (zero error) and t = 0 have no place on log axes and are left out.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(9.0, 5.0), layout="constrained")
    else:
        fig = ax.figure
    backends = list(dict.fromkeys(backend for scene in report.scenes for backend in scene.residuals))
    styles = dict(zip(backends, ("-", "--", ":", "-.")))
    for k, scene in enumerate(report.scenes):
        for backend, series in scene.residuals.items():
            orbits_elapsed = np.asarray(scene.residual_times) / (2 * np.pi * scene.code_units.time)  # times in s
            shown = np.where((series > 0) & (orbits_elapsed > 0), series, np.nan)
            ax.loglog(orbits_elapsed, shown, color=_colors(len(report.scenes))[k], ls=styles.get(backend, "-"),
                        lw=1.3, label=f"{scene.name}: {backend}")
    ax.set_xlabel("time [orbits of the scene's length scale, 2 pi sqrt(L**3 / GM)]")
    ax.set_ylabel("position error |dr| / r_max [dimensionless]")
    ax.grid(alpha=0.3, which="major")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    return fig, ax


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


def save(fig: Any, path: str | Path) -> None:
    """Write the figure to `path` atomically; the format follows the suffix (.png, .svg or .pdf)."""
    suffix = str(path).rsplit(".", 1)[-1].lower()
    if suffix not in ("png", "svg", "pdf"):
        raise ValueError(f"plot file {path!r} must end in .png, .svg or .pdf")
    buffer = io.BytesIO()
    fig.savefig(buffer, format=suffix, dpi=150)
    write_atomic(path, buffer.getvalue())
