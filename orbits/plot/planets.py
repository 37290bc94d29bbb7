"""The solar system at a date: the planets (and Pluto) on their osculating heliocentric orbits, read from the
ephemeris once per body, drawn by orbits.plot.conics in the ecliptic frame of J2000."""

from typing import Any

import numpy as np

from orbits import ephemeris
from orbits.core import frames
from orbits.plot import frame
from orbits.plot.conics import PROJECTIONS, Conic, draw_orbits

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
    states: dict | None = None,
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
    states : heliocentric BodyStates at `epoch` already read (ephemeris.states(..., center="Sun")) holding every
        body of `solar_system_points`: nothing is read again

    The orbits are those of `Orbit.from_body(name, epoch)` (orbits.ephemeris.osculating) drawn by `orbits` (the
    first time each orbit passes through the body's position); the title gives the date in TDB and the ephemeris
    that answered. DE421 gives Jupiter-Pluto as system barycentres, and their legend entries say so. Tested in
    tests/api/test_plot_and_display.py (the dots equal astropy's reading of DE421, rotated to the ecliptic, to
    1e-9 AU).
    """
    when = ephemeris.epoch(epoch)
    resolved = ephemeris.resolve_source(source)
    names, missing = _drawn(which, resolved)
    target = None if highlight is None else _DRAWN_AS.get(ephemeris.point_name(highlight),
                                                          ephemeris.point_name(highlight))
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
    drawn = draw_orbits(*conics, ax=ax, projection=projection, primary="Sun", labels=[seen[n].point for n in names])
    ax, scale = drawn.axes, drawn.scale
    axes_index = PROJECTIONS[projection]
    if target is not None and target not in (*names, "Sun"):
        raise ValueError(f"{highlight} is not drawn in the {which} solar system ({', '.join(names)})")
    positions = {name: conic.state[0] * scale for name, conic in zip(names, conics)}
    shown = None if highlight is None else ephemeris.point_name(highlight)
    for name in _uncrowded(positions, axes_index, target):
        text = f"{shown} (at {name})" if name == target and shown != target else name  # "Moon (at Earth)"
        _label_point(ax, positions[name], axes_index, text, bold=name == target)
    if target in names:
        drawn.curves[names.index(target)].set_linewidth(3.0)
    if sighted:
        positions["Sun"] = np.zeros(3)
        for name in elsewhere:
            positions[name] = frames.equatorial_to_ecliptic(seen[name].r_si) * scale
        _line_of_sight(ax, seer, target, positions, axes_index)
    title = f"The {'' if which == 'all' else which + ' '}solar system on {when.tdb.iso[:16]} TDB (ecliptic J2000)"
    title += f"\npositions: {seen[names[0]].source}"
    if missing:
        title += f"\nleft out: {', '.join(missing)}"
    notes = "\n".join(drawn.notes)  # a closest approach inside the Sun, if any, stays in the title
    ax.set_title(title + (f"\n{notes}" if notes else ""), fontsize="medium")
    return drawn.figure, ax


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
    seer = None if target is None or observer is None else ephemeris.point_name(observer)
    if seer is not None and seer != target and seer not in (*names, "Sun"):
        names.append(seer)
    return names


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


def _line_of_sight(ax, seer, target, positions, axes_index):
    """A dashed line from the observer (drawn or not) to the target."""
    ends = np.stack([positions[seer], positions[target]])
    ax.plot(*(ends[:, i] for i in axes_index), color="0.3", ls="--", lw=1.0, gid="line of sight",
            label=f"line of sight from {seer}")
    frame.legend_beside(ax)
