"""`orbits rocket`: the rocket equation (notes X, sign corrected), stages, burn times at constant thrust."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OnlyOption

Masses = Annotated[list[str] | None, typer.Option(
    help="one per stage, bottom first (repeat the option), e.g. '2100 t'")]


def command(
    m0: Annotated[str | None, typer.Option("--m0", help="single stage: initial (wet) mass, e.g. '100 t'")] = None,
    mf: Annotated[str | None, typer.Option("--mf", help="single stage: final (dry) mass, e.g. '40 t'")] = None,
    propellant: Masses = None,
    structure: Masses = None,
    payload: Annotated[str | None, typer.Option(help="staged: the payload mass, e.g. '45 t'")] = None,
    isp: Annotated[list[str] | None, typer.Option(
        "--isp", help="specific impulse, one for all stages or one per stage, e.g. '300 s'")] = None,
    exhaust_speed: Annotated[list[str] | None, typer.Option(
        "--exhaust-speed", help="exhaust speed instead of --isp, e.g. '3 km/s'")] = None,
    thrust: Annotated[list[str] | None, typer.Option(
        help="constant thrust, one for all stages or one per stage, e.g. '34 MN' (gives the burn times)")] = None,
    g: Annotated[str | None, typer.Option(
        "--g", help="uniform gravity for a vertical ascent, e.g. '9.80665 m/s2' (gives the gravity loss)")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Delta-v of a rocket v_e ln(m0 / mf) per stage and in total, and burn times at constant thrust (X.ii)."""
    from orbits import Rocket
    from orbits._common import inputs
    from orbits_cli import render

    single = m0 is not None or mf is not None
    if single == (propellant is not None or structure is not None or payload is not None):
        raise typer.BadParameter("give --m0 and --mf (one stage) or --propellant, --structure and --payload (stages)")
    if single and (m0 is None or mf is None):
        raise typer.BadParameter("a single stage needs both --m0 and --mf")
    if not single and (not propellant or not structure or payload is None):
        raise typer.BadParameter("stages need --propellant and --structure for each stage, and --payload")
    stage_count = 1 if single else len(propellant)
    for option, values in (("--isp", isp), ("--exhaust-speed", exhaust_speed), ("--thrust", thrust)):
        if values and len(values) not in (1, stage_count):
            raise typer.BadParameter(f"{len(values)} {option} for {stage_count} stage{'s' * (stage_count > 1)}: "
                                     f"give one for all stages or one per stage")
    speeds = {"exhaust_speed": _each(exhaust_speed, "speed", "--exhaust-speed")} if exhaust_speed else {}
    if isp:
        speeds["isp"] = _each(isp, "time", "--isp")
    force = None if not thrust else _each(thrust, "force", "--thrust")
    if single:
        rocket = Rocket.single_stage(inputs.parse_quantity(m0, "mass", "--m0"),
                                     inputs.parse_quantity(mf, "mass", "--mf"), thrust=force, **speeds)
    else:
        if len(propellant) != len(structure):
            raise typer.BadParameter(f"{len(propellant)} --propellant but {len(structure)} --structure: one of each "
                                     "per stage")
        rocket = Rocket.staged(_each(propellant, "mass", "--propellant"), _each(structure, "mass", "--structure"),
                               inputs.parse_quantity(payload, "mass", "--payload"), thrust=force, **speeds)
    result = rocket.quantities(inputs.names(only))
    if g is not None:
        gravity = inputs.parse_quantity(g, "acceleration", "--g")
        result |= {"gravity_loss": rocket.gravity_loss(gravity),
                   "vertical_ascent_speed": rocket.vertical_ascent_speed(gravity)}
    stages = f"{rocket.stages} stages" if rocket.stages > 1 else "one stage"
    render.emit(f"Rocket, {stages} (delta-v = v_e ln(m0 / mf), the rocket equation of notes X)", result, fmt.value)


def _each(texts, kind, option):
    """One Quantity array from a repeated option."""
    import astropy.units as u

    from orbits import OrbitDomainError
    from orbits._common import inputs

    values = [inputs.parse_quantity(text, kind, option) for text in texts]
    unit = values[0].unit
    if len(values) == 1:
        return values[0]
    try:
        return u.Quantity([v.to(unit) for v in values])
    except u.UnitConversionError:
        raise OrbitDomainError(f"{option}: {', '.join(texts)} do not share one kind of unit") from None

