"""Torsional vibration of the crankshaft: modes, phase-vector sums, criticals and forced
response, and their result.

The shaft line and its solution are openTorsion's (Aalto University's library of disks and
shafts: ``pip install 'engine-balance[torsion]'``); balance supplies the engine's side: each throw's
inertia (or the mean reduced mass of the parts on it), and the excitation, each cylinder's exact
tangential torque order by order (:func:`balance_cli.analysis.cylinders.cylinder_torques`),
which carries its firing phase because it is given against the crank angle of throw 1.

The model, free end first: the ``front`` inertias (pulley, damper), the throws, the flywheel and
the load, each joined to the next by a section of stiffness k (and damping c). At a speed Ω the
order-k torque of a cylinder is G_k + (Ω/ω₀)²·I_k: the gas part is taken as the same cycle at
every speed, the inertia part grows as the square of the speed (ω₀ the configuration's speed).
The steady response to a torque Re(U·e^{ikΩt}) is Re(Q·e^{ikΩt}), (K − (kΩ)²M + ikΩC)·Q = U;
a section's vibratory torque is k·(Q_left − Q_right) (:mod:`.forced`).
"""

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..analysis.firing import firing_angles
from ..analysis.shaking import DEFAULT_SAMPLES
from ..checks import curve, is_real
from ..errors import AnalysisError
from ..model import Engine
from ..tabular import Tabular
from ..units import rad_s_to_rpm
from .adapter import assembly_of, natural_frequencies, require_opentorsion
from .excitation import excitation
from .forced import forced_response
from .line import shaft_line, torsion_model
from .modes import CRITICAL_KINDS, Critical, Mode, modes_and_criticals, normalised

__all__ = [
    "Mode",
    "Critical",
    "Peak",
    "TorsionResult",
    "torsional_vibration",
    "first_mode_amplitudes",
    "default_speeds_rpm",
    "DEFAULT_MAX_ORDER",
    "MAX_SPEEDS",
    "CRITICAL_KINDS",
]

#: the default speed range, as fractions of the engine's own speed, and its number of speeds
DEFAULT_SPEED_RANGE = (0.2, 1.2)
DEFAULT_SPEED_COUNT = 201
#: the most speeds of one sweep: each costs about 0.1 MB at twelve orders
MAX_SPEEDS = 5000
#: speeds as the configuration takes them, rpm
_SPEED_LIMITS_RPM = (1e-3, 1e6)
#: the highest order applied; twelve cover the criticals of the usual first two modes
DEFAULT_MAX_ORDER = 12
#: a peak belongs to a critical of its order within this fraction of its speed
_PEAK_BAND = 0.1


@dataclass(frozen=True)
class Peak:
    """The largest vibratory torque of a sweep, all sections and speeds: where it is and what
    makes it. ``order`` is the order of the largest amplitude there; ``mode`` the mode whose
    critical of that order is nearest, within 10 % of the speed (None if none), and
    ``critical_rpm`` that critical's speed; ``major`` whether the order is a major one."""

    section: str
    torque_nm: float
    speed_rpm: float
    order: float
    mode: int | None
    critical_rpm: float | None
    major: bool

    def to_dict(self) -> dict:
        return {
            "section": self.section,
            "torque_Nm": self.torque_nm,
            "speed_rpm": self.speed_rpm,
            "order": self.order,
            "mode": self.mode,
            "critical_rpm": self.critical_rpm,
            "major": self.major,
        }


@dataclass(frozen=True)
class TorsionResult(Tabular):
    """Modes, criticals and forced response of one engine's crankshaft.

    Attributes
    ----------
    engine : Engine
    nodes : tuple of str
        the shaft line's inertias, free end first
    sections : tuple of str
        "A–B" for each section between consecutive nodes
    inertia_kgm2, stiffness_nm_rad : ndarray
        per node, per section
    modes : tuple of Mode
    criticals : tuple of Critical
        every mode and order whose resonance falls within the speeds
    orders : ndarray
        the orders applied (multiples of ½ for a four-stroke)
    speeds_rpm : ndarray
    order_torque_nm : ndarray
        vibratory torque amplitude, N·m, by speed × section × order
    torque_nm : ndarray
        the synthesised waveform's peak ``|T|`` over the cycle, N·m, by speed × section
    free_end_deg : ndarray
        the free end's angular amplitude (peak of the synthesised waveform), degrees, by speed
    stress_pa : ndarray or None
        torque_nm as shear stress τ = T·r/J_p, Pa, with the [torsion] shaft diameter
    with_gas : bool
        whether the excitation has a gas torque ([gas] table or a pressure curve), or the
        inertia torque alone
    free_end_order_deg : ndarray or None
        the free end's amplitude of each order, degrees, by speed × order
    free_end_elastic_deg, free_end_elastic_order_deg : ndarray or None
        the same for the free end's elastic twist: its angle less the angle of the line's
        centre of inertia, Σ J·θ / Σ J (the rigid-body mode's coordinate, the whole line
        turning as one body, which the free end's own angle includes), degrees
    major_orders : tuple of float
        the orders that put every cylinder in phase
    selection : dict or None
        which criticals :meth:`filtered` kept (``kind``, ``orders``, ``modes``); None: all
    """

    engine: Engine
    nodes: tuple
    sections: tuple
    inertia_kgm2: np.ndarray
    stiffness_nm_rad: np.ndarray
    modes: tuple
    criticals: tuple
    orders: np.ndarray
    speeds_rpm: np.ndarray
    order_torque_nm: np.ndarray
    torque_nm: np.ndarray
    free_end_deg: np.ndarray
    stress_pa: np.ndarray | None
    with_gas: bool = False
    free_end_order_deg: np.ndarray | None = None
    free_end_elastic_deg: np.ndarray | None = None
    free_end_elastic_order_deg: np.ndarray | None = None
    major_orders: tuple = ()
    selection: dict | None = None

    def _window(self, speed_rpm):
        # the speeds nearer to this speed of the sweep than to any other
        speeds = np.sort(self.speeds_rpm)
        i = int(np.searchsorted(speeds, speed_rpm))
        low = (speeds[i - 1] + speed_rpm) / 2 if i > 0 else -math.inf
        high = (speeds[i + 1] + speed_rpm) / 2 if i + 1 < len(speeds) else math.inf
        return low, high

    def near(self, speed_rpm) -> tuple:
        """The criticals this speed of the sweep stands for (a resonance marked): those nearer
        to it than to any other speed of the sweep."""
        low, high = self._window(speed_rpm)
        return tuple(c for c in self.criticals if low <= c.speed_rpm < high)

    def peak(self) -> Peak:
        """The largest vibratory torque over all sections and speeds, with the order of the
        largest amplitude there and the mode whose critical of that order is nearest, if
        within 10 % of that speed (damping moves a resonance's peak off its undamped
        critical, a damper's by several per cent). What :meth:`filtered` kept does not
        matter: the peak is what it is."""
        i, s = np.unravel_index(int(np.argmax(self.torque_nm)), self.torque_nm.shape)
        o = int(np.argmax(self.order_torque_nm[i, s]))
        order, speed = float(self.orders[o]), float(self.speeds_rpm[i])
        at = {m.number: rad_s_to_rpm(2 * math.pi * m.frequency_hz / order) for m in self.modes}
        nearest = min(at, key=lambda m: abs(at[m] - speed))
        mode = nearest if abs(at[nearest] - speed) <= _PEAK_BAND * speed else None
        return Peak(
            self.sections[s],
            float(self.torque_nm[i, s]),
            speed,
            order,
            mode,
            None if mode is None else float(at[mode]),
            order in self.major_orders,
        )

    def filtered(self, criticals="excited", orders=None, modes=None) -> "TorsionResult":
        """This result with only the criticals chosen (the modes, sums and response are kept
        whole): ``criticals`` "excited" (those the cylinders excite: the phase-vector sum is
        not zero), "major" (excited, of a major order) or "all" (the not excited ones too,
        flagged); ``orders`` (a list of orders applied) and ``modes`` (mode numbers) keep
        those only.

        Raises
        ------
        AnalysisError
            an unknown kind, an order not applied, a mode the line does not have
        """
        if criticals not in CRITICAL_KINDS:
            raise AnalysisError(
                f"must be one of {', '.join(CRITICAL_KINDS)}, got {criticals!r}", "criticals"
            )
        chosen_orders = None if orders is None else self._orders_of(orders)
        chosen_modes = None if modes is None else self._modes_of(modes)
        kept = tuple(
            c
            for c in self.criticals
            if (criticals == "all" or c.excited)
            and (criticals != "major" or c.major)
            and (chosen_orders is None or c.order in chosen_orders)
            and (chosen_modes is None or c.mode in chosen_modes)
        )
        selection = {
            "kind": criticals,
            "orders": None if chosen_orders is None else sorted(chosen_orders),
            "modes": None if chosen_modes is None else sorted(chosen_modes),
        }
        return dataclasses.replace(self, criticals=kept, selection=selection)

    def _orders_of(self, orders):
        values = [orders] if is_real(orders) else orders
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise AnalysisError(f"must be a list of orders, got {orders!r}", "orders")
        applied = {float(k) for k in self.orders}
        step = "½" if self.engine.cycle == 4 else "1"
        out = set()
        for k in values:
            if not is_real(k) or float(k) not in applied:
                raise AnalysisError(
                    f"has {k!r}, which is not an order of the excitation: the orders are "
                    f"{self.orders.min():g} to {self.orders.max():g} in steps of {step}",
                    "orders",
                )
            out.add(float(k))
        if not out:
            raise AnalysisError("must list one order or more", "orders")
        return out

    def _modes_of(self, modes):
        values = [modes] if is_real(modes) else modes
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise AnalysisError(f"must be a list of mode numbers, got {modes!r}", "modes")
        out = set()
        for m in values:
            if not is_real(m) or m != int(m) or not 1 <= m <= len(self.modes):
                raise AnalysisError(
                    f"has {m!r}: {self.engine.name!r} has modes 1 to {len(self.modes)}",
                    "modes",
                )
            out.add(int(m))
        if not out:
            raise AnalysisError("must list one mode or more", "modes")
        return out

    def largest(self):
        """Per section: (name, largest torque N·m, at speed rpm, stress Pa or None)."""
        out = []
        for s, name in enumerate(self.sections):
            i = int(np.argmax(self.torque_nm[:, s]))
            out.append(
                (
                    name,
                    float(self.torque_nm[i, s]),
                    float(self.speeds_rpm[i]),
                    None if self.stress_pa is None else float(self.stress_pa[i, s]),
                )
            )
        return out

    def records(self) -> list:
        """One row per critical kept, by speed: ``engine``, ``mode``, ``frequency_Hz`` (the
        mode's), ``order``, ``speed_rpm``, ``phase_vector_sum``, ``major``, ``excited``."""
        hz = {m.number: m.frequency_hz for m in self.modes}
        return [
            {"engine": self.engine.name, "mode": c.mode, "frequency_Hz": hz[c.mode]}
            | {k: v for k, v in c.to_dict().items() if k != "mode"}
            for c in self.criticals
        ]

    def to_dict(self) -> dict:
        """This engine's entry of ``torsion --format json`` (SI units; see the JSON page)."""
        engine = self.engine
        return {
            "name": engine.name,
            "config": engine.config_path,
            "cycle": engine.cycle,
            "excitation": "gas and inertia" if self.with_gas else "inertia",
            "nodes": [
                {"node": n, "inertia_kgm2": float(j)}
                for n, j in zip(self.nodes, self.inertia_kgm2, strict=True)
            ],
            "sections": [
                {"section": n, "stiffness_Nm_per_rad": float(k)}
                for n, k in zip(self.sections, self.stiffness_nm_rad, strict=True)
            ],
            "modes": [m.to_dict(self.nodes) for m in self.modes],
            "criticals": [c.to_dict() for c in self.criticals],
            "criticals_chosen": self.selection or {"kind": "all", "orders": None, "modes": None},
            "peak": self.peak().to_dict(),
            "largest": [
                {"section": n, "torque_Nm": t, "speed_rpm": v, "stress_Pa": s}
                for n, t, v, s in self.largest()
            ],
            "response": [
                {
                    "speed_rpm": float(v),
                    "criticals": [{"mode": c.mode, "order": c.order} for c in self.near(v)],
                    "free_end_deg": float(self.free_end_deg[i]),
                    "free_end_elastic_deg": (
                        None
                        if self.free_end_elastic_deg is None
                        else float(self.free_end_elastic_deg[i])
                    ),
                    "free_end_orders": (
                        []
                        if self.free_end_order_deg is None
                        else [
                            {
                                "order": float(k),
                                "amplitude_deg": float(self.free_end_order_deg[i, o]),
                                "elastic_deg": (
                                    None
                                    if self.free_end_elastic_order_deg is None
                                    else float(self.free_end_elastic_order_deg[i, o])
                                ),
                            }
                            for o, k in enumerate(self.orders)
                        ]
                    ),
                    "sections": [
                        {
                            "section": name,
                            "torque_Nm": float(self.torque_nm[i, s]),
                            "stress_Pa": (
                                None if self.stress_pa is None else float(self.stress_pa[i, s])
                            ),
                            "orders": [
                                {
                                    "order": float(k),
                                    "torque_Nm": float(self.order_torque_nm[i, s, o]),
                                }
                                for o, k in enumerate(self.orders)
                            ],
                        }
                        for s, name in enumerate(self.sections)
                    ],
                }
                for i, v in enumerate(self.speeds_rpm)
            ],
        }


def default_speeds_rpm(engine) -> np.ndarray:
    """The speeds a sweep takes unless told: 20 % to 120 % of the engine's own speed, 201 of
    them, rpm (a fixed range would miss a motorcycle's running range and put a marine
    engine's far above it)."""
    rpm = rad_s_to_rpm(engine.speed_rad_s)
    low, high = DEFAULT_SPEED_RANGE
    return np.linspace(low * rpm, high * rpm, DEFAULT_SPEED_COUNT)


def _speeds(speeds_rpm) -> np.ndarray:
    """``speeds_rpm`` as a checked array: a number or a flat list of numbers (not bools)."""
    if is_real(speeds_rpm):
        speeds = np.array([float(speeds_rpm)])
    elif isinstance(speeds_rpm, (list, tuple)) and not all(is_real(v) for v in speeds_rpm):
        # np.asarray([True, 1000]) would be [1, 1000]: each value is looked at
        bad = next(v for v in speeds_rpm if not is_real(v))
        raise AnalysisError(f"must be speeds in rpm, got {bad!r} among them", "speeds_rpm")
    elif np.ndim(speeds_rpm):
        speeds = curve(speeds_rpm, "speeds_rpm")
    else:
        raise AnalysisError(f"must be speeds in rpm, got {speeds_rpm!r}", "speeds_rpm")
    low_limit, high_limit = _SPEED_LIMITS_RPM
    if (
        speeds.size == 0
        or speeds.size > MAX_SPEEDS
        or np.any(speeds < low_limit)
        or np.any(speeds > high_limit)
    ):
        raise AnalysisError(
            f"must be 1 to {MAX_SPEEDS} speeds from {low_limit:g} to "
            f"{high_limit:g} rpm, got {speeds.size} from {np.min(speeds):g} to "
            f"{np.max(speeds):g}"
            if speeds.size
            else "must be one or more speeds, rpm",
            "speeds_rpm",
        )
    return speeds


def torsional_vibration(
    engine,
    speeds_rpm=None,
    max_order=DEFAULT_MAX_ORDER,
    samples=DEFAULT_SAMPLES,
    pressure=None,
    bore_m=None,
) -> TorsionResult:
    """Modes, phase-vector sums, criticals and forced response of ``engine``'s [torsion]
    model over ``speeds_rpm`` (rpm; default :func:`default_speeds_rpm`), for orders up to
    ``max_order`` (½ orders too for a four-stroke). Every critical in the speed range is
    listed, those the cylinders cannot excite flagged (:meth:`TorsionResult.filtered`
    chooses among them).

    Raises
    ------
    TorsionUnavailable
        openTorsion is not installed
    AnalysisError
        no [torsion] table, a rotary, several crankshafts, bad speeds; a speed that puts an
        order on the natural frequency of a mode nothing damps and the excitation drives
        (``speeds_rpm``: the response there is infinite)
    """
    require_opentorsion()
    if speeds_rpm is None:
        torsion_model(engine)
        speeds_rpm = default_speeds_rpm(engine)
    speeds = _speeds(speeds_rpm)
    line = shaft_line(engine, samples)
    assembly = assembly_of(line)
    omega_n, vectors = natural_frequencies(assembly)
    if not omega_n.size:
        raise AnalysisError(
            "has no elastic mode: the shaft line's inertias and stiffnesses are "
            "too far apart for the eigen-solver (every frequency came out as a "
            "rigid-body turning); check the [torsion] values",
            "engine",
        )
    model = engine.torsion
    orders, gas, inertia = excitation(engine, samples, max_order, pressure, bore_m)
    modes, criticals, major_orders = modes_and_criticals(
        omega_n,
        vectors,
        line.throw_nodes,
        firing_angles(engine),
        [(c.number, c.throw_index) for c in engine.cylinders],
        orders,
        (speeds.min(), speeds.max()),
    )
    forced = forced_response(
        engine,
        assembly,
        line,
        model.loss_factor,
        orders,
        gas,
        inertia,
        speeds,
        [(m.number, w, m.shape) for m, w in zip(modes, omega_n, strict=True)],
    )
    stress = None
    if model.shaft_diameter_m is not None:
        d, b = model.shaft_diameter_m, model.shaft_bore_m
        # τ = T·r/J_p with r = D/2 and J_p = π·(D⁴ − d⁴)/32
        stress = forced.torque_nm * (d / 2) / (math.pi * (d**4 - b**4) / 32)
    sections = tuple(f"{a}–{b}" for a, b in zip(line.names, line.names[1:], strict=False))
    return TorsionResult(
        engine,
        line.names,
        sections,
        line.inertia,
        line.stiffness,
        modes,
        criticals,
        orders,
        speeds,
        forced.order_torque_nm,
        forced.torque_nm,
        forced.free_end_deg,
        stress,
        bool(np.any(gas)),
        forced.free_end_order_deg,
        forced.elastic_deg,
        forced.elastic_order_deg,
        major_orders,
    )


def first_mode_amplitudes(engine, samples=DEFAULT_SAMPLES) -> np.ndarray:
    """The first natural mode's relative amplitude at each throw, as :func:`torsional_vibration`
    reports it (the mode's largest amplitude +1, amplitudes below MODE_FLOOR of it zero); it
    depends on the shaft line only, not on the throws' phases (the search's ``V`` terms turn
    it with each crank)."""
    require_opentorsion()
    line = shaft_line(engine, samples)
    _, vectors = natural_frequencies(assembly_of(line))
    return normalised(vectors[:, 0])[list(line.throw_nodes)]
