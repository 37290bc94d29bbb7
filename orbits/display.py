"""Rich display for notebooks: HTML tables of Quantities (`_repr_html_`) and short terminal reprs."""

import html
from collections.abc import Mapping
from typing import Any

import numpy as np


def _value(q):
    value = np.asarray(q.value)
    if value.ndim == 0:
        return f"{float(value):.12g}"
    return html.escape(np.array2string(value, precision=6, threshold=12))


def quantities_html(title: str, quantities: Mapping[str, Any]) -> str:
    """An HTML table: one row per quantity with its value and unit."""
    rows = "".join(
        f"<tr><td style='text-align:left'>{html.escape(name)}</td><td style='text-align:right'>{_value(q)}</td>"
        f"<td style='text-align:left'>{html.escape(q.unit.to_string())}</td></tr>"
        for name, q in quantities.items()
    )
    return (f"<table><caption style='text-align:left'><b>{html.escape(title)}</b></caption>"
            f"<tr><th>quantity</th><th>value</th><th>unit</th></tr>{rows}</table>")


def validation_html(report: Any) -> str:
    """An HTML table per scene of a ValidationReport: check, analytic value, each backend's error, pass."""
    parts = []
    for scene in report.scenes:
        names = list(scene.versions)
        head = "".join(f"<th>{html.escape(n)} error</th>" for n in names)
        rows = ""
        for check in scene.checks:
            errors = "".join(f"<td>{check.errors[n]:.3g}</td>" for n in names)
            analytic = "-" if check.analytic is None else f"{check.analytic:.6g}"
            verdict = "yes" if check.passed else "<b style='color:red'>NO</b>"
            rows += (f"<tr><td style='text-align:left'>{html.escape(check.quantity)}</td><td>{analytic}</td>"
                     f"{errors}<td>{check.tolerance:.0e}</td><td>{verdict}</td></tr>")
        times = ", ".join(f"{k} {v * 1e3:.1f} ms" for k, v in scene.wall_times.items())
        parts.append(f"<table><caption style='text-align:left'><b>{html.escape(scene.name)}</b>: "
                     f"{html.escape(scene.description)}<br>wall time: {times}</caption>"
                     f"<tr><th>check</th><th>analytic</th>{head}<th>tolerance</th><th>pass</th></tr>{rows}</table>")
    verdict = "all checks passed" if report.passed else "some checks FAILED"
    return "".join(parts) + f"<p><b>{verdict}</b> ({len(report.scenes)} scenes)</p>"
