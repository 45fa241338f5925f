"""What a sweep returns: :class:`SweepResult` of one parameter, :class:`SweepGrid` of two.

Their ``to_dict()`` is what ``sweep --format json`` writes, and their ``records()`` what its
CSV rows hold: both are the contract other programs read (see the JSON page).
"""

from dataclasses import dataclass

import numpy as np

from ...errors import NotInResultError
from ...output import DOCUMENT_VERSION
from ...tabular import Tabular
from ...units import rad_s_to_rpm
from .keys import Parameter

__all__ = ["SweepResult", "SweepGrid", "parameter_dict"]


def parameter_dict(parameter: Parameter, values, values_si) -> dict:
    """The JSON object of a swept parameter with its values."""
    return {
        "key": parameter.key,
        "kind": parameter.kind,
        "unit_SI": parameter.unit_si,
        "file_value": parameter.file_value,
        "changes": list(parameter.changes),
        "meaning": parameter.meaning,
        "values": list(values),
        "values_SI": list(values_si),
    }


def _listed(values):
    return None if values is None else list(values)


def _column(quantities, quantity):
    for q in quantities:
        if quantity in (q.name, q.column):
            return q.column
    raise NotInResultError(
        f"{quantity!r} is not among this sweep's quantities "
        f"({', '.join(q.name for q in quantities)})",
        "quantity",
    )


@dataclass(frozen=True)
class SweepResult(Tabular):
    """A sweep: one parameter's values and what each gives.

    Attributes
    ----------
    name, config : str
        the engine's name and the configuration's path (or the name given for a dict)
    parameter : Parameter
    values : tuple
        as written in the file ("140 mm", 60.0)
    values_si : tuple of float
        the same in SI (m, kg, rad/s, kg·m², Pa, W; radians for angles), see
        ``parameter.unit_si``
    quantities : tuple of Quantity
    points : tuple of dict
        one record per value: ``value``, ``value_SI`` and one key per quantity's ``column``
        (SI: N, N·m)
    engines : tuple of Engine
        each point's engine, built and checked (analyse one again for more than the
        quantities; the analyses are not kept, so that a long sweep stays small)
    samples, max_order : int
    inertia_kgm2 : float or None
        the flywheel inertia of the steadiness, kg·m²
    load : str
    overrides : tuple of (key, value)
        the keys set at every point besides the parameter
    mount_speeds_rpm : tuple of float or None
        the speeds over which a mount's force is the largest (None: each point's own speed)
    """

    name: str
    config: str
    parameter: Parameter
    values: tuple
    values_si: tuple
    quantities: tuple
    points: tuple
    engines: tuple
    samples: int
    max_order: int
    inertia_kgm2: float | None = None
    load: str = "propeller"
    overrides: tuple = ()
    mount_speeds_rpm: tuple | None = None

    @property
    def speed_rpm(self) -> float | None:
        """The speed of every point, rpm; None when the speed is what varies."""
        if self.parameter.key == "speed":
            return None
        return rad_s_to_rpm(self.engines[0].speed_rad_s)

    def series(self, quantity: str) -> np.ndarray:
        """One quantity at every point, SI, by name (``"F2"``) or column (``"F2_N"``)."""
        column = _column(self.quantities, quantity)
        return np.array([p[column] for p in self.points], dtype=float)

    def records(self) -> list:
        """One flat dict per point (``value``, ``value_SI``, the quantities' columns), ready
        for ``pandas.DataFrame(result.records())``."""
        return [dict(p) for p in self.points]

    def to_dict(self) -> dict:
        """What ``sweep --format json`` writes (SI; see the JSON page)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "samples": self.samples,
            "max_order": self.max_order,
            "speed_rpm": self.speed_rpm,
            "overrides": dict(self.overrides),
            "parameter": parameter_dict(self.parameter, self.values, self.values_si),
            "quantities": [q.to_dict() for q in self.quantities],
            "inertia_kgm2": self.inertia_kgm2,
            "load": self.load if self.inertia_kgm2 is not None else None,
            "mount_speeds_rpm": _listed(self.mount_speeds_rpm),
            "points": self.records(),
        }


@dataclass(frozen=True)
class SweepGrid(Tabular):
    """A sweep of two parameters over every pair of their values.

    Attributes
    ----------
    name, config : str
        the engine's name and the configuration's path (or the name given for a dict)
    parameters : tuple of two Parameter
    values, values_si : tuple of two tuples
        each parameter's values as written, and in SI (see :class:`SweepResult`)
    quantities : tuple of Quantity
    points : tuple of dict
        one record per pair, the second parameter's values varying fastest (row-major, as
        :meth:`grid` shapes them): ``value_1``, ``value_1_SI``, ``value_2``, ``value_2_SI``
        and one key per quantity's ``column`` (SI: N, N·m)
    engines : tuple of Engine
        each point's engine, in the order of ``points``
    samples, max_order, inertia_kgm2, load, overrides, mount_speeds_rpm
        as for :class:`SweepResult`
    """

    name: str
    config: str
    parameters: tuple
    values: tuple
    values_si: tuple
    quantities: tuple
    points: tuple
    engines: tuple
    samples: int
    max_order: int
    inertia_kgm2: float | None = None
    load: str = "propeller"
    overrides: tuple = ()
    mount_speeds_rpm: tuple | None = None

    @property
    def shape(self) -> tuple:
        """(number of values of the first parameter, of the second)."""
        return (len(self.values[0]), len(self.values[1]))

    @property
    def speed_rpm(self) -> float | None:
        """The speed of every point, rpm; None when either parameter is the speed."""
        if any(p.key == "speed" for p in self.parameters):
            return None
        return rad_s_to_rpm(self.engines[0].speed_rad_s)

    def grid(self, quantity: str) -> np.ndarray:
        """One quantity at every pair, SI, as an array of :attr:`shape`: ``grid("F2")[i, j]``
        is at the first parameter's i-th value and the second's j-th."""
        column = _column(self.quantities, quantity)
        return np.array([p[column] for p in self.points], dtype=float).reshape(self.shape)

    def records(self) -> list:
        """One flat dict per point (``value_1``, ``value_1_SI``, ``value_2``, ``value_2_SI``,
        the quantities' columns), ready for ``pandas.DataFrame(result.records())``."""
        return [dict(p) for p in self.points]

    def to_dict(self) -> dict:
        """What ``sweep --format json`` writes for two ``--vary`` (SI; see the JSON page)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "samples": self.samples,
            "max_order": self.max_order,
            "speed_rpm": self.speed_rpm,
            "overrides": dict(self.overrides),
            "parameters": [
                parameter_dict(p, v, s)
                for p, v, s in zip(self.parameters, self.values, self.values_si, strict=True)
            ],
            "shape": list(self.shape),
            "quantities": [q.to_dict() for q in self.quantities],
            "inertia_kgm2": self.inertia_kgm2,
            "load": self.load if self.inertia_kgm2 is not None else None,
            "mount_speeds_rpm": _listed(self.mount_speeds_rpm),
            "points": self.records(),
        }
