"""Three bodies and more, in the frame that turns with them: the restricted three-body problem's zero-velocity
curves and Lagrange points with trajectories over them (lagrange_plane, lagrange_departure, coorbital_plane), and
a ring of equal bodies breaking up (ring_breakup, ring_snapshots).

The three-body pictures take an orbits.RestrictedThreeBody and read its properties; the ring pictures take arrays
in the ring's code units.
"""

import math
from collections.abc import Sequence
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame, inputs, units
from orbits.core.threebody import rings
from orbits.core.threebody.lagrange import point_index
from orbits.threebody.rings import BREAKUP_DEVIATION, ROUND_OFF_SEED
from orbits.twobody.plot import catalogue_body, primary_color

# ---- the restricted three-body problem -----------------------------------------------------------------------


def lagrange_plane(
    system: Any,
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
    trajectories, own = trajectories or {}, jacobi_constants or {}
    if set(own) - set(trajectories):
        raise ValueError(f"jacobi_constants for {sorted(set(own) - set(trajectories))}: no trajectory of that "
                         f"label; trajectories: {sorted(trajectories)}")

    fig, ax = frame.axes(ax, figsize=(9.6, 6.4))
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
        bands = {1: (levels[1], levels[2]), 2: (levels[0], levels[1]), 3: (bottom, levels[0])}
        for shade_color, k in (("0.88", 1), ("0.72", 2), ("0.55", 3)):
            low, high = bands[k]
            if np.any((values >= low) & (values < high)):  # a legend entry only for a shade the window shows
                ax.add_patch(mpatches.Rectangle((0, 0), 0, 0, color=shade_color, label=f"forbidden at C(L{k})"))
    contours = ax.contour(xs, ys, values, levels=levels, colors=["C2", "C1", "C0"], linestyles=["--", "-.", "-"],
                          linewidths=1.0, zorder=1)
    ax.clabel(contours, fmt={level: f"C(L{k + 1})" for k, level in enumerate(constants[:3])}, fontsize="x-small")
    mu = float(system.mass_ratio.to_value(u.one))
    primary, secondary = catalogue_body(system.gm_primary), catalogue_body(system.gm_secondary)
    def seen(x: float) -> bool:  # a primary in the window gets its legend entry; one outside it, none
        return abs(x - center[0]) <= extent and abs(center[1]) <= extent

    ax.plot([-mu], [0], marker="o", ms=11, color=primary_color(primary), mec="0.3", ls="none", zorder=3,
            label=f"{display.body_name(system.gm_primary)} (M)" if seen(-mu) else "_primary")
    ax.plot([1 - mu], [0], marker="o", ms=6, color=primary_color(secondary), mec="0.3", ls="none", zorder=3,
            label=(f"{display.body_name(system.gm_secondary)} (m), $\\mu$ = {display.number_math(mu, 4)}"
                   if seen(1 - mu) else "_secondary"))
    xy = system.positions.to_value(u.m)[:, :2] / r
    ax.plot(xy[:, 0], xy[:, 1], marker="x", color="C3", ls="none", zorder=3, label="Lagrange points",
            gid="Lagrange points")
    for k, (label, track) in enumerate(trajectories.items()):
        color = f"C{(k + 4) % 10}"
        shown = units.to_si(track, units.M, f"trajectory {label!r}") / r
        ax.plot(shown[:, 0], shown[:, 1], color=color, lw=1.0, zorder=2, label=label, gid="trajectory")
        if label in own:
            name = f"Jacobi constant of {label!r}"
            c0 = inputs.single(units.to_si, own[label], units.M_PER_S**2, name)
            ax.contourf(xs, ys, values, levels=[bottom, c0], colors=[color], alpha=0.2, zorder=0)
            ax.contour(xs, ys, values, levels=[c0], colors=[color], linestyles=["--"], linewidths=1.2, zorder=1)
            ax.add_patch(mpatches.Rectangle((0, 0), 0, 0, color=color, alpha=0.2,
                                            label=f"forbidden to the {label.split(',')[0]} (its C)"))
    ax.set_aspect("equal")
    ax.set_xlim(center[0] - extent, center[0] + extent)
    ax.set_ylim(center[1] - extent, center[1] + extent)
    ax.set_xlabel(f"x (rotating frame) [separation r = {display.quantity_math(system.separation, digits=6)}]")
    ax.set_ylabel("y (rotating frame) [separation r]")
    ax.grid(alpha=0.3)
    frame.legend_beside(ax)
    frame.labels_apart(ax, [(f"L{k + 1}", point, dict(fontsize="small", gid="L", sides=POINT_SIDES[k]))
                            for k, point in enumerate(xy)])
    frame.title(ax, f"{_pair(system)}, in the frame turning with them: the Lagrange points and the zero-velocity "
                    f"curves through them")
    return fig, ax


#: the sides of its point each Lagrange point's label is tried on, in order: L1 towards M and L2 away from it
#: (they flank m, close to it when m is small), L3 out on M's side, L4 above, L5 below
POINT_SIDES = (("upper left", "lower left", "left", "above", "below"),
               ("upper right", "lower right", "right", "above", "below"),
               ("upper left", "lower left", "left", "upper right", "above", "below"),
               ("above", "upper right", "upper left", "right", "left"),
               ("below", "lower right", "lower left", "right", "left"))


def _pair(system: Any) -> str:
    """"Sun and Earth": the two primaries of a RestrictedThreeBody by name (or GM)."""
    return f"{display.body_name(system.gm_primary)} and {display.body_name(system.gm_secondary)}"


def lagrange_departure(system: Any, point: str, offset: u.Quantity, times: u.Quantity,
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
    seconds = units.to_si(times, units.S, "times")
    unit = display.natural_unit(times[-1])
    elapsed = (seconds << u.s).to_value(unit)
    rate = float(system.growth_rates[k].to_value(1 / u.s))
    start = inputs.single(units.to_si, offset, units.M, "offset")
    gone = np.hypot(*(shown - where).T) * r
    distance.semilogy(elapsed, gone / r, color="C4", lw=1.3, label="integrated", gid="trajectory")
    predicted = start * np.exp(rate * seconds) / r
    e_folding = display.quantity_math(1 / rate * u.s, digits=3)
    distance.semilogy(elapsed, np.where(predicted <= 1.0, predicted, np.nan), color="C3", ls="--",
                      label=f"offset $\\times$ exp(t / {e_folding}) (linear prediction)", gid="prediction")
    distance.set_xlabel(f"time [{display.unit_math(unit)}]")
    distance.set_ylabel(f"distance from {point} [separation r]")
    distance.grid(alpha=0.3, which="major")
    frame.legend_outside(distance)
    frame.title(plane, f"the rotating frame about {point}")
    frame.title(distance, f"distance from {point}: integrated and linear")
    frame.title(fig, f"{_pair(system)}: a particle leaving {point}, started "
                     f"{display.quantity_math(offset, digits=3)} off along the growing mode", size="large")
    return fig, np.array([plane, distance])


def coorbital_plane(system: Any, trajectories: dict[str, u.Quantity], ax: Any = None) -> tuple[Any, Any]:
    """Co-orbital motion unrolled: each trajectory's longitude from the secondary as seen from the primary (deg,
    -180 to 180) against its distance from the primary minus r (units of r), with L3 (at +-180 deg), L4 (+60),
    L5 (-60) and the secondary (0) marked. A tadpole stays on one side of the secondary; a horseshoe crosses
    +-180 deg and turns back before reaching the secondary. `trajectories` as for lagrange_plane."""
    fig, ax = frame.axes(ax)
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
    secondary = display.body_name(system.gm_secondary)
    for name, where in (("L3", -180.0), ("L5", -60.0), (secondary, 0.0), ("L4", 60.0), ("L3", 180.0)):
        ax.axvline(where, color="0.6" if name != secondary else "C7", lw=0.8, ls=":" if name != secondary else "-")
        ax.annotate(name, (where, 1.0), xycoords=("data", "axes fraction"), textcoords="offset points",
                    xytext=(2 if where < 180 else -2, -4), ha="left" if where < 180 else "right", va="top",
                    fontsize="small")
    ax.set_xlim(-180, 180)
    ax.set_xticks(np.arange(-180, 181, 60))
    primary = frame.in_a_sentence(display.body_name(system.gm_primary))
    ax.set_xlabel(f"longitude from {frame.in_a_sentence(secondary)}, seen from {primary} [deg]")
    ax.set_ylabel(f"distance from {primary} - r [separation r]")
    ax.grid(alpha=0.3)
    frame.legend_outside(ax)
    frame.title(ax, f"Co-orbital motion in the frame of {_pair(system)}: a tadpole keeps to one side of "
                    f"{frame.in_a_sentence(secondary)}, a horseshoe turns back before it")
    return fig, ax


# ---- rings ---------------------------------------------------------------------------------------------------


def ring_breakup(
    times: np.ndarray,
    deviations: np.ndarray,
    growth_rate: float,
    breakup_time: float,
    ax: Any = None,
    seed: float = ROUND_OFF_SEED,
    period: u.Quantity | None = None,
) -> tuple[Any, Any]:
    """Shape deviation of a ring against time (log), with the linear prediction seed * exp(rate t) (the seed by
    default the round-off orbits.threebody.rings.ROUND_OFF_SEED), the break-up level
    (orbits.threebody.rings.BREAKUP_DEVIATION, 1e-3
    of the radius) and the predicted break-up time. `times`, 1 / `growth_rate` and `breakup_time` are in the
    ring's code unit 1 / omega; the axis counts ring periods 2 pi / omega, and says what one is when `period`
    (a time Quantity, e.g. Ring.period) is given."""
    fig, ax = frame.axes(ax)
    periods = np.asarray(times, dtype=float) / (2 * np.pi)
    shown = np.where(np.asarray(deviations) > 0, deviations, np.nan)
    ax.semilogy(periods, shown, color="C0", label="integrated ring")
    e_folding = 1 / (2 * np.pi * growth_rate) if growth_rate > 0 else math.inf  # in periods
    ax.semilogy(
        periods,
        seed * np.exp(growth_rate * np.asarray(times)),
        color="C3",
        ls="--",
        label=f"round-off $\\times$ exp(t / {display.number_math(e_folding, 3)} periods)" if growth_rate > 0
        else "round-off, linearly stable",
    )
    if np.isfinite(breakup_time):
        ax.axvline(breakup_time / (2 * np.pi), color="gray", ls=":",
                   label=f"predicted break-up, {display.number_math(breakup_time / (2 * np.pi), 3)} periods")
    ax.axhline(BREAKUP_DEVIATION, color="C3", lw=0.8, ls="-.", gid="break-up level",
               label=f"break-up level {display.number_math(BREAKUP_DEVIATION, 3)} of the radius")
    ax.set_ylim(1e-17, 10)
    one = f", 1 period = {display.quantity_math(period, digits=4)}" if period is not None else ""
    ax.set_xlabel(f"time [ring periods $2\\pi/\\omega${one}]")
    ax.set_ylabel("largest chord error [ring radius]")
    ax.grid(alpha=0.3, which="major")
    frame.legend_outside(ax)
    frame.title(ax, "A ring breaking up: its shape's deviation from the regular polygon against time")
    return fig, ax


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
        ax.set_title(f"t = {display.number(times[k] / (2 * np.pi), 3)} periods\n"
                     f"deviation {display.number_math(deviations[k], 2)}", fontsize="small")
        ax.set_aspect("equal")
        reach = max(1.6, 1.1 * float(np.max(np.hypot(x, y))))
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
        ax.set_xlabel("x, turning with the ring [radius]", fontsize="x-small")
        if column == 0:
            ax.set_ylabel("y [ring radius]", fontsize="x-small")
        ax.tick_params(labelsize="x-small")
        panels.append(ax)
    top.set_title("")
    frame.title(fig, f"A ring of {n} bodies breaking up, seen in the frame turning with it", size="large")
    return fig, np.array([top, *panels])
