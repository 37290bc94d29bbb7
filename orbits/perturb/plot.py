"""Pictures of perturbed orbits: an oblate body's secular motion (secular_elements: the node and the argument of
periapsis of integrations over the closed form's secular lines), a frozen orbit (frozen_eccentricity: the mean
eccentricity vectors of a frozen and a circular start circling the frozen point), the Kozai-Lidov cycles
(kozai_cycles: e, i and the conserved sqrt(1 - e**2) cos i of integrations with the quadrupole theory's marks) and
drag decay (drag_decay: altitude against time, the closed form's curve, where it stops holding, and integrations
over it).

Each reads what it is given: a record of integrations (orbits.validate.histories' SecularHistory, FrozenHistory,
KozaiHistory or DecayHistory) or a DragDecay, through their attributes; nothing here integrates.
"""

import math
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame

#: how each backend's curves look: (colour, line style of the osculating curve, marker of the means)
BACKEND_STYLES = {"rebound": ("C0", "-", "o"), "heyoka": ("C1", "--", "x")}
#: the closed form's curves and marks
THEORY_COLOR = "0.15"
#: each element's name on an axis
ELEMENT_LABELS = {"node": r"node $\Omega$", "periapsis": r"argument of periapsis $\omega$"}
ELEMENT_SYMBOLS = {"node": r"\Omega", "periapsis": r"\omega"}
#: the time axis of a decay: (unit, its label, for lifetimes below this)
TIME_UNITS = ((u.h, "h", 2 * u.day), (u.day, "d", 1000 * u.day), (u.year, "yr", np.inf * u.year))


def _style(backend: str, k: int) -> tuple[str, str, str]:
    return BACKEND_STYLES.get(backend, (f"C{k + 2}", ":", "+"))


def _legend_below(figure: Any, axes: np.ndarray, columns: int = 3) -> None:
    """One legend for all panels, below them, each entry once (in the order first drawn)."""
    entries = {}
    for ax in np.ravel(axes):
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(label, handle)
    figure.legend(list(entries.values()), list(entries), loc="outside lower center", ncol=min(columns, len(entries)),
                  fontsize="small", frameon=False)


# ---- an oblate body's secular motion -------------------------------------------------------------------------
def secular_elements(history: Any, figure: Any = None) -> tuple[Any, np.ndarray]:
    """The node Omega (and the argument of periapsis omega, where the history has it) against time, as each backend
    integrates the orbit (thin: osculating; markers: the average over each revolution), over the straight line of
    the first-order closed form; beside each, the revolution averages less that line (arcsec), which show the
    theory's own error, O(J2 (R/p)**2) of the rate. `history` is a SecularHistory (orbits.validate.histories).
    Returns (figure, (rows, 2) array of panels)."""
    names = list(history.lines)
    figure = frame.figure(figure, (11.0, 2.9 * len(names) + 1.9))
    panels = figure.subplots(len(names), 2, sharex=True, squeeze=False, width_ratios=(3, 2))
    for row, name in zip(panels, names, strict=True):
        _element_panels(row, history, name)
    for ax in panels[-1]:
        ax.set_xlabel("time [d]")
    panels[0, 0].set_title("integrated (osculating and revolution means) over the closed form", fontsize="medium")
    panels[0, 1].set_title(f"revolution means less the closed form\n(first order: O(J2 (R/p)$^2$) = "
                           f"{display.number_math(history.accuracy, 2)} of the rate)", fontsize="medium")
    moving = " and ".join(ELEMENT_LABELS[name].split(" $")[0] for name in names)
    figure.suptitle(f"The {moving} under J2 and J4: rebound and heyoka over the secular closed form\n"
                    f"{history.title}")
    _legend_below(figure, panels)
    return figure, panels


def _element_panels(row: np.ndarray, history: Any, name: str) -> None:
    """One element: its values over the closed form's line (left) and the means less the line (right)."""
    left, right = row
    start, rate = history.lines[name]
    times = np.asarray(history.times, dtype=float)
    span = np.array([0.0, times[-1]])
    left.plot(span, start + rate * span, color=THEORY_COLOR, lw=1.4, zorder=3,
              label=f"closed form: first-order J2 rates ({'+' if rate > 0 else ''}{display.number_math(rate, 4)} deg/d "
              f"for ${ELEMENT_SYMBOLS[name]}$ here)"
              if len(history.lines) == 1 else "closed form: first-order J2 rates")
    right.axhline(0.0, color=THEORY_COLOR, lw=1.4, zorder=1)
    mean_times = np.asarray(history.mean_times, dtype=float)
    line_at_means = start + rate * mean_times
    for k, backend in enumerate(history.osculating):
        color, dashes, marker = _style(backend, k)
        left.plot(times, history.osculating[backend][name], color=color, ls=dashes, lw=0.7, alpha=0.8, zorder=1,
                  label=f"{backend}: osculating")
        left.plot(mean_times, history.mean[backend][name], color=color, ls="none", marker=marker, ms=5,
                  mfc="none", zorder=2, label=f"{backend}: mean over each revolution")
        right.plot(mean_times, (np.asarray(history.mean[backend][name]) - line_at_means) * 3600.0, color=color,
                   ls=dashes, lw=0.8, marker=marker, ms=5, mfc="none", zorder=2)
    left.set_ylabel(f"{ELEMENT_LABELS[name]} [deg]")
    left.ticklabel_format(axis="y", useOffset=False)
    right.set_ylabel(f"${ELEMENT_SYMBOLS[name]}$ less the line [arcsec]")
    for ax in row:
        ax.grid(alpha=0.3)


# ---- the Kozai-Lidov cycles ----------------------------------------------------------------------------------
def kozai_cycles(history: Any, figure: Any = None) -> tuple[Any, np.ndarray]:
    """The eccentricity, the inclination and sqrt(1 - e**2) cos i against time (units of the Kozai timescale tau)
    as each backend integrates a hierarchical triple, with the quadrupole theory's marks: e_max, the inclination
    at e_max that the conserved sqrt(1 - e**2) cos i gives, that conserved value, and the times of e_max (half a
    period, then every period, from a start at e_min; none marked from a start between e_min and e_max).
    `history` is a KozaiHistory (orbits.validate.histories). Returns (figure, array of the three panels)."""
    figure = frame.figure(figure, (9.6, 8.6))
    panels = figure.subplots(3, 1, sharex=True)
    times = np.asarray(history.times, dtype=float)
    e_ax, i_ax, c_ax = panels
    for k, backend in enumerate(history.eccentricity):
        color, dashes, _ = _style(backend, k)
        for ax, values in zip(panels, (history.eccentricity, history.inclination, history.constant), strict=True):
            ax.plot(times, values[backend], color=color, ls=dashes, lw=0.9 if ax is not c_ax else 0.5,
                    alpha=1.0 if ax is not c_ax else 0.45, label=f"{backend} (osculating)")
        c_ax.plot(history.mean_times, history.mean_constant[backend], color=color, ls=dashes, lw=2.0,
                  label=f"{backend}, averaged over each orbit of the perturber")
    e_ax.axhline(history.e_max, color=THEORY_COLOR, ls="--", lw=1.0,
                 label=f"quadrupole: $e_{{max}}$ = {display.number(history.e_max, 4)}, i = "
                       f"{display.number(history.inclination_at_e_max, 4)}$\\degree$ there")
    i_ax.axhline(history.inclination_at_e_max, color=THEORY_COLOR, ls="--", lw=1.0)
    c_ax.axhline(history.start, color=THEORY_COLOR, ls="-.", lw=1.0,
                 label=f"quadrupole: $\\sqrt{{1-e^2}}\\,\\cos i$ conserved at its start, "
                       f"{display.number(history.start, 4)}")
    first = history.first_peak
    peaks = np.empty(0) if first is None else np.arange(first, times[-1] + history.period, history.period)
    for j, peak in enumerate(peaks[peaks <= times[-1]]):
        for ax in panels:
            ax.axvline(peak, color="0.5", ls=":", lw=1.0,
                       label=f"quadrupole: $e_{{max}}$ every period, {display.number(history.period, 4)} $\\tau$"
                       if j == 0 and ax is e_ax else None)
    e_ax.set_ylabel("eccentricity e")
    i_ax.set_ylabel(r"inclination i [$\degree$]")
    c_ax.set_ylabel(r"$\sqrt{1-e^2}\,\cos i$")
    c_ax.set_xlabel(r"time [Kozai timescales $\tau$]")
    for ax in panels:
        ax.grid(alpha=0.3)
    figure.suptitle(f"Kozai-Lidov cycles: rebound and heyoka with the quadrupole theory's marks\n{history.title}\n"
                    f"(the doubly averaged theory drops terms of relative size $\\epsilon_{{sa}}$ = "
                    f"{display.number_math(history.accuracy, 2)})")
    _legend_below(figure, panels, columns=2)
    return figure, panels


# ---- a frozen orbit ----------------------------------------------------------------------------------------------
def frozen_eccentricity(history: Any, figure: Any = None) -> tuple[Any, Any]:
    """The mean eccentricity vector (e cos omega, e sin omega), averaged over each revolution, of a frozen design
    and of a circular orbit of the same size and inclination as each backend integrates them under J2, J3 and J4:
    both circle the frozen point (the closed form's e at its omega, a star) at the apsidal rate, the circular start
    on the closed form's circle through the origin. `history` is a FrozenHistory (orbits.validate.histories).
    Returns (figure, axes)."""
    figure = frame.figure(figure, (7.6, 8.2))
    ax = figure.subplots()
    scale = 1e3  # the vector's components in units of 1e-3
    centre = history.e * np.array([np.cos(np.radians(history.argp)), np.sin(np.radians(history.argp))]) * scale
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(centre[0] + np.hypot(*centre) * np.cos(angle), centre[1] + np.hypot(*centre) * np.sin(angle),
            color=THEORY_COLOR, ls="--", lw=1.0, label="closed form: a circular start circles the frozen point")
    inset = ax.inset_axes([0.37, 0.58, 0.28, 0.2])  # inside the circle, above the star
    wander = max(float(np.max(np.hypot(xi * scale - centre[0], eta * scale - centre[1])))
                 for xi, eta in history.frozen.values())
    zoom = 10.0 ** math.floor(math.log10(max(wander, 1e-12)))  # the inset's unit, in units of 1e-3
    for k, backend in enumerate(history.frozen):
        color, dashes, marker = _style(backend, k)
        xi, eta = history.circular[backend]
        ax.plot(xi * scale, eta * scale, color=color, ls=dashes, lw=1.2, alpha=0.45,
                label=f"{backend}, started circular (mean elements)")
        xi, eta = history.frozen[backend]
        ax.plot(xi * scale, eta * scale, color=color, ls=dashes, lw=1.2)  # a point at this scale: see the inset
        inset.plot((xi * scale - centre[0]) / zoom, (eta * scale - centre[1]) / zoom, color=color, ls=dashes, lw=1.0,
                   label=f"{backend}, started at the frozen e and $\\omega$ (mean elements): the inset")
        ax.plot([], [], color=color, ls=dashes, lw=1.2,
                label=f"{backend}, started at the frozen e and $\\omega$ (mean elements): in the inset")
    inset.plot(0.0, 0.0, marker="*", ms=9, color=THEORY_COLOR, ls="none")
    inset.set_aspect("equal", adjustable="datalim")
    inset.tick_params(labelsize="x-small")
    power = int(round(math.log10(zoom))) - 3
    inset.set_title(f"about the frozen point [$10^{{{power}}}$]", fontsize="x-small")
    inset.grid(alpha=0.3)
    ax.plot(*centre, marker="*", ms=15, color=THEORY_COLOR, ls="none",
            label=f"frozen point: e = {display.number(history.e, 4)} at $\\omega$ = "
                  f"{display.number(history.argp, 4)}$\\degree$")
    ax.plot(0.0, 0.0, marker="+", ms=10, color="0.5", ls="none")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$e\,\cos\omega$ [$10^{-3}$], revolution means")
    ax.set_ylabel(r"$e\,\sin\omega$ [$10^{-3}$], revolution means")
    ax.grid(alpha=0.3)
    frame.title(figure, f"A frozen orbit under J2, J3 and J4: rebound and heyoka\n{history.title}\n(a mean "
                        f"eccentricity vector circles the frozen point once in {display.number(history.period, 4)} d; "
                        f"each start is set so that its first revolution has the mean elements named, clear of J2's "
                        f"short-period terms, of order J2 R / a = {display.number_math(history.short_period, 2)})")
    _legend_below(figure, np.array([ax]), columns=1)
    return figure, ax


# ---- a repeat ground track -----------------------------------------------------------------------------------------
def _km(value: float) -> str:
    return display.quantity_math(value * u.km, digits=3, unit=u.km)


def _closure(km: float) -> str:
    """E.g. "0.545 km west of its start" for a last node 0.545 km west of the first."""
    return f"{_km(abs(km))} {'east' if km > 0 else 'west'} of its start" if km else "on its start"


def _wrapped(longitude: np.ndarray) -> np.ndarray:
    """Longitudes (deg) in [-180, 180)."""
    return (np.asarray(longitude) + 180.0) % 360.0 - 180.0


def _broken_at_the_date_line(longitude: np.ndarray, latitude: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The track with NaN where the longitude wraps from +180 to -180 deg (or back), so no line crosses the map."""
    jumps = np.flatnonzero(np.abs(np.diff(longitude)) > 180.0) + 1
    return np.insert(longitude, jumps, np.nan), np.insert(latitude, jumps, np.nan)


def ground_track(track: Any, figure: Any = None) -> tuple[Any, np.ndarray]:
    """A repeat-ground-track design's track over one cycle as each backend integrates it (longitude and latitude
    over the turning body, spherical), with its ascending nodes and, beside it, each node's longitude less where
    the closed form puts it (the cycle's nodes evenly spaced, each day's one revolution's shift apart), in km at
    the equator: the track closes where that line ends at 0. `track` is a GroundTrack (orbits.validate.histories).
    Returns (figure, array of the two panels)."""
    figure = frame.figure(figure, (12.0, 6.4))
    panels = figure.subplots(1, 2, width_ratios=(2.2, 1))
    world, closing = panels
    count = np.arange(track.revolutions + 1)
    places = -360.0 * track.days / track.revolutions * count  # each node this far west of the one before
    for k, backend in enumerate(track.longitude):
        color, dashes, marker = _style(backend, k)
        world.plot(*_broken_at_the_date_line(track.longitude[backend], track.latitude[backend]), color=color,
                   ls=dashes, lw=0.6, label=f"{backend}: track")
        nodes = track.nodes[backend][: track.revolutions + 1]
        world.plot(_wrapped(nodes), np.zeros_like(nodes), marker=marker, ls="none", color=color, ms=5,
                   label=f"{backend}: ascending nodes")
        closing.plot(count, _wrapped(nodes - places) * track.equator_km_per_deg, color=color, ls=dashes,
                     marker=marker, ms=4, label=f"{backend}: the cycle closes {_closure(track.closure_km[backend])}")
    world.set_xlim(-180.0, 180.0)
    world.set_ylim(-90.0, 90.0)
    world.set_xticks(np.arange(-180, 181, 60))
    world.set_yticks(np.arange(-90, 91, 30))
    world.set_xlabel(r"longitude east of the first node [$\degree$]")
    world.set_ylabel(r"latitude [$\degree$]")
    world.grid(alpha=0.3)
    closing.axhline(0.0, color=THEORY_COLOR, ls="--", lw=1.0, label="closed form: every node on its place")
    closing.set_xlabel("revolution")
    closing.set_ylabel("node less the closed form's place [km at the equator]")
    closing.grid(alpha=0.3)
    figure.suptitle(f"A repeat ground track under J2 and J4: rebound and heyoka\n{track.title}\n(started on the "
                    f"mean orbit; the first-order rates leave terms of order J2 (R/p)$^2$ = "
                    f"{display.number_math(track.accuracy, 2)} of themselves)")
    _legend_below(figure, panels)
    return figure, panels


# ---- drag decay ----------------------------------------------------------------------------------------------
def drag_decay(decay: Any, history: Any = None, figure: Any = None) -> tuple[Any, np.ndarray]:
    """Altitude against time of a circular orbit decaying by drag: the closed form's curve (a DragDecay, read
    through its properties) to the end of its lifetime and the point where it stops holding (the band's base, or
    the breakdown altitude where the decay in one revolution reaches the scale height H). With a DecayHistory
    (orbits.validate.histories), each backend's integrated altitude over it, and below, the integration less the
    closed form (m). Returns (figure, array of the panels)."""
    table = decay.quantities()
    lifetime = decay.lifetime
    unit, label = next((unit, label) for unit, label, below in TIME_UNITS if lifetime < below)
    figure = frame.figure(figure, (9.0, 7.4 if history is not None else 5.8))
    panels = np.atleast_1d(figure.subplots(2 if history is not None else 1, 1, sharex=True, squeeze=False,
                                           height_ratios=(3, 1.4) if history is not None else None)[:, 0])
    ax = panels[0]
    times = np.linspace(0.0, 1.0, 400) * lifetime
    ax.plot(times.to_value(unit), decay.altitude_after(times).to_value(u.km), color=THEORY_COLOR, lw=1.6, zorder=2,
            label="closed form (a circular orbit in one exponential band)")
    if history is not None:
        _integrated_decay(panels, decay, history, unit)
    base = table["base_altitude"].to_value(u.km)
    breakdown = table["breakdown_altitude"].to_value(u.km) if "breakdown_altitude" in table else -np.inf
    end = max(base, breakdown)
    km = {name: display.quantity_math(table[name], digits=4, unit=u.km)
          for name in ("altitude", "base_altitude", "breakdown_altitude", "scale_height") if name in table}
    if base >= breakdown:
        ax.axhline(base, color="0.5", ls=":", lw=1.0, label=f"the band's base, {km['base_altitude']}")
    else:
        ax.axhline(breakdown, color="C3", ls=":", lw=1.0, label=f"breakdown altitude, {km['breakdown_altitude']} "
                   f"(the band's base: {km['base_altitude']})")
    why = ("the band's base, where its exponential law ends" if base >= breakdown
           else "the decay in one revolution reaches H")
    ax.plot([lifetime.to_value(unit)], [end], marker="*", ms=13, color="C3", mec="0.2", ls="none", zorder=4,
            label=f"the closed form stops holding: {why}")
    ax.set_ylabel("altitude above the equator [km]")
    panels[-1].set_xlabel(f"time [{label}]")
    for panel in panels:
        panel.grid(alpha=0.3)
    lasts = display.number_math(lifetime.to_value(unit), 4)
    figure.suptitle(f"Drag decay of a circular orbit about {decay.primary}: from {km['altitude']} to "
                    f"{display.quantity_math(end * u.km, digits=4)} in {lasts} {label}\n"
                    f"B = C$_D$A/m = {display.number_math(decay.b, 4)} m$^2$/kg, scale height H = "
                    f"{km['scale_height']}\nthe closed form's error order, (decay in a revolution / H)$^2$, is "
                    f"{display.number_math(table['accuracy'].to_value(u.one), 2)} at the start")
    _legend_below(figure, panels, columns=2)
    return figure, panels


def _integrated_decay(panels: np.ndarray, decay: Any, history: Any, unit: u.UnitBase) -> None:
    """Each backend's altitude over the closed form (top) and less it, in m (bottom)."""
    days = np.asarray(history.times, dtype=float) * u.day
    means = np.asarray(history.mean_times, dtype=float) * u.day
    closed = decay.altitude_after(np.minimum(means, decay.lifetime)).to_value(u.km)
    for k, (backend, altitude) in enumerate(history.altitude.items()):
        color, dashes, marker = _style(backend, k)
        panels[0].plot(days.to_value(unit), altitude, color=color, ls=dashes, lw=1.0, zorder=3,
                       label=f"{backend}: integrated radius less the equatorial radius")
        panels[1].plot(means.to_value(unit), (np.asarray(history.mean_altitude[backend]) - closed) * 1e3, color=color,
                       ls=dashes, lw=0.8, marker=marker, ms=4, mfc="none",
                       label=f"{backend}: radius averaged over each revolution")
    panels[1].axhline(0.0, color=THEORY_COLOR, lw=1.2)
    panels[1].set_ylabel("averaged radius less\nthe closed form [m]")
