"""``balance regress``'s table: the quantities that moved beyond tolerance against the
baseline, and the engines added and removed."""

from ..units import Scale
from .table import render, safe_for

__all__ = ["value_text", "regression_tables"]


def value_text(value):
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
    safe = safe_for(fmt)
    checked = len(regression.checked)
    if not regression.moved:
        return (
            f"{heading}balance regress: nothing moved beyond tolerance ({checked} engine"
            f"{'s' if checked != 1 else ''} checked against {safe(regression.baseline_path)})\n"
        )
    moved_engines = len({row.engine for row in regression.rows})
    out = [
        f"{heading}balance regress: {len(regression.rows)} quantities moved in {moved_engines} "
        f"of {checked} engines; {len(regression.added)} added, {len(regression.removed)} "
        f"removed (baseline {safe(regression.baseline_path)})",
        "",
    ]
    if regression.rows:
        rows = []
        for row in regression.rows:
            change, relative = row.change, row.relative_change

            def shown(v, q=row.quantity):
                return _in_units(q, v, scale)

            rows.append(
                [
                    row.engine,
                    "-" if row.order is None else str(row.order),
                    row.quantity,
                    value_text(shown(row.baseline)),
                    value_text(shown(row.now)),
                    "-" if change is None else f"{shown(change):+.3g}",
                    "-" if relative is None else f"{100 * relative:+.3g} %",
                    "-" if row.tolerance is None else f"{shown(row.tolerance):.3g}",
                ]
            )
        out += [
            render(
                [
                    "Engine",
                    "Order",
                    "Quantity",
                    "Baseline",
                    "Now",
                    "Change",
                    "Relative",
                    "Tolerance",
                ],
                rows,
                fmt,
            ),
            "",
        ]
    for title, names in (
        ("Engines added (not in the baseline)", regression.added),
        ("Engines removed (in the baseline, not now)", regression.removed),
    ):
        if names:
            out += [f"{title}:", ""] + [f"- {safe(n)}" for n in names] + [""]
    out.append(
        f"Units: {scale.units} for *_N and {scale.moment_label} for *_Nm, degrees for "
        "*_deg; change is now − baseline. Update the baseline on purpose with --update."
    )
    return "\n".join(out) + "\n"
