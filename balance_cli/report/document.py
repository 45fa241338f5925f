"""The JSON document of ``balance compare``: a contract other programs read (see README)."""

import json

from ..units import rad_s_to_rpm
from .values import order_values

__all__ = ["compare_document", "balance_document", "to_json"]


def engine_document(result, reference):
    """One engine's entry: identification, firing, largest resultant and every order."""
    engine = result.engine
    firing = result.firing
    return {
        "name": engine.name,
        "config": engine.config_path,
        "source": engine.source,
        "cylinders": engine.n_cylinders,
        "cycle": engine.cycle,
        "frame": engine.frame,
        "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
        "unit_force_N": engine.unit_force_n,
        "firing": {
            "order": list(firing.order),
            "angles_deg": list(firing.angles_deg),
            "intervals_deg": list(firing.intervals_deg),
            "uniform": firing.uniform,
            "max_deviation_deg": firing.max_deviation_deg,
            "given": firing.given,
        },
        "largest_resultant_N": result.largest_force_n,
        "counterweighted_resultant_N": result.counterweighted_force_n,
        "counterweighted_resultant_per_cylinder": result.counterweighted_per_cylinder,
        "percent_of_reference": result.percent_of(reference),
        "sampling_ok": result.shaking.sampling_ok,
        "orders": [
            {"order": o.order, **order_values(o, result.per_cylinder_unit_n)} for o in result.shaking.orders
        ],
    }


def compare_document(results, reference_index, samples, max_order):
    reference = results[reference_index]
    return {
        "balance_version": 1,
        "samples": samples,
        "max_order": max_order,
        "reference": reference.engine.name,
        "engines": [engine_document(r, reference) for r in results],
    }


def to_json(document):
    return json.dumps(document, indent=2, ensure_ascii=False) + "\n"


def _orders(shaking, unit_n):
    return [{"order": o.order, **order_values(o, unit_n)} for o in shaking.orders]


def balance_document(results, samples, max_order):
    """JSON of ``balance counterweight``: see the README for every key."""
    engines = []
    for r in results:
        engine = r.engine
        unit = engine.unit_force_n * engine.n_cylinders
        entry = {
            "name": engine.name,
            "config": engine.config_path,
            "cylinders": engine.n_cylinders,
            "frame": engine.frame,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "unit_force_N": engine.unit_force_n,
            "balance_factor": r.balance_factor,
            "counterweights": [
                {"z_m": c.plane.z_m, "throw": c.plane.throw, "mass_kg": c.mass_kg,
                 "radius_m": c.radius_m, "angle_deg": c.angle_deg}
                for c in r.counterweights
            ],
            "antivibrateur": None if r.antivibrateur is None else {
                "mass_eccentricity_kgm": r.antivibrateur.mass_eccentricity_kgm,
                "eccentricity_m": r.antivibrateur.eccentricity_m,
                "mass_kg": r.antivibrateur.mass_kg,
                "phase_deg": r.antivibrateur.phase_deg,
            },
            "residual": {"largest_resultant_N": r.residual.largest_force(),
                         "orders": _orders(r.residual, unit)},
        }
        if r.after_shafts is not None:
            entry["shafts"] = [
                {"order": s.order, "speed_ratio": s.speed_ratio,
                 "mass_eccentricity_kgm": s.mass_eccentricity_kgm, "phase_deg": s.phase_deg,
                 "z_m": s.z_m}
                for s in r.shafts
            ]
            entry["after_shafts"] = {"largest_resultant_N": r.after_shafts.largest_force(),
                                     "orders": _orders(r.after_shafts, unit)}
        if r.test_masses_kg is not None:
            entry["test_masses_kg"] = list(r.test_masses_kg)
        engines.append(entry)
    return {"balance_version": 1, "samples": samples, "max_order": max_order, "engines": engines}
