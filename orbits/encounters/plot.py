"""Two bodies meeting or bound: a flyby in its plane (flyby_plane, collision_note), and a binary in its plane, on
the sky and in radial velocity (binary_plane, binary_sky, radial_velocity_curves).

Each function takes the object it draws (an orbits.Flyby or orbits.Binary of shape ()) and reads its properties.
"""

import warnings
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame, inputs, units
from orbits.core.twobody import elements
from orbits.twobody.plot import (
    CIRCULAR,
    InsideBodyWarning,
    catalogue_body,
    conic_points,
    draw_primary,
    eccentricity_text,
    primary_color,
)

# ---- flybys --------------------------------------------------------------------------------------------------


def flyby_plane(flyby: Any, ax: Any = None, unit: u.UnitBase | None = None) -> tuple[Any, Any]:
    """Draw a single Flyby in its plane: the hyperbola about the focus within 4 max(b, q) of it with an arrow along
    the motion, both asymptotes there (incoming dashed, outgoing dotted), the impact parameter b (the focus's
    distance from the incoming asymptote), the closest approach, and the primary as a disc to scale; the title
    names the bodies, v_inf and the deflection. A closest approach inside the bodies (the primary's radius, plus
    the secondary's for Flyby.between) gives an InsideBodyWarning and a red note."""
    if flyby.shape != ():
        raise ValueError(f"flyby_plane draws one flyby; this Flyby holds {flyby.shape}: index it first")
    fig, ax = frame.axes_for(ax, "xy")
    orbit = flyby.orbit
    p, e = float(orbit.p), float(orbit.e)
    q, b = p / (1 + e), float(flyby.impact_parameter.si.value)
    r_max = 4 * max(b, q)
    unit, scale = frame.length_unit(r_max, unit)
    x, y = conic_points(p, e, r_max)
    ax.plot(x * scale, y * scale, color="C0", lw=1.5, label=f"trajectory, e = {eccentricity_text(e)}")
    ahead = int(np.argmin(np.abs(np.hypot(x, y)[: len(x) // 2] - 0.5 * r_max)))  # an arrow along the motion,
    # half way in on the incoming branch
    ax.annotate("", xy=(x[ahead + 1] * scale, y[ahead + 1] * scale), xytext=(x[ahead] * scale, y[ahead] * scale),
                arrowprops=dict(arrowstyle="-|>", color="C0", lw=1.5, mutation_scale=16))
    ax.plot(q * scale, 0, marker="o", color="C3", ls="none",
            label=f"closest approach {display.quantity_math(q << u.m, digits=4)}")
    nu_inf = float(flyby.asymptote_true_anomaly.to_value(u.rad))
    reach = np.sqrt(r_max**2 - b**2)  # the asymptotes pass b from the focus; draw them within r_max of it
    centre = np.array([p / (e * e - 1) * e, 0.0])  # the hyperbola's centre, a e beyond the focus
    feet = {}
    for sign, name, style in ((-1, "incoming asymptote", dict(ls="--", color="0.45")),
                              (1, "outgoing asymptote", dict(ls=":", color="0.2"))):
        direction = np.array([np.cos(nu_inf), sign * np.sin(nu_inf)])  # outward along the asymptote
        feet[name] = centre + direction * np.dot(-centre, direction)  # its nearest point to the focus
        line = feet[name][:, None] + direction[:, None] * np.array([-reach, reach])
        ax.plot(line[0] * scale, line[1] * scale, lw=1.1, label=name, gid=name, **style)
    foot = feet["incoming asymptote"]
    ax.plot([0, foot[0] * scale], [0, foot[1] * scale], color="C2", lw=1.5,
            label=f"impact parameter b = {display.quantity_math(b << u.m, digits=4)}")
    bodies = _bodies(flyby)
    draw_primary(ax, bodies[0], (0, 1), scale, r_max)
    semi_axis = p / (e * e - 1)
    if semi_axis > r_max:  # the arc drawn here is still far from its asymptotes
        ax.plot([], [], ls="none", label=f"(the track meets its asymptotes only beyond |a| = "
                                          f"{display.quantity_math(semi_axis << u.m, digits=3)})")
    radius = sum(body.radius for body in bodies if body is not None)
    if 5 * max(q, radius) < 0.05 * r_max:
        _periapsis_inset(ax, p, e, q, bodies[0], radius)
    deflection = display.number(np.degrees(float(flyby.deflection_angle.to_value(u.rad))), 5)
    lines = [f"{_flyby_text(flyby, bodies)}: $v_\\infty$ = {display.quantity_math(flyby.speed_at_infinity, digits=4)}, "
             f"deflection {deflection} deg"]
    note = _collision_note(q, bodies)
    if note:
        warnings.warn(note, InsideBodyWarning, stacklevel=2)
        lines.append(_collision_note(q, bodies, display.quantity_math))
    frame.finish_plane(ax, unit, "x toward closest approach")
    frame.legend_beside(ax)
    frame.title(ax, "\n".join(lines), color="C3" if note else "k")
    return fig, ax


def _flyby_text(flyby: Any, bodies: list) -> str:
    """"Flyby past Jupiter", "Flyby of Jupiter past the Sun", or by GM where the catalogue lacks a body."""
    names = [frame.in_a_sentence(body.name) if body is not None else display.body_name(gm)
             for body, gm in zip(bodies, (flyby.gm1 if flyby.gm1 is not None else flyby.mu, flyby.gm2))]
    return f"Flyby of {names[1]} past {names[0]}" if len(names) == 2 else f"Flyby past {names[0]}"


def _bodies(flyby):
    """[the primary's catalogue Body, the secondary's for Flyby.between]; None for a GM the catalogue lacks."""
    bodies = [catalogue_body(flyby.gm1 if flyby.gm1 is not None else flyby.mu)]
    if flyby.gm2 is not None:
        bodies.append(catalogue_body(flyby.gm2))
    return bodies


def _periapsis_inset(ax, p, e, q, body, radius):
    """An inset (top right, above the outgoing asymptote) around the closest approach, where the main picture is
    too coarse to show it: the track within 5 max(q, R) of the focus, the primary to scale and the closest
    approach, in the natural unit of that size."""
    half = 5 * max(q, radius)
    unit, scale = frame.length_unit(half)
    unit_text = display.unit_math(unit)
    if body is not None:  # in radii of the primary: small numbers, and its size read off at once
        scale, unit_text = 1.0 / body.radius, f"{body.name} radii"
    inset = ax.inset_axes([0.66, 0.66, 0.31, 0.31])
    x, y = conic_points(p, e, 1.5 * half)
    inset.plot(x * scale, y * scale, color="C0", lw=1.2)
    if body is not None:
        import matplotlib.patches as mpatches

        inset.add_patch(mpatches.Circle((0, 0), body.radius * scale, facecolor=primary_color(body),
                                        edgecolor="0.4", alpha=0.8))
    inset.plot(q * scale, 0, marker="o", ms=4, color="C3", ls="none")
    inset.set_xlim(-half * scale, half * scale)
    inset.set_ylim(-half * scale, half * scale)
    inset.set_aspect("equal")
    inset.tick_params(labelsize="x-small")
    inset.set_title(f"near closest approach [{unit_text}]", fontsize="x-small")


def collision_note(flyby: Any) -> str | None:
    """A sentence when the flyby's closest approach is inside the bodies (catalogue radii; the two radii added for
    Flyby.between), else None. E.g. "closest approach 8.4e+04 km is inside the Sun (radius 6.957e+05 km)"."""
    if flyby.shape != ():
        raise ValueError(f"collision_note checks one flyby; this Flyby holds {flyby.shape}: index it first")
    return _collision_note(float(flyby.periapsis_distance.to_value(u.m)), _bodies(flyby))


def _collision_note(q, bodies, written=display.quantity_text):
    """The note for closest approach q (m) among the known `bodies` (None for unknown ones), or None; quantities
    written by `written` (an orbits._common.display formatter: quantity_text, or quantity_math in a picture)."""
    known = [body for body in bodies if body is not None]
    if not known:
        return None
    reach = sum(body.radius for body in known)
    if q >= reach:
        return None
    names = " and ".join(frame.in_a_sentence(body.name) for body in known)
    what = f"inside {names}" if len(known) == 1 else f"inside the radii of {names} added"
    return (f"closest approach {written(q << u.m, digits=4)} is {what} "
            f"({written(reach << u.m, digits=4)}): they collide")


# ---- binaries ------------------------------------------------------------------------------------------------


def binary_plane(binary: Any, ax: Any = None, unit: u.UnitBase | None = None) -> tuple[Any, Any]:
    """Draw a single Binary in its orbital plane: both stars' ellipses about the centre of mass, the stars at t0
    (their true anomaly) and the line joining them; the title names the masses and the orbit."""
    if binary.shape != ():
        raise ValueError(f"binary_plane draws one binary; this Binary holds {binary.shape}: index it first")
    fig, ax = frame.axes(ax)
    relative = binary.relative
    p, e, nu = float(relative.p), float(relative.e), float(relative.nu)
    share2 = float(binary.mass_fraction.to_value(u.one))  # star 2 sits at (1 - x2) r, star 1 at -x2 r
    unit, scale = frame.length_unit(p / (1 - e), unit)
    x, y = conic_points(p, e, np.inf)
    r_now = p / (1 + e * np.cos(nu)) * np.array([np.cos(nu), np.sin(nu)])
    small = share2 < SMALL_ORBIT * (1 - share2)  # star 1's orbit under a few pixels: drawn again in an inset
    for k, (share, color) in enumerate(((-share2, "C0"), (1 - share2, "C1"))):
        label = f"star {k + 1} ({_mass(binary, k)})"
        if k == 0 and small:
            ax.plot([], [], color=color, lw=1.5, label=label + ", enlarged in the inset")  # the legend's entry
        else:
            ax.plot(share * x * scale, share * y * scale, color=color, lw=1.5, label=label)
        ax.plot(share * r_now[0] * scale, share * r_now[1] * scale, marker="o", color=color, ls="none",
                gid=f"star {k + 1} at t0")
    if small:
        _star1_inset(ax, binary, x, y, r_now, share2)
    ax.plot(
        [-share2 * r_now[0] * scale, (1 - share2) * r_now[0] * scale],
        [-share2 * r_now[1] * scale, (1 - share2) * r_now[1] * scale],
        color="gray",
        lw=1,
        label=f"the line joining the stars (dots) at t0, $\\nu$ = {display.quantity_math(nu << u.rad, digits=4)}",
        gid="joining line",
    )
    ax.plot(0, 0, marker="+", ms=12, color="k", ls="none", label="centre of mass")
    frame.finish_plane(ax, unit, "x toward periapsis")
    frame.legend_outside(ax)
    frame.title(ax, f"A binary about its centre of mass, the stars at t0\n{_binary_text(binary)}")
    return fig, ax


#: star 1's orbit gets an inset when it is smaller than this fraction of star 2's
SMALL_ORBIT = 0.04


def _star1_inset(ax: Any, binary: Any, x: np.ndarray, y: np.ndarray, r_now: np.ndarray, share2: float) -> None:
    """Star 1's orbit about the centre of mass, too small to see beside star 2's, enlarged in an inset at the
    centre of the frame with a length scale of its own."""
    from matplotlib.ticker import MaxNLocator

    size = share2 * float(np.max(np.hypot(x[np.isfinite(x)], y[np.isfinite(y)])))
    unit, scale = frame.length_unit(size)
    inset = ax.inset_axes([0.36, 0.36, 0.28, 0.28])
    inset.plot(-share2 * x * scale, -share2 * y * scale, color="C0", lw=1.5, label=f"star 1 ({_mass(binary, 0)})")
    inset.plot(-share2 * r_now[0] * scale, -share2 * r_now[1] * scale, marker="o", color="C0", ls="none")
    inset.plot(0, 0, marker="+", ms=8, color="k", ls="none")
    inset.set_aspect("equal", adjustable="datalim")
    inset.tick_params(labelsize="x-small")
    for axis in (inset.xaxis, inset.yaxis):
        axis.set_major_locator(MaxNLocator(3, symmetric=True))
    inset.set_title(f"star 1 [{display.unit_math(unit)}]", fontsize="x-small")
    inset.grid(alpha=0.3)


def _mass(binary: Any, k: int) -> str:
    """Star k's (0 or 1) mass, typeset in its natural unit."""
    return display.quantity_math((binary.mass1, binary.mass2)[k], digits=4)


def _binary_text(binary: Any) -> str:
    """"1.1 M$_\\odot$ + 0.8 M$_\\odot$, a = 8.5 AU, e = 0.5, P = 20 yr": a binary as a title names it."""
    relative = binary.relative
    return (f"{_mass(binary, 0)} + {_mass(binary, 1)}, a = {display.quantity_math(relative.semi_major_axis, digits=4)}"
            f", e = {display.number(float(relative.e), 4)}, P = {display.quantity_math(binary.period, digits=4)}")


def _sky_unit(size_m, distance_m):
    """(unit, metres -> unit factor) of a sky picture: a length unit, or with a distance an angle (arcsec or mas,
    small angles: offset / distance rad)."""
    if distance_m is None:
        return frame.length_unit(size_m)
    unit = u.mas if size_m / distance_m < 1 * u.arcsec.to(u.rad) else u.arcsec
    return unit, u.rad.to(unit) / distance_m


def binary_sky(binary: Any, ax: Any = None, distance: u.Quantity | None = None,
               samples: int = 721) -> tuple[Any, Any]:
    """The apparent orbit of star 2 about star 1 on the sky, north up and east to the LEFT (as the sky is seen): the
    relative orbit r2 - r1 projected along the line of sight, star 1 at the origin, star 2 now with an arrow along
    its motion across the sky (none where it moves along the line of sight), periastron, the line of nodes (position
    angle Omega) with the ascending node (where star 2 recedes) and the descending node. Offsets in a length unit,
    or in arcsec (mas) given the `distance`.

    Elements in the sky frame of orbits.encounters.binary (x north, y east, z away from the observer). The projected
    ellipse
    has area pi a b |cos i| (tests/api/test_binary_observables.py).
    """
    if binary.shape != ():
        raise ValueError(f"binary_sky draws one binary; this Binary holds {binary.shape}: index it first")
    rel = binary.relative
    rel._require_ellipse("an apparent orbit")
    fig, ax = frame.axes(ax)
    p, e, inc, raan, argp = (float(x) for x in (rel.p, rel.e, rel.inc, rel.raan, rel.argp))
    mu = float(rel.mu)

    def sky(nu):
        r, v = elements.elements_to_state(p, e, inc, raan, argp, np.asarray(nu, dtype=float), mu)
        return r, v

    distance_m = None if distance is None else inputs.single(inputs.positive, distance, units.M, "distance")
    unit, scale = _sky_unit(p / (1 - e), distance_m)
    track, _ = sky(np.linspace(-np.pi, np.pi, samples))
    east, north = track[..., 1] * scale, track[..., 0] * scale
    ax.plot(east, north, color="C0", lw=1.5, label="apparent orbit of star 2")
    ax.plot(0, 0, marker="*", ms=14, color="gold", mec="0.3", ls="none", label="star 1")
    reach = 1.15 * np.max(np.hypot(east, north))
    node = np.array([np.sin(raan), np.cos(raan)]) * reach  # (east, north) along position angle Omega
    ax.plot([-node[0], node[0]], [-node[1], node[1]], color="gray", ls="--", lw=1, gid="line of nodes",
            label=f"line of nodes, position angle {display.number(np.degrees(raan) % 360, 4)} deg")
    nodes, _ = sky(np.array([-argp, np.pi - argp]))
    ax.plot(nodes[0, 1] * scale, nodes[0, 0] * scale, marker="^", ms=8, color="C3", ls="none",
            gid="ascending node", label="ascending node (receding)")
    ax.plot(nodes[1, 1] * scale, nodes[1, 0] * scale, marker="v", ms=8, color="C2", ls="none",
            gid="descending node", label="descending node (approaching)")
    if e > CIRCULAR:
        peri, _ = sky(0.0)
        ax.plot(peri[1] * scale, peri[0] * scale, marker="o", mfc="none", color="C0", ls="none", gid="periastron",
                label="periastron")
    now_r, now_v = sky(float(rel.nu))
    across = np.hypot(*now_v[:2])
    along_the_line_of_sight = across <= 1e-9 * np.linalg.norm(now_v)  # edge on at a node: no direction to draw
    ax.plot(now_r[1] * scale, now_r[0] * scale, marker="o", color="k", ls="none", gid="star 2 at t0",
            label="star 2 at t0 (moving along the line of sight)" if along_the_line_of_sight else "star 2 at t0")
    if not along_the_line_of_sight:
        arrow = now_v[:2] / across * 0.12 * reach
        ax.annotate("", xy=(now_r[1] * scale + arrow[1], now_r[0] * scale + arrow[0]),
                    xytext=(now_r[1] * scale, now_r[0] * scale), arrowprops=dict(arrowstyle="->", color="k"))
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_xaxis()  # east to the left, as the sky is seen
    text = display.unit_math(unit)
    ax.set_xlabel(f"east offset [{text}] (east to the left)")
    ax.set_ylabel(f"north offset [{text}]")
    ax.grid(alpha=0.3)
    frame.legend_beside(ax)
    degrees = [display.number(np.degrees(angle), 4) for angle in (inc, raan, argp)]
    frame.title(ax, f"Star 2 about star 1 on the sky, star 2 at t0\n{_mass(binary, 0)} + {_mass(binary, 1)}, "
                    f"P = {display.quantity_math(binary.period, digits=4)}, e = {display.number(e, 4)}\n"
                    f"i = {degrees[0]} deg, $\\Omega$ = {degrees[1]} deg, $\\omega$ = {degrees[2]} deg")
    return fig, ax


def radial_velocity_curves(binary: Any, ax: Any = None, cycles: float = 1.25, samples: int = 600
                           ) -> tuple[Any, Any]:
    """Both stars' radial velocities (> 0 receding) against orbital phase from periastron, over `cycles` periods,
    with the systemic velocity gamma and each star's semi-amplitude K in the legend."""
    if binary.shape != ():
        raise ValueError(f"radial_velocity_curves draws one binary; this Binary holds {binary.shape}: "
                         f"index it first")
    fig, ax = frame.axes(ax, figsize=(9.5, 4.8))
    period = binary.period.to_value(u.s)
    phase = np.linspace(0.0, cycles, samples)
    dt = (phase * period - binary.time_since_periapsis.to_value(u.s)) << u.s
    v1, v2 = binary.radial_velocities(dt)
    k1, k2 = binary.rv_semi_amplitude1, binary.rv_semi_amplitude2
    gamma = binary.center_of_mass_velocity[2]
    unit = display.axis_unit(max(k1, k2, np.abs(gamma)))
    text = display.unit_math(unit)
    small = min(k1, k2) < SMALL_ORBIT * max(k1, k2)  # the lighter star's curve on an axis of its own, at right
    for star, (v, k, color) in enumerate(((v1, k1, "C0"), (v2, k2, "C1"))):
        label = f"star {star + 1} ({_mass(binary, star)}), K = {display.quantity_math(k, digits=4)}"
        if small and k == min(k1, k2):
            own = display.axis_unit(k)
            right = ax.twinx()
            right.plot(phase, (v - gamma).to_value(own), color=color, lw=1.5, label=label)
            right.set_ylabel(f"star {star + 1}: radial velocity $-$ $\\gamma$ [{display.unit_math(own)}]",
                             color=color)
            ax.plot([], [], color=color, lw=1.5, label=label + " (right axis)")  # the legend's entry
        else:
            ax.plot(phase, v.to_value(unit), color=color, lw=1.5, label=label)
    ax.axhline(gamma.to_value(unit), color="gray", ls="--", lw=1,
               label=f"systemic velocity $\\gamma$ = {display.quantity_math(gamma, digits=4, unit=unit)}")
    ax.set_xlabel(f"orbital phase from periastron [periods of {display.quantity_math(binary.period, digits=5)}]")
    ax.set_ylabel(f"radial velocity [{text}] (> 0 receding)")
    ax.set_xlim(0, cycles)
    ax.grid(alpha=0.3)
    if small:  # the right side holds the second axis: the legend goes below
        frame.legend_outside(ax, columns=1)
    else:
        frame.legend_beside(ax)
    inclination = display.quantity_math(binary.relative.inclination, digits=4)
    frame.title(ax, f"Radial velocities of a binary: {_binary_text(binary)}, i = {inclination}\n"
                    f"{display.number(cycles, 3)} periods from periastron")
    return fig, ax
