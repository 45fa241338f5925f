"""A sweep as a table or CSV, rendered from the records of a
:class:`~balance_cli.studies.sweep.SweepResult` (one parameter) or
:class:`~balance_cli.studies.sweep.SweepGrid` (two): one row per point (its picture is
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


def _parameters(result):
    """The swept parameters and the record keys of their values, of a sweep or a grid."""
    if hasattr(result, "parameters"):
        return list(result.parameters), ["value_1", "value_2"]
    return [result.parameter], ["value"]


def sweep_tables(result, fmt, units="N"):
    """The sweep as text ("table") or Markdown: a title, one row per point (of a grid: per
    pair of values), what each column is."""
    heading = "#### " if fmt == "markdown" else ""
    safe = markdown_text if fmt == "markdown" else plain_text
    parameters, keys = _parameters(result)
    shown = ", ".join(q.name for q in result.quantities)
    at = "" if result.speed_rpm is None else f" at {result.speed_rpm:g} rpm"
    against = " and ".join(safe(p.key) for p in parameters)
    size = "×".join(str(len(v)) for v in result.values) + " = " if len(parameters) > 1 else ""
    title = (
        f"{heading}{safe(result.name)}{at}: {shown} against {against} "
        f"({safe(result.config)}, {size}{len(result.points)} "
        f"point{'s' if len(result.points) != 1 else ''}, "
        f"{result.samples} samples)"
    )
    headers = [_parameter_heading(p) for p in parameters] + [
        f"{q.name} ({shown_unit(q, units)})" if shown_unit(q, units) else q.name
        for q in result.quantities
    ]
    rows = [
        [_value_text(p[k]) for k in keys]
        + [figure(shown_value(q, p[q.column], units)) for q in result.quantities]
        for p in result.points
    ]
    notes = [f"- {q.name}: {q.meaning}" for q in result.quantities]
    notes += [f"- {p.key}: {p.meaning}" for p in parameters if p.derived is not None]
    if result.inertia_kgm2 is not None:
        notes.append(
            f"- with a flywheel of {result.inertia_kgm2:g} kg·m² driving a {result.load} load"
        )
    if any(p.kind == "fraction" for p in parameters):
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
    every quantity in SI at full precision; the unit ends each quantity's column name. Of a
    grid, the same four columns for each parameter, numbered: ``parameter_1``, ``value_1``,
    ``value_1_SI``, ``unit_1_SI``, ``parameter_2``, ..."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    parameters, keys = _parameters(result)
    columns = [q.column for q in result.quantities]
    if len(parameters) == 1:
        head = ["parameter", "value", "value_SI", "unit_SI"]
    else:
        head = [
            name
            for n in range(1, len(parameters) + 1)
            for name in (f"parameter_{n}", f"value_{n}", f"value_{n}_SI", f"unit_{n}_SI")
        ]
    writer.writerow(head + columns)
    for point in result.points:
        values = []
        for parameter, key in zip(parameters, keys, strict=True):
            values += [
                parameter.key,
                _csv_value(point[key]),
                _csv_value(point[f"{key}_SI"]),
                parameter.unit_si,
            ]
        writer.writerow(values + [_csv_value(point[c]) for c in columns])
    return buffer.getvalue()
