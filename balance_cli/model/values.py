"""The model's checks of one value (a finite SI quantity within range, an angle within a turn
either way), which every model class runs on its fields, and a point of the transverse plane
given by its lateral and vertical offsets."""

import math

from ..checks import is_real
from ..errors import ModelError, UnitError
from ..units import check_finite_range

__all__ = ["check_quantity", "check_angle", "offset_position"]


def offset_position(lateral_m, vertical_m, vertical_rad):
    """A point of the transverse plane as a complex number (real part along the reference
    axis), from its lateral and vertical distances to the crank axis, the vertical lying at
    ``vertical_rad`` from the reference axis and the lateral 90° on from it with rotation."""
    return complex(vertical_m, lateral_m) * complex(math.cos(vertical_rad), math.sin(vertical_rad))


def check_quantity(value, dimension, parameter, sign="positive", cylinder=None):
    """A finite SI value within the accepted range; ``sign`` "positive", "non-negative" or "any"."""
    prefix = f"cylinder {cylinder}: {parameter} " if cylinder is not None else ""
    name = None if prefix else parameter
    if not is_real(value):
        raise ModelError(f"{prefix}must be a number, got {value!r}", name, cylinder)
    try:
        # a value that may be zero may also be tiny (rounding noise of a computed position)
        check_finite_range(float(value), dimension, smallest=sign == "positive")
    except UnitError as exc:
        raise ModelError(f"{prefix}is invalid: {exc}", name, cylinder) from None
    if sign == "positive" and value <= 0 or sign == "non-negative" and value < 0:
        need = "greater than zero" if sign == "positive" else "zero or more"
        raise ModelError(f"{prefix}must be {need}, got {value!r}", name, cylinder)


def check_angle(value, parameter, cylinder=None):
    if not is_real(value) or not math.isfinite(value) or abs(value) > 2 * math.pi:
        where = f"cylinder {cylinder}: {parameter} " if cylinder is not None else ""
        raise ModelError(
            f"{where}must be a finite angle between -2π and 2π rad, got {value!r}",
            None if where else parameter,
            cylinder,
        )
