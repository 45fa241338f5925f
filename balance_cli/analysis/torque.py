"""Torques on the crankshaft and the engine frame, and the reduced mass of the moving parts.

Everything comes from the kinetic energy of the exact motion, T = ½·μ(θ)·θ̇², where the
reduced mass μ(θ) = Σ m·|dx/dθ|² + Σ C·(dβ/dθ)² + I_shaft sums the point masses (x their
positions in the fixed frame), the rods' correcting moments of inertia C (β a rod's angle) and
the shaft's own inertia. At constant speed ω, Lagrange's equation gives:

- the **inertia torque** on the crankshaft (a rotary's crankcase), positive with rotation:
  −(d/dt ∂T/∂θ̇ − ∂T/∂θ) = −½·ω²·dμ/dθ; for one reciprocating mass on a massless rod this is
  m·r²·ω²·(λ/4·sin θ − ½·sin 2θ − 3λ/4·sin 3θ − …);
- the **tilting couple** (Fraeys de Veubeke's V_k), the moving parts' −dH/dt about the crank
  axis, H = θ̇·(Σ m·Im(x̄·dx/dθ) + Σ C·dβ/dθ + I_shaft) their angular momentum;
- the **gas torque**, −Σ (p − p_crankcase)·A·ds/dθ with s each piston's travel (virtual work);
- the **frame reaction**, the couple on the engine frame: −(gas + inertia) + tilting
  (Fraeys's (23) without reduction gear; for inertia alone, Tanaka's ΣC_I + C_L).

Derivatives with respect to θ are taken spectrally (multiplying Fourier coefficients by ik),
exact for the band-limited motion; a four-stroke's torques repeat every 720°, so their orders
are multiples of ½.
"""

import dataclasses
import math
import warnings
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from .results import DOCUMENT_VERSION
from ..checks import instance, is_real, items, positive
from ..errors import AnalysisError, OrderError, SamplingWarning
from .gas import PressureCurve, cycle_pressure
from ..harmonics import orders_of
from .firing import firing_sequence
from ..kinematics.linkage import (BIG_ENDS, CRANKSHAFT_OWNERS, check_assembly, crank_angles_of,
                                  engine_angles, linkage, linkage_state, pin_angle, piston_travel,
                                  travel_at)
from ..model import Engine
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, MAX_SAMPLES, check_settings, part_values
from .steadiness import LOADS, Steadiness, flywheel_for, steadiness
from ..tolerances import NOISE_FLOOR
from ..units import phasor_deg, rad_s_to_rpm

__all__ = ["Series", "ReducedMass", "PinForce", "CrankshaftTorque", "TorqueResult", "TorqueSet",
           "torque", "periodic_derivative"]


def periodic_derivative(values, period=2 * math.pi):
    """d/dθ of samples of a periodic function over one ``period`` (last axis), spectrally."""
    n = values.shape[-1]
    k = orders_of(n) * (2 * math.pi / period)
    if n % 2 == 0:
        k[n // 2] = 0.0   # the Nyquist term has no sign; its derivative is dropped
    return np.fft.ifft(np.fft.fft(values, axis=-1) * 1j * k, axis=-1)


@dataclass(frozen=True)
class Series:
    """A quantity over one period: X(θ) = mean + Σ_k (cos_k·cos kθ + sin_k·sin kθ), in ``unit``
    (a torque in N·m, a force component in N).

    θ is the crank angle of throw 1 (a rotary's crankcase angle), positive with rotation; k
    runs over multiples of ½ for a four-stroke. ``curve`` holds X at ``theta_deg``.
    """

    period_deg: float
    mean: float
    orders: tuple
    theta_deg: np.ndarray
    curve: np.ndarray
    unit: str = "Nm"

    @classmethod
    def from_curve(cls, curve, period_deg, max_order, floor, unit="Nm"):
        """The series of samples ``curve`` (over one period) up to ``max_order``; terms below
        ``floor`` are rounding noise and read as exact zeros."""
        curve = np.real(curve)
        n = curve.shape[-1]
        per_turn = period_deg / 360.0
        c = np.fft.rfft(curve) / n
        orders = []
        for j in range(1, int(round(max_order * per_turn)) + 1):
            cos, sin = float(2 * c[j].real), float(-2 * c[j].imag)
            orders.append((j / per_turn, cos if abs(cos) >= floor else 0.0,
                           sin if abs(sin) >= floor else 0.0))
        mean = c[0].real if abs(c[0].real) >= floor else 0.0
        theta = np.arange(n) * period_deg / n
        if np.abs(curve).max() < floor:
            curve = np.zeros_like(curve)   # rounding noise only (a centred piston's tilting)
        return cls(float(period_deg), float(mean), tuple(orders), theta, curve, unit)

    @property
    def max(self) -> float:
        return float(self.curve.max())

    @property
    def min(self) -> float:
        return float(self.curve.min())

    @property
    def range(self) -> float:
        """ΔC, the largest minus the smallest value over the period."""
        return self.max - self.min

    def order(self, k) -> tuple:
        """(cos, sin) of order ``k`` (a multiple of ½ for a four-stroke); OrderError (a
        KeyError) otherwise."""
        if is_real(k):
            for order, cos, sin in self.orders:
                if abs(order - k) < 1e-9:
                    return cos, sin
        highest = self.orders[-1][0] if self.orders else 0
        raise OrderError(f"order {k!r} is not among the orders of this series (multiples of "
                         f"{360 / self.period_deg:g} up to {highest:g})")

    def to_dict(self) -> dict:
        """``mean_<unit>``, ``max_``, ``min_``, ``range_`` and ``orders[]`` (``order``, ``cos_``,
        ``sin_``, ``amplitude_``, ``phase_deg``: the order is amplitude·cos(kθ − phase))."""
        u = self.unit
        return {
            f"mean_{u}": self.mean, f"max_{u}": self.max, f"min_{u}": self.min,
            f"range_{u}": self.range,
            "orders": [{"order": k, f"cos_{u}": cos, f"sin_{u}": sin,
                        f"amplitude_{u}": math.hypot(cos, sin),
                        "phase_deg": phasor_deg(complex(cos, sin))}
                       for k, cos, sin in self.orders],
        }


@dataclass(frozen=True)
class ReducedMass:
    """μ(θ): the kinetic energy of the moving parts is ½·μ·ω², kg·m² (Margoulis § 2)."""

    theta_deg: np.ndarray
    curve_kgm2: np.ndarray

    @property
    def mean_kgm2(self) -> float:
        return float(self.curve_kgm2.mean())

    @property
    def min_kgm2(self) -> float:
        return float(self.curve_kgm2.min())

    @property
    def max_kgm2(self) -> float:
        return float(self.curve_kgm2.max())

    def to_dict(self) -> dict:
        return {"mean_kgm2": self.mean_kgm2, "min_kgm2": self.min_kgm2, "max_kgm2": self.max_kgm2}


@dataclass(frozen=True)
class PinForce:
    """The force the rods exert on one crank pin (``throw``, 1-based), or the crankshaft on its
    main bearings together (``throw`` None), over one period, in the fixed frame.

    ``force_n`` is complex, N (real part along the reference axis); ``radial`` (outwards along
    the throw) and ``tangential`` (positive with rotation: r·tangential turns the crank) are
    given for a pin. Orders are multiples of ½ for a four-stroke with gas.
    """

    throw: int | None
    period_deg: float
    theta_deg: np.ndarray
    force_n: np.ndarray
    radial: Series | None
    tangential: Series | None

    @cached_property
    def _spectrum(self):
        return np.fft.fft(self.force_n) / self.force_n.shape[-1]

    def order(self, k):
        """Forward and backward phasors of order ``k``, N: F = F⁺·e^{ikθ} + F⁻·e^{−ikθ}; k
        from 0 to below half the samples a period, a multiple of ½ for a four-stroke with gas
        (OrderError, a KeyError, otherwise)."""
        n = self.force_n.shape[-1]
        steps = k * self.period_deg / 360.0 if is_real(k) and math.isfinite(k) else math.nan
        # order(1e300) once wrapped round the samples and answered
        if not (0 <= steps < n / 2 and abs(steps - round(steps)) < 1e-9):
            raise OrderError(f"order {k!r} is not among the orders of these forces (multiples of "
                             f"{360 / self.period_deg:g} below {n / 2 * 360 / self.period_deg:g})")
        j = int(round(steps))
        c = self._spectrum
        return complex(c[j % n]), complex(c[-j % n])

    def to_dict(self, max_order, floor_n) -> dict:
        per_turn = self.period_deg / 360.0
        orders = []
        for j in range(0, int(round(max_order * per_turn)) + 1):
            forward, backward = self.order(j / per_turn)
            if j == 0:
                # the steady part: one phasor, kept as the forward one
                backward = 0j
            # a crank pin's force is read in the crank's terms (radial, tangential, forward,
            # backward); the engine's vertical belongs to the free forces
            orders.append({"order": j / per_turn,
                           "force": part_values(forward, backward, floor_n, "N", components=False)})
        entry: dict = {"throw": self.throw, "orders": orders}
        if self.radial is not None and self.tangential is not None:
            entry["radial"] = self.radial.to_dict()
            entry["tangential"] = self.tangential.to_dict()
        return entry


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
        return {"crankshaft": self.number, "direction": self.direction,
                "torque": self.torque.to_dict(),
                "main_bearings": (None if self.main_bearings is None else
                                  self.main_bearings.to_dict(max_order, floor_n))}


@dataclass(frozen=True)
class TorqueResult:
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

    def to_dict(self) -> dict:
        """This engine's entry of ``torque --format json`` (SI units; see the README)."""
        engine = self.engine
        return {
            "name": engine.name, "config": engine.config_path, "cycle": engine.cycle,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "period_deg": self.period_deg,
            "reduced_mass": self.reduced_mass.to_dict(),
            "inertia": self.inertia.to_dict(), "frame": self.frame.to_dict(),
            "tilting": self.tilting.to_dict(),
            "gas": None if self.gas is None else self.gas.to_dict(),
            "indicated_power_kW": self.indicated_power_kw,
            "total": self.total.to_dict(),
            "bearing": {
                "crank_pins": [p.to_dict(self.max_order, engine.noise_floor_n) for p in self.pins],
                "main_bearings": (None if self.main_bearings is None else
                                  self.main_bearings.to_dict(self.max_order, engine.noise_floor_n)),
            },
            "steadiness": None if self.steadiness is None else {
                **self.steadiness.to_dict(), "flywheel_for_target_kgm2": self.flywheel_kgm2},
            "guide_force": None if self.guide is None else self.guide.to_dict(),
            "crankshafts": [c.to_dict(self.max_order, engine.noise_floor_n)
                            for c in self.crankshafts],
        }


@dataclass(frozen=True)
class TorqueSet:
    """The torques of several engines, analysed alike."""

    results: tuple

    def __post_init__(self):
        # TorqueSet(()) failed later, in to_dict, with an IndexError
        object.__setattr__(self, "results", tuple(items(self.results, TorqueResult, "results",
                                                         what="engine's torques")))

    def to_dict(self) -> dict:
        """What ``torque --format json`` writes: one :meth:`TorqueResult.to_dict` per engine."""
        first = self.results[0]
        return {"balance_version": DOCUMENT_VERSION, "samples": first.samples,
                "max_order": first.max_order, "engines": [r.to_dict() for r in self.results]}


def _torque_unit(engine):
    """m_rec·r²·ω²·n, N·m: the size torques are measured against (as forces against m·r·ω²·n)."""
    return engine.per_cylinder_unit_n * engine.crank_radius_m


def selected(state, masses_kept, rods_kept):
    """The linkage ``state`` with only the point masses and rods the boolean masks keep: the
    parts of one crankshaft, one cylinder or one throw (μ is a sum over the parts, so their
    torques add up to the engine's)."""
    masses, rods = state.masses, state.rods
    return state._replace(
        masses=dataclasses.replace(masses, **{
            name: getattr(masses, name)[masses_kept]
            for name in ("positions", "masses_kg", "z_m", "cylinder", "throw")}),
        rods=dataclasses.replace(rods, **{
            name: getattr(rods, name)[rods_kept]
            for name in ("directions", "corrections_kgm2", "cylinder", "throw")}))


def _reduced_mass_and_momentum(engine, state, crankshaft=None):
    """μ(θ) and h(θ) = H/θ̇ from the linkage ``state`` over one revolution, kg·m²; of the parts
    one ``crankshaft`` (an index) drives, if given."""
    if crankshaft is not None:
        shaft_of = np.array([t.crankshaft for t in engine.throws])
        # a balancer-shaft mass (throw −1) rides on no crankshaft
        throws = state.masses.throw
        state = selected(state, (throws >= 0) & (shaft_of[throws] == crankshaft),
                         shaft_of[state.rods.throw] == crankshaft)
    masses, rods = state.masses, state.rods
    rates = periodic_derivative(masses.positions)
    weights = masses.masses_kg[:, None]
    mu = (weights * np.abs(rates) ** 2).sum(axis=0)
    h = (weights * (np.conj(masses.positions) * rates).imag).sum(axis=0)
    if np.any(rods.corrections_kgm2):
        # a rod's angular rate from its unit vector u: dβ/dθ = Im(ū·du/dθ)
        turning = (np.conj(rods.directions) * periodic_derivative(rods.directions)).imag
        corrections = rods.corrections_kgm2[:, None]
        mu = mu + (corrections * turning**2).sum(axis=0)
        h = h + (corrections * turning).sum(axis=0)
    # the crankshaft and flywheel inertia belongs to the first (output) crankshaft
    shaft = engine.shaft_inertia_kgm2 if crankshaft in (None, 0) else 0.0
    return mu + shaft, h + shaft


def _piston_travels(engine, angles):
    """Each piston's own travel over engine angles ``angles``, by crankshaft index and then
    cylinder number, m: an opposed-piston cylinder has one on each of its two crankshafts."""
    link = linkage(engine, crank_angles_of(engine, angles))
    out: dict = {}
    for c in engine.cylinders:
        travel = link.travel[c.number]
        if c.is_opposed:
            own = link.opposed[c.number][1]
            out.setdefault(engine.throws[c.opposed_throw].crankshaft, {})[c.number] = own
            travel = travel - own
        out.setdefault(engine.throws[c.throw].crankshaft, {}).setdefault(c.number, 0.0)
        out[engine.throws[c.throw].crankshaft][c.number] = \
            out[engine.throws[c.throw].crankshaft][c.number] + travel
    return out


def _crankshaft_torques(engine, state, angles, turns, net_pressure, area, series):
    """Each crankshaft's gas and inertia torque over the cycle, in its own sense of turning:
    the virtual work of the parts it alone drives (the gas presses on each piston; the two
    pistons of an opposed cylinder load their two crankshafts)."""
    omega = engine.speed_rad_s
    travels = _piston_travels(engine, angles)
    out = []
    for index, shaft in enumerate(engine.crankshafts):
        mu, _ = _reduced_mass_and_momentum(engine, state, index)
        curve = np.tile(-0.5 * omega**2 * periodic_derivative(mu).real, turns)
        if net_pressure:
            for number, travel in travels.get(index, {}).items():
                rate = periodic_derivative(np.asarray(travel)).real
                curve = curve - net_pressure[number] * area * np.tile(rate, turns)
        out.append((index + 1, shaft.direction, series(curve)))
    return out


def _firing_angles_deg(engine, firing):
    """Engine angle of each cylinder's firing top dead centre, by cylinder number."""
    start = firing.tdc_deg[firing.order[0]]
    return {n: (start + a) % engine.cycle_deg for n, a in zip(firing.order, firing.angles_deg)}


def _travel_rates(engine, angles):
    """ds/dθ of every piston over one revolution of engine angles, by cylinder number, m/rad."""
    travel = piston_travel(engine, crank_angles_of(engine, angles))
    numbers = list(travel)
    rates = periodic_derivative(np.array([travel[n] for n in numbers])).real
    return dict(zip(numbers, rates))


def _pressure_curves(engine, fire, pressure):
    """Every cylinder's pressure curve: ``pressure``, or its own [gas] cycle."""
    out = {}
    for cylinder in engine.cylinders:
        n = cylinder.number
        curve = pressure
        if curve is None:
            def travel_of(psi_deg, n=n):
                return travel_at(engine, np.radians(fire[n] + psi_deg), [n])[n]
            curve = cycle_pressure(engine.gas, travel_of, engine.cycle_deg, engine.config_path)
        out[n] = curve
    return out


def _net_pressures(engine, cycle_angles, fire, curves):
    """(p − p_crankcase) of every cylinder over the cycle grid ``cycle_angles`` (rad), Pa."""
    gas = engine.gas
    crankcase = gas.crankcase_pa if gas is not None else 101325.0
    theta_deg = np.degrees(cycle_angles)
    return {n: curve.at(theta_deg - fire[n]) - crankcase for n, curve in curves.items()}


#: the gas torque's mean may move by this fraction (of its mean, or of a hundredth of its
#: peak for a cycle that averages out) when the samples are doubled before a warning: the
#: README promises a few 1e-3 at the default sampling
GAS_CONVERGENCE = 1e-3


def _gas_torque(engine, samples, turns, fire, curves, area):
    """The gas torque over the cycle at ``samples`` a revolution, and the net pressures."""
    angles = engine_angles(samples)
    net = _net_pressures(engine, engine_angles(samples * turns) * turns, fire, curves)
    rates = _travel_rates(engine, angles)
    return sum(-net[c.number] * area * np.tile(rates[c.number], turns)
               for c in engine.cylinders), net


def _check_gas_sampling(engine, samples, turns, fire, curves, area, gas_curve):
    """Warn when doubling the samples moves the gas torque's mean: a sharp pressure curve
    (a compression ratio of 100 burning in 1°) aliased by 1.3 % at 256 samples, silently."""
    finer, _ = _gas_torque(engine, 2 * samples, turns, fire, curves, area)
    mean, better = float(np.mean(gas_curve)), float(np.mean(finer))
    scale = max(abs(better), 1e-2 * float(np.abs(finer).max()))
    moved = abs(mean - better) / scale if scale > 0 else 0.0
    if moved > GAS_CONVERGENCE:
        # an aliasing error falls at least as the square of the samples
        needed = samples * 2 ** math.ceil(math.log2(math.sqrt(moved / GAS_CONVERGENCE)) + 1)
        warning = SamplingWarning(
            f"{engine.name}: the gas torque is not converged at {samples} samples a revolution: "
            f"its mean moves by {moved:.1e} of itself at {2 * samples} (a sharp pressure curve); "
            f"use {min(needed, MAX_SAMPLES)} samples or more")
        warning.samples, warning.excess = samples, moved
        warnings.warn(warning, stacklevel=3)


#: virtual shifts of a crank pin, in crank radii: ±h and ±h/2 for a Richardson-extrapolated
#: central difference (error O(h⁴), far below the noise floor at h = 1e-4)
_SHIFT = 1e-4
_STEPS = np.array([1.0, -1.0, 0.5, -0.5])


def _derivative(values):
    """d/dh at 0 from ``values`` at h = _STEPS·step (leading axis), per unit step: central
    differences extrapolated, (4·fine − coarse)/3."""
    coarse = (values[0] - values[1]) / 2
    fine = (values[2] - values[3])
    return (4 * fine - coarse) / 3


def _pin_forces(engine, state, angles, turns, net_pressure, area):
    """The force of the pin on the rods riding on it, by virtual work: for a virtual shift δP
    of the pin (the cylinders held), F·δP = Σ m·a·δx + Σ C·β̈·δβ + Σ (p − p_c)·A·δs; the force
    of the rods on the pin is −F. One complex curve over the cycle per throw, N."""
    omega = engine.speed_rad_s
    n = len(angles)
    masses, rods = state.masses, state.rods
    k = orders_of(n)
    accelerations = np.fft.ifft(np.fft.fft(masses.positions, axis=-1) * -(k * omega) ** 2, axis=-1)
    # what rides on the pins: the cylinders' masses and the big ends (not the crankshaft's own
    # masses, counterweights or balancer shafts)
    weights = np.where(masses.cylinder >= BIG_ENDS, masses.masses_kg, 0.0)[:, None]
    rates = (np.conj(rods.directions) * periodic_derivative(rods.directions)).imag
    angular_accelerations = omega**2 * periodic_derivative(rates).real
    step = _SHIFT * engine.crank_radius_m
    # every shift of one pin at once: (direction along/across) × (the four steps)
    shifts = (np.array([1.0, 1j])[:, None] * _STEPS[None, :] * step).reshape(-1, 1)
    grid = np.broadcast_to(angles, (len(shifts), n))
    forces = []
    for index in range(len(engine.throws)):
        shifted = linkage_state(engine, grid, {index: shifts}, throw=index)
        # only what rides on this pin moves with it: the same rows of the whole engine's state
        on_pin = np.isin(masses.cylinder, shifted.masses.cylinder) & (
            (masses.cylinder > 0) | (masses.throw == index))
        rods_on_pin = np.isin(rods.cylinder, shifted.rods.cylinder)
        size = (2, len(_STEPS))
        dx = _derivative(np.moveaxis(shifted.masses.positions.reshape(-1, *size, n), 2, 0)) / step
        du = _derivative(np.moveaxis(shifted.rods.directions.reshape(-1, *size, n), 2, 0)) / step
        inertial = (weights[on_pin, None] * (np.conj(accelerations[on_pin])[:, None] * dx).real
                    ).sum(axis=0)
        inertial += (rods.corrections_kgm2[rods_on_pin, None, None]
                     * angular_accelerations[rods_on_pin, None]
                     * (np.conj(rods.directions[rods_on_pin])[:, None] * du).imag).sum(axis=0)
        parts = np.tile(inertial, turns)                       # (along, across) × cycle
        # an opposed-piston cylinder has two rods but one pressure
        numbers = list(dict.fromkeys(int(m) for m in shifted.rods.cylinder))
        if net_pressure and numbers:
            ds = _derivative(np.moveaxis(np.array([shifted.travel[m] for m in numbers])
                                         .reshape(-1, *size, n), 2, 0)) / step
            parts = parts + sum(net_pressure[m] * area * np.tile(ds[i], turns)
                                for i, m in enumerate(numbers))
        forces.append(-(parts[0] + 1j * parts[1]))
    # each crankshaft's own masses and its counterweights load its own main bearings; a
    # balancer shaft runs in bearings of its own: its rows (throw −1, which picks the last
    # throw's crankshaft here) fall out by their owner code
    shaft_of = np.array([t.crankshaft for t in engine.throws])[masses.throw]
    crank_inertia = []
    for s_index in range(len(engine.crankshafts)):
        own = np.where(np.isin(masses.cylinder, CRANKSHAFT_OWNERS) & (shaft_of == s_index),
                       masses.masses_kg, 0.0)
        crank_inertia.append(np.tile(-(own[:, None] * accelerations).sum(axis=0), turns))
    return forces, crank_inertia


def _gas_bore(engine, pressure, bore_m):
    """The bore the gas torque acts on, m (None: no gas torque): ``bore_m`` (or the [gas]
    table's) for a pressure curve of the engine's cycle, the [gas] table's without one; a bore
    without a pressure is an error, as is a pressure curve without a bore."""
    if pressure is not None:
        instance(pressure, PressureCurve, "pressure", hint=" (balance.read_pressure_csv gives one)")
        if pressure.cycle_deg != engine.cycle_deg:
            raise AnalysisError(f"covers {pressure.cycle_deg:g}°, but {engine.name!r} is a "
                                f"{engine.cycle}-stroke ({engine.cycle_deg:g}°)", "pressure")
        bore_m = bore_m if bore_m is not None else (engine.gas.bore_m if engine.gas else None)
        if bore_m is None:
            raise AnalysisError("is missing for the pressure curve: give the bore, or a [gas] "
                                "table with one", "bore_m")
        return positive(bore_m, "bore_m", "length")
    if bore_m is not None:
        raise AnalysisError("applies to a pressure curve only; give the pressure too (a [gas] "
                            "table has its own bore)", "bore_m")
    return None if engine.gas is None else engine.gas.bore_m


def torque(engine, samples=DEFAULT_SAMPLES, max_order=DEFAULT_MAX_ORDER, pressure=None,
           bore_m=None, inertia_kgm2=None, load="propeller", target=None,
           bearings=True, guide=True) -> TorqueResult:
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
        raise AnalysisError(f"must be a steadiness above ½ (the least there is), got {target!r}",
                            "target")
    if not isinstance(load, str) or load not in LOADS:
        raise AnalysisError(f"must be one of {', '.join(LOADS)}, got {load!r}", "load")
    check_assembly(engine)
    bore_m = _gas_bore(engine, pressure, bore_m)
    omega = engine.speed_rad_s
    angles = engine_angles(samples)
    state = linkage_state(engine, angles)
    mu, h = _reduced_mass_and_momentum(engine, state)
    turns = int(round(engine.cycle_deg / 360.0))
    floor = NOISE_FLOOR * _torque_unit(engine)

    def series(values, unit="Nm", tile=True):
        values = np.tile(np.real(values), turns) if tile else np.real(values)
        return Series.from_curve(values, engine.cycle_deg, max_order,
                                 floor if unit == "Nm" else engine.noise_floor_n, unit)

    inertia = -0.5 * omega**2 * periodic_derivative(mu).real
    tilting = -omega**2 * periodic_derivative(h).real
    total = np.tile(inertia, turns)
    net_pressure, area, gas = {}, 0.0, None
    if bore_m is not None:
        area = math.pi * bore_m**2 / 4
        fire = _firing_angles_deg(engine, firing_sequence(engine))
        curves = _pressure_curves(engine, fire, pressure)
        gas_curve, net_pressure = _gas_torque(engine, samples, turns, fire, curves, area)
        _check_gas_sampling(engine, samples, turns, fire, curves, area, gas_curve)
        gas = series(gas_curve, tile=False)
        total = total + gas_curve
    # imported here: guideforce builds its results with this module's Series
    from .guideforce import guide_forces
    several = engine.has_several_crankshafts
    # the guide-force couples are about one crank axis, as the project guides give them
    guide = None if not guide or several else guide_forces(
        engine, state, net_pressure, area, turns,
        lambda values, unit: series(values, unit, tile=False))
    pins, crank_inertia = (_pin_forces(engine, state, angles, turns, net_pressure, area)
                           if bearings else ([], None))
    theta = np.arange(samples * turns) * 360.0 / samples
    pin_results = []
    for index, force in enumerate(pins):
        # the pin's direction: turning with θ on a crankshaft, fixed on a rotary's crank
        along = np.exp(1j * pin_angle(engine, index, 0.0 if engine.is_rotary else np.radians(theta)))
        local = force * np.conj(along)
        # tangential: positive in the sense its own crankshaft turns
        sense = engine.crankshaft_of(index).direction
        pin_results.append(PinForce(index + 1, engine.cycle_deg, theta, force,
                                    series(local.real, "N", tile=False),
                                    series(sense * local.imag, "N", tile=False)))
    bearing_loads: list[PinForce | None] = [None] * len(engine.crankshafts)
    if bearings and not engine.is_rotary:
        for s_index in range(len(engine.crankshafts)):
            on_shaft = [f for f, t in zip(pins, engine.throws) if t.crankshaft == s_index]
            bearing_loads[s_index] = PinForce(None, engine.cycle_deg, theta,
                                              sum(on_shaft) + crank_inertia[s_index], None, None)
    main = None if several else bearing_loads[0]
    shafts = () if not several else tuple(
        CrankshaftTorque(number, direction, curve, bearing_loads[number - 1])
        for number, direction, curve in _crankshaft_torques(
            engine, state, angles, turns, net_pressure, area,
            lambda values: series(values, tile=False)))
    speed, flywheel = None, None
    if inertia_kgm2 is not None or target is not None:
        if gas is None:
            raise AnalysisError("needs a gas torque to drive the engine: give a pressure curve "
                                "or a [gas] table", "inertia_kgm2" if inertia_kgm2 else "target")
        if load == "propeller" and not gas.mean > 0:
            raise AnalysisError(f"needs an engine that drives its propeller, but the gas torque's "
                                f"mean is {gas.mean:.4g} N·m (a motored cycle?); give the [gas] "
                                "table an imep", "inertia_kgm2" if inertia_kgm2 else "target")
        drive = dict(torque_nm=gas.curve, period_deg=engine.cycle_deg, speed_rad_s=omega,
                     load=load, reduced_mass_kgm2=np.tile(mu.real, turns))
        if target is not None:
            flywheel = flywheel_for(target, **drive)
        if inertia_kgm2 is not None:
            speed = steadiness(inertia_kgm2=inertia_kgm2, **drive)
        elif flywheel is not None:
            # the speed with the flywheel found; with none needed, the moving parts' own
            # inertia alone (a vanishing flywheel: the integration needs a positive one)
            speed = steadiness(inertia_kgm2=max(flywheel, 1e-12), **drive)
            speed = dataclasses.replace(speed, inertia_kgm2=flywheel)
    return TorqueResult(engine, samples, ReducedMass(np.degrees(angles), mu.real), series(inertia),
                        series(tilting), series(-total + np.tile(tilting, turns), tile=False), gas,
                        series(total, tile=False), tuple(pin_results), main, max_order, speed,
                        flywheel, guide, shafts)


@dataclass(frozen=True)
class CylinderTorque:
    """One cylinder's own tangential torque on its throw, at the engine's speed.

    ``inertia`` is what its piston, rod (and link) exert, −½·ω²·dμ_c/dθ with μ_c the reduced
    mass of its parts alone (the crank pins' masses turn at a constant radius and exert none);
    ``gas`` its gas pressure's, −(p − p_crankcase)·A·ds/dθ (None without a pressure). Both
    against θ, the crank angle of throw 1, so its firing phase is in them; the engine's total
    torque is their sum over the cylinders.
    """

    number: int
    throw: int
    inertia: Series
    gas: Series | None


def cylinder_torques(engine, samples=DEFAULT_SAMPLES, max_order=DEFAULT_MAX_ORDER,
                     pressure=None, bore_m=None) -> tuple:
    """Every cylinder's own inertia and gas torque (:class:`CylinderTorque`, in cylinder
    order), from the same linkage, reduced mass and gas pieces as :func:`torque`.

    ``pressure`` and ``bore_m`` as in :func:`torque` (default the engine's [gas] cycle, if
    any). An engine of one crankshaft only (AnalysisError otherwise).
    """
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    check_assembly(engine)
    if engine.has_several_crankshafts or any(c.is_opposed for c in engine.cylinders):
        raise AnalysisError("has several crankshafts or opposed pistons; a cylinder's torque "
                            "on one throw is given for one crankshaft only", "engine")
    bore_m = _gas_bore(engine, pressure, bore_m)
    omega = engine.speed_rad_s
    angles = engine_angles(samples)
    state = linkage_state(engine, angles)
    turns = int(round(engine.cycle_deg / 360.0))
    floor = NOISE_FLOOR * _torque_unit(engine)
    masses, rods = state.masses, state.rods
    net, rates, area = {}, {}, 0.0
    if bore_m is not None:
        area = math.pi * bore_m**2 / 4
        fire = _firing_angles_deg(engine, firing_sequence(engine))
        net = _net_pressures(engine, engine_angles(samples * turns) * turns, fire,
                             _pressure_curves(engine, fire, pressure))
        rates = _travel_rates(engine, angles)
    out = []
    for cylinder in engine.cylinders:
        n = cylinder.number
        # only this cylinder's rows; the shaft's constant inertia in μ has no derivative: no
        # torque of its own
        mu, _ = _reduced_mass_and_momentum(
            engine, selected(state, masses.cylinder == n, rods.cylinder == n))
        inertia = np.tile(-0.5 * omega**2 * periodic_derivative(mu).real, turns)
        gas = None
        if net:
            gas = Series.from_curve(-net[n] * area * np.tile(rates[n], turns), engine.cycle_deg,
                                    max_order, floor)
        out.append(CylinderTorque(n, cylinder.throw + 1,
                                  Series.from_curve(inertia, engine.cycle_deg, max_order, floor),
                                  gas))
    return tuple(out)
