"""``balance compare``'s tables: the orders of every engine, the power related unbalance,
the firing and a summary of the largest free force and moment, in the style of Tanaka's
Part III."""

from ..units import significant
from .display import figure
from .table import intervals, order_parts, pru_text, render, safe_for

__all__ = ["PERCENT_LIMIT", "compare_parts", "compare_tables"]


def _shortened(name, length=24):
    """A name short enough for a column heading: whole words, as many as fit in ``length``
    characters with the "…" that marks the cut; a first word longer than that is given
    whole (never cut inside a word)."""
    if len(name) <= length:
        return name
    head = name[: length - 1]
    if not name[length - 1].isspace():
        head = head[: max(head.rfind(" "), 0)]
    # "In-line 3, two-stroke, ..." reads better cut before the comma than after it
    head = head.rstrip(" ,;:(")
    return head + "…" if head else name


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
    entries = [
        (record["name"], record["orders"], unit_n)
        for record, unit_n in zip(records, units, strict=True)
    ]
    firing = [
        [
            record["name"],
            str(record["cylinders"]),
            str(record["cycle"]),
            record["frame"],
            "-".join(map(str, record["firing"]["order"])),
            intervals(record["firing"]),
        ]
        for record in records
    ]
    # per cylinder beside per-cylinder figures (Tanaka's), in newtons beside absolute ones
    share = "percent_of_reference_absolute" if scale.absolute else "percent_of_reference"
    summary = []
    for record, unit_n in zip(records, units, strict=True):

        def force(v, u=unit_n):
            return scale.force(v, u)

        summary.append(
            [
                record["name"],
                figure(force(record["counterweighted_resultant_N"])),
                _share_text(record[share]),
                _main_text(
                    record["main_force_order"], force, record["counterweighted_resultant_N"]
                ),
                figure(scale.moment(record["counterweighted_moment_Nm"])),
                _main_text(
                    record["main_moment_order"], scale.moment, record["counterweighted_moment_Nm"]
                ),
            ]
        )
    notes = [
        "%: of the reference engine's largest force"
        + (", in newtons." if scale.absolute else ", per cylinder (Tanaka's Part III)."),
        "Largest: the resultant's largest magnitude over a revolution, all orders; main "
        "order: the order with the largest ellipse, its max and direction (rotating: a "
        "circle, turning with the crank (forward) or against it (backward)). A turning crank's "
        "ideal counterweight has taken the forward first order of "
        "force and moment away (a rotary's crank does not turn), and where a crankshaft "
        "turns against the first, its counterweights the backward first order too.",
    ]
    if any(record[share] is None for record in records):
        notes.append("n/a: the reference engine has no resultant to compare with.")
    if any((record[share] or 0.0) > PERCENT_LIMIT for record in records):
        notes.append(
            f"×: a multiple of the reference's resultant, where it is above {PERCENT_LIMIT:.0f} %."
        )
    fl, ml = scale.force_label, scale.moment_label
    return (
        order_parts(entries, scale, comparison.samples)
        + _pru_parts(records, scale)
        + [
            (
                "Firing",
                ["Engine", "Cyl", "Cycle", "Frame", "Firing order", "Intervals (°)"],
                firing,
                "",
            ),
            (
                "Largest free force and moment (after an ideal crankshaft counterweight)",
                [
                    "Engine",
                    f"Largest F ({fl})",
                    f"% of {_shortened(comparison.reference.engine.name)}",
                    f"Main F order: max ({fl}), direction",
                    f"Largest M ({ml})",
                    f"Main M order: max ({ml}), direction",
                ],
                summary,
                " ".join(notes),
            ),
        ]
    )


def _pru_parts(records, scale):
    """The power related unbalance table, when any engine has a power: per engine its power
    and, per order judged, the pitching and yawing moments' PRU with their class; the first
    order under the balance asked (default the project guides' standard balance), with the
    rotating-only and as-the-crank-stands figures beside it."""
    with_power = [r for r in records if r["pru"] is not None]
    if not with_power:
        # a power given at another speed than analysed is worth a word; no power at all is not
        notes = sorted({r["pru_note"] for r in records if "given at" in (r["pru_note"] or "")})
        return (
            [("Power related unbalance", [], [], "Not computed: " + "; ".join(notes) + ".")]
            if notes
            else []
        )
    orders = [e["order"] for e in with_power[0]["pru"]["orders"]]
    alternatives = ("rotating", "crank")
    headers = ["Engine", "Power (kW)"]
    for k in orders:
        headers += [f"M{k}V", f"M{k}H"]
        if k == 1:
            headers += [f"M1{d} {name}" for name in alternatives for d in "VH"]
    rows = []
    balances = set()
    for record in records:
        pru = record["pru"]
        if pru is None:
            rows.append([record["name"], "—"] + ["—"] * (len(headers) - 2))
            continue
        balances.add(pru["first_order_balance"]["description"])
        source = {"given": "", "option": " (--power)", "indicated": " (indicated)"}
        row = [record["name"], figure(pru["power_kW"]) + source[pru["power_source"]]]
        for entry in pru["orders"]:
            row += [pru_text(entry, "vertical"), pru_text(entry, "horizontal")]
            if entry["order"] == 1:
                for name in alternatives:
                    named = pru["first_order"][name]
                    row += (
                        ["—", "—"]
                        if named is None
                        else [pru_text(named, "vertical"), pru_text(named, "horizontal")]
                    )
        rows.append(row)
    classes = with_power[0]["pru"]["classes"]
    bounds = ", ".join(f"below {c['below_Nm_per_kW']:g} {c['class']}" for c in classes[:-1])
    bounds += f", above {classes[-2]['below_Nm_per_kW']:g} {classes[-1]['class']}"
    missing = [r["name"] for r in records if r["pru"] is None]
    first = (
        " M1 under " + "; ".join(sorted(balances)) + "; 'rotating' with counterweights for "
        "the rotating masses only, 'crank' as the crank stands (--first-order-balance "
        "chooses)."
        if 1 in orders
        else ""
    )
    note = (
        "PRU = external moment / engine power (N·m/kW) at the speed analysed, and the need "
        "for a moment compensator: " + bounds + ". MkV is the "
        "pitching moment of order k, MkH the yawing one."
        + first
        + (
            " —: " + "; ".join(sorted({r["pru_note"] for r in records if r["pru"] is None})) + "."
            if missing
            else ""
        )
    )
    return [
        ("Power related unbalance (N·m/kW, and the need for a compensator)", headers, rows, note)
    ]


def compare_tables(comparison, scale, fmt):
    """The comparison as text or Markdown: orders of every engine, then a summary."""
    heading = "#### " if fmt == "markdown" else ""
    safe = safe_for(fmt)
    out = []
    for title, headers, rows, note in compare_parts(comparison, scale):
        out += [f"{heading}{safe(title)}", ""] + ([render(headers, rows, fmt), ""] if rows else [])
        if note:
            out += [note, ""]
    return "\n".join(out)
