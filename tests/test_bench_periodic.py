"""`orbits bench periodic`: the rows it measures, and a table of 80 columns."""

import json

from orbits.tools.bench.periodic import bench_periodic, format_periodic
from orbits.tools.bench.table import rows_to_json


def test_a_small_run_counts_the_integrations_and_checks_the_closure():
    """Both integrators correct the same orbit in about the same work (the two agree to rounding, so their Newton
    paths may part by an integration or two); every orbit closes to 1e-11 of its size."""
    rows = bench_periodic(members=4, repeats=1, numpy=True)
    assert [r.status for r in rows] == ["ok"] * 4
    one = [r for r in rows if r.case.startswith("one orbit")]
    assert abs(one[0].integrations - one[1].integrations) <= 3 and one[0].iterations > 0
    assert all(r.closure < 1e-11 and r.steps > r.integrations for r in rows)
    lines = format_periodic(rows).splitlines()
    assert max(map(len, lines)) <= 80 and lines[-1].startswith("Machine: ")
    json.dumps(rows_to_json(rows), allow_nan=False)
