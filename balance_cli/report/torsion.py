"""``balance torsion`` as text, Markdown and CSV (its pictures are
:mod:`balance_cli.plot.torsion`'s)."""

import csv
import io

import numpy as np

from ..units import Scale, significant
from .display import figure, markdown_text, plain_text
from .table import render

__all__ = ["torsion_tables", "torsion_csv", "peak_text"]


def _sum_text(value):
    # the analysis sets a sum that cancels to rounding to exactly 0 (not excited)
    return "0" if value == 0.0 else significant(value, 3)


def _selection_text(r):
    """The criticals :meth:`TorsionResult.filtered` kept, in words ("" for all of them)."""
    chosen = r.selection
    if not chosen:
        return ""
    words = {
        "excited": "those the cylinders excite",
        "major": "of major orders, excited",
        "all": "",
    }[chosen["kind"]]
    parts = [words] if words else []
    if chosen["orders"]:
        parts.append("order " + ", ".join(f"{k:g}" for k in chosen["orders"]))
    if chosen["modes"]:
        parts.append("mode " + ", ".join(str(m) for m in chosen["modes"]))
    return "; ".join(parts)


def peak_text(r, scale):
    """The sweep's largest vibratory torque in words: where, and the order (and mode) there."""
    p = r.peak()
    what = f"order {p.order:g} ({'major' if p.major else 'minor'})"
    if p.mode is not None:
        what += f", mode {p.mode} (its critical at {p.critical_rpm:.0f} rpm)"
    return (
        f"{figure(scale.moment(p.torque_nm))} {scale.moment_label} in {p.section} at "
        f"{p.speed_rpm:g} rpm, {what}"
    )


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
            "Natural modes (relative amplitudes, the largest 1; 0 a node: below 1e-8 of it):",
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
        chosen = r.selection or {}
        orders = chosen.get("orders") or [float(k) for k in r.orders]
        modes = [m for m in r.modes if not chosen.get("modes") or m.number in chosen["modes"]]
        out += [
            "Phase-vector sums |Σ β·e^{ik·φ}| by order (β the throw's amplitude in the "
            "mode, φ the cylinder's firing angle; 0: the cylinders cannot excite the mode "
            "at that order):",
            "",
            render(
                ["Order"] + [f"mode {m.number}" for m in modes],
                [[f"{k:g}"] + [_sum_text(m.phase_vector_sums[k]) for m in modes] for k in orders],
                fmt,
            ),
            "",
        ]
        rows = [
            [
                f"{c.speed_rpm:.0f}",
                str(c.mode),
                f"{c.order:g}",
                c.kind,
                _sum_text(c.phase_vector_sum),
            ]
            for c in r.criticals
        ]
        which = _selection_text(r)
        out += [
            "Criticals in the speed range (the order's frequency equals the mode's"
            + (f"; {which}" if which else "")
            + "):",
            "",
            render(["Speed (rpm)", "Mode", "Order", "Kind", "Phase-vector sum"], rows, fmt)
            if rows
            else "none",
            "",
        ]
        rows = []
        for s_index, (name, t, v, s) in enumerate(r.largest()):
            i = int(np.argmax(r.torque_nm[:, s_index]))
            top = r.orders[int(np.argmax(r.order_torque_nm[i, s_index]))]
            rows.append(
                [name, figure(scale.moment(t)), f"{v:g}"]
                + ([] if s is None else [figure(s / 1e6)])
                + [f"{top:g}", ", ".join(f"{c.order:g}/{c.mode}" for c in r.near(v)) or "-"]
            )
        stress = [] if r.stress_pa is None else ["τ (MPa)"]
        elastic = r.free_end_elastic_deg
        out += [
            "Largest vibratory torque per section (peak of all orders together; the "
            "order of the largest amplitude there; the criticals, order/mode, that speed "
            "of the sweep stands for):",
            "",
            render(
                ["Section", f"Torque ({scale.moment_label})", "at (rpm)"]
                + stress
                + ["Order", "Critical"],
                rows,
                fmt,
            ),
            "",
            f"Largest of all: {peak_text(r, scale)}.",
            "",
            f"Free end: largest angular amplitude {figure(r.free_end_deg.max())}° at "
            f"{r.speeds_rpm[int(np.argmax(r.free_end_deg))]:g} rpm (the whole line's rigid "
            "turning included); its elastic twist (less the turning of the line's centre "
            f"of inertia) largest {figure(elastic.max())}° at "
            f"{r.speeds_rpm[int(np.argmax(elastic))]:g} rpm.",
            "",
        ]
    return "\n".join(out)


def torsion_csv(results, scale=None):
    """The forced response in long form: engine, config, speed_rpm, section, order (``all``
    for the synthesised waveform's peak), torque_Nm (``scale``'s moment unit: torque_kNm,
    ...), stress_Pa (empty without a shaft diameter), and the free end's amplitude and its
    elastic twist (free_end_deg, free_end_elastic_deg, on the ``all`` rows)."""
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
            "free_end_elastic_deg",
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
                        repr(float(r.free_end_elastic_deg[i])),
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
                            "",
                        ]
                    )
    return buffer.getvalue()
