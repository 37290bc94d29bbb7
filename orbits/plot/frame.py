"""The frame every picture shares: figures and axes, the length unit of an axis and the factor into it, legends
off the data, and saving. matplotlib is imported only inside the functions that draw.

Nothing here imports another module of orbits.plot: the subject modules build on this one.
"""

import io
from pathlib import Path
from typing import Any

import astropy.units as u

from orbits import display
from orbits.io import write_atomic


def axes(ax: Any = None, figsize: tuple[float, float] = (6.4, 5.6)) -> tuple[Any, Any]:
    """(figure, axes): those of `ax`, or a new constrained-layout figure of `figsize` inches with one axes."""
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=figsize, layout="constrained")
        return fig, ax
    return ax.figure, ax


def axes_for(ax: Any, projection: str) -> tuple[Any, Any]:
    """(figure, axes) for a picture in space with its legend beside it: the given Axes, or a new figure with one
    axes (a 3D one for projection "3d")."""
    import matplotlib.pyplot as plt

    if ax is not None:
        return ax.figure, ax
    if projection == "3d":
        fig = plt.figure(figsize=(8.4, 6.4), layout="constrained")
        return fig, fig.add_subplot(projection="3d")
    fig, ax = plt.subplots(figsize=(8.4, 6.0), layout="constrained")
    return fig, ax


def figure(figure: Any, size: tuple[float, float]) -> Any:
    """`figure` (a Figure or SubFigure), or a new constrained-layout Figure of `size` inches."""
    if figure is not None:
        return figure
    import matplotlib.pyplot as plt

    return plt.figure(figsize=size, layout="constrained")


def length_unit(size_m: float, unit: u.UnitBase | None = None) -> tuple[u.UnitBase, float]:
    """(unit, metres -> unit factor) of a picture spanning `size_m` metres: `unit` when given, else the natural one
    (orbits.display.axis_unit: km, 10^3 km, AU, pc, ...). Pictures scale their data by the factor returned here,
    the one that also labels the axes."""
    unit = unit or display.axis_unit(size_m << u.m)
    return unit, u.m.to(unit)


def colors(n: int) -> list[Any]:
    """n distinct colours: matplotlib's ten, then tab20's twenty; beyond, a sequence along viridis (first and last
    as far apart as it goes, none repeated), which reads as the order of the curves."""
    import matplotlib

    if n <= 10:
        return [f"C{k}" for k in range(n)]
    if n <= 20:
        return list(matplotlib.colormaps["tab20"].colors[:n])
    return [matplotlib.colormaps["viridis"](k / (n - 1)) for k in range(n)]


def finish_plane(ax: Any, unit: u.UnitBase, x_label: str) -> None:
    """Equal aspect, the axes labelled with the length unit (x as `x_label`, y as "y"), and a grid: the end of a
    picture drawn in a plane. The caller places the legend."""
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"{x_label} [{display.unit_text(unit)}]")
    ax.set_ylabel(f"y [{display.unit_text(unit)}]")
    ax.grid(alpha=0.3)


def legend_beside(ax: Any) -> None:
    """The legend to the right of the axes, its top level with theirs, off the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)


def legend_outside(ax: Any) -> None:
    """The legend below the axes, off the data, in as many columns as fit (none when nothing is labelled)."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), fontsize="small", ncol=min(2, len(handles)),
                  frameon=False)


def save(fig: Any, path: str | Path) -> None:
    """Write the figure to `path` atomically (orbits.io.write_atomic) at 150 dpi; the format follows the suffix
    (.png, .svg or .pdf)."""
    suffix = str(path).rsplit(".", 1)[-1].lower()
    if suffix not in ("png", "svg", "pdf"):
        raise ValueError(f"plot file {path!r} must end in .png, .svg or .pdf")
    buffer = io.BytesIO()
    fig.savefig(buffer, format=suffix, dpi=150)
    write_atomic(path, buffer.getvalue())
