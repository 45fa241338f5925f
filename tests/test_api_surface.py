"""The library's public face: every name listed and reachable the same way every time, every
exception under BalanceError in one module, numbers from 1 and results with to_dict()."""

import ast
import importlib
import inspect
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = ROOT / "configs"


def test_every_public_name_is_listed_and_resolves():
    listed = set(dir(balance))
    assert set(balance.__all__) <= listed
    for name in balance.__all__:
        assert getattr(balance, name) is not None, name


def test_names_loaded_on_first_use_and_subpackages_resolve_the_same_every_time():
    """``balance.search`` stays the function whatever imports the search's modules, and
    ``balance.torsion`` is the subpackage before and after torsional vibration is used (it
    was an AttributeError, then the module, in 0.1)."""
    code = (
        "import balance_cli as b, importlib\n"
        "assert b.torsion.__name__ == 'balance_cli.torsion'\n"
        "f = b.search\n"
        "importlib.import_module('balance_cli.cranksearch.run')\n"
        "assert b.search is f and callable(b.search)\n"
        "assert b.torsional_vibration.__name__ == 'torsional_vibration'\n"
        "assert b.torsion.__name__ == 'balance_cli.torsion'\n"
        "assert 'matplotlib' not in __import__('sys').modules\n"
        "assert callable(b.plot.locus)\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'nothing_here'"):
        balance.nothing_here  # noqa: B018


def test_every_exception_lives_in_errors_under_balance_error():
    """A caller catches everything balance raises with one ``except BalanceError``; the
    classes are found by reading every module, not from a list."""
    defined = []
    for path in sorted((ROOT / "balance_cli").rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef) and any(
                getattr(b, "id", getattr(b, "attr", "")).endswith(
                    ("Error", "Exception", "Warning", "Unavailable")
                )
                for b in node.bases
            ):
                defined.append((path.relative_to(ROOT).as_posix(), node.name))
    assert defined and {p for p, _ in defined} == {"balance_cli/errors.py"}, defined
    errors = importlib.import_module("balance_cli.errors")
    for _, name in defined:
        cls = getattr(errors, name)
        assert issubclass(cls, balance.BalanceError) or issubclass(cls, Warning), name
        assert getattr(balance, name) is cls


def test_what_users_read_and_write_is_numbered_from_one():
    """The files' numbers, in the model: cylinder 2 of the in-line 4 sits on throw 2 of bank
    1; the built counterweight's throw is the file's."""
    engine = balance.load(CONFIGS / "inline-4-car.toml")
    second = engine.cylinder(2)
    assert (second.bank, second.throw) == (1, 2)
    assert engine.throws[second.throw_index] is engine.throws[1]
    assert all(t.crankshaft == 1 for t in engine.throws)
    with pytest.raises(balance.ModelError, match="throw is a number from 1, got 0"):
        balance.Cylinder(1, 1, 0, 0.0, 1.0)
    built = balance.loads(
        (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
        + '\n[[counterweights]]\nthrow = 3\nmass_radius = "0.01 kg*m"\n'
        "angle = 180\n",
        "weights.toml",
    )
    assert built.counterweights[0].throw == 3 and built.counterweights[0].throw_index == 2
    torques = balance.cylinder_torques(engine)
    assert [c.throw for c in torques] == [c.throw for c in engine.cylinders]


DIMENSIONAL = (
    "radius",
    "bore",
    "inertia",
    "speed",
    "speeds",
    "pitch",
    "power",
    "period",
    "step",
    "offsets",
    "eccentricity",
)
UNITS = ("_m", "_kg", "_rad", "_deg", "_rpm", "_rad_s", "_w", "_nm", "_kgm2", "_pa")


def unitless(function):
    """The parameters of ``function`` that name a dimensional quantity without its unit."""
    return [
        p
        for p in inspect.signature(function).parameters
        if p.startswith(DIMENSIONAL) or p.endswith(DIMENSIONAL)
        if not p.endswith(UNITS)
    ]


def test_parameters_carry_their_units():
    """SI, or the engineer's unit in the name: every parameter of a public function that is a
    length, mass, speed, angle, inertia or power ends in its unit."""
    found = {
        name: unitless(getattr(balance, name))
        for name in balance.__all__
        if inspect.isfunction(getattr(balance, name))
    }
    assert len(found) > 20
    assert not {name: bad for name, bad in found.items() if bad}


def test_the_unit_check_finds_a_parameter_without_its_unit():
    def probe(engine, radius=None, speed_rpm=None, bore=None):
        pass

    assert unitless(probe) == ["radius", "bore"]


def test_results_are_objects_with_to_dict_not_tuples(tmp_path):
    """Each result below was a bare tuple in 0.1; its dict is JSON and holds its values."""
    engine = balance.load(CONFIGS / "abc-dragonfly.toml")
    torques = balance.cylinder_torques(engine)
    total = balance.torque(engine)
    summed = sum(c.inertia.curve + c.gas.curve for c in torques)
    assert_allclose(summed, total.total.curve, rtol=0, atol=1e-9 * np.abs(total.total.curve).max())
    document = json.loads(json.dumps(torques.to_dict()))
    assert [c["cylinder"] for c in document["cylinders"]] == [c.number for c in engine.cylinders]
    assert torques.cylinder(3).number == 3 and len(torques) == engine.n_cylinders

    without = balance.power_related_unbalance(
        balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))
    )
    assert not without.available and "no power" in without.note
    assert without.to_dict() == {"note": without.note}

    path = tmp_path / "torque.csv"
    path.write_text(
        "angle_deg,torque_Nm\n"
        + "".join(f"{a},{math.sin(math.radians(a))}\n" for a in range(0, 720, 10))
    )
    curve = balance.read_cycle_csv(path, "torque")
    assert curve.cycle_deg == 720.0 and curve.quantity == "torque"
    assert json.loads(json.dumps(curve.to_dict()))["values_Nm"][9] == pytest.approx(1.0)

    configuration = balance.read_configuration(CONFIGS / "inline-4-car.toml")
    assert configuration.engine() == balance.load(CONFIGS / "inline-4-car.toml")
    assert (
        json.loads(json.dumps(configuration.to_dict()))["data"]["name"]
        == configuration.engine().name
    )
    assert balance.Plane(0.1, 2).to_dict() == {"z_m": 0.1, "throw": 2}


def test_a_lookup_of_what_a_result_does_not_hold_is_a_balance_error_and_a_key_error():
    engine = balance.load(CONFIGS / "inline-4-car.toml")
    torques = balance.cylinder_torques(engine)
    with pytest.raises(
        balance.NotInResultError,
        match=r"0 is not one of the engine's cylinders "
        r"\(1, 2, 3, 4\)",
    ) as caught:
        torques.cylinder(0)
    assert isinstance(caught.value, KeyError) and caught.value.parameter == "number"
    swept = balance.sweep(CONFIGS / "inline-4-car.toml", "speed", ["1000 rpm"], quantities="F2")
    with pytest.raises(balance.NotInResultError, match="'F9' is not among this sweep's"):
        swept.series("F9")
    with pytest.raises(balance.OrderError):
        balance.analyse(engine).order(99)
    assert issubclass(balance.OrderError, balance.NotInResultError)
