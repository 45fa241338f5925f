"""``balance list`` and ``balance show``: the engines of a folder in a table, and one
engine's data with a row per cylinder."""

import math

from ..units import kg_to_g, m_to_mm, pa_to_bar, rad_s_to_rpm, round_degrees, wrap_degrees
from .display import figure, plain_text
from .table import render

__all__ = ["list_table", "list_tables", "show_table"]


def list_table(engines, estimates=None):
    """The engines of one folder; ``estimates``, parallel to them, the number of each file's
    numbers an estimate names (None: the file declares no ``sources`` or ``estimates``)."""
    if estimates is None:
        estimates = [None] * len(engines)
    rows = [
        [e.config_path, e.name, str(e.n_cylinders), str(e.cycle), e.frame, _estimates(n), e.source]
        for e, n in zip(engines, estimates, strict=True)
    ]
    return render(["Config", "Name", "Cyl", "Cycle", "Frame", "Estimates", "Source"], rows, "table")


def _estimates(count):
    """The Estimates cell: how many numbers are estimates, "none", or blank (not declared)."""
    if count is None:
        return ""
    return str(count) if count else "none"


def list_tables(groups):
    """``balance list``: one table per folder, under its heading. ``groups`` is a sequence of
    (heading, engines, estimates), in the order to print them (``estimates`` as
    :func:`list_table` takes them)."""
    blocks = []
    for heading, engines, estimates in groups:
        count = len(engines)
        blocks.append(
            f"{heading} ({count} engine{'s' if count != 1 else ''})\n"
            f"{list_table(engines, estimates)}"
        )
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
        lines.append(
            f"  parts:         piston {kg_to_g(parts.piston_kg):g} g; "
            f"rod {kg_to_g(parts.rod_kg):g} g, "
            f"centre of gravity {_mm(parts.rod_cg_m)} from the big end, "
            f"J {_inertia(parts.rod_inertia_kgm2)}"
            + (
                f"; link rod {kg_to_g(parts.link_kg):g} g, {_mm(parts.link_cg_m)}, "
                f"j {_inertia(parts.link_inertia_kgm2)}"
                if parts.link_kg
                else ""
            )
            + f"; crank {kg_to_g(parts.crank_kg):g} g"
        )
    rods = sorted({c.rod_inertia_kgm2 for c in engine.cylinders if not c.is_link})
    links = sorted({c.rod_inertia_kgm2 for c in engine.cylinders if c.is_link})
    if any(rods) or any(links) or engine.shaft_inertia_kgm2:
        lines.append(
            "  rod inertia:   left out by the point masses: "
            + ("master rods" if links else "rods")
            + " C = J − M·H·(L − H) = "
            + ", ".join(_inertia(c) for c in rods)
            + (
                f"; link rods c = j − m·h·(l − h) = {', '.join(_inertia(c) for c in links)}"
                if links
                else ""
            )
            + f"; crankshaft and flywheel {_inertia(engine.shaft_inertia_kgm2)}"
        )
    if engine.gas is not None:
        gas = engine.gas
        lines.append(
            f"  gas:           bore {_mm(gas.bore_m)}, compression ratio {gas.compression_ratio:g}"
            + ("" if gas.imep_pa is None else f", imep {pa_to_bar(gas.imep_pa):g} bar")
        )
    return lines


def _crankshaft_lines(engine):
    """The crankshafts of an engine with several: position, sense of turning and gear phase."""
    if not engine.has_several_crankshafts:
        return []
    lines = []
    for i, shaft in enumerate(engine.crankshafts, 1):
        turning = "with the first" if shaft.direction == 1 else "against the first"
        lines.append(
            f"  crankshaft {i}:  at ({_mm(shaft.x_m)}, {_mm(shaft.y_m)}), turning "
            f"{turning}, phase {math.degrees(shaft.phase_rad):g}°"
            + (" (the reference)" if i == 1 else "")
        )
    if engine.has_opposed_pistons:
        lines.append("  opposed:       TDC is the inner dead centre (the bore at its smallest)")
    return lines


def _as_built_show_lines(engine):
    """``balance show``'s lines for the counterweights and balancer shafts as built."""
    lines = []
    for weight in engine.counterweights:
        lines.append(
            f"  counterweight: throw {weight.throw}, m·ρ {figure(weight.mass_radius_kgm)} "
            f"kg·m at {math.degrees(weight.angle_rad):g}° from its pin, z "
            f"{_mm(engine.counterweight_z_m(weight))}"
        )
    for shaft in engine.balancer_shafts:
        masses = "; ".join(
            f"m·e {figure(m.mass_radius_kgm)} kg·m at {math.degrees(m.angle_rad):g}°, "
            f"z {_mm(engine.balancer_z_m(m))}"
            for m in shaft.masses
        )
        lines.append(
            f"  shaft:         ratio {shaft.ratio:+d}, axis lateral {_mm(shaft.lateral_m)}, "
            f"vertical {_mm(shaft.vertical_m)}; {masses}"
        )
    return lines


def _own_rotating(engine):
    """The throws whose big ends weigh their own (parts weighed one by one), as text."""
    own = [
        f"throw {i} {kg_to_g(t.rotating_kg):g} g"
        for i, t in enumerate(engine.throws, 1)
        if t.rotating_kg is not None
    ]
    return f"; own rotating: {', '.join(own)}" if own else ""


def _tolerance_lines(engine):
    """The [tolerances] scatter, one standard deviation each, in a file's units."""
    band = engine.tolerances
    if band is None or band.empty:
        return []
    values = [
        ("reciprocating", band.reciprocating_kg * 1e3, "g"),
        ("rotating", band.rotating_kg * 1e3, "g"),
        ("crank radius", band.crank_radius_m * 1e3, "mm"),
        ("rod length", band.rod_length_m * 1e3, "mm"),
        ("phase", math.degrees(band.phase_rad), "°"),
        ("bank angle", math.degrees(band.bank_angle_rad), "°"),
        ("pin offset", band.pin_offset_m * 1e3, "mm"),
    ]
    shown = ", ".join(
        f"{name} {value:g}{'' if unit == '°' else ' '}{unit}"
        for name, value, unit in values
        if value
    )
    return [f"  tolerances:    σ {shown}"]


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
        f"  vertical:      {wrap_degrees(math.degrees(engine.vertical_axis_rad)):g}° "
        "from the reference axis "
        f"({engine.vertical_origin})",
        f"  masses:        reciprocating {kg_to_g(engine.mean_reciprocating_kg):g} g mean per "
        f"cylinder, rotating {kg_to_g(engine.rotating_kg):g} g and crank "
        f"{kg_to_g(engine.crank_kg):g} g per throw"
        + "".join(f", knuckle {kg_to_g(kg):g} g per link rod" for kg in knuckles)
        + _own_rotating(engine),
        *_parts_lines(engine),
        *_crankshaft_lines(engine),
        *_as_built_show_lines(engine),
        *_tolerance_lines(engine),
        f"  firing:        {'-'.join(map(str, firing.order))} "
        f"({'given' if firing.given else 'most uniform the crank allows'})",
        f"  intervals (°): {', '.join(f'{i:.2f}' for i in firing.intervals_deg)}",
        "",
    ]
    offsets = any(
        c.pin_offset_m is not None and c.pin_offset_m != engine.pin_offset_m
        for c in engine.cylinders
    )
    several = engine.has_several_crankshafts
    rows = []
    for c in engine.cylinders:
        rod = engine.rod_type(c)
        if c.is_link:
            rod = (
                f"link on {c.master} ({_mm(c.link_length_m)}, knuckle {_mm(c.knuckle_radius_m)} "
                f"at {math.degrees(c.knuckle_angle_rad):g}°)"
            )
        elif c.is_opposed:
            rod = f"opposed: throw {c.opposed_throw}, {kg_to_g(c.opposed_reciprocating_kg):g} g"
        bank = math.degrees(engine.bank_angles_rad[c.bank_index])
        throw = str(c.throw) + (
            f" (shaft {engine.throws[c.throw_index].crankshaft})" if several else ""
        )
        row = [
            str(c.number),
            f"{c.bank} ({bank:g}°)",
            throw,
            f"{math.degrees(engine.throws[c.throw_index].phase_rad):g}",
            f"{m_to_mm(c.z_m):g}",
            f"{kg_to_g(c.reciprocating_kg):g}",
            rod,
        ]
        if offsets:
            row.append(f"{m_to_mm(engine.pin_offset_of(c)):g}")
        rows.append(row + [f"{round_degrees(firing.tdc_deg[c.number], 2):.2f}"])
    table = render(
        ["Cyl", "Bank (angle)", "Throw", "Phase (°)", "z (mm)", "Recip. (g)", "Rod"]
        + (["Pin offset (mm)"] if offsets else [])
        + ["TDC (°)"],
        rows,
        "table",
    )
    return "\n".join(header) + table + "\n"
