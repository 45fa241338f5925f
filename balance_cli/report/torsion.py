"""``balance torsion`` as text, Markdown and CSV (its pictures are
:mod:`balance_cli.plot.torsion`'s)."""

import csv
import io

import numpy as np

from ..units import Scale, significant
from .display import figure, markdown_text, plain_text
from .table import render

__all__ = ["torsion_tables", "torsion_csv"]

#: phase-vector sums below this are shown as 0 (rounding of a sum that cancels)
_ZERO_SUM = 1e-9


def _sum_text(value):
    return "0" if value < _ZERO_SUM else significant(value, 3)


def torsion_tables(results, fmt, scale=None):
    """Modes, phase-vector sums, criticals in the speed range and the largest vibratory
    torque per section, engine by engine; torques in ``scale``'s moment unit (N·m)."""
    scale = scale or Scale()
    heading = "#### " if fmt == "markdown" else ""
    safe = markdown_text if fmt == "markdown" else plain_text
    out = []
    for r in results:
        low, high = r.speeds_rpm.min(), r.speeds_rpm.max()
        out += [
            f"{heading}{safe(r.engine.name)}: torsional vibration, {low:g} to {high:g} rpm",
            "",
            "Excitation: each cylinder's "
            + ("gas and inertia torque" if r.with_gas else "inertia torque alone (no [gas] table)")
            + ", orders up to "
            + f"{r.orders.max():g}.",
            "",
        ]
        rows = [[name, figure(j)] for name, j in zip(r.nodes, r.inertia_kgm2, strict=True)]
        out += ["Shaft line, free end first:", "", render(["Inertia", "J (kg·m²)"], rows, fmt), ""]
        out += [
            "Natural modes (relative amplitudes, the largest throw amplitude 1):",
            "",
            render(
                ["Mode", "f (Hz)", "f (1/min)"] + list(r.nodes),
                [
                    [str(m.number), figure(m.frequency_hz), figure(60 * m.frequency_hz)]
                    + [f"{a:.3f}" for a in m.shape]
                    for m in r.modes
                ],
                fmt,
            ),
            "",
        ]
        orders = list(r.orders)
        out += [
            "Phase-vector sums |Σ β·e^{ik·φ}| by order (β the throw's amplitude in the "
            "mode, φ the cylinder's firing angle):",
            "",
            render(
                ["Order"] + [f"mode {m.number}" for m in r.modes],
                [
                    [f"{k:g}"] + [_sum_text(m.phase_vector_sums[float(k)]) for m in r.modes]
                    for k in orders
                ],
                fmt,
            ),
            "",
        ]
        rows = [
            [
                f"{c.speed_rpm:.0f}",
                str(c.mode),
                f"{c.order:g}",
                "major" if c.major else "minor",
                _sum_text(c.phase_vector_sum),
            ]
            for c in r.criticals
        ]
        out += [
            "Criticals in the speed range (the order's frequency equals the mode's):",
            "",
            render(["Speed (rpm)", "Mode", "Order", "Kind", "Phase-vector sum"], rows, fmt)
            if rows
            else "none",
            "",
        ]
        rows = [
            [name, figure(scale.moment(t)), f"{v:g}"]
            + ([] if s is None else [figure(s / 1e6)])
            + [", ".join(f"{c.order:g}/{c.mode}" for c in r.near(v)) or "-"]
            for name, t, v, s in r.largest()
        ]
        stress = [] if r.stress_pa is None else ["τ (MPa)"]
        out += [
            "Largest vibratory torque per section (peak of all orders together; the "
            "criticals, order/mode, that speed of the sweep stands for):",
            "",
            render(
                ["Section", f"Torque ({scale.moment_label})", "at (rpm)"] + stress + ["Critical"],
                rows,
                fmt,
            ),
            "",
            f"Free end: largest angular amplitude {figure(r.free_end_deg.max())}° at "
            f"{r.speeds_rpm[int(np.argmax(r.free_end_deg))]:g} rpm.",
            "",
        ]
    return "\n".join(out)


def torsion_csv(results, scale=None):
    """The forced response in long form: engine, config, speed_rpm, section, order (``all``
    for the synthesised waveform's peak), torque_Nm (``scale``'s moment unit: torque_kNm,
    ...), stress_Pa (empty without a shaft diameter), and the free end's amplitude
    (free_end_deg, on the ``all`` rows)."""
    scale = scale or Scale()
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(
        [
            "engine",
            "config",
            "speed_rpm",
            "section",
            "order",
            f"torque_{scale.column_moment}",
            "stress_Pa",
            "free_end_deg",
        ]
    )
    for r in results:
        for i, speed in enumerate(r.speeds_rpm):
            for s, name in enumerate(r.sections):
                stress = "" if r.stress_pa is None else repr(float(r.stress_pa[i, s]))
                writer.writerow(
                    [
                        r.engine.name,
                        r.engine.config_path,
                        repr(float(speed)),
                        name,
                        "all",
                        repr(float(scale.moment(r.torque_nm[i, s]))),
                        stress,
                        repr(float(r.free_end_deg[i])),
                    ]
                )
                for o, k in enumerate(r.orders):
                    writer.writerow(
                        [
                            r.engine.name,
                            r.engine.config_path,
                            repr(float(speed)),
                            name,
                            repr(float(k)),
                            repr(float(scale.moment(r.order_torque_nm[i, s, o]))),
                            "",
                            "",
                        ]
                    )
    return buffer.getvalue()
