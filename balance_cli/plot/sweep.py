"""A sweep's picture: each quantity against the varied parameter, one axes per kind of
quantity; of a grid of two parameters, one heat map with contour lines per quantity. In one
system of units (:data:`~balance_cli.units.UNIT_SYSTEMS`)."""

import math
import re

from ..units import shown_unit, shown_value

__all__ = ["sweep_figure", "axis_values"]

#: kinds of quantity drawn on one axes each, in this order, and their axis titles
_GROUPS = (
    ("force", "Force"),
    ("moment", "Free moment"),
    ("torque", "Torque"),
    ("steadiness", "Steadiness"),
    ("pru", "PRU (N·m/kW)"),
    ("frequency", "Natural frequency"),
    ("mount force", "Force on the frame"),
    ("decoupling", "TRA purity"),
    ("axes angle", "TRA to elastic axis"),
)
_WRITTEN = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*$", re.ASCII)


def axis_values(result, which=0):
    """The parameter axis of a picture: (values, label). In the unit the values are written in
    when they share one ("rod_length (mm)"), degrees for angles, else SI. Of a grid, ``which``
    parameter (0 or 1)."""
    if hasattr(result, "parameters"):
        parameter = result.parameters[which]
        values, values_si = result.values[which], result.values_si[which]
    else:
        parameter, values, values_si = result.parameter, result.values, result.values_si
    if parameter.kind == "angle":
        return [float(v) for v in values], f"{parameter.key} (°)"
    if not parameter.takes_units:
        return [float(v) for v in values], parameter.key
    matches = [m for m in (_WRITTEN.match(v) for v in values) if m]
    written_units = {m.group(2) for m in matches}
    if len(matches) == len(values) and len(written_units) == 1:
        return [float(m.group(1)) for m in matches], f"{parameter.key} ({written_units.pop()})"
    return list(values_si), f"{parameter.key} ({parameter.unit_si})"


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
    steadiness) sharing the parameter axis, one line per quantity. Of a
    :class:`~balance_cli.studies.sweep.SweepGrid`, one heat map per quantity over the two
    parameters (the first along x), with labelled contour lines. A matplotlib Figure (drawn
    into ``fig`` when given, else a new pyplot figure)."""
    if hasattr(result, "parameters"):
        return _grid_figure(result, units, fig)
    groups = [
        (kind, title, [q for q in result.quantities if q.kind == kind]) for kind, title in _GROUPS
    ]
    groups = [g for g in groups if g[2]]
    if fig is None:
        import matplotlib.pyplot as plt  # only when the caller gives no figure of their own

        fig = plt.figure(figsize=(8.0, 1.0 + 2.8 * len(groups)), dpi=100)
    x, xlabel = axis_values(result)
    # values listed out of order are drawn along the axis, not zigzagging back and forth
    order = sorted(range(len(x)), key=x.__getitem__)
    x = [x[i] for i in order]
    points = [result.points[i] for i in order]
    axes = fig.subplots(len(groups), 1, sharex=True, squeeze=False)[:, 0]
    marker = "o" if len(x) <= 30 else None
    for ax, (_kind, title, quantities) in zip(axes, groups, strict=True):
        drawn = []
        for q in quantities:
            y = [shown_value(q, p[q.column], units) for p in points]
            ax.plot(x, y, marker=marker, markersize=4, label=q.name)
            drawn += [v for v in y if math.isfinite(v)]
        unit = shown_unit(quantities[0], units)
        ax.set_ylabel(f"{title} ({unit})" if unit else title)
        ax.grid(True, alpha=0.3)
        ax.set_ylim(*_from_zero(drawn))
        ax.legend(fontsize=8, frameon=False, loc="best")
    axes[-1].set_xlabel(xlabel)
    at = "" if result.speed_rpm is None else f" at {result.speed_rpm:g} rpm"
    fig.suptitle(f"{result.name}{at}: against {result.parameter.key}", fontsize=10)
    fig.tight_layout()
    return fig


def _grid_figure(result, units, fig):
    """One heat map per quantity: colour and contour lines over the two parameters."""
    import numpy as np

    from .figure import grid_size

    quantities = list(result.quantities)
    columns, rows = grid_size(len(quantities))
    if fig is None:
        import matplotlib.pyplot as plt  # only when the caller gives no figure of their own

        fig = plt.figure(figsize=(1.0 + 4.6 * columns, 0.8 + 3.8 * rows), dpi=100)
    x, xlabel = axis_values(result, 0)
    y, ylabel = axis_values(result, 1)
    # values listed out of order are drawn along the axes in order
    across, up = np.argsort(x, kind="stable"), np.argsort(y, kind="stable")
    xs, ys = np.asarray(x, dtype=float)[across], np.asarray(y, dtype=float)[up]
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, q in zip(axes, quantities, strict=False):
        field = np.array(
            [[shown_value(q, v, units) for v in row] for row in result.grid(q.name)], dtype=float
        )[np.ix_(across, up)].T  # rows along y (the second parameter), columns along x
        # the colour scale includes zero, so that a colour reads as a size, not a difference
        low, high = _from_zero(field[np.isfinite(field)].tolist())
        mesh = ax.pcolormesh(xs, ys, field, shading="nearest", cmap="viridis", vmin=low, vmax=high)
        unit = shown_unit(q, units)
        fig.colorbar(mesh, ax=ax, label=f"{q.name} ({unit})" if unit else q.name)
        finite = field[np.isfinite(field)]
        if finite.size and finite.max() > finite.min():
            lines = ax.contour(xs, ys, field, levels=6, colors="white", linewidths=0.7)
            ax.clabel(lines, fontsize=7, fmt=lambda v: f"{v:.4g}")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(q.name, fontsize=9)
    for ax in axes[len(quantities) :]:
        ax.set_visible(False)
    at = "" if result.speed_rpm is None else f" at {result.speed_rpm:g} rpm"
    keys = " and ".join(p.key for p in result.parameters)
    fig.suptitle(f"{result.name}{at}: against {keys}", fontsize=10)
    fig.tight_layout()
    return fig
