"""One kinematic state per engine and sampling grid: the linkage is closed once and every
analysis reads what it gave."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.firing import firing_angles
from balance_cli.analysis.pressure import CYCLE_GRID_DEG
from balance_cli.kinematics import (
    FINE_SAMPLES,
    fine_travel,
    kinematic_state,
    linkage,
    linkage_state,
)
from tests.support import REFERENCE, ROOT

MENDES = (REFERENCE / "opentorsion_ice" / "mendes2008.toml").read_text(encoding="utf-8")
GAS = '\n[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "15 bar"\n'


def fresh(text, name):
    """An engine no other test has analysed (the states are kept by engine)."""
    return balance.loads(text.replace('name = "', f'name = "{name}: ', 1), name)


@pytest.fixture
def closings(monkeypatch):
    """A counter of the linkage's closings (every one goes through close_linkage)."""
    count = {"n": 0}
    closed = linkage.close_linkage

    def counting(*args, **kwargs):
        count["n"] += 1
        return closed(*args, **kwargs)

    monkeypatch.setattr(linkage, "close_linkage", counting)
    return count


def test_torque_closes_the_linkage_once_per_grid_and_once_per_pin(closings):
    """The Mendes diesel with a [gas] cycle: the analysis grid, the gas cycle's fine grid and a
    virtual shift of each of its six crank pins: 8 (15 before the one kinematic state)."""
    engine = fresh(MENDES + GAS, "torque closings")
    balance.torque(engine)
    assert closings["n"] == 1 + 1 + len(engine.throws) == 8
    # the same engine again: everything but the pins' virtual shifts is kept
    balance.torque(engine)
    assert closings["n"] == 8 + len(engine.throws)


def test_torsional_vibration_closes_the_linkage_twice(closings):
    """Its throws' inertias and its cylinders' torques read one state; the gas cycle the fine
    grid (9 closings before)."""
    pytest.importorskip("opentorsion")
    balance.torsional_vibration(fresh(MENDES + GAS, "torsion closings"))
    assert closings["n"] == 2


def test_analyses_of_one_engine_share_its_state(closings):
    engine = fresh(MENDES, "shared state")
    balance.analyse(engine)
    balance.counterweights(engine)
    balance.cylinder_torques(engine)
    assert closings["n"] == 1
    assert kinematic_state(engine, 256) is kinematic_state(engine, 256)
    # another grid is another state
    assert kinematic_state(engine, 512).samples == 512 and closings["n"] == 2


def test_the_fine_grid_travel_is_the_closed_linkage_at_those_angles():
    """Second method: the linkage closed directly at the firing angle plus each angle of the
    gas cycle's grid (as the gas cycle read it before). The shift theorem on the fine grid
    agrees to rounding: 1e-14 of the stroke."""
    for config in (
        "configs/abc-dragonfly.toml",
        "configs/today/opposed-piston/junkers-jumo-205.toml",
    ):
        engine = balance.load(ROOT / config)
        fire = firing_angles(engine)
        for c in engine.cylinders[:3]:
            direct = linkage_state(engine, np.radians(fire[c.number] + CYCLE_GRID_DEG)).travel
            shifted = fine_travel(engine, c.number, fire[c.number] - 180.0)
            stroke = np.ptp(direct[c.number])
            assert_allclose(shifted, direct[c.number], rtol=0, atol=1e-14 * stroke)


def test_the_fine_grid_is_the_gas_cycles_grid():
    assert FINE_SAMPLES == round(360.0 / (CYCLE_GRID_DEG[1] - CYCLE_GRID_DEG[0]))
    assert len(CYCLE_GRID_DEG) == FINE_SAMPLES + 1


def test_travel_rates_are_the_derivative_of_travel():
    """ds/dθ of a plain rod, by hand: r·sin θ·(1 + λ·cos θ/√(1 − λ²sin²θ)) (outward travel
    falls after TDC, so the rate is its negative), to 1e-12 of r."""
    engine = fresh(MENDES, "rates")
    state = kinematic_state(engine, 256)
    r, rod = engine.crank_radius_m, engine.rod_length_m
    lam = r / rod
    c = engine.cylinders[0]
    theta = state.angles_rad + engine.throws[c.throw_index].phase_rad
    by_hand = (
        -r * np.sin(theta) * (1 + lam * np.cos(theta) / np.sqrt(1 - (lam * np.sin(theta)) ** 2))
    )
    assert_allclose(state.travel_rates[c.number], by_hand, rtol=0, atol=1e-12 * r)


def test_kept_states_are_bounded(monkeypatch):
    """Memory is bounded: past the budget the oldest state goes (the newest always stays)."""
    from balance_cli.kinematics import state as module

    monkeypatch.setattr(module, "_KEPT_BYTES", 1)
    first = fresh(MENDES, "bounded 1")
    kept = kinematic_state(first, 64)
    kinematic_state(fresh(MENDES, "bounded 2"), 64)
    assert kinematic_state(first, 64) is not kept
    assert math.isclose(kinematic_state(first, 64).travel[1][0], kept.travel[1][0])


def test_only_the_most_recent_states_are_kept():
    """A command that goes through a library keeps the last few states, not every engine's:
    the fifth new state lets the first go, the second is still kept."""
    engines = [fresh(MENDES, f"recent {i}") for i in range(5)]
    states = [kinematic_state(e, 64) for e in engines[:2]]
    for e in engines[2:]:
        kinematic_state(e, 64)
    assert kinematic_state(engines[1], 64) is states[1]
    assert kinematic_state(engines[0], 64) is not states[0]


def test_a_kept_state_cannot_be_changed_in_place():
    """Every analysis of the engine reads the same arrays: writing into one is refused."""
    state = kinematic_state(fresh(MENDES, "read-only"), 64)
    for array in (
        state.masses.positions,
        state.rods.directions,
        state.travel[1],
        state.crankshaft_travel[0][1],
        state.angles_rad,
    ):
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 0.0


def test_a_kept_states_tables_cannot_be_changed_either():
    """Its mappings and rates are read-only too: replacing a cylinder's travel, or writing
    into its rate, would reach the next analysis."""
    state = kinematic_state(fresh(MENDES, "read-only tables"), 64)
    with pytest.raises(TypeError):
        state.travel[1] = state.travel[1] * 0
    with pytest.raises(TypeError):
        state.crankshaft_travel[0] = {}
    with pytest.raises(ValueError, match="read-only"):
        state.travel_rates[1][0] = 0.0
    with pytest.raises(ValueError, match="read-only"):
        state.crankshaft_travel_rates[0][1][0] = 0.0


@pytest.mark.parametrize("samples", [0, -4, 3, True, 2.5, "256"])
def test_a_state_needs_a_whole_number_of_samples(samples):
    with pytest.raises(balance.ModelError, match="samples must be a whole number from 4"):
        kinematic_state(fresh(MENDES, "samples"), samples)
