"""Histograms of a tolerance band's scatter (:func:`balance_cli.tolerance`): how often each
size of free force and moment comes out of a production run, with the closed form's mean and
95th percentile marked."""

from typing import TYPE_CHECKING

import numpy as np

from ..checks import instance
from ..errors import PlotError
from ..units import UNIT_SYSTEMS
from .figure import new_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["tolerance_histograms"]

_BINS = 60


def _panel(ax, values, title, unit, closed=None):
    """One histogram, the runs' mean and 95th percentile solid, ``closed`` (the closed form's
    mean and 95th percentile, or None) dashed."""
    ax.hist(values, bins=_BINS, color="0.7", edgecolor="0.5", linewidth=0.3)
    mean, p95 = float(np.mean(values)), float(np.quantile(values, 0.95))
    ax.axvline(mean, color="C0", linewidth=1.2, label=f"mean {mean:.4g}")
    ax.axvline(p95, color="C3", linewidth=1.2, label=f"95th {p95:.4g}")
    if closed is not None:
        ax.axvline(closed[0], color="C0", linestyle="--", linewidth=1.0, label="closed form")
        ax.axvline(closed[1], color="C3", linestyle="--", linewidth=1.0)
    ax.set(title=title, xlabel=unit, ylabel="runs")
    ax.legend(fontsize=7)


def tolerance_histograms(result, order: int = 1, units: str = "N", fig=None) -> "Figure":
    """Four histograms of ``result`` (a ToleranceResult): the order's vertical free force and
    vertical free moment (pitching), and the largest resultant force and moment over a
    revolution, in ``units`` (N, kN, MN, kgf or lbf and their moments); the Monte Carlo's mean
    and 95th percentile solid, the closed form's dashed.

    Raises
    ------
    PlotError
        not a tolerance result, an order it has not, a unit that is not a system
    """
    from ..workshop import ToleranceResult

    instance(result, ToleranceResult, "result", PlotError)
    if (
        isinstance(order, bool)
        or not isinstance(order, (int, np.integer))
        or not 1 <= order <= len(result.orders)
    ):
        raise PlotError(f"must be an order from 1 to {len(result.orders)}, got {order!r}", "order")
    if units not in UNIT_SYSTEMS:
        raise PlotError(f"must be one of {', '.join(UNIT_SYSTEMS)}, got {units!r}", "units")
    per_force, moment_unit, per_moment = UNIT_SYSTEMS[units]
    fig = fig if fig is not None else new_figure((10.0, 7.0))
    axes = fig.subplots(2, 2)
    spread = result.order(order)
    for ax, key, linear, scale, unit, title in (
        (
            axes[0, 0],
            "force_vertical",
            spread.linear_force["vertical"],
            per_force,
            units,
            f"Order {order}: vertical force",
        ),
        (
            axes[0, 1],
            "moment_vertical",
            spread.linear_moment["vertical"],
            per_moment,
            moment_unit,
            f"Order {order}: pitching moment",
        ),
        (axes[1, 0], "largest_force", None, per_force, units, "Largest force, all orders"),
        (axes[1, 1], "largest_moment", None, per_moment, moment_unit, "Largest moment, all orders"),
    ):
        values = result.values[key]
        values = values[:, order - 1] if values.ndim == 2 else values
        closed = None
        if linear is not None and linear.rms > 0:
            closed = (linear.mean / scale, linear.p95 / scale)
        _panel(ax, values / scale, title, unit, closed)
    fig.suptitle(f"{result.engine.name}: {result.runs:,} runs of its tolerance band", fontsize=10)
    fig.tight_layout()
    return fig
