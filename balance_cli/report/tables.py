"""Plain-text and Markdown tables, in the style of Tanaka's Part III.

Every table is rendered from result objects' ``to_dict()`` records; text that comes from a
user (engine names, paths, sources) is made safe for the format here.
"""

import math

import numpy as np
from tabulate import tabulate

from ..units import (Scale, kg_to_g, m_to_mm, pa_to_bar, rad_s_to_rpm, round_degrees,
                     significant, wrap_degrees)
from .display import figure, markdown_text, plain_text

__all__ = ["render", "compare_parts", "compare_tables", "part_rows", "part_headers", "order_parts",
           "balance_tables", "balance_summary", "list_table", "list_tables", "show_table", "regression_tables",
           "torque_tables", "torque_summary", "steadiness_text", "search_tables", "search_summary",
           "search_rows"]

_TABLEFMT = {"table": "simple", "markdown": "pipe"}


def _safe(fmt):
    return markdown_text if fmt == "markdown" else plain_text


def render(headers, rows, fmt):
    """One table as text ("table") or Markdown ("markdown"); cells must already be text."""
    safe = _safe(fmt)
    return tabulate([[safe(c) for c in row] for row in rows], headers=[safe(h) for h in headers],
                    tablefmt=_TABLEFMT[fmt], disable_numparse=True)


def _axis_text(axis_deg):
    """An ellipse's axis for a table: "—" where there is none (a circle, or nothing)."""
    return "—" if axis_deg is None else f"{round_degrees(axis_deg, 0, 180.0):.0f}"


def order_values(record, unit_n, scale):
    """The CSV columns of one order's record (``OrderComponents.to_dict``) in display units:
    force forward, backward, max, min, axis; moment forward, backward, max; then (added with
    format version 2, so older readers keep their columns) force vertical and horizontal,
    moment min, axis, vertical (pitch) and horizontal (yaw)."""
    f, m = record["force"], record["moment"]
    force = lambda key: scale.force(f[key], unit_n)  # noqa: E731
    return ([force(k) for k in ("forward_N", "backward_N", "max_N", "min_N")] + [f["axis_deg"]]
            + [scale.moment(m[k]) for k in ("forward_Nm", "backward_Nm", "max_Nm")]
            + [force("vertical_N"), force("horizontal_N"), scale.moment(m["min_Nm"]),
               m["axis_deg"], scale.moment(m["vertical_Nm"]), scale.moment(m["horizontal_Nm"])])


#: the columns of a part's table: (record key without unit, heading)
_PART_COLUMNS = {
    "force": ("F", ("forward", "fwd"), ("backward", "bwd"), ("max", "max"), ("min", "min"),
              ("vertical", "vertical"), ("horizontal", "horizontal")),
    "moment": ("M", ("forward", "fwd"), ("backward", "bwd"), ("max", "max"), ("min", "min"),
               ("vertical", "V (pitch)"), ("horizontal", "H (yaw)")),
}


def part_headers(scale, part):
    """Headings of the force or moment table of the orders."""
    symbol, *columns = _PART_COLUMNS[part]
    label = scale.force_label if part == "force" else scale.moment_label
    headings = [f"{symbol} {heading} ({label})" for _, heading in columns]
    return ["Engine", "Order"] + headings[:4] + [f"{symbol} axis (°)"] + headings[4:]


def part_rows(name, records, unit_n, scale, part):
    """Text rows of the force (or moment) table: every order where it is not zero, with its
    forward, backward, max, min, axis and vertical and horizontal amplitudes."""
    unit = "N" if part == "force" else "Nm"
    shown = (lambda v: scale.force(v, unit_n)) if part == "force" else scale.moment
    _, *columns = _PART_COLUMNS[part]
    rows = []
    for record in records:
        values = record[part]
        if values[f"max_{unit}"] == 0.0:
            continue
        cells = [figure(shown(values[f"{key}_{unit}"])) for key, _ in columns]
        rows.append([name, str(record["order"])] + cells[:4] + [_axis_text(values["axis_deg"])]
                    + cells[4:])
    return rows


def order_parts(entries, scale, samples):
    """The force and moment tables of the orders, as (title, headers, rows, note), for
    ``entries`` of (name, order records, m_rec·r·ω²·n)."""
    unit = ("per cylinder, in units of m_rec·r·ω²·n" if not scale.absolute
            else f"in {scale.units}")
    forces = [row for name, records, unit_n in entries
              for row in part_rows(name, records, unit_n, scale, "force")]
    moments = [row for name, records, unit_n in entries
               for row in part_rows(name, records, unit_n, scale, "moment")]
    top = entries and len(entries[0][1])
    return [
        (f"Free forces by order ({unit})", part_headers(scale, "force"), forces,
         f"No free force in any order up to {top}." if not forces else
         "Orders not listed are zero. fwd turns with the crank, bwd against it; max and min are "
         "the semi-axes of the order's ellipse, axis the direction of max from the reference axis "
         "(— where the ellipse is a circle); vertical and horizontal are the amplitudes of the "
         f"components along the engine's vertical and across it ({samples} samples a "
         "revolution)."),
        (f"Free moments by order (in {scale.moment_label})", part_headers(scale, "moment"), moments,
         "V (pitch) is the moment of the vertical forces, about the horizontal axis across the "
         "crankshaft (marine M1V, M2V); H (yaw) the moment of the horizontal forces, about the "
         "vertical (M1H, M2H)." if moments else f"No free moment in any order up to {top}."),
    ]


def _intervals(firing):
    mean = sum(firing["intervals_deg"]) / len(firing["intervals_deg"])
    if firing["uniform"]:
        return f"every {mean:g}"
    return f"{min(firing['intervals_deg']):.1f} to {max(firing['intervals_deg']):.1f}"


def _shortened(name, length=24):
    """A name short enough for a column heading."""
    return name if len(name) <= length else name[: length - 1].rstrip() + "…"


#: a share of the reference above this many per cent is shown as a ratio (×62, not 6200 %)
PERCENT_LIMIT = 1000.0


def _share_text(percent):
    if percent is None:
        return "n/a"
    if percent > PERCENT_LIMIT:
        return f"×{significant(percent / 100.0, 3)}"
    return f"{percent:.1f}"


def _main_text(main, shown, largest):
    """The main order of a part in words: "2: 0.2147, vertical"."""
    if main is None:
        # what is left lies in orders above those analysed
        return "— (above the orders analysed)" if largest else "—"
    value = main.get("max_N", main.get("max_Nm"))
    return f"{main['order']}: {figure(shown(value))}, {main['direction']}"


def compare_parts(comparison, scale):
    """The comparison as (title, headers, rows, note) tables, for any renderer; rendered from
    the records of ``Comparison.to_dict``."""
    records = comparison.to_dict()["engines"]
    units = [r.per_cylinder_unit_n for r in comparison.results]
    entries = [(record["name"], record["orders"], unit_n) for record, unit_n in zip(records, units)]
    firing = [[record["name"], str(record["cylinders"]), str(record["cycle"]), record["frame"],
               "-".join(map(str, record["firing"]["order"])), _intervals(record["firing"])]
              for record in records]
    # per cylinder beside per-cylinder figures (Tanaka's), in newtons beside absolute ones
    share = "percent_of_reference_absolute" if scale.absolute else "percent_of_reference"
    summary = []
    for record, unit_n in zip(records, units):
        force = lambda v, u=unit_n: scale.force(v, u)  # noqa: E731
        summary.append([record["name"], figure(force(record["counterweighted_resultant_N"])),
                        _share_text(record[share]),
                        _main_text(record["main_force_order"], force,
                                   record["counterweighted_resultant_N"]),
                        figure(scale.moment(record["counterweighted_moment_Nm"])),
                        _main_text(record["main_moment_order"], scale.moment,
                                   record["counterweighted_moment_Nm"])])
    notes = ["%: of the reference engine's largest force"
             + (", in newtons." if scale.absolute else ", per cylinder (Tanaka's Part III)."),
             "Largest: the resultant's largest magnitude over a revolution, all orders; main "
             "order: the order with the largest ellipse, its max and direction (rotating: a "
             "circle, turning with the crank (forward) or against it (backward)). A turning crank's ideal counterweight has taken the forward first order of "
             "force and moment away (a rotary's crank does not turn), and where a crankshaft "
             "turns against the first, its counterweights the backward first order too."]
    if any(record[share] is None for record in records):
        notes.append("n/a: the reference engine has no resultant to compare with.")
    if any((record[share] or 0.0) > PERCENT_LIMIT for record in records):
        notes.append(f"×: a multiple of the reference's resultant, where it is above "
                     f"{PERCENT_LIMIT:.0f} %.")
    fl, ml = scale.force_label, scale.moment_label
    return order_parts(entries, scale, comparison.samples) + _pru_parts(records, scale) + [
        ("Firing", ["Engine", "Cyl", "Cycle", "Frame", "Firing order", "Intervals (°)"], firing, ""),
        ("Largest free force and moment (after an ideal crankshaft counterweight)",
         ["Engine", f"Largest F ({fl})", f"% of {_shortened(comparison.reference.engine.name)}",
          f"Main F order: max ({fl}), direction", f"Largest M ({ml})",
          f"Main M order: max ({ml}), direction"],
         summary, " ".join(notes)),
    ]


def _pru_text(entry, side):
    """One PRU cell: "124.4 (likely)"."""
    return f"{figure(entry[f'{side}_Nm_per_kW'])} ({entry[f'{side}_class']})"


def _pru_parts(records, scale):
    """The power related unbalance table, when any engine has a power: per engine its power
    and, per order judged, the pitching and yawing moments' PRU with their class; the first
    order as the crank stands and with its rotating masses balanced."""
    with_power = [r for r in records if r["pru"] is not None]
    if not with_power:
        # a power given at another speed than analysed is worth a word; no power at all is not
        notes = sorted({r["pru_note"] for r in records if "given at" in (r["pru_note"] or "")})
        return [("Power related unbalance", [], [], "Not computed: " + "; ".join(notes) + ".")] \
            if notes else []
    orders = [e["order"] for e in with_power[0]["pru"]["orders"]]
    headers = ["Engine", "Power (kW)"]
    for k in orders:
        headers += [f"M{k}V", f"M{k}H"]
        if k == 1:
            headers += ["M1V balanced", "M1H balanced"]
    rows = []
    for record in records:
        pru = record["pru"]
        if pru is None:
            rows.append([record["name"], "—"] + ["—"] * (len(headers) - 2))
            continue
        source = {"given": "", "option": " (--power)", "indicated": " (indicated)"}
        row = [record["name"], figure(pru["power_kW"]) + source[pru["power_source"]]]
        for entry in pru["orders"]:
            row += [_pru_text(entry, "vertical"), _pru_text(entry, "horizontal")]
            if entry["order"] == 1:
                balanced = pru["first_order_balanced"]
                row += (["—", "—"] if balanced is None else
                        [_pru_text(balanced, "vertical"), _pru_text(balanced, "horizontal")])
        rows.append(row)
    classes = with_power[0]["pru"]["classes"]
    bounds = ", ".join(f"below {c['below_Nm_per_kW']:g} {c['class']}" for c in classes[:-1])
    bounds += f", above {classes[-2]['below_Nm_per_kW']:g} {classes[-1]['class']}"
    missing = [r["name"] for r in records if r["pru"] is None]
    note = ("PRU = external moment / engine power (N·m/kW) at the speed analysed, and the need "
            "for a moment compensator: " + bounds + ". MkV is the "
            "pitching moment of order k, MkH the yawing one; M1 as the crank stands, and "
            "'balanced' with counterweights for the rotating masses (balance factor 0)."
            + (" —: " + "; ".join(sorted({r["pru_note"] for r in records if r["pru"] is None}))
               + "." if missing else "")
            + (" 'Balanced' is not given for a rotary (its crank does not turn) or an engine with "
               "several crankshafts (each would need "
               "its own counterweights)." if any(r["pru"] is not None and
                                                 r["pru"]["first_order_balanced"] is None
                                                 for r in records) else ""))
    return [("Power related unbalance (N·m/kW, and the need for a compensator)", headers, rows,
             note)]


def compare_tables(comparison, scale, fmt):
    """The comparison as text or Markdown: orders of every engine, then a summary."""
    heading = "#### " if fmt == "markdown" else ""
    safe = _safe(fmt)
    out = []
    for title, headers, rows, note in compare_parts(comparison, scale):
        out += [f"{heading}{safe(title)}", ""] + ([render(headers, rows, fmt), ""] if rows else [])
        if note:
            out += [note, ""]
    return "\n".join(out)


def list_table(engines):
    rows = [[e.config_path, e.name, str(e.n_cylinders), str(e.cycle), e.frame, e.source]
            for e in engines]
    return render(["Config", "Name", "Cyl", "Cycle", "Frame", "Source"], rows, "table")


def list_tables(groups):
    """``balance list``: one table per folder, under its heading. ``groups`` is a sequence of
    (heading, engines), in the order to print them."""
    blocks = []
    for heading, engines in groups:
        count = len(engines)
        blocks.append(f"{heading} ({count} engine{'s' if count != 1 else ''})\n{list_table(engines)}")
    return "\n\n".join(blocks)


def _mm(length_m):
    return f"{m_to_mm(length_m):g} mm"


def _inertia(value):
    return f"{value:.6g} kg·m²"


def _parts_lines(engine):
    """The part data and what the two-point rod model keeps of the rods' inertia."""
    lines = []
    parts = engine.parts
    if parts is not None:
        lines.append(f"  parts:         piston {kg_to_g(parts.piston_kg):g} g; rod {kg_to_g(parts.rod_kg):g} g, "
                     f"centre of gravity {_mm(parts.rod_cg_m)} from the big end, J {_inertia(parts.rod_inertia_kgm2)}"
                     + (f"; link rod {kg_to_g(parts.link_kg):g} g, {_mm(parts.link_cg_m)}, "
                        f"j {_inertia(parts.link_inertia_kgm2)}" if parts.link_kg else "")
                     + f"; crank {kg_to_g(parts.crank_kg):g} g")
    rods = sorted({c.rod_inertia_kgm2 for c in engine.cylinders if not c.is_link})
    links = sorted({c.rod_inertia_kgm2 for c in engine.cylinders if c.is_link})
    if any(rods) or any(links) or engine.shaft_inertia_kgm2:
        lines.append("  rod inertia:   left out by the point masses: "
                     + ("master rods" if links else "rods") + " C = J − M·H·(L − H) = "
                     + ", ".join(_inertia(c) for c in rods)
                     + (f"; link rods c = j − m·h·(l − h) = {', '.join(_inertia(c) for c in links)}"
                        if links else "")
                     + f"; crankshaft and flywheel {_inertia(engine.shaft_inertia_kgm2)}")
    if engine.gas is not None:
        gas = engine.gas
        lines.append(f"  gas:           bore {_mm(gas.bore_m)}, compression ratio {gas.compression_ratio:g}"
                     + ("" if gas.imep_pa is None else f", imep {pa_to_bar(gas.imep_pa):g} bar"))
    return lines


def _crankshaft_lines(engine):
    """The crankshafts of an engine with several: position, sense of turning and gear phase."""
    if not engine.has_several_crankshafts:
        return []
    lines = []
    for i, shaft in enumerate(engine.crankshafts, 1):
        turning = "with the first" if shaft.direction == 1 else "against the first"
        lines.append(f"  crankshaft {i}:  at ({_mm(shaft.x_m)}, {_mm(shaft.y_m)}), turning "
                     f"{turning}, phase {math.degrees(shaft.phase_rad):g}°"
                     + (" (the reference)" if i == 1 else ""))
    if engine.has_opposed_pistons:
        lines.append("  opposed:       TDC is the inner dead centre (the bore at its smallest)")
    return lines


def _as_built_show_lines(engine):
    """``balance show``'s lines for the counterweights and balancer shafts as built."""
    lines = []
    for weight in engine.counterweights:
        lines.append(f"  counterweight: throw {weight.throw + 1}, m·ρ {figure(weight.mass_radius_kgm)} "
                     f"kg·m at {math.degrees(weight.angle_rad):g}° from its pin, z "
                     f"{_mm(engine.counterweight_z_m(weight))}")
    for shaft in engine.balancer_shafts:
        masses = "; ".join(f"m·e {figure(m.mass_radius_kgm)} kg·m at {math.degrees(m.angle_rad):g}°, "
                           f"z {_mm(engine.balancer_z_m(m))}" for m in shaft.masses)
        lines.append(f"  shaft:         ratio {shaft.ratio:+d}, axis lateral {_mm(shaft.lateral_m)}, "
                     f"vertical {_mm(shaft.vertical_m)}; {masses}")
    return lines


def show_table(engine, firing):
    """One engine, one row per cylinder, with the engine's data above."""
    knuckles = sorted({c.knuckle_kg for c in engine.cylinders if c.is_link})
    header = [
        plain_text(engine.name),
        f"  source:        {plain_text(engine.source) or '-'}",
        f"  config:        {plain_text(engine.config_path)}",
        f"  cycle:         {engine.cycle}-stroke, frame {engine.frame}, "
        f"{rad_s_to_rpm(engine.speed_rad_s):g} rpm",
        f"  crank radius:  {_mm(engine.crank_radius_m)}, rod {_mm(engine.rod_length_m)}, "
        f"pin offset {_mm(engine.pin_offset_m)}",
        f"  vertical:      {wrap_degrees(math.degrees(engine.vertical_axis_rad)):g}° from the reference axis "
        f"({engine.vertical_origin})",
        f"  masses:        reciprocating {kg_to_g(engine.mean_reciprocating_kg):g} g mean per "
        f"cylinder, rotating {kg_to_g(engine.rotating_kg):g} g and crank "
        f"{kg_to_g(engine.crank_kg):g} g per throw"
        + "".join(f", knuckle {kg_to_g(kg):g} g per link rod" for kg in knuckles),
        *_parts_lines(engine),
        *_crankshaft_lines(engine),
        *_as_built_show_lines(engine),
        f"  firing:        {'-'.join(map(str, firing.order))} "
        f"({'given' if firing.given else 'most uniform the crank allows'})",
        f"  intervals (°): {', '.join(f'{i:.2f}' for i in firing.intervals_deg)}",
        "",
    ]
    offsets = any(c.pin_offset_m is not None and c.pin_offset_m != engine.pin_offset_m
                  for c in engine.cylinders)
    several = engine.has_several_crankshafts
    rows = []
    for c in engine.cylinders:
        rod = engine.rod_type(c)
        if c.is_link:
            rod = (f"link on {c.master} ({_mm(c.link_length_m)}, knuckle {_mm(c.knuckle_radius_m)} "
                   f"at {math.degrees(c.knuckle_angle_rad):g}°)")
        elif c.is_opposed:
            rod = f"opposed: throw {c.opposed_throw + 1}, {kg_to_g(c.opposed_reciprocating_kg):g} g"
        bank = math.degrees(engine.bank_angles_rad[c.bank])
        throw = str(c.throw + 1) + (f" (shaft {engine.throws[c.throw].crankshaft + 1})"
                                    if several else "")
        row = [str(c.number), f"{c.bank + 1} ({bank:g}°)", throw,
               f"{math.degrees(engine.throws[c.throw].phase_rad):g}", f"{m_to_mm(c.z_m):g}",
               f"{kg_to_g(c.reciprocating_kg):g}", rod]
        if offsets:
            row.append(f"{m_to_mm(engine.pin_offset_of(c)):g}")
        rows.append(row + [f"{round_degrees(firing.tdc_deg[c.number], 2):.2f}"])
    table = render(["Cyl", "Bank (angle)", "Throw", "Phase (°)", "z (mm)", "Recip. (g)", "Rod"]
                   + (["Pin offset (mm)"] if offsets else []) + ["TDC (°)"], rows, "table")
    return "\n".join(header) + table + "\n"


#: how the SI records of counterweights and shafts are shown: (key, column heading, text)
WEIGHT_COLUMNS = [
    ("throw", "Throw", lambda v: "-" if v is None else str(v)),
    ("z_m", "z (mm)", lambda v: f"{m_to_mm(v):g}"),
    ("mass_kg", "Mass (kg)", figure),
    ("radius_m", "Radius (mm)", lambda v: f"{m_to_mm(v):g}"),
    ("angle_deg", "Angle (° from throw 1)", lambda v: f"{round_degrees(v, 2):.2f}"),
]
#: one row per counterweight as built (``Balance.to_dict``'s ``as_built.counterweights``)
BUILT_WEIGHT_COLUMNS = [
    ("throw", "Throw", str),
    ("z_m", "z (mm)", lambda v: f"{m_to_mm(v):g}"),
    ("mass_radius_kgm", "m·ρ (kg·m)", figure),
    ("mass_kg", "Mass (kg)", lambda v: "-" if v is None else figure(v)),
    ("radius_m", "Radius (mm)", lambda v: "-" if v is None else f"{m_to_mm(v):g}"),
    ("angle_deg", "Angle (° from its pin)", lambda v: f"{round_degrees(v, 2):.2f}"),
]
#: one row per mass of a balancer shaft (``Balance.to_dict``'s ``balancer_shafts``, each mass
#: record with its shaft's ``shaft`` number, ``speed_ratio`` and ``offset_m``; None on the
#: shaft's second mass and after, so that a shaft reads as one block)
SHAFT_COLUMNS = [
    ("shaft", "Shaft", lambda v: "" if v is None else str(v)),
    ("speed_ratio", "Speed ratio", lambda v: "" if v is None else f"{v:+d}"),
    ("speed_ratio", "Turning",
     lambda v: "" if v is None else "with the crank" if v > 0 else "against the crank"),
    ("offset_m", "Offset lateral, vertical (mm)",
     lambda v: "" if v is None else f"{m_to_mm(v['lateral']):g}, {m_to_mm(v['vertical']):g}"),
    ("mass_eccentricity_kgm", "m·e (kg·m)", figure),
    ("phase_deg", "Angle at θ = 0 (°)", lambda v: f"{round_degrees(v, 2):.2f}"),
    ("z_m", "z (mm)", lambda v: f"{m_to_mm(v):g}"),
]


def _shaft_rows(shafts):
    """The mass records of ``balancer_shafts``, each with its shaft's columns on its first."""
    rows = []
    for number, shaft in enumerate(shafts, 1):
        for i, mass in enumerate(shaft["masses"]):
            first = i == 0
            rows.append({**mass, "shaft": number if first else None,
                         "speed_ratio": shaft["speed_ratio"] if first else None,
                         "offset_m": shaft["offset_m"] if first else None})
    return rows


def _rolling_lines(record, scale, fmt):
    """The rolling moment the shafts' offsets leave, or why there is none."""
    shafts = record["balancer_shafts"]
    if all(s["offset_m"]["lateral"] == 0 and s["offset_m"]["vertical"] == 0 for s in shafts):
        which = "the proposed shafts" if "as_built" in record else "the shafts"
        return [f"Rolling moment about the crank axis of {which}: none; they sit on the crank "
                "axis, and a centred shaft's force passes through it.", ""]
    rows = []
    for total in record["shaft_rolling_moments"]:
        mine = [(n, s) for n, s in enumerate(shafts, 1) if s["order"] == total["order"]]
        if all(s["offset_m"]["lateral"] == 0 and s["offset_m"]["vertical"] == 0 for _, s in mine):
            continue
        for number, shaft in mine:
            m = shaft["rolling_moment"]
            rows.append([str(total["order"]), f"{number} ({shaft['speed_ratio']:+d})",
                         figure(scale.moment(m["amplitude_Nm"])),
                         f"{round_degrees(m['phase_deg'], 2):.2f}"])
        if len(mine) > 1:
            rows.append([str(total["order"]),
                         " and ".join(f"{n}" for n, _ in mine) + " together",
                         figure(scale.moment(total["amplitude_Nm"])),
                         f"{round_degrees(total['phase_deg'], 2):.2f}"])
    return ["Rolling moment about the crank axis from the shafts' forces at their offsets "
            "(M = amplitude·cos(kθ − phase), positive with rotation, as the frame torque of "
            "balance torque; a centred shaft makes none, and orders whose shafts are all "
            "centred are left out):", "",
            render(["Order", "Shaft", f"Amplitude ({scale.moment_label})", "Phase (°)"], rows, fmt),
            ""]


def _left(name, stage, records, n_unit, scale, fmt):
    """The orders left after ``stage`` (forces, then moments), or the words that nothing is."""
    forces = part_rows(name, records, n_unit, scale, "force")
    moments = part_rows(name, records, n_unit, scale, "moment")
    if not forces and not moments:
        return [f"After the {stage}, nothing is left up to order {len(records)}: every force and "
                "moment is zero.", ""]
    out = [f"Left after the {stage}:", ""]
    for rows, part, none in ((forces, "force", "no force"), (moments, "moment", "no moment")):
        out += ([render(part_headers(scale, part), rows, fmt), ""] if rows
                else [f"({none} in any order up to {len(records)})", ""])
    return out


def _record_table(records, columns, fmt):
    headers = [label for _, label, _ in columns]
    rows = [[shown(record[key]) for key, _, shown in columns] for record in records]
    return render(headers, rows, fmt)


def _plane_text(weight):
    if weight["throw"]:
        return f"throw {weight['throw']}"
    return f"z = {m_to_mm(weight['z_m']):g} mm"


def _as_built_lines(record, n_unit, scale, fmt):
    """The counterweights and shafts the configuration gives as built, and what they leave."""
    built = record.get("as_built")
    if built is None:
        return []
    weights, shafts = built["counterweights"], built["balancer_shafts"]
    out = [f"As built: {len(weights)} counterweight{'' if len(weights) == 1 else 's'} and "
           f"{len(shafts)} balancer shaft{'' if len(shafts) == 1 else 's'} (from the "
           "configuration). Everything proposed below is in addition to them.", ""]
    if weights:
        out += [_record_table(weights, BUILT_WEIGHT_COLUMNS, fmt), ""]
    if shafts:
        out += ["Balancer shafts as built (each mass's m·e, its angle from the reference axis when "
                "θ = 0, positive with the crank's rotation — the file gives a shaft turning "
                "against the crank its angle in its own sense, the negative of this — and its "
                "axial position):", "",
                _record_table(_shaft_rows(shafts), SHAFT_COLUMNS, fmt), ""]
        rolling = [[f"{n} ({s['speed_ratio']:+d})", str(s["rolling_moment"]["order"]),
                    figure(scale.moment(s["rolling_moment"]["amplitude_Nm"])),
                    f"{round_degrees(s['rolling_moment']['phase_deg'], 2):.2f}"]
                   for n, s in enumerate(shafts, 1)
                   if s["offset_m"]["lateral"] or s["offset_m"]["vertical"]]
        if rolling:
            out += ["Rolling moment about the crank axis of the shafts as built, from their "
                    "forces at their offsets (M = amplitude·cos(kθ − phase), positive with "
                    "rotation; in balance torque's frame torque):", "",
                    render(["Shaft", "Order", f"Amplitude ({scale.moment_label})", "Phase (°)"],
                           rolling, fmt), ""]
    return out + _left(record["name"], "counterweights and shafts as built", built["orders"],
                       n_unit, scale, fmt)


def balance_tables(balances, scale, fmt):
    """``balance counterweight`` as text or Markdown, engine by engine, rendered from the
    records of ``Balance.to_dict``."""
    heading = "#### " if fmt == "markdown" else ""
    safe = _safe(fmt)
    unit = "per cylinder, × m_rec·r·ω²·n" if not scale.absolute else scale.units
    out = []
    for b in balances:
        record = b.to_dict()
        n_unit = b.engine.per_cylinder_unit_n
        factor = record["balance_factor"]
        how = ("cancelling the forward first order" if factor is None else
               f"balance factor {factor:g}: rotating masses plus {factor:g} of the reciprocating "
               "ones per throw")
        carrier = "crankcase" if record["frame"] == "rotary" else "crank"
        out += [f"{heading}{safe(record['name'])}: counterweights on the {carrier}, {how}", ""]
        out += _as_built_lines(record, n_unit, scale, fmt)
        if all(w["mass_kg"] == 0.0 for w in record["counterweights"]):
            out += [f"None needed: the forward first order is already zero on the {carrier}.", ""]
        else:
            if "as_built" in record:
                out += ["Counterweights to add to those built:", ""]
            out += [_record_table(record["counterweights"], WEIGHT_COLUMNS, fmt), ""]
        a = record["antivibrateur"]
        if a is not None:
            out += [f"Antivibrateur on the crank pin, turning at twice crank speed with the crank: "
                    f"M·e = {figure(a['mass_eccentricity_kgm'])} kg·m (M = {figure(a['mass_kg'])} "
                    f"kg at e = {m_to_mm(a['eccentricity_m']):g} mm), at "
                    f"{round_degrees(a['phase_deg'], 2):.2f}° when θ = 0; the counterweights above "
                    "include its mass.", ""]
        first = record["residual"]["orders"][0]
        f, m = first["force"], first["moment"]
        out += [f"First order left: forward {figure(scale.force(f['forward_N'], n_unit))}, "
                f"backward {figure(scale.force(f['backward_N'], n_unit))} ({unit}; no counterweight "
                f"touches the backward part); moment {figure(scale.moment(m['forward_Nm']))} "
                f"forward, {figure(scale.moment(m['backward_Nm']))} backward "
                f"({scale.moment_label}).", ""]
        out += _left(record["name"], "counterweights", record["residual"]["orders"], n_unit,
                     scale, fmt)
        if "after_shafts" in record and not record["balancer_shafts"]:
            out += ["Balancer shafts: none needed; the orders asked for are already zero.", ""]
        elif "after_shafts" in record:
            # "as built": one shaft per speed ratio with its masses; on an engine that has
            # shafts already, these are more of them
            what = ("Balancer shafts to add to those built" if "as_built" in record
                    else "Balancer shafts as built")
            out += [f"{what} (each mass's m·e, its angle from the reference axis "
                    "when θ = 0, positive with rotation, and its axial position):", "",
                    _record_table(_shaft_rows(record["balancer_shafts"]), SHAFT_COLUMNS, fmt), ""]
            built = {s["order"] for s in record["balancer_shafts"]}
            idle = [k for k in record.get("shaft_orders", []) if k not in built]
            if idle:
                out += [f"Order{'s' if len(idle) > 1 else ''} {', '.join(map(str, idle))}: no "
                        "shaft needed, already zero.", ""]
            out += _rolling_lines(record, scale, fmt)
            out += _left(record["name"], "shafts", record["after_shafts"]["orders"], n_unit,
                         scale, fmt)
            left = [k for k in record.get("shaft_orders", [])
                    if record["after_shafts"]["orders"][k - 1]["moment"]["max_Nm"] > 0.0]
            if left and len(record["counterweights"]) < 2:
                out += [f"One correction plane cannot cancel a couple: order"
                        f"{'s' if len(left) > 1 else ''} {', '.join(map(str, left))} keep"
                        f"{'' if len(left) > 1 else 's'} a free moment. Give two planes "
                        "(--planes A,B, throws or axial positions) to put shafts' masses in "
                        "both.", ""]
        if "test_masses_kg" in record:
            rows = [[str(i + 1), figure(m)] for i, m in enumerate(record["test_masses_kg"])]
            out += ["Balancing-machine test masses (hang on each crank pin; the crankshaft's own "
                    "unbalance excluded):", "",
                    render(["Throw", "Mass (kg)"], rows, fmt), ""]
    return "\n".join(out)


def balance_summary(balances):
    """One row per engine of ``balance counterweight`` with default planes: (headers, rows)."""
    rows = []
    for b in balances:
        record = b.to_dict()
        n_unit = b.engine.per_cylinder_unit_n
        first = record["residual"]["orders"][0]["force"]
        weights = "; ".join(
            f"{figure(c['mass_kg'])} kg at {round_degrees(c['angle_deg'], 1):.1f}° ({_plane_text(c)})"
            for c in record["counterweights"])
        rows.append([record["name"], weights, figure(first['forward_N'] / n_unit),
                     figure(first['backward_N'] / n_unit),
                     figure(record['residual']['largest_resultant_N'] / n_unit)])
    headers = ["Engine", "Counterweights at crank radius", "1st order left fwd (per cyl)",
               "1st order bwd (per cyl)", "Largest resultant left (per cyl)"]
    return headers, rows


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
        for i, (name, series) in enumerate((("inertia", r.inertia), ("gas", r.gas),
                                            ("total", r.total), ("frame", r.frame))):
            values = (["—"] * 4 if series is None else
                      [figure(scale.moment(v)) for v in (series.mean, series.max, series.min,
                                                         series.range)])
            rows.append([r.engine.name if i == 0 else "", name] + values)
        mu = r.reduced_mass
        masses.append([r.engine.name] + [_inertia_text(v, mu) for v in
                                         (mu.mean_kgm2, mu.min_kgm2, mu.max_kgm2)])
    ml = scale.moment_label
    return ((["Engine", "Torque", f"Mean ({ml})", f"Max ({ml})", f"Min ({ml})", f"Range ΔC ({ml})"],
             rows),
            (["Engine", "Mean μ (kg·m²)", "Min μ (kg·m²)", "Max μ (kg·m²)"], masses))


def _value_text(value):
    if isinstance(value, float):
        return f"{value:.9g}"
    if isinstance(value, list):
        return "-".join(map(str, value))
    return str(value)


def _in_units(quantity, value, scale):
    """A regression value in ``scale``'s units: forces (``*_N``) and moments (``*_Nm``) only."""
    if not isinstance(value, float):
        return value
    if quantity.endswith("_Nm"):
        return scale.moment(value)
    if quantity.endswith("_N"):
        return scale.force(value, 1.0)
    return value


def regression_tables(regression, fmt, scale=None):
    """The regression table as text or Markdown: what moved, then engines added and removed;
    forces and moments in ``scale``'s units (default N and N·m)."""
    scale = Scale(True, "N") if scale is None else scale
    heading = "### " if fmt == "markdown" else ""
    safe = _safe(fmt)
    checked = len(regression.checked)
    if not regression.moved:
        return (f"{heading}balance regress: nothing moved beyond tolerance ({checked} engine"
                f"{'s' if checked != 1 else ''} checked against {safe(regression.baseline_path)})\n")
    moved_engines = len({row.engine for row in regression.rows})
    out = [f"{heading}balance regress: {len(regression.rows)} quantities moved in {moved_engines} "
           f"of {checked} engines; {len(regression.added)} added, {len(regression.removed)} "
           f"removed (baseline {safe(regression.baseline_path)})", ""]
    if regression.rows:
        rows = []
        for row in regression.rows:
            change, relative = row.change, row.relative_change
            shown = lambda v, q=row.quantity: _in_units(q, v, scale)  # noqa: E731
            rows.append([row.engine, "-" if row.order is None else str(row.order), row.quantity,
                         _value_text(shown(row.baseline)), _value_text(shown(row.now)),
                         "-" if change is None else f"{shown(change):+.3g}",
                         "-" if relative is None else f"{100 * relative:+.3g} %",
                         "-" if row.tolerance is None else f"{shown(row.tolerance):.3g}"])
        out += [render(["Engine", "Order", "Quantity", "Baseline", "Now", "Change", "Relative",
                        "Tolerance"], rows, fmt), ""]
    for title, names in (("Engines added (not in the baseline)", regression.added),
                         ("Engines removed (in the baseline, not now)", regression.removed)):
        if names:
            out += [f"{title}:", ""] + [f"- {safe(n)}" for n in names] + [""]
    out.append(f"Units: {scale.units} for *_N and {scale.moment_label} for *_Nm, degrees for "
               "*_deg; change is now − baseline. Update the baseline on purpose with --update.")
    return "\n".join(out) + "\n"


def _torque_rows(result, scale):
    rows = []
    for name, series in (("inertia", result.inertia), ("gas", result.gas), ("total", result.total),
                         ("tilting", result.tilting), ("frame", result.frame)):
        if series is None:
            continue
        rows.append([name] + [figure(scale.moment(v)) for v in (series.mean, series.max,
                                                                 series.min, series.range)])
    return rows


def _order_table(series, scale, fmt, largest):
    """The orders of a torque above a thousandth of its largest one."""
    rows = [[f"{k:g}", figure(scale.moment(c)), figure(scale.moment(s)),
             figure(scale.moment(math.hypot(c, s))), f"{round_degrees(d['phase_deg'], 1):.1f}"]
            for (k, c, s), d in zip(series.orders, series.to_dict()["orders"])
            if math.hypot(c, s) >= 1e-3 * largest and largest > 0]
    ml = scale.moment_label
    return render(["Order", f"cos ({ml})", f"sin ({ml})", f"Amplitude ({ml})", "Phase (°)"], rows, fmt)


def _guide_force_lines(guide, scale, fmt):
    """The H-type and X-type guide-force moments by order (MAN B&W project guides, 17.05)."""
    ml = scale.moment_label
    h, x = guide.h_type.to_dict()["orders"], guide.x_type.to_dict()["orders"]
    largest = max([o["amplitude_Nm"] for o in h + x] + [0.0])
    def phase(order):
        # a vanished order has no phase to print
        return f"{round_degrees(order['phase_deg'], 1):.1f}" if order["amplitude_Nm"] else "-"

    rows = [[f"{a['order']:g}", figure(scale.moment(a["amplitude_Nm"])), phase(a),
             figure(scale.moment(b["amplitude_Nm"])), phase(b)]
            for a, b in zip(h, x)
            if largest > 0 and max(a["amplitude_Nm"], b["amplitude_Nm"]) >= 1e-3 * largest]
    return [f"Guide-force moments (the couples of the pistons' (crossheads') guide forces with the main "
            f"bearings; H-type their sum, X-type their bimoment about the engine's centre over "
            f"L = {guide.lever_m:.4g} m, the rod length; amplitude·cos(kθ − phase); orders below "
            "a thousandth of the largest left out):", "",
            render(["Order", f"H-type ({ml})", "H phase (°)", f"X-type ({ml})", "X phase (°)"],
                   rows or [["-", "0", "-", "0", "-"]], fmt), ""]


def torque_tables(results, scale, fmt):
    """``balance torque`` as text or Markdown, engine by engine."""
    heading = "#### " if fmt == "markdown" else ""
    safe = _safe(fmt)
    ml, fl = scale.moment_label, scale.force_label
    out = []
    for r in results:
        engine = r.engine
        mu = r.reduced_mass
        out += [f"{heading}{safe(engine.name)}: torques at {rad_s_to_rpm(engine.speed_rad_s):g} rpm "
                f"({engine.cycle}-stroke, period {r.period_deg:g}°)", "",
                f"Reduced mass μ (kinetic energy ½·μ·ω²): mean {_inertia_text(mu.mean_kgm2, mu)}, "
                f"min {_inertia_text(mu.min_kgm2, mu)}, max {_inertia_text(mu.max_kgm2, mu)} "
                "kg·m².", "",
                render(["Torque", f"Mean ({ml})", f"Max ({ml})", f"Min ({ml})", f"Range ΔC ({ml})"],
                       _torque_rows(r, scale), fmt), ""]
        if r.indicated_power_kw is not None:
            out += [f"Indicated power (mean gas torque × ω): {figure(r.indicated_power_kw)} kW.", ""]
        if r.crankshafts:
            out += ["Each crankshaft's torque (gas and inertia of the parts it drives, positive in "
                    "its own sense of turning; geared 1:1, their sum is the total on the first):",
                    "", render(["Crankshaft", "Turning", f"Mean ({ml})", f"Max ({ml})", f"Min ({ml})",
                                f"Range ΔC ({ml})"],
                               [[str(c.number), "with the first" if c.direction == 1 else
                                 "against the first"]
                                + [figure(scale.moment(v)) for v in (c.torque.mean, c.torque.max,
                                                                     c.torque.min, c.torque.range)]
                                for c in r.crankshafts], fmt), ""]
        largest = max(math.hypot(c, s) for _, c, s in r.total.orders) if r.total.orders else 0.0
        out += [f"Orders of the total torque ({'gas and inertia' if r.gas else 'inertia only'}; "
                "amplitude·cos(kθ − phase); orders below a thousandth of the largest left out):", "",
                _order_table(r.total, scale, fmt, largest), ""]
        rows = []
        for pin in r.pins:
            magnitude = np.abs(pin.force_n)
            rows.append([str(pin.throw)] + [figure(scale.force(v, 1.0)) for v in (
                pin.radial.mean, pin.tangential.mean, float(magnitude.max()), float(magnitude.min()))])
        bearings = [("main bearings", r.main_bearings)] + [
            (f"main bearings, crankshaft {c.number}", c.main_bearings) for c in r.crankshafts]
        for label, load in bearings:
            if load is None:
                continue
            magnitude = np.abs(load.force_n)
            rows.append([label, "-", "-", figure(scale.force(float(magnitude.max()), 1.0)),
                         figure(scale.force(float(magnitude.min()), 1.0))])
        out += ["Forces of the rods on the crank pins, and of the crankshaft on its main bearings "
                "together:", "",
                render(["Throw", f"Radial mean ({fl})", f"Tangential mean ({fl})", f"Largest ({fl})",
                        f"Smallest ({fl})"], rows, fmt), ""]
        if r.guide is not None:
            out += _guide_force_lines(r.guide, scale, fmt)
        elif engine.is_rotary:
            out += ["Guide-force moments: none on a rotary; its cylinders turn with the crankcase, "
                    "so the guide forces are the frame's own.", ""]
        if r.steadiness is not None:
            out += [steadiness_text(r.steadiness, r.flywheel_kgm2), ""]
    return "\n".join(out)


def _g4(value):
    # a closed form beyond a double is None in JSON, words here
    return value if isinstance(value, str) else f"{value:.4g}"


def steadiness_text(speed, flywheel_kgm2=None):
    """The speed and steadiness of an engine set, in one paragraph."""
    margoulis = {k: ("beyond 1e308" if v is None else v) for k, v in speed.to_dict().items()}
    flywheel = (f"a flywheel of {speed.inertia_kgm2:.5g} kg·m²" if speed.inertia_kgm2 > 0 else
                "no flywheel (the moving parts' own inertia)")
    text = (f"With {flywheel} and a {speed.load} load: speed "
            f"{margoulis['min_speed_rpm']:.2f} to {margoulis['max_speed_rpm']:.2f} rpm (mean "
            f"{margoulis['mean_speed_rpm']:.2f}), steadiness ω_m/(ω_max − ω_min) = "
            f"{_g4(margoulis['steadiness'])} integrated; Margoulis's closed forms (one harmonic of "
            f"order {speed.order:g}, ΔC = {margoulis['torque_range_Nm']:.4g} N·m): r_c = "
            f"{_g4(margoulis['r_c'])}, r_v = {_g4(margoulis['r_v'])}, r_h = {_g4(margoulis['r_h'])}.")
    if flywheel_kgm2 == 0.0:
        text += " The target steadiness needs no flywheel."
    elif flywheel_kgm2 is not None:
        text += f" The target steadiness needs a flywheel of {flywheel_kgm2:.5g} kg·m²."
    return text


def _coefficient_names(result):
    """The objective's coefficients that are not zero in every listed arrangement (all of
    them; a zero column says nothing), and whether any were left out."""
    names = [t.name for t in result.objective]
    shown = [n for n in names if any(a.coefficients[n] != 0.0 for a in result.arrangements)]
    return shown or names[:1], len(shown) < len(names)


def search_summary(result):
    """What was searched, how much, and whether the list is proved: a few lines of text."""
    what = "even firing" if result.even else f"every crank on a {result.step_deg:g}° grid"
    proof = ("exhaustive: no arrangement scores better than those listed" if result.exhaustive
             else "HEURISTIC local search: the best found, NOT proved optimal")
    lines = [
        f"{result.template.name} ({result.template.config_path or 'template'}): {what}; "
        f"objective {', '.join(str(t) for t in result.objective)}",
        f"{result.arrangements_total:,} arrangements with throw 1 at 0° "
        f"({result.firing_orders_per_crank} firing order{'s' if result.firing_orders_per_crank != 1 else ''} "
        f"a crank), {result.arrangements_distinct:,} distinct; {result.evaluated:,} cranks "
        f"evaluated, {result.pruned:,} skipped by bound ({result.elapsed_s:.2f} s, "
        f"{result.workers} worker{'s' if result.workers != 1 else ''})",
        f"Symmetries: {'; '.join(result.symmetries)}",
        proof + ("; more arrangements tie at the last score than were kept, so the tie-break "
                 "by firing order saw only the first found" if result.ties_truncated else ""),
    ]
    return lines


def _score_text(score):
    # four decimals read best at the usual sizes; a weight of 1e100 or 1e-10 makes a score
    # that they would print with 100 digits, or as 0.0000
    return f"{score:.4f}" if score == 0 or 1e-3 <= abs(score) < 1e6 else f"{score:.6g}"


def search_rows(result):
    """Ranking rows: rank, score, phases, firing order, intervals, coefficients, mirror."""
    names, _ = _coefficient_names(result)
    rows = []
    for a in result.arrangements:
        record = a.to_dict()
        rows.append([str(a.rank), _score_text(a.score),
                     " ".join(f"{round_degrees(p, 3):g}" for p in a.phases_deg),
                     "-".join(map(str, record["firing"]["order"])),
                     _intervals(record["firing"])]
                    + [f"{a.coefficients[n]:.4f}" for n in names]
                    + ["" if a.mirror_of is None else str(a.mirror_of)])
    headers = (["Rank", "Score", "Phases (°)", "Firing order", "Intervals (°)"] + names
               + ["Mirror of"])
    return headers, rows


def search_tables(result, comparison, scale, fmt):
    """The search as text or Markdown: what was done, the ranking, then the order table of
    every listed arrangement as ``compare`` prints it."""
    heading = "#### " if fmt == "markdown" else ""
    safe = _safe(fmt)
    out = [safe(line) + ("  " if fmt == "markdown" else "") for line in search_summary(result)]
    headers, rows = search_rows(result)
    out += ["", f"{heading}Best arrangements (coefficients: F_k in one throw's largest order-k "
            "force, M_k in that force × the mean throw pitch; H_k and X_k in one throw's order-k "
            "guide-force couple, X_k also per mean throw pitch)", "", render(headers, rows, fmt),
            ""]
    if _coefficient_names(result)[1]:
        out += ["The objective's other coefficients are 0 in every arrangement listed.", ""]
    if comparison is not None:
        out.append(compare_tables(comparison, scale, fmt))
    return "\n".join(out)


def family_parts(result, scale):
    """``balance family`` as (title, headers, rows, note), rendered from
    ``FamilyResult.to_dict``: one row per number of cylinders."""
    record = result.to_dict()
    ml = scale.moment_label
    power = ("" if record["power_per_cylinder_kW"] is None else
             f", {figure(record['power_per_cylinder_kW'])} kW a cylinder")
    title = (f"{record['name']}: the family, objective {record['objective']}, pitch "
             f"{m_to_mm(record['pitch_m']):g} mm{power}; guide-force moments from "
             f"{record['guide_forces_from']}")
    headers = ["Cyl", "Firing order", "Found", f"M1V* ({ml})", f"M1H* ({ml})", f"M2V ({ml})",
               f"M2H ({ml})", "PRU M1V*", "PRU M1H*", "PRU M2V", "PRU M2H", "H-type (order)",
               "X-type (order)", "2nd-order compensator"]
    rows = []
    for row in record["rows"]:
        pru = row["pru"]
        cells = [str(row["cylinders"]), "-".join(map(str, row["firing_order"])), row["method"]]
        # the first order with the rotating masses balanced, as the project guides give it
        first = "_balanced" if "M1V_balanced_Nm" in row else ""
        cells += [figure(scale.moment(row[f"M1{d}{first}_Nm"])) for d in "VH"]
        cells += [figure(scale.moment(row[f"M2{d}_Nm"])) for d in "VH"]
        entries = {} if pru is None else {e["order"]: e for e in pru["orders"]}
        if pru is not None and pru["first_order_balanced"] is not None:
            entries[1] = pru["first_order_balanced"]
        for k in (1, 2):
            for side in ("vertical", "horizontal"):
                cells.append(_pru_text(entries[k], side) if k in entries else "—")
        for key in ("h_type", "x_type"):
            moment = row[key]
            cells.append("—" if moment is None else
                         f"{figure(scale.moment(moment['amplitude_Nm']))} ({moment['order']:g})")
        compensator = row["second_order_compensator"]
        cells.append("—" if compensator is None else "yes" if compensator else "no")
        rows.append(cells)
    notes = ["Found: exhaustive (proved best for the objective), heuristic (the best found, not "
             "proved) or given. M1*: the first-order couple with counterweights for the rotating "
             "masses (balance factor 0), as the project guides give it; M2 as the crank stands; "
             "PRU in N·m/kW with the need for a compensator; H-type and X-type: the largest "
             f"guide-force moment ({record['guide_forces_from']}: a [gas] table adds the gas "
             "forces) of the orders analysed (at least up to the number of cylinders) and its "
             "order; a second-order compensator is indicated where M2's PRU "
             "is likely or most likely to need one."]
    missing = sorted({row["pru_note"] for row in record["rows"] if row["pru"] is None})
    if missing:
        notes.append("PRU —: " + "; ".join(missing) + " (--power-per-cylinder gives it).")
    return title, headers, rows, " ".join(notes)


def family_tables(result, scale, fmt):
    """``balance family`` as text or Markdown."""
    heading = "#### " if fmt == "markdown" else ""
    title, headers, rows, note = family_parts(result, scale)
    return "\n".join([f"{heading}{_safe(fmt)(title)}", "", render(headers, rows, fmt), "", note,
                      ""])
