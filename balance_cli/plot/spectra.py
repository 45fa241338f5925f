"""The spectrum picture: the forward and backward amplitude of every order, forces and free
moments, as grouped bars on a log axis."""

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from ..tolerances import SPECTRUM_FLOOR
from .figure import PICTURE_UNITS, colours, engine_results, new_figure, picture_scale, short

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = ["SPECTRUM_UNITS", "spectrum", "spectrum_data"]

SPECTRUM_UNITS = PICTURE_UNITS


def spectrum_data(results, units="per-cylinder"):
    """What :func:`spectrum` draws: orders, per engine the forward and backward magnitudes of
    forces and moments in display units, the floors below which nothing is drawn, and labels.

    ``units``: "per-cylinder" (forces × m_rec·r·ω²·n, moments N·m), or a system of units
    (:data:`~balance_cli.units.UNIT_SYSTEMS`: "N" for N and N·m, "kN", "MN", "kgf", "lbf").
    """
    scale = picture_scale(units)
    chosen = engine_results(results)
    engines = []
    for r in chosen:
        unit = r.per_cylinder_unit_n
        engines.append(
            {
                "name": short(r.engine.name),
                "force": np.array(
                    [
                        [
                            scale.force(abs(o.force_forward), unit),
                            scale.force(abs(o.force_backward), unit),
                        ]
                        for o in r.shaking.orders
                    ]
                ),
                "moment": np.array(
                    [
                        [scale.moment(abs(o.moment_forward)), scale.moment(abs(o.moment_backward))]
                        for o in r.shaking.orders
                    ]
                ),
            }
        )
    # the floors: SPECTRUM_FLOOR of the largest engine's m_rec·r·ω²·n (times one metre)
    largest = max(r.per_cylinder_unit_n for r in chosen)
    return {
        "orders": np.arange(1, max(r.max_order for r in chosen) + 1),
        "engines": engines,
        "force_floor": SPECTRUM_FLOOR * scale.force(largest, largest),
        "moment_floor": SPECTRUM_FLOOR * scale.moment(largest),
        "force_label": f"force ({scale.force_unit_text})",
        "moment_label": f"free moment ({scale.moment_label})",
        "has_moments": any(
            (e["moment"] > SPECTRUM_FLOOR * scale.moment(largest)).any() for e in engines
        ),
    }


def spectrum(
    results: "Iterable[EngineResult]", units: str = "per-cylinder", fig: "Figure | None" = None
) -> "Figure":
    """Forward (solid) and backward (hatched) amplitude of every order: forces, and free
    moments when any engine has one above the floor; grouped bars on a log axis."""
    from matplotlib.patches import Patch
    from matplotlib.ticker import FuncFormatter

    data = spectrum_data(results, units)
    panels = 2 if data["has_moments"] else 1
    # the legend below the panels, in columns across the width (beside them it took a
    # quarter of the width whatever the names' lengths)
    names = [e["name"] for e in data["engines"]]
    columns = 3 if max(len(n) for n in names) <= 52 else 2
    legend_in = 0.15 + 0.18 * math.ceil((len(names) + 2) / columns)
    if fig is None:
        fig = new_figure((12, (8 if panels == 2 else 4.5) + legend_in))
    axes = fig.subplots(panels, 1, sharex=True, squeeze=False)[:, 0]
    orders = data["orders"]
    n = len(data["engines"])
    width = 0.8 / (2 * n)
    handles = []
    quantities = [("force", data["force_floor"], data["force_label"])]
    if panels == 2:
        quantities.append(("moment", data["moment_floor"], data["moment_label"]))
    for i, (engine, colour) in enumerate(zip(data["engines"], colours(n), strict=True)):
        offset = -0.4 + 2 * i * width
        for ax, (quantity, floor, _) in zip(axes, quantities, strict=True):
            values = engine[quantity]
            for part, shift, style in ((0, 0.0, {}), (1, width, {"alpha": 0.45, "hatch": "//"})):
                heights = values[: len(orders), part]
                shown = heights > floor
                _bars(
                    ax,
                    orders[: len(heights)][shown] + offset + shift,
                    heights[shown],
                    floor,
                    width,
                    facecolor=colour,
                    **style,
                )
        handles.append(Patch(color=colour, label=engine["name"]))
    handles += [
        Patch(facecolor="white", edgecolor="black", label="forward (turns with the crank)"),
        Patch(facecolor="white", edgecolor="black", hatch="//", label="backward (against it)"),
    ]
    for ax, (quantity, floor, label) in zip(axes, quantities, strict=True):
        ax.set_yscale("log")
        top = max((e[quantity].max() for e in data["engines"]), default=floor)
        ax.set_ylim(floor, max(top, floor) * 3)
        # plain labels ("1e-06"): mathematical text costs more than drawing all the bars
        ax.yaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
        ax.set_ylabel(label)
        ax.set_xlim(0.5, orders[-1] + 0.5)
        ax.set_xticks(orders)
        ax.grid(True, axis="y", linewidth=0.3)
    axes[-1].set_xlabel("order")
    title = (
        f"Forward and backward parts by order (parts below {SPECTRUM_FLOOR:g} of "
        "m_rec·r·ω²·n not drawn)"
    )
    if panels == 1:
        title += "\nno engine has a free moment above that floor"
    axes[0].set_title(title, y=1.0)
    height = fig.get_size_inches()[1]
    fig.legend(
        handles=handles,
        loc="upper center",
        ncol=columns,
        fontsize=8,
        frameon=False,
        bbox_to_anchor=(0.5, legend_in / height),
    )
    # inches: the title above; tick labels and "order" below, then the legend
    fig.subplots_adjust(
        left=0.07,
        right=0.98,
        top=1 - (0.56 if panels == 2 else 0.72) / height,
        bottom=(legend_in + 0.63) / height,
        hspace=0.08,
    )
    return fig


def _bars(ax, left, top, bottom, width, **style):
    """Bars from ``bottom`` up to each ``top``, starting at each ``left``, as one collection
    (one artist for all: hundreds of separate rectangles are slow to draw)."""
    from matplotlib.collections import PolyCollection

    if len(left) == 0:
        return
    corners = [
        [(x, bottom), (x + width, bottom), (x + width, y), (x, y)]
        for x, y in zip(left, top, strict=True)
    ]
    ax.add_collection(PolyCollection(corners, linewidth=0, **style), autolim=False)
