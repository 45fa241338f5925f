"""The balancing sheet: a 90° cross-plane V8's bobweights against the race shops' rule (100 %
rotating + 50 % reciprocating per journal, two rods a pin) by hand, from the configuration's
masses and from weighed parts; a chosen factor; a boxer; a single's and a twin's trade between
vertical and horizontal shaking by hand (the Triumph 650 used 85 %); errors."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import AnalysisError, CounterweightError
from balance_cli.workshop import PartSet, Piston, Rod
from tests.support import CONFIGS, JUMO, TODAY

V8 = TODAY / "v" / "v8-90-cross-plane.toml"
#: the V8 configuration gives 750 g reciprocating per cylinder; these rotating per pin
ROTATING_KG = 1.1
RECIPROCATING_KG = 0.75


@pytest.fixture(scope="module")
def v8():
    return balance.load(V8).edit(rotating=f"{ROTATING_KG} kg")


def test_cross_plane_v8_bobweights_are_the_race_shops_rule(v8):
    """Two rods a pin: 100 % of the pin's rotating mass (both big ends) and 50 % of its two
    cylinders' reciprocating masses: 1.1 + ½·2·0.75 = 1.85 kg on each of the four pins."""
    sheet = balance.bobweights(v8)
    assert [p.throw for p in sheet.pins] == [1, 2, 3, 4]
    for pin in sheet.pins:
        assert len(pin.cylinders) == 2
        assert_allclose(pin.rotating_kg, ROTATING_KG, rtol=1e-12)
        assert_allclose(pin.reciprocating_kg, 2 * RECIPROCATING_KG, rtol=1e-12)
        # the test mass is the forward first order of the pin's masses, from a 256-point FFT
        assert_allclose(pin.factor, 0.5, rtol=1e-9)
        assert_allclose(pin.bobweight_kg, ROTATING_KG + 0.5 * 2 * RECIPROCATING_KG, rtol=1e-9)
    assert sheet.trade == ()  # eight cylinders: no single's trade


def test_weighed_parts_make_each_pins_own_bobweight(v8):
    """Each pin by hand from its two cylinders' parts (in the order given: piston i and rod i in
    cylinder i): both big ends + ½·(both pistons + both small ends)."""
    rng = np.random.default_rng(3)
    pistons = 0.6 + rng.normal(0, 0.002, 8)
    small = 0.15 + rng.normal(0, 0.002, 8)
    big = 0.55 + rng.normal(0, 0.003, 8)
    parts = PartSet(
        tuple(Piston(f"P{i + 1}", m) for i, m in enumerate(pistons)),
        tuple(Rod(f"R{i + 1}", s, b) for i, (s, b) in enumerate(zip(small, big, strict=True))),
    )
    sheet = balance.bobweights(v8, parts)
    for pin in sheet.pins:
        assert len(pin.cylinders) == 2
        # cylinder n gets the n-th part listed: the order given, by cylinder number
        index = [n - 1 for n in pin.cylinders]
        by_hand = big[index].sum() + 0.5 * (pistons[index].sum() + small[index].sum())
        assert_allclose(pin.bobweight_kg, by_hand, rtol=1e-9)  # an FFT's first order
        assert_allclose(pin.rotating_kg, big[index].sum(), rtol=1e-12)


def test_a_chosen_factor_and_a_boxer():
    """A flat-twin boxer: one cylinder a pin; factor 0.6: rotating + 0.6 × reciprocating."""
    boxer = balance.load(TODAY / "boxer" / "boxer-2.toml").edit(rotating="0.4 kg")
    sheet = balance.bobweights(boxer, balance_factor=0.6)
    for pin in sheet.pins:
        assert len(pin.cylinders) == 1
        c = boxer.cylinder(pin.cylinders[0])
        assert_allclose(pin.bobweight_kg, 0.4 + 0.6 * c.reciprocating_kg, rtol=1e-12)
        assert pin.factor == 0.6


def test_a_singles_trade_by_hand():
    """One cylinder, counterweights for F·m at crank radius: the first order left is
    (1 − F)·m·r·ω² along the axis (vertical) and F·m·r·ω² across it."""
    twin = balance.load(TODAY / "inline" / "inline-2-360.toml")
    single = twin.replace(
        cylinders=twin.cylinders[:1], throws=twin.throws[:1], firing_order=None, name="single"
    )
    m, r, omega = 0.55, 0.034, 7000 * math.pi / 30
    sheet = balance.bobweights(single, factors=(0.5, 0.85))
    for trade in sheet.trade:
        f = trade.factor
        assert_allclose(
            [trade.force_vertical_n, trade.force_horizontal_n],
            [(1 - f) * m * r * omega**2, f * m * r * omega**2],
            rtol=1e-9,  # an FFT's first order against rounding
        )
        assert trade.moment_vertical_nm == 0.0 == trade.moment_horizontal_nm


def test_the_triumph_twins_85_percent_by_hand():
    """A 360° twin is a single doubled: at 85 % it shakes 0.15·2m·r·ω² vertically and
    0.85·2m·r·ω² horizontally, and no couple (both pistons move together)."""
    twin = balance.load(TODAY / "inline" / "inline-2-360.toml")
    m, r, omega = 0.55, 0.034, 7000 * math.pi / 30
    sheet = balance.bobweights(twin)
    assert [t.factor for t in sheet.trade] == [0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85]
    last = sheet.trade[-1]
    assert_allclose(
        [last.force_vertical_n, last.force_horizontal_n],
        [0.15 * 2 * m * r * omega**2, 0.85 * 2 * m * r * omega**2],
        rtol=1e-9,
    )
    assert last.moment_vertical_nm == 0.0 and last.moment_horizontal_nm == 0.0


def test_what_cannot_be_balanced_on_a_machine_is_refused(v8):
    with pytest.raises(AnalysisError, match="rotary"):
        balance.bobweights(balance.load(CONFIGS / "clerget-rotary.toml"))
    with pytest.raises(AnalysisError, match="several crankshafts"):
        balance.bobweights(balance.load(JUMO))
    with pytest.raises(CounterweightError, match="balance_factor must be a fraction"):
        balance.bobweights(v8, balance_factor=1.5)
    with pytest.raises(CounterweightError, match="balance_factor must be a fraction"):
        balance.bobweights(v8, factors=(0.5, -0.1))
    with pytest.raises(AnalysisError, match="factors needs one balance factor"):
        balance.bobweights(v8, factors=())
