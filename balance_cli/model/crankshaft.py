"""The crankshafts and their throws: where each crank pin sits and how it turns."""

import numbers
from dataclasses import dataclass

from ..errors import ModelError
from .values import check_angle, check_quantity

__all__ = ["Crankshaft", "Throw", "REFERENCE_CRANKSHAFT"]


@dataclass(frozen=True)
class Crankshaft:
    """One crankshaft of an engine with several (an H engine, an opposed-piston engine, the
    Napier Deltic), geared 1:1 to the first.

    Every crankshaft makes one turn per turn of the first (the engine angle θ): the pistons it
    drives share cylinders and a firing cycle with the others', which repeat only then.

    Parameters
    ----------
    x_m, y_m : float
        position of its axis in the transverse plane, m: along the reference axis (bank angle
        0) and across it (bank angle 90°), from the first crankshaft's axis
    direction : int
        +1 turning with the first crankshaft, −1 against it
    phase_rad : float
        its angle when the first is at 0, measured in its own sense of turning, rad: a throw of
        phase φ on it points at direction·(θ + phase_rad + φ) from the reference axis
    """

    x_m: float = 0.0
    y_m: float = 0.0
    direction: int = 1
    phase_rad: float = 0.0

    def __post_init__(self):
        check_quantity(self.x_m, "length", "x_m", sign="any")
        check_quantity(self.y_m, "length", "y_m", sign="any")
        if (
            isinstance(self.direction, bool)
            or not isinstance(self.direction, numbers.Integral)
            or self.direction not in (1, -1)
        ):
            raise ModelError(
                f"must be +1 (with the first crankshaft) or -1 (against it), got "
                f"{self.direction!r}",
                "direction",
            )
        object.__setattr__(self, "direction", int(self.direction))
        check_angle(self.phase_rad, "phase_rad")

    @property
    def centre(self) -> complex:
        """The axis position as a complex number, m (real along the reference axis)."""
        return complex(self.x_m, self.y_m)


@dataclass(frozen=True)
class Throw:
    """One crank throw.

    Parameters
    ----------
    phase_rad : float
        angle of the throw relative to throw 1, positive with rotation (of its own
        crankshaft), rad
    z_m : float
        axial position, m
    crankshaft : int
        the number of the crankshaft that carries it, from 1 (the first, for an engine with
        one), as in ``[[throws]]``'s ``crankshaft``
    rotating_kg : float or None
        the big ends at this throw's pin, kg, where they differ from throw to throw (parts
        weighed one by one, :func:`balance_cli.match`); None (the default) takes the engine's
        ``rotating_kg``
    """

    phase_rad: float
    z_m: float = 0.0
    crankshaft: int = 1
    rotating_kg: float | None = None

    def __post_init__(self):
        # checked here too, not only in the Engine: a Throw of NaN once built without a word
        check_angle(self.phase_rad, "phase_rad")
        check_quantity(self.z_m, "length", "z_m", sign="any")
        if (
            isinstance(self.crankshaft, bool)
            or not isinstance(self.crankshaft, numbers.Integral)
            or self.crankshaft < 1
        ):
            raise ModelError(
                f"must be a crankshaft number from 1, got {self.crankshaft!r}", "crankshaft"
            )
        object.__setattr__(self, "crankshaft", int(self.crankshaft))
        if self.rotating_kg is not None:
            check_quantity(self.rotating_kg, "mass", "rotating_kg", sign="non-negative")

    @property
    def crankshaft_index(self) -> int:
        """Where its crankshaft stands in ``Engine.crankshafts`` (0-based, for indexing)."""
        return self.crankshaft - 1


#: the one crankshaft of an engine that names none: the reference itself
REFERENCE_CRANKSHAFT = Crankshaft()
