"""The locus picture: the resultant shaking force per cylinder, or the free moment, over one
revolution (Tanaka's Fig. 9), every engine on one set of equal-scaled axes."""

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, cast

import numpy as np

from .figure import colours, engine_results, new_figure, quantity, short

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = ["locus", "locus_points"]


def locus_points(result, order=None, of="force", counterweight=True):
    """What :func:`locus` draws of one engine, as x = across, y = along the reference axis:
    ``of="force"`` the resultant force per cylinder (× m_rec·r·ω² per cylinder, Tanaka's
    Fig. 9), ``of="moment"`` the free moment about the engine's mid-length (z̄), N·m, over a
    revolution; all orders, or ``order`` only. With ``counterweight`` (the default) an ideal
    crankshaft counterweight has taken the forward first order away, in two planes for the
    moment (none on a rotary, whose crank does not turn). A locus below the noise floor all
    round is exact zeros."""
    quantity(of)
    forward, backward = result.counterweight_cancels if counterweight else (False, False)
    engine = result.engine
    if of == "force":
        values = result.shaking.locus(order, forward, skip_backward_first=backward)
        floor, unit = engine.noise_floor_n, result.per_cylinder_unit_n
    else:
        values = result.shaking.moment_locus(order, forward, skip_backward_first=backward)
        floor, unit = engine.noise_floor_nm, 1.0
    if np.abs(values).max() < floor:
        values = np.zeros_like(values)
    values = values / unit
    return values.imag, values.real


def _legend_rows(names):
    """Columns and rows of a legend of ``names`` below a picture 8 in wide."""
    columns = 1 if len(names) <= 3 or max(len(n) for n in names) > 48 else 2
    return columns, math.ceil(len(names) / columns)


def locus(
    results: "Iterable[EngineResult]",
    order: int | None = None,
    ax: "Axes | None" = None,
    of: str = "force",
) -> "Figure":
    """Locus over one revolution of the resultant shaking force per cylinder (``of="force"``,
    Tanaka's Fig. 9) or of the free moment in N·m (``of="moment"``), every engine on one set
    of equal-scaled axes; ``order`` draws one order only. See :func:`locus_points`.

    In a figure of its own the legend goes below the axes, in as many rows as the engines
    need; drawn into ``ax``, the legend is the axes'."""
    quantity(of)
    chosen = engine_results(results, order)
    points = [locus_points(r, order, of) for r in chosen]
    # an engine with nothing left is a dot at the origin, hidden under the others
    names = [
        short(r.engine.name) + ("" if x.any() or y.any() else f" (no free {of})")
        for r, (x, y) in zip(chosen, points, strict=True)
    ]
    columns, rows = _legend_rows(names)
    own = ax is None
    legend_in = 0.25 + 0.19 * rows  # a legend row of 8-point text, and the frame's padding
    if ax is None:
        height = 8.0 + legend_in
        # inches: title above, tick and axis labels then the legend below
        ax = new_figure((8, height)).add_axes(
            (0.11, (legend_in + 0.75) / height, 0.84, 1 - (legend_in + 0.75 + 0.85) / height)
        )
    fig = cast("Figure", ax.figure)
    for (x, y), name, colour in zip(points, names, colours(len(chosen)), strict=True):
        ax.plot(np.append(x, x[0]), np.append(y, y[0]), label=name, linewidth=1.6, color=colour)
    ax.axhline(0, color="0.6", linewidth=0.6)
    ax.axvline(0, color="0.6", linewidth=0.6)
    ax.set_aspect("equal", adjustable="datalim")
    what = f"order {order}" if order else "all orders"
    rotary = "none on a rotary"
    if of == "force":
        title = f"Locus of the resultant shaking force per cylinder ({what})"
        counterweight = f"after an ideal crankshaft counterweight ({rotary})"
        unit = "× m_rec·r·ω² per cylinder"
        ax.set_xlabel(f"across the reference axis ({unit})")
        ax.set_ylabel(f"along the reference axis ({unit})")
    else:
        title = f"Locus of the free moment about the engine's mid-length, N·m ({what})"
        counterweight = f"after an ideal two-plane crankshaft counterweight ({rotary})"
        ax.set_xlabel("moment of the forces across the reference axis (yawing), N·m")
        ax.set_ylabel("moment of the forces along the reference axis (pitching), N·m")
    # the counterweight turns at crank speed: it changes the first order only
    ax.set_title(title + (f",\n{counterweight}" if order in (None, 1) else ""))
    if own:
        fig.legend(
            *ax.get_legend_handles_labels(),
            loc="upper center",
            ncol=columns,
            fontsize=8,
            frameon=False,
            bbox_to_anchor=(0.5, legend_in / (fig.bbox.height / fig.dpi)),
        )
    else:
        ax.legend(fontsize=8, loc="upper right")
    ax.grid(True, linewidth=0.3)
    return fig
