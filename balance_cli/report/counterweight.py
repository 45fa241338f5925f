"""``balance counterweight``'s tables: the counterweights, antivibrateur and balancer shafts
proposed (and those built), the rolling moment of offset shafts, and the orders each stage
leaves; and the report's one-row-per-engine summary."""

from ..units import m_to_mm, round_degrees
from .display import figure
from .table import part_headers, part_rows, render, safe_for

__all__ = [
    "WEIGHT_COLUMNS",
    "BUILT_WEIGHT_COLUMNS",
    "SHAFT_COLUMNS",
    "balance_tables",
    "balance_summary",
]


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
    (
        "speed_ratio",
        "Turning",
        lambda v: "" if v is None else "with the crank" if v > 0 else "against the crank",
    ),
    (
        "offset_m",
        "Offset lateral, vertical (mm)",
        lambda v: "" if v is None else f"{m_to_mm(v['lateral']):g}, {m_to_mm(v['vertical']):g}",
    ),
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
            rows.append(
                {
                    **mass,
                    "shaft": number if first else None,
                    "speed_ratio": shaft["speed_ratio"] if first else None,
                    "offset_m": shaft["offset_m"] if first else None,
                }
            )
    return rows


def _rolling_lines(record, scale, fmt):
    """The rolling moment the shafts' offsets leave, or why there is none."""
    shafts = record["balancer_shafts"]
    if all(s["offset_m"]["lateral"] == 0 and s["offset_m"]["vertical"] == 0 for s in shafts):
        which = "the proposed shafts" if "as_built" in record else "the shafts"
        return [
            f"Rolling moment about the crank axis of {which}: none; they sit on the crank "
            "axis, and a centred shaft's force passes through it.",
            "",
        ]
    rows = []
    for total in record["shaft_rolling_moments"]:
        mine = [(n, s) for n, s in enumerate(shafts, 1) if s["order"] == total["order"]]
        if all(s["offset_m"]["lateral"] == 0 and s["offset_m"]["vertical"] == 0 for _, s in mine):
            continue
        for number, shaft in mine:
            m = shaft["rolling_moment"]
            rows.append(
                [
                    str(total["order"]),
                    f"{number} ({shaft['speed_ratio']:+d})",
                    figure(scale.moment(m["amplitude_Nm"])),
                    f"{round_degrees(m['phase_deg'], 2):.2f}",
                ]
            )
        if len(mine) > 1:
            rows.append(
                [
                    str(total["order"]),
                    " and ".join(f"{n}" for n, _ in mine) + " together",
                    figure(scale.moment(total["amplitude_Nm"])),
                    f"{round_degrees(total['phase_deg'], 2):.2f}",
                ]
            )
    return [
        "Rolling moment about the crank axis from the shafts' forces at their offsets "
        "(M = amplitude·cos(kθ − phase), positive with rotation, as the frame torque of "
        "balance torque; a centred shaft makes none, and orders whose shafts are all "
        "centred are left out):",
        "",
        render(["Order", "Shaft", f"Amplitude ({scale.moment_label})", "Phase (°)"], rows, fmt),
        "",
    ]


def _left(name, stage, records, n_unit, scale, fmt):
    """The orders left after ``stage`` (forces, then moments), or the words that nothing is."""
    forces = part_rows(name, records, n_unit, scale, "force")
    moments = part_rows(name, records, n_unit, scale, "moment")
    if not forces and not moments:
        return [
            f"After the {stage}, nothing is left up to order {len(records)}: every force and "
            "moment is zero.",
            "",
        ]
    out = [f"Left after the {stage}:", ""]
    for rows, part, none in ((forces, "force", "no force"), (moments, "moment", "no moment")):
        out += (
            [render(part_headers(scale, part), rows, fmt), ""]
            if rows
            else [f"({none} in any order up to {len(records)})", ""]
        )
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
    out = [
        f"As built: {len(weights)} counterweight{'' if len(weights) == 1 else 's'} and "
        f"{len(shafts)} balancer shaft{'' if len(shafts) == 1 else 's'} (from the "
        "configuration). Everything proposed below is in addition to them.",
        "",
    ]
    if weights:
        out += [_record_table(weights, BUILT_WEIGHT_COLUMNS, fmt), ""]
    if shafts:
        out += [
            "Balancer shafts as built (each mass's m·e, its angle from the reference axis when "
            "θ = 0, positive with the crank's rotation — the file gives a shaft turning "
            "against the crank its angle in its own sense, the negative of this — and its "
            "axial position):",
            "",
            _record_table(_shaft_rows(shafts), SHAFT_COLUMNS, fmt),
            "",
        ]
        rolling = [
            [
                f"{n} ({s['speed_ratio']:+d})",
                str(s["rolling_moment"]["order"]),
                figure(scale.moment(s["rolling_moment"]["amplitude_Nm"])),
                f"{round_degrees(s['rolling_moment']['phase_deg'], 2):.2f}",
            ]
            for n, s in enumerate(shafts, 1)
            if s["offset_m"]["lateral"] or s["offset_m"]["vertical"]
        ]
        if rolling:
            out += [
                "Rolling moment about the crank axis of the shafts as built, from their "
                "forces at their offsets (M = amplitude·cos(kθ − phase), positive with "
                "rotation; in balance torque's frame torque):",
                "",
                render(
                    ["Shaft", "Order", f"Amplitude ({scale.moment_label})", "Phase (°)"],
                    rolling,
                    fmt,
                ),
                "",
            ]
    return out + _left(
        record["name"], "counterweights and shafts as built", built["orders"], n_unit, scale, fmt
    )


def balance_tables(balances, scale, fmt):
    """``balance counterweight`` as text or Markdown, engine by engine, rendered from the
    records of ``Balance.to_dict``."""
    heading = "#### " if fmt == "markdown" else ""
    safe = safe_for(fmt)
    unit = "per cylinder, × m_rec·r·ω²·n" if not scale.absolute else scale.units
    out = []
    for b in balances:
        record = b.to_dict()
        n_unit = b.engine.per_cylinder_unit_n
        factor = record["balance_factor"]
        how = (
            "cancelling the forward first order"
            if factor is None
            else f"balance factor {factor:g}: rotating masses plus {factor:g} of the reciprocating "
            "ones per throw"
        )
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
            out += [
                f"Antivibrateur on the crank pin, turning at twice crank speed with the crank: "
                f"M·e = {figure(a['mass_eccentricity_kgm'])} kg·m (M = {figure(a['mass_kg'])} "
                f"kg at e = {m_to_mm(a['eccentricity_m']):g} mm), at "
                f"{round_degrees(a['phase_deg'], 2):.2f}° when θ = 0; the counterweights above "
                "include its mass.",
                "",
            ]
        first = record["residual"]["orders"][0]
        f, m = first["force"], first["moment"]
        out += [
            f"First order left: forward {figure(scale.force(f['forward_N'], n_unit))}, "
            f"backward {figure(scale.force(f['backward_N'], n_unit))} ({unit}; no counterweight "
            f"touches the backward part); moment {figure(scale.moment(m['forward_Nm']))} "
            f"forward, {figure(scale.moment(m['backward_Nm']))} backward "
            f"({scale.moment_label}).",
            "",
        ]
        out += _left(
            record["name"], "counterweights", record["residual"]["orders"], n_unit, scale, fmt
        )
        if "after_shafts" in record and not record["balancer_shafts"]:
            out += ["Balancer shafts: none needed; the orders asked for are already zero.", ""]
        elif "after_shafts" in record:
            # "as built": one shaft per speed ratio with its masses; on an engine that has
            # shafts already, these are more of them
            what = (
                "Balancer shafts to add to those built"
                if "as_built" in record
                else "Balancer shafts as built"
            )
            out += [
                f"{what} (each mass's m·e, its angle from the reference axis "
                "when θ = 0, positive with rotation, and its axial position):",
                "",
                _record_table(_shaft_rows(record["balancer_shafts"]), SHAFT_COLUMNS, fmt),
                "",
            ]
            built = {s["order"] for s in record["balancer_shafts"]}
            idle = [k for k in record.get("shaft_orders", []) if k not in built]
            if idle:
                out += [
                    f"Order{'s' if len(idle) > 1 else ''} {', '.join(map(str, idle))}: no "
                    "shaft needed, already zero.",
                    "",
                ]
            out += _rolling_lines(record, scale, fmt)
            out += _left(
                record["name"], "shafts", record["after_shafts"]["orders"], n_unit, scale, fmt
            )
            left = [
                k
                for k in record.get("shaft_orders", [])
                if record["after_shafts"]["orders"][k - 1]["moment"]["max_Nm"] > 0.0
            ]
            if left and len(record["counterweights"]) < 2:
                out += [
                    f"One correction plane cannot cancel a couple: order"
                    f"{'s' if len(left) > 1 else ''} {', '.join(map(str, left))} keep"
                    f"{'' if len(left) > 1 else 's'} a free moment. Give two planes "
                    "(--planes A,B, throws or axial positions) to put shafts' masses in "
                    "both.",
                    "",
                ]
        if "test_masses_kg" in record:
            rows = [[str(i + 1), figure(m)] for i, m in enumerate(record["test_masses_kg"])]
            out += [
                "Balancing-machine test masses (hang on each crank pin; the crankshaft's own "
                "unbalance excluded):",
                "",
                render(["Throw", "Mass (kg)"], rows, fmt),
                "",
            ]
    return "\n".join(out)


def balance_summary(balances):
    """One row per engine of ``balance counterweight`` with default planes: (headers, rows)."""
    rows = []
    for b in balances:
        record = b.to_dict()
        n_unit = b.engine.per_cylinder_unit_n
        first = record["residual"]["orders"][0]["force"]
        weights = "; ".join(
            f"{figure(c['mass_kg'])} kg at {round_degrees(c['angle_deg'], 1):.1f}° "
            f"({_plane_text(c)})"
            for c in record["counterweights"]
        )
        rows.append(
            [
                record["name"],
                weights,
                figure(first["forward_N"] / n_unit),
                figure(first["backward_N"] / n_unit),
                figure(record["residual"]["largest_resultant_N"] / n_unit),
            ]
        )
    headers = [
        "Engine",
        "Counterweights at crank radius",
        "1st order left fwd (per cyl)",
        "1st order bwd (per cyl)",
        "Largest resultant left (per cyl)",
    ]
    return headers, rows
