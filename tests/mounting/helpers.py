"""What the mount tests share: the two shipped examples, and a second derivation of the rigid
body's matrices and excitation written apart from the library (no transfer matrices: the
potential energy of the mounts' springs, and the shaking analysis's phasors turned into
engine axes by hand)."""

import numpy as np

import balance_cli as balance
from tests.support import CONFIGS

MOUNTS = CONFIGS / "mounts"
COUPLED = MOUNTS / "four-mount-coupled.toml"
SYMMETRIC = MOUNTS / "four-mount-symmetric.toml"


def mass_matrix(system):
    """diag(m, m, m) and J, written out."""
    out = np.zeros((6, 6))
    out[0, 0] = out[1, 1] = out[2, 2] = system.mass_kg
    out[3:, 3:] = system.inertia_kgm2
    return out


def mount_deflection(mount, q):
    """The mount point's small displacement: the centre of gravity's translation plus the
    rotation's θ × r."""
    return np.asarray(q[:3]) + np.cross(q[3:], mount.position_m)


def stiffness_by_energy(system, step=1e-3):
    """The Hessian of the springs' energy V(q) = ½·Σ uᵢᵀ·Kᵢ·uᵢ by central differences (exact
    for a quadratic V up to rounding), Kᵢ = Σ_j k_j·d_j·d_jᵀ from each mount's rates and
    directions."""

    def energy(q):
        total = 0.0
        for mount in system.mounts:
            u = mount_deflection(mount, q)
            along = np.array(mount.directions) @ u
            total += 0.5 * float(np.sum(np.array(mount.rates_n_m) * along**2))
        return total

    out = np.zeros((6, 6))
    eye = np.eye(6) * step
    for a in range(6):
        for b in range(6):
            out[a, b] = (
                energy(eye[a] + eye[b])
                - energy(eye[a] - eye[b])
                - energy(-eye[a] + eye[b])
                + energy(-eye[a] - eye[b])
            ) / (4 * step * step)
    return out


def hand_wrench(engine, system, order, speed_rpm, samples=256):
    """The wrench at the centre of gravity of order ``order`` at ``speed_rpm``, from balance's
    public results, turned into engine axes by hand for a crank turning clockwise seen from
    the front (about −x): balance's vertical is +z and its horizontal, 90° on with the crank,
    is +y; the front is −z of balance's axial axis, so a force (0, Fy, Fz) at axial z lies at
    x = −(z − z̄) and its moment is (0, (z − z̄)·Fz, −(z − z̄)·Fy): the vertical part of the free
    moment about +y, the horizontal part about −z; the frame torque T (with rotation) is −T
    about x; then moved from the crank axis P to G: M_G = M_P + (P − G) × F."""
    assert system.rotation == "clockwise" and engine.gas is None  # all of it grows as Ω²
    scale = (speed_rpm * np.pi / 30 / engine.speed_rad_s) ** 2
    force = np.zeros(3, dtype=complex)
    moment = np.zeros(3, dtype=complex)
    if float(order).is_integer():
        part = balance.analyse(engine, samples, max_order=int(order)).order(int(order))
        # along the reference axis (vertical, in-line engine) Re(X), across it Im(X):
        # A = X⁺ + conj X⁻ is the vertical amplitude, B = −i·(X⁺ − conj X⁻) the horizontal
        assert engine.vertical_axis_rad == 0.0
        a_f = part.force_forward + np.conj(part.force_backward)
        b_f = -1j * (part.force_forward - np.conj(part.force_backward))
        a_m = part.moment_forward + np.conj(part.moment_backward)
        b_m = -1j * (part.moment_forward - np.conj(part.moment_backward))
        force = np.array([0.0, b_f, a_f])
        moment = np.array([0.0, a_m, -b_m])
    frame = balance.torque(engine, samples, max_order=int(np.ceil(order))).frame
    cos, sin = frame.order(order)
    moment = moment + np.array([-(cos - 1j * sin), 0.0, 0.0])
    lever = -np.array(system.cg_m)
    return scale * np.concatenate([force, moment + np.cross(lever, force)])
