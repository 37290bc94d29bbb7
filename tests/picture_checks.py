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


def problems(figure):
    """Everything the shared checks find wrong with a picture: overlapping texts, text outside the figure, a
    legend entry twice, no title, untypeset powers. Empty for a picture fit for a talk."""
    found = [f"overlap: {a!r} / {b!r}" for a, b in overlapping_texts(figure)]
    labels = legend_labels(figure)
    found += [f"legend entry twice: {label!r}" for label in sorted({x for x in labels if labels.count(x) > 1})]
    if not titles(figure):
        found.append("no title")
    found += [f"not typeset: {text!r}" for text in untypeset(figure)]
    return found
