"""The benchmarks' shared presentation: plain-text tables of at most WIDTH columns and JSON-ready rows.

Every benchmark module formats its rows with these; this module imports none of them. Figures are written
with a fixed number of significant digits (sig, fixed), throughputs in millions per second (mega); long
names and notes wrap rather than being cut (wrap, plain_table), and notes go under a table as numbered
footnotes (mark, notes).
"""

import dataclasses
import math
import textwrap
from collections.abc import Iterable

#: Width of every plain-text table: a line never exceeds it, and no text is cut to fit (it wraps).
WIDTH = 80
GAP = "  "


def wrap(text, width, indent="", subsequent=None, split_words=True):
    """Lines of text, at most `width` wide; words are split only if one alone is wider than the line (and
    split_words, else that line is wider)."""
    wrapper = textwrap.TextWrapper(
        width, initial_indent=indent, subsequent_indent=indent if subsequent is None else subsequent,
        break_on_hyphens=False, break_long_words=split_words,
    )
    return wrapper.wrap(text) or [indent.rstrip()]


def fixed(x, digits):
    """x in fixed notation with at least `digits` significant digits (all the integer digits if more)."""
    if not math.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    return f"{x:.{max(0, digits - 1 - math.floor(math.log10(abs(x))))}f}"


def sig(x, digits=3):
    """x to `digits` significant digits: fixed notation from 0.001 to 10**digits, scientific beyond."""
    if math.isfinite(x) and x != 0 and not 1e-3 <= abs(x) < 10**digits:
        return f"{x:.{digits - 1}e}"
    return fixed(x, digits)


def mega(per_second):
    """A throughput in millions per second: 4 significant digits from 1 M/s, 3 below."""
    x = per_second / 1e6
    return fixed(x, 4) if abs(x) >= 1 else sig(x, 3)


def plain_table(header, rows, stack=False, width=WIDTH, first="<"):
    """Lines of a plain-text table at most `width` wide.

    header: the column titles; rows: lists of cells, the first left-aligned and wrapped (continuation lines
    indented, the other cells on the last) to what the other columns leave of `width`, the others
    right-aligned; or strings, section titles drawn as rules across the table.  stack=True wraps the titles
    word by word over several header lines, so that a column is only as wide as its longest title word or
    cell; first=">" right-aligns the first column too (numbers)."""
    cells = [r for r in rows if not isinstance(r, str)]
    widths = [
        max([len(w) for w in (title.split() if stack else [title])] + [len(r[j]) for r in cells])
        for j, title in enumerate(header)
    ]
    rest = sum(widths[1:]) + len(GAP) * (len(widths) - 1)
    widths[0] = max(min(widths[0], width - rest), 12)
    total = sum(widths) + len(GAP) * (len(widths) - 1)
    titles = [wrap(t, w) if stack else [t] for t, w in zip(header, widths)]
    depth = max(map(len, titles))
    titles = [[""] * (depth - len(t)) + t for t in titles]
    lines = [_row([t[i] for t in titles], widths, first) for i in range(depth)]
    if not rows or not isinstance(rows[0], str):
        lines.append("-" * total)
    for r in rows:
        if isinstance(r, str):
            lines.extend(_section(r, max(total, len(r) + 6), width))
        else:
            lines.extend(_cells(r, widths, first, width))
    return lines


def _row(cells, widths, align="<"):
    first, *others = cells
    text = f"{first:{align}{widths[0]}}" + "".join(f"{GAP}{c:>{w}}" for c, w in zip(others, widths[1:]))
    return text.rstrip()


def _cells(cells, widths, align="<", width=WIDTH):
    """A table row: its first cell wrapped to its column, the others on its last line (so that the text reads
    on without figures in between); a text with a word wider than its column takes whole lines instead, and
    the figures a line of their own under it."""
    first = wrap(cells[0], widths[0], subsequent="  ", split_words=False)
    if max(map(len, first)) > widths[0]:
        first = [*wrap(cells[0], width, subsequent="  "), ""]
    return first[:-1] + [_row([first[-1], *cells[1:]], widths, align)]


def _section(title, rule, width):
    """A section title drawn into a rule: '-- title ------' (wrapped if the title is wider than `width`)."""
    if len(title) + 6 > width:
        return wrap(title, width, "-- ", "   ")
    return [f"-- {title} " + "-" * (min(rule, width) - len(title) - 4)]


def notes(texts, width=WIDTH):
    """The footnote list: '[n] text' with hanging indents; `texts` maps each text to its number."""
    if not texts:
        return []
    mark_width = len(f"[{len(texts)}]")
    lines = []
    for text, number in texts.items():
        label = f"[{number}]"
        lines.extend(wrap(text, width, f"{label:>{mark_width}} ", " " * (mark_width + 1)))
    return lines


def mark(texts, text):
    """' [n]', the footnote number of text (a new one if unseen), or '' for no text."""
    if not text:
        return ""
    return f" [{texts.setdefault(text, len(texts) + 1)}]"


#: the legend of the ratio column of by_dataset's tables
RATIO_LEGEND = "ratio: throughput over that of orbits (1 thread) on the same set; above 1 is faster."


def by_dataset(rows, reference, stats):
    """Table rows of a throughput benchmark: a section per data set (in order of appearance), one row per
    method with its footnote mark, then the footnote texts {text: number}."""
    texts, table = {}, []
    for dataset in dict.fromkeys(r.dataset for r in rows):
        table.append(dataset)
        for r in (r for r in rows if r.dataset == dataset):
            if r.status == "ok":
                ratio = sig(r.throughput_per_s / reference[dataset], 3) if dataset in reference else "-"
                cells = [mega(r.throughput_per_s), ratio, *stats(r), str(r.n_nan)]
            else:
                cells = ["-"] * 5
            table.append([r.method + mark(texts, _note(r)), *cells])
    return table, texts


def _note(row):
    """The row's note, its status if not ok, and its one-off setup time."""
    note = row.note if row.status == "ok" else f"{row.status}: {row.note}"
    if row.setup_seconds:
        note = f"{note} (compile/setup {row.setup_seconds:.3f} s)".lstrip()
    return note


def rows_to_json(rows: Iterable[object]) -> list[dict[str, object]]:
    """Rows (any of the benchmarks' row classes) as JSON-ready dicts (NaN and infinity become None)."""
    return [_clean(dataclasses.asdict(r)) for r in rows]


def _clean(value):
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    return None if isinstance(value, float) and not math.isfinite(value) else value

