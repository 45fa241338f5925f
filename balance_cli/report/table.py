"""Plain-text, Markdown and CSV tables, in the style of Tanaka's Part III."""

import csv
import io
import math

from tabulate import tabulate

from ..units import rad_s_to_rpm
from .values import Scale, is_negligible, order_values

__all__ = ["compare_parts", "render_parts", "compare_tables", "compare_csv", "balance_tables",
           "balance_csv", "balance_summary", "list_table", "show_table"]

_TABLEFMT = {"table": "simple", "markdown": "pipe"}


def _fmt(value, digits):
    return f"{value:.{digits}f}"


def _intervals(firing):
    mean = sum(firing.intervals_deg) / len(firing.intervals_deg)
    if firing.uniform:
        return f"every {mean:g}"
    return f"{min(firing.intervals_deg):.1f} to {max(firing.intervals_deg):.1f}"


def _order_rows(name, shaking, unit_n, scale, full):
    """Rows (engine, order, force fwd/bwd/max/min/axis, moment fwd/bwd/max) of one engine;
    ``unit_n`` is its m_rec·r·ω²·n."""
    digits = 4 if not scale.absolute else 1 if scale.units == "N" else 2
    rows = []
    for order in shaking.orders:
        v = order_values(order, unit_n)
        if not full and is_negligible(v):
            continue
        f, m = v["force"], v["moment"]
        force = [scale.force(f[k], unit_n) for k in ("forward_N", "backward_N", "max_N", "min_N")]
        moment = [scale.moment(m[k]) for k in ("forward_Nm", "backward_Nm", "max_Nm")]
        rows.append(
            [name, order.order]
            + (force if full else [_fmt(x, digits) for x in force])
            + [f["axis_deg"] if full else _fmt(f["axis_deg"], 0)]
            + (moment if full else [_fmt(x, 2) for x in moment])
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
    rows = []
    for r in results:
        largest = (_fmt(r.counterweighted_per_cylinder, 4) if not scale.absolute
                   else _fmt(scale.force(r.counterweighted_force_n, r.per_cylinder_unit_n), 1))
        percent = r.percent_of(reference)
        rows.append([
            r.engine.name, r.engine.n_cylinders, r.engine.cycle, r.engine.frame,
            "-".join(map(str, r.firing.order)), _intervals(r.firing), largest,
            "-" if percent is None else f"{percent:.1f}",
        ])
    return rows


def compare_parts(results, reference_index, scale, samples):
    """The comparison as (title, headers, rows, note) tables, for any renderer."""
    unit = ("per cylinder, in units of m_rec·r·ω²·n" if not scale.absolute
            else f"in {scale.units}")
    reference = results[reference_index].engine.name
    rows = [row for r in results
            for row in _order_rows(r.engine.name, r.shaking, r.per_cylinder_unit_n, scale, full=False)]
    return [
        (f"Free forces and moments by order (forces {unit}; moments in {scale.moment_label})",
         _order_headers(scale), rows,
         "Orders not listed are zero. fwd turns with the crank, bwd against it; max and min are "
         "the semi-axes of the order's ellipse, axis the direction of max from the reference axis "
         f"({samples} samples a revolution)."),
        ("Firing and largest resultant (after an ideal crankshaft counterweight)",
         ["Engine", "Cyl", "Cycle", "Frame", "Firing order", "Intervals (°)",
          f"Largest ({scale.force_label})", f"% of {reference}"],
         _summary_rows(results, reference_index, scale), ""),
    ]


def render_parts(parts, tablefmt):
    """Tables from :func:`compare_parts` as text or Markdown."""
    heading = "#### " if tablefmt == "markdown" else ""
    out = []
    for title, headers, rows, note in parts:
        out += [f"{heading}{title}", "",
                tabulate(rows, headers=headers, tablefmt=_TABLEFMT[tablefmt], disable_numparse=True), ""]
        if note:
            out += [note, ""]
    return "\n".join(out)


def compare_tables(results, reference_index, scale, tablefmt, samples):
    """The comparison as text or Markdown: orders of every engine, then a summary."""
    return render_parts(compare_parts(results, reference_index, scale, samples), tablefmt)


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
        for row in _order_rows(r.engine.name, r.shaking, r.per_cylinder_unit_n, scale, full=True):
            writer.writerow([row[0], r.engine.config_path] + [repr(x) for x in row[1:]])
    return buffer.getvalue()


def list_table(engines):
    rows = [[e.config_path, e.name, e.n_cylinders, e.cycle, e.frame, e.source] for e in engines]
    return tabulate(rows, headers=["Config", "Name", "Cyl", "Cycle", "Frame", "Source"],
                    tablefmt="simple", disable_numparse=True)


def show_table(engine, firing):
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
        f"rotating {engine.rotating_kg * 1000:g} g and crank {engine.crank_kg * 1000:g} g per throw"
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
            f"{c.reciprocating_kg * 1000:g}", rod, f"{firing.tdc_deg[c.number]:.2f}",
        ])
    table = tabulate(
        rows,
        headers=["Cyl", "Bank (angle)", "Throw", "Phase (°)", "z (mm)", "Recip. (g)", "Rod",
                 "TDC (°)"],
        tablefmt="simple", disable_numparse=True,
    )
    return "\n".join(header) + table + "\n"


def balance_tables(results, scale, tablefmt):
    """``balance counterweight`` as text or Markdown, engine by engine."""
    fmt = _TABLEFMT[tablefmt]
    heading = "#### " if tablefmt == "markdown" else ""
    unit = ("per cylinder, × m_rec·r·ω²·n" if not scale.absolute else scale.units)
    out = []
    for r in results:
        engine = r.engine
        n_unit = engine.unit_force_n * engine.n_cylinders
        how = ("cancelling the forward first order" if r.balance_factor is None else
               f"balance factor {r.balance_factor:g}: rotating masses plus {r.balance_factor:g} of "
               "the reciprocating ones per throw")
        carrier = "crankcase" if engine.frame == "rotary" else "crank"
        out += [f"{heading}{engine.name}: counterweights on the {carrier}, {how}", ""]
        rows = [[c.plane.throw or "-", f"{c.plane.z_m * 1000:g}", f"{c.mass_kg:.4f}",
                 f"{c.radius_m * 1000:g}", f"{c.angle_deg:.2f}"] for c in r.counterweights]
        out += [tabulate(rows, headers=["Throw", "z (mm)", "Mass (kg)", "Radius (mm)",
                                        "Angle (° from throw 1)"], tablefmt=fmt,
                         disable_numparse=True), ""]
        if r.antivibrateur is not None:
            a = r.antivibrateur
            out += [f"Antivibrateur on the crank pin, turning at twice crank speed with the crank: "
                    f"M·e = {a.mass_eccentricity_kgm * 1000:.2f} kg·mm (M = {a.mass_kg:.4f} kg at "
                    f"e = {a.eccentricity_m * 1000:g} mm), at {a.phase_deg:.2f}° when θ = 0; the "
                    f"counterweights above include its mass.", ""]
        first = order_values(r.residual.orders[0], n_unit)
        f, m = first["force"], first["moment"]
        out += [f"First order left: forward {scale.force(f['forward_N'], n_unit):.4g}, "
                f"backward {scale.force(f['backward_N'], n_unit):.4g} ({unit}; no counterweight "
                f"touches the backward part); moment {scale.moment(m['forward_Nm']):.4g} forward, "
                f"{scale.moment(m['backward_Nm']):.4g} backward ({scale.moment_label}).", ""]
        out += ["Left after the counterweights:", "",
                tabulate(_order_rows(engine.name, r.residual, n_unit, scale, full=False),
                         headers=_order_headers(scale), tablefmt=fmt, disable_numparse=True), ""]
        if r.after_shafts is not None:
            rows = [[s.order, f"{s.speed_ratio:+d}", s.direction,
                     f"{s.mass_eccentricity_kgm * 1000:.3f}", f"{s.phase_deg:.2f}",
                     f"{s.z_m * 1000:g}"] for s in r.shafts]
            out += ["Balancer shafts:", "",
                    tabulate(rows, headers=["Order", "Speed ratio", "Turning", "m·e (kg·mm)",
                                            "Phase at θ = 0 (°)", "z (mm)"],
                             tablefmt=fmt, disable_numparse=True), "",
                    "Left after the shafts:", "",
                    tabulate(_order_rows(engine.name, r.after_shafts, n_unit, scale, full=False),
                             headers=_order_headers(scale), tablefmt=fmt, disable_numparse=True), ""]
        if r.test_masses_kg is not None:
            rows = [[i + 1, f"{m:.4f}"] for i, m in enumerate(r.test_masses_kg)]
            out += ["Balancing-machine test masses (hang on each crank pin; the crankshaft's own "
                    "unbalance excluded):", "",
                    tabulate(rows, headers=["Throw", "Mass (kg)"], tablefmt=fmt,
                             disable_numparse=True), ""]
    return "\n".join(out)


def balance_csv(results, scale):
    """Everything of ``balance counterweight`` in long form: engine, item, quantity, value, unit."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["engine", "config", "item", "quantity", "value", "unit"])
    fl = "per_cyl" if not scale.absolute else scale.units
    ml = "kgf·m" if scale.units == "kgf" else "N·m"
    for r in results:
        rows = []
        for i, c in enumerate(r.counterweights, 1):
            item = f"counterweight {i}"
            rows += [(item, "throw", c.plane.throw or "", ""), (item, "z", c.plane.z_m, "m"),
                     (item, "mass", c.mass_kg, "kg"), (item, "radius", c.radius_m, "m"),
                     (item, "angle", c.angle_deg, "deg")]
        if r.antivibrateur is not None:
            a = r.antivibrateur
            rows += [("antivibrateur", "mass_eccentricity", a.mass_eccentricity_kgm, "kg·m"),
                     ("antivibrateur", "eccentricity", a.eccentricity_m, "m"),
                     ("antivibrateur", "mass", a.mass_kg, "kg"),
                     ("antivibrateur", "phase", a.phase_deg, "deg")]
        n_unit = r.engine.unit_force_n * r.engine.n_cylinders
        stages = [("residual", r.residual)] + ([("after shafts", r.after_shafts)]
                                               if r.after_shafts is not None else [])
        for stage, shaking in stages:
            for row in _order_rows(r.engine.name, shaking, n_unit, scale, full=True):
                item = f"{stage} order {row[1]}"
                for name, value in zip(("force_forward", "force_backward", "force_max", "force_min"),
                                       row[2:6]):
                    rows.append((item, name, value, fl))
                rows.append((item, "force_axis", row[6], "deg"))
                for name, value in zip(("moment_forward", "moment_backward", "moment_max"), row[7:10]):
                    rows.append((item, name, value, ml))
        for i, shaft in enumerate(r.shafts, 1):
            item = f"shaft {i}"
            rows += [(item, "order", shaft.order, ""), (item, "speed_ratio", shaft.speed_ratio, ""),
                     (item, "mass_eccentricity", shaft.mass_eccentricity_kgm, "kg·m"),
                     (item, "phase", shaft.phase_deg, "deg"), (item, "z", shaft.z_m, "m")]
        for i, mass in enumerate(r.test_masses_kg or (), 1):
            rows.append((f"test mass throw {i}", "mass", mass, "kg"))
        for item, quantity, value, unit in rows:
            writer.writerow([r.engine.name, r.engine.config_path, item, quantity,
                             repr(value) if isinstance(value, float) else value, unit])
    return buffer.getvalue()


def balance_summary(results):
    """One row per engine of ``balance counterweight`` with default planes: (headers, rows)."""
    rows = []
    for r in results:
        engine = r.engine
        n_unit = engine.unit_force_n * engine.n_cylinders
        first = order_values(r.residual.orders[0], n_unit)["force"]
        weights = "; ".join(
            f"{c.mass_kg:.4g} kg at {c.angle_deg:.1f}° ({'throw ' + str(c.plane.throw) if c.plane.throw else f'z = {c.plane.z_m * 1000:g} mm'})"
            for c in r.counterweights)
        rows.append([engine.name, weights, f"{first['forward_N'] / n_unit:.4f}",
                     f"{first['backward_N'] / n_unit:.4f}",
                     f"{r.residual.largest_force() / n_unit:.4f}"])
    headers = ["Engine", "Counterweights at crank radius", "1st order left fwd (per cyl)",
               "1st order bwd (per cyl)", "Largest resultant left (per cyl)"]
    return headers, rows
