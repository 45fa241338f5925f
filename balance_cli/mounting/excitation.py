"""What shakes the engine on its mounts, order by order: the shaking forces and free moments
(balance's exact harmonic analysis) and the frame torque's orders (the roll), as six-component
wrenches at the centre of gravity.

In engine axes (:mod:`balance_cli.model.mounts`) with the crank turning about spin·x: an order's
vertical force A and horizontal force B (:func:`balance_cli.analysis.shaking.directional`, each
component Re(A·e^{ikθ})) act at the crank axis's reference point P as F = A·z + B·h, h = −spin·y
the horizontal; the free moment's vertical part (the moment of the vertical forces, pitching)
is about y and its horizontal part (yawing) about spin·z, because balance's axial z grows
towards the back (x = z̄ − z): a force f at axial position z lies at r = −(z − z̄)·x, and
r × (A·z + B·h) = (z − z̄)·A·y + spin·(z − z̄)·B·z. The frame torque T (positive with rotation)
is the couple spin·T·x. Moved to the centre of gravity G, the moment gains (P − G) × F.
"""

from dataclasses import dataclass

import numpy as np

from ..analysis.shaking import directional, shaking_forces
from ..analysis.torque import torque

__all__ = ["Excitation", "order_wrenches"]


@dataclass(frozen=True)
class Excitation:
    """The wrenches at the centre of gravity, order by order, as complex amplitudes (each
    component Re(W·e^{ikθ}), θ the crank angle): forces N, moments N·m, in the order
    (Fx, Fy, Fz, Mx, My, Mz).

    Attributes
    ----------
    orders : ndarray
        the orders, multiples of ½ for a four-stroke
    speed_rad_s : float
        the engine's own speed ω₀, at which ``inertial`` holds, rad/s
    inertial : ndarray, complex, shape (orders, 6)
        the moving parts' share at ω₀: it grows as the square of the speed
    gas : ndarray, complex, shape (orders, 6)
        the gas torque's share (roll only), the same at every speed
    mean_gas_nm : float or None
        the gas torque's mean at ω₀ (None without a gas cycle), N·m
    """

    orders: np.ndarray
    speed_rad_s: float
    inertial: np.ndarray
    gas: np.ndarray
    mean_gas_nm: float | None

    def at(self, speeds_rad_s) -> np.ndarray:
        """The wrenches at engine speeds Ω (rad/s): shape (speeds, orders, 6)."""
        scale = (np.asarray(speeds_rad_s, dtype=float) / self.speed_rad_s) ** 2
        return scale[:, None, None] * self.inertial[None] + self.gas[None]


def _cleaned(value, floor):
    # rounding noise of an exact cancellation (a vertical force's horizontal part, a couple
    # that cancels) as an exact zero: resonances it cannot drive are then told apart from
    # those it drives
    return complex(value) if abs(value) >= floor else 0j


def order_wrenches(engine, system, orders, samples) -> Excitation:
    """The wrenches of ``engine`` on its mount ``system`` for ``orders`` (a sorted array of
    multiples of ½ or whole numbers), from its shaking forces and its torques at its own
    speed, ``samples`` crank angles a revolution."""
    omega = engine.speed_rad_s
    top = int(np.ceil(orders.max()))
    whole = [k for k in orders if float(k).is_integer()]
    shaking = shaking_forces(engine, samples, max(int(max(whole, default=1)), 1))
    torques = torque(engine, samples, top, bearings=False, guide=False)
    spin = float(system.spin)
    horizontal = system.horizontal
    lever = -np.array(system.cg_m)  # from the centre of gravity to P
    vertical = engine.vertical_axis_rad
    inertial = np.zeros((len(orders), 6), dtype=complex)
    gas = np.zeros((len(orders), 6), dtype=complex)
    frame_of = {k: complex(c, -s) for k, c, s in torques.frame.orders}
    gas_of = (
        {}
        if torques.gas is None
        else {k: -complex(c, -s) for k, c, s in torques.gas.orders}  # the frame's share: −gas
    )
    for o, k in enumerate(orders):
        roll_gas = gas_of.get(float(k), 0j)
        # the frame couple less its gas share: the inertia and tilting couples, ∝ Ω²
        roll = frame_of.get(float(k), 0j) - roll_gas
        force = np.zeros(3, dtype=complex)
        moment = np.array([spin * roll, 0j, 0j])
        if float(k).is_integer():
            part = shaking.order(int(k))
            floor_n, floor_nm = engine.noise_floor_n, engine.noise_floor_nm
            a_f, b_f = (
                _cleaned(c, floor_n)
                for c in directional(part.force_forward, part.force_backward, vertical)
            )
            a_m, b_m = (
                _cleaned(c, floor_nm)
                for c in directional(part.moment_forward, part.moment_backward, vertical)
            )
            force = a_f * np.array([0.0, 0.0, 1.0]) + b_f * horizontal
            moment = moment + np.array([0j, a_m, spin * b_m])
        inertial[o, :3] = force
        inertial[o, 3:] = moment + np.cross(lever, force)
        gas[o, 3] = spin * roll_gas
    return Excitation(
        orders,
        omega,
        inertial,
        gas,
        None if torques.gas is None else torques.gas.mean,
    )
