"""Firing orders and intervals, against hand-worked crank diagrams."""

import math

import pytest
from numpy.testing import assert_allclose

from balance_cli import load
from balance_cli.analysis.firing import firing_sequence as firing
from balance_cli.errors import FiringError, ModelError
from balance_cli.model import Cylinder, Engine, Throw
from tests.support import CONFIGS, make_engine

INLINE4 = [(0, 0.0), (180, 0.1), (180, 0.2), (0, 0.3)]


def test_given_inline4_order_fires_every_180_degrees():
    fire = firing(make_engine([0], INLINE4, firing_order=(1, 3, 4, 2)))
    assert fire.order == (1, 3, 4, 2) and fire.given and fire.uniform
    assert_allclose(fire.angles_deg, [0, 180, 360, 540], atol=1e-6)
    assert_allclose(fire.intervals_deg, [180] * 4, atol=1e-6)


def test_order_that_does_not_fit_the_crank_is_refused():
    """1-4-2-3 on a flat crank: 1 and 4 share TDC, so 4 fires at 360°, 2 at 540° and 3
    would need 720°: past the cycle."""
    with pytest.raises(FiringError, match="cannot fire after cylinder 2"):
        firing(make_engine([0], INLINE4, firing_order=(1, 4, 2, 3)))


def test_order_that_is_not_a_permutation_is_refused_when_the_engine_is_built():
    with pytest.raises(ModelError, match="not a permutation") as caught:
        make_engine([0], INLINE4, firing_order=(1, 3, 3, 2))
    assert caught.value.parameter == "firing_order"


def test_most_uniform_order_of_a_nine_cylinder_radial_skips_every_other_cylinder():
    """Four-stroke, one throw, cylinders 40° apart: firing every other one gives 80°."""
    fire = firing(make_engine([40 * i for i in range(9)], [(0, 0.0)]))
    assert fire.order == (1, 3, 5, 7, 9, 2, 4, 6, 8) and not fire.given
    assert_allclose(fire.intervals_deg, [80] * 9, atol=1e-6)


def test_most_uniform_inline4_order_is_one_of_the_two_classic_ones():
    fire = firing(make_engine([0], INLINE4))
    assert fire.order in {(1, 3, 4, 2), (1, 2, 4, 3)}
    assert fire.uniform


def test_two_stroke_fires_at_every_tdc_and_may_fire_two_together():
    """Nakanishi's point: a two-stroke in-line 4 on a flat crank fires two cylinders at once."""
    fire = firing(make_engine([0], INLINE4, cycle=2))
    assert_allclose(sorted(fire.intervals_deg), [0, 0, 180, 180], atol=1e-6)
    assert not fire.uniform
    given = firing(make_engine([0], INLINE4, cycle=2, firing_order=(1, 4, 2, 3)))
    assert_allclose(given.angles_deg, [0, 0, 180, 180], atol=1e-6)


def test_library_firing_figures():
    """Library engines: car in-line 4 every 180°, Part III W12 every 60°, in-line 12 every 60°."""
    for name, interval in [
        ("inline-4-car.toml", 180),
        ("inline-12.toml", 60),
        ("tanaka-part3/2a-w12-60.toml", 60),
        ("tanaka-part3/3-inline-6.toml", 120),
    ]:
        fire = firing(load(CONFIGS / name))
        assert fire.uniform, name
        assert_allclose(fire.intervals_deg, [interval] * len(fire.order), atol=1e-6)


def test_eighteen_cylinder_two_row_radial_fires_every_40_degrees():
    """Two rows of nine, the rear row turned 20° and on a throw at 180°: the rear row's TDCs
    fall at 20° + 180° + 40°k = 40°(k + 5), the front row's, so each 40° mark has two
    cylinders, one per revolution: 720°/18 = 40° is possible. 18 cylinders are past the
    exhaustive search, so this checks the local search."""
    front = [(40 * i, 0) for i in range(9)]
    rear = [(20 + 40 * i, 1) for i in range(9)]
    banks = tuple(math.radians(a) for a, _ in front + rear)
    throws = (Throw(0.0, 0.0), Throw(math.pi, 0.15))
    cylinders = tuple(
        Cylinder(i + 1, i + 1, t + 1, throws[t].z_m, 1.0) for i, (_, t) in enumerate(front + rear)
    )
    engine = Engine(
        name="two-row radial",
        cycle=4,
        speed_rad_s=200.0,
        crank_radius_m=0.08,
        rod_length_m=0.3,
        bank_angles_rad=banks,
        throws=throws,
        cylinders=cylinders,
    )
    fire = firing(engine)
    assert fire.uniform
    assert_allclose(fire.intervals_deg, [40.0] * 18, atol=1e-6)


def test_the_kept_firing_sequence_cannot_be_changed_by_a_caller():
    """The firing sequence is found once per engine and handed to every analysis: its top
    dead centres are read-only, so moving one cannot move the next torque's gas curves."""
    sequence = firing(load(CONFIGS / "abc-dragonfly.toml"))
    with pytest.raises(TypeError):
        sequence.tdc_deg[sequence.order[0]] += 30.0
    assert firing(load(CONFIGS / "abc-dragonfly.toml")) is sequence


def test_gaps_alike_are_shared_out_evenly_among_the_revolutions():
    """A four-stroke in-line 8 on a flat crank 0-180-180-0-0-180-180-0: its TDCs fall at 0° and
    180° only, four cylinders each, so every choice leaves gaps of 0° and 180°, four of each;
    but one puts two firings in each of the slots 0, 180, 360 and 540° and another three in
    one slot and one in the next. The phase sums Σ_j e^{2πi·m·a_j/720}, m = 1..7, are
    Σ_s c_s·i^{ms} over the slots' counts c_s: all zero for c_s = 2 but m = 4 (which gives 8),
    larger for any other counts: the even pairs are chosen."""
    crank = [(p, 0.1 * i) for i, p in enumerate((0, 180, 180, 0, 0, 180, 180, 0))]
    fire = firing(make_engine([0], crank))
    slots = [round(a) for a in fire.angles_deg]
    assert sorted(slots) == [0, 0, 180, 180, 360, 360, 540, 540]
