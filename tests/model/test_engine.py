"""The engine model built in code: every value checked when the engine is built or replaced,
collections made tuples, the defaults of its vertical, crankshafts and opposed pistons."""

import dataclasses
import math

import pytest

import balance_cli as balance
from balance_cli.errors import ModelError
from balance_cli.model import Cylinder, Throw
from tests.support import TWIN, make_engine


def test_two_cylinders_in_one_bore_are_refused_in_code():
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    with pytest.raises(ModelError, match="cylinder 3 sits in the bore of cylinder 1") as caught:
        dataclasses.replace(engine, cylinders=engine.cylinders + (Cylinder(3, 1, 1, 0.0, 1.0),))
    assert caught.value.cylinder == 3
    # side by side on one pin (its own z) is not one bore
    dataclasses.replace(engine, cylinders=engine.cylinders + (Cylinder(3, 1, 1, 0.02, 1.0),))


def test_non_finite_values_are_refused_in_code():
    engine = make_engine([0], [(0, 0.0)])
    for field, value in (
        ("speed_rad_s", math.inf),
        ("crank_radius_m", math.nan),
        ("rod_length_m", 1e300),
        ("rotating_kg", -1.0),
    ):
        with pytest.raises(ModelError, match=field):
            dataclasses.replace(engine, **{field: value})
    with pytest.raises(balance.CounterweightError, match="radius_m is invalid"):
        balance.counterweights(engine, radius_m=math.inf)
    with pytest.raises(balance.CounterweightError, match="balance_factor must be"):
        balance.counterweights(engine, balance_factor=math.nan)


def test_engine_fields_given_as_lists_become_tuples():
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    listed = dataclasses.replace(
        engine, throws=list(engine.throws), cylinders=list(engine.cylinders), firing_order=[1, 2]
    )
    assert listed.throws == engine.throws and hash(listed)
    assert balance.analyse(listed).order(2) == balance.analyse(engine).order(2)
    with pytest.raises(balance.ModelError, match="Throw objects"):
        dataclasses.replace(engine, throws=((0.0, 0.0),))
    with pytest.raises(balance.ModelError, match="firing_order"):
        dataclasses.replace(engine, firing_order=(1, "2"))
    with pytest.raises(balance.ModelError, match="cycle must be 2 or 4"):
        dataclasses.replace(engine, cycle=4.0)
    assert Throw(0.0).z_m == 0.0


def test_engine_replace_is_checked():
    engine = balance.loads(TWIN)
    assert engine.replace(speed_rad_s=100.0).speed_rad_s == 100.0
    with pytest.raises(balance.ModelError, match="not a field"):
        engine.replace(speed=1.0)
    with pytest.raises(balance.ModelError, match="rod_length_m"):
        engine.replace(rod_length_m=0.01)


def test_default_vertical_is_the_banks_bisector():
    """In-line: its axis; V: the bisector; banks that add up to nothing (a radial, a boxer):
    the reference axis."""
    assert make_engine([30], [(0, 0)]).vertical_axis_rad == pytest.approx(math.radians(30))
    assert make_engine([-30, 90], [(0, 0)]).vertical_axis_rad == pytest.approx(math.radians(30))
    radial = balance.load("configs/abc-dragonfly.toml")
    assert radial.vertical_axis_rad == 0.0
    assert make_engine([90, 270], [(0, 0)]).vertical_axis_rad == 0.0


def test_old_engines_have_one_reference_crankshaft():
    engine = balance.load("configs/inline-4-car.toml")
    assert engine.crankshafts == (balance.Crankshaft(),)
    assert not engine.has_several_crankshafts and not engine.has_opposed_pistons
    assert balance.torque(engine).crankshafts == ()


def test_the_api_takes_the_opposed_piston_mass_as_the_near_ones_by_default():
    cylinder = balance.Cylinder(1, 1, 1, 0.0, 2.0, opposed_throw=2)
    assert cylinder.opposed_reciprocating_kg == 2.0
    with pytest.raises(balance.ModelError, match="direction"):
        balance.Crankshaft(1.0, 0.0, -1.0)


def test_a_torsion_model_built_with_lists_keeps_the_engine_hashable():
    """Every analysis keeps what it finds by engine: a TorsionModel given lists in code, as a
    user writes it, made that a TypeError (unhashable list)."""
    from balance_cli import Engine, TorsionModel, analyse, load
    from tests.support import CONFIGS

    base = load(CONFIGS / "inline-4-car.toml")
    model = TorsionModel([0.01] * 4, 0.0, [1e5] * 3, [0.0] * 4)
    engine = base.replace(torsion=model)
    assert isinstance(engine, Engine) and engine.torsion.stiffness_nm_rad == (1e5, 1e5, 1e5)
    assert analyse(engine).order(2).force_forward == analyse(base).order(2).force_forward
