"""The steady forced response of the shaft line, order by order and speed by speed, and what
is read from it: each section's vibratory torque, the free end's swing and its elastic part.

Each (speed, order) is one frequency ω = kΩ at which openTorsion solves
(K − ω²·M + iω·C)·Q = U. A mode that nothing damps (no loss factor, and no damper where the
mode moves) makes that matrix singular at its natural frequency: there the response is
infinite if the excitation drives the mode, and it is refused with one line saying so; if the
excitation cannot drive it (every throw at a node, or the cylinders' torques cancelling), the
response is finite and is solved with the mode held out (the limit of a vanishing damping).
"""

import math
from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..tolerances import MODE_FLOOR, RESONANCE_WINDOW
from ..units import rad_s_to_rpm

__all__ = ["ForcedResponse", "forced_response"]

#: a mode whose damping ratio is below this is undamped: the solve at its natural frequency
#: would divide by rounding noise
_UNDAMPED = 1e-12


@dataclass(frozen=True)
class ForcedResponse:
    """Amplitudes by speed (and section, order) of one sweep; angles in degrees, torques N·m."""

    order_torque_nm: np.ndarray  # speed × section × order
    torque_nm: np.ndarray  # speed × section: peak of the synthesised waveform
    free_end_deg: np.ndarray  # speed
    free_end_order_deg: np.ndarray  # speed × order
    elastic_deg: np.ndarray  # speed: the free end's swing less the line's rigid turning
    elastic_order_deg: np.ndarray  # speed × order


def forced_response(engine, assembly, line, loss_factor, orders, gas, inertia, speeds, modes):
    """The response of ``line`` (its openTorsion ``assembly``) to the throws' excitation
    ``gas`` + (Ω/ω₀)²·``inertia`` (throw × order, complex N·m) at ``speeds`` (rpm), with
    ``modes`` the line's (number, ω_n rad/s, shape largest +1) for the undamped check.

    Raises
    ------
    AnalysisError
        (``speeds_rpm``) a speed puts an order on the natural frequency of a mode that nothing
        damps and that the excitation drives: the response there is infinite
    """
    omega0 = engine.speed_rad_s
    omega = speeds * 2 * math.pi / 60.0
    n_nodes, n_orders = len(line.inertia), len(orders)
    u = np.zeros((n_nodes, len(speeds), n_orders), dtype=complex)
    ratio = (omega / omega0) ** 2
    for j, node in enumerate(line.throw_nodes):
        u[node] = gas[j][None, :] + ratio[:, None] * inertia[j][None, :]
    frequencies = (omega[:, None] * orders[None, :]).ravel()
    solved = _solve(
        assembly, loss_factor, u.reshape(n_nodes, -1), frequencies, modes, speeds, orders
    )
    q = solved.reshape(n_nodes, len(speeds), n_orders)

    # a section's torque k·(θ_left − θ_right)
    torques = line.stiffness[:, None, None] * (q[:-1] - q[1:])  # section × speed × order
    # the line's rigid turning is the angle of its centre of inertia, Σ J·θ / Σ J (the
    # rigid-body mode's coordinate): what is left is the elastic twist, the elastic modes' sum
    rigid = np.tensordot(line.inertia, q, axes=1) / line.inertia.sum()
    elastic = q[0] - rigid
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

    return ForcedResponse(
        np.abs(torques).transpose(1, 0, 2),
        wave_peak(torques).T,
        np.degrees(wave_peak(q[0])),
        np.degrees(np.abs(q[0])),
        np.degrees(wave_peak(elastic)),
        np.degrees(np.abs(elastic)),
    )


def _solve(assembly, loss_factor, u, frequencies, modes, speeds, orders):
    """Q (node × frequency) for the excitation columns ``u`` at ``frequencies`` (rad/s)."""
    base, stiffness, mass = assembly.C, assembly.K, assembly.M
    q = np.zeros_like(u)
    held_out = np.zeros(len(frequencies), dtype=bool)
    for number, w_n, shape in modes:
        if loss_factor or _damping_ratio(shape, w_n, base, mass) >= _UNDAMPED:
            continue
        at = np.flatnonzero(np.abs(frequencies - w_n) <= RESONANCE_WINDOW * w_n)
        for i in at:
            # the torque the excitation puts into the mode, against the most it could
            drive = abs(shape @ u[:, i])
            if drive > MODE_FLOOR * np.abs(u[:, i]).sum():
                speed, order = divmod(i, len(orders))
                raise AnalysisError(
                    f"puts order {orders[order]:g} at {speeds[speed]:.6g} rpm on the "
                    f"natural frequency of mode {number} ({w_n / (2 * math.pi):.6g} Hz, "
                    f"critical at {rad_s_to_rpm(w_n / orders[order]):.6g} rpm), and nothing "
                    "damps that mode: the response there is infinite; give the [torsion] "
                    "model damping (loss_factor, throw_damping or a section's damping) or "
                    "leave that speed out",
                    "speeds_rpm",
                )
            q[:, i] = _held_out(stiffness, mass, base, shape, u[:, i], frequencies[i])
            held_out[i] = True
    rest = np.flatnonzero(~held_out)
    if rest.size:
        c_func = None
        if loss_factor:

            def c_func(w):
                # relative damping: each section's c = loss_factor·k/Ω
                return base + loss_factor / w * stiffness

        q[:, rest], _ = assembly.ss_response(u[:, rest], frequencies[rest], C=base, C_func=c_func)
    return q


def _damping_ratio(shape, w_n, damping, mass):
    # ζ = φᵀCφ / (2·ω_n·φᵀMφ): the mode's own damping (C positive semi-definite, so a zero
    # ζ means C·φ = 0 and the mode is uncoupled from every damper)
    return float(shape @ damping @ shape) / (2 * w_n * float(shape @ mass @ shape))


def _held_out(stiffness, mass, damping, shape, u, w):
    """The response at ω to ``u`` with the undamped mode ``shape`` held out: A·Q + M·φ·λ = U,
    φᵀ·M·Q = 0 (A = K − ω²M + iωC). A is singular at the mode's frequency with null vector φ,
    the bordered system is not; as the excitation does not drive the mode (φᵀU = 0), λ = 0
    and Q is the limit of the damped response as the damping vanishes."""
    n = len(u)
    system = np.zeros((n + 1, n + 1), dtype=complex)
    system[:n, :n] = stiffness - w**2 * mass + 1j * w * damping
    system[:n, n] = mass @ shape
    system[n, :n] = shape @ mass
    return np.linalg.solve(system, np.append(u, 0.0))[:n]
