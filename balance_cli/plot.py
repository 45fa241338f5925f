"""Pictures of analysed engines (matplotlib).

Each function takes results of :func:`balance_cli.analyse`, draws, and returns the Figure; none
recomputes an analysis. Give ``ax`` (locus) or ``fig`` (the others) to draw into your own;
otherwise a new pyplot figure is made, so figures show inline in a notebook. Importing this
module never chooses a backend: that is the application's business (the command line uses Agg).

Kinds: :func:`locus` (Tanaka's Fig. 9), :func:`spectrum`, :func:`star`, :func:`firing` (of
:func:`balance_cli.analyse`'s results) and :func:`torque` (of :func:`balance_cli.torques.torque`'s).
:func:`save` writes a figure in the format its file name's extension names.
"""

import math
import os
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

import matplotlib
import numpy as np
from matplotlib.artist import Artist

from .checks import instance, items
from .errors import PlotError
from .output import write_bytes
from .report.display import Scale
from .tolerances import SPECTRUM_FLOOR

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from .analysis import EngineResult
    from .torques import TorqueResult

__all__ = ["KINDS", "FORMATS", "locus", "spectrum", "star", "firing", "torque", "save", "format_of",
           "grid_size", "locus_points", "spectrum_data", "star_chains", "torque_data", "colours",
           "short"]

KINDS = ("locus", "spectrum", "star", "firing", "torque")
#: file formats :func:`save` writes (those of matplotlib's that need neither LaTeX nor a viewer
#: for raw pixels)
FORMATS = ("png", "svg", "svgz", "pdf", "eps", "ps", "jpg", "jpeg", "tif", "tiff", "webp")
#: inches per subplot cell of the star and firing grids, the narrowest figure (its title must
#: fit), and dots per inch of bitmaps
CELL_IN = 4.0
MIN_WIDTH_IN = 8.0
DPI = 100
SPECTRUM_UNITS = ("per-cylinder", "N", "kgf")
#: units of :func:`torque`: N·m or kgf·m
TORQUE_UNITS = ("N", "kgf")


def _new_figure(size):
    import matplotlib.pyplot as plt  # only when the caller gives no figure of their own

    return plt.figure(figsize=size, dpi=DPI)


def _results(results, order=None) -> "list[EngineResult]":
    """The results as a list; an ``order`` every one of them was analysed to."""
    from .analysis import EngineResult

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


def locus_points(result, order=None):
    """Per-cylinder resultant force over a revolution after an ideal crankshaft counterweight
    (none on a rotary), as x = across, y = along the reference axis (Tanaka's Fig. 9)."""
    force = result.counterweighted_locus(order) / result.per_cylinder_unit_n
    return force.imag, force.real


def locus(results: "Iterable[EngineResult]", order: int | None = None, ax: "Axes | None" = None) -> "Figure":
    """Locus of the resultant shaking force per cylinder over one revolution, every engine on
    one set of equal-scaled axes; ``order`` draws one order only."""
    chosen = _results(results, order)
    if ax is None:
        ax = _new_figure((8, 8)).add_subplot()
    fig = cast("Figure", ax.figure)
    for r, colour in zip(chosen, colours(len(chosen))):
        x, y = locus_points(r, order)
        ax.plot(np.append(x, x[0]), np.append(y, y[0]), label=short(r.engine.name), linewidth=1.6,
                color=colour)
    ax.axhline(0, color="0.6", linewidth=0.6)
    ax.axvline(0, color="0.6", linewidth=0.6)
    ax.set_aspect("equal", adjustable="datalim")
    what = f"order {order}" if order else "all orders"
    ax.set_title(f"Locus of the resultant shaking force per cylinder ({what}),\n"
                 "after an ideal crankshaft counterweight (none on a rotary)")
    ax.set_xlabel("across the reference axis (× m_rec·r·ω² per cylinder)")
    ax.set_ylabel("along the reference axis (× m_rec·r·ω² per cylinder)")
    ax.legend(fontsize=8, loc="upper right")
    ax.grid(True, linewidth=0.3)
    return fig


def spectrum_data(results, units="per-cylinder"):
    """What :func:`spectrum` draws: orders, per engine the forward and backward magnitudes of
    forces and moments in display units, the floors below which nothing is drawn, and labels.

    ``units``: "per-cylinder" (forces × m_rec·r·ω²·n, moments N·m), "N" (N, N·m) or "kgf"
    (kgf, kgf·m).
    """
    if units not in SPECTRUM_UNITS:
        raise PlotError(f"must be one of {', '.join(SPECTRUM_UNITS)}, got {units!r}", "units")
    chosen = _results(results)
    scale = Scale.of(absolute=units != "per-cylinder", units="kgf" if units == "kgf" else "N")
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
    if fig is None:
        fig = _new_figure((12, 8 if panels == 2 else 4.5))
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
    fig.legend(handles=handles, loc="center right", fontsize=8, frameon=False)
    fig.subplots_adjust(left=0.07, right=0.72, top=0.93 if panels == 2 else 0.84,
                        bottom=0.08 if panels == 2 else 0.14, hspace=0.08)
    return fig


def _bars(ax, left, top, bottom, width, **style):
    """Bars from ``bottom`` up to each ``top``, starting at each ``left``, as one collection
    (one artist for all: hundreds of separate rectangles are slow to draw)."""
    from matplotlib.collections import PolyCollection

    if len(left) == 0:
        return
    corners = [[(x, bottom), (x + width, bottom), (x + width, y), (x, y)] for x, y in zip(left, top)]
    ax.add_collection(PolyCollection(corners, linewidth=0, **style), autolim=False)


def star_chains(result, order):
    """For :func:`star`: each part ("forward", "backward") of order ``order`` as a list of
    (label, tail, head) arrows per cylinder, chained tip to tail, in units of m_rec·r·ω²·n
    (complex: real along the reference axis); the last head is the engine's resultant."""
    _results([result], order)
    shares = result.shaking.cylinder_phasors(order)
    unit = result.per_cylinder_unit_n
    floor = result.engine.noise_floor_n / unit
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


def star(results: "Iterable[EngineResult]", order: int = 2, fig: "Figure | None" = None) -> "Figure":
    """Each cylinder's forward (blue) and backward (red) phasor of ``order`` at θ = 0, chained
    tip to tail and labelled by cylinder; the dashed line is the engine's resultant. One small
    picture per engine, with a scale bar in units of m_rec·r·ω²·n."""
    chosen = _results(results, order)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = _grid_figure(len(chosen))
    axes = fig.subplots(rows, columns, squeeze=False)
    for ax in axes.flat[len(chosen):]:
        ax.axis("off")
    for ax, r in zip(axes.flat, chosen):
        chains = star_chains(r, order)
        for row, (part, colour) in enumerate((("forward", "C0"), ("backward", "C3"))):
            arrows = chains[part]
            end = arrows[-1][2] if arrows else 0j
            if arrows:
                tails = np.array([a[1] for a in arrows])
                steps = np.array([a[2] for a in arrows]) - tails
                ax.quiver(tails.imag, tails.real, steps.imag, steps.real, angles="xy",
                          scale_units="xy", scale=1, color=colour, width=0.006)
                for label, tail, head in arrows:
                    middle = (tail + head) / 2
                    ax.text(middle.imag, middle.real, label, fontsize=6, color=colour)
            ax.plot([0, end.imag], [0, end.real], linestyle="--", color=colour, linewidth=1.4)
            # a text, not a legend: 17 legends cost more to lay out than the rest of the picture
            ax.text(0.02, 0.98 - 0.06 * row, f"{part}: |Σ| = {abs(end):.4f}", color=colour,
                    fontsize=7, transform=ax.transAxes, va="top")
        ax.plot([0], [0], marker="o", color="k", markersize=3)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(short(r.engine.name), fontsize=9, y=1.0)
        # no axes (their ticks cost more than the rest of the picture): a scale bar instead
        ax.axis("off")
        _scale_bar(ax, chains)
    fig.suptitle(f"Order {order}: each cylinder's forward (blue) and backward (red) phasor at "
                 "θ = 0, chained; dashed: the resultant\n(× m_rec·r·ω²·n, scale bar below each; "
                 "horizontal across the reference axis, vertical along it)", fontsize=9)
    fig.subplots_adjust(left=0.06, right=0.97, bottom=0.04, top=1 - 1.1 / (CELL_IN * rows),
                        wspace=0.3, hspace=0.35)
    return fig


def _nice_length(span):
    """A round length (1, 2 or 5 times a power of ten) of about a quarter of ``span``."""
    if span <= 0:
        return 0.0
    power = 10.0 ** math.floor(math.log10(span / 4))
    return next(step * power for step in (5, 2, 1) if step * power <= span / 4 * 1.0001)


def _scale_bar(ax, chains):
    points = [0j] + [p for arrows in chains.values() for _, tail, head in arrows for p in (tail, head)]
    xs, ys = [p.imag for p in points], [p.real for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    length = _nice_length(span)
    if not length:
        return
    x0, y0 = min(xs), min(ys) - 0.08 * span
    ax.plot([x0, x0 + length], [y0, y0], color="k", linewidth=1.5)
    ax.text(x0 + length / 2, y0 - 0.02 * span, f"{length:g}", ha="center", va="top", fontsize=7)


def firing(results: "Iterable[EngineResult]", fig: "Figure | None" = None) -> "Figure":
    """Firing angles on a dial of one working cycle (720° or 360°, clockwise from the top),
    cylinder numbers outside, intervals in red."""
    chosen = _results(results)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = _grid_figure(len(chosen))
    axes = fig.subplots(rows, columns, squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    ring = np.linspace(0, 2 * np.pi, 181)
    for ax, r in zip(axes.flat, chosen):
        cycle = r.engine.cycle_deg
        fire = r.firing
        where = lambda angle, radius: (radius * math.sin(2 * math.pi * angle / cycle),  # noqa: E731
                                       radius * math.cos(2 * math.pi * angle / cycle))
        ax.plot(np.sin(ring), np.cos(ring), color="0.7", linewidth=0.6)
        for tick in np.arange(0, cycle, cycle / 4):
            ax.text(*where(tick, 1.32), f"{tick:g}°", ha="center", va="center", fontsize=6,
                    color="0.5")
        for angle, number in zip(fire.angles_deg, fire.order):
            x, y = where(angle, 1.0)
            ax.plot([0, x], [0, y], color="C0", linewidth=1.2)
            ax.text(*where(angle, 1.13), str(number), ha="center", va="center", fontsize=8)
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
    """What :func:`torque` draws of one engine's :class:`~balance_cli.torques.TorqueResult`.

    Returns ``theta_deg`` (the crank angle of throw 1 over one period, the first angle repeated
    at the end to close the curve), ``inertia``, ``gas`` (None without one) and ``total`` at
    those angles, ``mean`` and ``range`` of the total torque, and its ``orders`` (multiples of ½
    for a four-stroke) with their ``amplitudes`` √(cos² + sin²); torques in N·m, or kgf·m
    when ``units`` is "kgf". Also ``name``, ``period_deg``, ``cycle``, ``speed_rpm``, ``unit``.
    """
    from .units import rad_s_to_rpm

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

    def panel(self, box_in, xlim, ylim, xticks, xlabels, yticks, ylabels, xlabel, ylabel):
        """A panel (``box_in``: left, bottom, width, height, inches) showing ``xlim`` × ``ylim``,
        with grid lines at the ticks, their labels (none where a label is empty) and axis
        labels; returns the transform from its data to the figure."""
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
    """Torques of :func:`balance_cli.torques.torque`, one small picture per engine: above, the
    inertia, gas (when there is one) and total torque over one period (360°, or 720° for a
    four-stroke) against the crank angle of throw 1, and the mean total torque (dashed); below,
    the amplitude of each order of the total torque (half orders too for a four-stroke).
    Torques in N·m, or kgf·m when ``units`` is "kgf".

    The pictures are drawn on the figure itself, not in Axes: 17 engines' Axes and their ticks
    would take longer to draw than all the rest. In ``fig.artists``, each engine's lines carry
    the labels "inertia", "gas", "total" and "mean total" and its bars are one PathPatch
    labelled "orders" (rectangles from 0 up to each amplitude, centred on the order), each with
    a transform from its data (degrees or orders, torque) to the figure; the engines' titles
    are ``fig.texts``, the tick and axis labels one more artist.
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import PathPatch

    from .torques import TorqueResult

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
        # grid lines at whole orders (at most about 8 of them), labels at about 4 of those
        every = max(1, math.ceil(highest / 8))
        xticks = np.arange(every, highest + 0.5 * every, every)
        labelled = 1 if highest <= 5 else every * max(1, round(highest / every / 4))
        bars = panels.panel((x0 + left, top - cell_h + foot, cell_w - left - right, order_h),
                            (0.0, highest + step), ylim, xticks,
                            [f"{x:g}" if round(x) % labelled == 0 else "" for x in xticks], yticks,
                            ["" if y == 0 else _tick_text(y) for y in yticks],   # bars stand on 0
                            "order of the total torque", f"amplitude ({unit})")
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
