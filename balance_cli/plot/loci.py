"""The locus picture: the resultant shaking force (per cylinder, or in a system of units), or
the free moment, over one revolution (Tanaka's Fig. 9), every engine on one set of
equal-scaled axes; curves that coincide are told apart by their dashes and their legend."""

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, cast

import numpy as np

from .figure import colours, engine_results, new_figure, picture_scale, quantity, short

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = ["COINCIDE", "locus", "locus_points", "coinciding"]

#: two loci coincide where each lies within this fraction of the larger one's largest distance
#: from the origin from the other: equal engines' loci do, and even loci that fill the picture
#: are then closer than a quarter of a line's width (1.6 pt on 6.7-inch axes), one hiding the
#: other
COINCIDE = 1e-3
#: points of each locus the coincidence test compares
_COMPARED = 512
#: points of a dash of a coinciding curve
_DASH_PT = 5.0


def locus_points(result, order=None, of="force", counterweight=True, units="per-cylinder"):
    """What :func:`locus` draws of one engine, as x = across, y = along the reference axis:
    ``of="force"`` the resultant force, ``of="moment"`` the free moment about the engine's
    mid-length (z̄), over a revolution; all orders, or ``order`` only. ``units``:
    "per-cylinder" (forces × m_rec·r·ω² per cylinder, Tanaka's Fig. 9; moments N·m) or a
    system of units (:data:`~balance_cli.units.UNIT_SYSTEMS`: "N" for N and N·m, "kN",
    "MN", "kgf", "lbf"). With ``counterweight`` (the default) an ideal crankshaft
    counterweight has taken the forward first order away, in two planes for the moment (none
    on a rotary, whose crank does not turn). A locus below the noise floor all round is exact
    zeros."""
    quantity(of)
    scale = picture_scale(units)
    forward, backward = result.counterweight_cancels if counterweight else (False, False)
    engine = result.engine
    if of == "force":
        values = result.shaking.locus(order, forward, skip_backward_first=backward)
        floor = engine.noise_floor_n
    else:
        values = result.shaking.moment_locus(order, forward, skip_backward_first=backward)
        floor = engine.noise_floor_nm
    if np.abs(values).max() < floor:
        values = np.zeros_like(values)
    if of == "force":
        values = scale.force(values, result.per_cylinder_unit_n)
    else:
        values = scale.moment(values)
    return values.imag, values.real


def _distances(points, curve):
    """The distance of each of ``points`` (complex) from the closed polyline ``curve``."""
    a = curve[:, None]
    d = np.roll(curve, -1)[:, None] - a
    length2 = np.abs(d) ** 2
    # the foot of each point on each segment, clipped to the segment
    t = np.clip(
        np.divide(
            ((points[None, :] - a) * d.conj()).real,
            length2,
            out=np.zeros((len(curve), len(points))),
            where=length2 > 0,
        ),
        0.0,
        1.0,
    )
    return np.abs(points[None, :] - (a + t * d)).min(axis=0)


def coinciding(points, tolerance=COINCIDE):
    """For loci ``points`` (each (x, y), as :func:`locus_points` gives them): the index of the
    first earlier locus each one coincides with, or None. Two loci coincide where each point
    of either lies within ``tolerance`` of the larger one's largest distance from the origin
    from the other curve (whatever crank angle it is reached at); a locus that is all zeros
    coincides with nothing (its legend says it has nothing)."""
    curves = [np.asarray(x) * 1j + np.asarray(y) for x, y in points]
    # at most _COMPARED points a curve (a locus has 4 × samples, up to 262 144): a chord between
    # them strays from a smooth curve by about (2π/512)²/8 = 2e-5 of its radius, far below the
    # tolerance, and the distances of 512 × 512 points take 4 MB
    thin = [c[:: max(1, math.ceil(len(c) / _COMPARED))] for c in curves]
    # bounding box and largest radius: two curves differ in each by no more than their
    # distance, so that those apart in any are apart without the full test
    boxes = [
        np.array([c.real.min(), c.real.max(), c.imag.min(), c.imag.max(), np.abs(c).max()])
        for c in curves
    ]
    found: list[int | None] = []
    for j in range(len(curves)):
        match = None
        for i in range(j):
            gap = tolerance * max(boxes[i][4], boxes[j][4])
            if (
                found[i] is None
                and boxes[i][4] > 0
                and boxes[j][4] > 0
                and np.abs(boxes[i] - boxes[j]).max() <= gap
                and _distances(thin[j], thin[i]).max() <= gap
                and _distances(thin[i], thin[j]).max() <= gap
            ):
                match = i
                break
        found.append(match)
    return found


def _line_styles(same):
    """Matplotlib line styles of the loci whose coincidences are ``same`` (see
    :func:`coinciding`): solid for a curve that coincides with no earlier one; in a group of g
    coinciding curves, the k-th after the first dashed in the k-th of g slots of a pattern
    g dashes long, so that every curve of the group shows in turn (the first in slot 0)."""
    groups: dict[int, list[int]] = {}
    for j, first in enumerate(same):
        if first is not None:
            groups.setdefault(first, []).append(j)
    styles: list = ["-"] * len(same)
    for members in groups.values():
        g = len(members) + 1
        for k, j in enumerate(members, 1):
            # the dash pattern starts (g − k) dashes in: its dash covers slot k
            styles[j] = ((g - k) * _DASH_PT, (_DASH_PT, (g - 1) * _DASH_PT))
    return styles


def _legend_rows(names):
    """Columns and rows of a legend of ``names`` below a picture 8 in wide."""
    columns = 1 if len(names) <= 3 or max(len(n) for n in names) > 48 else 2
    return columns, math.ceil(len(names) / columns)


def locus(
    results: "Iterable[EngineResult]",
    order: int | None = None,
    ax: "Axes | None" = None,
    of: str = "force",
    units: str = "per-cylinder",
) -> "Figure":
    """Locus over one revolution of the resultant shaking force (``of="force"``, Tanaka's
    Fig. 9) or of the free moment (``of="moment"``), every engine on one set of equal-scaled
    axes; ``order`` draws one order only; ``units`` "per-cylinder" (forces per cylinder,
    moments N·m) or a system of units. See :func:`locus_points`.

    A locus that coincides with an earlier one (see :func:`coinciding`) is drawn dashed over
    it, the dashes of each such curve falling in the gaps of the others', and its legend
    names the engine it coincides with. In a figure of its own the legend goes below the
    axes, in as many rows as the engines need; drawn into ``ax``, the legend is the axes'."""
    quantity(of)
    scale = picture_scale(units)
    chosen = engine_results(results, order)
    points = [locus_points(r, order, of, units=units) for r in chosen]
    same = coinciding(points)
    # an engine with nothing left is a dot at the origin, hidden under the others; a curve
    # over another one says so
    names = [
        short(r.engine.name)
        + ("" if x.any() or y.any() else f" (no free {of})")
        + ("" if first is None else f" (coincides with {short(chosen[first].engine.name, 40)})")
        for r, (x, y), first in zip(chosen, points, same, strict=True)
    ]
    styles = _line_styles(same)
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
    for (x, y), name, colour, style in zip(
        points, names, colours(len(chosen)), styles, strict=True
    ):
        ax.plot(
            np.append(x, x[0]),
            np.append(y, y[0]),
            label=name,
            linewidth=1.6,
            color=colour,
            linestyle=style,
        )
    ax.axhline(0, color="0.6", linewidth=0.6)
    ax.axvline(0, color="0.6", linewidth=0.6)
    ax.set_aspect("equal", adjustable="datalim")
    what = f"order {order}" if order else "all orders"
    rotary = "none on a rotary"
    if of == "force":
        per = "" if scale.absolute else " per cylinder"
        title = f"Locus of the resultant shaking force{per} ({what})"
        counterweight = f"after an ideal crankshaft counterweight ({rotary})"
        unit = scale.force_unit_text
        ax.set_xlabel(f"across the reference axis ({unit})")
        ax.set_ylabel(f"along the reference axis ({unit})")
    else:
        ml = scale.moment_label
        title = f"Locus of the free moment about the engine's mid-length, {ml} ({what})"
        counterweight = f"after an ideal two-plane crankshaft counterweight ({rotary})"
        ax.set_xlabel(f"moment of the forces across the reference axis (yawing), {ml}")
        ax.set_ylabel(f"moment of the forces along the reference axis (pitching), {ml}")
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
