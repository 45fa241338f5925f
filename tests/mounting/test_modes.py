"""The six rigid-body modes: the symmetric example against Harris' closed forms, the coupled one
against a second assembly and solver, and the kinetic-energy distribution."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.mounting import energy_distribution, natural_modes
from tests.mounting.helpers import COUPLED, SYMMETRIC, mass_matrix, stiffness_by_energy

#: eigenvalues of a 6×6 system of well-separated scales: rounding of a few ulps of the largest
EIGEN = 1e-10


def test_symmetric_example_frequencies_are_harris_closed_forms():
    """Four identical mounts at (±a, ±b, 0), a = 0.30 m, b = 0.25 m, rates k_x = k_y = 100 N/mm
    and k_z = 200 N/mm along the engine's axes; m = 150 kg, J = diag(6, 9, 8) kg·m², the
    centre of gravity in the mounts' plane (z = 0) and the principal axes the engine's.

    A mount's deflection is u = X + θ × r, with r = (±a, ±b, 0):
    u_x = X + θ_y·0 − θ_z·y, u_y = Y + θ_z·x − θ_x·0, u_z = Z + θ_x·y − θ_y·x. The energy
    ½·Σ k·u² has cross terms only through Σ x, Σ y (zero: the mounts are symmetric about both
    axes) and Σ x·y (zero too), and none through z (every mount at z = 0): the stiffness
    matrix is diagonal and no motion couples with another (Harris, Shock and Vibration
    Handbook, ch. 3: a mounting with two planes of symmetry through the centre of gravity and
    the mounts in its horizontal plane). Each motion is then a single degree of freedom:

    - fore-aft   f = √(4·k_x/m)/2π                = √(4·1e5/150)/2π           = 8.2187 Hz
    - lateral    f = √(4·k_y/m)/2π                = the same                  = 8.2187 Hz
    - bounce     f = √(4·k_z/m)/2π                = √(4·2e5/150)/2π           = 11.623 Hz
    - roll       f = √(4·k_z·b²/J_xx)/2π          = √(4·2e5·0.0625/6)/2π      = 14.529 Hz
    - pitch      f = √(4·k_z·a²/J_yy)/2π          = √(4·2e5·0.09/9)/2π        = 14.235 Hz
    - yaw        f = √(4·(k_x·b² + k_y·a²)/J_zz)/2π = √(4·(6250 + 9000)/8)/2π  = 13.898 Hz

    Note that the centre of gravity on the crank axis changes nothing here: the modes depend
    on the mass, inertia and mounts only (the crank axis matters to the excitation)."""
    kx = ky = 100e3
    kz = 200e3
    m, jxx, jyy, jzz, a, b = 150.0, 6.0, 9.0, 8.0, 0.30, 0.25

    def f(k, inertia):
        return math.sqrt(k / inertia) / (2 * math.pi)

    by_hand = {
        "fore-aft": f(4 * kx, m),
        "lateral": f(4 * ky, m),
        "bounce": f(4 * kz, m),
        "roll": f(4 * kz * b * b, jxx),
        "pitch": f(4 * kz * a * a, jyy),
        "yaw": f(4 * (kx * b * b + ky * a * a), jzz),
    }
    assert_allclose(
        [by_hand[k] for k in ("fore-aft", "bounce", "yaw", "pitch", "roll")],
        [8.2187, 11.623, 13.898, 14.235, 14.529],
        rtol=5e-5,  # the docstring's figures, printed to 5 digits
    )
    modes = natural_modes(balance.load(SYMMETRIC).mounts)
    found = {}
    for mode in modes:
        # decoupled: all of a mode's energy in one motion
        assert_allclose(mode.purity_pct, 100.0, atol=1e-9)
        found.setdefault(mode.motion, []).append(mode.frequency_hz)
    assert sorted(found) == sorted(by_hand)
    for motion, frequencies in found.items():
        # rounding of the generalised eigen-solver on a diagonal system
        assert_allclose(frequencies, [by_hand[motion]], rtol=EIGEN)


def test_coupled_example_against_a_second_assembly_and_solver():
    """The coupled example's K assembled as the Hessian of the springs' energy (no transfer
    matrices) and its frequencies from numpy's general eigen-solver of M⁻¹·K (not scipy's
    symmetric one): the same six frequencies, and each mode shape satisfies K·φ = ω²·M·φ."""
    system = balance.load(COUPLED).mounts
    stiffness = stiffness_by_energy(system)
    # central differences of a quadratic: exact up to rounding of the energies (≈ 1e-16·V/h²)
    assert_allclose(system.stiffness_matrix(), stiffness, rtol=0, atol=1e-6 * stiffness.max())
    mass = mass_matrix(system)
    values = np.sort(np.linalg.eigvals(np.linalg.solve(mass, stiffness)).real)
    modes = natural_modes(system)
    assert_allclose(
        [m.frequency_hz for m in modes], np.sqrt(values) / (2 * np.pi), rtol=1e-8
    )  # the Hessian's 1e-6 of the largest entry, square-rooted into the frequencies
    for mode in modes:
        phi = mode.shape
        assert_allclose(phi @ mass @ phi, 1.0, rtol=EIGEN)  # mass-normalised
        residual = stiffness @ phi - mode.omega_rad_s**2 * (mass @ phi)
        assert np.abs(residual).max() < 1e-6 * np.abs(stiffness @ phi).max()


def test_coupled_example_modes_are_named_by_their_dominant_motion():
    """Every mode of the coupled example mixes motions (products of inertia, an inclined mount,
    mounts at different heights): none is pure, each is named by its largest share, and the
    shares add up to 100 %. The six names are the six motions, once each, for this example."""
    modes = natural_modes(balance.load(COUPLED).mounts)
    for mode in modes:
        assert_allclose(mode.energy_pct.sum(), 100.0, rtol=1e-12)
        assert 40.0 < mode.purity_pct < 100.0 - 1e-3
        assert mode.motion == balance.model.MOTIONS[int(np.argmax(mode.energy_pct))]
    assert sorted(m.motion for m in modes) == sorted(balance.model.MOTIONS)
    assert [m.frequency_hz for m in modes] == sorted(m.frequency_hz for m in modes)


def test_energy_distribution_of_a_hand_made_shape():
    """φ = (1, 0, 0, 0, 0, 1) on M = diag(2, 2, 2) ⊕ J with J_xx = J_zz = 1 and J_xz = 0.5:
    M·φ = (2, 0, 0, 0.5, 0, 1), φᵀ·M·φ = 3; shares 100·φ_j·(M·φ)_j/3 = (66.67, 0, 0, 0, 0, 33.33)
    — the rotation x gets none although J couples it (φ_x = 0)."""
    mass = np.diag([2.0, 2.0, 2.0, 1.0, 1.0, 1.0])
    mass[3, 5] = mass[5, 3] = 0.5
    shares = energy_distribution(np.array([1.0, 0, 0, 0, 0, 1.0]), mass)
    assert_allclose(shares, [200 / 3, 0, 0, 0, 0, 100 / 3], rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("height", [-0.1, 0.05])
def test_a_mount_plane_off_the_centre_of_gravity_couples_lateral_and_roll(height):
    """The symmetric example with its mounts moved to z = h: u_y = Y − h·θ_x couples lateral
    and roll (K_y,rx = −4·k_y·h), and u_x = X + h·θ_y fore-aft and pitch; bounce and yaw stay
    alone. The lateral-roll pair's frequencies are the roots of the 2×2 problem
    det([[4k_y − ω²m, −4k_y·h], [−4k_y·h, 4k_z·b² + 4k_y·h² − ω²J_xx]]) = 0, solved here as a
    quadratic in ω²."""
    system = balance.load(SYMMETRIC).mounts
    moved = system.replace(
        mounts=tuple(
            m.replace(position_m=(m.position_m[0], m.position_m[1], height)) for m in system.mounts
        )
    )
    ky, kz, m, jxx, b = 100e3, 200e3, 150.0, 6.0, 0.25
    k11, k12, k22 = 4 * ky, -4 * ky * height, 4 * kz * b * b + 4 * ky * height**2
    # (k11 − λm)(k22 − λJ) − k12² = 0: m·J·λ² − (k11·J + k22·m)·λ + k11·k22 − k12² = 0
    roots = np.roots([m * jxx, -(k11 * jxx + k22 * m), k11 * k22 - k12**2])
    by_hand = np.sort(np.sqrt(roots.real)) / (2 * np.pi)
    modes = natural_modes(moved)
    pair = sorted(
        mode.frequency_hz for mode in modes if mode.energy_pct[1] + mode.energy_pct[3] > 99.999
    )
    assert_allclose(pair, by_hand, rtol=1e-10)  # a quadratic's roots against eigh: rounding
    bounce = [mode for mode in modes if mode.motion == "bounce"]
    assert_allclose(bounce[0].purity_pct, 100.0, atol=1e-9)
