"""balance's vibratory torque of the Mendes et al. (2008) six-cylinder beside the measurements
openTorsion ships (Fig. 31: flywheel–6th cylinder; Fig. 32: pulley–gear train)."""

from pathlib import Path

import numpy as np

import balance_cli as balance
from balance_cli.analysis.pressure import PressureCurve
from balance_cli.torsion import torsional_vibration as torsion

HERE = Path(__file__).resolve().parent
BORE_M = 0.105
#: the sections of the figures, as balance names them
FIG31, FIG32 = "throw 6–flywheel", "pulley–gear train"


def measured(figure):
    """(speeds rpm, vibratory torque N·m) digitised from the paper's Fig. 31 or 32."""
    data = np.genfromtxt(
        HERE / f"torsional_vibration_data_fig{figure}.csv", delimiter=",", skip_header=1
    )
    return data[:, 0], data[:, 1]


def pressure_at(speed_rpm):
    """The example's cylinder pressure: its curve (MPa, firing TDC at 360°, peak 15.2 MPa)
    scaled to the peak pressure measured at ``speed_rpm``; absolute, Pa."""
    curve = np.genfromtxt(HERE / "pressure_data.csv", delimiter=";")
    peaks = np.genfromtxt(HERE / "peak_data.csv", delimiter=";")
    peak = np.interp(speed_rpm, peaks[:, 0], peaks[:, 1])
    angles = (curve[:-1, 0] - 360.0) % 720.0  # from the firing TDC; 720 repeats 0
    order = np.argsort(angles)
    pressure = curve[:-1, 1][order] / 15.2 * peak * 1e6
    return PressureCurve(angles[order], pressure, 720.0, "pressure_data.csv")


def response(speeds_rpm, max_order=12):
    """balance's vibratory torque (synthesised peak, and the sum of the orders' amplitudes as
    the example reports it) in the two sections, and the natural frequencies, Hz."""
    engine = balance.load(HERE / "mendes2008.toml")
    peak = {FIG31: [], FIG32: []}
    summed = {FIG31: [], FIG32: []}
    result = None
    for speed in speeds_rpm:
        # the pressure changes with speed: one analysis per speed
        result = torsion(engine, [speed], max_order, pressure=pressure_at(speed), bore_m=BORE_M)
        for name in peak:
            s = result.sections.index(name)
            peak[name].append(result.torque_nm[0, s])
            summed[name].append(result.order_torque_nm[0, s].sum())
    frequencies = [m.frequency_hz for m in result.modes]
    return (
        {k: np.array(v) for k, v in peak.items()},
        {k: np.array(v) for k, v in summed.items()},
        frequencies,
    )


def draw(path):
    """The comparison as a picture: balance's torque (orders summed, and the synthesised
    waveform's peak) beside the measurements of Fig. 31 and 32."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    speeds = np.arange(1000.0, 2551.0, 10.0)
    peak, summed, frequencies = response(speeds)
    fig = Figure(figsize=(10, 4.2), layout="constrained")
    for ax, figure, name in zip(fig.subplots(1, 2), (31, 32), (FIG31, FIG32), strict=True):
        x, y = measured(figure)
        ax.plot(x, y, "k.", markersize=4, label=f"measured (Fig. {figure})")
        ax.plot(speeds, summed[name], "C3", label="balance + openTorsion, orders summed")
        ax.plot(speeds, peak[name], "C0--", linewidth=1.0, label="the same, waveform peak")
        ax.set(
            title=f"{name} (Fig. {figure})",
            xlabel="Engine speed (rpm)",
            ylabel="Vibratory torque (N·m)",
        )
        ax.legend(fontsize=8)
    fig.suptitle(
        "Mendes et al. (2008): first mode "
        f"{frequencies[0]:.1f} Hz, its 6th order at {frequencies[0] * 10:.0f} rpm",
        fontsize=10,
    )
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    import sys

    draw(sys.argv[1] if len(sys.argv) > 1 else "docs/torsion-mendes2008.png")
