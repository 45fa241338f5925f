"""Plain-text, Markdown and CSV tables, in the style of Tanaka's Part III."""

import csv
import io
import math

from tabulate import tabulate

from ..units import rad_s_to_rpm
from .values import Scale, is_negligible, order_values

__all__ = ["compare_tables", "compare_csv", "list_table", "show_table"]

_TABLEFMT = {"table": "simple", "markdown": "pipe"}


def _fmt(value, digits):
    return f"{value:.{digits}f}"


def _intervals(firing):
    mean = sum(firing.intervals_deg) / len(firing.intervals_deg)
    if firing.uniform:
        return f"every {mean:g}"
    return f"{min(firing.intervals_deg):.1f} to {max(firing.intervals_deg):.1f}"


def _order_rows(result, scale, full):
    """Rows (engine, order, force fwd/bwd/max/min/axis, moment fwd/bwd/max) of one engine."""
    digits = 4 if not scale.absolute else 1 if scale.units == "N" else 2
    rows = []
    for order in result.shaking.orders:
        v = order_values(order, result)
        if not full and is_negligible(v):
            continue
        f, m = v["force"], v["moment"]
        force = [scale.force(f[k], result) for k in ("forward_N", "backward_N", "max_N", "min_N")]
        moment = [scale.moment(m[k]) for k in ("forward_Nm", "backward_Nm", "max_Nm")]
        rows.append(
            [result.engine.name, order.order]
            + ([x for x in force] if full else [_fmt(x, digits) for x in force])
            + [f["axis_deg"] if full else _fmt(f["axis_deg"], 0)]
            + ([x for x in moment] if full else [_fmt(x, 2) for x in moment])
        )
    return rows


def _order_headers(scale):
    fl, ml = scale.force_label, scale.moment_label
    return (
        ["Engine", "Order", f"F fwd ({fl})", f"F bwd ({fl})", f"F max ({fl})", f"F min ({fl})",
         "F axis (°)", f"M fwd ({ml})", f"M bwd ({ml})", f"M max ({ml})"]
    )


def _summary_rows(results, reference_index, scale):
    reference = results[reference_index]
    ref = reference.counterweighted_force_n / reference.per_cylinder_unit_n
    rows = []
    for r in results:
        per_cyl = r.counterweighted_force_n / r.per_cylinder_unit_n
        largest = (_fmt(per_cyl, 4) if not scale.absolute
                   else _fmt(scale.force(r.counterweighted_force_n, r), 1))
        rows.append([
            r.engine.name, r.engine.n_cylinders, r.engine.cycle, r.engine.frame,
            "-".join(map(str, r.firing.order)), _intervals(r.firing), largest,
            f"{100 * per_cyl / ref:.1f}" if ref else "-",
        ])
    return rows


def compare_tables(results, reference_index, scale, tablefmt, samples):
    """The comparison as text or Markdown: orders of every engine, then a summary."""
    fmt = _TABLEFMT[tablefmt]
    rows = [row for r in results for row in _order_rows(r, scale, full=False)]
    unit = ("per cylinder, in units of m_rec·r·ω²·n" if not scale.absolute
            else f"in {scale.units}")
    reference = results[reference_index].engine.name
    heading = "#### " if tablefmt == "markdown" else ""
    out = [
        f"{heading}Free forces and moments by order (forces {unit}; moments in {scale.moment_label})",
        "",
        tabulate(rows, headers=_order_headers(scale), tablefmt=fmt, disable_numparse=True),
        "",
        f"Orders not listed are zero. fwd turns with the crank, bwd against it; max and min are the "
        f"semi-axes of the order's ellipse, axis the direction of max from the reference axis "
        f"({samples} samples a revolution).",
        "",
        f"{heading}Firing and largest resultant (after an ideal crankshaft counterweight)",
        "",
        tabulate(
            _summary_rows(results, reference_index, scale),
            headers=["Engine", "Cyl", "Cycle", "Frame", "Firing order", "Intervals (°)",
                     f"Largest ({scale.force_label})", f"% of {reference}"],
            tablefmt=fmt, disable_numparse=True,
        ),
        "",
    ]
    return "\n".join(out)


def compare_csv(results, scale):
    """One row per engine and order, every order, full precision; units in the header."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    fl = "per_cyl" if not scale.absolute else scale.units
    ml = "kgfm" if scale.units == "kgf" else "Nm"
    writer.writerow(
        ["engine", "config", "order", f"force_forward_{fl}", f"force_backward_{fl}",
         f"force_max_{fl}", f"force_min_{fl}", "force_axis_deg", f"moment_forward_{ml}",
         f"moment_backward_{ml}", f"moment_max_{ml}"]
    )
    for r in results:
        for row in _order_rows(r, scale, full=True):
            writer.writerow([row[0], r.engine.config_path] + [repr(x) for x in row[1:]])
    return buffer.getvalue()


def list_table(engines):
    rows = [[e.config_path, e.name, e.n_cylinders, e.cycle, e.frame, e.source] for e in engines]
    return tabulate(rows, headers=["Config", "Name", "Cyl", "Cycle", "Frame", "Source"],
                    tablefmt="simple", disable_numparse=True)


def show_table(engine, tdc, firing):
    """One engine, one row per cylinder, with the engine's data above."""
    mm = lambda m: f"{1000 * m:g} mm"  # noqa: E731
    header = [
        f"{engine.name}",
        f"  source:        {engine.source or '-'}",
        f"  config:        {engine.config_path}",
        f"  cycle:         {engine.cycle}-stroke, frame {engine.frame}, "
        f"{rad_s_to_rpm(engine.speed_rad_s):g} rpm",
        f"  crank radius:  {mm(engine.crank_radius_m)}, rod {mm(engine.rod_length_m)}, "
        f"pin offset {mm(engine.pin_offset_m)}",
        f"  masses:        reciprocating {engine.mean_reciprocating_kg * 1000:g} g mean per cylinder, "
        f"rotating {engine.rotating_kg * 1000:g} g per throw"
        + "".join(f", knuckle {kg * 1000:g} g per link rod"
                  for kg in sorted({c.knuckle_kg for c in engine.cylinders if c.is_link})),
        f"  firing:        {'-'.join(map(str, firing.order))} "
        f"({'given' if firing.given else 'most uniform the crank allows'})",
        f"  intervals (°): {', '.join(f'{i:.2f}' for i in firing.intervals_deg)}",
        "",
    ]
    rows = []
    for c in engine.cylinders:
        rod = engine.rod_type(c)
        if c.is_link:
            rod = (f"link on {c.master} ({mm(c.link_length_m)}, knuckle {mm(c.knuckle_radius_m)} "
                   f"at {math.degrees(c.knuckle_angle_rad):g}°)")
        rows.append([
            c.number, f"{c.bank + 1} ({math.degrees(engine.bank_angles_rad[c.bank]):g}°)",
            c.throw + 1, f"{math.degrees(engine.throws[c.throw].phase_rad):g}", f"{c.z_m * 1000:g}",
            f"{c.reciprocating_kg * 1000:g}", rod, f"{tdc[c.number]:.2f}",
        ])
    table = tabulate(
        rows,
        headers=["Cyl", "Bank (angle)", "Throw", "Phase (°)", "z (mm)", "Recip. (g)", "Rod",
                 "TDC (°)"],
        tablefmt="simple", disable_numparse=True,
    )
    return "\n".join(header) + table + "\n"
