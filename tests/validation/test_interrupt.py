"""Ctrl-C stops an integration promptly with either backend (heyoka ran to the end of its grid before), and a
command line run at once, also after a rebound integration has finished (rebound's handler stayed installed)."""

import os
import pty
import select
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


LONG_SCENE = """
name = "long_after_rebound"
description = "a satellite over half a million orbits: minutes of integration"
asks = ["positions"]
[time]
periods = 500000
outputs = 10
[[bodies]]
name = "Earth"
body = "Earth"
[[bodies]]
name = "satellite"
test_particle = true
orbit = { primary = "Earth", p = "7000 km", e = 0.1 }
"""


def _orbits(*args: str) -> list[str]:
    return [sys.executable, "-c", "from orbits_cli.main import app; app()", *args]


def _read_until(fd: int, text: bytes, timeout: float) -> bytes:
    """What the terminal `fd` shows until `text` appears (or the time is up)."""
    seen, end = b"", time.monotonic() + timeout
    while text not in seen and time.monotonic() < end:
        ready, _, _ = select.select([fd], [], [], 0.2)
        if ready:
            try:
                seen += os.read(fd, 65536)
            except OSError:  # the process ended: the terminal is closed
                break
    return seen


def _interrupted_within_two_seconds(process: subprocess.Popen) -> float:
    """Send Ctrl-C; the seconds until the process has ended (a process still running after 30 s is killed)."""
    sent = time.perf_counter()
    process.send_signal(signal.SIGINT)
    try:
        process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
    return time.perf_counter() - sent


def test_ctrl_c_stops_orbits_validate_after_a_rebound_integration_and_writes_nothing(tmp_path):
    """rebound left its own SIGINT handler installed after each integrate, so a Ctrl-C in a later heyoka run or in
    Python went unseen: `orbits validate --output` ran to the end and wrote its file."""
    for name in ("rebound", "heyoka"):
        if not backends.available(name):
            pytest.skip(f"{name} is not installed")
    scene = tmp_path / "long.toml"
    scene.write_text(LONG_SCENE)
    output = tmp_path / "report.json"
    terminal, child = pty.openpty()  # a terminal, so that the progress bar names the scene being run
    process = subprocess.Popen(_orbits("validate", "circular", str(scene), "--backend", "heyoka,rebound", "--output",
                                       str(output)),
                               stdin=subprocess.DEVNULL, stdout=child, stderr=subprocess.PIPE, cwd=tmp_path,
                               env={**os.environ, "HEYOKA_CACHE_DIR": str(tmp_path), "TERM": "xterm"})
    os.close(child)
    try:
        # the scene `circular` has run with heyoka, then rebound: the long scene starts after a rebound integration
        shown = _read_until(terminal, b"validating long_after_rebound", timeout=60)
        assert b"validating long_after_rebound" in shown, shown[-400:]
        seconds = _interrupted_within_two_seconds(process)
    finally:
        os.close(terminal)
    assert seconds < 2.0, seconds  # measured 0.5 s; ran on for 3 minutes before (heyoka 18 s, then rebound)
    with process.stderr:
        assert process.returncode == 130 and process.stderr.read().decode().strip() == "orbits: interrupted"
    assert not output.exists() and not list(tmp_path.glob(".report.json.*"))


def test_ctrl_c_stops_bench_precision_after_its_rebound_runs_and_writes_nothing(tmp_path):
    """The same for `orbits bench precision`: its rebound runs come first, then heyoka's and scipy's (about 15 s
    on this problem), which a Ctrl-C did not stop."""
    for name in ("rebound", "heyoka"):
        if not backends.available(name):
            pytest.skip(f"{name} is not installed")
    pytest.importorskip("scipy")
    output = tmp_path / "precision.json"
    process = subprocess.Popen(_orbits("bench", "precision", "--quick", "--problem", "e=0.999", "--output",
                                       str(output)),
                               stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               cwd=tmp_path, env={**os.environ, "HEYOKA_CACHE_DIR": str(tmp_path)})
    time.sleep(8.0)  # the rebound runs end about 3 s in (start-up included); scipy's DOP853 runs until about 20 s
    assert process.poll() is None, "the run ended before it was interrupted"
    seconds = _interrupted_within_two_seconds(process)
    assert seconds < 2.0, seconds  # measured 0.1 s; ran to the end before (about 12 s more)
    with process.stderr:
        assert process.returncode == 130 and process.stderr.read().decode().strip().endswith("orbits: interrupted")
    assert not output.exists()


def test_an_interrupt_a_library_turned_into_another_exception_is_still_an_interrupt(capsys):
    """Ctrl-C while heyoka imports sympy left sympy half-loaded, and the run ended in AttributeError's traceback:
    a SIGINT seen during the command makes whatever it raises an interrupt (exit 130), while the same exception
    without one still surfaces as the bug it is, and input errors stay one line with exit 2."""
    import os
    import signal

    import typer

    from orbits import OrbitDomainError
    from orbits_cli.options import reports_errors

    def interrupted_import():
        try:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1.0)  # the handler runs here
        except KeyboardInterrupt:
            pass  # swallowed, as an import cut short leaves it
        raise AttributeError("module 'sympy' has no attribute 'core'")

    def plain_bug():
        raise AttributeError("a bug")

    def bad_input():
        raise OrbitDomainError("e = 2 is outside [0, 1)")

    with pytest.raises(typer.Exit) as stop:
        reports_errors(interrupted_import)()
    assert stop.value.exit_code == 130 and capsys.readouterr().err == "orbits: interrupted\n"
    with pytest.raises(AttributeError, match="a bug"):
        reports_errors(plain_bug)()
    with pytest.raises(typer.Exit) as stop:
        reports_errors(bad_input)()
    assert stop.value.exit_code == 2 and capsys.readouterr().err == "orbits: error: e = 2 is outside [0, 1)\n"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_ctrl_c_left_in_rebounds_flag_as_an_integrate_returns_is_an_interrupt(monkeypatch):
    """A Ctrl-C that reaches rebound's handler after its loop last looked, as integrate returns and before Python's
    handler is back, lived only in rebound's flag, which its next call clears: `orbits validate` of a long j2_iss
    scene then ran to the end and exited 0 (about one Ctrl-C in seven). The flag is read after every call."""
    if not backends.available("rebound"):
        pytest.skip("rebound is not installed")
    import rebound

    from orbits.validate import _rebound

    sim = rebound.Simulation()
    sim.add(m=1.0)
    sim.add(m=0.0, a=1.0, e=0.1)
    original = rebound.Simulation.integrate

    def late_ctrl_c(self, *args, **kwargs):  # the signal lands in rebound's handler just after its last look
        original(self, *args, **kwargs)
        _rebound._interrupt_flag().value = 1

    _rebound._integrate_to(sim, 1.0)  # an uninterrupted call returns
    monkeypatch.setattr(rebound.Simulation, "integrate", late_ctrl_c)
    with pytest.raises(KeyboardInterrupt):
        _rebound._integrate_to(sim, 2.0)
    assert sim.t == 2.0


KERNEL_BATCH = """
import numpy as np
from orbits.core.manoeuvres.lambert import solve
n = 1 << 22
rng = np.random.default_rng(1)
r1, r2, tof = rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), np.full(n, 2000.0)
solve(r1[:8], r2[:8], tof[:8], 1.0, 20, "left")  # the kernel compiled or loaded
print("started", flush=True)
try:
    solve(r1, r2, tof, 1.0, 20, "left")  # one call of about 6 s (20 revolutions, one thread)
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
"""


def test_ctrl_c_stops_a_compiled_batch_between_its_rounds():
    """A compiled loop never looks at signals: one call over 4 million 20-revolution Lambert transfers (6 s on one
    thread) ran to its end before a Ctrl-C was seen. Batches run in rounds of orbits.core._fast.ROUND elements a
    thread, and Python looks between them."""
    pytest.importorskip("numba")
    process = subprocess.Popen([sys.executable, "-c", KERNEL_BATCH], stdout=subprocess.PIPE, text=True,
                               env={**os.environ, "ORBITS_JIT": "1", "ORBITS_NUM_THREADS": "1"})
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.5)
    sent = time.perf_counter()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=60)
    assert out.strip() == "interrupted"
    assert time.perf_counter() - sent < 1.0  # measured 0.3-0.4 s; 4.5 s in one round
