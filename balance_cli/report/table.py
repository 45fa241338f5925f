"""What every command's tables share: rendering a table as plain text or Markdown, the
force and moment tables of the orders, and the text of cells several tables show (firing
intervals, a power related unbalance).

Every table is rendered from result objects' ``to_dict()`` records; text that comes from a
user (engine names, paths, sources) is made safe for the format here.
"""

from tabulate import tabulate

from ..units import round_degrees
from .display import figure, markdown_text, plain_text

__all__ = [
    "safe_for",
    "render",
    "order_values",
    "part_headers",
    "part_rows",
    "order_parts",
    "intervals",
    "pru_text",
]


_TABLEFMT = {"table": "simple", "markdown": "pipe"}


def safe_for(fmt):
    return markdown_text if fmt == "markdown" else plain_text


def render(headers, rows, fmt):
    """One table as text ("table") or Markdown ("markdown"); cells must already be text."""
    safe = safe_for(fmt)
    return tabulate(
        [[safe(c) for c in row] for row in rows],
        headers=[safe(h) for h in headers],
        tablefmt=_TABLEFMT[fmt],
        disable_numparse=True,
    )


def _axis_text(axis_deg):
    """An ellipse's axis for a table: "—" where there is none (a circle, or nothing)."""
    return "—" if axis_deg is None else f"{round_degrees(axis_deg, 0, 180.0):.0f}"


def order_values(record, unit_n, scale):
    """The CSV columns of one order's record (``OrderComponents.to_dict``) in display units:
    force forward, backward, max, min, axis; moment forward, backward, max; then (added with
    format version 2, so older readers keep their columns) force vertical and horizontal,
    moment min, axis, vertical (pitch) and horizontal (yaw)."""
    f, m = record["force"], record["moment"]

    def force(key):
        return scale.force(f[key], unit_n)

    return (
        [force(k) for k in ("forward_N", "backward_N", "max_N", "min_N")]
        + [f["axis_deg"]]
        + [scale.moment(m[k]) for k in ("forward_Nm", "backward_Nm", "max_Nm")]
        + [
            force("vertical_N"),
            force("horizontal_N"),
            scale.moment(m["min_Nm"]),
            m["axis_deg"],
            scale.moment(m["vertical_Nm"]),
            scale.moment(m["horizontal_Nm"]),
        ]
    )


#: the columns of a part's table: (record key without unit, heading)
_PART_COLUMNS = {
    "force": (
        "F",
        ("forward", "fwd"),
        ("backward", "bwd"),
        ("max", "max"),
        ("min", "min"),
        ("vertical", "vertical"),
        ("horizontal", "horizontal"),
    ),
    "moment": (
        "M",
        ("forward", "fwd"),
        ("backward", "bwd"),
        ("max", "max"),
        ("min", "min"),
        ("vertical", "V (pitch)"),
        ("horizontal", "H (yaw)"),
    ),
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
        rows.append(
            [name, str(record["order"])] + cells[:4] + [_axis_text(values["axis_deg"])] + cells[4:]
        )
    return rows


def order_parts(entries, scale, samples):
    """The force and moment tables of the orders, as (title, headers, rows, note), for
    ``entries`` of (name, order records, m_rec·r·ω²·n)."""
    unit = "per cylinder, in units of m_rec·r·ω²·n" if not scale.absolute else f"in {scale.units}"
    forces = [
        row
        for name, records, unit_n in entries
        for row in part_rows(name, records, unit_n, scale, "force")
    ]
    moments = [
        row
        for name, records, unit_n in entries
        for row in part_rows(name, records, unit_n, scale, "moment")
    ]
    top = entries and len(entries[0][1])
    return [
        (
            f"Free forces by order ({unit})",
            part_headers(scale, "force"),
            forces,
            f"No free force in any order up to {top}."
            if not forces
            else "Orders not listed are zero. fwd turns with the crank, bwd against it; max and "
            "min are the semi-axes of the order's ellipse, axis the direction of max from the "
            "reference axis "
            "(— where the ellipse is a circle); vertical and horizontal are the amplitudes of the "
            f"components along the engine's vertical and across it ({samples} samples a "
            "revolution).",
        ),
        (
            f"Free moments by order (in {scale.moment_label})",
            part_headers(scale, "moment"),
            moments,
            "V (pitch) is the moment of the vertical forces, about the horizontal axis across the "
            "crankshaft (marine M1V, M2V); H (yaw) the moment of the horizontal forces, about the "
            "vertical (M1H, M2H)."
            if moments
            else f"No free moment in any order up to {top}.",
        ),
    ]


def intervals(firing):
    """A firing's intervals as a cell: "every 180" when uniform, else the sequence in firing
    order from the first cylinder of the order, to 0.1° ("270-180-90-180")."""
    mean = sum(firing["intervals_deg"]) / len(firing["intervals_deg"])
    if firing["uniform"]:
        return f"every {mean:g}"
    return "-".join(f"{round(gap, 1) + 0.0:g}" for gap in firing["intervals_deg"])


def pru_text(entry, side):
    """One PRU cell: "124.4 (likely)"."""
    return f"{figure(entry[f'{side}_Nm_per_kW'])} ({entry[f'{side}_class']})"
