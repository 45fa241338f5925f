"""The torque picture: each engine's inertia, gas and total torque over one cycle and the
orders of the total, drawn as framed panels straight on the figure (an Axes per panel costs
more than the rest of the picture)."""

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import matplotlib
import numpy as np
from matplotlib.artist import Artist

from ..checks import items
from ..errors import PlotError
from ..units import UNIT_SYSTEMS, Scale
from .figure import CELL_IN, MIN_WIDTH_IN, grid_size, new_figure, short

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.torque import TorqueResult

__all__ = ["TORQUE_UNITS", "TORQUE_STYLES", "torque", "torque_data"]

#: units of :func:`torque`: the moment unit of a system of units (N·m, kN·m, ..., lbf·ft)
TORQUE_UNITS = tuple(UNIT_SYSTEMS)


def torque_data(result: "TorqueResult", units: str = "N") -> dict:
    """What :func:`torque` draws of one engine's :class:`~balance_cli.analysis.torque.TorqueResult`.

    Returns ``theta_deg`` (the crank angle of throw 1 over one period, the first angle repeated
    at the end to close the curve), ``inertia``, ``gas`` (None without one) and ``total`` at
    those angles, ``mean`` and ``range`` of the total torque, and its ``orders`` (multiples of ½
    for a four-stroke) with their ``amplitudes`` √(cos² + sin²); torques in the moment unit of
    ``units`` (N·m for "N", kN·m, MN·m, kgf·m, lbf·ft). Also ``name``, ``period_deg``,
    ``cycle``, ``speed_rpm``, ``unit``.
    """
    from ..units import rad_s_to_rpm

    if units not in TORQUE_UNITS:
        raise PlotError(f"must be one of {', '.join(TORQUE_UNITS)}, got {units!r}", "units")
    scale = Scale.of(True, units)

    def closed(series):
        return None if series is None else scale.moment(np.append(series.curve, series.curve[0]))

    total = result.total
    return {
        "name": short(result.engine.name),
        "cycle": result.engine.cycle,
        "speed_rpm": rad_s_to_rpm(result.engine.speed_rad_s),
        "period_deg": result.period_deg,
        "theta_deg": np.append(total.theta_deg, result.period_deg),
        "inertia": closed(result.inertia),
        "gas": closed(result.gas),
        "total": closed(total),
        "mean": scale.moment(total.mean),
        "range": scale.moment(total.range),
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
    return limits, [
        0.0 if abs(t) <= slack else float(t)
        for t in ticks
        if limits[0] - slack <= t <= limits[1] + slack
    ]


class _Labels(Artist):
    """Short one-line labels in one artist, at points in figure fractions, each aligned as a
    Text's box would be (``ha`` left, center or right; ``va`` top, center or bottom; rotation
    0 or 90°). Hundreds of Text artists, each laying itself out, take longer to draw than the
    rest of a picture, as hundreds of separate rectangles do (:func:`_bars`)."""

    def __init__(self, fig, fontsize=7):
        super().__init__()
        self.set_transform(fig.transSubfigure)
        self.set_zorder(3)  # as Text: above lines and frames
        self.fontsize = fontsize
        self.colour = matplotlib.rcParams["text.color"]
        self.items = []  # (x, y, text, ha, va, rotation)

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

        _, line_h, line_d = size("lp")  # a line's height and descent, as Text takes them
        _, canvas_h = renderer.get_canvas_width_height()
        gc = renderer.new_gc()
        gc.set_foreground(self.colour)
        points = self.get_transform().transform([item[:2] for item in self.items])
        for (x, y), (_, _, text, ha, va, rotation) in zip(points, self.items, strict=True):
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
        x, y = self.at(x_in, y_in)
        self.labels.add(x, y, text, **alignment)

    def panel(
        self, box_in, xlim, ylim, xticks, xlabels, yticks, ylabels, xlabel, ylabel, xminor=()
    ):
        """A panel (``box_in``: left, bottom, width, height, inches) showing ``xlim`` × ``ylim``,
        with grid lines at the ticks, their labels (none where a label is empty) and axis
        labels, and short tick marks below at ``xminor``; returns the transform from its data
        to the figure."""
        from matplotlib.transforms import Bbox, BboxTransform

        left, bottom, width, height = box_in
        (x0, y0), (x1, y1) = self.at(left, bottom), self.at(left + width, bottom + height)
        to_panel = BboxTransform(
            Bbox([[xlim[0], ylim[0]], [xlim[1], ylim[1]]]), Bbox([[x0, y0], [x1, y1]])
        )
        for x, label in zip(xticks, xlabels, strict=True):
            fx = x0 + (x1 - x0) * (x - xlim[0]) / (xlim[1] - xlim[0])
            self.grid.append([(fx, y0), (fx, y1)])
            if label:
                self.label(fx * self.size[0], bottom - 0.04, label, ha="center", va="top")
        for y, label in zip(yticks, ylabels, strict=True):
            fy = y0 + (y1 - y0) * (y - ylim[0]) / (ylim[1] - ylim[0])
            self.grid.append([(x0, fy), (x1, fy)])
            if label:
                self.label(left - 0.04, fy * self.size[1], label, ha="right", va="center")
        self.frames.append([(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)])
        # ticks in the frame's path: inward from the bottom edge, long at labels
        for x, length in [(x, 0.06) for x, label in zip(xticks, xlabels, strict=True) if label] + [
            (x, 0.03) for x in xminor
        ]:
            fx = x0 + (x1 - x0) * (x - xlim[0]) / (xlim[1] - xlim[0])
            self.frames.append([(fx, y0), (fx, y0 + length / self.size[1])])
        self.label(left + width / 2, bottom - 0.19, xlabel, ha="center", va="top")
        self.label(left - 0.52, bottom + height / 2, ylabel, ha="left", va="center", rotation=90)
        return to_panel + self.fig.transSubfigure

    def finish(self):
        """Draw the grid lines and frames, each as one path (a collection's many paths take
        longer to write)."""
        from matplotlib.patches import PathPatch

        for lines, style in (
            (self.grid, {"edgecolor": "0.85", "linewidth": 0.5, "zorder": 0.5}),
            (self.frames, {"edgecolor": "0.3", "linewidth": 0.6, "zorder": 2.5}),
        ):
            self.fig.add_artist(PathPatch(_compound(lines), fill=False, **style))
        self.fig.add_artist(self.labels)


def _compound(polylines, closed=False):
    """One path of many polylines (closed polygons when ``closed``)."""
    from matplotlib.path import Path as Shape

    vertices, codes = [], []
    for points in polylines:
        vertices += list(points) + ([points[0]] if closed else [])
        codes += (
            [Shape.MOVETO]
            + [Shape.LINETO] * (len(points) - 1)
            + ([Shape.CLOSEPOLY] if closed else [])
        )
    return Shape(vertices, codes)


def torque(
    results: "Iterable[TorqueResult]", units: str = "N", fig: "Figure | None" = None
) -> "Figure":
    """Torques of :func:`balance_cli.analysis.torque.torque`, one small picture per engine:
    above, the inertia, gas (when there is one) and total torque over one period (360°, or 720°
    for a four-stroke) against the crank angle of throw 1, and the mean total torque (dashed);
    below, the amplitude of each order of the total torque (half orders too for a four-stroke).
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
        fig = new_figure((max(CELL_IN * columns, MIN_WIDTH_IN), CELL_IN * rows + _HEADER_IN))
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
        panels.text(
            x0 + cell_w / 2,
            top - 0.03,
            f"{data['name']}\n{data['cycle']}-stroke, "
            f"{data['speed_rpm']:g} rpm{'' if data['gas'] is not None else ', no gas'}: "
            f"mean {data['mean']:.4g} {unit}, ΔC {data['range']:.4g} {unit}",
            fontsize=8,
            ha="center",
            va="top",
        )
        period = data["period_deg"]
        names = [n for n in ("inertia", "gas", "total") if data[n] is not None]
        ylim, yticks = _span(
            min(data[n].min() for n in names), max(data[n].max() for n in names), 3
        )
        xticks = np.arange(5) * period / 4  # labelled at 0, half and the whole period
        curves = panels.panel(
            (x0 + left, top - title - curve_h, cell_w - left - right, curve_h),
            (0.0, period),
            ylim,
            xticks,
            [f"{x:g}°" if i % 2 == 0 else "" for i, x in enumerate(xticks)],
            yticks,
            [_tick_text(y) for y in yticks],
            "crank angle of throw 1",
            f"torque ({unit})",
        )
        for name in names:
            fig.add_artist(
                Line2D(
                    data["theta_deg"],
                    data[name],
                    transform=curves,
                    label=name,
                    **TORQUE_STYLES[name],
                )
            )
        fig.add_artist(
            Line2D(
                [0.0, period],
                [data["mean"]] * 2,
                transform=curves,
                label="mean total",
                **TORQUE_STYLES["mean total"],
            )
        )
        orders, heights = data["orders"], data["amplitudes"]
        step, highest = orders[0], orders[-1]  # step: ½ for a four-stroke, 1 for a two-stroke
        ylim, yticks = _span(0.0, float(heights.max()), 2, floor=0.0)
        if not heights.any():
            yticks = []
        # whole orders labelled, with a grid line, a round step apart (at most 10 labels);
        # the others, and a four-stroke's half orders, get a short tick only
        every = next(n * 10**p for p in range(6) for n in (1, 2, 5) if highest / (n * 10**p) <= 10)
        xticks = np.arange(every, highest + 0.5 * every, every)
        minor = [x for x in np.arange(step, highest + 0.5 * step, step) if x % every]
        bars = panels.panel(
            (x0 + left, top - cell_h + foot, cell_w - left - right, order_h),
            (0.0, highest + step),
            ylim,
            xticks,
            [f"{x:g}" for x in xticks],
            yticks,
            ["" if y == 0 else _tick_text(y) for y in yticks],  # bars stand on 0
            "order of the total torque",
            f"amplitude ({unit})",
            xminor=minor,
        )
        width = 0.7 * step
        corners = [
            [(k - width / 2, 0.0), (k + width / 2, 0.0), (k + width / 2, h), (k - width / 2, h)]
            for k, h in zip(orders, heights, strict=True)
            if h > 0
        ]
        if corners:
            fig.add_artist(
                PathPatch(
                    _compound(corners, closed=True),
                    facecolor="0.35",
                    linewidth=0,
                    transform=bars,
                    label="orders",
                )
            )
        else:
            panels.label(
                x0 + left + (cell_w - left - right) / 2,
                top - cell_h + foot + order_h / 2,
                f"no order up to {highest:g}",
            )
    panels.finish()
    shown = [n for n in TORQUE_STYLES if n != "gas" or any(e["gas"] is not None for e in engines)]
    fig.legend(
        handles=[Line2D([], [], label=n, **TORQUE_STYLES[n]) for n in shown],
        loc="upper center",
        bbox_to_anchor=panels.at(width_in / 2, height_in - 0.36),
        ncol=len(shown),
        fontsize=8,
        frameon=False,
    )
    fig.suptitle(
        "Torque at constant speed over one cycle, and the amplitude of each order of "
        "the total torque",
        fontsize=10,
        y=1 - 0.08 / height_in,
    )
    return fig
