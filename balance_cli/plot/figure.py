"""What every picture shares: the engines' results it draws, new figures and grids of small
pictures, colours and short names; and writing a figure to a file in the format its name's
extension names."""

import math
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import matplotlib
import numpy as np

from ..checks import instance, items
from ..errors import PlotError
from ..output import write_bytes
from ..units import UNIT_SYSTEMS, Scale

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = [
    "KINDS",
    "FORMATS",
    "QUANTITIES",
    "CELL_IN",
    "MIN_WIDTH_IN",
    "DPI",
    "new_figure",
    "engine_results",
    "grid_size",
    "grid_figure",
    "cells",
    "short",
    "colours",
    "quantity",
    "PICTURE_UNITS",
    "picture_scale",
    "format_of",
    "save",
]

KINDS = ("locus", "spectrum", "star", "firing", "torque")
#: file formats :func:`save` writes (those of matplotlib's that need neither LaTeX nor a viewer
#: for raw pixels)
FORMATS = ("png", "svg", "svgz", "pdf", "eps", "ps", "jpg", "jpeg", "tif", "tiff", "webp")
#: inches per subplot cell of the star and firing grids, the narrowest figure (its title must
#: fit), and dots per inch of bitmaps
CELL_IN = 4.0
MIN_WIDTH_IN = 8.0
DPI = 100


def new_figure(size):
    import matplotlib.pyplot as plt  # only when the caller gives no figure of their own

    return plt.figure(figsize=size, dpi=DPI)


def engine_results(results, order=None) -> "list[EngineResult]":
    """The results as a list; an ``order`` every one of them was analysed to."""
    from ..analysis.results import EngineResult

    chosen = items(results, EngineResult, "results", PlotError)
    if order is not None:
        lowest = min(r.max_order for r in chosen)
        if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= lowest:
            raise PlotError(
                f"{order!r} is not among the orders analysed (1 to {lowest}: raise "
                "max_order or choose a lower order)",
                "order",
            )
    return chosen


def grid_size(count):
    """Columns and rows of a grid of ``count`` small pictures."""
    columns = min(3, count)
    return columns, math.ceil(count / columns)


def grid_figure(count):
    """A new figure for a grid of ``count`` pictures, wide enough for its two-line title."""
    columns, rows = grid_size(count)
    return new_figure((max(CELL_IN * columns, MIN_WIDTH_IN), CELL_IN * rows))


def cells(fig, rows, columns, count):
    """Axes in the first ``count`` cells of a grid, row by row: the empty cells get none (an
    axes costs more to make than most of what is drawn in it)."""
    grid = fig.add_gridspec(rows, columns)
    return [fig.add_subplot(grid[i // columns, i % columns]) for i in range(count)]


def short(name, length=60):
    """A name cut to ``length`` characters for titles and legends."""
    return name if len(name) <= length else name[: length - 1] + "…"


def colours(count):
    """``count`` distinguishable colours: matplotlib's tab10 or tab20, else a sampled map."""
    if count <= 10:
        return [matplotlib.colormaps["tab10"](i) for i in range(count)]
    if count <= 20:
        # tab20's dark shades first, then its light ones
        table = matplotlib.colormaps["tab20"]
        return [table(2 * i if i < 10 else 2 * (i - 10) + 1) for i in range(count)]
    return [matplotlib.colormaps["turbo"](x) for x in np.linspace(0.05, 0.95, count)]


#: what :func:`locus` and :func:`star` draw: the shaking force or the free moment
QUANTITIES = ("force", "moment")


def quantity(of):
    if of not in QUANTITIES:
        raise PlotError(f"must be one of {', '.join(QUANTITIES)}, got {of!r}", "of")
    return of


#: what the force pictures (locus, spectrum) are drawn in: per cylinder (× m_rec·r·ω²·n, with
#: moments in N·m), or one system of units for forces and moments alike
PICTURE_UNITS = ("per-cylinder",) + tuple(UNIT_SYSTEMS)


def picture_scale(units) -> Scale:
    """The :class:`~balance_cli.units.Scale` of a picture's ``units``, one of
    :data:`PICTURE_UNITS`: "per-cylinder", or a system of units (absolute forces, N too)."""
    if units not in PICTURE_UNITS:
        raise PlotError(f"must be one of {', '.join(PICTURE_UNITS)}, got {units!r}", "units")
    return Scale.of(False, None if units == "per-cylinder" else units)


def format_of(path: "str | os.PathLike[str]") -> str:
    """The file format :func:`save` writes to ``path``: its extension, one of :data:`FORMATS`."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in FORMATS:
        shown = f"'.{suffix}'" if suffix else "no extension"
        raise PlotError(
            f"{str(path)!r} has {shown}; end the file name in one of "
            f"{', '.join('.' + f for f in FORMATS)}",
            "path",
        )
    return suffix


def save(fig: "Figure", path: "str | os.PathLike[str]") -> None:
    """Write ``fig`` to ``path`` atomically, in the format of its extension (see
    :func:`format_of`), then close it if pyplot manages it."""
    fmt = format_of(path)
    from matplotlib.figure import Figure

    instance(fig, Figure, "fig", PlotError)
    try:
        with matplotlib.rc_context({"svg.fonttype": "none"}):
            write_bytes(path, lambda handle: fig.savefig(handle, format=fmt, dpi=DPI))
    finally:
        pyplot = sys.modules.get("matplotlib.pyplot")
        if pyplot is not None:
            pyplot.close(fig)
