"""Kepler orbits drawn about their primary: one orbit face on in its own plane (orbit_plane), or any number of
orbits and trajectories in one inertial frame, in projection or in 3D (orbits, the engine of Orbit.plot).

An orbit here is anything with the float64 SI elements of orbits.Orbit as fields (mu, p, e, inc, raan, argp, nu,
arrays of orbits included); each orbit it holds is drawn as a Conic. The primary at the focus is a catalogue body
drawn to scale (or a star where its disc would be too small to see).
"""

import dataclasses
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame, units
from orbits._common.constants import Body, body, body_with_gm
from orbits.core.errors import InsideBodyWarning
from orbits.core.twobody import elements, propagate, twobody
from orbits.ephemeris import positions

#: projection name -> the indices of the axes it shows
PROJECTIONS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2), "3d": (0, 1, 2)}
#: below this eccentricity the apsides are not marked: they mean nothing on a near-circle
CIRCULAR = 1e-3
_LONG = 100.0  # an ellipse with Q > _LONG q is drawn, like an open orbit, only within the picture's window
_AXES = "xyz"
_MARKERS = {"periapsis": "o", "apoapsis": "s", "position": "."}
#: the fields of an orbit that the pictures read (those of orbits.Orbit)
ELEMENTS = ("mu", "p", "e", "inc", "raan", "argp", "nu")


@dataclass(frozen=True)
class Conic:
    """One Kepler orbit as drawn: mu (m3/s2), p (m), e, and the angles i, Omega, omega, nu (rad) in the conventions
    of orbits.core.twobody.elements; positions from orbits.core."""

    mu: float
    p: float
    e: float
    inc: float
    raan: float
    argp: float
    nu: float

    @classmethod
    def from_state(cls, r: np.ndarray, v: np.ndarray, mu: float) -> "Conic":
        """The conic through position r (m) and velocity v (m/s), each of shape (3,), about mu (m3/s2)."""
        return cls(float(mu), *(float(x) for x in elements.state_to_elements(r, v, mu)))

    @property
    def periapsis(self) -> float:
        """q = p / (1 + e) (m)."""
        return float(twobody.periapsis_distance(self.p, self.e))

    @property
    def radius(self) -> float:
        """|r| = p / (1 + e cos nu) (m)."""
        return float(self.p / (1.0 + self.e * np.cos(self.nu)))

    @property
    def state(self) -> tuple[np.ndarray, np.ndarray]:
        """(r (m), v (m/s)), each of shape (3,), of the body at true anomaly nu."""
        return elements.elements_to_state(self.p, self.e, self.inc, self.raan, self.argp, self.nu, self.mu)

    def position_after(self, seconds: float) -> np.ndarray:
        """The body's position (m), shape (3,), `seconds` later on this conic (orbits.core.twobody.propagate)."""
        return propagate.propagate(*self.state, self.mu, seconds)[0]


def batch_shape(orbit: Any) -> tuple[int, ...]:
    """The shape of the batch of orbits an orbit-like object holds (its elements broadcast together)."""
    return np.broadcast_shapes(*(np.shape(getattr(orbit, name)) for name in ELEMENTS))


def conics_in(orbit: Any) -> list[Conic]:
    """Each orbit that an orbit-like object holds (in C order over its batch shape), as a Conic."""
    fields = np.broadcast_arrays(*(np.asarray(getattr(orbit, name), dtype=float) for name in ELEMENTS))
    return [Conic(*(float(field[index]) for field in fields)) for index in np.ndindex(fields[0].shape)]


def _is_orbit(item: Any) -> bool:
    return all(hasattr(item, name) for name in ELEMENTS)


def conic_points(p: float, e: float, r_max: float, samples: int = 721) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) in the perifocal frame (m) of the drawn part of the conic: the whole ellipse, or the arc of
    an open orbit within r_max of the focus."""
    if e < 1:
        nu = np.linspace(-np.pi, np.pi, samples)
    else:
        # 1 + e cos nu = p / r_max gives the true anomaly where the arc leaves the picture
        limit = np.arccos(np.clip((p / r_max - 1) / e, -1, 1))
        nu = np.linspace(-limit, limit, samples)
    r = p / (1 + e * np.cos(nu))
    return r * np.cos(nu), r * np.sin(nu)


def eccentricity_text(e: float) -> str:
    """e with the digits that matter, typeset: "1 + 6.4$\\times10^{-7}$" or "1 - $10^{-6}$" near a parabola, else
    4 digits."""
    if e != 1 and abs(e - 1) < 1e-3:
        return f"1 {'+' if e > 1 else '-'} {display.number_math(abs(e - 1), 2)}"
    return display.number(e, 4)


# ---- the primary at the focus --------------------------------------------------------------------------------


def catalogue_body(gm: Any) -> Body | None:
    """The catalogue Body drawn as the primary of orbits with this mu (m3/s2): its own GM within 2 %, so that the
    Sun is found under a Sun-Jupiter mu G (M_Sun + M_Jupiter) too (orbits._common.constants.body_with_gm); else None."""
    return body_with_gm(gm, tolerance=0.02)


def primary_body(primary: Any, gm: float | None) -> Body | None:
    """The Body drawn at the origin: `primary` (a Body or a catalogue name) or the catalogue body of GM."""
    if primary is None:
        return catalogue_body(gm)
    if isinstance(primary, str):
        return body(primary)
    return primary


def primary_color(primary: Body | None) -> str:
    """gold for a star, silver for a planet or moon (or an unnamed primary): colours outside matplotlib's cycle,
    so the primary never looks like one of the orbits (the cycle's C1 is orange)."""
    return "gold" if primary is not None and primary.kind == "star" else "silver"


def draw_primary(ax: Any, primary: Body | None, axes_index: tuple[int, ...], scale: float, size: float) -> None:
    """The primary at the origin: a disc (a sphere's outline in 3D) of its radius times `scale` (metres to the axis
    unit), and a star if that is under 1 % of the picture's half-size `size` (m)."""
    name = primary.name if primary is not None else "primary"
    radius = primary.radius * scale if primary is not None else 0.0
    tiny = radius < 0.01 * size * scale
    color = primary_color(primary)
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
                label=f"{name} (not to scale: radius {display.quantity_math(primary.radius << u.m, digits=3)})"
                if radius > 0 else name)


# ---- one orbit in its plane ----------------------------------------------------------------------------------


def orbit_plane(
    orbit: Any,
    times: u.Quantity | None = None,
    ax: Any = None,
    unit: u.UnitBase | None = None,
    label: str | None = None,
    primary: Any = None,
    epoch: Any = None,
) -> tuple[Any, Any]:
    """Draw a single orbit (an orbits.Orbit of shape ()) face on, in its own plane (perifocal frame: periapsis along
    +x, primary at the origin).

    The picture of `orbits` (the primary to scale and named, apsides where e > 1e-3, open and very long orbits
    within a window, a warning for a closest approach inside the primary, the legend outside, the title naming
    the orbit and the time of its position: `epoch` if given, else t0) for the same conic turned into the xy
    plane, with the centre and empty focus of an ellipse drawn whole and the body's positions at `times` (a time
    Quantity array) later, when given.
    """
    shape = batch_shape(orbit)
    if shape != ():
        raise ValueError(f"orbit_plane draws one orbit; this Orbit holds {shape} orbits: index it first")
    (conic,) = conics_in(orbit)
    flat = dataclasses.replace(conic, inc=0.0, raan=0.0, argp=0.0)
    seconds = [] if times is None else np.atleast_1d(units.to_si(times, units.S, "times"))
    later = [flat.position_after(dt) for dt in seconds]
    furthest = 1.05 * max((float(np.linalg.norm(r)) for r in later), default=0.0)  # the arc runs past each dot
    size = _extent([("", flat)], furthest)
    unit, _ = frame.length_unit(size, unit)
    drawn = draw_orbits(flat, ax=ax, labels=None if label is None else [label], unit=unit, primary=primary,
                        window=size << u.m if later else None, epoch=epoch, what=f"{_orbit_text(conic)} (face on)")
    ax, scale = drawn.axes, drawn.scale
    p, e = conic.p, conic.e
    whole = e < 1 and p / (1 - e) <= _LONG * p / (1 + e)
    if CIRCULAR < e < 1 and whole:
        c = e * p / (1 - e * e)
        ax.plot(-c * scale, 0, marker="+", ms=10, color="gray", ls="none", label="centre")
        ax.plot(-2 * c * scale, 0, marker="x", color="gray", ls="none", label="empty focus")
    if later:
        points = np.array(later) * scale
        after = display.summary(np.asarray(seconds, dtype=float) << u.s, digits=4)
        ax.plot(points[:, 0], points[:, 1], marker="d", ms=5, color="k", ls="none", alpha=0.7, gid="later",
                label=f"body {after} later")
    ax.set_xlabel(f"x toward periapsis [{display.unit_math(unit)}]")
    ax.set_ylabel(f"y, along the motion at periapsis [{display.unit_math(unit)}]")
    frame.legend_beside(ax)
    drawn.retitle()
    return drawn.figure, ax


# ---- several orbits and trajectories in one frame ------------------------------------------------------------


@dataclass(frozen=True)
class Drawing:
    """What draw_orbits chose and drew, for a picture that adds to it: the figure and axes, the length unit of the
    axes and the factor taking metres to it, the curve of each orbit or trajectory in the order given (an array of
    orbits gives one per orbit), the notes on closest approaches inside the primary, and the title (its lines,
    the notes last; a picture that widens the legend sets it again: frame.title wraps to the room left)."""

    figure: Any
    axes: Any
    unit: u.UnitBase
    scale: float
    curves: tuple[Any, ...]
    notes: tuple[str, ...]
    title: str

    def retitle(self) -> None:
        """Set the title again, wrapped to the room the axes have now (red when there are notes)."""
        frame.title(self.axes, self.title, color="C3" if self.notes else "k")


def orbits(
    *items: Any,
    ax: Any = None,
    projection: str = "xy",
    primary: Any = None,
    labels: Sequence[str] | None = None,
    unit: u.UnitBase | None = None,
    window: u.Quantity | None = None,
    epoch: Any = None,
) -> tuple[Any, Any]:
    """Draw any number of Orbits (arrays of orbits included) and trajectories ((n, 3) length Quantities, e.g.
    from an integrator) about one primary, in its inertial frame, each in its own colour.

    The primary is a disc to scale (a Body or a catalogue name, else the catalogue body of the first orbit's GM;
    a star marks it where the disc would be too small to see). projection: "xy", "xz", "yz" or "3d" (then `ax`,
    if given, must be a 3D Axes). Ellipses are drawn whole, open orbits (and ellipses with Q > 100 q) only out to
    the picture's half-size `window` (default: the largest closed orbit or trajectory, or 10 q). Periapsis
    (and apoapsis) are marked where e > 1e-3; each body's position at the orbit's true anomaly is a dot, "at t0"
    or, given the `epoch` of the elements (an astropy Time or ISO string), at that date. The title names the
    orbits and that time; a closest approach inside the primary gives an InsideBodyWarning and a note in red
    under it. The legend sits outside the axes.
    """
    drawn = draw_orbits(*items, ax=ax, projection=projection, primary=primary, labels=labels, unit=unit,
                        window=window, epoch=epoch)
    return drawn.figure, drawn.axes


def draw_orbits(
    *items: Any,
    ax: Any = None,
    projection: str = "xy",
    primary: Any = None,
    labels: Sequence[str] | None = None,
    unit: u.UnitBase | None = None,
    window: u.Quantity | None = None,
    epoch: Any = None,
    what: str | None = None,
) -> Drawing:
    """The picture of `orbits` (same arguments), returned with what it chose: a Drawing. `what` replaces the
    title's account of what is drawn (the time of the positions follows it)."""
    if projection not in PROJECTIONS:
        raise ValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")
    entries = _items(items, labels)
    if not entries:
        raise ValueError("give at least one Orbit or trajectory to draw")
    axes_index = PROJECTIONS[projection]
    fig, ax = frame.axes_for(ax, projection)
    gm = next((item.mu for _, item in entries if isinstance(item, Conic)), None)
    focus = primary_body(primary, gm)
    size = _extent(entries, 0.0 if window is None else units.to_si(window, units.M, "window"))
    unit, scale = frame.length_unit(size, unit)
    when = "t0" if epoch is None else frame.date_text(positions.epoch(epoch))
    marked, notes, curves = set(), [], []
    for (label, item), color in zip(entries, frame.colors(len(entries))):
        if isinstance(item, Conic):
            track, whole = _conic_track(item, size)
            closest = item.periapsis
        else:
            track, whole = item, False
            closest = float(np.min(np.linalg.norm(item, axis=1)))
        curves.append(ax.plot(*(track[:, i] * scale for i in axes_index), color=color, lw=1.4, label=label)[0])
        if isinstance(item, Conic):
            _mark_orbit(ax, item, color, axes_index, scale, marked, whole)
        if focus is not None and closest < focus.radius:
            notes.append(_inside_note(label, closest, focus))
    draw_primary(ax, focus, axes_index, scale, size)
    _marker_legend(ax, marked, len(axes_index), when)
    _finish_frame(ax, projection, unit)
    for note in notes:
        warnings.warn(note(display.quantity_text), InsideBodyWarning, stacklevel=3)
    about = [what or _what(entries, focus, labels)]
    if "position" in marked:
        about.append(f"{'the body' if len(entries) == 1 else 'each body'} at {when}")
    shown = [note(display.quantity_math) for note in notes]
    drawing = Drawing(fig, ax, unit, scale, tuple(curves), tuple(shown), "\n".join([*about, *shown]))
    drawing.retitle()
    return drawing


def _inside_note(label: str, closest: float, focus: Body):
    """The note on a closest approach (m) inside the primary, written with a quantity formatter of
    orbits._common.display
    (quantity_text for the warning, quantity_math for the title)."""
    return lambda written: (f"{label}: closest approach {written(closest << u.m, digits=4)} is inside {focus.name} "
                            f"(radius {written(focus.radius << u.m, digits=4)})")


def _orbit_text(conic: Conic) -> str:
    """"Orbit about Earth: a = 26600 km, e = 0.74, i = 63.4 deg": one conic as a title names it (its primary as
    the picture draws it: the catalogue body within 2 % of its GM, so a planet's heliocentric orbit, whose mu
    holds the planet's mass too, is about the Sun)."""
    known = catalogue_body(conic.mu)
    name = frame.in_a_sentence(known.name) if known is not None else display.body_name(conic.mu)
    tilt = f", i = {display.quantity_math(conic.inc << u.rad, digits=4)}" if conic.inc else ""
    return f"{'Orbit' if conic.e < 1 else 'Trajectory'} about {name}: {_size_text(conic)}{tilt}"


def _what(entries: list, focus: Body | None, labels: Sequence[str] | None) -> str:
    """What the title says is drawn: one orbit in full, else the few labelled ones by name, else how many orbits
    and trajectories, about what."""
    about = f" about {focus.name}" if focus is not None else ""
    if len(entries) == 1 and isinstance(entries[0][1], Conic) and labels is None:
        return _orbit_text(entries[0][1])
    if labels is not None and len(entries) == len(labels) <= 4:
        return ", ".join(labels[:-1]) + (" and " if len(labels) > 1 else "") + labels[-1] + about
    conics = sum(isinstance(item, Conic) for _, item in entries)
    parts = [f"{conics} orbit{'s' if conics > 1 else ''}" if conics else "",
             f"{len(entries) - conics} trajectories" if len(entries) - conics > 1 else
             ("1 trajectory" if len(entries) > conics else "")]
    return " and ".join(part for part in parts if part) + about


def _items(items, labels):
    """[(label, Conic or (n, 3) array in m)]: arrays of orbits split, Quantities of positions converted."""
    out = []
    for k, item in enumerate(items):
        given = None if labels is None else labels[k]
        if _is_orbit(item):
            flat = conics_in(item)
            for j, one in enumerate(flat):
                name = given if len(flat) == 1 else f"{given or 'orbit'} [{j}]: {_size_text(one)}"
                out.append((name or f"orbit, e = {eccentricity_text(one.e)}", one))
        else:
            track = np.asarray(units.to_si(item, units.M, "trajectory positions"), dtype=float)
            if track.ndim != 2 or track.shape[1] != 3:
                raise ValueError(f"a trajectory is a length Quantity of shape (n, 3); got shape {track.shape}")
            out.append((given or f"trajectory {k + 1}", track))
    return out


def _size_text(conic):
    """"a = 7000 km, e = 0.1" (q for an open orbit): what tells one orbit of an array from the others."""
    e = conic.e
    size = twobody.semi_major_axis(conic.p, e) if e < 1 else twobody.periapsis_distance(conic.p, e)
    return f"{'a' if e < 1 else 'q'} = {display.quantity_math(size << u.m, digits=7)}, e = {eccentricity_text(e)}"


def _extent(entries, times_window):
    """The picture's half-size (m): the largest whole ellipse, trajectory or current position, and at least
    10 q of every open or very long orbit."""
    size = 0.0
    for _, item in entries:
        if isinstance(item, Conic):
            p, e = item.p, item.e
            q = p / (1 + e)
            closed = e < 1 and p / (1 - e) <= _LONG * q
            size = max(size, p / (1 - e) if closed else 10 * q, item.radius)
        else:
            size = max(size, float(np.max(np.linalg.norm(item, axis=1))))
    return max(size, times_window)


def _conic_track(conic, window):
    """(points (n, 3) in m, closed) of one Conic: the whole ellipse, or the arc within `window` m of the focus
    for an open orbit or a very long ellipse (Q > 100 q)."""
    p, e = conic.p, conic.e
    q = p / (1 + e)
    whole = e < 1 and p / (1 - e) <= max(_LONG * q, window)
    if whole:
        nu = np.linspace(-np.pi, np.pi, 721)
    else:
        limit = np.arccos(np.clip((p / window - 1) / e, -1, 1))  # 1 + e cos nu = p / window
        if e >= 1:
            limit = min(limit, np.arccos(-1 / e) * (1 - 1e-9))  # inside the asymptotes
        nu = np.linspace(-limit, limit, 721)
    r, _ = elements.elements_to_state(p, e, conic.inc, conic.raan, conic.argp, nu, conic.mu)
    return r, whole


def _apsides(conic):
    """{"periapsis": r (3,), "apoapsis": r (3,) for an ellipse} in m."""
    angles = [0.0, np.pi] if conic.e < 1 else [0.0]
    r, _ = elements.elements_to_state(conic.p, conic.e, conic.inc, conic.raan, conic.argp, np.array(angles),
                                      conic.mu)
    return dict(zip(("periapsis", "apoapsis"), r))


def _mark_orbit(ax, conic, color, axes_index, scale, marked, whole):
    """Apsides (where e > 1e-3; the apoapsis only on a whole ellipse) and the body's position at its true anomaly,
    in the orbit's colour."""
    if conic.e > CIRCULAR:
        for name, point in _apsides(conic).items():
            if name == "apoapsis" and not whole:
                continue
            marked.add(name)
            ax.plot(*([point[i] * scale] for i in axes_index), marker=_MARKERS[name], ms=6, mfc="none", color=color,
                    ls="none", gid=name)
    now, _ = conic.state
    marked.add("position")
    ax.plot(*([now[i] * scale] for i in axes_index), marker=_MARKERS["position"], ms=9, color=color, ls="none",
            gid="position")


def _marker_legend(ax, marked, dimensions, when):
    """One gray legend entry per kind of marker drawn (the markers themselves take their orbit's colour); the
    positions are those at `when` ("t0" or a date)."""
    for name in ("periapsis", "apoapsis", "position"):
        if name in marked:
            ax.plot(*([] for _ in range(dimensions)), marker=_MARKERS[name], ms=6, color="0.3", ls="none",
                    mfc="none" if name != "position" else "0.3",
                    label=name if name != "position" else f"body at {when}")


def _finish_frame(ax, projection, unit):
    """Axis labels with the unit (clear of the tick labels in 3-D), equal scales, grid, and the legend outside
    the axes on the right."""
    names = [_AXES[i] for i in PROJECTIONS[projection]]
    text = display.unit_math(unit)
    pad = {"labelpad": 18} if projection == "3d" else {}
    ax.set_xlabel(f"{names[0]} [{text}]", **pad)
    ax.set_ylabel(f"{names[1]} [{text}]", **pad)
    if projection == "3d":
        ax.set_zlabel(f"{names[2]} [{text}]", **pad)
        ax.set_box_aspect((1, 1, 1), zoom=0.9)  # the labels inside the figure
        _equal_3d(ax)
    else:
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
    frame.legend_beside(ax)


def _equal_3d(ax):
    """Give the three axes of a 3D view the same span, centred on the data."""
    limits = np.array([ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d()])
    centre, half = limits.mean(axis=1), (limits[:, 1] - limits[:, 0]).max() / 2
    ax.set_xlim3d(centre[0] - half, centre[0] + half)
    ax.set_ylim3d(centre[1] - half, centre[1] + half)
    ax.set_zlim3d(centre[2] - half, centre[2] + half)
