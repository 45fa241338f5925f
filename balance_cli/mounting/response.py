"""The forced response of the engine on its mounts: every order at every speed in one batched
complex solve, each mount's transmitted force, and the orders summed over a cycle.

At engine speed Ω an order k drives at ω = k·Ω; the steady response to the wrench Re(W·e^{iωt})
is Re(q·e^{iωt}) with (K·(1 + iη) + iω·C − ω²·M)·q = W (the loss factors per mount: the
hysteretic part is Σ ηᵢ·Tᵢᵀ·Kᵢ·Tᵢ). Mount i deflects by uᵢ = Tᵢ·q and passes on to the frame
fᵢ = (Kᵢ·(1 + iηᵢ) + iω·Cᵢ)·uᵢ.
"""

import math
from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..units import rad_s_to_rpm

__all__ = [
    "Response",
    "forced_response",
    "modal_forces",
    "exciting",
    "check_resonances",
    "EXCITED_FLOOR",
]

#: a modal force below this fraction of the sum of its terms' sizes is a cancellation to
#: rounding: the order cannot drive the mode
EXCITED_FLOOR = 1e-9
#: samples per period of the highest order when the orders are summed over a cycle: the peak
#: of a sampled cosine is then within 1 − cos(π/32) = 0.5 % of the true one
_PER_PERIOD = 32
#: speeds summed over a cycle at a time (their waveforms held in memory together)
_CHUNK = 128


@dataclass(frozen=True)
class Response:
    """Complex amplitudes by speed × order (each quantity Re(X·e^{ikθ})), and the peaks of the
    orders summed over a cycle, by speed.

    Attributes
    ----------
    motion : ndarray, complex, shape (speeds, orders, 6)
        the centre of gravity's translations (m) and the rotations (rad)
    deflection_m : ndarray, complex, shape (speeds, orders, mounts, 3)
    force_n : ndarray, complex, shape (speeds, orders, mounts, 3)
        what each mount passes on to the frame, engine axes, N
    motion_peak : ndarray, shape (speeds, 6)
    deflection_peak_m, force_peak_n : ndarray, shape (speeds, mounts, 3)
        the largest |component| over a cycle
    force_magnitude_peak_n : ndarray, shape (speeds, mounts)
        the largest size of the force vector over a cycle, N
    """

    motion: np.ndarray
    deflection_m: np.ndarray
    force_n: np.ndarray
    motion_peak: np.ndarray
    deflection_peak_m: np.ndarray
    force_peak_n: np.ndarray
    force_magnitude_peak_n: np.ndarray


def modal_forces(modes, wrenches) -> tuple:
    """φᵀ·W of every mode for wrenches (..., 6), and the sums Σ|φ_j·W_j| they are measured
    against: two arrays (..., modes)."""
    shapes = np.array([m.shape for m in modes])  # (modes, 6)
    terms = wrenches[..., None, :] * shapes
    return terms.sum(axis=-1), np.abs(terms).sum(axis=-1)


def exciting(modes, wrenches) -> np.ndarray:
    """Whether each wrench (..., 6) drives each mode (..., modes): its modal force is more than
    rounding of its terms."""
    force, scale = modal_forces(modes, wrenches)
    return np.abs(force) > EXCITED_FLOOR * scale


def check_resonances(system, modes, orders, speeds_rad_s, wrenches):
    """Refuse a speed that puts a driven order exactly on an undamped mode: the response
    there is infinite.

    Raises
    ------
    AnalysisError
        (``speeds_rpm``) naming the speed, the order and the mode
    """
    shapes = np.array([m.shape for m in modes])
    damping = system.loss_matrix() + system.damping_matrix()
    undamped = np.einsum("rj,jk,rk->r", shapes, damping, shapes) <= 0.0
    if not undamped.any():
        return
    omega = orders[None, :] * speeds_rad_s[:, None]  # (speeds, orders)
    natural = np.array([m.omega_rad_s for m in modes])
    hits = np.abs(omega[..., None] / natural - 1.0) < 1e-9
    hits &= undamped & exciting(modes, wrenches)
    if hits.any():
        s, o, r = (int(i) for i in np.argwhere(hits)[0])
        mode = modes[r]
        raise AnalysisError(
            f"has {rad_s_to_rpm(speeds_rad_s[s]):g} rpm, which puts order {orders[o]:g} on "
            f"mode {mode.number} ({mode.motion}, {mode.frequency_hz:.6g} Hz), which nothing "
            "damps: the response there is infinite; give the mounts damping (loss_factor or "
            "damping) or leave that speed out",
            "speeds_rpm",
        )


def _waves(amplitudes, orders, turns):
    """Re(Σ_k X_k·e^{ikθ}) over a cycle of ``turns`` revolutions for amplitudes (speeds,
    orders, ...), a block of speeds at a time: yields (first speed, waves (block, ..., angles))."""
    count = max(64, _PER_PERIOD * math.ceil(float(orders.max()) * turns))
    theta = 2.0 * math.pi * turns * np.arange(count) / count
    phasors = np.exp(1j * np.outer(orders, theta))  # (orders, angles)
    shape = amplitudes.shape
    # (speeds, channels, orders) @ (orders, angles): one matrix product a block
    flat = np.moveaxis(amplitudes.reshape(shape[0], shape[1], -1), 1, 2)
    for start in range(0, shape[0], _CHUNK):
        block = flat[start : start + _CHUNK]
        wave = (block.real @ phasors.real) - (block.imag @ phasors.imag)
        yield start, wave.reshape((len(block),) + shape[2:] + (count,))


def _peaks(amplitudes, orders, turns):
    """The largest |component| over a cycle, for amplitudes (speeds, orders, ...)."""
    out = np.empty((amplitudes.shape[0],) + amplitudes.shape[2:])
    for start, wave in _waves(amplitudes, orders, turns):
        out[start : start + len(wave)] = np.abs(wave).max(axis=-1)
    return out


def _magnitude_peaks(forces, orders, turns):
    """The largest size of each mount's force vector over a cycle: (speeds, mounts)."""
    out = np.empty(forces.shape[:1] + forces.shape[2:3])
    for start, wave in _waves(forces, orders, turns):
        out[start : start + len(wave)] = np.sqrt((wave**2).sum(axis=-2)).max(axis=-1)
    return out


def forced_response(system, orders, speeds_rad_s, wrenches, turns) -> Response:
    """The response of ``system`` to ``wrenches`` (speeds, orders, 6) of ``orders`` at
    ``speeds_rad_s``, summed over a cycle of ``turns`` revolutions (2 for a four-stroke)."""
    stiffness = system.stiffness_matrix() + 1j * system.loss_matrix()
    damping, mass = system.damping_matrix(), system.mass_matrix()
    omega = orders[None, :] * speeds_rad_s[:, None]  # (speeds, orders)
    dynamic = (
        stiffness[None, None]
        + 1j * omega[..., None, None] * damping[None, None]
        - (omega**2)[..., None, None] * mass[None, None]
    )
    motion = np.linalg.solve(dynamic, wrenches[..., None])[..., 0]
    transfer = np.array([m.transfer() for m in system.mounts])  # (mounts, 3, 6)
    # (mounts, 3, 6) @ (speeds, orders, 1, 6, 1): each mount's deflection
    deflection = (transfer @ motion[:, :, None, :, None])[..., 0]
    rates = np.array([m.stiffness() * (1.0 + 1j * m.loss_factor) for m in system.mounts])
    viscous = np.array([m.viscous() for m in system.mounts])
    force = (rates @ deflection[..., None])[..., 0] + 1j * omega[..., None, None] * (
        viscous @ deflection[..., None]
    )[..., 0]
    return Response(
        motion,
        deflection,
        force,
        _peaks(motion, orders, turns),
        _peaks(deflection, orders, turns),
        _peaks(force, orders, turns),
        _magnitude_peaks(force, orders, turns),
    )
