"""Launch windows: the porkchop plot of a grid of Lambert transfers (an orbits.Porkchop, read through its
properties): departure C3, arrival v_inf and the time of flight against launch and arrival dates."""

import math
from collections.abc import Sequence
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame

#: matplotlib's date numbers count days from 1970-01-01 (Julian date 2440587.5)
_UNIX_EPOCH_JD = 2440587.5
KM2_PER_S2 = u.km**2 / u.s**2
#: where along a contour its label is tried, as fractions of the contour's length
_ALONG = (0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9)


def _rounded(x: float, digits: int) -> float:
    """x rounded to `digits` significant digits (x > 0)."""
    return round(x, digits - 1 - math.floor(math.log10(x)))


def _contour_levels(values: np.ndarray, factors: Sequence[float]) -> np.ndarray:
    """Contour levels at `factors` times the least value, each rounded to two significant digits."""
    least = float(np.min(values))
    levels = [_rounded(least * f, 2) for f in factors]
    return np.unique([level for level in levels if level > least])


def porkchop(p: Any, ax: Any = None) -> tuple[Any, Any]:
    """Draw a Porkchop: contours of departure C3 [km2/s2] (solid), of arrival v_inf [km/s] (dashed) and of the
    time of flight [d] (grey, dotted), launch date on x and arrival date on y (TDB), the cells of least C3, least
    arrival v_inf and least total v_inf marked. Cells whose arrival is not after the launch are left blank.

    Each contour level is labelled once, on its longest stretch, where the label meets no other label (the ridge
    of 180-degree transfers, where the contours crowd into short loops, gets none). A least value in a cell on the
    edge of the grid may be no minimum at all, the merit still falling outside the windows: it is ringed in red
    and its legend entry says which edge (PorkchopMinimum.edges; a margin round the grid keeps every marker
    whole). The title names the bodies and the windows.

    Each contour set carries a gid ("C3", "arrival v_inf", "time of flight"), each marker the gid "minimum" and
    each ring the gid "on the edge"; tested in tests/api/test_porkchop.py (the marker sits on the minimum's dates,
    the levels bracket the grid) and tests/api/test_pictures_for_a_talk.py.
    """
    import matplotlib.dates as mdates

    fig, ax = frame.axes(ax, figsize=(8.0, 7.6))
    x = p.launch_dates.tdb.jd - _UNIX_EPOCH_JD
    y = p.arrival_dates.tdb.jd - _UNIX_EPOCH_JD
    blank = ~p.valid
    c3 = np.ma.masked_array(p.c3.unmasked.to_value(KM2_PER_S2), blank)
    ridge = _ridge(p)  # the transfers through 180 degrees, narrower than a cell: no contour crosses it
    c3 = np.ma.masked_array(c3.data, blank | ridge)
    v_inf = np.ma.masked_array(p.arrival_v_inf.unmasked.to_value(u.km / u.s), blank | ridge)
    tof = np.ma.masked_array(p.time_of_flight.unmasked.to_value(u.day), blank)
    c3_lines = ax.contour(x, y, c3, levels=_contour_levels(c3.compressed(), (1.02, 1.1, 1.25, 1.5, 2, 3, 5, 8)),
                          colors="C0", linewidths=1.2)
    c3_lines.set_gid("C3")
    v_lines = ax.contour(x, y, v_inf, levels=_contour_levels(v_inf.compressed(), (1.05, 1.2, 1.5, 2, 3, 4)),
                         colors="C3", linewidths=1.0, linestyles="--")
    v_lines.set_gid("arrival v_inf")
    span = tof.compressed()
    step = max(25.0, _rounded(max(float(span.max() - span.min()), 1.0) / 6, 1))
    days = np.arange(np.ceil(span.min() / step) * step, span.max(), step)
    tof_lines = ax.contour(x, y, tof, levels=days, colors="0.55", linewidths=0.8, linestyles=":")
    tof_lines.set_gid("time of flight")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(mdates.AutoDateLocator(minticks=3, maxticks=6))
        axis.set_major_formatter(mdates.DateFormatter("%Y-%m-%d"))
    ax.set_xlabel("launch date [TDB]")
    ax.set_ylabel("arrival date [TDB]")
    ax.grid(alpha=0.25)
    for limits, dates in ((ax.set_xlim, x), (ax.set_ylim, y)):  # a margin round the grid: a marker on its
        reach = 0.06 * max(dates[-1] - dates[0], 1.0)  # edge is drawn whole, off the tick labels
        limits(dates[0] - reach, dates[-1] + reach)
    if ridge.any():
        ax.contourf(x, y, ridge.astype(float), levels=[0.5, 1.5], colors=["0.5"], alpha=0.25, zorder=0)
        import matplotlib.patches as mpatches

        ax.add_patch(mpatches.Rectangle((x[0], y[0]), 0, 0, color="0.5", alpha=0.25,  # the legend's entry
                                        label="r1, r2 nearly in line: the transfer plane turns steeply and "
                                              "$C_3$, $v_\\infty$ soar (not contoured)"))
    _mark_minima(ax, p)
    ax.plot([], [], color="C0", label=f"departure $C_3$ [{display.unit_math(KM2_PER_S2)}]")
    ax.plot([], [], color="C3", ls="--", label="arrival $v_\\infty$ [km/s]")
    ax.plot([], [], color="0.55", ls=":", label="time of flight [d]")
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize="small", ncol=1,
               frameon=False)
    frame.title(ax, f"{p.departure} to {p.target}: zero-revolution prograde transfers, launch "
                    f"{_date(p.launch_dates[0])} to {_date(p.launch_dates[-1])}, arrival {_date(p.arrival_dates[0])} "
                    f"to {_date(p.arrival_dates[-1])}\npositions: {p.source}")
    taken: list = []
    rough = _rough(c3, x, y)
    for lines, digits, unit in ((c3_lines, 2, ""), (v_lines, 2, ""), (tof_lines, 3, " d")):
        _label_once(ax, lines, lambda level, d=digits, text=unit: display.number_math(level, d) + text, taken, rough)
    return fig, ax


#: a transfer whose plane tilts this much more than either body's orbit lies on the ridge of 180-degree transfers
RIDGE_TILT = np.radians(10.0)


def _ridge(p: Any) -> np.ndarray:
    """The cells of the ridges of transfers through about 180 (or 0) degrees, where r1 and r2 are nearly in line,
    the plane through them and the Sun turns steeply and C3 soars within less than a cell (contours drawn across
    it zigzag from cell to cell): the transfer plane (normal along r1 x r2) tilts from the ecliptic by more than
    RIDGE_TILT beyond the larger of the two bodies' own orbital tilts."""
    from orbits.manoeuvres.lambert import ECLIPTIC_POLE

    def tilt(normal):
        normal = normal / np.linalg.norm(normal, axis=-1)[..., None]
        return np.arccos(np.clip(np.abs(normal @ ECLIPTIC_POLE), 0.0, 1.0))

    own = max(float(np.max(tilt(np.cross(p.r_departure, p.v_departure)))),
              float(np.max(tilt(np.cross(p.r_target, p.v_target)))))
    planes = np.cross(p.r_departure[None, :, :], p.r_target[:, None, :])
    return (tilt(planes) > own + RIDGE_TILT) & p.valid


def _rough(c3: np.ma.MaskedArray, x: np.ndarray, y: np.ndarray) -> Any:
    """Whether a point (data coordinates) lies within two cells of where C3 jumps by more than half between
    neighbouring cells (the ridge of transfers through 180 degrees, where the contours crowd) or of a blank
    cell: a function of (x, y)."""
    values = np.log(np.ma.filled(c3, np.nan))
    jump = np.zeros(values.shape, dtype=bool)
    for axis in (0, 1):
        step = np.abs(np.diff(values, axis=axis))
        big = ~(step <= np.log(1.5))  # NaN (a blank neighbour) counts as a jump
        lead = [slice(None)] * 2
        lead[axis] = slice(1, None)
        jump[tuple(lead)] |= big
        lead[axis] = slice(None, -1)
        jump[tuple(lead)] |= big
    near = jump.copy()
    for _ in range(2):
        grown = near.copy()
        grown[1:] |= near[:-1]
        grown[:-1] |= near[1:]
        grown[:, 1:] |= near[:, :-1]
        grown[:, :-1] |= near[:, 1:]
        near = grown

    def at(point):
        col = int(np.clip(np.searchsorted(x, point[0]), 0, x.size - 1))
        row = int(np.clip(np.searchsorted(y, point[1]), 0, y.size - 1))
        return bool(near[row, col])

    return at


def _date(when: Any) -> str:
    return when.tdb.iso[:10]


def _mark_minima(ax: Any, p: Any) -> None:
    """The cells of least C3, arrival v_inf and total v_inf, each drawn whole (on the edge of the grid too), with
    its dates, C3 and arrival v_inf in the legend; a red ring round each on the edge of the grid (its sides are
    PorkchopMinimum.edges)."""
    marks = {"$C_3$": ("*", "C0", 18, p.minimum_c3), "arrival $v_\\infty$": ("D", "C3", 11, p.minimum_arrival_v_inf),
             "total $v_\\infty$": ("o", "k", 6, p.minimum_total)}  # largest first: on one cell, each still seen
    ringed = False
    for kind, (marker, color, size, best) in marks.items():
        sides = best.edges
        label = (f"least {kind}: {_date(best.launch)} to {_date(best.arrival)}, "
                 f"$C_3$ = {display.quantity_math(best.c3, digits=3, unit=KM2_PER_S2)}, "
                 f"$v_\\infty$ = {display.quantity_math(best.arrival_v_inf, digits=3, unit=u.km / u.s)}"
                 + (f"\n(on the grid's edge: {' and '.join(sides)})" if sides else ""))
        at = (best.launch.tdb.jd - _UNIX_EPOCH_JD, best.arrival.tdb.jd - _UNIX_EPOCH_JD)
        ax.plot(*at, marker=marker, ms=size, color=color, mec="k", mew=0.8, ls="none", label=label, gid="minimum",
                zorder=5 + len(ax.get_lines()) * 1e-3)
        if sides:
            ring = dict(marker="o", mfc="none", mec="C3", mew=1.6, ls="none")
            ax.plot(*at, ms=size + 8, zorder=5, gid="on the edge", **ring)
            if not ringed:  # one legend entry, its ring of the legend's size
                ax.plot([], [], ms=12, label="on the grid's edge: the least value may lie outside the windows", **ring)
            ringed = True


def _label_once(ax: Any, lines: Any, text: Any, taken: list, rough: Any) -> None:
    """Label each level of a contour set once, inline, at the first point along its stretches (longest first, at
    the fractions _ALONG of each) where the field is smooth (not `rough`, a function of a data point), the label's
    box overlaps none already `taken` (boxes in pixels, added to) and stays inside the axes; a level with no
    such point goes unlabelled. `text` writes a level."""
    figure = ax.figure.figure
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    inside = ax.get_window_extent(renderer)
    spots, levels = [], []
    for level, path in zip(lines.levels, lines.get_paths()):
        pieces = [piece for piece in path.to_polygons(closed_only=False) if len(piece) > 1]
        if not pieces:
            continue
        shown = sorted((ax.transData.transform(piece) for piece in pieces), key=_length, reverse=True)
        box = _text_box(ax, text(level), renderer)
        for at in (_point_along(stretch, fraction) for stretch in shown for fraction in _ALONG):
            spot = box.translated(at[0] - box.width / 2, at[1] - box.height / 2)
            point = tuple(ax.transData.inverted().transform(at))
            if inside.contains(spot.x0, spot.y0) and inside.contains(spot.x1, spot.y1) and not rough(point) and not any(
                    spot.overlaps(other) for other in taken):
                taken.append(spot.padded(6))
                spots.append(point)
                levels.append(level)
                break
    if spots:
        ax.clabel(lines, levels=levels, manual=spots, inline=True, fontsize="x-small",
                  fmt={level: text(level) for level in levels})


def _length(points: np.ndarray) -> float:
    return float(np.sum(np.hypot(*np.diff(points, axis=0).T)))


def _point_along(points: np.ndarray, fraction: float) -> np.ndarray:
    """The point `fraction` of the way along a polyline (pixels)."""
    steps = np.hypot(*np.diff(points, axis=0).T)
    reach = np.concatenate([[0.0], np.cumsum(steps)])
    goal = fraction * reach[-1]
    k = int(np.clip(np.searchsorted(reach, goal) - 1, 0, len(steps) - 1))
    share = (goal - reach[k]) / steps[k] if steps[k] > 0 else 0.0
    return points[k] + share * (points[k + 1] - points[k])


def _text_box(ax: Any, text: str, renderer: Any) -> Any:
    """The box (pixels, at the origin) a contour label of `text` takes, with a little room about it."""
    from matplotlib.transforms import Bbox

    probe = ax.text(0, 0, text, fontsize="x-small")
    box = probe.get_window_extent(renderer)
    probe.remove()
    return Bbox([[0.0, 0.0], [box.width + 6, box.height + 2]])
