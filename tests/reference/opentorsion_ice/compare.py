"""balance's vibratory torque of the Mendes et al. (2008) six-cylinder beside the measurements
openTorsion ships (Fig. 31: flywheel–6th cylinder; Fig. 32: pulley–gear train)."""

from pathlib import Path

import numpy as np

import balance_cli as balance
from balance_cli.gas import PressureCurve
from balance_cli.torsion import torsion

HERE = Path(__file__).resolve().parent
BORE_M = 0.105
#: the sections of the figures, as balance names them
FIG31, FIG32 = "throw 6–flywheel", "pulley–gear train"


def measured(figure):
    """(speeds rpm, vibratory torque N·m) digitised from the paper's Fig. 31 or 32."""
    data = np.genfromtxt(HERE / f"torsional_vibration_data_fig{figure}.csv", delimiter=",",
                         skip_header=1)
    return data[:, 0], data[:, 1]


def pressure_at(speed_rpm):
    """The example's cylinder pressure: its curve (MPa, firing TDC at 360°, peak 15.2 MPa)
    scaled to the peak pressure measured at ``speed_rpm``; absolute, Pa."""
    curve = np.genfromtxt(HERE / "pressure_data.csv", delimiter=";")
    peaks = np.genfromtxt(HERE / "peak_data.csv", delimiter=";")
    peak = np.interp(speed_rpm, peaks[:, 0], peaks[:, 1])
    angles = (curve[:-1, 0] - 360.0) % 720.0   # from the firing TDC; 720 repeats 0
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
    return ({k: np.array(v) for k, v in peak.items()},
            {k: np.array(v) for k, v in summed.items()}, frequencies)
