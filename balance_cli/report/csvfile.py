"""CSV of ``compare`` and ``counterweight``, rendered from the results' ``to_dict()`` records."""

import csv
import io

from .counterweight import WEIGHT_COLUMNS
from .table import order_values

__all__ = ["compare_csv", "balance_csv", "torque_csv", "search_csv", "family_csv"]

#: key suffix of an SI record -> unit written in the CSV
_UNITS = (("_kgm", "kg·m"), ("_kg", "kg"), ("_deg", "deg"), ("_m", "m"))
_ORDER_QUANTITIES = (
    "force_forward",
    "force_backward",
    "force_max",
    "force_min",
    "force_axis",
    "moment_forward",
    "moment_backward",
    "moment_max",
    "force_vertical",
    "force_horizontal",
    "moment_min",
    "moment_axis",
    "moment_vertical",
    "moment_horizontal",
)


def _quantity_and_unit(key):
    for suffix, unit in _UNITS:
        if key.endswith(suffix):
            return key[: -len(suffix)], unit
    return key, ""


def _value(value):
    if value is None:
        return ""
    # float(): a numpy scalar's repr names its type (np.float64(…)) since numpy 2
    return repr(float(value)) if isinstance(value, float) else value


def compare_csv(comparison, scale):
    """One row per engine and order, every order, full precision; units in the header."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    fl, ml = scale.column_force, scale.column_moment
    writer.writerow(
        ["engine", "config", "order"]
        + [
            f"{q}_{'deg' if q.endswith('_axis') else fl if q.startswith('force') else ml}"
            for q in _ORDER_QUANTITIES
        ]
    )
    for result, record in zip(comparison.results, comparison.to_dict()["engines"], strict=True):
        for order in record["orders"]:
            writer.writerow(
                [record["name"], record["config"], order["order"]]
                + [_value(x) for x in order_values(order, result.per_cylinder_unit_n, scale)]
            )
    return buffer.getvalue()


def _records(item, record, keys=None):
    for key in keys or record:
        quantity, unit = _quantity_and_unit(key)
        yield item, quantity, record[key], unit


def _rolling_rows(item, moment):
    for key in ("cos_Nm", "sin_Nm", "amplitude_Nm"):
        yield item, key[: -len("_Nm")], moment[key], "N·m"
    yield item, "phase", moment["phase_deg"], "deg"


def _balancer_rows(item, shaft):
    """A shaft as built: its speed ratio, offset and force, each mass, its rolling moment (SI)."""
    yield item, "speed_ratio", shaft["speed_ratio"], ""
    yield item, "offset_lateral", shaft["offset_m"]["lateral"], "m"
    yield item, "offset_vertical", shaft["offset_m"]["vertical"], "m"
    yield item, "force", shaft["force_N"], "N"
    for j, mass in enumerate(shaft["masses"], 1):
        yield from _records(f"{item} mass {j}", mass)
    yield from _rolling_rows(
        f"{item} rolling moment order {shaft['order']}", shaft["rolling_moment"]
    )


def balance_csv(balances, scale):
    """Everything of ``balance counterweight`` in long form: engine, config, item, quantity,
    value, unit (SI, but forces and moments of the orders in ``scale``'s units; the shafts'
    rolling moments, which are no order of the shaking, in N·m)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["engine", "config", "item", "quantity", "value", "unit"])
    units = [
        (
            "deg"
            if q.endswith("_axis")
            else scale.column_force
            if q.startswith("force")
            else scale.moment_label
        )
        for q in _ORDER_QUANTITIES
    ]
    weight_keys = [key for key, _, _ in WEIGHT_COLUMNS]
    for b in balances:
        record = b.to_dict()
        rows = []
        built = record.get("as_built")
        if built is not None:
            for i, weight in enumerate(built["counterweights"], 1):
                rows += _records(f"built counterweight {i}", weight)
            for i, shaft in enumerate(built["balancer_shafts"], 1):
                rows += _balancer_rows(f"built balancer shaft {i}", shaft)
            for order in built["orders"]:
                values = order_values(order, b.engine.per_cylinder_unit_n, scale)
                rows += [
                    (f"as built order {order['order']}", name, value, unit)
                    for name, value, unit in zip(_ORDER_QUANTITIES, values, units, strict=True)
                ]
        for i, weight in enumerate(record["counterweights"], 1):
            rows += _records(f"counterweight {i}", weight, weight_keys)
        if record["antivibrateur"] is not None:
            rows += _records("antivibrateur", record["antivibrateur"])
        for stage, key in (("residual", "residual"), ("after shafts", "after_shafts")):
            for order in record.get(key, {}).get("orders", []):
                values = order_values(order, b.engine.per_cylinder_unit_n, scale)
                rows += [
                    (f"{stage} order {order['order']}", name, value, unit)
                    for name, value, unit in zip(_ORDER_QUANTITIES, values, units, strict=True)
                ]
        for i, shaft in enumerate(record.get("shafts", []), 1):
            rows += _records(f"shaft {i}", shaft)
        for i, shaft in enumerate(record.get("balancer_shafts", []), 1):
            rows += _balancer_rows(f"balancer shaft {i}", shaft)
        for total in record.get("shaft_rolling_moments", []):
            ratios = " ".join(f"{r:+d}" for r in total["speed_ratios"])
            rows += _rolling_rows(f"shafts {ratios} rolling moment order {total['order']}", total)
        for i, mass in enumerate(record.get("test_masses_kg") or [], 1):
            rows.append((f"test mass throw {i}", "mass", mass, "kg"))
        for item, quantity, value, unit in rows:
            writer.writerow([record["name"], record["config"], item, quantity, _value(value), unit])
    return buffer.getvalue()


def torque_csv(results, scale):
    """Every torque of ``balance torque`` in long form: engine, config, torque (inertia, gas,
    total, tilting, frame, and "crankshaft N" for each of several), order, cos, sin, amplitude,
    phase (order 0 is the mean); torques in ``scale``'s moment unit."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    ml = scale.column_moment
    writer.writerow(
        [
            "engine",
            "config",
            "torque",
            "order",
            f"cos_{ml}",
            f"sin_{ml}",
            f"amplitude_{ml}",
            "phase_deg",
        ]
    )
    for r in results:
        named = [
            (name, getattr(r, name)) for name in ("inertia", "gas", "total", "tilting", "frame")
        ]
        # an engine with several crankshafts: each one's torque, in its own sense
        named += [(f"crankshaft {c.number}", c.torque) for c in r.crankshafts]
        for name, series in named:
            if series is None:
                continue
            record = series.to_dict()
            writer.writerow(
                [
                    r.engine.name,
                    r.engine.config_path,
                    name,
                    0.0,
                    _value(scale.moment(record["mean_Nm"])),
                    "",
                    "",
                    "",
                ]
            )
            for order in record["orders"]:
                writer.writerow(
                    [r.engine.name, r.engine.config_path, name, order["order"]]
                    + [
                        _value(scale.moment(order[f"{key}_Nm"]))
                        for key in ("cos", "sin", "amplitude")
                    ]
                    + [_value(order["phase_deg"])]
                )
    return buffer.getvalue()


def search_csv(result):
    """One row per listed arrangement: rank, score, phases, firing order and intervals, and
    every coefficient (full precision)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    names = list(result.arrangements[0].coefficients) if result.arrangements else []
    writer.writerow(
        ["rank", "score", "phases_deg", "firing_order", "intervals_deg", "mirror_of"] + names
    )
    for a in result.arrangements:
        record = a.to_dict()
        writer.writerow(
            [
                a.rank,
                _value(a.score),
                " ".join(repr(float(p)) for p in a.phases_deg),
                "-".join(map(str, record["firing"]["order"])),
                " ".join(repr(float(x)) for x in record["firing"]["intervals_deg"]),
                "" if a.mirror_of is None else a.mirror_of,
            ]
            + [_value(a.coefficients[n]) for n in names]
        )
    return buffer.getvalue()


def family_csv(result):
    """One row per number of cylinders, SI, full precision."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    moments = [f"M{k}{d}_Nm" for k in (1, 2, 4) for d in "VH"] + [
        f"M1{d}_{name}_Nm" for name in ("standard", "rotating", "crank") for d in "VH"
    ]
    pru = [f"PRU_M{k}{d}_Nm_per_kW" for k in (1, 2) for d in "VH"] + [
        f"PRU_M1{d}_{name}_Nm_per_kW" for name in ("standard", "rotating", "crank") for d in "VH"
    ]
    writer.writerow(
        ["cylinders", "firing_order", "method", "score", "first_order_balance_factor"]
        + moments
        + ["power_kW"]
        + pru
        + ["h_type_order", "h_type_Nm", "x_type_order", "x_type_Nm", "second_order_compensator"]
    )
    for row in result.to_dict()["rows"]:
        entries = {} if row["pru"] is None else {e["order"]: e for e in row["pru"]["orders"]}
        values = [
            entries[k][f"{side}_Nm_per_kW"] if k in entries else None
            for k in (1, 2)
            for side in ("vertical", "horizontal")
        ]
        named = {} if row["pru"] is None else row["pru"]["first_order"] or {}
        values += [
            None if named.get(name) is None else named[name][f"{side}_Nm_per_kW"]
            for name in ("standard", "rotating", "crank")
            for side in ("vertical", "horizontal")
        ]
        guides = []
        for key in ("h_type", "x_type"):
            moment = row[key]
            guides += [None, None] if moment is None else [moment["order"], moment["amplitude_Nm"]]
        writer.writerow(
            [
                row["cylinders"],
                "-".join(map(str, row["firing_order"])),
                row["method"],
                _value(row["score"]),
                _value(row["first_order_balance"]["balance_factor"]),
            ]
            + [_value(row.get(m)) for m in moments]
            + [_value(row["power_kW"])]
            + [_value(v) for v in values]
            + [_value(v) for v in guides]
            + [row["second_order_compensator"]]
        )
    return buffer.getvalue()
