"""Checks of a public function's arguments, at its entry: one BalanceError naming the argument.

A caller of the library may pass anything (a string for a number, NaN, a list for an engine);
without these checks such values travelled until numpy, scipy or an attribute lookup failed
with their own exception, or were silently taken for something else (a negative bore as its
absolute value). Imports only errors and units, so that every module may use it.
"""

import math
import numbers
import os

import numpy as np

from .errors import AnalysisError, UnitError
from .units import check_finite_range

__all__ = ["is_real", "positive", "whole", "curve", "instance", "path", "items"]


def is_real(value) -> bool:
    """A real number (numpy's too), not a bool."""
    return isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))


def positive(value, name, dimension=None, error=AnalysisError) -> float:
    """``value`` as a float: a real number greater than zero, finite, and within the range
    balance accepts for ``dimension`` (a key of :data:`balance_cli.units.LIMITS`)."""
    if not is_real(value) or not value > 0:  # NaN fails "> 0" too
        raise error(f"must be a number greater than zero, got {value!r}", name)
    value = float(value)
    if dimension is not None:
        try:
            check_finite_range(value, dimension)
        except UnitError as exc:
            raise error(f"is invalid: {exc}", name) from None
    elif not math.isfinite(value):
        raise error(f"must be finite, got {value!r}", name)
    return value


def whole(value, name, low, high, error=AnalysisError) -> int:
    """``value`` as an int: a whole number (numpy's too, not a bool) from ``low`` to ``high``."""
    if (
        not isinstance(value, (int, np.integer))
        or isinstance(value, (bool, np.bool_))
        or not low <= value <= high
    ):
        raise error(f"must be a whole number from {low:,} to {high:,}, got {value!r}", name)
    return int(value)


def curve(values, name, error=AnalysisError) -> np.ndarray:
    """A one-dimensional float array of finite real numbers."""
    try:
        array = np.asarray(values)
        if array.dtype.kind not in "iuf" or array.ndim != 1:
            raise ValueError
        array = array.astype(float)
    except (TypeError, ValueError):
        raise error(
            f"must be a one-dimensional array of real numbers, got {type(values).__name__}", name
        ) from None
    if not np.all(np.isfinite(array)):
        raise error("must hold finite numbers only (it has NaN or inf)", name)
    return array


def instance(value, kind, name, error=AnalysisError, hint=""):
    """``value`` unchanged if it is a ``kind``."""
    if not isinstance(value, kind):
        names = " or ".join(k.__name__ for k in (kind if isinstance(kind, tuple) else (kind,)))
        raise error(
            f"must be {'an' if names[0] in 'AEIOU' else 'a'} {names}{hint}, got "
            f"{type(value).__name__}",
            name,
        )
    return value


def path(value, name="path"):
    """A file path (str or os.PathLike); a ConfigError naming ``name`` otherwise."""
    from .errors import ConfigError

    if isinstance(value, (str, os.PathLike)) and str(os.fspath(value)).strip():
        return value
    error = ConfigError(
        f"<{name}>", "", f"{name} must be a file path (a str or os.PathLike), got {value!r}"
    )
    error.parameter = name
    raise error


def items(values, kind, name, error=AnalysisError, what="analysed engine") -> list:
    """``values`` as a non-empty list of ``kind`` (one ``kind`` alone is taken as a list of one)."""
    if isinstance(values, kind):
        return [values]
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise error(f"must be a list of {kind.__name__}s, got {type(values).__name__}", name)
    chosen = list(values)
    if not chosen:
        raise error(f"needs at least one {what}", name)
    for value in chosen:
        if not isinstance(value, kind):
            raise error(f"must hold {kind.__name__}s only, got {type(value).__name__}", name)
    return chosen
