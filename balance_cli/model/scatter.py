"""The production scatter of an engine's parts and dimensions: one standard deviation each."""

import math
from dataclasses import dataclass, fields

from ..errors import ModelError
from .values import check_angle, check_quantity

__all__ = ["ToleranceBand"]

#: field -> (dimension, what it scatters), in the order a table lists them
_FIELDS = {
    "reciprocating_kg": ("mass", "each cylinder's reciprocating mass"),
    "rotating_kg": ("mass", "each throw's rotating mass (its big ends)"),
    "crank_radius_m": ("length", "each throw's crank radius"),
    "rod_length_m": ("length", "each rod's length, centre to centre"),
    "phase_rad": ("angle", "each throw's phase but throw 1's, the reference"),
    "bank_angle_rad": ("angle", "each bank's direction"),
    "pin_offset_m": ("length", "each cylinder's piston-pin offset"),
}
#: the largest angular scatter taken: a quarter turn is no tolerance
_MOST_RAD = math.pi / 2


@dataclass(frozen=True)
class ToleranceBand:
    """One standard deviation of a normal scatter for each part and dimension of an engine
    (the configuration's ``[tolerances]``); every one drawn independently, part by part.

    Parameters
    ----------
    reciprocating_kg : float
        of each cylinder's reciprocating mass, kg
    rotating_kg : float
        of each throw's rotating mass (the big ends on its pin), kg
    crank_radius_m : float
        of each throw's crank radius, m
    rod_length_m : float
        of each rod's length (a plain, master or link rod), m
    phase_rad : float
        of each throw's phase, rad; throw 1 is the reference the phases are measured from, so
        it has none
    bank_angle_rad : float
        of each bank's direction from the reference axis, rad
    pin_offset_m : float
        of each cylinder's piston-pin offset, m
    """

    reciprocating_kg: float = 0.0
    rotating_kg: float = 0.0
    crank_radius_m: float = 0.0
    rod_length_m: float = 0.0
    phase_rad: float = 0.0
    bank_angle_rad: float = 0.0
    pin_offset_m: float = 0.0

    def __post_init__(self):
        for name, (dimension, _) in _FIELDS.items():
            value = getattr(self, name)
            if dimension == "angle":
                check_angle(value, name)
                if not 0.0 <= value <= _MOST_RAD:
                    raise ModelError(
                        f"must be from 0 to {math.degrees(_MOST_RAD):g}° (one standard "
                        f"deviation), got {math.degrees(value):g}°",
                        name,
                    )
            else:
                check_quantity(value, dimension, name, sign="non-negative")
            object.__setattr__(self, name, float(value) + 0.0)

    @property
    def geometric(self) -> bool:
        """Whether any dimension scatters (not only masses): then every run's linkage is its
        own."""
        return any(
            getattr(self, n) > 0.0
            for n in _FIELDS
            if _FIELDS[n][1] and n not in ("reciprocating_kg", "rotating_kg")
        )

    @property
    def empty(self) -> bool:
        """Nothing scatters."""
        return all(getattr(self, f.name) == 0.0 for f in fields(self))

    @staticmethod
    def describe(name: str) -> str:
        """What the field ``name`` scatters, in words."""
        return _FIELDS[name][1]
