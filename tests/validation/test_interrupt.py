"""Ctrl-C stops an integration promptly with either backend (heyoka ran to the end of its grid before)."""

import os
import signal
import subprocess
import sys
import time

import pytest

from orbits.validate import backends

LONG_RUN = """
import numpy as np, sys
from orbits.validate import backends
from orbits.validate.builders import ring_problem
problem, _ = ring_problem(7, np.linspace(0, 200000 * np.pi, 4000)[1:], 1000.0)  # about 20 s
print("started", flush=True)
try:
    backends.integrate(sys.argv[1], problem, **({"adaptive_mode": "global"} if sys.argv[1] == "rebound" else {}))
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
"""


@pytest.mark.parametrize("backend", ["rebound", "heyoka"])
def test_ctrl_c_stops_an_integration_promptly(backend, tmp_path):
    if not backends.available(backend):
        pytest.skip(f"{backend} is not installed")
    process = subprocess.Popen([sys.executable, "-c", LONG_RUN, backend], stdout=subprocess.PIPE, text=True,
                               env={**os.environ, "HEYOKA_CACHE_DIR": str(tmp_path)})
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.5)  # past heyoka's compile, well inside the run
    sent = time.perf_counter()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=60)
    assert out.strip() == "interrupted"
    assert time.perf_counter() - sent < 2.0  # measured 0.06 s (rebound), 0.26 s (heyoka); 18 s before
