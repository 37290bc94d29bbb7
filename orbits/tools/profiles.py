"""CPU profiles: compute on this machine as a machine of another CPU class would, to find what changes with it.

Three libraries choose their machine code by the CPU they find, and each choice moves the last bits of a result:
numba compiles the kernels for the host's CPU (LLVM vectorises for its widest registers and fuses multiply-adds
differently), NumPy dispatches its loops (sin, exp, sums) to the widest instructions the CPU has, and OpenBLAS
picks its matrix kernels (the Newton steps' solves and the SVDs of the periodic-orbit correctors) by core type.
A profile sets the environment each of them reads at start-up:

    avx2     NUMBA_CPU_NAME=haswell with NUMBA_CPU_FEATURES empty (the AVX2 and FMA of Haswell, nothing wider),
             NPY_DISABLE_CPU_FEATURES = NumPy's dispatch targets that need AVX-512 on this build,
             OPENBLAS_CORETYPE=Haswell (the kernels OpenBLAS also runs on AMD Zen)
    native   the host as it is (the variables above removed)

On an AVX-512 host the avx2 profile reproduces what an AVX2 machine (Intel Haswell to Alder Lake, AMD Zen 1 to 3)
computes; numba keeps the kernels of each target apart in its cache. The profile only narrows: on a host without
AVX2 it is refused. `python -m orbits.tools.profiles avx2 COMMAND ...` runs a command under it (CI runs the
numerics-sensitive tests that way); `describe()` names the profile a process runs under, for benchmark tables.
"""

import contextlib
import os
import sys

PROFILES = ("native", "avx2")
#: the variables a profile sets or removes
VARIABLES = ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES", "NPY_DISABLE_CPU_FEATURES", "OPENBLAS_CORETYPE")


def cpu_info() -> tuple[str, set]:
    """(the CPU's model name, its feature flags) from /proc/cpuinfo; ("", set()) where there is none (not Linux)."""
    name, flags = "", set()
    with contextlib.suppress(OSError), open("/proc/cpuinfo", encoding="ascii", errors="replace") as info:
        for line in info:
            key, _, value = line.partition(":")
            if key.strip() == "model name" and not name:
                name = value.strip()
            elif key.strip() == "flags" and not flags:
                flags = set(value.split())
    return name, flags


def _numpy_wide_targets() -> list:
    """NumPy's dispatch targets that need AVX-512 (their names vary with NumPy's version: AVX512F, AVX512_SKX,
    X86_V4, AVX512_SPR ...); only these may be named in NPY_DISABLE_CPU_FEATURES."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__ as targets
    except ImportError:  # NumPy 1.x
        from numpy.core._multiarray_umath import __cpu_dispatch__ as targets
    return [name for name in targets if name.startswith("AVX512") or name == "X86_V4"]


def environment(profile: str, base: dict | None = None) -> dict:
    """A copy of `base` (os.environ by default) set for `profile` (one of PROFILES); ValueError for an unknown
    profile, or for avx2 on a host without AVX2 (a profile narrows the host's instructions, never widens them)."""
    if profile not in PROFILES:
        raise ValueError(f"unknown CPU profile {profile!r}; choose from {', '.join(PROFILES)}")
    env = {k: v for k, v in (os.environ if base is None else base).items() if k not in VARIABLES}
    if profile == "avx2":
        if "avx2" not in cpu_info()[1]:
            raise ValueError("the avx2 profile needs a host with AVX2 (it narrows the host's instructions)")
        env.update(NUMBA_CPU_NAME="haswell", NUMBA_CPU_FEATURES="", OPENBLAS_CORETYPE="Haswell",
                   NPY_DISABLE_CPU_FEATURES=" ".join(_numpy_wide_targets()))
    return env


def describe() -> str:
    """"" for a process on its host as it is, else ", under the AVX2 profile" (numba's target, NumPy's dispatch and
    OpenBLAS's kernels as an AVX2 machine has them), for the line that names the machine."""
    if os.environ.get("NUMBA_CPU_NAME") == "haswell" and os.environ.get("OPENBLAS_CORETYPE") == "Haswell":
        return ", under the AVX2 profile"
    return ""


def main(argv: list) -> int:
    """python -m orbits.tools.profiles PROFILE COMMAND [ARG ...]: run COMMAND under PROFILE."""
    if len(argv) < 2:
        print(f"usage: python -m orbits.tools.profiles {{{','.join(PROFILES)}}} COMMAND [ARG ...]", file=sys.stderr)
        return 2
    try:
        env = environment(argv[0])
        os.execvpe(argv[1], argv[1:], env)
    except ValueError as err:
        print(f"error: {err}", file=sys.stderr)
    except OSError as err:
        print(f"error: cannot run {argv[1]!r}: {err.strerror}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
