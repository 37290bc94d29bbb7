"""What every picture is checked for, whatever it draws: no text over other text or outside the figure, each
legend entry once, a title, and the texts a talk can show (no offset '1e+06', no '10^3 km' or 'km2/s2' written
out where mathtext typesets them)."""

import itertools
import re


def drawn_texts(figure):
    """(text, window box) of every text the figure shows: titles, axis labels, tick labels inside the view (in 2-D
    and 3-D axes), legend entries, annotations and contour labels."""
    from matplotlib.axes import Axes
    from matplotlib.text import Text

    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    hidden = set()
    for ax in figure.findobj(Axes):  # insets too
        for axis in (getattr(ax, f"{name}axis") for name in "xyz" if hasattr(ax, f"{name}axis")):
            low, high = sorted(axis.get_view_interval())
            margin = 1e-9 * max(abs(low), abs(high), 1.0)
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not low - margin <= tick.get_loc() <= high + margin:
                    hidden |= {id(tick.label1), id(tick.label2)}
    return [(text.get_text(), text.get_window_extent(renderer)) for text in figure.findobj(Text)
            if text.get_visible() and text.get_text().strip() and id(text) not in hidden]


def overlapping_texts(figure):
    """Pairs of shown texts whose boxes overlap (by more than half a pixel), and texts reaching outside the figure
    (as (text, "outside the figure"))."""
    boxes = drawn_texts(figure)
    inside = figure.bbox.padded(0.5)
    outside = [text for text, box in boxes if not (inside.contains(box.x0, box.y0) and inside.contains(box.x1, box.y1))]
    pairs = [(a, b) for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2) if box_a.padded(-0.5).overlaps(
        box_b.padded(-0.5))]
    return pairs + [(text, "outside the figure") for text in outside]


def legends(figure):
    """Every legend of the figure: its own, its subfigures' and its axes'."""
    from matplotlib.legend import Legend

    return [legend for legend in figure.findobj(Legend)]


def legend_labels(figure):
    """The entries of every legend of the figure, in order."""
    return [text.get_text() for legend in legends(figure) for text in legend.get_texts()]


def titles(figure):
    """The figure's titles: its suptitle, its subfigures' and each axes' (left, centre and right)."""
    from matplotlib.figure import SubFigure

    found = [f.get_suptitle() for f in [figure, *figure.findobj(SubFigure)] if f.get_suptitle()]
    for ax in figure.axes:
        found += [ax.get_title(loc) for loc in ("left", "center", "right") if ax.get_title(loc)]
    return found


def shown_texts(figure):
    """Every text the figure shows (drawn_texts without the boxes)."""
    return [text for text, _ in drawn_texts(figure)]


#: texts a picture for a talk does not show outside $...$ mathtext: an exponent written out (1e+06, 2.5e-07,
#: 6.96e5), a power written with '^' (10^3 km, theta0^2), a unit's power as a digit (km2/s2), a Greek letter
#: spelled out (theta0, nu, mu, Omega, pi)
UNTYPESET = (re.compile(r"\de[+-]?\d"), re.compile(r"\^"), re.compile(r"\b(?:km|m|s|AU|pc|Mpc)[23]\b"),
             re.compile(r"\b(?:theta0?|nu(?:_\d)?|mu|Omega|omega|pi|lambda|tau|gamma|Delta|epsilon|rho)\b"))


def untypeset(figure):
    """The shown texts with an exponent, a power or a Greek letter not typeset (see UNTYPESET)."""
    found = []
    for text in shown_texts(figure):
        plain = re.sub(r"\$[^$]*\$", " ", text)
        if any(pattern.search(plain) for pattern in UNTYPESET):
            found.append(text)
    return found


def _in_view_pixels(ax, artist):
    """The window positions (pixels) of the finite points of a Line2D or a collection's offsets that lie inside
    the axes' view; None for an artist of another kind."""
    import numpy as np
    from matplotlib.collections import Collection
    from matplotlib.lines import Line2D

    if isinstance(artist, Line2D):
        x, y = (np.asarray(a, dtype=float).ravel() for a in artist.get_data(orig=False))
        points = np.column_stack([x, y]) if x.size == y.size else np.zeros((0, 2))
    elif isinstance(artist, Collection) and len(artist.get_offsets()):
        points = np.asarray(artist.get_offsets(), dtype=float).reshape(-1, 2)
    else:
        return None
    points = points[np.all(np.isfinite(points), axis=1)]
    pixels = artist.get_transform().transform(points) if len(points) else np.zeros((0, 2))
    box = ax.get_window_extent()
    inside = ((pixels[:, 0] >= box.x0 - 0.5) & (pixels[:, 0] <= box.x1 + 0.5) & (pixels[:, 1] >= box.y0 - 0.5)
              & (pixels[:, 1] <= box.y1 + 0.5))
    return pixels[inside]


def _draws_something(ax, artist):
    """Whether `artist` leaves a mark a reader can see in its axes: visible, not transparent, and for a curve of
    two points or more an extent of at least 2 pixels."""
    from matplotlib.lines import Line2D

    if not artist.get_visible() or artist.get_alpha() == 0:
        return False
    if getattr(ax, "name", "") == "3d":
        return _has_data(artist)  # projected at draw time
    pixels = _in_view_pixels(ax, artist)
    if pixels is None:
        return True  # a patch, an image or a contour set: drawn as it is
    if isinstance(artist, Line2D) and artist.get_marker() in ("None", "", " ", None) and len(pixels) >= 2:
        extent = pixels.max(axis=0) - pixels.min(axis=0)
        return bool(max(extent) >= 2.0 and artist.get_linewidth() > 0)
    return len(pixels) > 0


def _has_data(artist):
    """Whether a curve or a collection holds points (a legend's proxy, drawn for its entry alone, holds none)."""
    from matplotlib.collections import Collection
    from matplotlib.lines import Line2D

    if isinstance(artist, Line2D):
        return len(artist.get_xdata(orig=False)) > 0
    if isinstance(artist, Collection):
        return len(artist.get_offsets()) > 0 or len(artist.get_paths()) > 0
    return True


def invisible_curves(figure, drawn=False):
    """Labelled curves and markers that leave no visible mark: all their points outside the view, or a curve
    shrunk below 2 pixels (an orbit too small for the frame it is drawn in). A legend's proxy (a labelled artist
    with no points) stands for marks drawn by others and is not counted."""
    if not drawn:  # problems() draws the figure once for every check
        figure.canvas.draw()
    found = []
    for ax in figure.axes:
        for artist in [*ax.get_lines(), *ax.collections]:
            label = str(artist.get_label())
            if label.startswith("_") or not label.strip() or not _has_data(artist):
                continue
            if not _draws_something(ax, artist):
                found.append(label)
    return found


def _marks(ax):
    return [a for a in [*ax.get_lines(), *ax.collections, *ax.patches, *ax.images]
            if _has_data(a) and _draws_something(ax, a)]


def blank_panels(figure, drawn=False):
    """Axes with a frame on and nothing drawn in them: no curve, marker, collection, patch or image."""
    if not drawn:  # problems() draws the figure once for every check
        figure.canvas.draw()
    return [ax.get_title() or ax.get_label() or "an untitled panel" for ax in figure.axes
            if ax.axison and ax.get_label() != "<colorbar>" and not _marks(ax)]


def blank_figure(figure, drawn=False):
    """Whether no panel of the figure draws anything (text alone, such as a sentence saying why, is blank)."""
    if not drawn:  # problems() draws the figure once for every check
        figure.canvas.draw()
    return not any(_marks(ax) for ax in figure.axes)


def problems(figure):
    """Everything the shared checks find wrong with a picture: overlapping texts, text outside the figure, a
    legend entry twice, no title, untypeset powers, a blank panel or a blank figure, a labelled curve that
    leaves no visible mark (so its legend entry names nothing drawn). Empty for a picture fit for a talk."""
    found = [f"overlap: {a!r} / {b!r}" for a, b in overlapping_texts(figure)]  # draws the figure
    found += [f"blank panel: {name!r}" for name in blank_panels(figure, drawn=True)]
    if blank_figure(figure, drawn=True):
        found.append("blank figure: no panel draws anything")
    found += [f"nothing drawn for {label!r}" for label in invisible_curves(figure, drawn=True)]
    labels = legend_labels(figure)
    found += [f"legend entry twice: {label!r}" for label in sorted({x for x in labels if labels.count(x) > 1})]
    if not titles(figure):
        found.append("no title")
    found += [f"not typeset: {text!r}" for text in untypeset(figure)]
    return found
