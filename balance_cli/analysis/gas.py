"""The gas torque: every cylinder's pressure at its own firing angle, acting on its piston.

By virtual work the gas torque is −Σ (p − p_crankcase)·A·ds/dθ, s each piston's travel. The
pressure over the cycle is a curve read from a file (the same for every cylinder, shifted to
its firing angle) or each cylinder's own parametric [gas] cycle, integrated on the
kinematics' fine grid of its own piston's travel.
"""

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ..checks import instance, positive
from ..errors import AnalysisError, SamplingWarning
from ..harmonics import periodic_derivative, resampled
from ..kinematics import FINE_SAMPLES, engine_angles, fine_travel, kinematic_state
from .firing import firing_angles
from .pressure import PressureCurve, cycle_pressure
from .shaking import MAX_SAMPLES

__all__ = [
    "GasLoad",
    "gas_bore",
    "gas_load",
    "gas_torque",
    "piston_gas_torque",
    "check_gas_sampling",
    "GAS_CONVERGENCE",
]

#: the gas torque's mean may move by this fraction (of its mean, or of a hundredth of its
#: peak for a cycle that averages out) when the samples are doubled before a warning: the
#: documentation (Gas pressure, sampling with gas) promises a few 1e-3 at the default sampling
GAS_CONVERGENCE = 1e-3


def gas_bore(engine, pressure, bore_m):
    """The bore the gas torque acts on, m (None: no gas torque): ``bore_m`` (or the [gas]
    table's) for a pressure curve of the engine's cycle, the [gas] table's without one; a bore
    without a pressure is an error, as is a pressure curve without a bore."""
    if pressure is not None:
        instance(pressure, PressureCurve, "pressure", hint=" (balance.read_pressure_csv gives one)")
        if pressure.cycle_deg != engine.cycle_deg:
            raise AnalysisError(
                f"covers {pressure.cycle_deg:g}°, but {engine.name!r} is a "
                f"{engine.cycle}-stroke ({engine.cycle_deg:g}°)",
                "pressure",
            )
        bore_m = bore_m if bore_m is not None else (engine.gas.bore_m if engine.gas else None)
        if bore_m is None:
            raise AnalysisError(
                "is missing for the pressure curve: give the bore, or a [gas] table with one",
                "bore_m",
            )
        return positive(bore_m, "bore_m", "length")
    if bore_m is not None:
        raise AnalysisError(
            "applies to a pressure curve only; give the pressure too (a [gas] "
            "table has its own bore)",
            "bore_m",
        )
    return None if engine.gas is None else engine.gas.bore_m


def _pressure_curves(engine, fire, pressure):
    """Every cylinder's pressure curve: ``pressure``, or its own [gas] cycle on its own
    piston's travel from bottom dead centre to bottom dead centre round its firing."""
    if pressure is not None:
        return {c.number: pressure for c in engine.cylinders}
    return {
        c.number: cycle_pressure(
            engine.gas,
            fine_travel(engine, c.number, fire[c.number] - 180.0),
            engine.cycle_deg,
            engine.config_path,
        )
        for c in engine.cylinders
    }


def _net_pressures(engine, samples, turns, fire, curves):
    """(p − p_crankcase) of every cylinder over the cycle at ``samples`` a revolution, Pa."""
    gas = engine.gas
    crankcase = gas.crankcase_pa if gas is not None else 101325.0
    theta_deg = np.degrees(engine_angles(samples * turns) * turns)
    return {n: curve.at(theta_deg - fire[n]) - crankcase for n, curve in curves.items()}


@dataclass(frozen=True)
class GasLoad:
    """The gas pressure on every piston over the cycle.

    Attributes
    ----------
    net_pressure : dict
        p − p_crankcase over the cycle at the analysis's samples a revolution, Pa, by
        cylinder number
    area_m2 : float
        the piston area it acts on, m²
    curves : dict
        each cylinder's pressure curve from its firing top dead centre, by cylinder number
    firing_deg : dict
        each cylinder's firing angle (engine angle), degrees, by cylinder number
    """

    net_pressure: dict
    area_m2: float
    curves: dict
    firing_deg: dict


def gas_load(engine, samples, pressure=None, bore_m=None) -> "GasLoad | None":
    """The :class:`GasLoad` of ``engine`` at ``samples`` a revolution, or None without a gas
    torque; ``pressure`` and ``bore_m`` as for :func:`gas_bore`."""
    bore = gas_bore(engine, pressure, bore_m)
    if bore is None:
        return None
    fire = firing_angles(engine)
    curves = _pressure_curves(engine, fire, pressure)
    turns = engine.turns_per_cycle
    return GasLoad(
        _net_pressures(engine, samples, turns, fire, curves), math.pi * bore**2 / 4, curves, fire
    )


def piston_gas_torque(net_pressure_pa, area_m2, travel_rate, turns):
    """One piston's gas torque over the cycle, N·m: −(p − p_c)·A·ds/dθ (virtual work), its
    travel rate over a revolution (m/rad) repeated over the cycle's ``turns``."""
    return -net_pressure_pa * area_m2 * np.tile(travel_rate, turns)


def gas_torque(engine, travel_rates, net_pressure, area):
    """The engine's gas torque over the cycle, N·m: the sum of its pistons'
    (:func:`piston_gas_torque`), each cylinder's travel rate by number."""
    turns = engine.turns_per_cycle
    return sum(
        piston_gas_torque(net_pressure[c.number], area, travel_rates[c.number], turns)
        for c in engine.cylinders
    )


def check_gas_sampling(engine, samples, load, gas_curve):
    """Warn (:class:`SamplingWarning`) when doubling the samples moves the mean of the gas
    torque ``gas_curve`` (of ``load`` at ``samples`` a revolution) by more than
    :data:`GAS_CONVERGENCE`: a sharp pressure curve (a compression ratio of 100 burning in 1°)
    aliased by 1.3 % at 256 samples, silently. The travel rates at twice the samples come from
    the fine grid's travel (no new closing of the linkage)."""
    finer = 2 * samples
    turns = engine.turns_per_cycle
    fine = kinematic_state(engine, FINE_SAMPLES).travel
    numbers = list(fine)
    rates = periodic_derivative(resampled(np.array([fine[n] for n in numbers]), finer)).real
    better_curve = gas_torque(
        engine,
        dict(zip(numbers, rates, strict=True)),
        _net_pressures(engine, finer, turns, load.firing_deg, load.curves),
        load.area_m2,
    )
    mean, better = float(np.mean(gas_curve)), float(np.mean(better_curve))
    scale = max(abs(better), 1e-2 * float(np.abs(better_curve).max()))
    moved = abs(mean - better) / scale if scale > 0 else 0.0
    if moved > GAS_CONVERGENCE:
        # an aliasing error falls at least as the square of the samples
        needed = samples * 2 ** math.ceil(math.log2(math.sqrt(moved / GAS_CONVERGENCE)) + 1)
        warning = SamplingWarning(
            f"{engine.name}: the gas torque is not converged at {samples} samples a revolution: "
            f"its mean moves by {moved:.1e} of itself at {finer} (a sharp pressure curve); "
            f"use {min(needed, MAX_SAMPLES)} samples or more",
            samples=samples,
            excess=moved,
        )
        warnings.warn(warning, stacklevel=3)
