"""A sweep as a table or CSV, rendered from :meth:`SweepResult.records` (its picture is
:func:`balance_cli.plot.sweep_figure`).

JSON and CSV stay SI; the table and the picture show forces, moments and torques in one
system of units (``--units``, :data:`~balance_cli.units.UNIT_SYSTEMS`).
"""

import csv
import io

from ..units import shown_unit, shown_value
from .display import figure, markdown_text, plain_text
from .table import render

__all__ = ["sweep_tables", "sweep_csv"]


def _value_text(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _parameter_heading(parameter):
    unit = {"angle": " (°)"}.get(parameter.kind, "")
    return parameter.key + unit


def sweep_tables(result, fmt, units="N"):
    """The sweep as text ("table") or Markdown: a title, one row per point, what each column is."""
    heading = "#### " if fmt == "markdown" else ""
    safe = markdown_text if fmt == "markdown" else plain_text
    shown = ", ".join(q.name for q in result.quantities)
    at = "" if result.speed_rpm is None else f" at {result.speed_rpm:g} rpm"
    title = (
        f"{heading}{safe(result.name)}{at}: {shown} against {safe(result.parameter.key)} "
        f"({safe(result.config)}, {len(result.points)} "
        f"point{'s' if len(result.points) != 1 else ''}, "
        f"{result.samples} samples)"
    )
    headers = [_parameter_heading(result.parameter)] + [
        f"{q.name} ({shown_unit(q, units)})" if shown_unit(q, units) else q.name
        for q in result.quantities
    ]
    rows = [
        [_value_text(p["value"])]
        + [figure(shown_value(q, p[q.column], units)) for q in result.quantities]
        for p in result.points
    ]
    notes = [f"- {q.name}: {q.meaning}" for q in result.quantities]
    if result.inertia_kgm2 is not None:
        notes.append(
            f"- with a flywheel of {result.inertia_kgm2:g} kg·m² driving a {result.load} load"
        )
    if result.parameter.kind == "fraction":
        notes.append(
            "- each point after classic per-throw counterweights of that balance factor "
            "(rotating masses plus the factor times the reciprocating ones)"
        )
    return "\n".join([title, "", render(headers, rows, fmt), ""] + notes) + "\n"


def _csv_value(value):
    # float(): a numpy scalar's repr names its type (np.float64(…)) since numpy 2
    return repr(float(value)) if isinstance(value, float) else value


def sweep_csv(result):
    """One row per point: the parameter, its value as written and in SI (with the SI unit), and
    every quantity in SI at full precision; the unit ends each quantity's column name."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    columns = [q.column for q in result.quantities]
    writer.writerow(["parameter", "value", "value_SI", "unit_SI"] + columns)
    for point in result.points:
        writer.writerow(
            [
                result.parameter.key,
                _csv_value(point["value"]),
                _csv_value(point["value_SI"]),
                result.parameter.unit_si,
            ]
            + [_csv_value(point[c]) for c in columns]
        )
    return buffer.getvalue()
