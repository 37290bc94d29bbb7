"""Friedmann universes: the scale factor against cosmic time, distances and the Hubble diagram against redshift,
and the three together for one universe beside Planck 2018 and Einstein-de Sitter (cosmology_overview).

Each function takes {label: orbits.Cosmology} or one Cosmology and reads its methods.
"""

import math
from typing import Any

import astropy.units as u
import numpy as np

from orbits._common import display, frame
from orbits.cosmology.models import Cosmology


def scale_factor_curves(
    models: dict[str, Any], t_max: u.Quantity, ax: Any = None, samples: int = 400, log: bool = False
) -> tuple[Any, Any]:
    """a(t) against cosmic time for {label: Cosmology}, from the big bang to t_max (time Quantity).

    Each model has its own colour and line style (solid, dashed, dash-dotted, dotted), so two models that nearly
    coincide both show. A universe that recollapses is drawn through its turnaround (a dot) down to its big crunch
    (a cross) when they fall before t_max, each named with its model; today (a = 1) is the dotted grey line.
    `log` puts a on a log scale (from 1e-2), for models whose a(t) spans decades by t_max.
    """
    fig, ax = frame.axes(ax)
    unit = display.axis_unit(t_max)
    end = t_max.to_value(unit)
    styles = ("-", "--", "-.", ":")
    for k, (label, model) in enumerate(models.items()):
        color, style = f"C{k % 10}", styles[k % len(styles)]
        crunch = model.big_crunch_time.to_value(unit)
        last = min(end, crunch)
        times = np.linspace(0.0, last, samples) * unit
        ax.plot(times.to_value(unit), model.scale_factor(times).to_value(u.one), color=color, ls=style, lw=1.6,
                label=label)
        turnaround = model.turnaround_time.to_value(unit)
        when = {name: display.quantity_math(time, digits=4, unit=unit)
                for name, time in (("turnaround", model.turnaround_time), ("crunch", model.big_crunch_time))}
        if turnaround <= end:
            ax.plot(turnaround, model.model.max_scale_factor, marker="o", color=color, ls="none", clip_on=False,
                    label=f"{label}: turnaround, t = {when['turnaround']}")
        if crunch <= end:
            ax.plot(crunch, 1e-2 if log else 0.0, marker="X", ms=9, color=color, ls="none", clip_on=False,
                    label=f"{label}: big crunch, t = {when['crunch']}")
    ax.axhline(1.0, color="gray", lw=0.8, ls=":", label="today, a = 1")
    ax.set_xlim(0, end)
    if log:
        ax.set_yscale("log")
        ax.set_ylim(bottom=1e-2)
    else:
        ax.set_ylim(bottom=0)
    ax.set_xlabel(f"time since the big bang [{display.unit_math(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3, which="major")
    frame.legend_outside(ax)
    frame.title(ax, f"Scale factor a(t) of {_names(models)}, from the big bang to "
                    f"{display.quantity_math(t_max, digits=4, unit=unit)}")
    return fig, ax


def _names(models: dict[str, Any]) -> str:
    """The models' labels as a title lists them."""
    names = list(models)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _redshift_grid(z_max, samples):
    """Redshifts from 1e-3 to z_max, evenly spaced in log z (for a log z axis)."""
    return np.geomspace(1e-3, z_max, samples)


def hubble_diagram(
    models: dict[str, Any], z_max: float = 10.0, ax: Any = None, samples: int = 300,
    emphasis: str | None = None,
) -> tuple[Any, Any]:
    """The Hubble diagram: distance modulus mu = 5 log10(D_L / 10 pc) against redshift (log axis) for
    {label: Cosmology}, from z = 1e-3 to z_max; the model labelled `emphasis` is drawn last, thick and black, so
    that no reference curve hides it."""
    fig, ax = frame.axes(ax)
    z = _redshift_grid(z_max, samples)
    order = [label for label in models if label != emphasis] + ([emphasis] if emphasis in models else [])
    for k, label in enumerate(order):
        style = dict(color="k", lw=2.6, zorder=3) if label == emphasis else dict(color=f"C{k}", lw=1.4)
        ax.plot(z, models[label].distance_modulus(z).to_value(u.mag), label=label, **style)
    ax.set_xscale("log")
    ax.set_xlabel("redshift z")
    ax.set_ylabel("distance modulus m - M [mag]")
    ax.grid(alpha=0.3, which="both")
    frame.legend_outside(ax, columns=1)
    frame.title(ax, f"Hubble diagram of {_names(models)}, z = {display.number(z[0], 3)} to z = "
                    f"{display.number(z_max, 4)}")
    return fig, ax


def distance_curves(cosmology: Any, z_max: float = 10.0, ax: Any = None, samples: int = 300
                    ) -> tuple[Any, Any]:
    """Luminosity, transverse comoving and angular-diameter distances of one Cosmology against redshift (log-log);
    D_A peaks (objects look smallest) and then falls, D_L = (1 + z)**2 D_A."""
    fig, ax = frame.axes(ax)
    z = _redshift_grid(z_max, samples)
    curves = {
        "luminosity distance $D_L$": cosmology.luminosity_distance(z),
        "transverse comoving distance $D_M$": cosmology.transverse_comoving_distance(z),
        "angular-diameter distance $D_A$": cosmology.angular_diameter_distance(z),
    }
    unit = u.Mpc
    for k, (label, distance) in enumerate(curves.items()):
        ax.loglog(z, distance.to_value(unit), color=f"C{k}", label=label)
    ax.set_xlabel("redshift z")
    ax.set_ylabel(f"distance [{display.unit_math(unit)}]")
    ax.grid(alpha=0.3, which="both")
    frame.legend_outside(ax, columns=1)
    frame.title(ax, f"Distances to z = {display.number(z_max, 4)}: $D_L$ = (1 + z)$^2$ $D_A$")
    return fig, ax


def cosmology_overview(cosmology: Any, label: str, z_max: float = 10.0) -> tuple[Any, np.ndarray]:
    """Three panels for one universe: a(t) (to its big crunch if it recollapses, else to twice its age), its
    distances against z, and its Hubble diagram beside those of Planck 2018 and of Einstein-de Sitter with the
    same H0. The figure title is `label`."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 5.2), layout="constrained")
    crunch = cosmology.big_crunch_time
    if np.isfinite(cosmology.age()):
        t_max = crunch if np.isfinite(crunch) else 2 * cosmology.age()
        scale_factor_curves({"a(t)": cosmology}, t_max.to(display.axis_unit(t_max)), ax=axes[0])
    else:  # no big bang (de Sitter): a against the time from today, from z_max to a = 10
        _scale_factor_from_today(cosmology, z_max, axes[0])
    distance_curves(cosmology, z_max, ax=axes[1])
    references = {
        "Planck 2018 (flat, no radiation)": Cosmology.planck18(),
        "Einstein-de Sitter, same $H_0$": Cosmology.einstein_de_sitter(cosmology.hubble_constant),
    }
    same = [name for name, other in references.items() if _same_universe(other, cosmology)]
    models = {"this universe" + (f" = {same[0]}" if same else ""): cosmology,
              **{name: other for name, other in references.items() if name not in same}}
    hubble_diagram(models, z_max, ax=axes[2], emphasis=next(iter(models)))
    for ax, name in zip(axes, ("Scale factor", "Distances", "Hubble diagram"), strict=True):
        frame.title(ax, name)
    frame.title(fig, label, size="large")
    return fig, axes


def _same_universe(one: Any, other: Any) -> bool:
    """Whether two Cosmology objects have the same H0 and density parameters (to 1e-12)."""
    fields = ("h0", "omega_m", "omega_r", "omega_k", "omega_l")
    return all(math.isclose(getattr(one, f), getattr(other, f), rel_tol=1e-12, abs_tol=1e-15) for f in fields)


def _scale_factor_from_today(cosmology: Any, z_max: float, ax: Any) -> None:
    """a = 1 / (1 + z) against t - t0 = -lookback time(z), from z_max to a = 10 (z = -0.9): the a(t) panel of a
    universe with no big bang, whose age is infinite."""
    z = np.concatenate([np.geomspace(z_max, 1e-3, 200), [0.0], -np.geomspace(1e-3, 0.9, 200)])
    time = -cosmology.lookback_time(z)
    unit = display.axis_unit(np.max(np.abs(time)))
    ax.plot(time.to_value(unit), 1.0 / (1.0 + z), color="C0", label="a(t): no big bang, infinite age")
    ax.axhline(1.0, color="gray", lw=0.8, ls=":", label="today, a = 1")
    ax.axvline(0.0, color="gray", lw=0.8, ls=":")
    ax.set_yscale("log")
    ax.set_xlabel(f"time from today [{display.unit_math(unit)}]")
    ax.set_ylabel("scale factor a [dimensionless]")
    ax.grid(alpha=0.3, which="both")
    frame.legend_outside(ax)
