"""``balance_cli.mounts``: the engine on its mounts, from its configuration's [mounts] table
(or a :class:`~balance_cli.model.MountSystem` given) and its exact excitation."""

import math

import numpy as np

from ..analysis.shaking import DEFAULT_SAMPLES, check_settings
from ..checks import curve, instance, is_real, positive
from ..errors import AnalysisError
from ..kinematics.linkage import check_assembly
from ..model import Engine, MountSystem
from ..units import rad_s_to_rpm
from .axes import angle_between_deg, elastic_axis, torque_roll_axis
from .excitation import order_wrenches
from .modes import natural_modes
from .response import check_resonances, exciting, forced_response
from .result import Crossing, MountResult
from .statics import torque_reaction, weight

__all__ = [
    "mounts",
    "default_speeds_rpm",
    "DEFAULT_MAX_ORDER",
    "MAX_ORDER",
    "MAX_SPEEDS",
    "SPEED_RANGE",
]

#: orders ½ (a four-stroke's) or 1 to this by default: a V12's firing order is the sixth
DEFAULT_MAX_ORDER = 12
#: the highest order accepted
MAX_ORDER = 64
#: the most speeds of one analysis: the amplitudes of every order at every speed are kept
MAX_SPEEDS = 5000
#: the default speeds, as fractions of the engine's own speed, and how many: a car's
#: powertrain modes (5 to 20 Hz) are crossed by the half and first orders near idle
SPEED_RANGE = (0.1, 1.2)
_SPEED_COUNT = 221
_SPEED_LIMITS_RPM = (1e-3, 1e6)


def default_speeds_rpm(engine) -> np.ndarray:
    """10 % to 120 % of the engine's own speed, 221 speeds (steps of ½ %), rpm."""
    rpm = rad_s_to_rpm(engine.speed_rad_s)
    return np.linspace(SPEED_RANGE[0] * rpm, SPEED_RANGE[1] * rpm, _SPEED_COUNT)


def _speeds(speeds_rpm):
    values = np.array([float(speeds_rpm)]) if is_real(speeds_rpm) else None
    if values is None:
        if isinstance(speeds_rpm, (list, tuple)) and not all(is_real(v) for v in speeds_rpm):
            bad = next(v for v in speeds_rpm if not is_real(v))
            raise AnalysisError(f"must be speeds in rpm, got {bad!r} among them", "speeds_rpm")
        values = curve(speeds_rpm, "speeds_rpm")
    low, high = _SPEED_LIMITS_RPM
    if not 1 <= values.size <= MAX_SPEEDS or values.min() < low or values.max() > high:
        raise AnalysisError(
            f"must be 1 to {MAX_SPEEDS} speeds from {low:g} to {high:g} rpm, got "
            + (
                f"{values.size} from {values.min():g} to {values.max():g}"
                if values.size
                else "none"
            ),
            "speeds_rpm",
        )
    return values


def _orders(engine, orders, max_order):
    """The orders applied, sorted: every multiple of the cycle's step (½ for a four-stroke, 1
    for a two-stroke) up to ``max_order``, or the ``orders`` given (each such a multiple)."""
    step = 2.0 / engine.cycle
    if orders is None:
        if isinstance(max_order, bool) or not is_real(max_order):
            raise AnalysisError(f"must be a whole number, got {max_order!r}", "max_order")
        if max_order != int(max_order) or not 1 <= max_order <= MAX_ORDER:
            raise AnalysisError(
                f"must be a whole number from 1 to {MAX_ORDER}, got {max_order!r}", "max_order"
            )
        return step * np.arange(1, int(round(max_order / step)) + 1)
    values = [orders] if is_real(orders) else orders
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise AnalysisError(f"must be a list of orders, got {orders!r}", "orders")
    out = set()
    for k in values:
        if (
            not is_real(k)
            or not 0 < k <= MAX_ORDER
            or not math.isclose(k / step, round(k / step), abs_tol=1e-9)
        ):
            what = "multiples of ½" if engine.cycle == 4 else "whole numbers"
            raise AnalysisError(
                f"has {k!r}: the orders of a {engine.cycle}-stroke are {what}, up to {MAX_ORDER}",
                "orders",
            )
        out.add(step * round(k / step))
    if not out:
        raise AnalysisError("must list one order or more", "orders")
    return np.array(sorted(out))


def _mean_torque(engine, power_w, mean_gas_nm):
    """(torque N·m, where it comes from) for the static deflection, or (None, reason)."""
    rpm = rad_s_to_rpm(engine.speed_rad_s)
    if power_w is not None:
        return power_w / engine.speed_rad_s, f"the power given, {power_w / 1e3:g} kW at {rpm:g} rpm"
    if mean_gas_nm is not None:
        return mean_gas_nm, f"the [gas] cycle's mean torque at {rpm:g} rpm"
    if engine.power_at_speed_w is not None:
        return (
            engine.power_at_speed_w / engine.speed_rad_s,
            f"the configuration's power, {engine.power_at_speed_w / 1e3:g} kW at {rpm:g} rpm",
        )
    return None, "no [gas] table and no power given"


def _crossings(modes, orders, speeds_rpm, exc):
    low, high = float(speeds_rpm.min()), float(speeds_rpm.max())
    out = []
    for mode in modes:
        for k in orders:
            rpm = rad_s_to_rpm(mode.omega_rad_s / k)
            if not low <= rpm <= high:
                continue
            wrench = exc.at(np.array([mode.omega_rad_s / k]))[0, list(orders).index(k)]
            driven = bool(exciting(modes, wrench)[mode.number - 1])
            out.append(Crossing(mode.number, mode.motion, float(k), float(rpm), driven))
    return tuple(sorted(out, key=lambda c: (c.speed_rpm, c.mode)))


def mounts(
    engine,
    speeds_rpm=None,
    orders=None,
    max_order=DEFAULT_MAX_ORDER,
    power_w=None,
    samples=DEFAULT_SAMPLES,
    system=None,
) -> MountResult:
    """The engine on its mounts: the six rigid-body modes with their kinetic-energy
    distribution, the torque roll axis and the elastic axis, the static deflections under the
    weight and the mean torque's reaction, and the forced response to every order of the
    shaking forces and moments and of the frame torque over ``speeds_rpm``.

    Parameters
    ----------
    engine : Engine
    speeds_rpm : array_like, optional
        engine speeds of the forced response, rpm (default :func:`default_speeds_rpm`)
    orders : list of float, optional
        the orders applied (multiples of ½ for a four-stroke); default every one up to
        ``max_order``
    max_order : int
        the highest order applied when ``orders`` is not given
    power_w : float, optional
        the power whose mean torque (power / speed, at the engine's own speed) the static
        deflection is under, W; default the [gas] cycle's mean torque, else the
        configuration's ``power``
    samples : int
        crank angles a revolution for the Fourier analysis
    system : MountSystem, optional
        the mounts to analyse instead of the engine's own [mounts] (a design's variant:
        :meth:`MountSystem.replace_mount`)

    Returns
    -------
    MountResult

    Raises
    ------
    AnalysisError
        no mount system, a rotary engine, orders, speeds or settings out of range, a speed
        that puts a driven order exactly on an undamped mode
    """
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    if system is None:
        system = engine.mounts
        if system is None:
            raise AnalysisError(
                "has no [mounts] table: give the powertrain's mass, centre of gravity, "
                "inertia and mounts (see the how-to page 'The engine on its mounts')",
                "engine",
            )
    instance(system, MountSystem, "system", hint=" (Engine.mounts is one)")
    if engine.is_rotary:
        raise AnalysisError(
            "is a rotary engine: its crank is fixed to the airframe and its crankcase turns, "
            "so it has no frame on mounts to analyse",
            "engine",
        )
    if power_w is not None:
        power_w = positive(power_w, "power_w", "power")
    chosen = _orders(engine, orders, max_order)
    speeds = default_speeds_rpm(engine) if speeds_rpm is None else _speeds(speeds_rpm)
    check_settings(samples, max(1, math.ceil(chosen.max())))
    check_assembly(engine)
    modes = natural_modes(system)
    exc = order_wrenches(engine, system, chosen, samples)
    omega = speeds * (2.0 * math.pi / 60.0)
    wrenches = exc.at(omega)
    check_resonances(system, modes, chosen, omega, wrenches)
    response = forced_response(system, chosen, omega, wrenches, engine.turns_per_cycle)
    torque_nm, source = _mean_torque(engine, power_w, exc.mean_gas_nm)
    tra, elastic = torque_roll_axis(system), elastic_axis(system)
    return MountResult(
        engine,
        system,
        modes,
        tra,
        elastic,
        angle_between_deg(tra, elastic),
        weight(system),
        None if torque_nm is None else torque_reaction(system, torque_nm, source),
        chosen,
        speeds,
        response,
        _crossings(modes, chosen, speeds, exc),
        exc.mean_gas_nm is not None,
    )
