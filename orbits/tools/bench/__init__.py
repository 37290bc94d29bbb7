"""Benchmarks behind ``orbits bench``: orbits against its peers, every figure measured in the same run.

One module per benchmark, each with its row class, its run function and its table:

- kepler: Kepler's equation (bench_kepler, format_rows).
- propagate: two-body propagation (bench_propagate, format_propagate).
- lambert: Lambert solvers (bench_lambert, format_lambert).
- periodic: periodic orbits of the restricted problem, one and a family (bench_periodic, format_periodic).
- ephemeris: states of a body from DE421 (bench_ephemeris, format_ephemeris).
- api: the unit-aware API against the float64 core (bench_api, format_api).
- cli: cold start of the command line (bench_cli, format_cli).
- validate: where the time of ``orbits validate`` goes (bench_validate, format_validate).
- suite: all of them in one run (bench_all, format_report, report_to_json).

They share two modules and import nothing from one another: table (plain-text tables of at most 80 columns,
significant digits, footnotes, rows_to_json) and harness (the peer adapter, best-of timing, thread settings,
plain NumPy baselines). A new benchmark is a new module here that imports those two, and a line in
suite.BENCHMARKS.

Threads: numpy's element-wise functions run on one thread; heyoka's cfunc splits large batches over its own
thread pool; orbits' kernels split over orbits.core._fast.num_threads(). Rows say how many threads they used.
Peers whose package is absent are skipped with a note; every peer is imported lazily.
"""
