"""Quantity tables shared by the domain objects: {snake_case name: Quantity}, `only` selecting names."""

from collections.abc import Callable, Collection, Iterable
from typing import Any

from orbits.core.errors import OrbitDomainError, UnknownNameError


def check_names(names: Iterable[str], allowed: Collection[str]) -> None:
    """Raise KeyError listing the allowed names if any of `names` is not one of them."""
    unknown = [n for n in names if n not in allowed]
    if unknown:
        raise UnknownNameError(f"unknown quantities {unknown}; choose from {', '.join(allowed)}")


def quantity_table(
    lookup: Callable[[str], Any], allowed: Collection[str], only: Iterable[str] | None = None
) -> dict[str, Any]:
    """{name: Quantity} for `only` (default: all `allowed`); lookup(name) returns a Quantity or a dict of them.

    A name of `only` may also be one row of such a dict, as the table shows it (covertex_time_periapsis_side of
    covertex_times). Without `only`, names this object does not have (lookup raises OrbitDomainError, e.g. the
    period of a hyperbola) are left out; names asked for explicitly raise instead.
    """
    names = allowed if only is None else list(only)
    rows = _rows_of_groups(lookup, allowed) if any(name not in allowed for name in names) else {}
    check_names(names, [*allowed, *rows])
    result = {}
    for name in names:
        try:
            value = lookup(rows.get(name, name))
        except OrbitDomainError:
            if only is not None:
                raise
            continue
        if name in rows:
            value = {name: value[name]}
        result.update(value if isinstance(value, dict) else {name: value})
    return result


def _rows_of_groups(lookup: Callable[[str], Any], allowed: Collection[str]) -> dict[str, str]:
    """{row name: its group's name} of every allowed name whose lookup is a dict of rows (the object has it)."""
    rows = {}
    for group in allowed:
        try:
            value = lookup(group)
        except OrbitDomainError:
            continue
        if isinstance(value, dict):
            rows.update(dict.fromkeys(value, group))
    return rows


def attribute_table(obj: Any, names: Collection[str], only: Iterable[str] | None) -> dict[str, Any]:
    """{name: Quantity} of an object's (cached) properties named in `names` (`quantity_table` with getattr)."""
    return quantity_table(lambda name: getattr(obj, name), names, only)
