"""Invariants on seeded random layouts, plain and articulated, fixed and rotary.

The expensive check (finite differences of the exact positions) runs on a fixed set of
layouts built to assemble; the cheap invariants (turning, mirroring, scaling) run under
hypothesis in test_shaking_properties.py.
"""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from balance_cli.analysis.shaking import shaking_forces as shaking
from balance_cli.kinematics.linkage import check_assembly, linkage_state
from tests.support import make_engine

SAMPLES = 256
MAX_ORDER = 60
CASES = 24


def random_engine(seed, frame="fixed"):
    rng = np.random.default_rng(seed)
    n_banks = int(rng.integers(1, 4))
    n_throws = int(rng.integers(1, 5))
    r = rng.uniform(0.03, 0.1)
    rod = r * rng.uniform(3.0, 5.0)
    links = None
    if n_banks > 1 and rng.random() < 0.6:
        # a link rod a bit shorter than the master rod, pinned well inside the big end
        links = (
            int(rng.integers(0, n_banks)),
            rod - rng.uniform(0.5, 0.9) * r,
            rng.uniform(0.5, 0.9) * r,
            rng.uniform(0.0, 0.5),
        )
    engine = make_engine(
        sorted(rng.uniform(-180, 180, n_banks)),
        [(rng.uniform(0, 360), rng.uniform(-0.3, 0.3)) for _ in range(n_throws)],
        r=r,
        rod=rod,
        m=rng.uniform(0.5, 3.0),
        rpm=rng.uniform(500, 5000),
        frame=frame,
        rotating=rng.uniform(0.0, 2.0),
        pin_offset=rng.uniform(-0.1, 0.1) * r,
        links=links,
    )
    check_assembly(engine)
    return engine


def scale(engine):
    return engine.unit_force_n * engine.n_cylinders


ENGINES = [random_engine(seed, frame) for seed in range(CASES) for frame in ("fixed", "rotary")]


@pytest.mark.parametrize("seed", range(CASES))
def test_mirror_symmetric_crankshaft_has_no_free_moments(seed):
    """Throw j and its mirror image have the same phase at z and −z: every moment cancels."""
    rng = np.random.default_rng(1000 + seed)
    half = [(rng.uniform(0, 360), rng.uniform(0.05, 0.4)) for _ in range(int(rng.integers(1, 4)))]
    throws = half + [(phase, -z) for phase, z in reversed(half)]
    banks = sorted(rng.uniform(-90, 90, int(rng.integers(1, 3))))
    links = (0, 0.22, 0.05, 0.4) if len(banks) > 1 else None
    engine = make_engine(banks, throws, r=0.08, rod=0.28, rotating=1.2, links=links)
    result = shaking(engine, SAMPLES, MAX_ORDER)
    tol = 1e-10 * scale(engine)
    for order in result.orders:
        assert abs(order.moment_forward) < tol and abs(order.moment_backward) < tol


@pytest.mark.parametrize("engine", ENGINES[::3])
def test_time_domain_resultant_equals_the_sum_of_its_orders(engine):
    """−Σm·ẍ by Richardson-extrapolated central differences of the exact positions
    (independent of the FFT) against Σ_k X⁺e^{ikθ} + X⁻e^{−ikθ}, k = 1..60, to 1e-9 of
    m·r·ω²·n. Orders above 60 are far below that for l/r ≥ 3."""
    result = shaking(engine, SAMPLES, MAX_ORDER)
    angles = 2 * np.pi * np.arange(SAMPLES) / SAMPLES

    def weighted(a):
        masses = linkage_state(engine, a).masses
        return masses.masses_kg @ masses.positions

    h, levels = 0.02, 4
    table = [
        (weighted(angles + h / 2**i) - 2 * weighted(angles) + weighted(angles - h / 2**i))
        / (h / 2**i) ** 2
        for i in range(levels)
    ]
    for j in range(1, levels):
        table = [(4**j * table[i + 1] - table[i]) / (4**j - 1) for i in range(len(table) - 1)]
    direct = -table[0] * engine.speed_rad_s**2
    summed = sum(
        o.force_forward * np.exp(1j * o.order * angles)
        + o.force_backward * np.exp(-1j * o.order * angles)
        for o in result.orders
    )
    assert_allclose(summed / scale(engine), direct / scale(engine), atol=1e-9)


def test_random_layouts_include_links_and_both_frames():
    """Guard that the generator really covers what the tests above claim."""
    assert any(any(c.is_link for c in e.cylinders) for e in ENGINES)
    assert any(not any(c.is_link for c in e.cylinders) for e in ENGINES)
    assert {e.frame for e in ENGINES} == {"fixed", "rotary"}
    assert any(e.pin_offset_m != 0.0 and math.isfinite(e.pin_offset_m) for e in ENGINES)
