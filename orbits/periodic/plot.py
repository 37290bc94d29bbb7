"""Periodic orbits of the restricted three-body problem in the rotating frame: an orbit or a family in 3-D and in its
three projections, with the primaries to scale and the Lagrange points marked (periodic_orbit, periodic_family),
and the family's stability indices against its Jacobi constant with the bifurcations marked (stability_diagram).

The pictures take an orbits.PeriodicOrbit or orbits.PeriodicFamily and read their properties: the states over one
period, the amplitudes, the stability indices, the bifurcations. Positions are offsets from the orbit's Lagrange
point (or the secondary, for an orbit about it) in the unit of the orbit's size, x from the primary M to the
secondary m, z along the binary's spin.
"""

from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame
from orbits.twobody.plot import catalogue_body, primary_color

#: samples of each orbit drawn
SAMPLES = 400
#: the projections drawn beside the 3-D view: (axes indices, title)
VIEWS = (((0, 1), "x-y: the binary's plane"), ((0, 2), "x-z: seen from the side"),
         ((1, 2), "y-z: seen from the primary along x"))
_NAMES = "xyz"


def _tracks(orbits) -> list:
    """Rotating-frame positions (SAMPLES + 1, 3) in metres of each orbit over one period."""
    return [orbit.states(np.linspace(0.0, 1.0, SAMPLES + 1) * orbit.period)[0].to_value(u.m) for orbit in orbits]


def _window(tracks, margin: float = 0.08) -> tuple[np.ndarray, float]:
    """(centre (3,), half-width) of a cube holding every track, with a margin."""
    points = np.concatenate(tracks)
    low, high = points.min(axis=0), points.max(axis=0)
    half = 0.5 * float(np.max(high - low)) * (1.0 + margin)
    return 0.5 * (low + high), max(half, 1e-9 * float(np.max(np.abs(high))))


def _bodies(system, centre, half):
    """[(name, position (3,) m, radius m, colour)] of the two primaries."""
    mu = float(system.mu)
    r = float(system.separation.to_value(u.m))
    out = []
    for gm, x in ((system.gm_primary, -mu * r), (system.gm_secondary, (1.0 - mu) * r)):
        known = catalogue_body(gm)
        out.append((display.body_name(gm), np.array([x, 0.0, 0.0]), 0.0 if known is None else known.radius,
                    primary_color(known)))
    return out


#: an orbit whose largest |z| is below this fraction of its window is planar: its x-y view alone is drawn
PLANAR = 1e-9


def _reference(orbit) -> tuple[str, np.ndarray]:
    """(name, rotating-frame position (3,) m) the views measure from: the orbit's Lagrange point, or the
    secondary for an orbit about it; coordinates about the barycentre read as 0.990 AU to the last digit, offsets
    from the point as the orbit's own size."""
    system = orbit.system
    if orbit.point:
        k = int(orbit.point[1]) - 1
        return orbit.point, system.positions.to_value(u.m)[k]
    r = float(system.separation.to_value(u.m))
    return display.body_name(system.gm_secondary), np.array([(1.0 - float(system.mu)) * r, 0.0, 0.0])


def _draw_views(fig, orbits, colours, labels, title):
    """The 3-D view and the three projections of `orbits` on four axes of `fig` (a 2 x 2 grid of subplots), or the
    x-y view alone on one axes for planar orbits, in offsets from the orbits' Lagrange point (or the secondary) in
    the unit of the orbits' size; returns the axes."""
    import matplotlib.patches as mpatches
    from matplotlib.ticker import MaxNLocator

    name, origin = _reference(orbits[0])
    tracks = [track - origin for track in _tracks(orbits)]
    centre, half = _window(tracks)
    planar = max(float(np.max(np.abs(track[:, 2]))) for track in tracks) <= PLANAR * half
    unit, scale = frame.length_unit(half)
    if half * scale >= 1e4:  # five-digit ticks collide where the 3-D view's axes meet: count in thousands
        unit, scale = frame.length_unit(half, u.CompositeUnit(1e3, [unit], [1]))
    system = orbits[0].system
    bodies = [(body, where - origin, radius, colour) for body, where, radius, colour in _bodies(system, centre, half)]
    points = system.positions.to_value(u.m) - origin
    if planar:
        axes = [fig.add_subplot(1, 1, 1)]
        views = (((0, 1), "the binary's plane (the orbit stays in it)"),)
    else:
        axes = [fig.add_subplot(2, 2, 1, projection="3d")] + [fig.add_subplot(2, 2, k) for k in (2, 3, 4)]
        views = VIEWS
    text = display.unit_math(unit)
    inside = [k for k, p in enumerate(points) if np.all(np.abs(p - centre) <= half)]
    if not planar:
        view = axes[0]
        for track, colour, label in zip(tracks, colours, labels):
            view.plot(*(track.T * scale), color=colour, lw=0.8, label=label)
        for _, where, radius, colour in bodies:
            if np.all(np.abs(where - centre) <= half + radius):
                _sphere(view, where * scale, radius * scale, colour)
        for k in inside:
            view.plot(*(points[k][:, None] * scale), marker="x", color="C3", ls="none")
        for limit, c in zip((view.set_xlim3d, view.set_ylim3d, view.set_zlim3d), centre):
            limit((c - half) * scale, (c + half) * scale)
        view.set_box_aspect((1, 1, 1), zoom=0.85)  # the labels inside the panel
        for axis_name, axis in zip(_NAMES, (view.xaxis, view.yaxis, view.zaxis)):
            axis.set_major_locator(MaxNLocator(3))  # tick labels apart where two axes meet
            axis.set_label_text(f"{axis_name} [{text}]")
            axis.labelpad = 22
        view.set_title(f"3-D, rotating frame, from {name}", fontsize="medium")
    for ax, ((i, j), caption) in zip(axes[0 if planar else 1:], views):
        for track, colour, label in zip(tracks, colours, labels):
            ax.plot(track[:, i] * scale, track[:, j] * scale, color=colour, lw=0.8,
                    label=label if planar else None)
        for _, where, radius, colour in bodies:
            if not np.all(np.abs(where - centre) <= half + radius):
                continue  # outside the window (in the projected-out coordinate too): not in front of the orbits
            ax.add_patch(mpatches.Circle((where[i] * scale, where[j] * scale), radius * scale, facecolor=colour,
                                         edgecolor="0.4", zorder=3))
            if radius < 0.01 * half:
                ax.plot(where[i] * scale, where[j] * scale, marker="o", ms=4, color=colour, mec="0.3", zorder=3)
        spots = _projected_points(points, centre, half, (i, j))
        for a, b in spots:
            ax.plot(a * scale, b * scale, marker="x", color="C3", ls="none", zorder=4)
        ax.set_xlim((centre[i] - half) * scale, (centre[i] + half) * scale)
        ax.set_ylim((centre[j] - half) * scale, (centre[j] + half) * scale)
        ax.set_aspect("equal")
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(MaxNLocator(5))  # tick labels apart at any length unit
        ax.set_xlabel(f"{_NAMES[i]} from {name} [{text}]")
        ax.set_ylabel(f"{_NAMES[j]} from {name} [{text}]")
        ax.set_title(caption, fontsize="medium")
        ax.grid(alpha=0.3)
        frame.labels_apart(ax, [(", ".join(names), (a * scale, b * scale), dict(fontsize="small"))
                                for (a, b), names in spots.items()])
    shown = [body for body in bodies if np.all(np.abs(body[1] - centre) <= half + body[2])]
    names = [f"{body} (to scale, radius {display.quantity_math(radius << u.m, digits=4)})" if radius > 0 else body
             for body, _, radius, _ in shown]
    handles = [mpatches.Patch(facecolor=colour, edgecolor="0.4", label=body)
               for body, (_, _, _, colour) in zip(names, shown)]
    handles.append(axes[0].plot([], [], marker="x", color="C3", ls="none", label="Lagrange points")[0])
    fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize="small", frameon=False)
    if not planar:
        frame.labels_apart(axes[0], [(f"L{k + 1}", points[k] * scale, dict(fontsize="small")) for k in inside])
    frame.title(fig, title, size="large")
    return axes


def _projected_points(points, centre, half, axes) -> dict:
    """{(a, b): ["L1", ...]}: the Lagrange points inside the window, projected onto `axes`, those that fall on one
    spot (L1, L2 and L3 seen along x) named together."""
    spots = {}
    for k, p in enumerate(points):
        if np.all(np.abs(p - centre) <= half):
            key = tuple(round(float(p[a]) / half, 6) * half for a in axes)
            spots.setdefault(key, []).append(f"L{k + 1}")
    return spots


def _sphere(ax, centre, radius, colour):
    """A body to scale in a 3-D view: a sphere's surface."""
    if radius <= 0.0:
        ax.plot(*(centre[:, None]), marker="o", ms=4, color=colour, mec="0.3", ls="none")
        return
    a, b = np.meshgrid(np.linspace(0.0, 2.0 * np.pi, 25), np.linspace(0.0, np.pi, 13))
    ax.plot_surface(centre[0] + radius * np.cos(a) * np.sin(b), centre[1] + radius * np.sin(a) * np.sin(b),
                    centre[2] + radius * np.cos(b), color=colour, alpha=0.8, linewidth=0)


def periodic_orbit(orbit: Any, fig: Any = None) -> tuple[Any, np.ndarray]:
    """An orbits.PeriodicOrbit over one period in the rotating frame: 3-D and the x-y, x-z and y-z projections, the
    primaries to scale and the Lagrange points within the window marked; a planar orbit in its plane alone. Returns
    (figure, its axes: four, or one for a planar orbit)."""
    planar = orbit.family == "lyapunov" or orbit.family == "dro"
    fig = frame.figure(fig, (8.5, 8.0) if planar else (12.5, 10.5))
    title = (f"{orbit.describe()} orbit: T = {display.quantity_math(orbit.period, digits=5)}, "
             f"C = {display.number(orbit.dimensionless_jacobi_constant, 7)} (units of $(n\\,r)^2$)")
    return fig, np.array(_draw_views(fig, [orbit], ["C0"], [orbit.describe()], title))


def periodic_family(family: Any, fig: Any = None) -> tuple[Any, np.ndarray]:
    """An orbits.PeriodicFamily: its members in 3-D and in three projections (coloured by Jacobi constant, the
    primaries to scale, the Lagrange points marked) above its stability indices against the Jacobi constant
    (stability_diagram). Returns (figure, its five axes)."""
    import matplotlib as mpl

    fig = frame.figure(fig, (12.5, 15.5))
    top, bottom = fig.subfigures(2, 1, height_ratios=[2.0, 1.0])
    c = np.array([m.dimensionless_jacobi_constant for m in family.members])
    norm = mpl.colors.Normalize(c.min(), c.max() if c.max() > c.min() else c.min() + 1e-12)
    cmap = mpl.colormaps["viridis"]
    colours = [cmap(norm(value)) for value in c]
    title = f"{family.members[0].describe()} family: {len(family)} members to {family.end}"
    axes = _draw_views(top, list(family.members), colours, [None] * len(family), title)
    top.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), ax=axes, shrink=0.6, label="Jacobi constant C")
    ax = bottom.subplots()
    stability_diagram(family, ax)
    return fig, np.array(list(axes) + [ax])


def _continued(nu: np.ndarray) -> np.ndarray:
    """The members' index pairs (M, 2) reordered so that each index continues the one of the member before (the
    pairs come larger first, which would swap the curves where they cross)."""
    out = nu.copy()
    for k in range(1, len(out)):
        if abs(out[k, 0] - out[k - 1, 1]) + abs(out[k, 1] - out[k - 1, 0]) < \
                abs(out[k, 0] - out[k - 1, 0]) + abs(out[k, 1] - out[k - 1, 1]):
            out[k] = out[k, ::-1]
    return out


def stability_diagram(family: Any, ax: Any = None) -> tuple[Any, Any]:
    """The stability indices nu = lambda + 1 / lambda of a PeriodicFamily's members against their Jacobi constant, in
    the family's order (the curve folds back where C turns), on a symmetric-log axis (the band |nu| <= 2 where a
    pair is stable stays readable beside indices in the thousands), the lines nu = +-2, and each bifurcation
    marked where an index crosses them."""
    fig, ax = frame.axes(ax, figsize=(9.0, 5.0))
    c = np.array([m.dimensionless_jacobi_constant for m in family.members])
    nu = _continued(np.array([m.stability_indices for m in family.members]))
    for k, style in enumerate(("-", "--")):
        real = np.abs(nu[:, k].imag) <= 1e-9 * np.maximum(1.0, np.abs(nu[:, k]))
        ax.plot(c, nu[:, k].real, ls=style, marker=".", ms=4, lw=0.9, color=f"C{k}",
                label=f"$\\nu_{k + 1}$" + (" (real part where complex: hollow)" if not np.all(real) else ""))
        if not np.all(real):
            ax.plot(c[~real], nu[~real, k].real, ls="none", marker="o", mfc="none", color=f"C{k}")
    for level in (2.0, -2.0):
        ax.axhline(level, color="0.4", lw=0.8, ls=":")
    ax.axhspan(-2.0, 2.0, color="C2", alpha=0.08, label="$|\\nu| \\leq 2$: the pair is stable")
    markers = {"tangent": ("v", "C3", "a family branches off ($\\nu$ = 2)"),
               "period doubling": ("^", "C4", "period doubling ($\\nu$ = -2)")}
    shown = set()
    for kind, orbit in family.bifurcations:
        marker, colour, text = markers[kind]
        level = 2.0 if kind == "tangent" else -2.0
        ax.plot(orbit.dimensionless_jacobi_constant, level, marker=marker, ms=9, color=colour, ls="none",
                zorder=4, label=f"bifurcation: {text}" if kind not in shown else None)
        shown.add(kind)
    ax.set_yscale("symlog", linthresh=3.0)
    top = max(3.0, float(np.max(np.abs(nu.real))))
    ticks = [v for v in (1e4, 1e3, 1e2, 10.0, 2.0, 0.0) if v <= 1.5 * top]
    ax.set_yticks(sorted({*ticks, *(-v for v in ticks)}))
    ax.set_yticklabels([display.number_math(v, 3) for v in ax.get_yticks()])
    ax.set_xlabel("Jacobi constant C [$(n\\,r)^2$]")
    ax.set_ylabel("stability index $\\nu$")
    ax.grid(alpha=0.3)
    frame.legend_beside(ax)
    frame.title(ax, f"Stability of the {family.members[0].describe()} family: its {len(family)} members' indices "
                    f"$\\nu = \\lambda + 1/\\lambda$")
    return fig, ax
