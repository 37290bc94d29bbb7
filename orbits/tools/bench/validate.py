"""`orbits bench validate`: where the time of ``orbits validate`` goes (analytic, integrator setup and
compile, integration) per built-in scene, sequential and as a dask sweep.
"""

import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from orbits.tools.bench.table import GAP, WIDTH, plain_table, wrap

if TYPE_CHECKING:
    from orbits.validate.models import ModelScene
    from orbits.validate.scene import Scene


@dataclass(frozen=True)
class ValidateRow:
    """Wall time of one scene (or of the whole run, scene "all") by stage: "analytic", "<backend> setup"
    (integrator construction; heyoka's compilation, or its cache hit) and "<backend> integration";
    "other" is the rest of validate_scene (comparisons, residuals). mode: sequential or sweep."""

    scene: str
    mode: str
    stages: dict
    total_seconds: float


def _scene_row(report, total, mode):
    stages = {"analytic": report.wall_times["analytic"]}
    for backend, setup in report.setup_times.items():
        stages[f"{backend} setup"] = setup
        stages[f"{backend} integration"] = report.wall_times[backend]
    stages["other"] = total - sum(stages.values())
    return ValidateRow(report.name, mode, stages, total)


def bench_validate(
    scenes: "Sequence[str | Scene | ModelScene] | None" = None,
    backend_names: Sequence[str] = ("rebound", "heyoka"),
    sweep: bool = True,
) -> list[ValidateRow]:
    """Time `orbits validate` stage by stage on the built-in data and model scenes (or `scenes`, names or
    loaded scenes): sequentially in this process, scene by scene, then (sweep=True, dask installed) as
    validate_sweep on a 2-worker LocalCluster of threads and of processes, whole runs only (cluster start-up
    included). A scene given by name is loaded inside its timing, as `orbits validate` does: a model scene
    makes its prediction (the "analytic" stage) when it is built, so only then do the stages add up to at most
    the total; a scene passed loaded has had that time already."""
    from orbits.validate import builtin_names, load, validate

    rows, loaded = [], []
    start_all = time.perf_counter()
    for item in scenes or builtin_names():
        start = time.perf_counter()
        scene = load(item) if isinstance(item, str) else item
        report = validate([scene], backend_names).scenes[0]
        rows.append(_scene_row(report, time.perf_counter() - start, "sequential"))
        loaded.append(scene)
    rows.append(ValidateRow("all", "sequential", {}, time.perf_counter() - start_all))
    if sweep:
        rows.extend(_sweep_rows(loaded, backend_names))
    return rows


def _sweep_rows(scenes, backend_names):
    try:
        from orbits.tools import distributed
    except ImportError:
        return []
    rows = []
    for processes in (False, True):
        start = time.perf_counter()
        try:
            with distributed.sweep_client(processes=processes) as client:
                started = time.perf_counter()
                distributed.validate_sweep(scenes, client, backend_names)
                swept = time.perf_counter()
        except ImportError:
            return []
        mode = f"sweep, 2 worker {'processes' if processes else 'threads'}"
        stages = {"cluster start": started - start, "scenes": swept - started}
        rows.append(ValidateRow("all", mode, stages, time.perf_counter() - start))
    return rows


def format_validate(rows: Sequence[ValidateRow]) -> str:
    """Plain-text tables of bench_validate, at most 80 columns: seconds in total and per stage, one line per
    scene or run.  Consecutive rows with compatible stages share a table, titled by what they have in common
    (e.g. the mode "sequential") and labelled by what varies (the scene, or the mode of the sweeps); a table
    with more stages than 80 columns hold continues, label repeated, in further blocks under it."""
    sections = []  # [(stage names, rows)]
    for r in rows:
        if sections and (r.stages.keys() <= set(sections[-1][0]) or set(sections[-1][0]) <= r.stages.keys()):
            stages, group = sections.pop()
            sections.append((list(dict.fromkeys([*stages, *r.stages])), [*group, r]))
        else:
            sections.append((list(r.stages), [r]))
    return "\n\n".join("\n".join(_validate_section(stages, group)) for stages, group in sections)


def _validate_section(stages, rows):
    """Lines of one table of format_validate."""
    fields = {"scene": [r.scene for r in rows], "mode": [r.mode for r in rows]}
    varying = [name for name, values in fields.items() if len(set(values)) > 1] or ["scene"]
    label = ", ".join(varying)
    labels = [", ".join(values) for values in zip(*(fields[name] for name in varying))]
    common = "; ".join(f"{name} {values[0]}" for name, values in fields.items() if name not in varying)
    columns = [("total", [f"{r.total_seconds:.3f}" for r in rows])]
    columns += [(s, [f"{r.stages[s]:.4f}" if s in r.stages else "" for r in rows]) for s in stages]
    lines = wrap(f"{common}: seconds, in total and per stage" if common else "seconds, in total and per stage", WIDTH)
    for i, block in enumerate(_blocks(max(map(len, [label, *labels])), columns)):
        table = [[name, *(cells[j] for _, cells in block)] for j, name in enumerate(labels)]
        table = [row for row in table if any(row[1:])]  # a run without these stages is in the first block
        lines += [""] * (i > 0) + plain_table([label, *(title for title, _ in block)], table, stack=True)
    return lines


def _blocks(label_width, columns, width=WIDTH):
    """columns [(title, cells)] split into as few consecutive blocks as fit beside the label column in
    `width`, as evenly as possible."""
    need = [max([len(w) for w in title.split()] + [len(c) for c in cells]) + len(GAP) for title, cells in columns]
    room = max(width - min(label_width, 3 * width // 5), max(need, default=0))

    def pack(capacity):
        blocks, used = [[]], 0
        for column, w in zip(columns, need):
            if blocks[-1] and used + w > capacity:
                blocks.append([])
                used = 0
            blocks[-1].append(column)
            used += w
        return blocks

    fewest = len(pack(room))
    return next(pack(c) for c in range(max(need, default=0), room + 1) if len(pack(c)) == fewest)
