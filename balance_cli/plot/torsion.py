"""Pictures of a torsional vibration analysis (:class:`~balance_cli.torsion.TorsionResult`):
the Campbell diagram, the mode shapes and the vibratory torque against speed."""

import numpy as np

from ..units import Scale

__all__ = ["campbell", "mode_shapes", "torque_speed"]


def _figure(fig, size):
    if fig is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=size, layout="constrained")
    return fig


def campbell(result, fig=None):
    """The Campbell diagram: each mode's frequency (horizontal lines) and each order's
    frequency k·n against speed (rays), the result's criticals marked (filled: major orders;
    a grey cross: one the cylinders cannot excite). Returns the Figure."""
    fig = _figure(fig, (8, 5))
    ax = fig.add_subplot()
    speeds = np.array([0.0, result.speeds_rpm.max() * 1.05])
    top = max(m.frequency_hz for m in result.modes[:2]) * 1.2
    for k in result.orders:
        ax.plot(speeds, k * speeds / 60.0, color="0.8", linewidth=0.6)
        if k * speeds[-1] / 60.0 <= top:
            ax.annotate(f"{k:g}", (speeds[-1], k * speeds[-1] / 60.0), fontsize=7)
    for m in result.modes:
        if m.frequency_hz <= top:
            ax.axhline(m.frequency_hz, color="C0", linewidth=1.0)
            ax.annotate(
                f"mode {m.number}: {m.frequency_hz:.4g} Hz",
                (0, m.frequency_hz),
                fontsize=8,
                va="bottom",
            )
    for c in result.criticals:
        f = c.order * c.speed_rpm / 60.0
        if not c.excited:
            ax.plot(c.speed_rpm, f, "x", color="0.5", markersize=5)
            continue
        ax.plot(
            c.speed_rpm,
            f,
            "o",
            color="C3",
            markerfacecolor="C3" if c.major else "none",
            markersize=5,
        )
    ax.axvspan(result.speeds_rpm.min(), result.speeds_rpm.max(), color="C2", alpha=0.07)
    ax.set(
        xlim=(0, speeds[-1]),
        ylim=(0, top),
        xlabel="Engine speed (rpm)",
        ylabel="Frequency (Hz)",
        title=f"{result.engine.name}: Campbell diagram",
    )
    return fig


def mode_shapes(result, fig=None):
    """Each mode's relative amplitude along the shaft line (the first three). Returns the
    Figure."""
    fig = _figure(fig, (8, 5))
    ax = fig.add_subplot()
    x = np.arange(len(result.nodes))
    for m in result.modes[:3]:
        ax.plot(x, m.shape, "o-", label=f"mode {m.number}, {m.frequency_hz:.4g} Hz")
    ax.axhline(0.0, color="0.5", linewidth=0.6)
    ax.set_xticks(x, result.nodes, rotation=45, ha="right", fontsize=8)
    ax.set(ylabel="Relative amplitude", title=f"{result.engine.name}: mode shapes")
    ax.legend(fontsize=8)
    return fig


def torque_speed(result, fig=None, scale=None):
    """Vibratory torque (peak of all orders together) against speed, one line per section,
    the result's excited criticals of major orders marked, and the largest peak labelled
    with its torque, speed, order (major or minor) and mode, whatever its order, in
    ``scale``'s moment unit (N·m). Returns the Figure."""
    scale = scale or Scale()
    fig = _figure(fig, (8, 5))
    ax = fig.add_subplot()
    for s, name in enumerate(result.sections):
        ax.plot(result.speeds_rpm, scale.moment(result.torque_nm[:, s]), label=name, linewidth=1.0)
    for c in result.criticals:
        if c.major and c.excited:
            ax.axvline(c.speed_rpm, color="0.6", linestyle=":", linewidth=0.8)
            ax.annotate(
                f"{c.order:g}/{c.mode}", (c.speed_rpm, ax.get_ylim()[1]), fontsize=7, va="top"
            )
    # the largest peak, whatever makes it: a minor order's can be the largest of all
    p = result.peak()
    top = scale.moment(p.torque_nm)
    label = (
        f"order {p.order:g} ({'major' if p.major else 'minor'})"
        + ("" if p.mode is None else f", mode {p.mode} ({p.critical_rpm:.0f} rpm)")
        + f":\n{top:.4g} {scale.moment_label} at {p.speed_rpm:g} rpm\n{p.section}"
    )
    ax.plot(p.speed_rpm, top, "v", color="C3", markersize=6)
    low, high = result.speeds_rpm.min(), result.speeds_rpm.max()
    # text towards the middle of the plot, so that it stays inside
    right = p.speed_rpm > (low + high) / 2
    ax.annotate(
        label,
        (p.speed_rpm, top),
        xytext=(-12 if right else 12, -4),
        textcoords="offset points",
        ha="right" if right else "left",
        va="top",
        fontsize=7,
        arrowprops={"arrowstyle": "-", "color": "C3", "linewidth": 0.6},
    )
    ax.set(
        xlabel="Engine speed (rpm)",
        ylabel=f"Vibratory torque ({scale.moment_label})",
        title=f"{result.engine.name}: vibratory torque per section",
    )
    ax.legend(fontsize=7, ncol=2)
    return fig
