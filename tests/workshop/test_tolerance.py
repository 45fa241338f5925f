"""What a tolerance band leaves: a flat-crank in-line 4's first-order force and couple under a
reciprocating scatter σ against their half-normal laws worked out by hand, the Monte Carlo
within its own sampling error; a phase scatter by hand; every run's linkage closed in a batch
against the engine's own analysis; the runs independent of how they are batched; errors."""

import math
import sys

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.shaking import shaking_forces
from balance_cli.errors import AnalysisError, ConfigError
from balance_cli.model import ToleranceBand
from balance_cli.workshop.basis import unit_basis
from balance_cli.workshop.runs import Draws, geometry_of, run_coefficients
from tests.support import CONFIGS, JUMO, TODAY

M, R, RPM = 0.55, 0.043, 6000.0
RW2 = R * (RPM * math.pi / 30) ** 2
SIGMA = 0.002  # kg
Z = np.array([0.0, 0.088, 0.176, 0.264])
SIGNS = np.array([1.0, -1.0, -1.0, 1.0])  # cos β of the flat crank 0-180-180-0
FLAT_4 = """\
name = "In-line 4, flat crank"
cycle = 4
speed = "6000 rpm"
crank_radius = "43 mm"
rod_length = "143 mm"
firing_order = [1, 3, 4, 2]

[masses]
reciprocating = "550 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 180
z = "88 mm"
[[throws]]
phase = 180
z = "176 mm"
[[throws]]
phase = 0
z = "264 mm"

[tolerances]
reciprocating = "2 g"
"""
#: the standard normal's 95th percentile of |N| (the two-sided 95 % point), to 7 digits
Z975 = 1.959964


@pytest.fixture(scope="module")
def flat_4():
    engine = balance.loads(FLAT_4, "flat-4.toml")
    return engine, balance.tolerance(engine, max_order=2)


def _within(stats, expected_mean, expected_p95):
    """The Monte Carlo's mean within four of its standard errors of ``expected_mean``, and
    ``expected_p95`` inside its 95th percentile's 95 % interval, widened by a tenth for the
    interval's own chance to miss."""
    assert abs(stats.mean - expected_mean) < 4 * stats.mean_error, (stats.mean, expected_mean)
    low, high = stats.p95_interval
    width = high - low
    assert low - 0.1 * width <= expected_p95 <= high + 0.1 * width, (stats.p95, expected_p95)


def test_the_first_order_force_is_a_half_normal_of_2_sigma(flat_4):
    """F₁ = Σ δmᵢ·cos(θ + βᵢ)·r·ω² along the axis: amplitude |Σ sᵢ·δmᵢ|·r·ω², sᵢ = ±1, which
    is |N(0, 4σ²)|·r·ω²: mean 2σ·√(2/π)·r·ω², 95th percentile 1.96·2σ·r·ω²."""
    _, result = flat_4
    mean = 2 * SIGMA * math.sqrt(2 / math.pi) * RW2
    p95 = Z975 * 2 * SIGMA * RW2
    first = result.order(1)
    _within(first.force["vertical"], mean, p95)
    linear = first.linear_force["vertical"]
    assert linear.model == "zero-mean"
    # the closed form's mean is exact (an elliptic integral of a degenerate ellipse) on
    # gradients from central differences of ±1 % of σ of a linear function: rounding, 1e-9;
    # its percentile a bisection of the trapezoidal rule's CDF (rounding of the 1.96: 1e-6)
    assert_allclose(linear.mean, mean, rtol=1e-9)
    assert_allclose(linear.p95, p95, rtol=1e-6)
    assert_allclose(linear.rms, 2 * SIGMA * RW2, rtol=1e-9)
    # a line force: no horizontal part, and the ellipse's max is the vertical amplitude
    assert first.force["horizontal"].max < 1e-9 * RW2
    assert_allclose(
        result.values["force_max"][:, 0], result.values["force_vertical"][:, 0], rtol=1e-9
    )


def test_the_first_order_couple_likewise(flat_4):
    """M₁ = Σ δmᵢ·sᵢ·(zᵢ − z̄)·r·ω²: |N(0, Σ(sᵢ·zᵢ)²·σ²)|·r·ω²."""
    _, result = flat_4
    spread = math.sqrt(np.sum((SIGNS * (Z - Z.mean())) ** 2)) * SIGMA * RW2
    mean, p95 = spread * math.sqrt(2 / math.pi), Z975 * spread
    first = result.order(1)
    _within(first.moment["vertical"], mean, p95)
    assert_allclose(first.linear_moment["vertical"].mean, mean, rtol=1e-9)  # as the force
    assert_allclose(first.linear_moment["vertical"].p95, p95, rtol=1e-6)


def test_the_second_order_spreads_about_its_nominal(flat_4):
    """The second order's nominal 4·m·r·ω²·A₂ moves by Σ δmᵢ·r·ω²·A₂ (all in phase): normal,
    about the nominal, its standard deviation 2σ times the nominal over 4m."""
    engine, result = flat_4
    nominal = balance.analyse(engine, max_order=2).order(2)
    size = abs(nominal.force_forward) + abs(nominal.force_backward)
    linear = result.order(2).linear_force["vertical"]
    assert linear.model == "about the nominal"
    assert_allclose(linear.nominal, size, rtol=1e-12)
    assert_allclose(linear.p95 - size, 1.6448536 * 2 * SIGMA * size / (4 * M), rtol=1e-6)
    stats = result.order(2).force["vertical"]
    assert abs(stats.mean - size) < 4 * stats.mean_error


def test_a_phase_scatter_by_hand():
    """Throws 2-4 off by δⱼ (throw 1 is the reference): the first-order phasor Σ sⱼ·e^{iδⱼ}
    gains i·Σ sⱼ·δⱼ, so the vertical amplitude is m·r·ω²·|Σ sⱼ·δⱼ|, |N(0, 3σ²)|·m·r·ω²; each
    run's linkage is closed with its own phases."""
    engine = balance.loads(FLAT_4, "flat-4.toml")
    sigma = math.radians(0.05)
    result = balance.tolerance(engine, ToleranceBand(phase_rad=sigma), runs=4000, max_order=1)
    assert result.method == "linkage"
    spread = math.sqrt(3) * sigma * M * RW2
    _within(result.order(1).force["vertical"], spread * math.sqrt(2 / math.pi), Z975 * spread)
    # linear by central differences of the closed linkage: to the step's second order
    assert_allclose(
        result.order(1).linear_force["vertical"].mean, spread * math.sqrt(2 / math.pi), rtol=1e-6
    )


@pytest.mark.parametrize(
    "path",
    [
        CONFIGS / "abc-dragonfly.toml",  # link rods
        CONFIGS / "clerget-rotary.toml",  # a rotary
        TODAY / "vr" / "vw-vr6.toml",  # pin offsets
        TODAY / "h" / "brm-h16.toml",  # two crankshafts
        CONFIGS / "inline-4-car-lanchester.toml",  # balancer shafts as built
    ],
)
def test_a_runs_linkage_is_the_engines_own_analysis(path):
    """The batched linkage at the engine's own dimensions and masses gives the coefficients
    its own analysis does, to rounding (1e-10 of m·r·ω²: the FFT's aliasing noise)."""
    engine = balance.load(path)
    geometry = geometry_of(engine)
    draws = Draws(
        np.array([[c.reciprocating_kg for c in engine.cylinders]]),
        np.array([[engine.rotating_of(i) for i in range(len(engine.throws))]]),
        geometry,
    )
    force, moment = run_coefficients(engine, draws, 256, unit_basis(engine, 256, 8))
    own = shaking_forces(engine, 256, 8)
    scale = engine.unit_force_n
    assert_allclose(force[0], own.force_coefficients, atol=1e-10 * scale, rtol=0)
    assert_allclose(moment[0], own.moment_coefficients, atol=1e-10 * scale, rtol=0)


def test_the_same_seed_draws_the_same_runs_whatever_the_batches(monkeypatch):
    engine = balance.loads(FLAT_4, "flat-4.toml")
    band = ToleranceBand(reciprocating_kg=SIGMA, crank_radius_m=2e-5)
    one = balance.tolerance(engine, band, runs=300, seed=7, max_order=2)
    # the module that batches the runs
    module = sys.modules["balance_cli.workshop.production"]
    monkeypatch.setattr(module, "_BLOCK", 4096)  # batches of a few runs
    two = balance.tolerance(engine, band, runs=300, seed=7, max_order=2)
    assert_allclose(one.values["force_vertical"], two.values["force_vertical"], rtol=1e-12)
    other = balance.tolerance(engine, band, runs=300, seed=8, max_order=2)
    assert not np.allclose(one.values["force_vertical"], other.values["force_vertical"])


def test_the_band_is_read_from_the_configuration_and_refused_where_it_cannot_be():
    engine = balance.loads(FLAT_4, "flat-4.toml")
    assert engine.tolerances == ToleranceBand(reciprocating_kg=SIGMA)
    bare = engine.replace(tolerances=None)
    with pytest.raises(AnalysisError, match=r"tolerances are not given.*\[tolerances\] table"):
        balance.tolerance(bare)
    with pytest.raises(AnalysisError, match="tolerances scatter nothing"):
        balance.tolerance(bare, ToleranceBand())
    with pytest.raises(AnalysisError, match="runs must"):
        balance.tolerance(engine, runs=1)
    jumo = balance.load(JUMO)
    with pytest.raises(AnalysisError, match="opposed pistons"):
        balance.tolerance(jumo, ToleranceBand(rod_length_m=1e-5), runs=10)
    wide = ToleranceBand(rod_length_m=0.05)
    with pytest.raises(AnalysisError, match="rod unable to reach its axis"):
        balance.tolerance(engine, wide, runs=2000)
    with pytest.raises(ConfigError, match=r"tolerances\.phase: must be from 0 to 90"):
        balance.loads(FLAT_4.replace('reciprocating = "2 g"\n', "phase = 120\n"), "t.toml")
    with pytest.raises(ConfigError, match=r"tolerances\.rod: unknown key"):
        balance.loads(FLAT_4 + 'rod = "1 mm"\n', "t.toml")
    with pytest.raises(ConfigError, match=r"tolerances\.rotating: must not be negative"):
        balance.loads(FLAT_4 + 'rotating = "-1 g"\n', "t.toml")
