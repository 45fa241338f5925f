"""``balance family``'s table: one row per number of cylinders, its firing order, free
moments, power related unbalance and guide-force moments."""

from ..units import m_to_mm
from .display import figure
from .table import pru_text, render, safe_for

__all__ = ["family_parts", "family_tables"]


def family_parts(result, scale):
    """``balance family`` as (title, headers, rows, note), rendered from
    ``FamilyResult.to_dict``: one row per number of cylinders."""
    record = result.to_dict()
    ml = scale.moment_label
    power = (
        ""
        if record["power_per_cylinder_kW"] is None
        else f", {figure(record['power_per_cylinder_kW'])} kW a cylinder"
    )
    title = (
        f"{record['name']}: the family, objective {record['objective']}, pitch "
        f"{m_to_mm(record['pitch_m']):g} mm{power}; guide-force moments from "
        f"{record['guide_forces_from']}"
    )
    moments = [(k, d) for k in (1, 2, 4) for d in "VH"]
    headers = (
        ["Cyl", "Firing order", "Found"]
        + [f"M{k}{d} ({ml})" for k, d in moments]
        + ["PRU M1V", "PRU M1H", "PRU M2V", "PRU M2H"]
        + ["H-type (order)", "X-type (order)", "2nd-order compensator"]
    )
    # a V family: how its banks excite the major orders (an in-line engine's are all 1)
    v_family = record["firing"] != "even"
    if v_family:
        headers.append("Major orders (vector sum)")
    rows = []
    for row in record["rows"]:
        pru = row["pru"]
        cells = [str(row["cylinders"]), "-".join(map(str, row["firing_order"])), row["method"]]
        cells += [
            "—" if row[f"M{k}{d}_Nm"] is None else figure(scale.moment(row[f"M{k}{d}_Nm"]))
            for k, d in moments
        ]
        entries = {} if pru is None else {e["order"]: e for e in pru["orders"]}
        for k in (1, 2):
            for side in ("vertical", "horizontal"):
                cells.append(pru_text(entries[k], side) if k in entries else "—")
        for key in ("h_type", "x_type"):
            moment = row[key]
            cells.append(
                "—"
                if moment is None
                else f"{figure(scale.moment(moment['amplitude_Nm']))} ({moment['order']:g})"
            )
        compensator = row["second_order_compensator"]
        cells.append("—" if compensator is None else "yes" if compensator else "no")
        if v_family:
            cells.append(
                ", ".join(f"{m['order']:g}: {m['vector_sum']:.3f}" for m in row["major_orders"])
            )
        rows.append(cells)
    balances = sorted({row["first_order_balance"]["description"] for row in record["rows"]})
    notes = [
        "Found: exhaustive (proved best for the objective), heuristic (the best found, not "
        "proved) or given. M1: the first-order couple under "
        + "; ".join(balances)
        + " (the JSON and CSV give the rotating-only and as-the-crank-stands figures "
        "beside it); M2 and M4 as the crank stands; "
        "PRU in N·m/kW with the need for a compensator; H-type and X-type: the largest "
        f"guide-force moment ({record['guide_forces_from']}: a [gas] table adds the gas "
        "forces) of the orders analysed (at least up to the number of cylinders) and its "
        "order; a second-order compensator is indicated where M2's PRU "
        "is likely or most likely to need one."
    ]
    if v_family:
        notes.append(
            "Each bank fires evenly on its own, the other bank's cylinder on each throw the bank "
            "angle (or that and a revolution, whichever excites the major orders less) after "
            "its partner; major orders: those at which a bank's cylinders all fire in phase, "
            "with the engine's vector sum over its cylinders (1: every cylinder in phase)."
        )
    missing = sorted({row["pru_note"] for row in record["rows"] if row["pru"] is None})
    if missing:
        notes.append("PRU —: " + "; ".join(missing) + " (--power-per-cylinder gives it).")
    return title, headers, rows, " ".join(notes)


def family_tables(result, scale, fmt):
    """``balance family`` as text or Markdown."""
    heading = "#### " if fmt == "markdown" else ""
    title, headers, rows, note = family_parts(result, scale)
    return "\n".join(
        [f"{heading}{safe_for(fmt)(title)}", "", render(headers, rows, fmt), "", note, ""]
    )
