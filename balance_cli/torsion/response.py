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
a section's vibratory torque is k·(Q_left − Q_right).
"""

import math
from dataclasses import dataclass

import numpy as np

from ..analysis.firing import firing_angles
from ..analysis.shaking import DEFAULT_SAMPLES
from ..errors import AnalysisError
from ..model import Engine
from ..units import rad_s_to_rpm
from .adapter import assembly_of, natural_frequencies, require_opentorsion
from .excitation import excitation, phase_vector_sum
from .line import shaft_line, torsion_model

__all__ = [
    "Mode",
    "Critical",
    "TorsionResult",
    "torsional_vibration",
    "first_mode_amplitudes",
    "default_speeds_rpm",
    "DEFAULT_MAX_ORDER",
    "MAX_SPEEDS",
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
#: a phase-vector sum within this fraction of the cylinders' number is a major order
_MAJOR = 1e-6


@dataclass(frozen=True)
class Mode:
    """One natural mode: its frequency, its shape over the shaft line (largest throw amplitude
    +1) and its phase-vector sums by order."""

    number: int
    frequency_hz: float
    shape: np.ndarray  # per node
    throw_amplitudes: np.ndarray
    phase_vector_sums: dict  # order -> |Σ β e^{ikφ}|

    def to_dict(self, names) -> dict:
        return {
            "mode": self.number,
            "frequency_Hz": self.frequency_hz,
            "frequency_cpm": 60.0 * self.frequency_hz,
            "shape": [
                {"node": name, "amplitude": float(a)}
                for name, a in zip(names, self.shape, strict=True)
            ],
            "throw_amplitudes": [float(a) for a in self.throw_amplitudes],
            "phase_vector_sums": [
                {"order": k, "sum": v} for k, v in self.phase_vector_sums.items()
            ],
        }


@dataclass(frozen=True)
class Critical:
    """A mode's resonance with an order: at ``speed_rpm`` the order's frequency k·n equals
    the mode's."""

    mode: int
    order: float
    speed_rpm: float
    phase_vector_sum: float
    major: bool

    def to_dict(self) -> dict:
        return {
            "mode": self.mode,
            "order": self.order,
            "speed_rpm": self.speed_rpm,
            "phase_vector_sum": self.phase_vector_sum,
            "major": self.major,
        }


@dataclass(frozen=True)
class TorsionResult:
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
        the synthesised waveform's peak |T| over the cycle, N·m, by speed × section
    free_end_deg : ndarray
        the free end's angular amplitude (peak of the synthesised waveform), degrees, by speed
    stress_pa : ndarray or None
        torque_nm as shear stress τ = T·r/J_p, Pa, with the [torsion] shaft diameter
    with_gas : bool
        whether the excitation has a gas torque ([gas] table or a pressure curve), or the
        inertia torque alone
    free_end_order_deg : ndarray or None
        the free end's amplitude of each order, degrees, by speed × order
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

    def near(self, speed_rpm) -> tuple:
        """The criticals this speed of the sweep stands for (a resonance marked): those nearer
        to it than to any other speed of the sweep."""
        speeds = np.sort(self.speeds_rpm)
        i = int(np.searchsorted(speeds, speed_rpm))
        low = (speeds[i - 1] + speed_rpm) / 2 if i > 0 else -math.inf
        high = (speeds[i + 1] + speed_rpm) / 2 if i + 1 < len(speeds) else math.inf
        return tuple(c for c in self.criticals if low <= c.speed_rpm < high)

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

    def to_dict(self) -> dict:
        """This engine's entry of ``torsion --format json`` (SI units; see the README)."""
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
            "largest": [
                {"section": n, "torque_Nm": t, "speed_rpm": v, "stress_Pa": s}
                for n, t, v, s in self.largest()
            ],
            "response": [
                {
                    "speed_rpm": float(v),
                    "criticals": [{"mode": c.mode, "order": c.order} for c in self.near(v)],
                    "free_end_deg": float(self.free_end_deg[i]),
                    "free_end_orders": (
                        []
                        if self.free_end_order_deg is None
                        else [
                            {
                                "order": float(k),
                                "amplitude_deg": float(self.free_end_order_deg[i, o]),
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
    ``max_order`` (½ orders too for a four-stroke).

    Raises
    ------
    TorsionUnavailable
        openTorsion is not installed
    AnalysisError
        no [torsion] table, a rotary, several crankshafts, bad speeds
    """
    require_opentorsion()
    if speeds_rpm is None:
        torsion_model(engine)
        speeds_rpm = default_speeds_rpm(engine)
    try:
        if isinstance(speeds_rpm, (bool, str, bytes)) or np.ndim(speeds_rpm) > 1:
            raise TypeError
        speeds = np.asarray(speeds_rpm, dtype=float).ravel()
    except (TypeError, ValueError):
        raise AnalysisError(f"must be speeds in rpm, got {speeds_rpm!r}", "speeds_rpm") from None
    low_limit, high_limit = _SPEED_LIMITS_RPM
    if (
        speeds.size == 0
        or speeds.size > MAX_SPEEDS
        or not np.all(np.isfinite(speeds))
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
    throw_nodes = list(line.throw_nodes)
    model = engine.torsion

    fire = firing_angles(engine)
    numbers = [c.number for c in engine.cylinders]
    throw_of = [c.throw_index for c in engine.cylinders]
    orders, gas, inertia = excitation(engine, samples, max_order, pressure, bore_m)
    n_cyl = len(numbers)
    major = {
        float(k): abs(abs(phase_vector_sum(np.ones(n_cyl), [fire[m] for m in numbers], k)) - n_cyl)
        < _MAJOR * n_cyl
        for k in orders
    }
    modes, criticals = [], []
    low, high = speeds.min(), speeds.max()
    for i, (w, shape) in enumerate(zip(omega_n, vectors.T, strict=True), 1):
        at_throws = shape[throw_nodes]
        biggest = int(np.argmax(np.abs(at_throws)))
        scale = at_throws[biggest] if at_throws[biggest] else shape[np.argmax(np.abs(shape))]
        shape = shape / scale
        beta = shape[throw_nodes]
        sums = {
            float(k): abs(
                phase_vector_sum([beta[t] for t in throw_of], [fire[m] for m in numbers], k)
            )
            for k in orders
        }
        modes.append(Mode(i, w / (2 * math.pi), shape, beta, sums))
        for k in orders:
            rpm = rad_s_to_rpm(w / k)
            if low <= rpm <= high:
                criticals.append(Critical(i, float(k), rpm, sums[float(k)], major[float(k)]))
    criticals.sort(key=lambda c: c.speed_rpm)

    order_torque, peak, free_end, free_orders = _response(
        engine, assembly, line, model.loss_factor, orders, gas, inertia, speeds
    )
    stress = None
    if model.shaft_diameter_m is not None:
        d, b = model.shaft_diameter_m, model.shaft_bore_m
        # τ = T·r/J_p with r = D/2 and J_p = π·(D⁴ − d⁴)/32
        stress = peak * (d / 2) / (math.pi * (d**4 - b**4) / 32)
    sections = tuple(f"{a}–{b}" for a, b in zip(line.names, line.names[1:], strict=False))
    return TorsionResult(
        engine,
        line.names,
        sections,
        line.inertia,
        line.stiffness,
        tuple(modes),
        tuple(criticals),
        orders,
        speeds,
        order_torque,
        peak,
        free_end,
        stress,
        bool(np.any(gas)),
        free_orders,
    )


def _response(engine, assembly, line, loss_factor, orders, gas, inertia, speeds):
    """Vibratory torque amplitudes by speed × section × order, the synthesised peaks by speed ×
    section, and the free end's peak angle (degrees) by speed."""
    omega0 = engine.speed_rad_s
    omega = speeds * 2 * math.pi / 60.0
    n_nodes, n_orders = len(line.inertia), len(orders)
    # every (speed, order) is one frequency: one call to openTorsion solves them all
    u = np.zeros((n_nodes, len(speeds), n_orders), dtype=complex)
    ratio = (omega / omega0) ** 2
    for j, node in enumerate(line.throw_nodes):
        u[node] = gas[j][None, :] + ratio[:, None] * inertia[j][None, :]
    frequencies = (omega[:, None] * orders[None, :]).ravel()
    base = assembly.C
    k_sections = assembly.K
    c_func = None
    if loss_factor:

        def c_func(w):
            # relative damping: each section's c = loss_factor·k/Ω
            return base + loss_factor / w * k_sections

    q, _ = assembly.ss_response(u.reshape(n_nodes, -1), frequencies, C=base, C_func=c_func)
    q = q.reshape(n_nodes, len(speeds), n_orders)
    # a section's torque k·(θ_left − θ_right)
    twist = q[:-1] - q[1:]
    torques = line.stiffness[:, None, None] * twist  # section × speed × order
    amplitude = np.abs(torques).transpose(1, 0, 2)
    per_turn = engine.cycle_deg / 360.0
    # the waveform over one cycle, sampled finely enough for the highest order
    theta = np.linspace(
        0, 2 * math.pi * per_turn, int(32 * orders.max() * per_turn) + 1, endpoint=False
    )
    phase = orders[:, None] * theta[None, :]  # order × angle
    cos, sin = np.cos(phase), np.sin(phase)

    def wave_peak(values):
        # max over θ of |Re Σ_k V_k·e^{ikθ}|
        return np.abs(values.real @ cos - values.imag @ sin).max(axis=-1)

    peak = wave_peak(torques).T  # speed × section
    free = np.degrees(wave_peak(q[0]))
    return amplitude, peak, free, np.degrees(np.abs(q[0]))


def first_mode_amplitudes(engine, samples=DEFAULT_SAMPLES) -> np.ndarray:
    """The first natural mode's relative amplitude at each throw (the largest +1), as
    :func:`torsion` reports it; it depends on the shaft line only, not on the throws' phases
    (the search's ``V`` terms turn it with each crank)."""
    require_opentorsion()
    line = shaft_line(engine, samples)
    _, vectors = natural_frequencies(assembly_of(line))
    beta = vectors[list(line.throw_nodes), 0]
    return beta / beta[int(np.argmax(np.abs(beta)))]
