"""Launch windows: the porkchop plot of a grid of Lambert transfers (an orbits.Porkchop, read through its
properties): departure C3, arrival v_inf and the time of flight against launch and arrival dates."""

from collections.abc import Sequence
from typing import Any

import astropy.units as u
import numpy as np

from orbits.plot import frame

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

    fig, ax = frame.axes(ax, figsize=(8.0, 7.2))
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
