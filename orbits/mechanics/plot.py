"""Pictures of the mechanics of the notes: collisions in velocity space (IX), rolling down an incline (XI),
projectile paths (XX), pendulum periods, damped motion and the normal force round a vertical circle (XXV).

Each function takes the objects it draws ({label: object} or one object: an orbits Collision, Projectile, Pendulum,
DampedOscillator, VerticalCircle or Rolling) and reads their properties.
"""

from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame
from orbits.core.mechanics.oscillations import pendulum_period, pendulum_period_series


def _axes(ax):
    """(figure, axes): those of `ax`, or a new 6.4 x 4.8 inch figure."""
    return frame.axes(ax, figsize=(6.4, 4.8))


def _finish(ax, x_label, y_label, title):
    """Axis labels with units, a light grid, the legend below the axes, off the data, and the title."""
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    ax.grid(alpha=0.3)
    frame.legend_outside(ax)
    frame.title(ax, title)


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
    masses = " and ".join(display.quantity_math(np.ravel(m)[0] << u.kg, digits=4) for m in (collision.m1, collision.m2))
    restitution = display.number(float(np.ravel(collision.e)[0]), 3)
    _finish(ax, "$v_x$ [m/s]" if not head_on else "velocity along the line [m/s]", "$v_y$ [m/s]" if not head_on
            else "", f"{'Head-on' if head_on else 'Oblique'} collision of {masses}, restitution e = {restitution}: "
                     f"the velocities before and after")
    return fig, ax


def projectile_paths(projectiles: dict[str, Any], ax: Any = None, samples: int = 200) -> tuple[Any, Any]:
    """y against x for {label: Projectile} (XX), each from its launch to its landing point (dot), with its apex
    (triangle), in m; the title gives the launch (speed, angle, height) the projectiles share, or says it
    differs."""
    fig, ax = _axes(ax)
    for k, (label, shot) in enumerate(projectiles.items()):
        x, y = shot.path(samples)
        ax.plot(x.to_value(u.m), y.to_value(u.m), color=f"C{k}", label=label)
        ax.plot(shot.apex_distance.to_value(u.m), shot.apex_height.to_value(u.m), marker="^", color=f"C{k}",
                ls="none", gid="apex")
        ax.plot(shot.range.to_value(u.m), 0.0, marker="o", color=f"C{k}", ls="none", gid="landing")
    for marker, name in (("^", "apex"), ("o", "landing")):  # one gray entry each, the markers in their colours
        ax.plot([], [], marker=marker, color="0.3", ls="none", label=name)
    ax.axhline(0.0, color="gray", lw=0.8)
    ax.set_aspect("equal", adjustable="datalim")
    launches = {_launch_text(shot) for shot in projectiles.values()}
    launch = launches.pop() if len(launches) == 1 else "different launches"
    _finish(ax, "x [m]", "y [m]", f"{'Projectile' if len(projectiles) == 1 else 'Projectiles'} launched at {launch}: "
                                  f"{_names(projectiles)}, from launch to landing")
    return fig, ax


def _launch_text(shot: Any) -> str:
    """"30 m/s, 60 deg above the horizontal" (and the height, when not from the ground)."""
    height = float(np.ravel(shot.height)[0])
    return (f"{display.quantity_math(np.ravel(shot.speed)[0] << u.m / u.s, digits=4, unit=u.m / u.s)}, "
            f"{display.quantity_math(np.ravel(shot.angle)[0] << u.rad, digits=4)} above the horizontal"
            + (f" from {display.quantity_math(height << u.m, digits=4, unit=u.m)}" if height else ""))


def _names(items: dict[str, Any]) -> str:
    """The labels of {label: object} as a title lists them."""
    names = list(items)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def pendulum_periods(pendulum: Any = None, ax: Any = None, samples: int = 400) -> tuple[Any, Any]:
    """T / T0 against the amplitude up to 179 deg: exact (AGM), and the series 1 + theta0**2 / 16 (XXV.iv); a
    given Pendulum is marked."""
    fig, ax = _axes(ax)
    amplitude = np.linspace(0.0, np.radians(179.0), samples)
    ax.plot(np.degrees(amplitude), pendulum_period(1.0, amplitude) / (2 * np.pi), color="C0",
            label=r"exact: $2K(m)/\pi$, $m = \sin^2(\theta_0/2)$")
    ax.plot(np.degrees(amplitude), pendulum_period_series(amplitude, 2), color="C1", ls="--",
            label=r"series: $1 + \theta_0^2/16$")
    title = "Period of a pendulum against its amplitude, in units of its small-angle period"
    if pendulum is not None:
        ax.plot(pendulum.amplitude_angle.to_value(u.deg), pendulum.period_ratio.value, marker="o", color="k",
                ls="none", label="this pendulum")
        title += (f"\nthis pendulum: $\\theta_0$ = {display.quantity_math(pendulum.amplitude_angle, digits=4)}, "
                  f"T = {display.quantity_math(pendulum.period, digits=4)} "
                  f"($T_0$ = {display.quantity_math(pendulum.small_angle_period, digits=4)})")
    _finish(ax, r"amplitude $\theta_0$ [deg]", "period / small-angle period [dimensionless]", title)
    return fig, ax


def damped_motion(oscillators: dict[str, Any], duration: u.Quantity, ax: Any = None,
                  samples: int = 400) -> tuple[Any, Any]:
    """x(t) for {label: DampedOscillator} over `duration` (XXV.v), sampled `samples` times or, for fast
    oscillations, PER_PERIOD times per damped period (at most MAX_SAMPLES in all), so every swing shows."""
    fig, ax = _axes(ax)
    seconds = duration.to_value(u.s)
    fastest = max(float(np.max(oscillator.damped_frequency.to_value(u.rad / u.s))) for oscillator in
                  oscillators.values())
    count = int(min(MAX_SAMPLES, max(samples, np.ceil(PER_PERIOD * seconds * fastest / (2 * np.pi)) + 1)))
    times = np.linspace(0.0, seconds, count) << u.s
    for k, (label, oscillator) in enumerate(oscillators.items()):
        ax.plot(times.value, oscillator.position_at(times).to_value(u.m), color=f"C{k}",
                label=f"{label} ({oscillator.regime})")
    ax.axhline(0.0, color="gray", lw=0.8)
    _finish(ax, "t [s]", "x [m]", f"Damped {'oscillator' if len(oscillators) == 1 else 'oscillators'} "
                                  f"{_names(oscillators)}: x(t) over {display.quantity_math(duration, digits=4)}")
    return fig, ax


#: samples per damped period drawn, and the most drawn in all
PER_PERIOD, MAX_SAMPLES = 40, 100_000


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
                    color=color, label=f"{label}: {mark} at {display.number(np.degrees(end), 4)} deg")
    ax.axhline(0.0, color="gray", lw=0.8)
    ax.set_xlim(-180.0, 180.0)
    ax.set_xticks(np.arange(-180, 181, 60))
    radii = {display.quantity_math(np.ravel(circle.radius)[0] << u.m, digits=4) for circle in circles.values()}
    _finish(ax, "angle from the lowest point [deg]", "normal force N / (m g) [dimensionless]",
            f"Normal force round a vertical circle{' of radius ' + radii.pop() if len(radii) == 1 else 's'}"
            + (f": {_names(circles)}" if len(circles) == 1 else ""))
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
        ax.plot(t, 0.5 * a * t * t, color=f"C{k}", label=f"{label} (k = {display.number(float(rolling.factor), 3)})")
    inclines = {display.quantity_math(np.ravel(rolling.incline)[0] << u.rad, digits=4) for rolling in rollings.values()}
    _finish(ax, "t [s]", "distance down the incline [m]",
            f"Rolling down {'a ' + inclines.pop() + ' incline' if len(inclines) == 1 else 'inclines'}: "
            f"{_names(rollings)} over the first {display.quantity_math(length, digits=4)}")
    return fig, ax
