"""`orbits validate`: the main job. Predict each scene analytically, integrate it with rebound and heyoka,
and report the differences, the run times and the settings; exit status 1 if any check fails."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OutputOption, PlotOption, save_plot


def command(
    scenes: Annotated[
        list[str] | None, typer.Argument(metavar="[SCENE]...", help="built-in scene names or .toml/.json files")
    ] = None,
    backend: Annotated[str, typer.Option(help="comma-separated backends")] = "rebound,heyoka",
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
    sweep: Annotated[
        bool, typer.Option(help="run the scenes as dask tasks (pip install 'orbits\\[dask]'), one per scene")
    ] = False,
    scheduler: Annotated[
        str | None, typer.Option(help="with --sweep: dask scheduler address, e.g. tcp://host:8786 (default: local)")
    ] = None,
    quiet: Annotated[bool, typer.Option("--quiet", help="print the one-screen summary alone (each scene's worst "
                                                        "check per backend and its time), not every check")] = False,
) -> None:
    """Cross-check the analytic answers of the built-in scenes (or the given ones) against N-body codes: every
    check of every scene, then a one-screen summary (--quiet: the summary alone)."""
    import sys

    from orbits._common.io import write_atomic
    from orbits.validate import available, builtin_names, load, unavailable_builtins, validate
    from orbits_cli import render

    if quiet and fmt == Format.json:
        raise typer.BadParameter("--quiet shortens the table; the JSON is always whole (drop one of them)")
    names = scenes
    if not names:  # the built-in scenes this install can run; the others are named, with what they need
        skipped = unavailable_builtins()
        names = [name for name in builtin_names() if name not in skipped]
        for name, reason in skipped.items():
            print(f"orbits: skipped the built-in scene {name}: it {reason}", file=sys.stderr)
    loaded = [load(name) for name in names]  # every scene is checked before anything runs
    chosen = [b.strip() for b in backend.split(",") if b.strip()]
    if not chosen:
        raise typer.BadParameter(f"--backend {backend!r}: give at least one of rebound, heyoka")
    for name in chosen:
        if not available(name):
            raise typer.BadParameter(f"--backend: {name} is not installed (pip install {name})")
    if sweep or scheduler:
        validate = _sweeper(scheduler)
    report = _run(validate, loaded, chosen, show_progress=fmt == Format.table and sys.stdout.isatty())
    data = report.to_dict()
    if output:
        write_atomic(output, render.dumps(data) + "\n")
    if plot:
        from orbits.plot import validation_overview

        save_plot(lambda: validation_overview(report), plot)
    if fmt == Format.json:
        print(render.dumps(data))
    elif quiet:
        render.validation_summary(data)
    else:
        render.validation_report(data)
    if not report.passed:
        raise typer.Exit(1)


def _sweeper(address):
    """validate(scenes, backend_names, progress=None) running each scene as a task on a dask cluster."""
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise typer.BadParameter("--sweep needs dask: pip install 'orbits[dask]'") from None
    from orbits.tools.distributed import sweep_client, validate_sweep

    def run(scenes, backend_names, progress=None):
        with sweep_client(address) as client:
            return validate_sweep(scenes, client, backend_names, progress=progress)

    return run


def _run(validate, scenes, backend_names, show_progress):
    """Run the validation; on a terminal, a live bar per scene that follows each integration as it goes."""
    if not show_progress:
        return validate(scenes, backend_names)
    from rich.progress import BarColumn, Progress, TaskProgressColumn, TextColumn, TimeElapsedColumn

    from orbits.validate.nbody import reporting

    columns = (TextColumn("{task.description}"), BarColumn(), TaskProgressColumn(), TimeElapsedColumn())
    with Progress(*columns, transient=True) as progress:
        task = progress.add_task("validating", total=len(scenes))
        from orbits._common.display import printable

        names = [scene.name for scene in scenes]
        current = {"index": 0, "runs": 0, "last": 0.0}  # scene, backends finished in it, last fraction

        def advance(name):
            current.update(index=names.index(name), runs=0, last=0.0)
            progress.update(task, description=f"validating {printable(name)}", completed=current["index"])

        def integrating(fraction):
            if fraction < current["last"]:  # the next backend started
                current["runs"] += 1
            current["last"] = fraction
            share = (current["runs"] + fraction) / max(1, len(backend_names))
            progress.update(task, completed=current["index"] + min(1.0, share))

        with reporting(integrating):
            report = validate(scenes, backend_names, progress=advance)
        progress.update(task, completed=len(scenes))
    return report
