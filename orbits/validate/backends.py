"""Registry of the validation backends: what each offers, whether it is installed, and a uniform entry point.

Each backend is registered with its adapter's integrate function, imported here like any other name (editors and
the layering test follow it). The adapters import rebound and heyoka inside integrate, so loading this registry
loads neither library.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from dataclasses import dataclass

from orbits.core.errors import OrbitDomainError
from orbits.validate import _heyoka, _rebound
from orbits.validate.nbody import NBodyProblem, NBodyResult


@dataclass(frozen=True)
class BackendInfo:
    """Static description of one backend.

    ``integrate`` is the adapter's entry point; ``package`` is the third-party module it needs.
    ``supports_extended_precision`` states what the installed library build can do (heyoka 7.13.2 ships
    long double and real128 integrators); the adapters themselves always integrate in float64.
    """

    name: str
    package: str
    integrate: Callable[..., NBodyResult]
    integrators: tuple[str, ...]
    supports_test_particles: bool
    supports_extended_precision: bool


BACKENDS: dict[str, BackendInfo] = {
    "rebound": BackendInfo(
        name="rebound",
        package="rebound",
        integrate=_rebound.integrate,
        integrators=_rebound.INTEGRATORS,
        supports_test_particles=True,
        supports_extended_precision=False,
    ),
    "heyoka": BackendInfo(
        name="heyoka",
        package="heyoka",
        integrate=_heyoka.integrate,
        integrators=("taylor_adaptive",),
        supports_test_particles=True,
        supports_extended_precision=True,
    ),
}


def _info(name: str) -> BackendInfo:
    """Return the registry entry for ``name``; raise OrbitDomainError naming the known backends."""
    try:
        return BACKENDS[name]
    except KeyError:
        raise OrbitDomainError(f"backend = {name!r} is unknown; choose one of {sorted(BACKENDS)}") from None


def available(name: str) -> bool:
    """Return whether the library behind backend ``name`` is installed (found without importing it)."""
    return importlib.util.find_spec(_info(name).package) is not None


def integrate(name: str, problem: NBodyProblem, **settings: object) -> NBodyResult:
    """Run ``problem`` on backend ``name`` with the adapter's keyword ``settings``; return its NBodyResult."""
    info = _info(name)
    if not available(name):
        raise ModuleNotFoundError(
            f"backend {name!r} needs the {info.package!r} package, which is not installed (pip install {info.package})"
        )
    return info.integrate(problem, **settings)
