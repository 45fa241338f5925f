"""Torques on the crankshaft and the engine frame at constant speed.

Everything comes from the kinetic energy of the exact motion, T = ½·μ(θ)·θ̇²
(:mod:`.inertia`). At constant speed ω, Lagrange's equation gives:

- the **inertia torque** on the crankshaft (a rotary's crankcase), positive with rotation:
  −(d/dt ∂T/∂θ̇ − ∂T/∂θ) = −½·ω²·dμ/dθ; for one reciprocating mass on a massless rod this is
  m·r²·ω²·(λ/4·sin θ − ½·sin 2θ − 3λ/4·sin 3θ − …);
- the **tilting couple** (Fraeys de Veubeke's V_k), the moving parts' −dH/dt about the crank
  axis, H = θ̇·h(θ) their angular momentum;
- the **gas torque**, −Σ (p − p_crankcase)·A·ds/dθ with s each piston's travel (virtual work,
  :mod:`.gas`);
- the **frame reaction**, the couple on the engine frame: −(gas + inertia) + tilting
  (Fraeys's (23) without reduction gear; for inertia alone, Tanaka's ΣC_I + C_L).

Derivatives with respect to θ are taken spectrally (multiplying Fourier coefficients by ik),
exact for the band-limited motion; a four-stroke's torques repeat every 720°, so their orders
are multiples of ½. Every piece reads the engine's one kinematic state.
"""

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import instance, is_real, items, positive
from ..errors import AnalysisError
from ..harmonics import periodic_derivative
from ..kinematics import kinematic_state, pin_angle
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular
from ..units import rad_s_to_rpm
from .gas import check_gas_sampling, gas_load, gas_torque, piston_gas_torque
from .guideforce import guide_forces
from .inertia import reduced_mass_and_momentum
from .pins import PinForce, pin_forces
from .pressure import PressureCurve
from .series import ReducedMass, Series, cycle_series
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings
from .steadiness import LOADS, Steadiness, flywheel_for, steadiness

__all__ = ["CrankshaftTorque", "TorqueResult", "TorqueSet", "torque"]


@dataclass(frozen=True)
class CrankshaftTorque:
    """The torque one crankshaft of several passes on to the gears, and its main bearings'
    load.

    ``torque`` is the gas and inertia torque of the parts this crankshaft drives (its pistons,
    rods and pins; the first crankshaft also carries ``Engine.shaft_inertia_kgm2``), positive
    in its own sense of turning; geared 1:1, the output torque on the first crankshaft's
    sense is their sum (the engine's ``total``). ``main_bearings`` is the crankshaft's force
    on its main bearings together (None when the bearing loads were not asked for).
    """

    number: int
    direction: int
    torque: Series
    main_bearings: "PinForce | None" = None

    def to_dict(self, max_order, floor_n) -> dict:
        return {
            "crankshaft": self.number,
            "direction": self.direction,
            "torque": self.torque.to_dict(),
            "main_bearings": (
                None
                if self.main_bearings is None
                else self.main_bearings.to_dict(max_order, floor_n)
            ),
        }


@dataclass(frozen=True)
class TorqueResult(Tabular):
    """Torques of one engine at constant speed.

    Attributes
    ----------
    engine : Engine
    samples : int
        crank angles a revolution
    reduced_mass : ReducedMass
    inertia, tilting, frame, total : Series
    gas : Series or None
        None when no pressure was given (then ``total`` is the inertia torque alone)
    pins : tuple of PinForce
        the force of the rods on each crank pin
    main_bearings : PinForce or None
        the crankshaft's force on its main bearings together (fixed frame, one crankshaft
        only; an engine with several has them in ``crankshafts``)
    max_order : int
    steadiness : Steadiness or None
        the speed with a flywheel and a load, when asked for
    flywheel_kgm2 : float or None
        the flywheel inertia that reaches a target steadiness, when asked for
    guide : GuideForces or None
        every cylinder's guide force and couple, and the H-type and X-type guide-force
        moments (:mod:`balance_cli.analysis.guideforce`); None for a rotary, and for an engine with
        several crankshafts
    crankshafts : tuple of CrankshaftTorque
        each crankshaft's torque and main-bearing load, for an engine with several (empty
        for one)
    """

    engine: Engine
    samples: int
    reduced_mass: ReducedMass
    inertia: Series
    tilting: Series
    frame: Series
    gas: Series | None
    total: Series
    pins: tuple = ()
    main_bearings: PinForce | None = None
    max_order: int = DEFAULT_MAX_ORDER
    steadiness: Steadiness | None = None
    flywheel_kgm2: float | None = None
    guide: Any = None
    crankshafts: tuple = ()

    @property
    def indicated_power_kw(self) -> float | None:
        """The gas's mean torque × ω, kW: the indicated power of the [gas] cycle or of a
        pressure file (None without a gas torque)."""
        return None if self.gas is None else self.gas.mean * self.engine.speed_rad_s / 1e3

    @property
    def period_deg(self) -> float:
        return self.total.period_deg

    def records(self) -> list:
        """One row per torque and order: ``engine``, ``torque`` ("inertia", "tilting",
        "frame", "gas" when there is a gas torque, "total"), then the series' row
        (:meth:`Series.records <balance_cli.Series.records>`: ``order``, the mean as order 0,
        ``cos_Nm``, ``sin_Nm``, ``amplitude_Nm``, ``phase_deg``)."""
        torques = {"inertia": self.inertia, "tilting": self.tilting, "frame": self.frame}
        if self.gas is not None:
            torques["gas"] = self.gas
        torques["total"] = self.total
        return [
            {"engine": self.engine.name, "torque": name, **row}
            for name, series in torques.items()
            for row in series.records()
        ]

    def to_dict(self) -> dict:
        """This engine's entry of ``torque --format json`` (SI units; see the JSON page)."""
        engine = self.engine
        return {
            "name": engine.name,
            "config": engine.config_path,
            "cycle": engine.cycle,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "period_deg": self.period_deg,
            "reduced_mass": self.reduced_mass.to_dict(),
            "inertia": self.inertia.to_dict(),
            "frame": self.frame.to_dict(),
            "tilting": self.tilting.to_dict(),
            "gas": None if self.gas is None else self.gas.to_dict(),
            "indicated_power_kW": self.indicated_power_kw,
            "total": self.total.to_dict(),
            "bearing": {
                "crank_pins": [p.to_dict(self.max_order, engine.noise_floor_n) for p in self.pins],
                "main_bearings": (
                    None
                    if self.main_bearings is None
                    else self.main_bearings.to_dict(self.max_order, engine.noise_floor_n)
                ),
            },
            "steadiness": None
            if self.steadiness is None
            else {**self.steadiness.to_dict(), "flywheel_for_target_kgm2": self.flywheel_kgm2},
            "guide_force": None if self.guide is None else self.guide.to_dict(),
            "crankshafts": [
                c.to_dict(self.max_order, engine.noise_floor_n) for c in self.crankshafts
            ],
        }


@dataclass(frozen=True)
class TorqueSet(Tabular):
    """The torques of several engines, analysed alike."""

    results: tuple

    def __post_init__(self):
        # TorqueSet(()) failed later, in to_dict, with an IndexError
        object.__setattr__(
            self,
            "results",
            tuple(items(self.results, TorqueResult, "results", what="engine's torques")),
        )

    def records(self) -> list:
        """Every engine's :meth:`TorqueResult.records`, one after the other."""
        return [row for result in self.results for row in result.records()]

    def to_dict(self) -> dict:
        """What ``torque --format json`` writes: one :meth:`TorqueResult.to_dict` per engine."""
        first = self.results[0]
        return {
            "balance_version": DOCUMENT_VERSION,
            "samples": first.samples,
            "max_order": first.max_order,
            "engines": [r.to_dict() for r in self.results],
        }


def torque(
    engine,
    samples=DEFAULT_SAMPLES,
    max_order=DEFAULT_MAX_ORDER,
    pressure=None,
    bore_m=None,
    inertia_kgm2=None,
    load="propeller",
    target=None,
    bearings=True,
    guide=True,
) -> TorqueResult:
    """Inertia, tilting, gas, total and frame torques and the reduced mass of ``engine`` at
    its speed.

    Parameters
    ----------
    engine : Engine
    samples, max_order : int
        crank angles a revolution, and the highest order reported (half orders too for a
        four-stroke)
    pressure : PressureCurve, optional
        the cylinder pressure over a cycle from the firing top dead centre, the same for every
        cylinder at its own firing angle; without it, the engine's [gas] cycle when it has one,
        else no gas torque
    bore_m : float, optional
        the bore for ``pressure``, m (default the engine's [gas] bore)
    inertia_kgm2 : float, optional
        a flywheel (and propeller) inertia: then the speed over the cycle is integrated with
        the gas torque driving, the moving parts' μ(θ) and the ``load`` ("propeller" or
        "constant"; see :func:`balance_cli.analysis.steadiness.steadiness`)
    target : float, optional
        a steadiness to reach: the flywheel inertia that does is given too (and the speed
        with it, when no ``inertia_kgm2`` is given)
    bearings : bool
        False leaves out the forces on the crank pins and main bearings (``pins`` empty,
        ``main_bearings`` None), half the work, for what needs the torques only
    guide : bool
        False leaves out the guide-force moments (``guide`` None), for what does not show them

    Raises
    ------
    AnalysisError
        settings out of range, a pressure curve of another cycle, a pressure without a bore,
        or a steadiness asked for without a gas torque to drive the engine
    """
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    if pressure is not None:
        instance(pressure, PressureCurve, "pressure", hint=" (balance.read_pressure_csv gives one)")
    if bore_m is not None:
        # the command line refused NaN, inf, zero and negative bores; the library took
        # a negative one as its absolute value and NaN as a gas torque of NaN
        positive(bore_m, "bore_m", "length")
    if inertia_kgm2 is not None:
        inertia_kgm2 = positive(inertia_kgm2, "inertia_kgm2", "moment of inertia")
    if target is not None and (not is_real(target) or not 0.5 < target < math.inf):
        raise AnalysisError(
            f"must be a steadiness above ½ (the least there is), got {target!r}", "target"
        )
    if not isinstance(load, str) or load not in LOADS:
        raise AnalysisError(f"must be one of {', '.join(LOADS)}, got {load!r}", "load")
    state = kinematic_state(engine, samples)
    gas_on = gas_load(engine, samples, pressure, bore_m)
    omega = engine.speed_rad_s
    mu, h = reduced_mass_and_momentum(engine, state)
    turns = engine.turns_per_cycle

    def series(values, unit="Nm"):
        return cycle_series(engine, np.real(values), max_order, unit)

    inertia = np.tile(-0.5 * omega**2 * periodic_derivative(mu).real, turns)
    tilting = np.tile(-(omega**2) * periodic_derivative(h).real, turns)
    total = inertia
    net_pressure, area, gas = {}, 0.0, None
    if gas_on is not None:
        net_pressure, area = gas_on.net_pressure, gas_on.area_m2
        gas_curve = gas_torque(engine, state.travel_rates, net_pressure, area)
        check_gas_sampling(engine, samples, gas_on, gas_curve)
        gas = series(gas_curve)
        total = total + gas_curve
    several = engine.has_several_crankshafts
    # the guide-force couples are about one crank axis, as the project guides give them
    guide = (
        None
        if not guide or several
        else guide_forces(engine, state, net_pressure, area, turns, max_order)
    )
    pins, bearing_loads = (
        _bearing_loads(engine, state, turns, net_pressure, area, max_order)
        if bearings
        else ((), [None] * len(engine.crankshafts))
    )
    shafts = (
        ()
        if not several
        else tuple(
            CrankshaftTorque(number, direction, curve, bearing_loads[number - 1])
            for number, direction, curve in _crankshaft_torques(
                engine, state, turns, net_pressure, area, max_order
            )
        )
    )
    speed, flywheel = _driven(engine, gas, mu, inertia_kgm2, target, load)
    return TorqueResult(
        engine,
        samples,
        ReducedMass(np.degrees(state.angles_rad), mu.real),
        series(inertia),
        series(tilting),
        series(-total + tilting),
        gas,
        series(total),
        pins,
        None if several else bearing_loads[0],
        max_order,
        speed,
        flywheel,
        guide,
        shafts,
    )


def _bearing_loads(engine, state, turns, net_pressure, area, max_order):
    """The force of the rods on each crank pin (:class:`PinForce`, radial and tangential), and
    each crankshaft's force on its main bearings (None for a rotary's fixed crank)."""
    forces, crank_inertia = pin_forces(engine, state, turns, net_pressure, area)
    theta = np.arange(state.samples * turns) * 360.0 / state.samples
    pins = []
    for index, force in enumerate(forces):
        # the pin's direction: turning with θ on a crankshaft, fixed on a rotary's crank
        along = np.exp(
            1j * pin_angle(engine, index, 0.0 if engine.is_rotary else np.radians(theta))
        )
        local = force * np.conj(along)
        # tangential: positive in the sense its own crankshaft turns
        sense = engine.crankshaft_of(index).direction
        pins.append(
            PinForce(
                index + 1,
                engine.cycle_deg,
                theta,
                force,
                cycle_series(engine, local.real, max_order, "N"),
                cycle_series(engine, sense * local.imag, max_order, "N"),
            )
        )
    loads: list[PinForce | None] = [None] * len(engine.crankshafts)
    if not engine.is_rotary:
        for s_index in range(len(engine.crankshafts)):
            on_shaft = [
                f
                for f, t in zip(forces, engine.throws, strict=True)
                if t.crankshaft_index == s_index
            ]
            loads[s_index] = PinForce(
                None, engine.cycle_deg, theta, sum(on_shaft) + crank_inertia[s_index], None, None
            )
    return tuple(pins), loads


def _driven(engine, gas, mu, inertia_kgm2, target, load):
    """(speed, flywheel): the speed over the cycle with a flywheel of ``inertia_kgm2`` driven
    by the gas torque against the ``load``, and the flywheel that reaches a ``target``
    steadiness; (None, None) when neither is asked for."""
    if inertia_kgm2 is None and target is None:
        return None, None
    if gas is None:
        raise AnalysisError(
            "needs a gas torque to drive the engine: give a pressure curve or a [gas] table",
            "inertia_kgm2" if inertia_kgm2 else "target",
        )
    if load == "propeller" and not gas.mean > 0:
        raise AnalysisError(
            f"needs an engine that drives its propeller, but the gas torque's "
            f"mean is {gas.mean:.4g} N·m (a motored cycle?); give the [gas] "
            "table an imep",
            "inertia_kgm2" if inertia_kgm2 else "target",
        )
    turns = engine.turns_per_cycle
    drive = dict(
        torque_nm=gas.curve,
        period_deg=engine.cycle_deg,
        speed_rad_s=engine.speed_rad_s,
        load=load,
        reduced_mass_kgm2=np.tile(mu.real, turns),
    )
    speed, flywheel = None, None
    if target is not None:
        flywheel = flywheel_for(target, **drive)
    if inertia_kgm2 is not None:
        speed = steadiness(inertia_kgm2=inertia_kgm2, **drive)
    elif flywheel is not None:
        # the speed with the flywheel found; with none needed, the moving parts' own
        # inertia alone (a vanishing flywheel: the integration needs a positive one)
        speed = steadiness(inertia_kgm2=max(flywheel, 1e-12), **drive)
        speed = dataclasses.replace(speed, inertia_kgm2=flywheel)
    return speed, flywheel


def _crankshaft_torques(engine, state, turns, net_pressure, area, max_order):
    """Each crankshaft's gas and inertia torque over the cycle, in its own sense of turning:
    the virtual work of the parts it alone drives (the gas presses on each piston; the two
    pistons of an opposed cylinder load their two crankshafts)."""
    omega = engine.speed_rad_s
    out = []
    for index, shaft in enumerate(engine.crankshafts):
        mu, _ = reduced_mass_and_momentum(engine, state, index)
        curve = np.tile(-0.5 * omega**2 * periodic_derivative(mu).real, turns)
        if net_pressure:
            for number, rate in state.crankshaft_travel_rates.get(index, {}).items():
                curve = curve + piston_gas_torque(net_pressure[number], area, rate, turns)
        out.append((index + 1, shaft.direction, cycle_series(engine, curve, max_order)))
    return out
