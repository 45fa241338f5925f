"""``balance torque``'s tables: the torques, their orders, the crank-pin and main-bearing
forces, the guide-force moments and the steadiness; and the report's torque summary."""

import math

import numpy as np

from ..units import Scale, rad_s_to_rpm, round_degrees
from .display import figure
from .table import render, safe_for

__all__ = ["torque_tables", "torque_summary", "steadiness_text"]


def _inertia_text(value_kgm2, reduced_mass):
    """A reduced mass for a table: rounding noise (a twin's μ at top dead centre, exactly 0,
    computes as 1e-31) is 0, beside its largest value."""
    return figure(value_kgm2 if abs(value_kgm2) > 1e-12 * reduced_mass.max_kgm2 else 0.0)


def torque_summary(results, scale=None):
    """The report's torques: per engine the mean, largest, smallest and range of the inertia,
    gas ("—" without one), total and frame torques, in ``scale``'s moment unit (default N·m),
    one row each; and a second table of the reduced mass. Returns ((headers, rows), (headers,
    rows))."""
    scale = Scale() if scale is None else scale
    rows, masses = [], []
    for r in results:
        for i, (name, series) in enumerate(
            (("inertia", r.inertia), ("gas", r.gas), ("total", r.total), ("frame", r.frame))
        ):
            values = (
                ["—"] * 4
                if series is None
                else [
                    figure(scale.moment(v))
                    for v in (series.mean, series.max, series.min, series.range)
                ]
            )
            rows.append([r.engine.name if i == 0 else "", name] + values)
        mu = r.reduced_mass
        masses.append(
            [r.engine.name]
            + [_inertia_text(v, mu) for v in (mu.mean_kgm2, mu.min_kgm2, mu.max_kgm2)]
        )
    ml = scale.moment_label
    return (
        (
            ["Engine", "Torque", f"Mean ({ml})", f"Max ({ml})", f"Min ({ml})", f"Range ΔC ({ml})"],
            rows,
        ),
        (["Engine", "Mean μ (kg·m²)", "Min μ (kg·m²)", "Max μ (kg·m²)"], masses),
    )


def _torque_rows(result, scale):
    rows = []
    for name, series in (
        ("inertia", result.inertia),
        ("gas", result.gas),
        ("total", result.total),
        ("tilting", result.tilting),
        ("frame", result.frame),
    ):
        if series is None:
            continue
        rows.append(
            [name]
            + [figure(scale.moment(v)) for v in (series.mean, series.max, series.min, series.range)]
        )
    return rows


def _order_table(series, scale, fmt, largest):
    """The orders of a torque above a thousandth of its largest one."""
    rows = [
        [
            f"{k:g}",
            figure(scale.moment(c)),
            figure(scale.moment(s)),
            figure(scale.moment(math.hypot(c, s))),
            f"{round_degrees(d['phase_deg'], 1):.1f}",
        ]
        for (k, c, s), d in zip(series.orders, series.to_dict()["orders"], strict=True)
        if math.hypot(c, s) >= 1e-3 * largest and largest > 0
    ]
    ml = scale.moment_label
    return render(
        ["Order", f"cos ({ml})", f"sin ({ml})", f"Amplitude ({ml})", "Phase (°)"], rows, fmt
    )


def _guide_force_lines(guide, scale, fmt):
    """The H-type and X-type guide-force moments by order (MAN B&W project guides, 17.05)."""
    ml = scale.moment_label
    h, x = guide.h_type.to_dict()["orders"], guide.x_type.to_dict()["orders"]
    largest = max([o["amplitude_Nm"] for o in h + x] + [0.0])

    def phase(order):
        # a vanished order has no phase to print
        return f"{round_degrees(order['phase_deg'], 1):.1f}" if order["amplitude_Nm"] else "-"

    rows = [
        [
            f"{a['order']:g}",
            figure(scale.moment(a["amplitude_Nm"])),
            phase(a),
            figure(scale.moment(b["amplitude_Nm"])),
            phase(b),
        ]
        for a, b in zip(h, x, strict=True)
        if largest > 0 and max(a["amplitude_Nm"], b["amplitude_Nm"]) >= 1e-3 * largest
    ]
    return [
        "Guide-force moments (the couples of the pistons' (crossheads') guide forces with the "
        "main "
        f"bearings; H-type their sum, X-type their bimoment about the engine's centre over "
        f"L = {guide.lever_m:.4g} m, the rod length; amplitude·cos(kθ − phase); orders below "
        "a thousandth of the largest left out):",
        "",
        render(
            ["Order", f"H-type ({ml})", "H phase (°)", f"X-type ({ml})", "X phase (°)"],
            rows or [["-", "0", "-", "0", "-"]],
            fmt,
        ),
        "",
    ]


def torque_tables(results, scale, fmt):
    """``balance torque`` as text or Markdown, engine by engine."""
    heading = "#### " if fmt == "markdown" else ""
    safe = safe_for(fmt)
    ml, fl = scale.moment_label, scale.force_label
    out = []
    for r in results:
        engine = r.engine
        mu = r.reduced_mass
        out += [
            f"{heading}{safe(engine.name)}: torques at {rad_s_to_rpm(engine.speed_rad_s):g} rpm "
            f"({engine.cycle}-stroke, period {r.period_deg:g}°)",
            "",
            f"Reduced mass μ (kinetic energy ½·μ·ω²): mean {_inertia_text(mu.mean_kgm2, mu)}, "
            f"min {_inertia_text(mu.min_kgm2, mu)}, max {_inertia_text(mu.max_kgm2, mu)} "
            "kg·m².",
            "",
            render(
                ["Torque", f"Mean ({ml})", f"Max ({ml})", f"Min ({ml})", f"Range ΔC ({ml})"],
                _torque_rows(r, scale),
                fmt,
            ),
            "",
        ]
        if r.indicated_power_kw is not None:
            out += [
                f"Indicated power (mean gas torque × ω): {figure(r.indicated_power_kw)} kW.",
                "",
            ]
        if r.crankshafts:
            out += [
                "Each crankshaft's torque (gas and inertia of the parts it drives, positive in "
                "its own sense of turning; geared 1:1, their sum is the total on the first):",
                "",
                render(
                    [
                        "Crankshaft",
                        "Turning",
                        f"Mean ({ml})",
                        f"Max ({ml})",
                        f"Min ({ml})",
                        f"Range ΔC ({ml})",
                    ],
                    [
                        [
                            str(c.number),
                            "with the first" if c.direction == 1 else "against the first",
                        ]
                        + [
                            figure(scale.moment(v))
                            for v in (c.torque.mean, c.torque.max, c.torque.min, c.torque.range)
                        ]
                        for c in r.crankshafts
                    ],
                    fmt,
                ),
                "",
            ]
        largest = max(math.hypot(c, s) for _, c, s in r.total.orders) if r.total.orders else 0.0
        out += [
            f"Orders of the total torque ({'gas and inertia' if r.gas else 'inertia only'}; "
            "amplitude·cos(kθ − phase); orders below a thousandth of the largest left out):",
            "",
            _order_table(r.total, scale, fmt, largest),
            "",
        ]
        rows = []
        for pin in r.pins:
            magnitude = np.abs(pin.force_n)
            rows.append(
                [str(pin.throw)]
                + [
                    figure(scale.force(v, 1.0))
                    for v in (
                        pin.radial.mean,
                        pin.tangential.mean,
                        float(magnitude.max()),
                        float(magnitude.min()),
                    )
                ]
            )
        bearings = [("main bearings", r.main_bearings)] + [
            (f"main bearings, crankshaft {c.number}", c.main_bearings) for c in r.crankshafts
        ]
        for label, load in bearings:
            if load is None:
                continue
            magnitude = np.abs(load.force_n)
            rows.append(
                [
                    label,
                    "-",
                    "-",
                    figure(scale.force(float(magnitude.max()), 1.0)),
                    figure(scale.force(float(magnitude.min()), 1.0)),
                ]
            )
        out += [
            "Forces of the rods on the crank pins, and of the crankshaft on its main bearings "
            "together:",
            "",
            render(
                [
                    "Throw",
                    f"Radial mean ({fl})",
                    f"Tangential mean ({fl})",
                    f"Largest ({fl})",
                    f"Smallest ({fl})",
                ],
                rows,
                fmt,
            ),
            "",
        ]
        if r.guide is not None:
            out += _guide_force_lines(r.guide, scale, fmt)
        elif engine.is_rotary:
            out += [
                "Guide-force moments: none on a rotary; its cylinders turn with the crankcase, "
                "so the guide forces are the frame's own.",
                "",
            ]
        if r.steadiness is not None:
            out += [steadiness_text(r.steadiness, r.flywheel_kgm2), ""]
    return "\n".join(out)


def _g4(value):
    # a closed form beyond a double is None in JSON, words here
    return value if isinstance(value, str) else f"{value:.4g}"


def steadiness_text(speed, flywheel_kgm2=None):
    """The speed and steadiness of an engine set, in one paragraph."""
    margoulis = {k: ("beyond 1e308" if v is None else v) for k, v in speed.to_dict().items()}
    flywheel = (
        f"a flywheel of {speed.inertia_kgm2:.5g} kg·m²"
        if speed.inertia_kgm2 > 0
        else "no flywheel (the moving parts' own inertia)"
    )
    text = (
        f"With {flywheel} and a {speed.load} load: speed "
        f"{margoulis['min_speed_rpm']:.2f} to {margoulis['max_speed_rpm']:.2f} rpm (mean "
        f"{margoulis['mean_speed_rpm']:.2f}), steadiness ω_m/(ω_max − ω_min) = "
        f"{_g4(margoulis['steadiness'])} integrated; Margoulis's closed forms (one harmonic of "
        f"order {speed.order:g}, ΔC = {margoulis['torque_range_Nm']:.4g} N·m): r_c = "
        f"{_g4(margoulis['r_c'])}, r_v = {_g4(margoulis['r_v'])}, r_h = {_g4(margoulis['r_h'])}."
    )
    if flywheel_kgm2 == 0.0:
        text += " The target steadiness needs no flywheel."
    elif flywheel_kgm2 is not None:
        text += f" The target steadiness needs a flywheel of {flywheel_kgm2:.5g} kg·m²."
    return text
