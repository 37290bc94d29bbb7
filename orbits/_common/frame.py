"""The frame every picture shares: figures and axes, the length unit of an axis and the factor into it, titles
that fit, labels beside their points that stay apart, legends off the data, and saving. matplotlib is imported
only inside the functions that draw.

Nothing here imports another module of orbits.plot: the subject modules build on this one. Numbers and units in
the texts come from orbits._common.display (quantity_math, number_math, unit_math), typeset by matplotlib's mathtext.
"""

import functools
import io
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import astropy.units as u

from orbits._common import display
from orbits._common.io import write_atomic


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
    (orbits._common.display.axis_unit: km, 10^3 km, AU, pc, ...). Pictures scale their data by the factor returned here,
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
    ax.set_xlabel(f"{x_label} [{display.unit_math(unit)}]")
    ax.set_ylabel(f"y [{display.unit_math(unit)}]")
    ax.grid(alpha=0.3)


# ---- titles --------------------------------------------------------------------------------------------------

#: the width of a character of the default font, in units of its size (measured: 0.53 for DejaVu Sans)
_CHARACTER_WIDTH = 0.56
_SIZES = {"small": 0.833, "medium": 1.0, "large": 1.2}


def wrapped(text: str, characters: int) -> str:
    """`text` broken between words into lines of at most `characters` shown characters (a $...$ formula counts
    as what it shows and is never broken); its own line breaks kept. Each paragraph takes as few lines as the
    width allows, made as even as they can be, so that no word is left alone on a last line."""
    lines = []
    for paragraph in text.split("\n"):
        words = _unbroken(re.findall(r"(?:\$[^$]*\$|[^\s$])+", paragraph))
        shown = [len(re.sub(r"\\[A-Za-z]+|[${}^_]", "", word)) for word in words]
        room = max(1, characters)
        fewest = len(_greedy(shown, room))
        least = min(max(shown, default=1), room)  # room itself always qualifies
        width = next(w for w in range(least, room + 1) if len(_greedy(shown, w)) <= fewest)
        lines += [" ".join(words[i:j]) for i, j in _greedy(shown, width)] or [""]
    return "\n".join(lines)


def _greedy(shown: list[int], characters: int) -> list[tuple[int, int]]:
    """(start, end) of each line when words of these shown lengths fill lines of `characters` in turn."""
    spans, start, length = [], 0, 0
    for k, size in enumerate(shown):
        if k > start and length + 1 + size > characters:
            spans.append((start, k))
            start, length = k, 0
        length += size + (1 if k > start else 0)
    if shown:
        spans.append((start, len(shown)))
    return spans


#: a word that reads as the unit of the number before it: "yr", "km/s,", "M$_\\odot$"
_UNIT = r"[A-Za-z][\w$\\{}^/]{0,9}[,;:)]?"


def _unbroken(words: list[str]) -> list[str]:
    """The words with each unit joined to the number before it and an equation to its sides ("P = 20 yr",
    "1.1 M$_\\odot$,"), so that no line break falls inside them."""
    joined = []
    for word in words:
        unit = bool(joined) and re.search(r"[\d$]$", joined[-1]) and re.fullmatch(_UNIT, word)
        if joined and (unit or word == "=" or joined[-1].endswith("=")):
            joined[-1] += " " + word
        else:
            joined.append(word)
    return joined


def title(target: Any, text: str, size: str = "medium", **options: Any) -> Any:
    """The title of an Axes, or the suptitle of a Figure or SubFigure, set to `text` wrapped to the width it has
    once the figure is laid out (so call it after the legends): an axes' own width, or, alone in its figure, as
    much as stays inside the figure centred over it; a figure's width. A title short enough for any layout is
    set as it is. Returns the Text."""
    import matplotlib

    root = target.figure.figure
    pixels = matplotlib.rcParams["font.size"] * _SIZES[size] * root.dpi / 72
    on_axes = hasattr(target, "set_title")
    setter = functools.partial(target.set_title, pad=10) if on_axes else target.suptitle  # pad: clear of a tick
    # label at the axes' top corner
    longest = max(len(line) for line in text.split("\n")) * _CHARACTER_WIDTH * pixels
    if longest <= 0.6 * (target.get_position().width * root.bbox.width if on_axes else target.bbox.width):
        return setter(text, fontsize=size, **options)
    root.canvas.draw()
    if on_axes:
        box, whole = target.get_window_extent(), root.bbox
        centre = (box.x0 + box.x1) / 2
        alone = len(target.figure.axes) == 1
        room = max(box.width, 1.9 * min(centre - whole.x0, whole.x1 - centre)) if alone else box.width
    else:
        room = 0.95 * target.bbox.width
    return setter(wrapped(text, max(20, int(room / (_CHARACTER_WIDTH * pixels)))), fontsize=size, **options)


def date_text(epoch: Any) -> str:
    """An epoch in TDB (an astropy Time, as orbits.ephemeris.positions.epoch returns it) to the minute:
    "2026-11-25 00:01 TDB"."""
    return f"{epoch.tdb.iso[:16]} TDB"


#: bodies a sentence names with the article
_WITH_THE = ("Sun", "Moon")


def in_a_sentence(name: str) -> str:
    """A body's name as a sentence writes it: "the Sun", "the Moon", "Jupiter"."""
    return f"the {name}" if name in _WITH_THE else name


# ---- labels beside points ------------------------------------------------------------------------------------

#: where a label may sit beside its point: name -> (offset x, offset y in points, horizontal, vertical alignment)
SIDES = {"upper right": (4, 4, "left", "bottom"), "upper left": (-4, 4, "right", "bottom"),
         "lower right": (4, -4, "left", "top"), "lower left": (-4, -4, "right", "top"),
         "right": (7, 0, "left", "center"), "left": (-7, 0, "right", "center"),
         "above": (0, 7, "center", "bottom"), "below": (0, -7, "center", "top")}


def labels_apart(ax: Any, labels: Sequence[tuple[str, Sequence[float], dict]], clear: float = 4.0) -> list[Any]:
    """Write each (text, point in data coordinates (2 or 3 of them), options) beside its point, on the first of
    its sides (options["sides"], else SIDES in order) where it stays inside the axes and overlaps none of the
    texts already in them, no label written before it and no other labelled point (a square of `clear` points
    about each); a label that fits nowhere is left out (the legend names what it marks). Other options go to
    matplotlib's annotate. The figure is laid out first, so the boxes are measured where they are drawn. Returns
    the texts written."""
    figure = ax.figure.figure
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    anchors = [_plane_point(ax, point) for _, point, _ in labels]
    reach = clear * figure.dpi / 72
    marks = [_square(*ax.transData.transform(anchor), reach) for anchor in anchors]
    taken = [text.get_window_extent(renderer) for text in ax.texts if text.get_visible() and text.get_text()]
    inside = ax.get_window_extent(renderer)
    written = []
    for k, ((text, _, options), anchor) in enumerate(zip(labels, anchors, strict=True)):
        options = dict(options)
        others = taken + marks[:k] + marks[k + 1:]
        for side in options.pop("sides", tuple(SIDES)):
            dx, dy, ha, va = SIDES[side]
            note = ax.annotate(text, anchor, xytext=(dx, dy), textcoords="offset points", ha=ha, va=va, **options)
            box = note.get_window_extent(renderer)
            if (inside.x0 <= box.x0 and box.x1 <= inside.x1 and inside.y0 <= box.y0 and box.y1 <= inside.y1
                    and not any(box.overlaps(other) for other in others)):
                taken.append(box)
                written.append(note)
                break
            note.remove()
    return written


def _plane_point(ax: Any, point: Sequence[float]) -> tuple[float, float]:
    """A point in the axes' 2-D data coordinates: itself, or in a 3-D axes its projection in the current view."""
    if len(point) == 3:
        from mpl_toolkits.mplot3d import proj3d

        x, y, _ = proj3d.proj_transform(*point, ax.get_proj())
        return float(x), float(y)
    return float(point[0]), float(point[1])


def _square(x: float, y: float, half: float) -> Any:
    """The box of half-width `half` (pixels) about (x, y)."""
    from matplotlib.transforms import Bbox

    return Bbox([[x - half, y - half], [x + half, y + half]])


# ---- legends -------------------------------------------------------------------------------------------------


def legend_beside(ax: Any) -> None:
    """The legend to the right of the axes, its top level with theirs, off the data. A 3-D axes alone in its
    figure gets a figure legend outside on the right instead, clear of its z label."""
    if ax.name == "3d" and len(ax.figure.axes) == 1:
        for old in list(ax.figure.legends):
            old.remove()
        ax.figure.legend(*ax.get_legend_handles_labels(), loc="outside right upper", fontsize="small",
                         frameon=False)
        return
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)


def legend_outside(ax: Any, columns: int = 2) -> None:
    """The legend below the axes, off the data, in up to `columns` columns: as many as fit the axes' width (none
    when nothing is labelled)."""
    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return
    figure = ax.figure.figure
    renderer = figure.canvas.get_renderer()
    width = ax.get_position().width * figure.bbox.width
    for ncol in range(min(columns, len(handles)), 0, -1):
        legend = ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), fontsize="small", ncol=ncol,
                           frameon=False)
        if ncol == 1 or legend.get_window_extent(renderer).width <= width:
            return


def save(fig: Any, path: str | Path) -> None:
    """Write the figure to `path` atomically (orbits._common.io.write_atomic) at 150 dpi; the format follows the suffix
    (.png, .svg or .pdf)."""
    suffix = str(path).rsplit(".", 1)[-1].lower()
    if suffix not in ("png", "svg", "pdf"):
        raise ValueError(f"plot file {path!r} must end in .png, .svg or .pdf")
    buffer = io.BytesIO()
    fig.savefig(buffer, format=suffix, dpi=150)
    write_atomic(path, buffer.getvalue())

