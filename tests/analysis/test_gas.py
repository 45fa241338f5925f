"""The gas torque: its orders, its mean (the indicated work), a pressure curve read from a file,
and the pressure and bore it is given checked."""

import dataclasses
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli
import balance_cli as balance
from balance_cli.analysis.torque import torque
from balance_cli.model import GasCycle
from tests.support import CONFIGS, invoke, make_engine


def engine_with_gas(throws, imep_bar=12.0, cycle=4):
    engine = make_engine([0], throws, r=0.045, rod=0.15, m=0.5, rpm=3000.0, cycle=cycle)
    return dataclasses.replace(
        engine, gas=GasCycle(bore_m=0.086, compression_ratio=10.0, imep_pa=imep_bar * 1e5)
    )


def test_gas_torque_of_an_even_inline_six_has_only_orders_of_three():
    """Identical cylinders firing every 120°: Σ T(θ − 120°·j) keeps orders 3, 6, 9, …
    (N/2·k). The pressure's sharp features alias into the sampled curve; with 2048 samples the
    other orders are below 1e-6 of the third."""
    six = engine_with_gas([(0, 0.0), (120, 0.1), (240, 0.2), (240, 0.3), (120, 0.4), (0, 0.5)])
    gas = torque(six, samples=2048, max_order=10).gas
    third = math.hypot(*gas.order(3))
    for k, cos, sin in gas.orders:
        if k % 3:
            assert math.hypot(cos, sin) < 1e-6 * third, k
    assert math.hypot(*gas.order(6)) > 0.1 * third


def test_gas_torque_of_one_four_stroke_cylinder_has_every_half_order():
    gas = torque(engine_with_gas([(0, 0.0)]), max_order=4).gas
    assert [k for k, _, _ in gas.orders] == [0.5 * j for j in range(1, 9)]
    assert all(math.hypot(c, s) > 1e-3 * abs(gas.mean) for _, c, s in gas.orders)


@pytest.mark.parametrize("cycle", [2, 4])
def test_mean_gas_torque_is_the_indicated_work(cycle):
    """C_m = imep·V_d·N / (2π·cycle/2): the cycle's ∮p·dV (trapezoid on the model's 0.05° grid)
    against −∮p·A·ds/dθ on the analysis grid, two integrations: 1e-5."""
    engine = engine_with_gas([(0, 0.0), (180, 0.1)], imep_bar=10.0, cycle=cycle)
    gas = torque(engine, samples=1024).gas
    swept = math.pi / 4 * 0.086**2 * 2 * 0.045
    assert_allclose(gas.mean, 10e5 * swept * 2 / (math.pi * cycle), rtol=1e-5)


def test_a_pressure_curve_from_a_file_gives_the_parametric_torque(tmp_path):
    """The [gas] cycle written to a CSV every 0.25° and read back: the same torque to the
    linear interpolation of that grid (1e-3 of the largest order)."""
    from balance_cli.analysis.pressure import CYCLE_GRID_DEG, cycle_pressure, read_pressure_csv

    engine = engine_with_gas([(0, 0.0), (180, 0.1), (180, 0.2), (0, 0.3)])
    reference = torque(engine, max_order=6)
    n = engine.cylinders[0].number
    fire = 0.0

    def travel(psi):
        return balance_cli.kinematics.linkage_state(engine, np.radians(fire + psi)).travel[n]

    curve = cycle_pressure(engine.gas, travel(CYCLE_GRID_DEG), 720.0)
    angles = np.arange(0, 720, 0.25)
    rows = ["angle_deg,pressure_bar"] + [
        f"{float(a)!r},{float(p) / 1e5!r}" for a, p in zip(angles, curve.at(angles), strict=True)
    ]
    path = tmp_path / "p.csv"
    path.write_text("\n".join(rows) + "\n")
    pressure = read_pressure_csv(path, 720.0)
    plain = dataclasses.replace(engine, gas=dataclasses.replace(engine.gas))
    from_file = torque(plain, max_order=6, pressure=pressure)
    largest = max(math.hypot(c, s) for _, c, s in reference.gas.orders)
    for (k, c1, s1), (_, c2, s2) in zip(reference.gas.orders, from_file.gas.orders, strict=True):
        assert math.hypot(c1 - c2, s1 - s2) < 1e-3 * largest, k


def test_an_isothermal_exponent_is_refused(tmp_path):
    text = (CONFIGS / "abc-dragonfly.toml").read_text(encoding="utf-8")
    path = tmp_path / "e.toml"
    path.write_text(
        text.replace('imep = "9 bar"', 'imep = "9 bar"\npolytropic_exponent = 1.0'),
        encoding="utf-8",
    )
    with pytest.raises(balance.ConfigError, match="gas.polytropic_exponent"):
        balance.load(path)


def test_a_bore_without_a_pressure_is_refused_by_the_library():
    engine = balance.load(CONFIGS / "bramo-323.toml")
    with pytest.raises(balance.AnalysisError, match="applies to a pressure curve only") as caught:
        torque(engine, bore_m=0.154)
    assert caught.value.parameter == "bore_m"


@pytest.mark.parametrize("bore", [math.nan, math.inf, -0.154, 0.0, "0.154", None])
def test_torque_checks_the_bore_as_the_command_does(bore):
    """Guards against bores taken as they came: bore_m=nan gave a gas torque of mean 0.0 and NaN
    extremes, a negative bore was taken as its absolute value and a zero one as no gas."""
    import balance_cli as balance

    engine = balance.load(CONFIGS / "abc-dragonfly.toml")
    angles = np.arange(0.0, 720.0, 2.0)
    curve = balance.PressureCurve(angles, 1e5 + 4e6 * np.exp(-(((angles - 10) / 30) ** 2)), 720.0)
    if bore is None:  # the control: the [gas] bore, given explicitly, gives the [gas] torque
        np.testing.assert_allclose(
            balance.torque(engine, pressure=curve, bore_m=0.1397, bearings=False).gas.mean,
            balance.torque(engine, pressure=curve, bearings=False).gas.mean,
            rtol=1e-12,
        )
        return
    with pytest.raises(balance.BalanceError) as caught:
        balance.torque(engine, pressure=curve, bore_m=bore, bearings=False)
    assert caught.value.parameter == "bore_m"


def test_a_sharp_pressure_curve_warns_that_the_gas_torque_is_not_converged(tmp_path):
    """Guards against a silent aliasing: a compression ratio of 100 burning in 1° gave a mean gas
    torque 1.34 % above imep·V_d/(4π) at 256 samples without a word. The work of the cycle fixes
    the mean: one cylinder, imep 10 bar, V_d = π/4·(80 mm)²·80 mm, so 32.00 N·m exactly."""
    import warnings

    import balance_cli as balance

    text = (
        'name = "one"\ncycle = 4\nspeed = "3000 rpm"\ncrank_radius = "40 mm"\n'
        'rod_length = "140 mm"\n[masses]\nreciprocating = "500 g"\n[gas]\nbore = "80 mm"\n'
        'compression_ratio = 100\ncombustion_duration = 1\nimep = "10 bar"\n'
        "[[banks]]\nangle = 0\n[[throws]]\nphase = 0\n"
    )
    engine = balance.loads(text, "one.toml")
    exact = 10e5 * math.pi / 4 * 0.08**2 * 0.08 / (4 * math.pi)
    with pytest.warns(balance.SamplingWarning, match="gas torque is not converged at 256"):
        coarse = balance.torque(engine, bearings=False)
    assert abs(coarse.gas.mean / exact - 1) > 1e-2  # the aliasing warned about
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fine = balance.torque(engine, samples=2048, bearings=False)
    np.testing.assert_allclose(fine.gas.mean, exact, rtol=1e-5)
    config = tmp_path / "one.toml"
    config.write_text(text, encoding="utf-8")
    result = invoke("torque", config)
    assert result.exit_code == 0
    assert result.stderr.startswith("warning: one: the gas torque is not converged"), result.stderr
    assert "(--samples)" in result.stderr
