"""Pictures of analysed engines (matplotlib).

Each function takes results of :func:`balance_cli.analyse`, draws, and returns the Figure; none
recomputes an analysis. Give ``ax`` (locus) or ``fig`` (the others) to draw into your own;
otherwise a new pyplot figure is made, so figures show inline in a notebook. Importing this
module never chooses a backend: that is the application's business (the command line uses Agg).

Kinds: :func:`locus` (Tanaka's Fig. 9), :func:`spectrum`, :func:`star`, :func:`firing` (of
:func:`balance_cli.analyse`'s results) and :func:`torque` (of :func:`balance_cli.analysis.torque.torque`'s);
``of="moment"`` makes the locus and the star those of the free moment instead of the force.
:func:`save` writes a figure in the format its file name's extension names.
"""

import functools
import math
import os
import sys
import textwrap
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

import matplotlib
import numpy as np
from matplotlib.artist import Artist

from ..checks import instance, items
from ..errors import PlotError
from ..output import write_bytes
from ..tolerances import SPECTRUM_FLOOR
from ..units import UNIT_SYSTEMS, Scale

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult
    from ..analysis.torque import TorqueResult

__all__ = ["KINDS", "FORMATS", "QUANTITIES", "locus", "spectrum", "star", "firing", "torque", "save",
           "format_of", "grid_size", "locus_points", "spectrum_data", "star_chains", "torque_data",
           "colours", "short", "place_labels"]

KINDS = ("locus", "spectrum", "star", "firing", "torque")
#: file formats :func:`save` writes (those of matplotlib's that need neither LaTeX nor a viewer
#: for raw pixels)
FORMATS = ("png", "svg", "svgz", "pdf", "eps", "ps", "jpg", "jpeg", "tif", "tiff", "webp")
#: inches per subplot cell of the star and firing grids, the narrowest figure (its title must
#: fit), and dots per inch of bitmaps
CELL_IN = 4.0
MIN_WIDTH_IN = 8.0
DPI = 100
SPECTRUM_UNITS = ("per-cylinder",) + tuple(UNIT_SYSTEMS)
#: units of :func:`torque`: the moment unit of a system of units (N·m, kN·m, ..., lbf·ft)
TORQUE_UNITS = tuple(UNIT_SYSTEMS)


def _new_figure(size):
    import matplotlib.pyplot as plt  # only when the caller gives no figure of their own

    return plt.figure(figsize=size, dpi=DPI)


def _results(results, order=None) -> "list[EngineResult]":
    """The results as a list; an ``order`` every one of them was analysed to."""
    from ..analysis.results import EngineResult

    chosen = items(results, EngineResult, "results", PlotError)
    if order is not None:
        lowest = min(r.max_order for r in chosen)
        if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= lowest:
            raise PlotError(f"{order!r} is not among the orders analysed (1 to {lowest}: raise "
                            "max_order or choose a lower order)", "order")
    return chosen


def grid_size(count):
    """Columns and rows of a grid of ``count`` small pictures."""
    columns = min(3, count)
    return columns, math.ceil(count / columns)


def _grid_figure(count):
    """A new figure for a grid of ``count`` pictures, wide enough for its two-line title."""
    columns, rows = grid_size(count)
    return _new_figure((max(CELL_IN * columns, MIN_WIDTH_IN), CELL_IN * rows))


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


def _quantity(of):
    if of not in QUANTITIES:
        raise PlotError(f"must be one of {', '.join(QUANTITIES)}, got {of!r}", "of")
    return of


def locus_points(result, order=None, of="force", counterweight=True):
    """What :func:`locus` draws of one engine, as x = across, y = along the reference axis:
    ``of="force"`` the resultant force per cylinder (× m_rec·r·ω² per cylinder, Tanaka's
    Fig. 9), ``of="moment"`` the free moment about the engine's mid-length (z̄), N·m, over a
    revolution; all orders, or ``order`` only. With ``counterweight`` (the default) an ideal
    crankshaft counterweight has taken the forward first order away, in two planes for the
    moment (none on a rotary, whose crank does not turn). A locus below the noise floor all
    round is exact zeros."""
    _quantity(of)
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


def locus(results: "Iterable[EngineResult]", order: int | None = None, ax: "Axes | None" = None,
          of: str = "force") -> "Figure":
    """Locus over one revolution of the resultant shaking force per cylinder (``of="force"``,
    Tanaka's Fig. 9) or of the free moment in N·m (``of="moment"``), every engine on one set
    of equal-scaled axes; ``order`` draws one order only. See :func:`locus_points`.

    In a figure of its own the legend goes below the axes, in as many rows as the engines
    need; drawn into ``ax``, the legend is the axes'."""
    _quantity(of)
    chosen = _results(results, order)
    points = [locus_points(r, order, of) for r in chosen]
    # an engine with nothing left is a dot at the origin, hidden under the others
    names = [short(r.engine.name) + ("" if x.any() or y.any() else f" (no free {of})")
             for r, (x, y) in zip(chosen, points)]
    columns, rows = _legend_rows(names)
    own = ax is None
    legend_in = 0.25 + 0.19 * rows      # a legend row of 8-point text, and the frame's padding
    if ax is None:
        height = 8.0 + legend_in
        # inches: title above, tick and axis labels then the legend below
        ax = _new_figure((8, height)).add_axes((0.11, (legend_in + 0.75) / height, 0.84,
                                                1 - (legend_in + 0.75 + 0.85) / height))
    fig = cast("Figure", ax.figure)
    for (x, y), name, colour in zip(points, names, colours(len(chosen))):
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
        fig.legend(*ax.get_legend_handles_labels(), loc="upper center", ncol=columns, fontsize=8,
                   frameon=False, bbox_to_anchor=(0.5, legend_in / (fig.bbox.height / fig.dpi)))
    else:
        ax.legend(fontsize=8, loc="upper right")
    ax.grid(True, linewidth=0.3)
    return fig


def spectrum_data(results, units="per-cylinder"):
    """What :func:`spectrum` draws: orders, per engine the forward and backward magnitudes of
    forces and moments in display units, the floors below which nothing is drawn, and labels.

    ``units``: "per-cylinder" (forces × m_rec·r·ω²·n, moments N·m), or a system of units
    (:data:`~balance_cli.units.UNIT_SYSTEMS`: "N" for N and N·m, "kN", "MN", "kgf", "lbf").
    """
    if units not in SPECTRUM_UNITS:
        raise PlotError(f"must be one of {', '.join(SPECTRUM_UNITS)}, got {units!r}", "units")
    chosen = _results(results)
    scale = Scale.of(absolute=units != "per-cylinder", units="N" if units == "per-cylinder" else units)
    engines = []
    for r in chosen:
        unit = r.per_cylinder_unit_n
        engines.append({
            "name": short(r.engine.name),
            "force": np.array([[scale.force(abs(o.force_forward), unit),
                                scale.force(abs(o.force_backward), unit)] for o in r.shaking.orders]),
            "moment": np.array([[scale.moment(abs(o.moment_forward)),
                                 scale.moment(abs(o.moment_backward))] for o in r.shaking.orders]),
        })
    # the floors: SPECTRUM_FLOOR of the largest engine's m_rec·r·ω²·n (times one metre)
    largest = max(r.per_cylinder_unit_n for r in chosen)
    return {
        "orders": np.arange(1, max(r.max_order for r in chosen) + 1),
        "engines": engines,
        "force_floor": SPECTRUM_FLOOR * scale.force(largest, largest),
        "moment_floor": SPECTRUM_FLOOR * scale.moment(largest),
        "force_label": f"force ({scale.force_unit_text})",
        "moment_label": f"free moment ({scale.moment_label})",
        "has_moments": any((e["moment"] > SPECTRUM_FLOOR * scale.moment(largest)).any()
                           for e in engines),
    }


def spectrum(results: "Iterable[EngineResult]", units: str = "per-cylinder",
             fig: "Figure | None" = None) -> "Figure":
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
        fig = _new_figure((12, (8 if panels == 2 else 4.5) + legend_in))
    axes = fig.subplots(panels, 1, sharex=True, squeeze=False)[:, 0]
    orders = data["orders"]
    n = len(data["engines"])
    width = 0.8 / (2 * n)
    handles = []
    quantities = [("force", data["force_floor"], data["force_label"])]
    if panels == 2:
        quantities.append(("moment", data["moment_floor"], data["moment_label"]))
    for i, (engine, colour) in enumerate(zip(data["engines"], colours(n))):
        offset = -0.4 + 2 * i * width
        for ax, (quantity, floor, _) in zip(axes, quantities):
            values = engine[quantity]
            for part, shift, style in ((0, 0.0, {}), (1, width, {"alpha": 0.45, "hatch": "//"})):
                heights = values[: len(orders), part]
                shown = heights > floor
                _bars(ax, orders[: len(heights)][shown] + offset + shift, heights[shown], floor,
                      width, facecolor=colour, **style)
        handles.append(Patch(color=colour, label=engine["name"]))
    handles += [Patch(facecolor="white", edgecolor="black", label="forward (turns with the crank)"),
                Patch(facecolor="white", edgecolor="black", hatch="//", label="backward (against it)")]
    for ax, (quantity, floor, label) in zip(axes, quantities):
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
    title = (f"Forward and backward parts by order (parts below {SPECTRUM_FLOOR:g} of "
             "m_rec·r·ω²·n not drawn)")
    if panels == 1:
        title += "\nno engine has a free moment above that floor"
    axes[0].set_title(title, y=1.0)
    height = fig.get_size_inches()[1]
    fig.legend(handles=handles, loc="upper center", ncol=columns, fontsize=8, frameon=False,
               bbox_to_anchor=(0.5, legend_in / height))
    # inches: the title above; tick labels and "order" below, then the legend
    fig.subplots_adjust(left=0.07, right=0.98, top=1 - (0.56 if panels == 2 else 0.72) / height,
                        bottom=(legend_in + 0.63) / height, hspace=0.08)
    return fig


def _bars(ax, left, top, bottom, width, **style):
    """Bars from ``bottom`` up to each ``top``, starting at each ``left``, as one collection
    (one artist for all: hundreds of separate rectangles are slow to draw)."""
    from matplotlib.collections import PolyCollection

    if len(left) == 0:
        return
    corners = [[(x, bottom), (x + width, bottom), (x + width, y), (x, y)] for x, y in zip(left, top)]
    ax.add_collection(PolyCollection(corners, linewidth=0, **style), autolim=False)


def star_chains(result, order, of="force"):
    """For :func:`star`: each part ("forward", "backward") of order ``order`` as a list of
    (label, tail, head) arrows per cylinder, chained tip to tail (complex: real along the
    reference axis); the last head is the engine's resultant. ``of="force"``: each cylinder's
    force, in units of m_rec·r·ω²·n; ``of="moment"``: its share of the free moment,
    (z_i − z̄)·F_i, N·m. Shares below the noise floor are left out."""
    _quantity(of)
    _results([result], order)
    if of == "force":
        shares = result.shaking.cylinder_phasors(order)
        unit = result.per_cylinder_unit_n
    else:
        shares = result.shaking.cylinder_moment_phasors(order, result.engine.mean_z_m)
        unit = 1.0
    floor = _star_floor(result, of)
    chains = {}
    for part, index in (("forward", 1), ("backward", 2)):
        tip, arrows = 0j, []
        for share in shares:
            phasor = share[index] / unit
            if abs(phasor) < floor:
                continue
            arrows.append((share[0], tip, tip + phasor))
            tip += phasor
        chains[part] = arrows
    return chains


def _star_floor(result, of):
    """The noise floor in the units of :func:`star_chains`."""
    if of == "force":
        return result.engine.noise_floor_n / result.per_cylinder_unit_n
    return result.engine.noise_floor_nm


def _magnitude(value, unit):
    """|Σ| of the star: four decimals of m_rec·r·ω²·n, or four significant figures of N·m
    with thousands spaced above 10⁴ (a marine couple reads 4 980 395, not 4.98e+06)."""
    if not unit:
        return f"{value:.4f}"
    text = f"{value:,.0f}".replace(",", " ") if value >= 1e4 else "0" if value == 0 else f"{value:.4g}"
    return f"{text} {unit}"


#: font size of the star's cylinder labels (points), and their gap from their arrow (points)
STAR_LABEL_PT = 6.5
STAR_LABEL_GAP_PT = 1.5
#: characters of a star picture's title in a line: what 9-point text fits a cell's width
STAR_TITLE_CHARS = 44
#: an arrow shorter than this (points) gets no label: the eye cannot tell which arrow it names
STAR_LABEL_MIN_PT = 5.0


@functools.lru_cache(maxsize=1024)
def _text_size_pt(text, fontsize):
    """Width and height (points) of one line of ``text``, as a Text artist lays it out; the
    same cylinder numbers recur on every engine, so each is measured once."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import text_to_path

    prop = FontProperties(size=fontsize)
    width, _, _ = text_to_path.get_text_width_height_descent(text, prop, ismath=False)
    _, height, descent = text_to_path.get_text_width_height_descent("lp", prop, ismath=False)
    return width, height + descent


def _boxes_overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _crosses(box, p, q):
    """Whether the segment ``p``–``q`` passes through ``box`` (x0, y0, x1, y1)."""
    # clip the segment's parameter range to the box on each axis (Liang–Barsky)
    low, high = 0.0, 1.0
    for start, step, lower, upper in ((p[0], q[0] - p[0], box[0], box[2]),
                                      (p[1], q[1] - p[1], box[1], box[3])):
        if step == 0:
            if not lower < start < upper:
                return False
            continue
        t0, t1 = sorted(((lower - start) / step, (upper - start) / step))
        low, high = max(low, t0), min(high, t1)
        if low >= high:
            return False
    return True


def place_labels(segments, sizes, gap=STAR_LABEL_GAP_PT, shortest=STAR_LABEL_MIN_PT, crowded=0.3):
    """Centres for labels of line ``segments`` ((x0, y0), (x1, y1)) of ``sizes`` (width,
    height), all in one unit (points or pixels) on equal axes; None for a label left out.

    The longest segments are labelled first. Each label sits beside its segment, at its
    middle or a third of the way from an end, on the side away from the centre of the whole
    drawing first; a place that overlaps a label already placed is refused, and among the
    rest the one crossing the fewest segments wins; only segments of at least ``crowded``
    times the longest may have a label across another segment. A segment with no such place,
    or shorter than ``shortest``, goes unlabelled: on a crowded star the short arrows are the
    ones whose number matters least."""
    points = np.array([p for segment in segments for p in segment], float).reshape(-1, 2)
    centre = points.mean(axis=0) if len(points) else np.zeros(2)
    placed: "list[tuple[float, float, float, float]]" = []
    found: "list[tuple[float, float] | None]" = [None] * len(segments)
    lengths = [math.dist(*segment) for segment in segments]
    for i in sorted(range(len(segments)), key=lambda i: -lengths[i]):
        if lengths[i] < shortest:
            continue
        (x0, y0), (x1, y1) = segments[i]
        w, h = sizes[i]
        ux, uy = (x1 - x0) / lengths[i], (y1 - y0) / lengths[i]
        nx, ny = -uy, ux
        middle = ((x0 + x1) / 2, (y0 + y1) / 2)
        if (middle[0] - centre[0]) * nx + (middle[1] - centre[1]) * ny < 0:
            nx, ny = -nx, -ny
        # from the segment to the box's edge along the normal, then the gap
        offset = gap + abs(nx) * w / 2 + abs(ny) * h / 2
        best = None
        for side in (1, -1):
            for t in (0.5, 1 / 3, 2 / 3):
                cx = x0 + t * (x1 - x0) + side * nx * offset
                cy = y0 + t * (y1 - y0) + side * ny * offset
                box = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                # a point of room: the renderer's hinted glyphs are a little wider than the
                # font's outlines
                room = (box[0] - 1, box[1] - 1, box[2] + 1, box[3] + 1)
                if any(_boxes_overlap(room, other) for other in placed):
                    continue
                crossings = sum(_crosses(box, *segment) for segment in segments)
                if best is None or crossings < best[0]:
                    best = (crossings, (cx, cy), box)
                if crossings == 0:
                    break
            if best is not None and best[0] == 0:
                break
        # over another arrow a short arrow's label would name that arrow as well as its own
        if best is not None and (best[0] == 0 or lengths[i] >= crowded * max(lengths)):
            found[i] = best[1]
            placed.append(best[2])
    return found


def _cells(fig, rows, columns, count):
    """Axes in the first ``count`` cells of a grid, row by row: the empty cells get none (an
    axes costs more to make than most of what is drawn in it)."""
    grid = fig.add_gridspec(rows, columns)
    return [fig.add_subplot(grid[i // columns, i % columns]) for i in range(count)]


def star(results: "Iterable[EngineResult]", order: int = 2, fig: "Figure | None" = None,
         of: str = "force") -> "Figure":
    """Each cylinder's forward (blue) and backward (red) phasor of ``order`` at θ = 0, chained
    tip to tail and labelled by cylinder; the dashed line is the engine's resultant. One small
    picture per engine, with a scale bar: of its force (``of="force"``, in units of
    m_rec·r·ω²·n) or of its share of the free moment, (z_i − z̄)·F_i (``of="moment"``, N·m).

    Cylinder labels never overlap: where they would (many cylinders, or forward and backward
    chains on top of each other) the shorter arrows go unlabelled (see :func:`place_labels`)."""
    _quantity(of)
    chosen = _results(results, order)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = _grid_figure(len(chosen))
    # the layout first: labels are placed in the axes' final scale
    axes = _cells(fig, rows, columns, len(chosen))
    # inches above the top row for the figure's two-line title, each picture's and its |Σ|
    fig.subplots_adjust(left=0.06, right=0.97, bottom=0.04, top=1 - 1.3 / (CELL_IN * rows),
                        wspace=0.3, hspace=0.4)
    unit = "N·m" if of == "moment" else ""
    for ax, r in zip(axes, chosen):
        chains = star_chains(r, order, of)
        parts = (("forward", "C0"), ("backward", "C3"))
        for row, (part, colour) in enumerate(parts):
            arrows = chains[part]
            end = arrows[-1][2] if arrows else 0j
            # shares above the floor may still cancel to rounding noise
            if abs(end) < _star_floor(r, of):
                end = 0j
            if arrows:
                tails = np.array([a[1] for a in arrows])
                steps = np.array([a[2] for a in arrows]) - tails
                # arrow widths in inches: a share of the axes' width grows fat in a wide cell
                ax.quiver(tails.imag, tails.real, steps.imag, steps.real, angles="xy",
                          scale_units="xy", scale=1, color=colour, units="inches", width=0.014)
            ax.plot([0, end.imag], [0, end.real], linestyle="--", color=colour, linewidth=1.4)
            # a text, not a legend: 17 legends cost more to lay out than the rest of the picture;
            # above the axes, where no chain runs
            ax.annotate(f"{part}: |Σ| = {_magnitude(abs(end), unit)}", (0, 1),
                        xycoords="axes fraction", xytext=(0, 10 - 9 * row),
                        textcoords="offset points", color=colour, fontsize=7, va="bottom")
        ax.plot([0], [0], marker="o", color="k", markersize=3)
        if not (chains["forward"] or chains["backward"]):
            ax.text(0.5, 0.4, f"no {'free moment' if of == 'moment' else 'force'} of order {order}",
                    transform=ax.transAxes, ha="center", fontsize=8, color="0.4")
        # two lines rather than one running into the next picture's title
        ax.set_title(textwrap.fill(short(r.engine.name), STAR_TITLE_CHARS), fontsize=9, y=1.0,
                     pad=21)
        # no axes (their ticks cost more than the rest of the picture): a scale bar instead
        ax.axis("off")
        _scale_bar(ax, chains, unit)
        _fit(ax, chains)
        _label_arrows(ax, [(label, tail, head, colour) for part, colour in parts
                           for label, tail, head in chains[part]])
    if of == "moment":
        title = (f"Order {order}: each cylinder's share (z − z̄)·F of the free moment, forward "
                 "(blue) and backward (red), at θ = 0, chained\ndashed: the resultant (N·m, scale "
                 "bar below each); horizontal: yawing (across), vertical: pitching (along)")
    else:
        title = (f"Order {order}: each cylinder's forward (blue) and backward (red) phasor at "
                 "θ = 0, chained; dashed: the resultant\n(× m_rec·r·ω²·n, scale bar below each; "
                 "horizontal across the reference axis, vertical along it)")
    fig.suptitle(title, fontsize=9)
    return fig


def _fit(ax, chains):
    """Equal-scaled limits with room round the chains for their labels and the scale bar,
    filling the axes' box, fixed now so that labels can be placed in the final scale."""
    points = [0j] + [p for arrows in chains.values() for _, tail, head in arrows for p in (tail, head)]
    xs, ys = [p.imag for p in points], [p.real for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    margin = 0.1 * span
    # the scale bar hangs 0.08 span below the chains, its figure below that
    (x0, x1), (y0, y1) = (min(xs) - margin, max(xs) + margin), (min(ys) - 0.1 * span - margin,
                                                                 max(ys) + margin)
    box = ax.get_position()
    fig_w, fig_h = ax.figure.get_size_inches()
    aspect = (box.height * fig_h) / (box.width * fig_w)     # height over width of the box
    if (y1 - y0) / (x1 - x0) < aspect:
        grow = aspect * (x1 - x0) - (y1 - y0)
        y0, y1 = y0 - grow / 2, y1 + grow / 2
    else:
        grow = (y1 - y0) / aspect - (x1 - x0)
        x0, x1 = x0 - grow / 2, x1 + grow / 2
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="box")
    ax.apply_aspect()


def _label_arrows(ax, arrows):
    """Cylinder labels beside ``arrows`` (label, tail, head, colour), where
    :func:`place_labels` finds room."""
    fig = ax.figure
    to_pt = 72.0 / fig.dpi
    data_to_pt = lambda z: ax.transData.transform((z.imag, z.real)) * to_pt  # noqa: E731
    segments = [(tuple(data_to_pt(tail)), tuple(data_to_pt(head))) for _, tail, head, _ in arrows]
    sizes = [_text_size_pt(label, STAR_LABEL_PT) for label, _, _, _ in arrows]
    centres = place_labels(segments, sizes)
    to_data = ax.transData.inverted()
    for (label, _, _, colour), centre in zip(arrows, centres):
        if centre is None:
            continue
        x, y = to_data.transform(np.array(centre) / to_pt)
        ax.text(x, y, label, fontsize=STAR_LABEL_PT, color=colour, ha="center", va="center",
                gid="cylinder label")


def _nice_length(span):
    """A round length (1, 2 or 5 times a power of ten) of about a quarter of ``span``."""
    if span <= 0:
        return 0.0
    power = 10.0 ** math.floor(math.log10(span / 4))
    return next(step * power for step in (5, 2, 1) if step * power <= span / 4 * 1.0001)


def _scale_bar(ax, chains, unit=""):
    points = [0j] + [p for arrows in chains.values() for _, tail, head in arrows for p in (tail, head)]
    xs, ys = [p.imag for p in points], [p.real for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    length = _nice_length(span)
    if not length:
        return
    x0, y0 = min(xs), min(ys) - 0.08 * span
    ax.plot([x0, x0 + length], [y0, y0], color="k", linewidth=1.5)
    text = _magnitude(length, unit) if unit else f"{length:g}"
    ax.text(x0 + length / 2, y0 - 0.02 * span, text, ha="center", va="top", fontsize=7)


def firing(results: "Iterable[EngineResult]", fig: "Figure | None" = None) -> "Figure":
    """Firing angles on a dial of one working cycle (720° or 360°, clockwise from the top),
    cylinder numbers outside, intervals in red (one, in the centre, when they are all equal)."""
    chosen = _results(results)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = _grid_figure(len(chosen))
    axes = _cells(fig, rows, columns, len(chosen))
    for ax in axes:
        ax.axis("off")
    ring = np.linspace(0, 2 * np.pi, 181)
    for ax, r in zip(axes, chosen):
        cycle = r.engine.cycle_deg
        fire = r.firing
        where = lambda angle, radius: (radius * math.sin(2 * math.pi * angle / cycle),  # noqa: E731
                                       radius * math.cos(2 * math.pi * angle / cycle))
        ax.plot(np.sin(ring), np.cos(ring), color="0.7", linewidth=0.6)
        for tick in np.arange(0, cycle, cycle / 4):
            ax.text(*where(tick, 1.32), f"{tick:g}°", ha="center", va="center", fontsize=6,
                    color="0.5")
        # every spoke in one line broken at NaN: one artist, not one per cylinder
        xs, ys = [], []
        for angle, number in zip(fire.angles_deg, fire.order):
            x, y = where(angle, 1.0)
            xs += [0.0, x, math.nan]
            ys += [0.0, y, math.nan]
            ax.text(*where(angle, 1.13), str(number), ha="center", va="center", fontsize=8)
        ax.plot(xs, ys, color="C0", linewidth=1.2)
        if fire.uniform:
            # one figure says it: a label in every gap of an even engine only repeats it
            ax.text(0.0, 0.0, f"every\n{fire.intervals_deg[0]:.4g}°", ha="center", va="center",
                    fontsize=6, color="C3")
        else:
            for angle, gap in zip(fire.angles_deg, fire.intervals_deg):
                ax.text(*where(angle + gap / 2, 0.65), f"{gap:.4g}°", ha="center", va="center",
                        fontsize=6, color="C3")
        ax.set_xlim(-1.45, 1.45)
        ax.set_ylim(-1.45, 1.45)
        ax.set_aspect("equal")
        uniform = "uniform" if fire.uniform else f"±{fire.max_deviation_deg:.2f}° from uniform"
        ax.set_title(f"{short(r.engine.name)}\n{r.engine.cycle}-stroke, {uniform}", fontsize=9, y=1.0)
    fig.suptitle("Firing angles over one working cycle (crank degrees from the first firing)",
                 fontsize=10)
    fig.subplots_adjust(left=0.02, right=0.98, bottom=0.02, top=1 - 0.8 / (CELL_IN * rows),
                        wspace=0.1, hspace=0.25)
    return fig


def torque_data(result: "TorqueResult", units: str = "N") -> dict:
    """What :func:`torque` draws of one engine's :class:`~balance_cli.analysis.torque.TorqueResult`.

    Returns ``theta_deg`` (the crank angle of throw 1 over one period, the first angle repeated
    at the end to close the curve), ``inertia``, ``gas`` (None without one) and ``total`` at
    those angles, ``mean`` and ``range`` of the total torque, and its ``orders`` (multiples of ½
    for a four-stroke) with their ``amplitudes`` √(cos² + sin²); torques in the moment unit of
    ``units`` (N·m for "N", kN·m, MN·m, kgf·m, lbf·ft). Also ``name``, ``period_deg``, ``cycle``, ``speed_rpm``, ``unit``.
    """
    from ..units import rad_s_to_rpm

    if units not in TORQUE_UNITS:
        raise PlotError(f"must be one of {', '.join(TORQUE_UNITS)}, got {units!r}", "units")
    scale = Scale.of(True, units)

    def closed(series):
        return None if series is None else scale.moment(np.append(series.curve, series.curve[0]))

    total = result.total
    return {
        "name": short(result.engine.name), "cycle": result.engine.cycle,
        "speed_rpm": rad_s_to_rpm(result.engine.speed_rad_s), "period_deg": result.period_deg,
        "theta_deg": np.append(total.theta_deg, result.period_deg),
        "inertia": closed(result.inertia), "gas": closed(result.gas), "total": closed(total),
        "mean": scale.moment(total.mean), "range": scale.moment(total.range),
        "orders": np.array([k for k, _, _ in total.orders]),
        "amplitudes": np.array([scale.moment(math.hypot(c, s)) for _, c, s in total.orders]),
        "unit": scale.moment_label,
    }


#: line styles of :func:`torque`, by the label each line carries
TORQUE_STYLES: "dict[str, dict[str, Any]]" = {
    "inertia": {"color": "C0", "linewidth": 1.0},
    "gas": {"color": "C1", "linewidth": 1.0},
    "total": {"color": "k", "linewidth": 1.4},
    "mean total": {"color": "C3", "linewidth": 1.0, "linestyle": "--"},
}
#: inches above the torque grid for its title and legend
_HEADER_IN = 0.75


def _tick_text(value):
    return "0" if value == 0 else f"{value:.6g}"


def _span(low, high, bins, floor=None):
    """Limits a little beyond ``low`` to ``high`` (from ``floor`` when given) and the round
    ticks between them, as an axis would choose them."""
    from matplotlib.ticker import MaxNLocator

    if not high > low:
        low, high = (low - 1.0, high + 1.0) if floor is None else (floor, floor + 1.0)
    margin = 0.05 * (high - low)
    limits = (floor if floor is not None else low - margin, high + margin)
    ticks = MaxNLocator(nbins=bins, steps=[1, 2, 2.5, 5, 10]).tick_values(*limits)
    slack = 1e-9 * (limits[1] - limits[0])
    return limits, [0.0 if abs(t) <= slack else float(t) for t in ticks
                    if limits[0] - slack <= t <= limits[1] + slack]


class _Labels(Artist):
    """Short one-line labels in one artist, at points in figure fractions, each aligned as a
    Text's box would be (``ha`` left, center or right; ``va`` top, center or bottom; rotation
    0 or 90°). Hundreds of Text artists, each laying itself out, take longer to draw than the
    rest of a picture, as hundreds of separate rectangles do (:func:`_bars`)."""

    def __init__(self, fig, fontsize=7):
        super().__init__()
        self.set_transform(fig.transSubfigure)
        self.set_zorder(3)      # as Text: above lines and frames
        self.fontsize = fontsize
        self.colour = matplotlib.rcParams["text.color"]
        self.items = []       # (x, y, text, ha, va, rotation)

    def add(self, x, y, text, ha="center", va="center", rotation=0):
        self.items.append((x, y, text, ha, va, rotation))

    def texts(self):
        """The labels' strings, in the order they were added."""
        return [item[2] for item in self.items]

    def draw(self, renderer):
        from matplotlib.font_manager import FontProperties

        if not self.get_visible() or not self.items:
            return
        prop = FontProperties(size=self.fontsize)
        metrics = {}

        def size(text):
            if text not in metrics:
                metrics[text] = renderer.get_text_width_height_descent(text, prop, ismath=False)
            return metrics[text]

        _, line_h, line_d = size("lp")     # a line's height and descent, as Text takes them
        _, canvas_h = renderer.get_canvas_width_height()
        gc = renderer.new_gc()
        gc.set_foreground(self.colour)
        points = self.get_transform().transform([item[:2] for item in self.items])
        for (x, y), (_, _, text, ha, va, rotation) in zip(points, self.items):
            w, h, d = size(text)
            h, d = max(h, line_h), max(d, line_d)
            # the box, w wide and h high (h high and w wide turned 90°), aligned on (x, y); then
            # the left end of the baseline within it
            box_w, box_h = (w, h) if rotation == 0 else (h, w)
            left = x - {"left": 0.0, "center": box_w / 2, "right": box_w}[ha]
            bottom = y - {"bottom": 0.0, "center": box_h / 2, "top": box_h}[va]
            if rotation == 0:
                x, y = left, bottom + d
            else:
                x, y = left + box_w - d, bottom
            renderer.draw_text(gc, x, canvas_h - y if renderer.flipy() else y, text, prop, rotation)
        gc.restore()
        self.stale = False


class _Panels:
    """Framed panels drawn straight on a figure, positioned in inches: an Axes per panel (and
    its ticks) would cost more than the rest of the torque picture. Grid lines and frames of
    every panel are gathered into two paths, and tick and axis labels into one
    :class:`_Labels`, all drawn by :meth:`finish`."""

    def __init__(self, fig):
        self.fig = fig
        self.size = (fig.bbox.width / fig.dpi, fig.bbox.height / fig.dpi)
        self.grid, self.frames = [], []
        self.labels = _Labels(fig)

    def at(self, x_in, y_in):
        """Figure fractions of a point ``x_in``, ``y_in`` inches from the bottom left."""
        return x_in / self.size[0], y_in / self.size[1]

    def text(self, x_in, y_in, text, **style):
        return self.fig.text(*self.at(x_in, y_in), text, **{"fontsize": 7, **style})

    def label(self, x_in, y_in, text, **alignment):
        self.labels.add(*self.at(x_in, y_in), text, **alignment)

    def panel(self, box_in, xlim, ylim, xticks, xlabels, yticks, ylabels, xlabel, ylabel,
              xminor=()):
        """A panel (``box_in``: left, bottom, width, height, inches) showing ``xlim`` × ``ylim``,
        with grid lines at the ticks, their labels (none where a label is empty) and axis
        labels, and short tick marks below at ``xminor``; returns the transform from its data
        to the figure."""
        from matplotlib.transforms import Bbox, BboxTransform

        left, bottom, width, height = box_in
        (x0, y0), (x1, y1) = self.at(left, bottom), self.at(left + width, bottom + height)
        to_panel = BboxTransform(Bbox([[xlim[0], ylim[0]], [xlim[1], ylim[1]]]),
                                 Bbox([[x0, y0], [x1, y1]]))
        for x, label in zip(xticks, xlabels):
            fx = x0 + (x1 - x0) * (x - xlim[0]) / (xlim[1] - xlim[0])
            self.grid.append([(fx, y0), (fx, y1)])
            if label:
                self.label(fx * self.size[0], bottom - 0.04, label, ha="center", va="top")
        for y, label in zip(yticks, ylabels):
            fy = y0 + (y1 - y0) * (y - ylim[0]) / (ylim[1] - ylim[0])
            self.grid.append([(x0, fy), (x1, fy)])
            if label:
                self.label(left - 0.04, fy * self.size[1], label, ha="right", va="center")
        self.frames.append([(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)])
        # ticks in the frame's path: inward from the bottom edge, long at labels
        for x, length in [(x, 0.06) for x, label in zip(xticks, xlabels) if label] \
                + [(x, 0.03) for x in xminor]:
            fx = x0 + (x1 - x0) * (x - xlim[0]) / (xlim[1] - xlim[0])
            self.frames.append([(fx, y0), (fx, y0 + length / self.size[1])])
        self.label(left + width / 2, bottom - 0.19, xlabel, ha="center", va="top")
        self.label(left - 0.52, bottom + height / 2, ylabel, ha="left", va="center", rotation=90)
        return to_panel + self.fig.transSubfigure

    def finish(self):
        """Draw the grid lines and frames, each as one path (a collection's many paths take
        longer to write)."""
        from matplotlib.patches import PathPatch

        for lines, style in ((self.grid, {"edgecolor": "0.85", "linewidth": 0.5, "zorder": 0.5}),
                             (self.frames, {"edgecolor": "0.3", "linewidth": 0.6, "zorder": 2.5})):
            self.fig.add_artist(PathPatch(_compound(lines), fill=False, **style))
        self.fig.add_artist(self.labels)


def _compound(polylines, closed=False):
    """One path of many polylines (closed polygons when ``closed``)."""
    from matplotlib.path import Path as Shape

    vertices, codes = [], []
    for points in polylines:
        vertices += list(points) + ([points[0]] if closed else [])
        codes += [Shape.MOVETO] + [Shape.LINETO] * (len(points) - 1) + ([Shape.CLOSEPOLY] if closed else [])
    return Shape(vertices, codes)


def torque(results: "Iterable[TorqueResult]", units: str = "N", fig: "Figure | None" = None) -> "Figure":
    """Torques of :func:`balance_cli.analysis.torque.torque`, one small picture per engine: above, the
    inertia, gas (when there is one) and total torque over one period (360°, or 720° for a
    four-stroke) against the crank angle of throw 1, and the mean total torque (dashed); below,
    the amplitude of each order of the total torque (half orders too for a four-stroke).
    Torques in the moment unit of ``units`` (N·m for "N", kN·m, MN·m, kgf·m or lbf·ft).

    The pictures are drawn on the figure itself, not in Axes: 17 engines' Axes and their ticks
    would take longer to draw than all the rest. In ``fig.artists``, each engine's lines carry
    the labels "inertia", "gas", "total" and "mean total" and its bars are one PathPatch
    labelled "orders" (rectangles from 0 up to each amplitude, centred on the order), each with
    a transform from its data (degrees or orders, torque) to the figure; the engines' titles
    are ``fig.texts``, the tick and axis labels one more artist.
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import PathPatch

    from ..analysis.torque import TorqueResult

    chosen = items(results, TorqueResult, "results", PlotError, "engine's torques")
    engines = [torque_data(r, units) for r in chosen]
    columns, rows = grid_size(len(engines))
    if fig is None:
        fig = _new_figure((max(CELL_IN * columns, MIN_WIDTH_IN), CELL_IN * rows + _HEADER_IN))
    panels = _Panels(fig)
    width_in, height_in = panels.size
    cell_w, cell_h = width_in / columns, (height_in - _HEADER_IN) / rows
    unit = engines[0]["unit"]
    # inches of a cell: title, curves, their tick labels and axis label, orders, theirs
    left, right, title, gap, foot = 0.68, 0.22, 0.45, 0.55, 0.42
    curve_h = 0.64 * (cell_h - title - gap - foot)
    order_h = cell_h - title - gap - foot - curve_h
    for index, data in enumerate(engines):
        row, column = divmod(index, columns)
        x0, top = column * cell_w, height_in - _HEADER_IN - row * cell_h
        # without gas the total is the inertia torque, and hides it
        panels.text(x0 + cell_w / 2, top - 0.03, f"{data['name']}\n{data['cycle']}-stroke, "
                    f"{data['speed_rpm']:g} rpm{'' if data['gas'] is not None else ', no gas'}: "
                    f"mean {data['mean']:.4g} {unit}, ΔC {data['range']:.4g} {unit}", fontsize=8,
                    ha="center", va="top")
        period = data["period_deg"]
        names = [n for n in ("inertia", "gas", "total") if data[n] is not None]
        ylim, yticks = _span(min(data[n].min() for n in names), max(data[n].max() for n in names), 3)
        xticks = np.arange(5) * period / 4        # labelled at 0, half and the whole period
        curves = panels.panel((x0 + left, top - title - curve_h, cell_w - left - right, curve_h),
                              (0.0, period), ylim, xticks,
                              [f"{x:g}°" if i % 2 == 0 else "" for i, x in enumerate(xticks)], yticks,
                              [_tick_text(y) for y in yticks], "crank angle of throw 1",
                              f"torque ({unit})")
        for name in names:
            fig.add_artist(Line2D(data["theta_deg"], data[name], transform=curves, label=name,
                                  **TORQUE_STYLES[name]))
        fig.add_artist(Line2D([0.0, period], [data["mean"]] * 2, transform=curves,
                              label="mean total", **TORQUE_STYLES["mean total"]))
        orders, heights = data["orders"], data["amplitudes"]
        step, highest = orders[0], orders[-1]      # step: ½ for a four-stroke, 1 for a two-stroke
        ylim, yticks = _span(0.0, float(heights.max()), 2, floor=0.0)
        if not heights.any():
            yticks = []
        # whole orders labelled, with a grid line, a round step apart (at most 10 labels);
        # the others, and a four-stroke's half orders, get a short tick only
        every = next(n * 10 ** p for p in range(6) for n in (1, 2, 5) if highest / (n * 10 ** p) <= 10)
        xticks = np.arange(every, highest + 0.5 * every, every)
        minor = [x for x in np.arange(step, highest + 0.5 * step, step) if x % every]
        bars = panels.panel((x0 + left, top - cell_h + foot, cell_w - left - right, order_h),
                            (0.0, highest + step), ylim, xticks, [f"{x:g}" for x in xticks], yticks,
                            ["" if y == 0 else _tick_text(y) for y in yticks],   # bars stand on 0
                            "order of the total torque", f"amplitude ({unit})", xminor=minor)
        width = 0.7 * step
        corners = [[(k - width / 2, 0.0), (k + width / 2, 0.0), (k + width / 2, h), (k - width / 2, h)]
                   for k, h in zip(orders, heights) if h > 0]
        if corners:
            fig.add_artist(PathPatch(_compound(corners, closed=True), facecolor="0.35", linewidth=0,
                                     transform=bars, label="orders"))
        else:
            panels.label(x0 + left + (cell_w - left - right) / 2, top - cell_h + foot + order_h / 2,
                         f"no order up to {highest:g}")
    panels.finish()
    shown = [n for n in TORQUE_STYLES if n != "gas" or any(e["gas"] is not None for e in engines)]
    fig.legend(handles=[Line2D([], [], label=n, **TORQUE_STYLES[n]) for n in shown],
               loc="upper center", bbox_to_anchor=panels.at(width_in / 2, height_in - 0.36),
               ncol=len(shown), fontsize=8, frameon=False)
    fig.suptitle("Torque at constant speed over one cycle, and the amplitude of each order of "
                 "the total torque", fontsize=10, y=1 - 0.08 / height_in)
    return fig


def format_of(path: "str | os.PathLike[str]") -> str:
    """The file format :func:`save` writes to ``path``: its extension, one of :data:`FORMATS`."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in FORMATS:
        shown = f"'.{suffix}'" if suffix else "no extension"
        raise PlotError(f"{str(path)!r} has {shown}; end the file name in one of "
                        f"{', '.join('.' + f for f in FORMATS)}", "path")
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
