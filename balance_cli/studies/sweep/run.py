"""The sweep itself: the parameters and overrides checked, every point's engine built (all of
them before any is analysed, so that a bad value is reported at once), then each point
analysed and its quantities read; progress reported from the start."""

import copy
import dataclasses
import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from ...analysis.counterweight import check_options
from ...analysis.marine import engine_power
from ...analysis.results import analyse
from ...analysis.shaking import check_settings
from ...analysis.steadiness import LOADS
from ...config import Configuration, build, parse_text, read_text, resolve
from ...errors import BalanceError, ConfigError, FiringError, SweepError
from ...units import parse_quantity, rad_s_to_rpm
from .keys import ANGLE, FRACTION, MAX_POINTS, parameter_of
from .mountquantities import MOUNT_KINDS, check_mount_quantities, measure_mounts
from .quantities import quantities_of
from .readout import measure
from .values import normalised

__all__ = ["run_sweep"]


def _shown(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _set(data, parameter, value, path):
    """Set one parameter's value in the parsed TOML ``data``, in place."""
    if parameter.derived is not None:
        parameter.derived.apply(data, value, path)
        return
    place = data
    for step in parameter.path[:-1]:
        place = place[step]
    place[parameter.path[-1]] = value


def _with(data, assignments, path):
    """A copy of ``data`` with every (parameter, value) set: the file's keys first, then the
    derived parameters, each after the keys it reads (a rod ratio of the point's crank
    radius)."""
    changed = copy.deepcopy(data)
    for parameter, value in sorted(assignments, key=lambda a: a[0].rank):
        if parameter.kind != FRACTION:
            _set(changed, parameter, value, path)
    return changed


def _si(parameter, value):
    if parameter.takes_units:
        return parse_quantity(value, parameter.kind)
    if parameter.kind == ANGLE:
        return math.radians(value)
    return float(value)


def _point_error(exc, assignments, path):
    """A failure at one point as one line: the file, the keys and the values."""
    at = ", ".join(
        f"{p.key} = {repr(v) if isinstance(v, str) else _shown(v)}" for p, v in assignments
    )
    keys = [p.key for p, _ in assignments]
    if isinstance(exc, ConfigError):
        # the model's sentences about a field start "of 0.01 m is ...": give them their subject
        if exc.problem.startswith("of "):
            problem = f"{exc.key} {exc.problem}"
        elif exc.key and exc.key not in keys:
            problem = f"{exc.key}: {exc.problem}"
        else:
            problem = exc.problem
        text = f"{exc.path}: {at}: {problem}"
    elif isinstance(exc, FiringError):
        text = f"{path}: {at}: firing_order: {exc}"
    elif isinstance(exc, SweepError) or isinstance(exc, BalanceError) and exc.parameter in keys:
        # the sweep's own sentences about a point, and a parameter's about its value
        text = f"{path}: {at}: {exc.problem}"
    else:
        text = f"{path}: {at}: {exc}"
    if len(assignments) == 1:
        key, value = assignments[0][0].key, assignments[0][1]
    else:
        key, value = tuple(keys), tuple(v for _, v in assignments)
    return SweepError(text, key=key, value=value, cause=exc)


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


def _check_arguments(inertia_kgm2, load, overrides, progress):
    """The keyword arguments every sweep takes, checked before any work."""
    if not isinstance(load, str) or load not in LOADS:
        raise SweepError(f"must be one of {', '.join(LOADS)}, got {load!r}", "load")
    if overrides is not None and not isinstance(overrides, Mapping):
        raise SweepError(
            "must be a dict of configuration keys and their values as written in the file, "
            f"such as {{'speed': '3000 rpm'}}, got {overrides!r}",
            "overrides",
        )
    if progress is not None and not callable(progress):
        raise SweepError(
            f"must be a function progress(done, total) or None, got {progress!r}", "progress"
        )
    if inertia_kgm2 is not None and (
        isinstance(inertia_kgm2, bool)
        or not isinstance(inertia_kgm2, (int, float))
        or not math.isfinite(inertia_kgm2)
        or inertia_kgm2 <= 0
    ):
        raise SweepError(
            f"must be a positive number of kg·m², got {inertia_kgm2!r}", "inertia_kgm2"
        )


def _fixed(data, path, overrides, varied):
    """The overrides as (Parameter, value) pairs, each a key (or derived parameter) the file
    may take, none set by the varied parameters or by another override."""
    fixed: list = []
    for key, value in (overrides or {}).items():
        try:
            parameter = parameter_of(data, key, path)
            if parameter.kind == FRACTION:
                raise SweepError(f"{key!r} is no key of the file; vary it instead", "parameter")
            value = normalised(parameter, [value])[0]
        except SweepError as exc:
            raise SweepError(f"sets {key!r}: {exc.problem}", "overrides") from None
        for other in varied:
            clash = parameter.conflicts(other)
            if clash is not None:
                what = "varies it" if other.key == parameter.key else f"varies {other.key}"
                raise SweepError(
                    f"sets {key!r}, which changes {clash}, and the sweep {what}; leave it out",
                    "overrides",
                )
        for other, _ in fixed:
            clash = parameter.conflicts(other)
            if clash is not None:
                raise SweepError(
                    f"sets {key!r} and {other.key!r}, which both change {clash}; give one",
                    "overrides",
                )
        fixed.append((parameter, value))
    return fixed


def _quantities(quantities, max_order, params):
    wanted = quantities_of(quantities, max_order)
    if any(p.kind == FRACTION for p in params):
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
    return wanted


def _without_power(engine, wanted):
    """Why a point's PRU has no power (the power given at another speed, or none), or None.
    An engine with a [gas] table is left to the analysis, which may take the indicated
    power."""
    asked = [q.name for q in wanted if q.kind == "pru"]
    if not asked or engine.gas is not None or engine.power_at_speed_w is not None:
        return None
    if engine.power_w is not None:
        return (
            f"{', '.join(asked)} needs the power at the point's speed, "
            f"{rad_s_to_rpm(engine.speed_rad_s):g} rpm, but the power is given at "
            f"{rad_s_to_rpm(engine.power_speed_rad_s):g} rpm; a sweep does not carry a power "
            "to other speeds: leave PRU out, or give a [gas] table with an imep"
        )
    return f"{', '.join(asked)}: {engine_power(engine)[1]}"


def run_sweep(
    configuration,
    names,
    value_lists,
    quantities,
    samples,
    max_order,
    inertia_kgm2,
    load,
    overrides,
    progress,
    grid,
    mount_speeds_rpm=None,
):
    """The work of :func:`~balance_cli.studies.sweep.sweep` (one name) and
    :func:`~balance_cli.studies.sweep.sweep_grid` (two): a dict of what their results hold."""
    check_settings(samples, max_order)
    _check_arguments(inertia_kgm2, load, overrides, progress)
    data, path = _load(configuration)
    file_engine = build(data, path)  # the file as it is first: its errors are the file's
    name_of = "parameters" if grid else "parameter"
    params = []
    for name in names:
        try:
            params.append(parameter_of(data, name, path))
        except SweepError as exc:
            raise SweepError(exc.problem, name_of) from None
    if grid:
        a, b = params
        if a.key == b.key:
            raise SweepError(f"names {a.key!r} twice; vary two different keys", "parameters")
        clash = a.conflicts(b)
        if clash is not None:
            raise SweepError(
                f"{a.key!r} and {b.key!r} both change {clash}; vary one of them", "parameters"
            )
    fixed = _fixed(data, path, overrides, params)
    try:
        base = build(_with(data, fixed, path), path) if fixed else file_engine
    except BalanceError as exc:
        shown = ", ".join(f"{p.key} = {v!r}" for p, v in fixed)
        problem = exc.problem if isinstance(exc, ConfigError) else str(exc)
        where = f"{exc.key}: " if isinstance(exc, ConfigError) and exc.key else ""
        raise SweepError(f"sets {shown}: {where}{problem}", "overrides") from None

    wanted = _quantities(quantities, max_order, params)
    check_mount_quantities(base, wanted, path)
    mount_speeds = _mount_speeds(mount_speeds_rpm, wanted)
    mount_key = next((p.key for p in params if p.key.startswith("mounts.")), None)
    if mount_key is not None and not any(q.kind in MOUNT_KINDS for q in wanted):
        raise SweepError(
            f"{mount_key!r} changes only the engine on its mounts: ask for its quantities, "
            "mode_1 to mode_6, roll_mode (or fore_aft, lateral, bounce, pitch, yaw), "
            "tra_purity, axes_angle, mount_<m>_force, mount_<m>_Fz",
            name_of,
        )
    values = []
    for param, listed in zip(params, value_lists, strict=True):
        checked = normalised(param, listed)
        if grid and len(checked) < 2:
            raise SweepError(
                f"holds one value of {param.key}: a grid needs two or more of each "
                "parameter (to fix a key at one value, give it in overrides)",
                "values",
            )
        values.append(checked)
    count = math.prod(len(v) for v in values)
    if count > MAX_POINTS:
        raise SweepError(
            f"make {' × '.join(str(len(v)) for v in values)} = {count} points; a sweep takes "
            f"at most {MAX_POINTS}",
            "values",
        )

    torque_wanted = any(q.kind in ("torque", "steadiness") for q in wanted)
    steady = any(q.kind == "steadiness" for q in wanted)
    if steady and inertia_kgm2 is None:
        raise SweepError(
            "is needed for the quantity steadiness: give the flywheel inertia, kg·m²",
            "inertia_kgm2",
        )
    if inertia_kgm2 is not None and not steady:
        raise SweepError(
            "applies to the quantity steadiness only; ask for it or leave the inertia out",
            "inertia_kgm2",
        )
    if steady and base.gas is None:
        raise SweepError(
            f"needs a gas torque to drive the engine, but {path} has no [gas] table", "quantities"
        )
    pru_wanted = any(q.kind == "pru" for q in wanted)
    if any(p.key == "power" for p in params) and not pru_wanted:
        raise SweepError(
            "power changes only the power related unbalance: ask for PRU<k>V or "
            "PRU<k>H (PRU2V), or vary another key",
            name_of,
        )

    # the power is given at the speed of the configuration it is written in: the file's
    # (or the overrides', when they set it), whatever speed a point runs at; a varied power
    # is given at each point's own speed
    power_varied = any(p.key == "power" for p in params)
    power_speed = (
        base.speed_rad_s if any(p.key == "power" for p, _ in fixed) else file_engine.speed_rad_s
    )

    def with_power(engine):
        if power_varied or engine.power_w is None or engine.power_speed_rad_s == power_speed:
            return engine
        return engine.replace(power_speed_rad_s=power_speed)

    base = with_power(base)
    speed_fixed = next((v for p, v in fixed if p.key == "speed"), None)
    if (
        pru_wanted
        and speed_fixed is not None
        and not power_varied
        and base.gas is None
        and base.power_w is not None
        and base.power_at_speed_w is None
    ):
        raise SweepError(
            f"sets speed = {speed_fixed!r}, but the file's power "
            f"({base.power_w / 1e3:g} kW) is given at {rad_s_to_rpm(power_speed):g} rpm, and "
            f"the PRU needs the power at {speed_fixed}: set the power at that speed too, or "
            "leave PRU out",
            "overrides",
        )

    # the engines that differ: one per value of each parameter that is a key (the balance
    # factor changes no key and reuses its point's engine)
    keyed = [i for i, p in enumerate(params) if p.kind != FRACTION]
    shape = tuple(len(v) for v in values)
    engine_keys = sorted({tuple(ix[i] for i in keyed) for ix in np.ndindex(*shape)})
    total = len(engine_keys) * bool(keyed) + count
    done = 0
    if progress is not None:
        progress(0, total)  # at once: a long sweep shows its bar before the first point

    # every point is built before any is analysed: a bad value is reported at once
    values_si = []
    for param, listed in zip(params, values, strict=True):
        axis = []
        for value in listed:
            try:
                if param.kind == FRACTION:
                    check_options(balance_factor=value)
                axis.append(_si(param, value) + 0.0)
            except BalanceError as exc:
                raise _point_error(exc, [(param, value)], path) from None
        values_si.append(axis)
    engines_by_key = {}
    for key in engine_keys:
        assignments = [(params[i], values[i][k]) for i, k in zip(keyed, key, strict=True)]
        if not keyed:
            engines_by_key[key] = base
            continue
        try:
            engine = with_power(build(_with(data, fixed + assignments, path), path))
        except BalanceError as exc:
            raise _point_error(exc, assignments, path) from None
        why = _without_power(engine, wanted)
        if why is not None:
            raise _point_error(SweepError(why, "quantities"), assignments, path)
        engines_by_key[key] = engine
        done += 1
        if progress is not None:
            progress(done, total)
    if not keyed and _without_power(base, wanted) is not None:
        raise SweepError(_without_power(base, wanted), "quantities")

    for i in keyed:
        # the engines along this parameter, the other held at its first value
        along = [engines_by_key[tuple(k if j == i else 0 for j in keyed)] for k in range(shape[i])]
        if len(set(values_si[i])) > 1 and all(e == along[0] for e in along):
            raise SweepError(
                f"{params[i].key!r} changes nothing in the engine {path} describes: another key "
                "sets what it would (a cylinder's own value overrides [links] and [masses], "
                "[parts] derive the lumped masses); vary that key instead",
                name_of,
            )

    torque_of: Any = None
    if torque_wanted:
        from ...analysis.torque import (
            torque as torque_of,  # the torques load scipy for the steadiness
        )

    factor_axis = next((i for i, p in enumerate(params) if p.kind == FRACTION), None)
    # the quantities of the shaking analysis; the others are the mount analysis's
    shaking = [q for q in wanted if q.kind not in MOUNT_KINDS]
    points, engines = [], []
    for index in np.ndindex(*shape):
        assignments = [(params[i], values[i][k]) for i, k in enumerate(index)]
        engine = engines_by_key[tuple(index[i] for i in keyed)]
        factor = None if factor_axis is None else values[factor_axis][index[factor_axis]]
        try:
            record = {}
            if shaking:
                result = analyse(engine, samples, max_order)
                record = measure(
                    result, shaking, factor, samples, max_order, torque_of, inertia_kgm2, load
                )
            if len(shaking) < len(wanted):
                record.update(measure_mounts(engine, wanted, samples, max_order, mount_speeds))
            record = {q.column: record[q.column] for q in wanted}
        except BalanceError as exc:
            raise _point_error(exc, assignments, path) from None
        if grid:
            head = {}
            for n, (i, k) in enumerate(enumerate(index), 1):
                head[f"value_{n}"] = values[i][k]
                head[f"value_{n}_SI"] = values_si[i][k]
        else:
            head = {"value": values[0][index[0]], "value_SI": values_si[0][index[0]]}
        points.append({**head, **record})
        engines.append(engine)
        done += 1
        if progress is not None:
            progress(done, total)
    return dict(
        name=base.name,
        config=path,
        values=tuple(tuple(v) for v in values),
        values_si=tuple(tuple(v) for v in values_si),
        params=tuple(params),
        quantities=wanted,
        points=tuple(points),
        engines=tuple(engines),
        extras=dict(
            samples=samples,
            max_order=max_order,
            inertia_kgm2=inertia_kgm2,
            load=load,
            overrides=tuple((overrides or {}).items()),
            mount_speeds_rpm=None if mount_speeds is None else tuple(mount_speeds),
        ),
    )


def _mount_speeds(speeds_rpm, wanted):
    """The speeds over which a mount's force takes its largest (a list of floats, rpm), or
    None: each point's own speed."""
    if speeds_rpm is None:
        return None
    if not any(q.kind == "mount force" for q in wanted):
        raise SweepError(
            "applies to the mounts' forces only (mount_<m>_force, mount_<m>_Fz); ask for one "
            "or leave the speeds out",
            "mount_speeds_rpm",
        )
    from ...mounting import MAX_SPEEDS

    try:
        values = np.asarray(speeds_rpm, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        values = np.array([math.nan])
    if not 1 <= values.size <= MAX_SPEEDS or not np.all(np.isfinite(values)) or values.min() <= 0:
        raise SweepError(
            f"must be 1 to {MAX_SPEEDS} speeds greater than zero, rpm, got {speeds_rpm!r}",
            "mount_speeds_rpm",
        )
    return [float(v) for v in values]
