"""Pictures of the cross-checks: residuals of the integrations against the closed forms over time, the integrated
tracks drawn on the analytic ones (a ValidationReport), and work-precision diagrams (orbits.tools.precision rows).

Each function reads the report or rows it is given; nothing here runs an integration.
"""

import math
from collections.abc import Sequence
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame

#: what the position errors are relative to (orbits.validate.predict.length_scale), as the pictures say it
LENGTH_SCALE = ("L: the largest distance of an orbiting body from its primary over the run (of two bodies, where "
                "none orbits)")
#: |dr| / L typeset
ERROR = r"$|\Delta r|/L$"


def validation_residuals(report: Any, figure: Any = None) -> tuple[Any, np.ndarray]:
    """Position error |dr| / L against time (a ValidationReport), one colour per scene and one line style per
    backend, errors on a log scale and each panel's legend below it; the title says what L is (LENGTH_SCALE).

    Scenes that run for at least one period of their first orbit (SceneReport.period) share the left panel, on
    log-log axes with time in that period (a 100-period scene ends at 100); the others (a flyby, an encounter,
    one passage of a near-parabolic comet, the expanding sphere) the right one, against the fraction of their run
    on a linear axis (a symmetric flyby's periapsis in the middle). Only the panels with something to show are
    drawn; an exact match (zero error) and t = 0 have no place on log axes and are left out. `figure` may be a
    Figure or SubFigure to draw into. Returns (figure, array of the panels).
    """
    figure = frame.figure(figure, (10.0, 5.0))
    shown = [scene for scene in report.scenes if scene.residuals]
    colors = dict(zip((scene.name for scene in shown), frame.colors(len(shown)), strict=True))
    backends = list(dict.fromkeys(backend for scene in shown for backend in scene.residuals))
    styles = dict(zip(backends, ("-", "--", ":", "-.")))
    orbiting = [s for s in shown if s.period and s.residual_times[-1] >= s.period]
    groups = {"closed": orbiting, "open": [s for s in shown if s not in orbiting]}
    groups = {kind: scenes for kind, scenes in groups.items() if scenes}
    if not groups:
        return figure, _nothing_to_draw(figure, "no scene here predicts positions: nothing to plot against time")
    panels = np.atleast_1d(figure.subplots(1, len(groups), sharey=True))
    for ax, (kind, scenes) in zip(panels, groups.items(), strict=True):
        for scene in scenes:
            times = np.asarray(scene.residual_times, dtype=float)
            elapsed = times / scene.period if kind == "closed" else times / times[-1]
            for backend, series in scene.residuals.items():
                ax.plot(elapsed, np.where((series > 0) & (elapsed > 0), series, np.nan), color=colors[scene.name],
                        ls=styles.get(backend, "-"), lw=1.3, label=f"{scene.name}: {backend}")
        ax.set_yscale("log")
        if kind == "closed":
            ax.set_xscale("log")
            ax.set_xlabel("time [periods of the scene's first orbit]")
        else:
            ax.set_xlim(0.0, 1.0)
            ax.set_xlabel("time [fraction of the run]")
        ax.grid(alpha=0.3, which="major")
        frame.legend_outside(ax)
    panels[0].set_ylabel(f"position error {ERROR} [dimensionless]")
    for ax, kind in zip(panels, groups, strict=True):
        frame.title(ax, "runs of whole orbits" if kind == "closed" else "single passages and open orbits")
    frame.title(figure, f"Position errors {ERROR} of the integrations against the closed forms\n{LENGTH_SCALE}")
    return figure, panels


def validation_tracks(report: Any, figure: Any = None, columns: int = 4) -> tuple[Any, np.ndarray]:
    """The integrated trajectories over the analytic ones (a ValidationReport): one panel per scene that predicts
    positions, each body relative to the first (the primary) and seen face on (the plane of largest spread of
    the predicted tracks), the closed form as a grey curve (over one period, SceneReport.outline) with open circles
    at the output times and each backend's positions as small markers in them (at most TRACK_MARKERS outputs per
    body, evenly spaced; where they fall on a few points only, as a run sampled every half period does, the panel
    says so); the title gives each backend's worst |dr| / L; the legend sits in the first empty cell, or below the
    panels. Axes in the scene's natural length unit (code units for a model scene), four ticks at most so that
    their labels stay apart. Returns (figure, array of the panels).
    """
    from matplotlib.ticker import MaxNLocator

    shown = [scene for scene in report.scenes if scene.expected is not None and scene.positions]
    rows = max(1, math.ceil(len(shown) / columns))
    figure = frame.figure(figure, (3.0 * min(columns, max(1, len(shown))) + 1.0, 3.2 * rows + 0.6))
    if not shown:
        return figure, _nothing_to_draw(figure, "no scene here predicts positions: no tracks to draw")
    panels = np.atleast_1d(figure.subplots(rows, min(columns, len(shown)), squeeze=False)).ravel()
    markers = ("x", "+", "1", "2")
    for ax, scene in zip(panels, shown, strict=False):
        relative = scene.expected[:, 1:] - scene.expected[:, :1]
        curve = relative if scene.outline is None else scene.outline[:, 1:] - scene.outline[:, :1]
        basis = _face_on_basis(np.concatenate([curve, relative]).reshape(-1, 3))
        size = float(np.max(np.abs(relative)))
        unit, factor = (u.one, 1.0) if scene.in_code_units else frame.length_unit(size)
        every = slice(None, None, math.ceil(len(relative) / TRACK_MARKERS) | 1)  # odd: outputs every half period
        # land on both of the points they alternate between
        for body in range(relative.shape[1]):
            ax.plot(*(curve[:, body] @ basis.T * factor).T, color="0.6", lw=0.8, zorder=1,
                    label="closed form" if body == 0 else None)
            ax.plot(*(relative[every, body] @ basis.T * factor).T, color="0.45", ls="none", marker="o", ms=5,
                    mfc="none", mew=0.7, zorder=1, label="closed form at the outputs" if body == 0 else None)
        for k, (backend, positions) in enumerate(scene.positions.items()):
            moving = positions[every, 1:] - positions[every, :1]
            for body in range(moving.shape[1]):
                x, y = (moving[:, body] @ basis.T * factor).T
                ax.plot(x, y, ls="none", marker=markers[k % len(markers)], ms=3.5, color=f"C{k}", zorder=2,
                        label=backend if body == 0 else None, gid=f"integrated {backend}")
        ax.plot([0.0], [0.0], marker="*", ms=9, color="gold", mec="0.3", ls="none", zorder=3,
                label="first body (the origin)")
        where = "code length" if scene.in_code_units else display.unit_math(unit)
        ax.set_xlabel(f"in-plane x [{where}]", fontsize="small")
        ax.set_ylabel(f"in-plane y [{where}]", fontsize="small")
        ax.set_aspect("equal", adjustable="datalim")
        ax.tick_params(labelsize="x-small")
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(MaxNLocator(4))
        ax.grid(alpha=0.3)
    for ax in panels[len(shown):]:
        ax.set_axis_off()
    handles, labels = panels[0].get_legend_handles_labels()
    if len(panels) > len(shown):  # in the first empty cell
        panels[len(shown)].legend(handles, labels, loc="center", fontsize="small", frameon=False)
    else:
        figure.legend(handles, labels, loc="outside lower center", ncol=len(labels), fontsize="small", frameon=False)
    for ax, scene in zip(panels, shown, strict=False):
        frame.title(ax, _track_title(scene), size="small")
    frame.title(figure, f"Integrated tracks over the closed forms, each scene face on; the worst {ERROR} of each "
                        f"backend over its panel")
    return figure, panels[:len(shown)]


def _track_title(scene: Any) -> str:
    """The scene, each backend's worst |dr| / L, and how many points its marked outputs fall on where they repeat
    (a run sampled every half period has two)."""
    worst = ", ".join(f"{backend} {display.number_math(float(np.max(series)), 2)}"
                      for backend, series in scene.residuals.items())
    relative = scene.expected[:, 1:] - scene.expected[:, :1]
    size = float(np.max(np.abs(relative))) or 1.0
    spots = len(np.unique(np.round(relative[:, 0] / size, 6), axis=0))
    repeats = f"\n{len(relative)} outputs at {spots} points" if spots <= len(relative) // 4 else ""
    return f"{scene.name}\n{worst}{repeats}"


#: at most this many outputs of each body are marked in validation_tracks (every k-th), so the markers stay apart
TRACK_MARKERS = 50


def _nothing_to_draw(figure: Any, text: str) -> np.ndarray:
    """One blank panel of `figure` saying why nothing is drawn; returned as the array of panels."""
    ax = figure.subplots()
    ax.text(0.5, 0.5, frame.wrapped(text, 60), ha="center", va="center", transform=ax.transAxes)
    ax.set_axis_off()
    return np.array([ax])


#: where a check that met its tolerance exactly, or a zero error, is drawn (fraction of the tolerance)
FLOOR = 1e-6


def validation_checks(report: Any, ax: Any = None) -> tuple[Any, Any]:
    """Every check of the report as one row: each backend's error as a fraction of the check's tolerance (log
    scale; at most 1 passes, the line at 1), the scene and quantity on the left. What `orbits validate --plot`
    draws for scenes that predict no positions over time. Returns (figure, axes)."""
    rows = [(scene.name, check) for scene in report.scenes for check in scene.checks]
    backends = list(dict.fromkeys(b for _, check in rows for b in check.errors))
    fig, ax = frame.axes(ax, figsize=(8.0, 1.6 + 0.32 * len(rows)))
    markers = ("o", "s", "^", "D")
    for k, (backend, color) in enumerate(zip(backends, frame.colors(len(backends)))):
        shares = [max(check.errors[backend] / check.tolerance, FLOOR) if backend in check.errors else np.nan
                  for _, check in rows]
        ax.plot(shares, np.arange(len(rows)), markers[k % len(markers)], color=color, ms=6, ls="none",
                label=backend, alpha=0.85)
    ax.axvline(1.0, color="0.3", lw=1.0, ls="--", label="tolerance")
    ax.set_xscale("log")
    several = len({name for name, _ in rows}) > 1
    ax.set_yticks(np.arange(len(rows)), [f"{name}: {check.quantity}" if several else check.quantity
                                         for name, check in rows], fontsize="small")
    ax.invert_yaxis()
    ax.set_xlabel("error / tolerance (at most 1 passes)")
    ax.grid(axis="x", which="major", alpha=0.3)
    names = ", ".join(dict.fromkeys(name for name, _ in rows))
    frame.title(ax, f"Each check of {names} against its tolerance")
    frame.legend_beside(ax)
    return fig, ax


def _face_on_basis(points: np.ndarray) -> np.ndarray:
    """(2, 3) orthonormal rows spanning the plane of largest spread of (M, 3) points about the origin (their
    first two right singular vectors): an orbit seen face on, whatever its inclination."""
    _, _, rows = np.linalg.svd(points, full_matrices=False)
    return rows[:2]


def validation_overview(report: Any) -> tuple[Any, np.ndarray]:
    """The picture of `orbits validate --plot`: residuals against time on top (validation_residuals), the
    integrated trajectories over the analytic ones below (validation_tracks); every check against its tolerance
    (validation_checks) when no scene of the report predicts positions. Returns (figure, all panels)."""
    import matplotlib.pyplot as plt

    tracks = sum(1 for scene in report.scenes if scene.expected is not None and scene.positions)
    if not tracks:  # nothing over time: every check against its tolerance instead
        fig, ax = validation_checks(report)
        return fig, np.array([ax])
    rows = max(1, math.ceil(tracks / 4))
    fig = plt.figure(figsize=(13.0, 5.4 + 3.3 * rows), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=(5.4, 3.3 * rows))
    _, residual_panels = validation_residuals(report, top)
    _, track_panels = validation_tracks(report, bottom)
    return fig, np.concatenate([residual_panels, track_panels])


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
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("position error / orbit size")
        ax.grid(alpha=0.3, which="major")
    for ax in list(axes.flat)[len(problems) :]:
        ax.set_visible(False)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside right upper", fontsize="small")
    for ax, problem in zip(axes.flat, problems):
        frame.title(ax, problem)
    frame.title(fig, "Work-precision: each method's position error (relative to the orbit's size) against its wall "
                     "time", size="large")
    return fig, axes
