"""Changing an engine's values as a configuration file writes them: ``"550 g"``, ``"3000 rpm"``,
a throw's phase in degrees. :meth:`Engine.edit <balance_cli.model.Engine.edit>` is the face of
it; here the keys, their units and their checks."""

import dataclasses
import math
import numbers

from ..checks import is_real
from ..errors import ModelError, UnitError
from ..units import parse_quantity

__all__ = ["ENGINE_KEYS", "CYLINDER_KEYS", "THROW_KEYS", "edited"]

#: the engine's own keys: key -> (dimension, field, sign); ``reciprocating`` sets every
#: cylinder's and ``rod_ratio`` (a plain number, l/r) the rod length
ENGINE_KEYS = {
    "speed": ("angular speed", "speed_rad_s", "positive"),
    "crank_radius": ("length", "crank_radius_m", "positive"),
    "rod_length": ("length", "rod_length_m", "positive"),
    "rod_ratio": ("ratio", None, "positive"),
    "pin_offset": ("length", "pin_offset_m", "any"),
    "reciprocating": ("mass", None, "positive"),
    "rotating": ("mass", "rotating_kg", "non-negative"),
    "crank": ("mass", "crank_kg", "non-negative"),
}
#: one cylinder's keys (``cylinder=N``)
CYLINDER_KEYS = {
    "reciprocating": ("mass", "reciprocating_kg", "positive"),
    "opposed_reciprocating": ("mass", "opposed_reciprocating_kg", "positive"),
    "z": ("length", "z_m", "any"),
    "pin_offset": ("length", "pin_offset_m", "any"),
}
#: one throw's keys (``throw=N``); ``phase`` in degrees, as a file writes it
THROW_KEYS = {
    "phase": ("angle", "phase_rad", "any"),
    "z": ("length", "z_m", "any"),
    "rotating": ("mass", "rotating_kg", "non-negative"),
}
_EXAMPLES = {"angular speed": '"3000 rpm"', "length": '"82.5 mm"', "mass": '"550 g"'}
#: a phase as a file may write it, degrees either way
_TURN_DEG = 360.0


def _value(key, raw, dimension, sign, where):
    """``raw`` (text with a unit; degrees or a ratio as a number) in SI, checked."""
    if dimension in ("angle", "ratio"):
        if not is_real(raw) or not math.isfinite(raw):
            what = "a number of degrees such as 90" if dimension == "angle" else "a number"
            raise ModelError(f"{where}must be {what}, got {raw!r}", key)
        if dimension == "angle":
            if abs(raw) > _TURN_DEG:
                raise ModelError(f"{where}must be from -360 to 360 degrees, got {raw!r}", key)
            return math.radians(raw)
        if raw <= 1.0:
            raise ModelError(
                f"{where}must be greater than 1 (the rod longer than the crank radius), "
                f"got {raw!r}",
                key,
            )
        return float(raw)
    if not isinstance(raw, str):
        raise ModelError(
            f"{where}must be {'an' if dimension[0] in 'aeiou' else 'a'} {dimension} with its "
            f"unit, such as {_EXAMPLES[dimension]}, got {raw!r}",
            key,
        )
    try:
        value = parse_quantity(raw, dimension)
    except UnitError as exc:
        raise ModelError(f"{where}is invalid: {exc}", key) from None
    if sign == "positive" and value <= 0.0 or sign == "non-negative" and value < 0.0:
        need = "greater than zero" if sign == "positive" else "zero or more"
        raise ModelError(f"{where}must be {need}, got {raw!r}", key)
    return value + 0.0  # -0 reads as 0


def _number(value, kind, numbers_of):
    """The cylinder or throw ``value`` names, checked against the engine's."""
    if (
        isinstance(value, bool)
        or not isinstance(value, numbers.Integral)
        or int(value) not in numbers_of
    ):
        listed = ", ".join(map(str, numbers_of))
        raise ModelError(
            f"must be one of the engine's {kind} numbers ({listed}), got {value!r}", kind
        )
    return int(value)


def _keys_of(values, allowed, scope):
    unknown = [key for key in values if key not in allowed]
    if unknown:
        others = (
            ""
            if scope == "the engine"
            else "; the engine's own keys go without cylinder= or throw="
        )
        raise ModelError(
            f"is not a key of {scope}: choose from {', '.join(allowed)}{others}", unknown[0]
        )


def _si(table, values, where):
    """``values`` of the keys of ``table`` in SI, by model field."""
    out = {}
    for key, raw in values.items():
        dimension, field, sign = table[key]
        out[field] = _value(key, raw, dimension, sign, where)
    return out


def edited(engine, cylinder, throw, values):
    """The changes to ``engine`` (its fields, for :meth:`Engine.replace`) that ``values``
    make, for ``cylinder`` or ``throw`` (a number) or the engine (both None)."""
    changes = {}
    if "name" in values:
        changes["name"] = values.pop("name")
    if not values and not changes:
        raise ModelError('nothing to change: give a key and its value, such as speed="3000 rpm"')
    if cylinder is not None and throw is not None:
        raise ModelError("and throw cannot both be given: edit one at a time", "cylinder")
    if cylinder is not None:
        number = _number(cylinder, "cylinder", [c.number for c in engine.cylinders])
        _keys_of(values, CYLINDER_KEYS, "a cylinder")
        fields = _si(CYLINDER_KEYS, values, f"of cylinder {number} ")
        changes["cylinders"] = tuple(
            dataclasses.replace(c, **fields) if c.number == number else c for c in engine.cylinders
        )
    elif throw is not None:
        number = _number(throw, "throw", list(range(1, len(engine.throws) + 1)))
        _keys_of(values, THROW_KEYS, "a throw")
        fields = _si(THROW_KEYS, values, f"of throw {number} ")
        changes["throws"] = tuple(
            dataclasses.replace(t, **fields) if i == number else t
            for i, t in enumerate(engine.throws, 1)
        )
    else:
        changes.update(_engine_changes(engine, values))
    return changes


def _engine_changes(engine, values):
    _keys_of(values, ENGINE_KEYS, "the engine")
    if "rod_ratio" in values and "rod_length" in values:
        raise ModelError("and rod_length cannot both be given: one sets the other", "rod_ratio")
    si = {k: _value(k, v, ENGINE_KEYS[k][0], ENGINE_KEYS[k][2], "") for k, v in values.items()}
    changes = {ENGINE_KEYS[k][1]: v for k, v in si.items() if ENGINE_KEYS[k][1]}
    if "rod_ratio" in si:
        radius = changes.get("crank_radius_m", engine.crank_radius_m)
        changes["rod_length_m"] = si["rod_ratio"] * radius
    if "reciprocating" in si:
        # every piston, an opposed bore's second one too, as [masses] reciprocating sets them
        mass = si["reciprocating"]
        changes["cylinders"] = tuple(
            dataclasses.replace(
                c,
                reciprocating_kg=mass,
                opposed_reciprocating_kg=mass if c.is_opposed else None,
            )
            for c in engine.cylinders
        )
    return changes
