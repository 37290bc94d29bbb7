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

from orbits import display
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


def flyby_plane(flyby: "Flyby", ax: Any = None, unit: u.UnitBase | None = None) -> tuple[Any, Any]:
    """Draw a single Flyby in its plane: the hyperbola about the focus, both asymptotes, the impact parameter b
    (the focus's distance from the incoming asymptote) and the closest approach; the title gives the deflection."""
    if flyby.shape != ():
        raise ValueError(f"flyby_plane draws one flyby; this Flyby holds {flyby.shape}: index it first")
    fig, ax = _axes(ax)
    orbit = flyby.orbit
    p, e = float(orbit.p), float(orbit.e)
    q, b = p / (1 + e), float(flyby.impact_parameter.si.value)
    a = p / (e * e - 1)  # |a|
    r_max = 4 * max(b, q)
    unit = unit or _length_unit(r_max)
    scale = u.m.to(unit)
    x, y = _conic_points(p, e, r_max)
    ax.plot(x * scale, y * scale, color="C0", lw=1.5, label=f"trajectory, e = {e:.4g}")
    ax.plot(0, 0, marker="*", ms=14, color="orange", ls="none", label="primary (focus)")
    ax.plot(q * scale, 0, marker="o", color="C3", ls="none", label=f"closest approach {q * scale:.4g} {unit}")
    nu_inf = np.arccos(-1 / e)
    centre = np.array([a * e, 0.0])
    reach = np.linspace(0, (a * e + r_max) * e, 2)  # from the hyperbola's centre out to x = -r_max
    for sign, name in ((-1, "incoming asymptote"), (1, "outgoing asymptote")):
        direction = np.array([np.cos(nu_inf), sign * np.sin(nu_inf)])
        line = centre[:, None] + direction[:, None] * reach
        ax.plot(line[0] * scale, line[1] * scale, ls="--", color="gray", lw=1, label=name)
    incoming = np.array([np.cos(nu_inf), -np.sin(nu_inf)])
    foot = centre + incoming * np.dot(-centre, incoming)  # nearest point of the incoming asymptote to the focus
    ax.plot(
        [0, foot[0] * scale],
        [0, foot[1] * scale],
        color="C2",
        lw=1.5,
        label=f"impact parameter b = {b * scale:.4g} {unit}",
    )
    ax.set_title(f"deflection {np.degrees(float(flyby.deflection_angle.to_value(u.rad))):.2f} deg")
    _finish_plane(ax, unit, "x toward closest approach")
    return fig, ax


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
    models: dict[str, "Cosmology"], t_max: u.Quantity, ax: Any = None, samples: int = 200
) -> tuple[Any, Any]:
    """a(t) against cosmic time for {label: Cosmology}, from the big bang to t_max (time Quantity)."""
    fig, ax = _axes(ax)
    unit = display.axis_unit(t_max)
    end = t_max.to_value(unit)
    times = np.linspace(end / samples, end, samples) * unit
    for label, model in models.items():
        ax.plot(times.to_value(unit), model.scale_factor(times).to_value(u.one), label=label)
    ax.axhline(1.0, color="gray", lw=0.8, ls=":")
    ax.set_xlabel(f"time since the big bang [{display.unit_text(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    return fig, ax


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
    """Position error |dr| / r_max against time, per scene and backend, on log axes (a ValidationReport)."""
    fig, ax = _axes(ax)
    for k, scene in enumerate(report.scenes):
        for j, (backend, series) in enumerate(scene.residuals.items()):
            times = scene.residual_times / scene.residual_times[-1]
            shown = np.where(series > 0, series, np.nan)  # an exact match has no place on a log axis
            ax.semilogy(times, shown, color=f"C{k}", ls=("-", "--", ":")[j % 3], label=f"{scene.name}: {backend}")
    ax.set_xlabel("time / scene span [dimensionless]")
    ax.set_ylabel("position error |dr| / r_max [dimensionless]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="best", fontsize="small", ncol=2)
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
