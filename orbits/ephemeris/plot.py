"""The solar system at a date: the planets (and Pluto) on their osculating heliocentric orbits, read from the
ephemeris once per body, drawn by orbits.twobody.plot in the ecliptic frame of J2000."""

from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame
from orbits._common.constants import AU
from orbits.core import frames
from orbits.ephemeris import positions as ephemeris
from orbits.twobody.plot import PROJECTIONS, Conic, draw_orbits

SOLAR_SYSTEM = {
    "inner": ("Mercury", "Venus", "Earth", "Mars"),
    "outer": ("Jupiter", "Saturn", "Uranus", "Neptune", "Pluto"),
}
SOLAR_SYSTEM["all"] = SOLAR_SYSTEM["inner"] + SOLAR_SYSTEM["outer"]
#: points of the ephemeris drawn as the planet they stay next to at this scale
_DRAWN_AS = {"Moon": "Earth", "Earth-Moon barycentre": "Earth", "solar system barycentre": "Sun"}


def solar_system_part(body: str) -> str:
    """The part of solar_system that shows `body` (a planet, Pluto, the Moon, a barycentre or a body of
    ephemeris.PROPAGATED): "inner" for Mercury-Mars, the Earth-Moon pair and the asteroids (drawn with them), "all"
    for Jupiter-Pluto and Eris (so the Earth is in the picture too)."""
    name = _DRAWN_AS.get(ephemeris.point_name(body), ephemeris.point_name(body))
    if name in ephemeris.PROPAGATED:
        from orbits.ephemeris.catalogue import mean_elements

        return "inner" if mean_elements(name).a < 5.0 * AU else "all"
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
    states: dict | None = None,
) -> tuple[Any, Any]:
    """Draw the planets (and Pluto for "outer" and "all") on their osculating heliocentric orbits at `epoch`, in
    the ecliptic frame of J2000, each body's position at the epoch a dot with its name beside it where the name
    fits, and the Sun at the centre.

    Parameters
    ----------
    epoch : astropy Time or ISO string (read as UTC unless it names its scale; see orbits.ephemeris.positions.epoch)
    which : "inner" (Mercury-Mars), "outer" (Jupiter-Pluto) or "all"; "all" in the plane and on a figure of its
        own draws a second panel beside the first, the inner planets enlarged (they crowd round the Sun at the
        scale of Pluto's orbit)
    projection : "xy" (the ecliptic seen from its north pole), "xz", "yz" or "3d"
    highlight : a body drawn with a thick orbit and a bold label (the Moon and the Earth-Moon barycentre are
        drawn as the Earth; an asteroid or dwarf planet of ephemeris.PROPAGATED is drawn beside the planets)
    observer : with `highlight`, a body from which a dashed line of sight is drawn to it
    source : the ephemeris, "auto", "de421" or "builtin" (astropy's, which has no Pluto: Pluto is then left out
        and the title says so)
    states : heliocentric BodyStates at `epoch` already read (ephemeris.states(..., center="Sun")) holding every
        body of `solar_system_points`: nothing is read again

    The orbits are those of `Orbit.from_body(name, epoch)` (orbits.ephemeris.positions.osculating) drawn by `orbits`
    (the
    first time each orbit passes through the body's position); the title gives the date in TDB and the ephemeris
    that answered. DE421 gives Jupiter-Pluto as system barycentres, and the title says so. Returns the figure
    and the axes of the whole picture (the enlarged inner planets are the figure's second axes). Tested in
    tests/api/test_plot_and_display.py (the dots equal astropy's reading of DE421, rotated to the ecliptic, to
    1e-9 AU).
    """
    when = ephemeris.epoch(epoch)
    resolved = ephemeris.resolve_source(source)
    names, missing = _drawn(which, resolved)
    target = None if highlight is None else _DRAWN_AS.get(ephemeris.point_name(highlight),
                                                          ephemeris.point_name(highlight))
    names += [target] if target in ephemeris.PROPAGATED and target not in names else []
    if target is not None and target not in (*names, "Sun"):
        raise ValueError(f"{highlight} is not drawn in the {which} solar system ({', '.join(names)})")
    seer = None if target is None or observer is None else ephemeris.point_name(observer)
    sighted = seer is not None and seer != target
    elsewhere = [seer] if sighted and seer not in (*names, "Sun") else []  # an observer not drawn
    if states is None:
        seen = ephemeris.states([*names, *elsewhere], when, "Sun", source=resolved)  # each body read once
    else:
        seen = {ephemeris.point_name(name): state for name, state in states.items()}
        absent = [name for name in (*names, *elsewhere) if name not in seen]
        if absent:
            raise ValueError(f"states lacks {', '.join(absent)}: give every body of solar_system_points")
    conics = [Conic.from_state(problem.r, problem.v, problem.mu)
              for problem in (ephemeris.osculating(seen[name]) for name in names)]
    enlarged = which == "all" and ax is None and projection != "3d"
    if enlarged:
        import matplotlib.pyplot as plt

        fig, (ax, inner) = plt.subplots(1, 2, figsize=(13.0, 6.6), layout="constrained")
    shown = None if highlight is None else ephemeris.point_name(highlight)
    sight = (seer, target, elsewhere, seen) if sighted else None
    drawn = _draw_part(ax, names, conics, projection, when, target, shown, sight,
                       named=[n for n in names if not enlarged or n not in SOLAR_SYSTEM["inner"]])
    ax = drawn.axes
    inner_names = list(SOLAR_SYSTEM["inner"])
    if enlarged:
        _draw_part(inner, inner_names, conics[:len(inner_names)], projection, when, target, shown, sight,
                   named=inner_names)
        for panel in (ax, inner):  # one legend, beside the second panel, for both
            panel.get_legend().remove()
        inner.legend(*ax.get_legend_handles_labels(), loc="upper left", bbox_to_anchor=(1.02, 1.0),
                     fontsize="small", frameon=False)
        frame.title(ax, f"out to {next(n for n in ('Eris', 'Pluto', 'Neptune') if n in names)}")
        frame.title(inner, "the inner planets")
    lines = [f"The {'' if which == 'all' else which + ' '}solar system on {frame.date_text(ephemeris.epoch(when))} "
             f"(ecliptic of J2000)", f"positions: {ephemeris.provenance(*(seen[name] for name in names))[0]}"]
    systems = [name for name in names if seen[name].point != name]
    if systems:
        lines.append(f"{_names(systems)}: {'the' if len(systems) > 1 else 'its'} system "
                     f"barycentre{'s' if len(systems) > 1 else ''} (planet and moons)")
    if missing:
        lines.append(f"left out: {', '.join(missing)}")
    lines += list(drawn.notes)  # a closest approach inside the Sun, if any, stays in the title
    if enlarged:
        frame.title(fig, "\n".join(lines))
    else:
        frame.title(ax, "\n".join(lines))
    return drawn.figure, ax


def _draw_part(ax, names, conics, projection, when, target, shown, sight, named):
    """The orbits of `names` on `ax` (a new figure if None), the target's orbit thick, the line of sight, and the
    names of `named` beside their dots where they fit (the target's first, in bold). Returns the Drawing."""
    drawn = draw_orbits(*conics, ax=ax, projection=projection, primary="Sun", labels=names, epoch=when)
    ax, scale = drawn.axes, drawn.scale
    axes_index = PROJECTIONS[projection]
    positions = {name: conic.state[0] * scale for name, conic in zip(names, conics)}
    if target in names:
        drawn.curves[names.index(target)].set_linewidth(3.0)
    if sight is not None:
        seer, _, elsewhere, seen = sight
        ends = dict(positions, Sun=np.zeros(3))
        for name in elsewhere:
            ends[name] = frames.equatorial_to_ecliptic(seen[name].r_si) * scale
        if target in ends and seer in ends:
            _line_of_sight(ax, seer, target, ends, axes_index)
    order = sorted((name for name in named if name in positions), key=lambda name: name != target)
    labels = [(f"{shown} (at {name})" if name == target and shown != target else name,  # "Moon (at Earth)"
               [positions[name][i] for i in axes_index], dict(fontsize="small", gid="name",
                                                              fontweight="bold" if name == target else "normal"))
              for name in order]
    frame.labels_apart(ax, labels)
    return drawn


def _names(names: list[str]) -> str:
    """"Jupiter", "Jupiter and Saturn", "Jupiter to Pluto" (a run of the drawn order)."""
    if len(names) > 2:
        return f"{names[0]} to {names[-1]}"
    return " and ".join(names)


def _drawn(which: str, resolved: str) -> tuple[list[str], list[str]]:
    """(the bodies drawn for `which` from the resolved source, what is left out and why)."""
    if which not in SOLAR_SYSTEM:
        raise ValueError(f"which {which!r} is not one of {', '.join(SOLAR_SYSTEM)}")
    names = list(SOLAR_SYSTEM[which])
    if resolved == "builtin" and "Pluto" in names:
        return [n for n in names if n != "Pluto"], ["Pluto (not in astropy's built-in ephemeris)"]
    return names, []


def solar_system_points(which: str = "inner", *, highlight: str | None = None, observer: str | None = None,
                        source: str = "auto") -> list[str]:
    """The bodies whose heliocentric states `solar_system` reads (the drawn planets and an observer not drawn), so
    that a caller reading them for itself can pass them in."""
    names, _ = _drawn(which, ephemeris.resolve_source(source))
    target = None if highlight is None else _DRAWN_AS.get(ephemeris.point_name(highlight),
                                                          ephemeris.point_name(highlight))
    names += [target] if target in ephemeris.PROPAGATED and target not in names else []
    seer = None if target is None or observer is None else ephemeris.point_name(observer)
    if seer is not None and seer != target and seer not in (*names, "Sun"):
        names.append(seer)
    return names


def _line_of_sight(ax, seer, target, positions, axes_index):
    """A dashed line from the observer (drawn or not) to the target."""
    ends = np.stack([positions[seer], positions[target]])
    ax.plot(*(ends[:, i] for i in axes_index), color="0.3", ls="--", lw=1.0, gid="line of sight",
            label=f"line of sight from {seer}")
    frame.legend_beside(ax)


def sky_chart(epoch: Any, body: str, observer: str = "Earth", *, which: str | None = None, source: str = "auto",
              states: dict | None = None, ax: Any = None) -> tuple[Any, Any]:
    """The sky seen from `observer` at `epoch`: right ascension (hours, growing to the left, as the sky is seen
    facing south) against declination (deg), geometric ICRF directions, with the ecliptic, the Sun, `body` marked
    and named with its elongation, and the other planets of solar_system_part(body) (or `which`) where they stand.

    `states` are heliocentric states {name: BodyState} (ephemeris.states(..., "Sun")) of at least `body`,
    `observer` and the planets drawn, as solar_system_points(which, highlight=body, observer=observer) names them:
    a caller that has read them passes them in, and nothing is read twice. Returns (figure, axes)."""
    which = solar_system_part(body) if which is None else which
    target, seer = ephemeris.point_name(body), ephemeris.point_name(observer)
    names = [n for n in solar_system_points(which, highlight=body, observer=observer, source=source)
             if n not in (target, seer)]
    if states is None:
        when = ephemeris.epoch(epoch)
        states = ephemeris.states([target, seer, *names], when, "Sun", source=source)
    else:
        when = states[target].epoch
    here = np.asarray(states[seer].r_si, dtype=float)
    fig, ax = frame.axes(ax, figsize=(10.0, 5.6))
    longitude = np.radians(np.linspace(0.0, 360.0, 721))
    ecliptic = frames.ecliptic_to_equatorial(np.stack([np.cos(longitude), np.sin(longitude), 0 * longitude], -1))
    hours, dec = _ra_dec(ecliptic)
    breaks = np.flatnonzero(np.abs(np.diff(hours)) > 12.0) + 1  # no line across the chart where RA wraps
    for k, (h, d) in enumerate(zip(np.split(hours, breaks), np.split(dec, breaks))):
        ax.plot(h, d, color="0.55", lw=1.0, ls="--", label="the ecliptic" if k == 0 else "_ecliptic")
    labels = []
    sun_h, sun_d = _ra_dec(-here)
    ax.plot(sun_h, sun_d, marker="o", ms=14, color="#f2c744", mec="0.3", ls="none", label="the Sun")
    labels.append(("Sun", (float(sun_h), float(sun_d)), dict(fontsize="small")))
    for name in names:
        h, d = _ra_dec(np.asarray(states[name].r_si, dtype=float) - here)
        ax.plot(h, d, marker="o", ms=5, color="0.35", ls="none", label="_planet")
        labels.append((name, (float(h), float(d)), dict(fontsize="x-small", color="0.3")))
    seen = ephemeris.sighting(states, target, seer)
    h, d = _ra_dec(np.asarray(states[target].r_si, dtype=float) - here)
    elongation = display.quantity_math(seen.elongation.to(u.deg), digits=4)
    ax.plot(h, d, marker="o", ms=9, color="C3", mec="k", ls="none", label=f"{target}: elongation {elongation}")
    labels.append((target, (float(h), float(d)), dict(fontsize="medium", fontweight="bold", color="C3")))
    ax.plot([], [], marker="o", ms=5, color="0.35", ls="none", label="the other planets")
    ax.set_xlim(24.0, 0.0)
    ax.set_ylim(-90.0, 90.0)
    ax.set_xticks(np.arange(24.0, -0.1, -3.0))
    ax.set_yticks(np.arange(-90.0, 90.1, 30.0))
    ax.set_xlabel("right ascension [h] (ICRF, geometric)")
    ax.set_ylabel("declination [deg]")
    ax.grid(alpha=0.3)
    frame.legend_outside(ax, columns=2)
    frame.labels_apart(ax, labels)
    frame.title(ax, f"The sky from {seer} on {frame.date_text(when)}: {target} among the planets")
    return fig, ax


def _ra_dec(direction: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(right ascension in hours in [0, 24), declination in deg) of ICRF direction(s) (..., 3), any length."""
    direction = np.asarray(direction, dtype=float)
    hours = np.degrees(np.arctan2(direction[..., 1], direction[..., 0])) % 360.0 / 15.0
    dec = np.degrees(np.arctan2(direction[..., 2], np.hypot(direction[..., 0], direction[..., 1])))
    return hours, dec
