"""Pictures, drawn headless (matplotlib, Agg). Each figure function takes results and draws;
none recomputes an analysis. Imported only by the commands that draw.

Kinds: ``locus`` (Tanaka's Fig. 9), ``spectrum``, ``star``, ``firing``. A new kind is a
function here and an entry in ``KINDS``.
"""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..output import write_bytes  # noqa: E402
from ..units import STANDARD_GRAVITY  # noqa: E402

__all__ = ["KINDS", "figure_locus", "figure_spectrum", "figure_star", "figure_firing", "save",
           "grid_size", "locus_points"]

#: inches per subplot cell of the star and firing grids, and dots per inch of PNGs
CELL_IN = 4.0
DPI = 100
#: values below this are drawn at this floor on the spectrum's log axis
SPECTRUM_FLOOR = 1e-6


def grid_size(count):
    """Columns and rows of a grid of ``count`` small pictures."""
    columns = min(3, count)
    return columns, math.ceil(count / columns)


def locus_points(result, order=None):
    """Per-cylinder resultant force over a revolution after an ideal crankshaft counterweight
    (none on a rotary), as x = across, y = along the reference axis (Tanaka's Fig. 9)."""
    skip = result.engine.frame == "fixed"
    points = 4 * result.shaking.force_coefficients.shape[-1]
    force = result.shaking.locus(order, skip_forward_first=skip, points=points)
    force = force / result.per_cylinder_unit_n
    return force.imag, force.real


def figure_locus(results, order=None):
    fig, ax = plt.subplots(figsize=(8, 8), dpi=DPI)
    for r in results:
        x, y = locus_points(r, order)
        ax.plot(np.append(x, x[0]), np.append(y, y[0]), label=r.engine.name, linewidth=1.6)
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
    fig.tight_layout()
    return fig


def figure_spectrum(results, units="per_cylinder"):
    """Forward and backward amplitude per order, forces and moments, log axis with a floor:
    parts below the floor (SPECTRUM_FLOOR of the largest engine's m_rec·r·ω²·n) are not drawn."""
    from matplotlib.patches import Patch

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(12, 8), dpi=DPI)
    orders = np.array([o.order for o in results[0].shaking.orders])
    n = len(results)
    width = 0.8 / (2 * n)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    largest_unit = max(r.per_cylinder_unit_n for r in results)
    force_floor = SPECTRUM_FLOOR * (1.0 if units == "per_cylinder" else
                                    largest_unit / (STANDARD_GRAVITY if units == "kgf" else 1.0))
    moment_floor = SPECTRUM_FLOOR * largest_unit
    handles = []
    for i, r in enumerate(results):
        colour = colours[i % len(colours)]
        per = r.per_cylinder_unit_n if units == "per_cylinder" else (
            STANDARD_GRAVITY if units == "kgf" else 1.0)
        forces = [(abs(o.force_forward) / per, abs(o.force_backward) / per) for o in r.shaking.orders]
        moments = [(abs(o.moment_forward), abs(o.moment_backward)) for o in r.shaking.orders]
        offset = (2 * i - n) * width + width / 2
        for ax, values, floor in ((top, forces, force_floor), (bottom, moments, moment_floor)):
            for part, shift, style in ((0, 0.0, {}), (1, width, {"alpha": 0.45, "hatch": "//"})):
                heights = np.array([v[part] for v in values])
                shown = heights > floor
                ax.bar(orders[shown] + offset + shift, heights[shown] - floor, width, bottom=floor,
                       color=colour, **style)
        handles.append(Patch(color=colour, label=r.engine.name))
    handles += [Patch(facecolor="white", edgecolor="black", label="forward (turns with the crank)"),
                Patch(facecolor="white", edgecolor="black", hatch="//", label="backward (against it)")]
    force_unit = {"per_cylinder": "× m_rec·r·ω² per cylinder", "kgf": "kgf", "N": "N"}[units]
    top.set_ylabel(f"force ({force_unit})")
    bottom.set_ylabel("free moment (N·m)")
    for ax, floor in ((top, force_floor), (bottom, moment_floor)):
        ax.set_yscale("log")
        ax.set_ylim(bottom=floor)
        ax.set_xticks(orders)
        ax.set_xlabel("order")
        ax.grid(True, axis="y", linewidth=0.3)
    if not any(abs(o.moment_forward) + abs(o.moment_backward) > moment_floor
               for r in results for o in r.shaking.orders):
        bottom.set_ylim(moment_floor, moment_floor * 10)
        bottom.text(0.5, 0.5, "no free moments above the floor", transform=bottom.transAxes,
                    ha="center", va="center", color="0.4")
    top.set_title(f"Forward and backward parts by order (parts below {SPECTRUM_FLOOR:g} of "
                  "m_rec·r·ω²·n not drawn)")
    fig.legend(handles=handles, loc="center right", fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0, 0.72, 1))
    return fig


def figure_star(stars, order):
    """``stars``: [(engine name, [(label, forward N, backward N)], unit N)] — the phasors of
    each cylinder, chained tip to tail, close on the resultant (dashed)."""
    columns, rows = grid_size(len(stars))
    fig, axes = plt.subplots(rows, columns, figsize=(CELL_IN * columns, CELL_IN * rows), dpi=DPI,
                             squeeze=False)
    for ax in axes.flat[len(stars):]:
        ax.axis("off")
    for ax, (name, shares, unit) in zip(axes.flat, stars):
        for part, colour, index in (("forward", "C0", 1), ("backward", "C3", 2)):
            tips = [0j]
            for label, *phasors in shares:
                phasor = phasors[index - 1] / unit
                if abs(phasor) < 1e-12:
                    continue
                start, end = tips[-1], tips[-1] + phasor
                ax.annotate("", xy=(end.imag, end.real), xytext=(start.imag, start.real),
                            arrowprops={"arrowstyle": "->", "color": colour, "linewidth": 1.1})
                middle = start + phasor / 2
                ax.text(middle.imag, middle.real, label, fontsize=7, color=colour)
                tips.append(end)
            tips = np.array(tips)
            ax.plot(tips.imag, tips.real, linewidth=0, marker=".", markersize=2, color=colour)
            ax.plot([0, tips[-1].imag], [0, tips[-1].real], linestyle="--", color=colour,
                    linewidth=1.4, label=f"{part}: |Σ| = {abs(tips[-1]):.4f}")
        ax.plot([0], [0], marker="o", color="k", markersize=3)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("across (× m_rec·r·ω²·n)", fontsize=8)
        ax.set_ylabel("along (× m_rec·r·ω²·n)", fontsize=8)
        ax.legend(fontsize=7, loc="best")
        ax.grid(True, linewidth=0.3)
    fig.suptitle(f"Order {order}: each cylinder's forward (blue) and backward (red) phasor at "
                 "θ = 0, chained; dashed: the resultant")
    fig.tight_layout()
    return fig


def figure_firing(results):
    """Firing angles on a dial of one working cycle (720° or 360°), intervals marked."""
    columns, rows = grid_size(len(results))
    fig, axes = plt.subplots(rows, columns, figsize=(CELL_IN * columns, CELL_IN * rows), dpi=DPI,
                             squeeze=False, subplot_kw={"projection": "polar"})
    for ax in axes.flat[len(results):]:
        ax.axis("off")
    for ax, r in zip(axes.flat, results):
        cycle = 180.0 * r.engine.cycle
        firing = r.firing
        ax.set_theta_zero_location("N")
        ax.set_theta_direction(-1)
        angles = [2 * math.pi * a / cycle for a in firing.angles_deg]
        for angle, number in zip(angles, firing.order):
            ax.plot([angle, angle], [0, 1], color="C0", linewidth=1.2)
            ax.text(angle, 1.12, str(number), ha="center", va="center", fontsize=8)
        for a, b, gap in zip(firing.angles_deg, list(firing.angles_deg[1:]) + [cycle], firing.intervals_deg):
            middle = 2 * math.pi * (a + gap / 2) / cycle
            ax.text(middle, 0.65, f"{gap:.4g}°", ha="center", va="center", fontsize=6, color="C3")
        ax.set_ylim(0, 1.25)
        ax.set_yticks([])
        ticks = np.arange(0, cycle, 90.0)
        ax.set_xticks(2 * np.pi * ticks / cycle)
        ax.set_xticklabels([f"{t:g}°" for t in ticks], fontsize=7)
        uniform = "uniform" if firing.uniform else f"±{firing.max_deviation_deg:.2f}° from uniform"
        ax.set_title(f"{r.engine.name}\n{r.engine.cycle}-stroke, {uniform}", fontsize=9)
    fig.suptitle("Firing angles over one working cycle (crank degrees from the first firing)")
    fig.tight_layout()
    return fig


def save(fig, path):
    """Write ``fig`` to ``path`` (PNG, or SVG when the name ends in .svg) atomically, and close it."""
    fmt = "svg" if str(path).lower().endswith(".svg") else "png"
    try:
        write_bytes(path, lambda handle: fig.savefig(handle, format=fmt, dpi=DPI))
    finally:
        plt.close(fig)


KINDS = ("locus", "spectrum", "star", "firing")
