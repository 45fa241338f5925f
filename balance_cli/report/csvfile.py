"""CSV of ``compare`` and ``counterweight``, rendered from the results' ``to_dict()`` records."""

import csv
import io

from .tables import WEIGHT_COLUMNS

__all__ = ["compare_csv", "balance_csv"]

#: key suffix of an SI record -> unit written in the CSV
_UNITS = (("_kgm", "kg·m"), ("_kg", "kg"), ("_deg", "deg"), ("_m", "m"))


def _quantity_and_unit(key):
    for suffix, unit in _UNITS:
        if key.endswith(suffix):
            return key[: -len(suffix)], unit
    return key, ""


def _value(value):
    if value is None:
        return ""
    return repr(value) if isinstance(value, float) else value


def _order_row(order, engine, scale):
    """Force fwd/bwd/max/min, axis, moment fwd/bwd/max of one order in display units."""
    values = order.to_dict(engine.noise_floor_n)
    f, m = values["force"], values["moment"]
    unit = engine.per_cylinder_unit_n
    return ([scale.force(f[k], unit) for k in ("forward_N", "backward_N", "max_N", "min_N")]
            + [f["axis_deg"]] + [scale.moment(m[k]) for k in ("forward_Nm", "backward_Nm", "max_Nm")])


def _labels(scale):
    return ("per_cyl" if not scale.absolute else scale.units), ("kgfm" if scale.units == "kgf" else "Nm")


def compare_csv(comparison, scale):
    """One row per engine and order, every order, full precision; units in the header."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    fl, ml = _labels(scale)
    writer.writerow(
        ["engine", "config", "order", f"force_forward_{fl}", f"force_backward_{fl}",
         f"force_max_{fl}", f"force_min_{fl}", "force_axis_deg", f"moment_forward_{ml}",
         f"moment_backward_{ml}", f"moment_max_{ml}"]
    )
    for r in comparison.results:
        for order in r.shaking.orders:
            writer.writerow([r.engine.name, r.engine.config_path, order.order]
                            + [_value(x) for x in _order_row(order, r.engine, scale)])
    return buffer.getvalue()


def _records(item, record, keys=None):
    for key in keys or record:
        quantity, unit = _quantity_and_unit(key)
        yield item, quantity, record[key], unit


def balance_csv(balances, scale):
    """Everything of ``balance counterweight`` in long form: engine, config, item, quantity,
    value, unit (SI, but forces and moments of the orders in ``scale``'s units)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["engine", "config", "item", "quantity", "value", "unit"])
    fl = "per_cyl" if not scale.absolute else scale.units
    ml = "kgf·m" if scale.units == "kgf" else "N·m"
    weight_keys = [key for key, _, _ in WEIGHT_COLUMNS]
    for b in balances:
        record = b.to_dict()
        rows = []
        for i, weight in enumerate(record["counterweights"], 1):
            rows += _records(f"counterweight {i}", weight, weight_keys)
        if record["antivibrateur"] is not None:
            rows += _records("antivibrateur", record["antivibrateur"])
        stages = [("residual", b.residual)] + ([("after shafts", b.after_shafts)]
                                               if b.after_shafts is not None else [])
        for stage, shaking in stages:
            for order in shaking.orders:
                item = f"{stage} order {order.order}"
                values = _order_row(order, b.engine, scale)
                names = ("force_forward", "force_backward", "force_max", "force_min", "force_axis",
                         "moment_forward", "moment_backward", "moment_max")
                units = (fl,) * 4 + ("deg",) + (ml,) * 3
                rows += [(item, n, v, u) for n, v, u in zip(names, values, units)]
        for i, shaft in enumerate(record.get("shafts", []), 1):
            rows += _records(f"shaft {i}", shaft)
        for i, mass in enumerate(record.get("test_masses_kg") or [], 1):
            rows.append((f"test mass throw {i}", "mass", mass, "kg"))
        for item, quantity, value, unit in rows:
            writer.writerow([b.engine.name, b.engine.config_path, item, quantity, _value(value), unit])
    return buffer.getvalue()
