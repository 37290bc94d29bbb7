"""The same answers on another CPU class: a run under the AVX2 profile (orbits.tools.profiles: numba's Haswell
target, NumPy without AVX-512 dispatch, OpenBLAS's Haswell kernels) against this process, on the host as it is.

A continuation that took its decisions (a step halved or grown, a member accepted, a turning point declared) on
rounding noise would follow another path on another CPU and come out with other members; these tests hold the
members of periodic families to the corrector's noise across the two profiles.
"""

import json
import subprocess
import sys

import numpy as np
import pytest

from orbits.tools import profiles

FAMILIES = """
import json, sys
import numpy as np
from orbits import PeriodicFamily, RestrictedThreeBody
em = RestrictedThreeBody.from_primaries("Earth", "Moon")
out = {}
for spacing in ("period", "arclength"):
    family = PeriodicFamily.of(em, "nrho", members=6, spacing=spacing, resonance="9:2")
    q = family.quantities(["dimensionless_position", "dimensionless_velocity", "period"])
    out[spacing] = np.hstack([q["dimensionless_position"].value, q["dimensionless_velocity"].value,
                              q["period"].to_value("d")[:, None]]).tolist()
json.dump(out, sys.stdout)
"""


def _avx2_host():
    try:
        profiles.environment("avx2")
    except ValueError:
        return False
    return True


pytestmark = pytest.mark.skipif(not _avx2_host(), reason="the AVX2 profile needs a host with AVX2")


def _families(profile):
    env = profiles.environment(profile)
    done = subprocess.run([sys.executable, "-c", FAMILIES], env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return {k: np.array(v) for k, v in json.loads(done.stdout).items()}


def test_a_family_has_the_same_members_under_the_avx2_profile():
    """The Earth-Moon southern halo family out to the 9:2 NRHO, six members spaced in period and in arclength:
    states within 2e-13 of the rotating frame's units and periods within 1e-13 of themselves on both profiles
    (measured 1.9e-14 and 9e-15; before the continuation's step control was freed of the Newton iterations spent at
    the noise floor, the arclength-spaced members differed by 3e-6 and the period spacing failed on AVX2)."""
    native, avx2 = _families("native"), _families("avx2")
    for spacing in ("period", "arclength"):
        a, b = native[spacing], avx2[spacing]
        assert np.max(np.abs(a[:, :6] - b[:, :6])) <= 2e-13, spacing
        assert np.max(np.abs(a[:, 6] / b[:, 6] - 1.0)) <= 1e-13, spacing


def test_the_profile_reaches_each_library():
    """Under the profile numba compiles for Haswell, NumPy dispatches no AVX-512 loop and OpenBLAS is told its core
    type; the native profile clears all three."""
    code = ("import os, numba, numpy as np; from numpy._core._multiarray_umath import __cpu_features__ as f, "
            "__cpu_dispatch__ as d; print(numba.config.CPU_NAME, [k for k in d if f[k] and "
            "(k.startswith('AVX512') or k == 'X86_V4')], os.environ.get('OPENBLAS_CORETYPE'))")
    avx2 = subprocess.run([sys.executable, "-c", code], env=profiles.environment("avx2"), capture_output=True,
                          text=True, timeout=120)
    assert avx2.stdout.split() == ["haswell", "[]", "Haswell"], avx2.stderr
    native = profiles.environment("native", {"NUMBA_CPU_NAME": "haswell", "OPENBLAS_CORETYPE": "Haswell", "X": "1"})
    assert native == {"X": "1"}


def test_an_unknown_profile_is_refused_in_one_line():
    with pytest.raises(ValueError, match="unknown CPU profile 'avx1'; choose from native, avx2"):
        profiles.environment("avx1")


def test_the_command_line_refuses_in_one_line():
    for words, message in ((["avx9", "true"], "unknown CPU profile 'avx9'"),
                           (["native", "no-such-command-here"], "cannot run 'no-such-command-here'"),
                           (["native"], "usage: python -m orbits.tools.profiles")):
        done = subprocess.run([sys.executable, "-m", "orbits.tools.profiles", *words], capture_output=True, text=True,
                              timeout=60)
        assert done.returncode == 2 and message in done.stderr and len(done.stderr.splitlines()) == 1, done.stderr
