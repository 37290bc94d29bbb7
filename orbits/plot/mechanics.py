"""Pictures of the mechanics of the notes: collisions in velocity space (IX), rolling down an incline (XI),
projectile paths (XX), pendulum periods, damped motion and the normal force round a vertical circle (XXV).

Each function takes the objects it draws ({label: object} or one object: an orbits Collision, Projectile, Pendulum,
DampedOscillator, VerticalCircle or Rolling) and reads their properties.
"""

from typing import Any

import astropy.units as u
import numpy as np

from orbits.core.oscillations import pendulum_period, pendulum_period_series
from orbits.plot import frame


def _axes(ax):
    """(figure, axes): those of `ax`, or a new 6.4 x 4.8 inch figure."""
    return frame.axes(ax, figsize=(6.4, 4.8))


def _finish(ax, x_label, y_label):
    """Axis labels with units, a light grid and the legend below the axes, off the data."""
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    ax.grid(alpha=0.3)
    frame.legend_outside(ax)


def collision_velocities(collision: Any, ax: Any = None) -> tuple[Any, Any]:
    """The velocities before (solid, round tip) and after (dashed, square tip) a collision as arrows in velocity
    space, with the centre-of-mass velocity (IX). A head-on collision's arrows lie along the line, one row each;
    an oblique one's are drawn from the origin, tips marked so that collinear arrows and zero vectors show."""
    fig, ax = _axes(ax)

    def planar(q):
        v = np.asarray(q.to_value(u.m / u.s), dtype=float)
        return np.array([float(v), 0.0]) if v.ndim == 0 else v[:2]

    arrows = [("body 1 before", collision.v1 << u.m / u.s, "C0", "-", "o"),
              ("body 2 before", collision.v2 << u.m / u.s, "C1", "-", "o"),
              ("body 1 after", collision.velocity1_after, "C0", "--", "s"),
              ("body 2 after", collision.velocity2_after, "C1", "--", "s")]
    head_on = not collision.vectors
    rows = (0.3, 0.1, -0.1, -0.3)  # a head-on collision's arrows, one row each, all along v_x
    tips = []
    for k, (label, velocity, color, style, marker) in enumerate(arrows):
        x, y = planar(velocity)
        base = rows[k] if head_on else 0.0
        width = 2.6 if style == "-" else 1.4  # a dashed "after" arrow over a solid one stays visible
        ax.plot([0.0, x], [base, y + base], color=color, ls=style, lw=width, marker=marker, markevery=[1],
                ms=7 if marker == "o" else 5, label=label + (" (at rest)" if x == 0 and y == 0 else ""))
        if x or y:
            ax.annotate("", xy=(x, y + base), xytext=(0.0, base), arrowprops=dict(arrowstyle="-|>", color=color,
                                                                                   lw=0))
        tips.append((x, y + base))
    center = planar(collision.center_of_mass_velocity)
    tips = np.array(tips + [tuple(center), (0.0, 0.0)])
    if head_on:
        ax.axvline(center[0], color="k", ls=":", lw=1.2, label="centre-of-mass velocity")
        ax.set_ylim(-0.5, 0.5)
        ax.set_yticks(rows, ["body 1 before", "body 2 before", "body 1 after", "body 2 after"])
        span = max(np.ptp(tips[:, 0]), 1e-300)
        ax.set_xlim(tips[:, 0].min() - 0.15 * span, tips[:, 0].max() + 0.15 * span)
    else:
        ax.plot(*center, marker="+", ms=12, color="k", ls="none", label="centre-of-mass velocity")
        middle, half = 0.5 * (tips.min(axis=0) + tips.max(axis=0)), 0.6 * max(np.ptp(tips[:, 0]), np.ptp(tips[:, 1]),
                                                                            1e-300)
        ax.set_xlim(middle[0] - half, middle[0] + half)
        ax.set_ylim(middle[1] - half, middle[1] + half)
        ax.set_aspect("equal", adjustable="box")  # square limits: nothing for matplotlib to override
    ax.set_title(f"restitution e = {float(np.ravel(collision.e)[0]):.3g}", fontsize="medium")
    _finish(ax, "v_x [m / s]" if not head_on else "velocity along the line [m / s]", "v_y [m / s]" if not head_on
            else "")
    return fig, ax


def projectile_paths(projectiles: dict[str, Any], ax: Any = None, samples: int = 200) -> tuple[Any, Any]:
    """y against x for {label: Projectile} (XX), each with its apex (triangle) and landing point (dot), in m."""
    fig, ax = _axes(ax)
    for k, (label, shot) in enumerate(projectiles.items()):
        x, y = shot.path(samples)
        ax.plot(x.to_value(u.m), y.to_value(u.m), color=f"C{k}", label=label)
        ax.plot(shot.apex_distance.to_value(u.m), shot.apex_height.to_value(u.m), marker="^", color=f"C{k}",
                ls="none")
        ax.plot(shot.range.to_value(u.m), 0.0, marker="o", color=f"C{k}", ls="none")
    ax.axhline(0.0, color="gray", lw=0.8)
    ax.set_aspect("equal", adjustable="datalim")
    _finish(ax, "x [m]", "y [m]")
    return fig, ax


def pendulum_periods(pendulum: Any = None, ax: Any = None, samples: int = 400) -> tuple[Any, Any]:
    """T / T0 against the amplitude up to 179 deg: exact (AGM), and the series 1 + theta0**2 / 16 (XXV.iv); a
    given Pendulum is marked."""
    fig, ax = _axes(ax)
    amplitude = np.linspace(0.0, np.radians(179.0), samples)
    ax.plot(np.degrees(amplitude), pendulum_period(1.0, amplitude) / (2 * np.pi), color="C0",
            label="exact: 4 K(sin^2(theta0 / 2)) / (2 pi)")
    ax.plot(np.degrees(amplitude), pendulum_period_series(amplitude, 2), color="C1", ls="--",
            label="1 + theta0^2 / 16")
    if pendulum is not None:
        ax.plot(pendulum.amplitude_angle.to_value(u.deg), pendulum.period_ratio.value, marker="o", color="k",
                ls="none", label="this pendulum")
    _finish(ax, "amplitude theta0 [deg]", "period / small-angle period [dimensionless]")
    return fig, ax


def damped_motion(oscillators: dict[str, Any], duration: u.Quantity, ax: Any = None,
                  samples: int = 400) -> tuple[Any, Any]:
    """x(t) for {label: DampedOscillator} over `duration` (XXV.v)."""
    fig, ax = _axes(ax)
    times = np.linspace(0.0, duration.to_value(u.s), samples) << u.s
    for k, (label, oscillator) in enumerate(oscillators.items()):
        ax.plot(times.value, oscillator.position_at(times).to_value(u.m), color=f"C{k}",
                label=f"{label} ({oscillator.regime})")
    ax.axhline(0.0, color="gray", lw=0.8)
    _finish(ax, "t [s]", "x [m]")
    return fig, ax


def vertical_circle_forces(circles: dict[str, Any], ax: Any = None,
                           samples: int = 721) -> tuple[Any, Any]:
    """N / (m g) against the angle from the lowest point (-180 to 180 deg) for {label: VerticalCircle} (XXV.vi),
    over the arc each body follows on the circle: all of it when looping, up to the turning angle when swinging
    (marked), and up to where a string slackens (N = 0, marked): beyond it the body is in free flight, off the
    circle. A rod's N < 0 pushes outward."""
    fig, ax = _axes(ax)
    theta = np.linspace(-np.pi, np.pi, samples)
    for k, (label, circle) in enumerate(circles.items()):
        color = f"C{k}"
        regime = circle.regime
        if regime == "leaves the circle":
            end = circle.leaving_angle.to_value(u.rad)
        elif regime in ("swings", "reaches the top", "at rest"):
            end = circle.turning_angle.to_value(u.rad)
        else:
            end = np.pi
        arc = theta[np.abs(theta) <= end]
        arc = np.unique(np.concatenate([arc, [-end, end]]))
        force = circle.normal_force_at(arc << u.rad).to_value(u.N) / (circle.mass * circle.g)
        ax.plot(np.degrees(arc), force, color=color, label=f"{label}: {regime}")
        if end < np.pi:
            ends = circle.normal_force_at(np.array([-end, end]) << u.rad).to_value(u.N) / (circle.mass * circle.g)
            mark = "leaves the circle (N = 0)" if regime == "leaves the circle" else "turns back (v = 0)"
            ax.plot(np.degrees([-end, end]), ends, ls="none", marker="v" if regime == "leaves the circle" else "o",
                    color=color, label=f"{label}: {mark} at {np.degrees(end):.1f} deg")
    ax.axhline(0.0, color="gray", lw=0.8)
    ax.set_xlim(-180.0, 180.0)
    ax.set_xticks(np.arange(-180, 181, 60))
    _finish(ax, "angle from the lowest point [deg]", "normal force N / (m g) [dimensionless]")
    return fig, ax


def rolling_race(rollings: dict[str, Any], length: u.Quantity, ax: Any = None,
                 samples: int = 200) -> tuple[Any, Any]:
    """Distance down an incline against time for {label: Rolling} (XI), each until it has covered `length`."""
    fig, ax = _axes(ax)
    distance = length.to_value(u.m)
    for k, (label, rolling) in enumerate(rollings.items()):
        a = rolling.acceleration.to_value(u.m / u.s**2)
        end = np.sqrt(2 * distance / a)
        t = np.linspace(0.0, end, samples)
        ax.plot(t, 0.5 * a * t * t, color=f"C{k}", label=f"{label} (k = {float(rolling.factor):.3g})")
    _finish(ax, "t [s]", "distance down the incline [m]")
    return fig, ax
