"""The engine's side of torsional vibration: each throw's excitation order by order, from
every cylinder's exact tangential torque at its firing phase, and phase-vector sums."""

import numpy as np

from ..analysis.cylinders import cylinder_torques
from ..checks import curve, is_real
from ..errors import AnalysisError

__all__ = ["excitation", "phase_vector_sum"]


def excitation(engine, samples, max_order, pressure, bore_m):
    """Per throw and order, the gas and inertia parts' complex amplitudes U (N·m; the torque
    is Re(U·e^{ikθ}) = cos_k·cos kθ + sin_k·sin kθ, so U = cos_k − i·sin_k), with the orders:
    (orders, gas, inertia)."""
    cylinders = cylinder_torques(engine, samples, max_order, pressure, bore_m)
    orders = cylinders.orders
    n = len(engine.throws)
    gas = np.zeros((n, len(orders)), dtype=complex)
    inertia = np.zeros((n, len(orders)), dtype=complex)
    for c in cylinders:
        inertia[c.throw - 1] += [cos - 1j * sin for _, cos, sin in c.inertia.orders]
        if c.gas is not None:
            gas[c.throw - 1] += [cos - 1j * sin for _, cos, sin in c.gas.orders]
    return orders, gas, inertia


def phase_vector_sum(amplitudes, firing_deg, order) -> complex:
    """Σ_c β_c·e^{ik·φ_c}: the phase-vector sum of order ``order`` (k) for cylinders firing at
    crank angles ``firing_deg`` (φ_c, degrees) whose throws move with relative amplitudes
    ``amplitudes`` (β_c) in a mode.

    Raises
    ------
    AnalysisError
        amplitudes or angles that are not finite numbers, lists of unequal lengths, an order
        that is not a finite number
    """
    beta = curve(amplitudes, "amplitudes")
    phi = np.radians(curve(firing_deg, "firing_deg"))
    if len(beta) != len(phi):
        raise AnalysisError(
            f"must give one angle per amplitude: {len(phi)} angles for {len(beta)} amplitudes",
            "firing_deg",
        )
    if not is_real(order) or not np.isfinite(order):
        raise AnalysisError(f"must be a finite number, got {order!r}", "order")
    return complex(np.sum(beta * np.exp(1j * order * phi)))
