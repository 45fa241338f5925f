"""``balance mounts`` as text, Markdown and CSV (its pictures are
:mod:`balance_cli.plot.mounts`'s)."""

import csv
import io

import numpy as np

from ..model import DOF_LABELS, MOTIONS
from .display import figure, markdown_text, plain_text
from .table import render

__all__ = ["mount_tables", "mount_csv", "decoupling_tables", "CSV_COLUMNS"]

#: the CSV's columns: :meth:`MountResult.records`' keys, in this order
CSV_COLUMNS = (
    "engine",
    "config",
    "speed_rpm",
    "order",
    "where",
    "x_m",
    "y_m",
    "z_m",
    "rx_rad",
    "ry_rad",
    "rz_rad",
    "Fx_N",
    "Fy_N",
    "Fz_N",
    "F_N",
)
#: below this fraction of the largest force (or motion) of a table, a figure is rounding noise
_NOISE = 1e-9


def _cleaned(value, largest):
    return 0.0 if abs(value) < _NOISE * largest else value


def _vector(values, digits=4):
    # a component that rounds to zero from below is shown as 0.0, not -0.0
    return "(" + ", ".join(f"{round(float(v), digits) + 0.0:.{digits}f}" for v in values) + ")"


def _modes(r, fmt):
    headers = ["Mode", "f (Hz)", "Motion", "Purity (%)"] + [
        f"{m} {d} (%)" for m, d in zip(MOTIONS, DOF_LABELS, strict=True)
    ]
    rows = [
        [str(m.number), figure(m.frequency_hz), m.motion, f"{m.purity_pct:.1f}"]
        # a share that rounds to zero from below is shown as 0.0, not -0.0
        + [f"{round(float(e), 1) + 0.0:.1f}" for e in m.energy_pct]
        for m in r.modes
    ]
    return [
        "Natural modes and their kinetic-energy distribution (percent of each mode's energy in "
        "each motion; the motion that holds most names the mode):",
        "",
        render(headers, rows, fmt),
        "",
    ]


def _axes(r):
    tra, ea = r.torque_roll_axis, r.elastic_axis
    return [
        "Torque roll axis (J⁻¹·x̂, through the centre of gravity): direction "
        f"{_vector(tra.direction)}.",
        f"Elastic axis of the crank's torque: direction {_vector(ea.direction)}, "
        f"{ea.distance_m * 1e3:.1f} mm from the centre of gravity (nearest point "
        f"{_vector([v * 1e3 for v in ea.through_m], 1)} mm).",
        f"Angle between them: {r.axes_angle_deg:.2f}°.",
        "",
    ]


def _static(r, load, fmt):
    largest = max(
        float(np.abs(load.deflection_m).max()), float(np.abs(load.displacement[:3]).max())
    )
    force_largest = float(np.abs(load.force_n).max())
    rows = [
        [name]
        + [figure(_cleaned(v, largest) * 1e3) for v in load.deflection_m[i]]
        + [figure(_cleaned(f, force_largest)) for f in load.force_n[i]]
        for i, name in enumerate(r.names)
    ]
    d = load.displacement
    rotation = float(np.abs(d[3:]).max())
    where = (
        f"under the weight ({figure(r.system.mass_kg * 9.80665)} N, {load.source})"
        if load.name == "weight"
        else f"under the reaction to a mean torque of {figure(load.torque_nm)} N·m ({load.source})"
    )
    return [
        f"Static deflection {where}: the centre of gravity moves "
        + _vector([_cleaned(v, largest) * 1e3 for v in d[:3]], 3)
        + " mm and turns "
        + _vector([_cleaned(v, rotation) * 1e3 for v in d[3:]], 3)
        + " mrad (x, y, z); each mount (forces: what it passes on to the frame):",
        "",
        render(["Mount", "δx (mm)", "δy (mm)", "δz (mm)", "Fx (N)", "Fy (N)", "Fz (N)"], rows, fmt),
        "",
    ]


def _crossings(r, fmt):
    rows = [
        [f"{c.speed_rpm:.0f}", str(c.mode), c.motion, f"{c.order:g}", "yes" if c.excited else "no"]
        for c in r.crossings
    ]
    return [
        "Resonances crossed in the speed range (an order's frequency equals a mode's; "
        "excited: the order drives the mode):",
        "",
        render(["Speed (rpm)", "Mode", "Motion", "Order", "Excited"], rows, fmt)
        if rows
        else "none",
        "",
    ]


def _largest(r, fmt):
    rows = []
    sizes = r.response.force_magnitude_peak_n
    largest = float(sizes.max()) if sizes.size else 0.0
    for name, peaks, at, size, where in r.largest():
        i = int(np.argmin(np.abs(r.speeds_rpm - where)))
        m = r.names.index(name)
        top = r.orders[int(np.argmax(np.abs(r.response.force_n[i, :, m, :]).max(axis=-1)))]
        rows.append(
            [name]
            + [f"{figure(_cleaned(p, largest))} at {s:g}" for p, s in zip(peaks, at, strict=True)]
            + [figure(_cleaned(size, largest)), f"{where:g}", f"{top:g}"]
            + [", ".join(f"{c.order:g}/{c.mode}" for c in r.near(where) if c.excited) or "-"]
        )
    motion = r.response.motion_peak
    units = [("mm", 1e3)] * 3 + [("mrad", 1e3)] * 3
    cells = []
    for j, (label, (unit, factor)) in enumerate(zip(DOF_LABELS, units, strict=True)):
        i = int(np.argmax(motion[:, j]))
        cells.append(f"{label} {figure(motion[i, j] * factor)} {unit} at {r.speeds_rpm[i]:g} rpm")
    return [
        "Largest force each mount passes on to the frame (every order summed over a cycle; "
        "component peaks at their speeds, rpm; the order of the largest amplitude there; the "
        "driven resonances, order/mode, that speed of the sweep stands for):",
        "",
        render(
            ["Mount", "Fx (N)", "Fy (N)", "Fz (N)", "|F| (N)", "at (rpm)", "Order", "Resonance"],
            rows,
            fmt,
        ),
        "",
        "Largest motion of the centre of gravity: " + "; ".join(cells) + ".",
        "",
    ]


def mount_tables(results, fmt) -> str:
    """Modes and energy distribution, axes, static deflections, resonances crossed and the
    largest transmitted forces, engine by engine; ``fmt`` "table" or "markdown"."""
    heading = "#### " if fmt == "markdown" else ""
    safe = markdown_text if fmt == "markdown" else plain_text
    out = []
    for r in results:
        low, high = r.speeds_rpm.min(), r.speeds_rpm.max()
        out += [
            f"{heading}{safe(r.engine.name)}: on its mounts, {low:g} to {high:g} rpm",
            "",
            f"{figure(r.system.mass_kg)} kg on {len(r.names)} mounts; the crank turns "
            f"{r.system.rotation} seen from the front. Excitation: the shaking forces and "
            "moments and the frame torque ("
            + ("gas, inertia and tilting" if r.with_gas else "inertia and tilting; no gas cycle")
            + f"), orders {r.orders.min():g} to {r.orders.max():g}.",
            "",
        ]
        out += _modes(r, fmt)
        out += _axes(r)
        out += _static(r, r.weight, fmt)
        if r.torque_load is not None:
            out += _static(r, r.torque_load, fmt)
        else:
            out += ["No static deflection under torque: no [gas] table and no power given.", ""]
        out += _crossings(r, fmt)
        out += _largest(r, fmt)
    return "\n".join(out)


def _kn(value_n_m):
    return figure(value_n_m / 1e3)


def decoupling_tables(decouplings, fmt) -> str:
    """Each :class:`~balance_cli.mounting.Decoupling`: the rates found and the torque roll axis
    mode before and after; ``fmt`` "table" or "markdown"."""
    heading = "#### " if fmt == "markdown" else ""
    safe = markdown_text if fmt == "markdown" else plain_text
    methods = {
        "closed form": "in closed form, the least change of the rates varied",
        "SLSQP": "by scipy's SLSQP, the least change of the rates varied within their bounds",
        "purest": "by scipy's L-BFGS-B, the purest mode these rates give within their bounds",
    }
    out = []
    for d in decouplings:
        before, after = d.before, d.after
        verdict = (
            "decoupled to rounding"
            if d.exact
            else "NOT decoupled: vary more rates, other rates, or widen the bounds"
        )
        rows = [
            [
                r.label,
                ", ".join(_kn(k) for k in dict.fromkeys(r.before_n_m)),
                _kn(r.after_n_m),
                f"{_kn(r.low_n_m)} to {_kn(r.high_n_m)}" + (" (at a bound)" if r.at_bound else ""),
            ]
            for r in d.rates
        ]

        def row(label, value, s=before, t=after):
            return [label, value(s), value(t)]

        states = [
            row("TRA mode", lambda s: f"{s.mode} ({s.motion})"),
            row("Frequency (Hz)", lambda s: figure(s.frequency_hz)),
            row("Purity (%)", lambda s: f"{s.purity_pct:.2f}"),
            row("Energy on the TRA (%)", lambda s: f"{s.tra_energy_pct:.2f}"),
            row("Mode's axis to the TRA (°)", lambda s: f"{s.axis_angle_deg:.3g}"),
            row("Mode's axis from the CG (mm)", lambda s: f"{s.axis_offset_m * 1e3:.3g}"),
            row("TRA to elastic axis (°)", lambda s: f"{s.axes_angle_deg:.3g}"),
        ]
        out += [
            f"{heading}{safe(d.name)}: torque roll axis decoupling",
            "",
            "The rates that make the turn about the torque roll axis (direction "
            f"{_vector(d.torque_roll_axis.direction)}, through the centre of gravity) a "
            f"natural mode (Jeong and Singh 2000), found {methods[d.method]}: {verdict}.",
            "",
            render(["Rate", "Before (N/mm)", "After (N/mm)", "Bounds (N/mm)"], rows, fmt),
            "",
            "The mode nearest the turn about the torque roll axis (purity: the share of its "
            "kinetic energy in that turn):",
            "",
            render(["", "Before", "After"], states, fmt),
            "",
        ]
    return "\n".join(out)


def mount_csv(results) -> str:
    """Every result's :meth:`~balance_cli.mounting.MountResult.records`, one row each, in the
    columns of :data:`CSV_COLUMNS` (SI units; an empty cell where a column does not apply)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    for r in results:
        for record in r.records():
            writer.writerow(
                [
                    ""
                    if record[k] is None
                    else repr(record[k])
                    if isinstance(record[k], float)
                    else record[k]
                    for k in CSV_COLUMNS
                ]
            )
    return buffer.getvalue()
