"""Pictures of the engine on its mounts (:class:`~balance_cli.mounting.MountResult`): its
mode shapes, the kinetic-energy distribution of each mode, and the force each mount passes on
against speed with the resonances crossed."""

import numpy as np

from ..checks import instance
from ..errors import PlotError
from ..model import DOF_LABELS, MOTIONS
from .figure import colours, grid_size, new_figure, short

__all__ = ["mount_modes", "energy_bars", "mount_forces", "equivalent_box"]

#: the largest displacement a mode is drawn with, as a fraction of the box's largest half-side
_MODE_SCALE = 0.25
#: the box's edges, as pairs of its corners (numbered by the bits of x, y, z)
_EDGES = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]


def _result(result):
    from ..mounting import MountResult

    return instance(result, MountResult, "result", PlotError, " (balance.mounts gives one)")


def equivalent_box(system) -> np.ndarray:
    """The half-sides (x, y, z) of the uniform box with the system's mass and the diagonal of
    its inertia tensor, m: J_xx = m·(b² + c²)/3, ..., so a² = 3·(J_yy + J_zz − J_xx)/(2·m)."""
    j = np.diag(np.array(system.inertia_kgm2))
    squares = 3.0 * (j.sum() - 2.0 * j) / (2.0 * system.mass_kg)
    return np.sqrt(np.clip(squares, 0.0, None))


def _corners(half):
    return np.array(
        [[(1 if i & b else -1) * h for b, h in zip((1, 2, 4), half, strict=True)] for i in range(8)]
    )


def _moved(points, shape):
    """Points (n, 3) moved by the rigid-body displacement ``shape`` (X, θ): X + θ × r."""
    return points + shape[:3] + np.cross(shape[3:], points)


def _box(ax, corners, **style):
    for a, b in _EDGES:
        ax.plot(*zip(corners[a], corners[b], strict=True), **style)


def mount_modes(result, fig=None):
    """Each mode's shape: the engine as its equivalent box (the uniform box of its mass and
    moments of inertia) at rest (grey, dotted) and moved in the mode (coloured, the largest
    displacement a quarter of the box's largest half-side), its mounts (triangles, moved with
    it), its centre of gravity (the origin) and the crank axis (dashed), in engine axes.
    Returns the Figure."""
    r = _result(result)
    system = r.system
    half = equivalent_box(system)
    corners = _corners(half)
    mounts = np.array([m.position_m for m in system.mounts])
    # room for the box, the mounts and a quarter of the box's size of motion
    reach = (1.0 + _MODE_SCALE) * max(float(half.max()), float(np.abs(mounts).max()))
    crank = np.array([[-reach, 0.0, 0.0], [reach, 0.0, 0.0]]) - np.array(system.cg_m)
    fig = fig or new_figure((12.0, 7.5))
    columns, rows = grid_size(len(r.modes))
    for i, mode in enumerate(r.modes):
        ax = fig.add_subplot(rows, columns, i + 1, projection="3d")
        points = np.vstack([corners, mounts])
        moved = np.array([_moved(p[None], mode.shape)[0] - p for p in points])
        size = float(np.linalg.norm(moved, axis=1).max()) or 1.0
        shape = mode.shape * (_MODE_SCALE * float(half.max()) / size)
        _box(ax, corners, color="0.45", linewidth=0.7, linestyle=":")
        _box(ax, _moved(corners, shape), color="C0", linewidth=1.4)
        ax.plot(*crank.T, color="0.5", linestyle="--", linewidth=0.8)
        at = _moved(mounts, shape)
        ax.scatter(*at.T, marker="^", color="C3", s=30, depthshade=False)
        for name, p in zip(r.names, at, strict=True):
            ax.text(*p, f" {name}", fontsize=6, color="C3")
        ax.scatter([0.0], [0.0], [0.0], color="k", s=8)
        ax.set(xlabel="x (m)", ylabel="y (m)", zlabel="z (m)", xlim=(-reach, reach))
        ax.set(ylim=(-reach, reach), zlim=(-reach, reach))
        ax.set_box_aspect((1, 1, 1))
        # no panes and no grid: the boxes are the picture
        ax.grid(False)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.pane.fill = False
        ax.tick_params(labelsize=6)
        ax.set_title(
            f"mode {mode.number}: {mode.frequency_hz:.3g} Hz\n{mode.motion} "
            f"({mode.purity_pct:.0f} % of its energy)",
            fontsize=9,
        )
    fig.suptitle(f"{short(r.engine.name)}: rigid-body modes on the mounts")
    # room between the rows for a panel's axis label and the title below it
    fig.subplots_adjust(hspace=0.3, top=0.9, bottom=0.04)
    return fig


def energy_bars(result, fig=None):
    """The kinetic-energy distribution of each mode as stacked bars, one colour per motion
    (the decoupling table as a picture). Returns the Figure."""
    r = _result(result)
    fig = fig or new_figure((9.0, 4.5))
    ax = fig.add_subplot()
    left = np.zeros(len(r.modes))
    labels = [f"{m.number}: {m.frequency_hz:.3g} Hz" for m in r.modes]
    for j, colour in enumerate(colours(6)):
        share = np.clip([m.energy_pct[j] for m in r.modes], 0.0, None)
        ax.barh(labels, share, left=left, color=colour, label=f"{MOTIONS[j]} ({DOF_LABELS[j]})")
        left += share
    ax.invert_yaxis()
    ax.set(xlim=(0, 100), xlabel="Share of the mode's kinetic energy (%)", ylabel="Mode")
    ax.set_title(f"{short(r.engine.name)}: kinetic-energy distribution")
    ax.legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.18))
    fig.subplots_adjust(bottom=0.3)
    return fig


def mount_forces(result, fig=None):
    """The force each mount passes on to the frame against speed (every order summed over a
    cycle: each component's peak and the vector's largest size), one panel per mount, on a
    logarithmic scale; the resonances crossed that an order drives marked "order/mode".
    Returns the Figure."""
    r = _result(result)
    count = len(r.names)
    columns, rows = grid_size(count)
    fig = fig or new_figure((4.5 * columns, 3.4 * rows + 0.6))
    speeds = r.speeds_rpm
    peaks, sizes = r.response.force_peak_n, r.response.force_magnitude_peak_n
    floor = 1e-9 * float(sizes.max()) if sizes.size and sizes.max() > 0 else 1e-12
    driven = [c for c in r.crossings if c.excited]
    for m, name in enumerate(r.names):
        ax = fig.add_subplot(rows, columns, m + 1)
        for c, label in enumerate(("Fx", "Fy", "Fz")):
            ax.plot(speeds, np.maximum(peaks[:, m, c], floor), linewidth=0.9, label=label)
        ax.plot(speeds, np.maximum(sizes[:, m], floor), color="k", linewidth=1.2, label="|F|")
        ax.set_yscale("log")
        low = max(floor, float(sizes[:, m].max()) * 1e-4)
        ax.set_ylim(bottom=low)
        # a label only where it clears the one before (4 % of the speeds apart): close
        # resonances share a line's label
        span = float(speeds.max() - speeds.min()) or 1.0
        last = -np.inf
        for c in driven:
            ax.axvline(c.speed_rpm, color="0.6", linestyle=":", linewidth=0.7)
            if c.speed_rpm - last < 0.04 * span:
                continue
            last = c.speed_rpm
            ax.annotate(
                f"{c.order:g}/{c.mode}",
                (c.speed_rpm, 1.0),
                xycoords=("data", "axes fraction"),
                fontsize=6,
                rotation=90,
                va="bottom",
                ha="center",
            )
        ax.set(xlabel="Engine speed (rpm)", ylabel="Force on the frame (N)", title=f"mount {name}")
        ax.legend(fontsize=6, loc="lower right")
    fig.suptitle(f"{short(r.engine.name)}: force passed on by each mount (resonances: order/mode)")
    fig.tight_layout()
    return fig
