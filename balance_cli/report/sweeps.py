"""A sweep as a table, CSV or picture, rendered from :meth:`SweepResult.records`.

JSON and CSV stay SI; the table and the picture show forces, moments and torques in one
system of units (``--units``, :data:`~balance_cli.units.UNIT_SYSTEMS`).
"""

import csv
import io
import math
import re

from ..units import Scale
from .display import figure, markdown_text, plain_text
from .tables import render

__all__ = ["sweep_tables", "sweep_csv", "sweep_figure", "axis_values"]

#: kinds of quantity drawn on one axes each, in this order, and their axis titles
_GROUPS = (("force", "Force"), ("moment", "Free moment"), ("torque", "Torque"),
           ("steadiness", "Steadiness"), ("pru", "PRU (N·m/kW)"))


def _label(quantity, units):
    """The unit a quantity is shown in, "" for a pure number."""
    scale = Scale.of(True, units)
    return {"N": scale.force_label, "Nm": scale.moment_label}.get(quantity.unit, "")


def _shown(quantity, value_si, units):
    scale = Scale.of(True, units)
    if quantity.unit == "N":
        return scale.force(value_si, 1.0)
    return scale.moment(value_si) if quantity.unit == "Nm" else value_si


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
    title = (f"{heading}{safe(result.name)}{at}: {shown} against {safe(result.parameter.key)} "
             f"({safe(result.config)}, {len(result.points)} point{'s' if len(result.points) != 1 else ''}, "
             f"{result.samples} samples)")
    headers = [_parameter_heading(result.parameter)] + [
        f"{q.name} ({_label(q, units)})" if _label(q, units) else q.name
        for q in result.quantities]
    rows = [[_value_text(p["value"])] + [figure(_shown(q, p[q.column], units))
                                         for q in result.quantities]
            for p in result.points]
    notes = [f"- {q.name}: {q.meaning}" for q in result.quantities]
    if result.inertia_kgm2 is not None:
        notes.append(f"- with a flywheel of {result.inertia_kgm2:g} kg·m² driving a "
                     f"{result.load} load")
    if result.parameter.kind == "fraction":
        notes.append("- each point after classic per-throw counterweights of that balance factor "
                     "(rotating masses plus the factor times the reciprocating ones)")
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
        writer.writerow([result.parameter.key, _csv_value(point["value"]),
                         _csv_value(point["value_SI"]), result.parameter.unit_si]
                        + [_csv_value(point[c]) for c in columns])
    return buffer.getvalue()


_WRITTEN = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*$", re.ASCII)


def axis_values(result):
    """The parameter axis of a picture: (values, label). In the unit the values are written in
    when they share one ("rod_length (mm)"), degrees for angles, else SI."""
    parameter = result.parameter
    if parameter.kind == "angle":
        return [float(v) for v in result.values], f"{parameter.key} (°)"
    if not parameter.takes_units:
        return [float(v) for v in result.values], parameter.key
    matches = [_WRITTEN.match(v) for v in result.values]
    written_units = {m.group(2) for m in matches if m}
    if all(matches) and len(written_units) == 1:
        return [float(m.group(1)) for m in matches], f"{parameter.key} ({written_units.pop()})"
    return list(result.values_si), f"{parameter.key} ({parameter.unit_si})"


def _from_zero(values):
    """Limits that include zero, so that a curve's size reads against nothing: a flat line
    of 1.61 must not look like a plunge."""
    low, high = min([0.0, *values]), max([0.0, *values])
    if high == low:
        return 0.0, 1.0
    pad = 0.05 * (high - low)
    return (low - pad if low < 0 else 0.0), (high + pad if high > 0 else 0.0)


def sweep_figure(result, units="N", fig=None):
    """Each quantity against the parameter: one axes per kind (forces, free moments, torques,
    steadiness) sharing the parameter axis, one line per quantity. A matplotlib Figure (drawn
    into ``fig`` when given, else a new pyplot figure)."""
    groups = [(kind, title, [q for q in result.quantities if q.kind == kind])
              for kind, title in _GROUPS]
    groups = [g for g in groups if g[2]]
    if fig is None:
        import matplotlib.pyplot as plt   # only when the caller gives no figure of their own

        fig = plt.figure(figsize=(8.0, 1.0 + 2.8 * len(groups)), dpi=100)
    x, xlabel = axis_values(result)
    # values listed out of order are drawn along the axis, not zigzagging back and forth
    order = sorted(range(len(x)), key=x.__getitem__)
    x = [x[i] for i in order]
    points = [result.points[i] for i in order]
    axes = fig.subplots(len(groups), 1, sharex=True, squeeze=False)[:, 0]
    marker = "o" if len(x) <= 30 else None
    for ax, (kind, title, quantities) in zip(axes, groups):
        drawn = []
        for q in quantities:
            y = [_shown(q, p[q.column], units) for p in points]
            ax.plot(x, y, marker=marker, markersize=4, label=q.name)
            drawn += [v for v in y if math.isfinite(v)]
        unit = _label(quantities[0], units)
        ax.set_ylabel(f"{title} ({unit})" if unit else title)
        ax.grid(True, alpha=0.3)
        ax.set_ylim(*_from_zero(drawn))
        ax.legend(fontsize=8, frameon=False, loc="best")
    axes[-1].set_xlabel(xlabel)
    at = "" if result.speed_rpm is None else f" at {result.speed_rpm:g} rpm"
    fig.suptitle(f"{result.name}{at}: against {result.parameter.key}", fontsize=10)
    fig.tight_layout()
    return fig
