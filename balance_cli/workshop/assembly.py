"""An engine as assembled from weighed parts: which piston and rod sit in which cylinder, the
masses that makes, and the configuration that describes it.

**The rule.** A mass the parts cover whole is theirs: with pistons and rods both given, a
cylinder's reciprocating mass is its piston plus its rod's small end, and a throw's rotating
mass the big ends of the rods on its pin. A mass they cover in part keeps the configuration's
share of the rest: with pistons only, a cylinder's reciprocating mass is the configuration's
less the mean piston plus its own piston (the rod's small end stays as configured, cylinder
by cylinder: a radial's master rod stays where it is); with rods only, the configuration's
less the mean small end plus its own. So the same engine with every part at the mean mass of
its kind differs from the one assembled only by the parts' deviations from their means, which
is what matching weighs; what the masses that are not matched leave (a radial's master rod,
heavier than its link rods, in the pistons' matching) counts as well, as Tanaka counts it: the
engine is measured against the same engine with every cylinder at the mean reciprocating mass
and every throw at the mean rotating mass (:func:`deviations`).
"""

from dataclasses import dataclass, replace

import numpy as np

from ..config import WRITE_DIGITS, as_built_toml
from ..errors import AnalysisError
from ..model import Engine
from ..units import kg_to_g

__all__ = ["Fit", "check_fits", "deviations", "at_means", "assembled", "assembled_toml"]


@dataclass(frozen=True)
class Fit:
    """Which part sits where: for each cylinder, in the order of ``Engine.cylinders``, the
    index of its piston in ``PartSet.pistons`` and of its rod in ``PartSet.rods`` (None: that
    kind is not fitted)."""

    pistons: tuple | None
    rods: tuple | None


def check_fits(engine, parts):
    """Raise AnalysisError unless ``parts`` can be fitted to ``engine``: one piston (rod) per
    cylinder, no opposed pistons, rods on plain rods only."""
    n = engine.n_cylinders
    if engine.has_opposed_pistons:
        raise AnalysisError(
            f"{engine.name!r} has opposed pistons (two in a bore): matching fits one piston "
            "and one rod per cylinder",
            "engine",
        )
    for kind in parts.kinds:
        count = len(getattr(parts, kind))
        if count != n:
            raise AnalysisError(
                f"lists {count} {kind} for the {n} cylinders of {engine.name!r}; give one per "
                "cylinder",
                "parts",
            )
    if parts.rods and any(c.is_link for c in engine.cylinders):
        raise AnalysisError(
            f"lists rods, but {engine.name!r} has master and link rods, which are not "
            "interchangeable: give its pistons only (the rods stay as the configuration has "
            "them)",
            "parts",
        )


def deviations(engine, parts, fit):
    """What the engine as assembled has more than the same engine with every cylinder's
    reciprocating mass at their mean and every throw's rotating mass at theirs (Tanaka's
    Part I § 5 measure of inequality): (per cylinder, in the order of ``Engine.cylinders``,
    kg; per throw, kg). The means do not depend on the assignment."""
    reciprocating, rotating = _masses(engine, parts, fit)
    reciprocating = np.array(reciprocating)
    rotating = np.array(
        [engine.rotating_of(i) if kg is None else kg for i, kg in enumerate(rotating)]
    )
    return reciprocating - reciprocating.mean(), rotating - rotating.mean()


def at_means(engine, parts):
    """:func:`deviations` with every part at the mean mass of its kind: what the masses that
    are not matched (a radial's master rod, a throw's own rotating mass) leave, kg."""
    mean_parts = type(parts)(
        tuple(type(p)(p.id, parts.mean_piston_kg()) for p in parts.pistons),
        tuple(
            type(r)(r.id, parts.mean_small_end_kg(), parts.mean_big_end_kg()) for r in parts.rods
        ),
    )
    n = engine.n_cylinders
    listed = tuple(range(n))
    fit = Fit(listed if parts.pistons else None, listed if parts.rods else None)
    return deviations(engine, mean_parts, fit)


def _masses(engine, parts, fit):
    """Each cylinder's reciprocating and each throw's rotating mass as assembled, kg."""
    reciprocating: list = []
    rotating: list = []
    for position, c in enumerate(engine.cylinders):
        piston = None if fit.pistons is None else parts.pistons[fit.pistons[position]]
        rod = None if fit.rods is None else parts.rods[fit.rods[position]]
        if piston is not None and rod is not None:
            reciprocating.append(piston.mass_kg + rod.small_end_kg)
        elif piston is not None:
            reciprocating.append(c.reciprocating_kg - parts.mean_piston_kg() + piston.mass_kg)
        else:
            assert rod is not None
            reciprocating.append(c.reciprocating_kg - parts.mean_small_end_kg() + rod.small_end_kg)
    for index in range(len(engine.throws)):
        if fit.rods is None:
            rotating.append(None)
            continue
        rotating.append(
            sum(
                parts.rods[fit.rods[position]].big_end_kg
                for position, c in enumerate(engine.cylinders)
                if c.throw_index == index
            )
        )
    return reciprocating, rotating


def assembled(engine, parts, fit, name=None) -> Engine:
    """``engine`` with ``parts`` fitted as ``fit`` says (see the module's rule), named
    ``name`` (default: its own)."""
    reciprocating, rotating = _masses(engine, parts, fit)
    for c, kg in zip(engine.cylinders, reciprocating, strict=True):
        if kg <= 0.0:
            raise AnalysisError(
                f"leave cylinder {c.number} a reciprocating mass of {kg_to_g(kg):.4g} g: the "
                "configuration's is lighter than the mean part; give its reciprocating mass "
                "with the parts in it",
                "parts",
            )
    cylinders = tuple(
        replace(c, reciprocating_kg=kg)
        for c, kg in zip(engine.cylinders, reciprocating, strict=True)
    )
    throws = tuple(
        t if kg is None else replace(t, rotating_kg=kg)
        for t, kg in zip(engine.throws, rotating, strict=True)
    )
    return engine.replace(cylinders=cylinders, throws=throws, name=name or engine.name)


def _grams(kg):
    """A mass as a configuration writes it: grams to :data:`WRITE_DIGITS` significant digits."""
    return f"{float(f'{kg_to_g(kg):.{WRITE_DIGITS}g}') + 0.0!r} g"


def assembled_toml(data: dict, engine: Engine, built: Engine, header: str, name: str) -> str:
    """The configuration of ``built`` (an :func:`assembled` copy of ``engine``) from the parsed
    configuration ``data`` of ``engine``: every cylinder with its own ``reciprocating`` (the
    ``[[cylinders]]`` listed, as the file lists them or one per cylinder) and, where rods are
    fitted, every throw with its own ``rotating``; named ``name``.

    Raises
    ------
    AnalysisError
        a configuration that derives its masses from ``[parts]``, which per-cylinder masses
        cannot override
    """
    if "parts" in data:
        raise AnalysisError(
            "cannot be written for a configuration with [parts]: its masses are derived from "
            "them; give [masses] instead to write each cylinder's own",
            "write",
        )
    out = dict(data)
    by_number = {c.number: c for c in built.cylinders}
    if "cylinders" in data:
        out["cylinders"] = [
            {**table, "reciprocating": _grams(by_number[table["number"]].reciprocating_kg)}
            for table in data["cylinders"]
        ]
    else:
        out["cylinders"] = [
            {
                "number": c.number,
                "bank": c.bank,
                "throw": c.throw,
                "reciprocating": _grams(by_number[c.number].reciprocating_kg),
            }
            for c in engine.cylinders
        ]
    if any(t.rotating_kg is not None for t in built.throws):
        out["throws"] = [
            {**table, "rotating": _grams(t.rotating_kg)} if t.rotating_kg is not None else table
            for table, t in zip(data["throws"], built.throws, strict=True)
        ]
    return as_built_toml(out, {}, header, name=name)
