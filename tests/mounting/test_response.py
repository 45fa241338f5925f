"""The forced response: a pure bounce system's transmitted force against F·k/(k − m·ω²), the
balance of forces at every speed, a time-domain integration of the six equations against the
frequency-domain amplitudes, the static deflections by hand, and the resonances crossed."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

import balance_cli as balance
from tests.mounting.helpers import COUPLED, SYMMETRIC, hand_wrench, mass_matrix

G = 9.80665


def rad_s(rpm):
    return np.asarray(rpm) * math.pi / 30


def test_transmitted_vertical_force_of_a_pure_bounce_system():
    """The symmetric example: the in-line four's secondary force is vertical and acts at the
    crank axis, where the centre of gravity is; its free moments are zero (a flat crank). So
    order 2 drives bounce by F = A₂·(Ω/ω₀)² (A the vertical amplitude X⁺ + conj X⁻ at the
    file's speed ω₀) and roll by the frame torque, nothing else. Roll moves the mounts at ±b
    by ±b·θ_x, which cancel in the sum; bounce is one degree of freedom of stiffness 4·k_z:
    the mounts pass on Σ f_z = F·k/(k − m·ω²), k = 4·k_z, ω = 2Ω — below resonance in phase,
    above it in opposition. Each mount's own z force adds the roll: k_z·(Z ± b·θ_x) with
    θ_x = −T/(4·k_z·b² − J_xx·ω²), T the frame torque (about −x for a crank turning clockwise
    seen from the front)."""
    engine = balance.load(SYMMETRIC)
    speeds = np.array([200.0, 300.0, 340.0, 360.0, 500.0, 1000.0, 3000.0, 6000.0])
    result = balance.mounts(engine, speeds_rpm=speeds, orders=[2])
    part = balance.analyse(engine).order(2)
    a_2 = part.force_forward + np.conj(part.force_backward)
    cos, sin = balance.torque(engine).frame.order(2)
    t_2 = cos - 1j * sin
    k, m, kz, b, jxx = 4 * 200e3, 150.0, 200e3, 0.25, 6.0
    scale = (rad_s(speeds) / engine.speed_rad_s) ** 2
    omega = 2 * rad_s(speeds)
    force = a_2 * scale * k / (k - m * omega**2)
    total = result.response.force_n[:, 0, :, 2].sum(axis=1)
    # a 6×6 complex solve against the closed form: rounding, amplified near resonance
    assert_allclose(total, force, rtol=1e-9)
    assert np.all(np.sign(total.real * a_2.real)[:2] > 0)  # below 348.7 rpm: in phase
    assert np.all(np.sign(total.real * a_2.real)[3:] < 0)  # above: in opposition
    bounce = a_2 * scale / (k - m * omega**2)
    roll = -t_2 * scale / (4 * kz * b * b - jxx * omega**2)
    names = result.names
    for side, name in ((1, "front left"), (-1, "front right")):
        assert_allclose(
            result.response.force_n[:, 0, names.index(name), 2],
            kz * (bounce + side * b * roll),
            rtol=1e-9,
        )


def test_the_forces_balance_at_every_speed():
    """The coupled example, every order ½ to 12 at 40 speeds: the mounts' forces on the body
    (−fᵢ, and their moments rᵢ × (−fᵢ) about the centre of gravity) plus the excitation equal
    the body's M·q̈ = −ω²·M·q — written Σ fᵢ − ω²·m·X = F and Σ rᵢ × fᵢ − ω²·J·θ = M_G, with
    the excitation turned into engine axes by hand (:func:`hand_wrench`; without a gas cycle
    all of it grows as the speed squared), the matrices written out, and the lever arms
    crossed with numpy (no transfer matrix)."""
    engine = balance.load(COUPLED)
    system = engine.mounts
    speeds = np.linspace(300.0, 6000.0, 40)
    result = balance.mounts(engine, speeds_rpm=speeds)
    mass = mass_matrix(system)
    positions = np.array([m.position_m for m in system.mounts])
    top = np.array([hand_wrench(engine, system, k, speeds[-1]) for k in result.orders])
    expected = top[None] * ((speeds / speeds[-1]) ** 2)[:, None, None]
    f = result.response.force_n  # (speeds, orders, mounts, 3)
    q = result.response.motion
    omega = result.orders[None, :] * rad_s(speeds)[:, None]
    moments = np.cross(positions[None, None], f).sum(axis=2)
    inertia = (omega**2)[..., None] * np.einsum("jk,sok->soj", mass, q)
    total = np.concatenate([f.sum(axis=2), moments], axis=-1) - inertia
    for s in range(len(speeds)):
        # the analyses' noise floor, 1e-9 of the largest (balance writes rounding noise of an
        # exact cancellation as zero, the hand's phasors keep it); rounding of the solves
        floor = 1e-9 * np.abs(expected[s]).max()
        assert_allclose(total[s], expected[s], rtol=1e-9, atol=floor)


def test_time_domain_integration_reaches_the_frequency_domain_amplitudes():
    """The coupled example with viscous damping (2 kN·s/m along every rate of every mount),
    driven by order 2 at 1500 rpm (ω = 2Ω = 314.2 rad/s): M·q̈ + C·q̇ + K·q = Re(W·e^{iωt})
    integrated from rest with scipy's DOP853 until the transient has died away (25 time
    constants of the slowest decaying mode), then q(t) projected on e^{iωt} over whole
    periods: its complex amplitude is the frequency domain's (K + iωC − ω²M)⁻¹·W."""
    engine = balance.load(COUPLED)
    damped = engine.mounts.replace(
        mounts=tuple(m.replace(damping_ns_m=(2e3, 2e3, 2e3)) for m in engine.mounts.mounts)
    )
    speed = 1500.0
    result = balance.mounts(engine, speeds_rpm=[speed], orders=[2], system=damped)
    wrench = hand_wrench(engine, damped, 2, speed)
    mass, stiffness, damping = (
        mass_matrix(damped),
        damped.stiffness_matrix(),
        damped.damping_matrix(),
    )
    omega = 2 * rad_s(speed)
    inverse = np.linalg.inv(mass)
    state = np.block([[np.zeros((6, 6)), np.eye(6)], [-inverse @ stiffness, -inverse @ damping]])
    slowest = -np.linalg.eigvals(state).real.max()
    period = 2 * math.pi / omega
    periods = 4
    end = period * math.ceil(25 / slowest / period)

    def rates(t, y):
        load = (wrench * np.exp(1j * omega * t)).real
        return np.concatenate([y[6:], inverse @ (load - stiffness @ y[:6] - damping @ y[6:])])

    times = end + np.linspace(0.0, periods * period, 400 * periods, endpoint=False)
    solved = solve_ivp(
        rates,
        (0.0, times[-1]),
        np.zeros(12),
        method="DOP853",
        t_eval=times,
        rtol=1e-11,
        atol=1e-14,
    )
    assert solved.success, solved.message
    amplitude = 2 * (solved.y[:6] * np.exp(-1j * omega * times)).mean(axis=1)
    expected = result.response.motion[0, 0]
    # the integrator's tolerance and the transient's e^-25 against the amplitudes
    assert_allclose(amplitude, expected, rtol=0, atol=1e-6 * np.abs(expected).max())


def test_static_deflection_under_the_weight_by_hand():
    """Symmetric example: each mount carries m·g/4 = 367.75 N and sinks m·g/(4·k_z) = 1.8387
    mm; nothing else moves. Coupled example: the mounts' forces add up to −m·g (pressing on the
    frame) with no moment about the centre of gravity."""
    result = balance.mounts(balance.load(SYMMETRIC), speeds_rpm=[1000.0], orders=[2])
    weight = result.weight
    assert_allclose(weight.displacement, [0, 0, -150 * G / 800e3, 0, 0, 0], atol=1e-15)
    assert_allclose(weight.force_n[:, 2], -150 * G / 4, rtol=1e-12)
    assert_allclose(weight.deflection_m[:, 2], -150 * G / 800e3, rtol=1e-12)
    coupled = balance.mounts(balance.load(COUPLED), speeds_rpm=[1000.0], orders=[2])
    forces = coupled.weight.force_n
    positions = np.array([m.position_m for m in coupled.system.mounts])
    assert_allclose(forces.sum(axis=0), [0, 0, -180 * G], atol=1e-9)
    assert_allclose(np.cross(positions, forces).sum(axis=0), 0.0, atol=1e-9)


def test_static_deflection_under_the_mean_torque_by_hand():
    """Symmetric example at 60 kW at the file's 6000 rpm: T = 60 000/(6000·π/30) = 95.49 N·m.
    The crank turns clockwise seen from the front (about −x); the frame's reaction turns the
    engine the other way, +T about x: θ_x = T/(4·k_z·b²) = 95.49/50 000 = 1.910 mrad, and the
    mounts at y = +b are lifted: the force they pass on is k_z·b·θ_x = +95.49 N (pulling the
    frame up), those at −b press with −95.49 N: a couple 4·95.49·0.25 = T."""
    engine = balance.load(SYMMETRIC)
    result = balance.mounts(engine, speeds_rpm=[1000.0], orders=[2], power_w=60e3)
    torque_nm = 60e3 / (6000 * math.pi / 30)
    load = result.torque_load
    assert_allclose(load.torque_nm, torque_nm, rtol=1e-12)
    assert_allclose(load.displacement, [0, 0, 0, torque_nm / 50e3, 0, 0], atol=1e-15)
    by_side = {"front left": 1, "rear left": 1, "front right": -1, "rear right": -1}
    for i, name in enumerate(result.names):
        assert_allclose(load.force_n[i], [0, 0, by_side[name] * torque_nm], atol=1e-9)
    turning = balance.mounts(
        engine,
        speeds_rpm=[1000.0],
        orders=[2],
        power_w=60e3,
        system=engine.mounts.replace(rotation="anticlockwise"),
    )
    assert_allclose(turning.torque_load.displacement[3], -torque_nm / 50e3, rtol=1e-12)


def test_a_gas_cycle_gives_the_mean_torque():
    """With a [gas] table and no power given, the torque is the gas cycle's mean at the file's
    speed — the indicated torque that balance.torque reports."""
    engine = balance.load(COUPLED)
    with_gas = engine.replace(
        gas=balance.GasCycle(bore_m=0.086, compression_ratio=10.0, imep_pa=10e5)
    )
    result = balance.mounts(with_gas, speeds_rpm=[1000.0], orders=[0.5, 2])
    assert result.with_gas
    mean = balance.torque(with_gas).gas.mean
    assert_allclose(result.torque_load.torque_nm, mean, rtol=1e-12)
    assert "gas" in result.torque_load.source


def test_resonances_crossed_and_whether_they_are_driven():
    """Symmetric example, orders 1 and 2 from 200 to 1000 rpm. Order 2 meets bounce
    (11.623 Hz) at 60·11.623/2 = 348.7 rpm and roll (14.529 Hz) at 435.9 rpm; it drives both
    (the secondary force is vertical at the centre of gravity, the frame torque has a second
    order). It meets fore-aft and lateral (8.219 Hz) at 246.6 rpm, yaw at 416.9 rpm and pitch
    at 427.1 rpm without driving them: no fore-aft or lateral force, no free couple. Order 1
    (no primary force or couple, no first order of the inertia torque) drives nothing."""
    result = balance.mounts(
        balance.load(SYMMETRIC), speeds_rpm=np.linspace(200, 1000, 81), orders=[1, 2]
    )
    found = {(c.order, c.motion): (c.speed_rpm, c.excited) for c in result.crossings}
    by_hand = {
        (2.0, "bounce"): (60 * 11.623 / 2, True),
        (2.0, "roll"): (60 * 14.529 / 2, True),
        (2.0, "fore-aft"): (60 * 8.2187 / 2, False),
        (2.0, "lateral"): (60 * 8.2187 / 2, False),
        (2.0, "yaw"): (60 * 13.898 / 2, False),
        (2.0, "pitch"): (60 * 14.235 / 2, False),
        (1.0, "bounce"): (60 * 11.623, False),
        (1.0, "yaw"): (60 * 13.898, False),
        (1.0, "pitch"): (60 * 14.235, False),
        (1.0, "roll"): (60 * 14.529, False),
        (1.0, "fore-aft"): (60 * 8.2187, False),
        (1.0, "lateral"): (60 * 8.2187, False),
    }
    assert set(found) == set(by_hand)
    for key, (speed, excited) in by_hand.items():
        assert_allclose(found[key][0], speed, rtol=5e-5)  # the frequencies' 5 printed digits
        assert found[key][1] is excited, key


def test_an_undamped_resonance_hit_exactly_is_refused():
    """A speed that puts order 2 exactly on the undamped bounce mode of the symmetric example:
    the response is infinite; the error names the speed, the order and the mode."""
    engine = balance.load(SYMMETRIC)
    bounce = math.sqrt(800e3 / 150) / (2 * math.pi)
    with pytest.raises(balance.AnalysisError, match="order 2 on mode 3 .bounce") as caught:
        balance.mounts(engine, speeds_rpm=[60 * bounce / 2], orders=[2])
    assert caught.value.parameter == "speeds_rpm"
    # the same speed with the mounts damped is a finite peak
    damped = engine.mounts.replace(
        mounts=tuple(m.replace(loss_factor=0.1) for m in engine.mounts.mounts)
    )
    peak = balance.mounts(engine, speeds_rpm=[60 * bounce / 2], orders=[2], system=damped)
    assert np.isfinite(peak.response.force_peak_n).all()


def test_a_loss_factor_bounds_the_resonance_by_one_over_eta():
    """One degree of freedom with a hysteretic rate k·(1 + iη) driven at its natural
    frequency passes on |F·k·(1 + iη)/(iη·k)| = F·√(1 + η²)/η: with η = 0.2, 5.099·F."""
    engine = balance.load(SYMMETRIC)
    damped = engine.mounts.replace(
        mounts=tuple(m.replace(loss_factor=0.2) for m in engine.mounts.mounts)
    )
    bounce = math.sqrt(800e3 / 150) / (2 * math.pi)
    speed = 60 * bounce / 2
    result = balance.mounts(engine, speeds_rpm=[speed], orders=[2], system=damped)
    part = balance.analyse(engine).order(2)
    force = abs(part.force_forward + np.conj(part.force_backward))
    force *= (rad_s(speed) / engine.speed_rad_s) ** 2
    total = abs(result.response.force_n[0, 0, :, 2].sum())
    assert_allclose(total, force * math.sqrt(1 + 0.04) / 0.2, rtol=1e-9)
