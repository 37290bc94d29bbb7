"""orbits.tools.bench.lambert and `orbits bench lambert` on tiny sizes (orbits' own rows; peers as installed)."""

import importlib.util
import json

from typer.testing import CliRunner

from orbits.tools.bench.lambert import bench_lambert, format_lambert, hard_cases
from orbits_cli.main import app


def test_rows_and_table_fit_80_columns():
    rows = bench_lambert(n=2000, n_ref=10, repeats=1, solvers=["orbits", "orbits (NumPy)", "pykep lambert_problem"])
    by_name = {r.method: r for r in rows}
    for name in ("orbits", "orbits (NumPy)"):
        row = by_name[name]
        assert row.status == "ok" and row.hard_failed == 0 and row.hard_total == len(hard_cases())
        assert row.worst_error < 1e-13 and row.throughput_per_s > 0
    text = format_lambert(rows)
    assert max(map(len, text.splitlines())) <= 80
    assert "hard failed" in text and "0/" in text


PEERS = {"pykep lambert_problem": "pykep", "hapsira izzo": "hapsira", "lamberthub izzo2015": "lamberthub"}


def test_peers_run_when_installed_and_say_so_when_not():
    """Each peer row is measured when its package imports and reads "not installed" when it does not."""
    rows = bench_lambert(n=100, n_ref=2, repeats=1, solvers=list(PEERS))
    assert [r.method for r in rows] == list(PEERS)
    for row in rows:
        if importlib.util.find_spec(PEERS[row.method]) is None:
            assert row.status == "not installed" and "not installed" in format_lambert(rows)
        else:
            assert row.status == "ok" and row.throughput_per_s > 0 and row.median_error < 1e-13, row


def test_cli_bench_lambert_json():
    result = CliRunner().invoke(app, ["bench", "lambert", "--transfers", "300", "--reference", "3", "--repeats",
                                      "1", "--format", "json"])
    assert result.exit_code == 0, result.output
    rows = json.loads(result.output)
    assert rows[0]["method"] == "orbits" and rows[0]["hard_failed"] == 0
