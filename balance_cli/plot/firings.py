"""The firing picture: each engine's firing angles on a dial of one working cycle, with the
intervals between them."""

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from .figure import CELL_IN, cells, engine_results, grid_figure, grid_size, short

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = ["firing"]


def _on_dial(angle, radius, cycle):
    """(x, y) of ``angle`` (degrees of a ``cycle``, clockwise from the top) at ``radius``."""
    return (
        radius * math.sin(2 * math.pi * angle / cycle),
        radius * math.cos(2 * math.pi * angle / cycle),
    )


def firing(results: "Iterable[EngineResult]", fig: "Figure | None" = None) -> "Figure":
    """Firing angles on a dial of one working cycle (720° or 360°, clockwise from the top),
    cylinder numbers outside, intervals in red (one, in the centre, when they are all equal)."""
    chosen = engine_results(results)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = grid_figure(len(chosen))
    axes = cells(fig, rows, columns, len(chosen))
    for ax in axes:
        ax.axis("off")
    ring = np.linspace(0, 2 * np.pi, 181)
    for ax, r in zip(axes, chosen, strict=True):
        cycle = r.engine.cycle_deg
        fire = r.firing
        ax.plot(np.sin(ring), np.cos(ring), color="0.7", linewidth=0.6)
        for tick in np.arange(0, cycle, cycle / 4):
            ax.text(
                *_on_dial(tick, 1.32, cycle),
                f"{tick:g}°",
                ha="center",
                va="center",
                fontsize=6,
                color="0.5",
            )
        # every spoke in one line broken at NaN: one artist, not one per cylinder
        xs, ys = [], []
        for angle, number in zip(fire.angles_deg, fire.order, strict=True):
            x, y = _on_dial(angle, 1.0, cycle)
            xs += [0.0, x, math.nan]
            ys += [0.0, y, math.nan]
            ax.text(
                *_on_dial(angle, 1.13, cycle), str(number), ha="center", va="center", fontsize=8
            )
        ax.plot(xs, ys, color="C0", linewidth=1.2)
        if fire.uniform:
            # one figure says it: a label in every gap of an even engine only repeats it
            ax.text(
                0.0,
                0.0,
                f"every\n{fire.intervals_deg[0]:.4g}°",
                ha="center",
                va="center",
                fontsize=6,
                color="C3",
            )
        else:
            for angle, gap in zip(fire.angles_deg, fire.intervals_deg, strict=True):
                ax.text(
                    *_on_dial(angle + gap / 2, 0.65, cycle),
                    f"{gap:.4g}°",
                    ha="center",
                    va="center",
                    fontsize=6,
                    color="C3",
                )
        ax.set_xlim(-1.45, 1.45)
        ax.set_ylim(-1.45, 1.45)
        ax.set_aspect("equal")
        uniform = "uniform" if fire.uniform else f"±{fire.max_deviation_deg:.2f}° from uniform"
        ax.set_title(
            f"{short(r.engine.name)}\n{r.engine.cycle}-stroke, {uniform}", fontsize=9, y=1.0
        )
    fig.suptitle(
        "Firing angles over one working cycle (crank degrees from the first firing)", fontsize=10
    )
    fig.subplots_adjust(
        left=0.02, right=0.98, bottom=0.02, top=1 - 0.8 / (CELL_IN * rows), wspace=0.1, hspace=0.25
    )
    return fig
