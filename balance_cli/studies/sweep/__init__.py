"""Parameter sweeps: one configuration analysed again and again with one of its values changed.

The parameter is a key of the configuration as written in the file (``rod_length``,
``banks[2].angle``, ``gas.imep``). Each point sets that key in the parsed TOML and builds the
engine with :func:`balance_cli.config.build`, so every value is read and checked exactly as in
a file, and a value that makes no engine is reported with the file, the key and the value.
The pseudo-parameter ``balance_factor`` instead balances the unchanged engine with classic
per-throw counterweights of that factor and reports what they leave.

What is reported comes from the same records as ``compare``, ``counterweight`` and
``torque``: the quantities are read out of each point's ``to_dict()``-style records, so a
sweep agrees with those commands to the last digit.

``keys`` says what can be varied and how its values are written, ``quantities`` what can be
reported; the sweep itself and its result are here.
"""

import copy
import dataclasses
import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ...analysis.counterweight import check_options, counterweights
from ...analysis.results import analyse
from ...analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings
from ...config import Configuration, build, parse_text, read_text, resolve
from ...errors import BalanceError, ConfigError, FiringError, NotInResultError, SweepError
from ...output import DOCUMENT_VERSION
from ...units import parse_quantity, rad_s_to_rpm
from .keys import (
    ANGLE,
    BALANCE_FACTOR,
    FRACTION,
    MAX_POINTS,
    SCHEMA,
    Parameter,
    parameter_of,
)
from .quantities import DEFAULT_QUANTITIES, QUANTITY_NAMES, Quantity, quantities_of
from .values import normalised, span

__all__ = [
    "SweepResult",
    "Parameter",
    "Quantity",
    "sweep",
    "span",
    "parameter_of",
    "quantities_of",
    "QUANTITY_NAMES",
    "DEFAULT_QUANTITIES",
    "BALANCE_FACTOR",
    "SCHEMA",
    "MAX_POINTS",
]


def _shown(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


@dataclass(frozen=True)
class SweepResult:
    """A sweep: one parameter's values and what each gives.

    Attributes
    ----------
    name, config : str
        the engine's name and the configuration's path (or the name given for a dict)
    parameter : Parameter
    values : tuple
        as written in the file ("140 mm", 60.0)
    values_si : tuple of float
        the same in SI (m, kg, rad/s, kg·m², Pa; radians for angles), see ``parameter.unit_si``
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

    @property
    def speed_rpm(self) -> float | None:
        """The speed of every point, rpm; None when the speed is what varies."""
        if self.parameter.key == "speed":
            return None
        return rad_s_to_rpm(self.engines[0].speed_rad_s)

    def series(self, quantity: str) -> np.ndarray:
        """One quantity at every point, SI, by name (``"F2"``) or column (``"F2_N"``)."""
        for q in self.quantities:
            if quantity in (q.name, q.column):
                return np.array([p[q.column] for p in self.points], dtype=float)
        raise NotInResultError(
            f"{quantity!r} is not among this sweep's quantities "
            f"({', '.join(q.name for q in self.quantities)})",
            "quantity",
        )

    def records(self) -> list:
        """One flat dict per point (``value``, ``value_SI``, the quantities' columns), ready
        for ``pandas.DataFrame(result.records())``."""
        return [dict(p) for p in self.points]

    def to_dict(self) -> dict:
        """What ``sweep --format json`` writes (SI; see the README)."""
        p = self.parameter
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "samples": self.samples,
            "max_order": self.max_order,
            "speed_rpm": self.speed_rpm,
            "overrides": dict(self.overrides),
            "parameter": {
                "key": p.key,
                "kind": p.kind,
                "unit_SI": p.unit_si,
                "file_value": p.file_value,
                "values": list(self.values),
                "values_SI": list(self.values_si),
            },
            "quantities": [q.to_dict() for q in self.quantities],
            "inertia_kgm2": self.inertia_kgm2,
            "load": self.load if self.inertia_kgm2 is not None else None,
            "points": self.records(),
        }


def _with_value(data, parameter, value):
    changed = copy.deepcopy(data)
    place = changed
    for step in parameter.path[:-1]:
        place = place[step]
    place[parameter.path[-1]] = value
    return changed


def _si(parameter, value):
    if parameter.takes_units:
        return parse_quantity(value, parameter.kind)
    if parameter.kind == ANGLE:
        return math.radians(value)
    return float(value)


def _point_error(exc, parameter, value, path):
    """A failure at one point as one line: the file, the key, the value."""
    shown = repr(value) if isinstance(value, str) else _shown(value)
    at = f"{parameter.key} = {shown}"
    if isinstance(exc, ConfigError):
        # the model's sentences about a field start "of 0.01 m is ...": give them their subject
        if exc.problem.startswith("of "):
            problem = f"{exc.key} {exc.problem}"
        elif exc.key and exc.key != parameter.key:
            problem = f"{exc.key}: {exc.problem}"
        else:
            problem = exc.problem
        text = f"{exc.path}: {at}: {problem}"
    elif isinstance(exc, FiringError):
        text = f"{path}: {at}: firing_order: {exc}"
    elif isinstance(exc, BalanceError) and exc.parameter == parameter.key:
        text = f"{path}: {at}: {exc.problem}"
    else:
        text = f"{path}: {at}: {exc}"
    return SweepError(text, key=parameter.key, value=value, cause=exc)


def _load(configuration):
    """The parsed data and path of a Configuration or a file."""
    if isinstance(configuration, Configuration):
        return copy.deepcopy(configuration.data), configuration.path
    if isinstance(configuration, (str, os.PathLike)):
        path = os.fspath(resolve(configuration))
        return parse_text(read_text(Path(path)), path), path
    raise SweepError(
        f"must be a Configuration (balance.read_configuration(path), or "
        f"balance.Configuration(data, path) of parsed TOML) or a file's path, got "
        f"{type(configuration).__name__}",
        "configuration",
    )


def sweep(
    configuration,
    parameter: str,
    values: Sequence,
    quantities=None,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    *,
    inertia_kgm2: float | None = None,
    load: str = "propeller",
    overrides: "dict | None" = None,
    progress: "Callable[[int, int], None] | None" = None,
) -> SweepResult:
    """Analyse ``configuration`` once per value of ``parameter``.

    Parameters
    ----------
    configuration : Configuration, str or PathLike
        a configuration (:func:`~balance_cli.read_configuration`, or
        ``balance.Configuration(data, path)`` of TOML parsed in code), or its file
    parameter : str
        a configuration key as written in the file: ``speed``, ``rod_length``,
        ``masses.rotating``, ``banks[2].angle``, ``throws[3].phase``, ``gas.imep``,
        ``cylinders[4].reciprocating``, ... (any number of the configuration; see
        :data:`SCHEMA`), or ``balance_factor`` (classic per-throw counterweights of that
        factor, 0 to 1, and what they leave)
    values : sequence
        as written in the file: text with a unit for a quantity ("140 mm", "3000 rpm"),
        numbers for angles (degrees), ratios and whole numbers (text holding a number is
        read as that number); :func:`span` makes evenly spaced ones
    quantities : str or sequence of str, optional
        what to report at each point (see :func:`quantities_of`); default the largest free
        force and moment after an ideal counterweight
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    inertia_kgm2 : float, optional
        flywheel inertia for the ``steadiness`` quantity, kg·m²
    load : str
        "propeller" or "constant", for the steadiness
    overrides : dict, optional
        other keys to set at every point, as written in the file (``{"speed": "3000 rpm"}``:
        the command line's ``--speed``); checked like the file's own values
    progress : callable, optional
        ``progress(done, total)`` after each point

    Raises
    ------
    ConfigError
        the configuration itself cannot be read or built
    SweepError
        an unknown parameter (``parameter``), unusable values (``values``) or quantities
        (``quantities``), a steadiness without ``inertia_kgm2``, or a point whose configuration
        is invalid (the message names the file, the key and the value; ``key`` and ``value``
        say which)
    AnalysisError
        ``samples`` or ``max_order`` out of range
    """
    check_settings(samples, max_order)
    data, path = _load(configuration)
    build(data, path)  # the file as it is first: its own errors are the file's, not the sweep's
    param = parameter_of(data, parameter, path)
    for key, value in (overrides or {}).items():
        try:
            fixed = parameter_of(data, key, path)
        except SweepError as exc:
            raise SweepError(exc.problem, "overrides") from None
        if fixed.key == param.key or fixed.kind == FRACTION:
            raise SweepError(
                f"sets {key!r}, which the sweep varies or which is no key of the "
                "file; leave it out",
                "overrides",
            )
        data = _with_value(data, fixed, normalised(fixed, [value])[0])
    try:
        base = build(data, path)
    except ConfigError as exc:
        if exc.key not in (overrides or {}):
            raise
        raise SweepError(
            f"{exc.key} = {(overrides or {})[exc.key]!r}: {exc.problem}", "overrides"
        ) from None
    wanted = quantities_of(quantities, max_order)
    if param.kind == FRACTION:
        # what the counterweights of each factor leave, not what an ideal one would
        wanted = tuple(
            dataclasses.replace(
                q,
                meaning=q.meaning.split(", after")[0] + ", after "
                "the counterweights of that balance factor",
            )
            if q.name.startswith("largest_")
            else q
            for q in wanted
        )
    values = normalised(param, values)
    torque_wanted = any(q.kind in ("torque", "steadiness") for q in wanted)
    steady = any(q.kind == "steadiness" for q in wanted)
    if steady and inertia_kgm2 is None:
        raise SweepError(
            "is needed for the quantity steadiness: give the flywheel inertia, kg·m²",
            "inertia_kgm2",
        )
    if inertia_kgm2 is not None:
        if (
            isinstance(inertia_kgm2, bool)
            or not isinstance(inertia_kgm2, (int, float))
            or not math.isfinite(inertia_kgm2)
            or inertia_kgm2 <= 0
        ):
            raise SweepError(
                f"must be a positive number of kg·m², got {inertia_kgm2!r}", "inertia_kgm2"
            )
        if not steady:
            raise SweepError(
                "applies to the quantity steadiness only; ask for it or leave the inertia out",
                "inertia_kgm2",
            )
    if steady and base.gas is None:
        raise SweepError(
            f"needs a gas torque to drive the engine, but {path} has no [gas] table", "quantities"
        )

    if param.key == "power" and not any(q.kind == "pru" for q in wanted):
        raise SweepError(
            "power changes only the power related unbalance: ask for PRU<k>V or "
            "PRU<k>H (PRU2V), or vary another key",
            "parameter",
        )

    # every point is built before any is analysed: a bad value is reported at once
    engines, values_si = [], []
    for value in values:
        try:
            if param.kind == FRACTION:
                check_options(balance_factor=value)
                engine = base
            else:
                engine = build(_with_value(data, param, value), path)
                if (
                    engine.power_w is not None
                    and engine.speed_rad_s != base.speed_rad_s
                    and param.key != "power"
                ):
                    # the file's power is given at the file's speed, not at the point's
                    engine = engine.replace(power_speed_rad_s=base.speed_rad_s)
            values_si.append(_si(param, value) + 0.0)
        except BalanceError as exc:
            raise _point_error(exc, param, value, path) from None
        engines.append(engine)

    if param.kind != FRACTION and len(set(values_si)) > 1 and all(e == engines[0] for e in engines):
        raise SweepError(
            f"{param.key!r} changes nothing in the engine {path} describes: another key sets "
            "what it would (a cylinder's own value overrides [links] and [masses], [parts] "
            "derive the lumped masses); vary that key instead",
            "parameter",
        )

    torque_of: Any = None
    if torque_wanted:
        from ...analysis.torque import (
            torque as torque_of,  # the torques load scipy for the steadiness
        )

    points = []
    for i, (engine, value, value_si) in enumerate(zip(engines, values, values_si, strict=True)):
        try:
            result = analyse(engine, samples, max_order)
            record = _measure(
                result, wanted, param, value, samples, max_order, torque_of, inertia_kgm2, load
            )
        except BalanceError as exc:
            raise _point_error(exc, param, value, path) from None
        points.append({"value": value, "value_SI": value_si, **record})
        if progress is not None:
            progress(i + 1, len(values))
    return SweepResult(
        base.name,
        path,
        param,
        tuple(values),
        tuple(values_si),
        wanted,
        tuple(points),
        tuple(engines),
        samples,
        max_order,
        inertia_kgm2,
        load,
        tuple((overrides or {}).items()),
    )


def _measure(result, wanted, param, value, samples, max_order, torque_of, inertia, load):
    """Every quantity of one point, read from the records ``compare`` writes."""
    engine = result.engine
    if param.kind == FRACTION:
        shaking = counterweights(result, balance_factor=value).residual
        largest_force = _above(shaking.largest_force(), engine.noise_floor_n)
        largest_moment = _above(shaking.largest_moment(), engine.noise_floor_nm)
    else:
        shaking = result.shaking
        largest_force, largest_moment = (
            result.counterweighted_force_n,
            result.counterweighted_moment_nm,
        )
    orders = shaking.records(engine)
    torques = None
    if torque_of is not None:
        steady = any(q.kind == "steadiness" for q in wanted)
        torques = torque_of(
            engine,
            samples,
            max_order,
            inertia_kgm2=inertia if steady else None,
            load=load,
            bearings=False,
            guide=False,
        )
    record = {}
    for q in wanted:
        if q.kind == "pru":
            pru = result.power_related_unbalance(orders=(q.order,))
            if not pru.available:
                raise SweepError(f"{q.name} at this point: {pru.note}", "quantities")
            record[q.column] = pru.orders[0][f"{q.part}_Nm_per_kW"]
        elif q.order is not None:
            record[q.column] = orders[q.order - 1][q.kind][f"{q.part}_{q.unit}"]
        elif q.name == "largest_force":
            record[q.column] = largest_force
        elif q.name == "largest_moment":
            record[q.column] = largest_moment
        else:
            # the steadiness or a torque: sweep gives torque_of when one is wanted
            assert torques is not None
            if q.name == "steadiness":
                record[q.column] = torques.steadiness.factor
            else:
                total = torques.total
                record[q.column] = {
                    "torque_mean": total.mean,
                    "torque_max": total.max,
                    "torque_min": total.min,
                    "torque_range": total.range,
                }[q.name]
    return record


def _above(value, floor):
    return value if value >= floor else 0.0
