"""Torque roll axis decoupling (balance.decouple) against hand derivations: the symmetric
example already decoupled, a focused pair of inclined mounts (the closed form Harris gives for
inclined isolators, derived below), and the coupled example checked by a second derivation
of the conditions and by the modes of K and M assembled here apart from the library."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.linalg import eigh

import balance_cli as balance
from balance_cli import AnalysisError, Mount, MountSystem
from tests.mounting.helpers import COUPLED, SYMMETRIC, mass_matrix, stiffness_by_energy

CORNERS = ("front left", "front right", "rear left", "rear right")


def tra_direction(system):
    """J⁻¹·x̂ by numpy's solve, made a unit vector."""
    e = np.linalg.solve(np.array(system.inertia_kgm2), [1.0, 0.0, 0.0])
    return e / np.linalg.norm(e)


def tra_mode(system):
    """The mode of K·φ = ω²·M·φ (K by the springs' energy, M written out, scipy's eigh) with
    the largest M-weighted overlap with the turn about J⁻¹·x̂: (frequency Hz, shape)."""
    mass = mass_matrix(system)
    values, shapes = eigh(stiffness_by_energy(system), mass)
    q = np.concatenate([np.zeros(3), tra_direction(system)])
    overlap = (shapes.T @ mass @ q) ** 2
    r = int(np.argmax(overlap))
    return math.sqrt(values[r]) / (2 * math.pi), shapes[:, r]


def test_the_symmetric_example_is_decoupled_as_it_stands():
    """J = diag(6, 9, 8): the TRA is the crank axis x. The mounts in the plane of the centre of
    gravity: a turn θ about x moves a mount at (x, ±b, 0) by (0, 0, ±b·θ), whose forces
    ±k_z·b·θ cancel in pairs, as do their moments about y (x·k_z·b·θ) — the mounts answer with
    a pure couple 4·k_z·b²·θ about x. Roll is a natural mode before any change: the rates stay,
    the purity is 100 %, the frequency √(4·k_z·b²/J_xx)/2π = √(4·200e3·0.0625/6)/2π =
    14.529 Hz (Harris' closed form for a roll about a plane of symmetry)."""
    engine = balance.load(SYMMETRIC)
    result = balance.decouple(engine, [(CORNERS, "z")])
    assert result.torque_roll_axis.direction == (1.0, 0.0, 0.0)
    assert result.method == "closed form" and result.exact
    (rate,) = result.rates
    assert rate.before_n_m == (200e3,) * 4
    assert_allclose(rate.after_n_m, 200e3, rtol=1e-12)  # no change, to rounding
    roll_hz = math.sqrt(4 * 200e3 * 0.25**2 / 6.0) / (2 * math.pi)
    assert_allclose(roll_hz, 14.5288, atol=5e-5)
    for state in (result.before, result.after):
        assert state.motion == "roll"
        assert_allclose(state.frequency_hz, roll_hz, rtol=1e-12)  # eigh's rounding
        assert_allclose(state.purity_pct, 100.0, rtol=1e-12)
        assert_allclose(state.tra_energy_pct, 100.0, rtol=1e-12)
        assert state.coupling < 1e-15 and state.axis_angle_deg < 1e-12


def inclined_system(shear_n_m, h=0.1, b=0.25, a=0.3, psi_deg=30.0, kp=300e3):
    """Four mounts at (±a, ±b, −h) from the centre of gravity, each of compression rate kp
    along a direction in the y-z plane leaning ψ towards the engine's middle as it rises,
    (0, ∓sin ψ, cos ψ) for y = ±b, and shear rate ``shear_n_m`` across it; J diagonal."""
    s, c = math.sin(math.radians(psi_deg)), math.cos(math.radians(psi_deg))
    mounts = [
        Mount.oriented(name, (x, y, -h), kp, shear_n_m, (0.0, -math.copysign(s, y), c))
        for name, (x, y) in zip(CORNERS, [(a, b), (a, -b), (-a, b), (-a, -b)], strict=True)
    ]
    return MountSystem(150.0, ((6.0, 0, 0), (0, 9.0, 0), (0, 0, 8.0)), mounts)


def test_inclined_mounts_focused_on_the_roll_axis():
    """Harris' inclined isolators (Shock and Vibration Handbook, ch. 3), derived here. A turn θ
    about x moves the mount at (a, b, −h) by θ·(0, h, b). With its compression axis
    n = (−sin ψ, cos ψ) in the y-z plane and the shear rate k_q across it, its stiffness
    there is k_q·I + (k_p − k_q)·n·nᵀ and its lateral force
    θ·[k_q·h + (k_p − k_q)·(−sin ψ)·(−h·sin ψ + b·cos ψ)]. Its mirror image (y → −y) pushes
    the same way laterally and the opposite way vertically, so the vertical forces and their
    moments cancel; the lateral forces (and their yawing moment x·ΣF_y) vanish only when
    k_q·h·cos²ψ + k_p·h·sin²ψ = (k_p − k_q)·b·sin ψ·cos ψ, that is, with r = k_q/k_p and
    t = tan ψ, h/b = t·(1 − r)/(r + t²): r = t·(b − h·t)/(h + b·t). For h = 0.1 m, b = 0.25
    m, ψ = 30°: r = 0.57735·0.19226/0.24434 = 0.45431, k_q = 136.29 N/mm for k_p = 300 N/mm.
    The mounts start at 80 N/mm of shear (roll coupled with lateral); one shear rate shared
    by the four is found."""
    t, h, b = math.tan(math.radians(30.0)), 0.1, 0.25
    r = t * (b - h * t) / (h + b * t)
    assert_allclose(r, 0.45431, atol=5e-6)
    before = inclined_system(80e3)
    result = balance.decouple(before, [(CORNERS, "shear")])
    assert result.method == "closed form" and result.exact
    assert result.before.purity_pct < 99.0  # coupled to begin with
    (rate,) = result.rates
    assert rate.slots == tuple((name, j) for name in CORNERS for j in (2, 3))
    # one linear equation in one unknown: exact to rounding of the solve
    assert_allclose(rate.after_n_m, r * 300e3, rtol=1e-10)
    assert_allclose(
        inclined_system(r * 300e3).stiffness_matrix(),
        result.system.stiffness_matrix(),
        rtol=1e-9,
        atol=1e-6,
    )
    frequency, shape = tra_mode(result.system)
    assert_allclose(shape[:3], 0.0, atol=1e-12)  # no translation: the turn is about the CG
    assert_allclose(shape[4:], 0.0, atol=1e-12)  # about x alone
    assert_allclose(result.after.frequency_hz, frequency, rtol=1e-10)


def wrench_conditions(system, rates_varied):
    """The decoupling conditions derived apart from the library, as Jeong and Singh state
    them: the mounts' answer to a unit turn q* about ê = J⁻¹·x̂/|J⁻¹·x̂| must be a couple about
    x alone (M·q* = (0, J·ê) is one), its force and its moments about y and z zero. A mount's
    rate k along d at r deflects along d by d·(ê × r) and pushes k·d·(d·(ê × r)), whose moment
    about the centre of gravity is r × that. Returns the five components (Fx, Fy, Fz, My, Mz)
    per N/m of each rate in ``rates_varied`` ((mount, index) pairs), a dict, and of the
    rest as held."""
    e = tra_direction(system)
    columns, held = {}, np.zeros(5)
    for mount in system.mounts:
        r = np.array(mount.position_m)
        for j, (k, d) in enumerate(zip(mount.rates_n_m, np.array(mount.directions), strict=True)):
            push = d * float(d @ np.cross(e, r))
            wrench = np.concatenate([push, np.cross(r, push)])[[0, 1, 2, 4, 5]]
            if (mount.name, j) in rates_varied:
                columns[(mount.name, j)] = wrench
            else:
                held += k * wrench
    return columns, held


@pytest.mark.parametrize(
    "vary",
    [
        None,
        [(("A", "B"), "y"), ("A", "z"), ("B", "x"), ("C", "compression"), ("C", "shear")],
    ],
    ids=["every rate", "five rates"],
)
def test_the_coupled_example_decoupled(vary):
    """The coupled example (TRA 5.6° off the crank axis, roll 68 % pure) with every rate, or
    five, free. The rates found are checked three ways: (1) the least change Σ(Δk/k)² that
    meets the conditions, by the pseudo-inverse of the wrench conditions derived above (a
    different set of five equations with the same solutions, so the same least change);
    (2) the mode of K and M assembled here (K from the springs' energy, scipy's eigh) nearest
    the turn about J⁻¹·x̂ is that turn: no translation, its axis along J⁻¹·x̂ to within the
    angle and offset the result reports; (3) those reported figures are rounding."""
    engine = balance.load(COUPLED)
    result = balance.decouple(engine, vary)
    assert result.exact and result.method == "closed form"
    assert result.before.purity_pct < 70.0
    system = engine.mounts
    # (1) the least change, from the wrench conditions
    groups = [[(name, j - 1) for name, j in r.slots] for r in result.rates]
    columns, held = wrench_conditions(system, {s for g in groups for s in g})
    start = [np.mean([system.mount(n).rates_n_m[j] for n, j in g]) for g in groups]
    per_group = np.array([sum(columns[s] for s in g) for g in groups]).T
    b = per_group @ np.diag(start)
    z = np.linalg.lstsq(b, -(held + per_group @ start), rcond=None)[0]  # minimum norm
    found = np.array(start) * (1 + z)
    # the two sets of equations are scaled differently: the same solution to rounding of two
    # pseudo-inverses of matrices whose conditioning is about 1e3
    assert_allclose([r.after_n_m for r in result.rates], found, rtol=1e-9)
    assert all(r.low_n_m <= r.after_n_m <= r.high_n_m for r in result.rates)
    # (2) the mode by scipy's eigh of this file's K and M
    frequency, shape = tra_mode(result.system)
    u, theta = shape[:3], shape[3:]
    e = tra_direction(system)
    angle = math.degrees(math.atan2(np.linalg.norm(np.cross(theta, e)), abs(theta @ e)))
    offset = np.linalg.norm(np.cross(theta, u)) / (theta @ theta)
    # two eigen-solvers and K by differences: 1e-9 of rounding beyond what is reported
    assert angle <= result.after.axis_angle_deg + 1e-9
    assert offset <= result.after.axis_offset_m + 1e-12
    assert_allclose(u, 0.0, atol=1e-10)
    assert_allclose(result.after.frequency_hz, frequency, rtol=1e-9)
    # (3) what is reported is rounding
    assert result.after.axis_angle_deg < 1e-9 and result.after.axis_offset_m < 1e-12
    assert result.after.coupling < 1e-12
    assert_allclose(result.after.purity_pct, 100.0, rtol=1e-12)
    assert result.after.axes_angle_deg < 1e-9  # the TRA is the elastic axis too


def test_bounds_that_exclude_the_least_change():
    """Every rate free but none below 30 N/mm: the least change wants A's and B's lateral
    rates at 26 N/mm, so another exact solution within the bounds is found (SLSQP), the
    lateral rates on their bound."""
    engine = balance.load(COUPLED)
    free = balance.decouple(engine)
    assert min(r.after_n_m for r in free.rates) < 30e3
    result = balance.decouple(engine, bounds_n_m=(30e3, 3e6))
    assert result.method == "SLSQP" and result.exact
    assert all(30e3 * (1 - 1e-9) <= r.after_n_m <= 3e6 for r in result.rates)
    lateral = {r.label: r for r in result.rates}
    assert lateral["A:y"].at_bound and lateral["B:y"].at_bound
    frequency, shape = tra_mode(result.system)
    assert_allclose(shape[:3], 0.0, atol=1e-9)


def test_too_few_rates_give_the_purest_mode_within_bounds():
    """One rate cannot meet five conditions: the rate whose TRA mode is purest is found
    within its bounds, not exact; it is at least as pure as the rate given (the search starts
    there), and no rate of a fine scan of the bounds does better (a brute force over 401
    rates, each mode from this file's K and M)."""
    engine = balance.load(COUPLED)
    result = balance.decouple(engine, [("A", "z")], bounds_n_m=(100e3, 500e3))
    assert result.method == "purest" and not result.exact
    (rate,) = result.rates
    assert 100e3 <= rate.after_n_m <= 500e3
    assert result.after.purity_pct >= result.before.purity_pct
    system = engine.mounts
    mass = mass_matrix(system)
    q = np.concatenate([np.zeros(3), tra_direction(system)])

    # K is linear in a rate: two Hessians of the springs' energy give it at any rate
    low, high = (
        stiffness_by_energy(system.replace_mount("A", rates_n_m=(150e3, 120e3, k)))
        for k in (100e3, 500e3)
    )

    def purity(k):
        stiffness = low + (k - 100e3) / 400e3 * (high - low)
        shapes = eigh(stiffness, mass)[1]
        return 100 * float(np.max((shapes.T @ mass @ q) ** 2)) / float(q @ mass @ q)

    scan = max(purity(k) for k in np.linspace(100e3, 500e3, 401))
    # the scan's step (1 N/mm) against the optimiser's tolerance
    assert result.after.purity_pct >= scan - 1e-3


def test_records_and_document():
    engine = balance.load(COUPLED)
    result = balance.decouple(engine, [(("A", "B"), "y"), ("C", "shear")])
    rows = result.records()
    # A+B:y sets two rates, C:shear C's two shear rates
    assert [(r["mount"], r["rate"], r["principal"]) for r in rows] == [
        ("A", "y", 2),
        ("B", "y", 2),
        ("C", "shear", 2),
        ("C", "shear", 3),
    ]
    assert rows[0]["before_N_per_m"] == 120e3 and rows[2]["before_N_per_m"] == 80e3
    document = result.to_dict()
    assert [r["mounts"] for r in document["rates"]] == [["A", "B"], ["C"]]
    assert document["before"]["mode"] == result.before.mode


@pytest.mark.parametrize(
    "vary, bounds, parameter, words",
    [
        ([("E", "z")], None, "vary", "'E' is not one of the mounts (A, B, C, D)"),
        ([("A", "w")], None, "vary", "one of x, y, z, compression, shear"),
        ([("C", "z")], None, "vary", "mount 'C' has no rate along z"),
        ([("A", "shear")], None, "vary", "vary 'x', 'y' or 'z'"),
        (
            [("A", "z"), (("B", "A"), "z")],
            None,
            "vary",
            "z rate of mount 'A' twice (A:z and B+A:z)",
        ),
        ("A:z", None, "vary", "(mount, rate) pairs"),
        ([("A",)], None, "vary", "(mount, rate) pairs"),
        ([], None, "vary", "one rate or more"),
        ([("A", "z")], (5e5, 1e5), "bounds_n_m", "0 < low < high"),
        ([("A", "z")], (0, 1e5), "bounds_n_m", "0 < low < high"),
    ],
)
def test_bad_arguments(vary, bounds, parameter, words):
    engine = balance.load(COUPLED)
    with pytest.raises(AnalysisError) as caught:
        balance.decouple(engine, vary, bounds)
    assert caught.value.parameter == parameter
    assert words in str(caught.value)


def test_an_engine_without_mounts_and_not_an_engine():
    with pytest.raises(AnalysisError, match="no \\[mounts\\] table"):
        balance.decouple(balance.load("configs/inline-4-car.toml"))
    with pytest.raises(AnalysisError, match="must be an Engine or MountSystem"):
        balance.decouple("configs/inline-4-car.toml")
