"""The star picture: each cylinder's forward and backward phasor of one order, chained tip
to tail, one small picture per engine with a scale bar instead of axes."""

import math
import textwrap
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from .figure import CELL_IN, cells, engine_results, grid_figure, grid_size, quantity, short
from .labels import label_arrows

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = ["STAR_TITLE_CHARS", "star", "star_chains"]


def star_chains(result, order, of="force"):
    """For :func:`star`: each part ("forward", "backward") of order ``order`` as a list of
    (label, tail, head) arrows per cylinder, chained tip to tail (complex: real along the
    reference axis); the last head is the engine's resultant. ``of="force"``: each cylinder's
    force, in units of m_rec·r·ω²·n; ``of="moment"``: its share of the free moment,
    (z_i − z̄)·F_i, N·m. Shares below the noise floor are left out."""
    quantity(of)
    engine_results([result], order)
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
    text = (
        f"{value:,.0f}".replace(",", " ") if value >= 1e4 else "0" if value == 0 else f"{value:.4g}"
    )
    return f"{text} {unit}"


#: characters of a star picture's title in a line: what 9-point text fits a cell's width
STAR_TITLE_CHARS = 44


def star(
    results: "Iterable[EngineResult]",
    order: int = 2,
    fig: "Figure | None" = None,
    of: str = "force",
) -> "Figure":
    """Each cylinder's forward (blue) and backward (red) phasor of ``order`` at θ = 0, chained
    tip to tail and labelled by cylinder; the dashed line is the engine's resultant. One small
    picture per engine, with a scale bar: of its force (``of="force"``, in units of
    m_rec·r·ω²·n) or of its share of the free moment, (z_i − z̄)·F_i (``of="moment"``, N·m).

    Cylinder labels never overlap: where they would (many cylinders, or forward and backward
    chains on top of each other) the shorter arrows go unlabelled (see :func:`place_labels`)."""
    quantity(of)
    chosen = engine_results(results, order)
    columns, rows = grid_size(len(chosen))
    if fig is None:
        fig = grid_figure(len(chosen))
    # the layout first: labels are placed in the axes' final scale
    axes = cells(fig, rows, columns, len(chosen))
    # inches above the top row for the figure's two-line title, each picture's and its |Σ|
    fig.subplots_adjust(
        left=0.06, right=0.97, bottom=0.04, top=1 - 1.3 / (CELL_IN * rows), wspace=0.3, hspace=0.4
    )
    unit = "N·m" if of == "moment" else ""
    for ax, r in zip(axes, chosen, strict=True):
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
                ax.quiver(
                    tails.imag,
                    tails.real,
                    steps.imag,
                    steps.real,
                    angles="xy",
                    scale_units="xy",
                    scale=1,
                    color=colour,
                    units="inches",
                    width=0.014,
                )
            ax.plot([0, end.imag], [0, end.real], linestyle="--", color=colour, linewidth=1.4)
            # a text, not a legend: 17 legends cost more to lay out than the rest of the picture;
            # above the axes, where no chain runs
            ax.annotate(
                f"{part}: |Σ| = {_magnitude(abs(end), unit)}",
                (0, 1),
                xycoords="axes fraction",
                xytext=(0, 10 - 9 * row),
                textcoords="offset points",
                color=colour,
                fontsize=7,
                va="bottom",
            )
        ax.plot([0], [0], marker="o", color="k", markersize=3)
        if not (chains["forward"] or chains["backward"]):
            ax.text(
                0.5,
                0.4,
                f"no {'free moment' if of == 'moment' else 'force'} of order {order}",
                transform=ax.transAxes,
                ha="center",
                fontsize=8,
                color="0.4",
            )
        # two lines rather than one running into the next picture's title
        ax.set_title(
            textwrap.fill(short(r.engine.name), STAR_TITLE_CHARS), fontsize=9, y=1.0, pad=21
        )
        # no axes (their ticks cost more than the rest of the picture): a scale bar instead
        ax.axis("off")
        _scale_bar(ax, chains, unit)
        _fit(ax, chains)
        label_arrows(
            ax,
            [
                (label, tail, head, colour)
                for part, colour in parts
                for label, tail, head in chains[part]
            ],
        )
    if of == "moment":
        title = (
            f"Order {order}: each cylinder's share (z − z̄)·F of the free moment, forward "
            "(blue) and backward (red), at θ = 0, chained\ndashed: the resultant (N·m, scale "
            "bar below each); horizontal: yawing (across), vertical: pitching (along)"
        )
    else:
        title = (
            f"Order {order}: each cylinder's forward (blue) and backward (red) phasor at "
            "θ = 0, chained; dashed: the resultant\n(× m_rec·r·ω²·n, scale bar below each; "
            "horizontal across the reference axis, vertical along it)"
        )
    fig.suptitle(title, fontsize=9)
    return fig


def _fit(ax, chains):
    """Equal-scaled limits with room round the chains for their labels and the scale bar,
    filling the axes' box, fixed now so that labels can be placed in the final scale."""
    points = [0j] + [
        p for arrows in chains.values() for _, tail, head in arrows for p in (tail, head)
    ]
    xs, ys = [p.imag for p in points], [p.real for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    margin = 0.1 * span
    # the scale bar hangs 0.08 span below the chains, its figure below that
    (x0, x1), (y0, y1) = (
        (min(xs) - margin, max(xs) + margin),
        (min(ys) - 0.1 * span - margin, max(ys) + margin),
    )
    box = ax.get_position()
    fig_w, fig_h = ax.figure.get_size_inches()
    aspect = (box.height * fig_h) / (box.width * fig_w)  # height over width of the box
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


def _nice_length(span):
    """A round length (1, 2 or 5 times a power of ten) of about a quarter of ``span``."""
    if span <= 0:
        return 0.0
    power = 10.0 ** math.floor(math.log10(span / 4))
    return next(step * power for step in (5, 2, 1) if step * power <= span / 4 * 1.0001)


def _scale_bar(ax, chains, unit=""):
    points = [0j] + [
        p for arrows in chains.values() for _, tail, head in arrows for p in (tail, head)
    ]
    xs, ys = [p.imag for p in points], [p.real for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    length = _nice_length(span)
    if not length:
        return
    x0, y0 = min(xs), min(ys) - 0.08 * span
    ax.plot([x0, x0 + length], [y0, y0], color="k", linewidth=1.5)
    text = _magnitude(length, unit) if unit else f"{length:g}"
    ax.text(x0 + length / 2, y0 - 0.02 * span, text, ha="center", va="top", fontsize=7)
