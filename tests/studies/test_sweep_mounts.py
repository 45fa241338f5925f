"""Sweeps of the engine on its mounts: [mounts] keys varied, the mount analysis's frequencies,
decoupling and forces as quantities, against Harris' closed forms for the symmetric example
and a forced response worked by hand."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.config import reader as config_module
from balance_cli.studies.sweep.mountkeys import MOUNT_SCHEMA, MOUNT_TABLE_SCHEMA
from tests.mounting.helpers import COUPLED, SYMMETRIC, hand_wrench
from tests.support import CONFIGS

#: the symmetric example: 150 kg, J = diag(6, 9, 8) kg·m², mounts at (±a, ±b, 0)
MASS, JXX, JYY = 150.0, 6.0, 9.0
A, B = 0.30, 0.25
EVERY_Z = "mounts.mount[*].stiffness[3]"


def hz(stiffness, inertia):
    """√(k/m)/2π."""
    return math.sqrt(stiffness / inertia) / (2 * math.pi)


def test_every_mounts_vertical_rate_gives_harris_closed_forms_at_every_point():
    """Four mounts in the plane of the centre of gravity, symmetric about both vertical planes:
    bounce, roll and pitch are each alone (Harris, ch. 3): √(4·k_z/m)/2π, √(4·k_z·b²/J_xx)/2π,
    √(4·k_z·a²/J_yy)/2π, while fore-aft (4·k_x) does not change with k_z; the TRA is the crank
    axis and its mode pure at every point. rtol 1e-12: eigh's rounding."""
    rates = [120.0, 180.0, 240.0, 300.0, 360.0]  # N/mm
    result = balance.sweep(
        SYMMETRIC,
        EVERY_Z,
        [f"{k:g} N/mm" for k in rates],
        "bounce_mode,roll_mode,pitch_mode,fore_aft_mode,tra_purity,axes_angle",
    )
    k = np.array(rates) * 1e3
    assert_allclose(result.values_si, k, rtol=1e-15)
    assert_allclose(result.series("bounce_mode"), [hz(4 * v, MASS) for v in k], rtol=1e-12)
    assert_allclose(result.series("roll_mode"), [hz(4 * v * B**2, JXX) for v in k], rtol=1e-12)
    assert_allclose(result.series("pitch_mode"), [hz(4 * v * A**2, JYY) for v in k], rtol=1e-12)
    assert_allclose(result.series("fore_aft_mode"), hz(4 * 100e3, MASS), rtol=1e-12)
    assert_allclose(result.series("tra_purity"), 100.0, rtol=1e-12)
    assert_allclose(result.series("axes_angle"), 0.0, atol=1e-12)
    assert result.parameter.changes == tuple(f"mounts.mount[{i}].stiffness[3]" for i in range(1, 5))
    assert result.parameter.file_value == "200 N/mm"
    # each point's engine holds the rate in every mount
    for engine, rate in zip(result.engines, k, strict=True):
        assert {m.rates_n_m[2] for m in engine.mounts.mounts} == {rate}


def test_a_mounts_force_against_the_bounce_and_roll_worked_by_hand():
    """At the file's 6000 rpm with orders up to 2, the in-line four shakes its mounts with
    its second-order vertical force F (at the centre of gravity: it is on the crank axis) and
    its second-order frame torque T (roll); it has no free moment. Bounce and roll are apart
    (the symmetric example): Z = F/(4·k_z − m·ω²), θ_x = M_x/(4·k_z·b² − J_xx·ω²), ω = 2Ω, the
    wrench by hand from balance's shaking forces and frame torque (tests/mounting/helpers).
    The front left mount at y = +b moves by Z + b·θ_x, vertically only (its z is zero, so roll
    moves it along z alone), and passes on k_z·(Z + b·θ_x). The sweep's force is the largest
    over a cycle of the sampled waveform: 32 samples a period, within 1 − cos(π/32) = 0.5 %
    below the amplitude."""
    rates = [150e3, 250e3, 400e3]
    result = balance.sweep(
        SYMMETRIC,
        EVERY_Z,
        [f"{k / 1e3:g} N/mm" for k in rates],
        "mount_front_left_Fz,mount_front_left_force,mount_1_Fx",
        max_order=2,
    )
    engine = balance.load(SYMMETRIC)
    wrench = hand_wrench(engine, engine.mounts, 2, 6000.0)
    assert_allclose(wrench[[0, 1, 4, 5]], 0.0, atol=1e-6 * abs(wrench[2]))
    omega = 2 * 6000 * math.pi / 30
    hand = []
    for k in rates:
        bounce = wrench[2] / (4 * k - MASS * omega**2)
        roll = wrench[3] / (4 * k * B**2 - JXX * omega**2)
        hand.append(abs(k * (bounce + B * roll)))
    assert_allclose(result.series("mount_front_left_Fz"), hand, rtol=5e-3)
    assert np.all(result.series("mount_front_left_Fz") <= np.array(hand) * (1 + 1e-12))
    assert_allclose(result.series("mount_front_left_force"), result.series("mount_front_left_Fz"))
    assert_allclose(result.series("mount_1_Fx"), 0.0, atol=1e-9 * max(hand))


def test_a_force_over_speeds_is_the_largest_of_balance_mounts():
    """mount_speeds_rpm: the largest over those speeds, as balance.mounts gives it at each."""
    speeds = [400.0, 700.0, 1000.0]
    result = balance.sweep(
        COUPLED,
        "mounts.mount[C].compression",
        ["250 N/mm", "350 N/mm"],
        "mount_C_force,mount_D_Fz",
        max_order=4,
        mount_speeds_rpm=speeds,
    )
    assert result.mount_speeds_rpm == tuple(speeds)
    assert result.to_dict()["mount_speeds_rpm"] == speeds
    engine = balance.load(COUPLED)
    for i, rate in enumerate((250e3, 350e3)):
        system = engine.mounts.replace_mount("C", rates_n_m=(rate, 80e3, 80e3))
        alone = balance.mounts(engine, speeds, max_order=4, system=system).response
        # the same analysis, the point's system rebuilt from its file: to rounding
        assert_allclose(
            result.series("mount_C_force")[i],
            alone.force_magnitude_peak_n[:, 2].max(),
            rtol=1e-12,
        )
        assert_allclose(
            result.series("mount_D_Fz")[i], alone.force_peak_n[:, 3, 2].max(), rtol=1e-12
        )


def test_a_grid_of_a_rate_and_an_inertia():
    """Roll √(4·k_z·b²/J_xx)/2π at every pair of k_z and J_xx; bounce √(4·k_z/m)/2π whatever
    J_xx."""
    rates, inertias = [150.0, 250.0, 350.0], [5.0, 6.0, 7.5]
    grid = balance.sweep_grid(
        SYMMETRIC,
        [EVERY_Z, "mounts.inertia[1]"],
        [[f"{k:g} N/mm" for k in rates], [f"{j:g} kg*m^2" for j in inertias]],
        "roll_mode,bounce_mode",
    )
    assert grid.shape == (3, 3)
    roll = [[hz(4 * k * 1e3 * B**2, j) for j in inertias] for k in rates]
    bounce = [[hz(4 * k * 1e3, MASS)] * 3 for k in rates]
    assert_allclose(grid.grid("roll_mode"), roll, rtol=1e-12)
    assert_allclose(grid.grid("bounce_mode"), bounce, rtol=1e-12)


def test_a_mount_by_name_or_number_and_the_mass():
    """A mount named or numbered is the same key; bounce falls as 1/√m."""
    by_name = balance.sweep(COUPLED, "mounts.mount[B].stiffness[1]", ["200 N/mm"], "mode_1")
    by_number = balance.sweep(COUPLED, "mounts.mount[2].stiffness[1]", ["200 N/mm"], "mode_1")
    assert by_name.points[0]["mode_1_Hz"] == by_number.points[0]["mode_1_Hz"]
    assert by_name.parameter.changes == by_number.parameter.changes
    masses = balance.sweep(SYMMETRIC, "mounts.mass", ["100 kg", "150 kg", "225 kg"], "bounce_mode")
    assert_allclose(
        masses.series("bounce_mode"), [hz(4 * 200e3, m) for m in (100, 150, 225)], rtol=1e-12
    )


def test_the_mount_keys_are_the_formats():
    """Every numeric key of [mounts] and [[mounts.mount]] can be swept; the rest is text or the
    mounts' own tables."""
    assert {k.removesuffix("[]") for k in MOUNT_TABLE_SCHEMA} | {
        "products_convention",
        "rotation",
        "mount",
    } == config_module.MOUNTS_KEYS
    assert {k.removesuffix("[]") for k in MOUNT_SCHEMA} | {"name"} == config_module.MOUNT_KEYS


@pytest.mark.parametrize(
    "config, parameter, values, quantities, options, error_parameter, words",
    [
        (SYMMETRIC, EVERY_Z, ["1 N/mm"], "F2", {}, "parameter", "ask for its quantities"),
        (
            CONFIGS / "inline-4-car.toml",
            "speed",
            ["1000 rpm"],
            "mode_1",
            {},
            "quantities",
            "no [mounts] table",
        ),
        (
            CONFIGS / "inline-4-car.toml",
            "mounts.mass",
            ["1 kg"],
            "mode_1",
            {},
            "parameter",
            "no [mounts] table; add one",
        ),
        (SYMMETRIC, EVERY_Z, ["1 N/mm"], "mount_x_force", {}, "quantities", "front_left (1)"),
        (SYMMETRIC, EVERY_Z, ["1 N/mm"], "mode_7", {}, "quantities", "not a quantity"),
        (
            SYMMETRIC,
            EVERY_Z,
            ["1 N/mm"],
            "mode_1",
            {"mount_speeds_rpm": [1000]},
            "mount_speeds_rpm",
            "mounts' forces only",
        ),
        (
            SYMMETRIC,
            EVERY_Z,
            ["1 N/mm"],
            "mount_1_force",
            {"mount_speeds_rpm": [0]},
            "mount_speeds_rpm",
            "greater than zero",
        ),
        (COUPLED, "mounts.mount[*].stiffness[3]", ["1 N/mm"], "mode_1", {}, "parameter", "(C)"),
        (COUPLED, "mounts.mount[E].stiffness[3]", ["1 N/mm"], "mode_1", {}, "parameter", "[1] A"),
        (COUPLED, "mounts.mount[1].stiffness", ["1 N/mm"], "mode_1", {}, "parameter", "[1]"),
        (COUPLED, "mounts.rotation", ["1 N/mm"], "mode_1", {}, "parameter", "holds text"),
        (COUPLED, "mounts.mount[C].shear[1]", ["1 N/mm"], "mode_1", {}, "parameter", "one value"),
        (COUPLED, "mounts.mount[1].stiffness[3]", [250], "mode_1", {}, "values", "with a unit"),
    ],
)
def test_refused(config, parameter, values, quantities, options, error_parameter, words):
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(config, parameter, values, quantities, **options)
    assert caught.value.parameter == error_parameter
    assert words in str(caught.value)


def test_a_point_that_makes_no_mounts_names_the_file_key_and_value():
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(SYMMETRIC, EVERY_Z, ["200 N/mm", "-5 N/mm"], "mode_1")
    assert str(caught.value) == (
        f"{SYMMETRIC}: mounts.mount[*].stiffness[3] = '-5 N/mm': mounts.mount[1].stiffness[3]: "
        "must be greater than zero, got '-5 N/mm'"
    )
    with pytest.raises(balance.SweepError, match="both change mounts.mount\\[1\\].stiffness"):
        balance.sweep_grid(
            COUPLED,
            ["mounts.mount[1].stiffness[3]", "mounts.mount[A].stiffness[3]"],
            [["1 N/mm", "2 N/mm"]] * 2,
            "mode_1",
        )
