"""`orbits info`: versions, caches, the ephemeris and the catalogue of bodies; --sources adds where each
constant comes from."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption

WIDTH = 80


def command(
    sources: Annotated[bool, typer.Option("--sources", help="also list the source of every constant")] = False,
    compile_kernels: Annotated[bool, typer.Option(
        "--compile", help="first compile every kernel not yet in the cache (once per machine and version)")] = False,
    fmt: FormatOption = Format.table,
) -> None:
    """Versions of orbits and its dependencies, where the compiled code is cached and which kernels it holds, which
    ephemeris answers, and the catalogue of bodies (GM, radius, rotation, J2); with --sources, the publication
    behind each constant.

    A kernel absent from the cache compiles at the first batch of 65,536 elements or more that needs it (smaller
    ones run the NumPy implementation meanwhile); --compile compiles them all now, saying how long each took."""
    if compile_kernels:
        _compile()
    show(fmt.value, sources)


def _compile() -> None:
    """Compile the absent kernels, one line on stderr for each, with its time."""
    from orbits.tools.kernels import compile_all

    def report(kernel: str, seconds: float | None) -> None:
        if seconds is not None:
            typer.echo(f"orbits: compiled {kernel} in {seconds:.1f} s", err=True)

    spent = compile_all(report)
    if spent:
        typer.echo(f"orbits: {len(spent)} kernels compiled in {sum(spent.values()):.0f} s", err=True)


def show(fmt: str, sources: bool = False) -> None:
    """Print the facts as text within 80 columns (paths, which cannot be broken, on lines of their own) or as
    JSON (which always holds the sources)."""
    from orbits._common.system import info
    from orbits_cli import render

    facts = info()
    if fmt == "json":
        print(render.dumps(facts))
        return
    print("\n".join(_summary(facts)))
    render.print_tables([_bodies(facts["bodies"])], None)
    if sources:
        print("\n".join(_sources(facts["constants"])))
    else:
        print("The source of every constant: orbits info --sources")


def _wrapped(label: str, text: str) -> list[str]:
    """`label: text` wrapped between words, continuation lines indented."""
    from orbits._common.display import wrapped

    return wrapped(f"{label}: {text}", WIDTH, subsequent_indent="    ")


def _summary(facts: dict) -> list[str]:
    from orbits._common.display import wrapped

    versions = facts["versions"]
    others = ", ".join(f"{name} {version}" for name, version in versions.items() if name != "orbits")
    lines = [f"orbits {versions['orbits']} on Python {facts['python']} ({facts['platform']})", ""]
    lines += _wrapped("versions", others)
    lines += _wrapped("ephemeris", facts["ephemeris"])
    caches = dict(facts["caches"])
    lines += _wrapped("compiled kernels in use", caches.pop("compiled kernels in use (ORBITS_JIT)"))
    lines += _wrapped("kernels in the cache", _readiness(facts["kernels_ready"]))
    lines.append("caches:")
    for label, path in caches.items():
        lines += wrapped(label, WIDTH, initial_indent="  ", subsequent_indent="  ") + [f"    {path}"]
    return lines + [""]


def _readiness(ready: dict[str, bool]) -> str:
    """"all 7" or "3 of 7; absent: ..., compiled by orbits info --compile"."""
    absent = [kernel.rpartition("._fast_")[2] for kernel, is_ready in ready.items() if not is_ready]
    if not absent:
        return f"all {len(ready)}"
    return (f"{len(ready) - len(absent)} of {len(ready)}; absent: {', '.join(absent)} (orbits info --compile "
            f"compiles them)")


def _sources(constants: dict) -> list[str]:
    from orbits._common.display import wrapped

    lines = ["", "sources:"]
    for name, source in constants.items():
        lines += wrapped(f"{name}: {source}", WIDTH, initial_indent="  ", subsequent_indent="      ")
    return lines


def _bodies(rows: list):
    """The catalogue as a table in natural units: GM km3/s2, radius km, rotation d (- retrograde), and J2 (times
    1e6) beside the reference radius of its fit, which J2 is meaningless without (Neptune's 3408.43e-6 holds at
    25,225 km, not at its 24,764 km equatorial radius)."""
    from rich import box
    from rich.table import Table

    from orbits._common.display import number

    table = Table(box=box.SIMPLE, pad_edge=False, padding=(0, 0),
                  title="bodies (rot. < 0: retrograde; @ R: the reference radius of J2)")
    for name, justify in (("body", "left"), ("kind", "left"), ("orbits", "left"), ("GM km3/s2", "right"),
                          ("R km", "right"), ("rot. d", "right"), ("1e6 J2", "right"), ("@ R km", "right")):
        table.add_column(name, justify=justify, no_wrap=True)
    for b in rows:
        rotation = b["rotation_period_s"] / 86400.0 * (-1 if b["retrograde"] else 1)
        has_j2 = b["j2"] is not None
        table.add_row(b["name"], b["kind"], b["parent"] or "", number(b["gm_m3_s2"] / 1e9, 7),
                      number(b["radius_m"] / 1e3, 6), number(rotation, 6),
                      number(b["j2"] * 1e6, 6) if has_j2 else "",
                      number(b["j2_radius_m"] / 1e3, 6) if has_j2 else "")
    return table
