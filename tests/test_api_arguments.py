"""The library under hostile arguments: every public function of balance_cli called with
wrong types, NaN, inf, empty and absurd values must raise a BalanceError whose message names
the parameter, never AttributeError, TypeError, KeyError, IndexError, ZeroDivisionError,
OverflowError or scipy's ValueError, and never answer silently.

Each case is (label, call taking the bad value, the word the message must hold, bad values).
The controls at the end show that the good values the cases replace do work, so a refusal
below is the bad value's doing. One table for every public function: its machinery (the
fixture of engines and results, the placeholder that builds the test ids) serves them all."""

import dataclasses
import math
import warnings

import numpy as np
import pytest

import balance_cli as balance
from balance_cli.cranksearch import Term
from tests.support import CONFIGS, TEMPLATES

NAN, INF = math.nan, math.inf
#: what a careless or hostile caller passes for a number
NUMBERS = ["x", NAN, INF, -INF, -1, 0, 1e300, -1e300, [], (), {}, True, object(), 2j]
#: ... for something that must be a collection of things
COLLECTIONS = [None, "x", NAN, INF, 0, 1e300, [], (), True, object(), [1, 2], ["x"]]


@pytest.fixture(scope="module")
def world(tmp_path_factory):
    folder = tmp_path_factory.mktemp("api")
    pressure = folder / "pressure.csv"
    angles = np.arange(0.0, 720.0, 2.0)
    bars = 1.0 + 40.0 * np.exp(-(((angles - 10.0) / 30.0) ** 2))
    pressure.write_text(
        "angle_deg,pressure_bar\n"
        + "".join(f"{float(a)!r},{float(p)!r}\n" for a, p in zip(angles, bars, strict=True)),
        encoding="utf-8",
    )
    engine = balance.load(CONFIGS / "inline-4-car.toml")
    radial = balance.load(CONFIGS / "abc-dragonfly.toml")
    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    result = balance.analyse(engine)
    torques = balance.torque(radial)
    return dict(
        engine=engine,
        radial=radial,
        template=template,
        result=result,
        torques=torques,
        pressure=pressure,
        curve=balance.read_pressure_csv(pressure),
        folder=folder,
    )


def cases(w):
    """Every public entry and argument, with the bad values it must refuse."""
    e, d, t, r, tq = w["engine"], w["radial"], w["template"], w["result"], w["torques"]
    gas = tq.gas.curve
    replace = dataclasses.replace
    yield from [
        ("load", lambda v: balance.load(v), "path", [None, 3, NAN, [], True, object(), ""]),
        ("load_template", lambda v: balance.load_template(v), "path", [None, 3, [], ""]),
        ("loads.text", lambda v: balance.loads(v), "text", [None, 3, NAN, [], b"name = 'x'"]),
        ("loads.name", lambda v: balance.loads("name = 'x'", name=v), "name", [None, 3, []]),
        ("find_configs", lambda v: balance.find_configs(v), "paths", [None, 3, NAN, [3], [None]]),
        ("load_many", lambda v: balance.load_many(v), "paths", [None, 3, [3]]),
        ("analyse.engine", lambda v: balance.analyse(v), "engine", COLLECTIONS + [r]),
        ("analyse.samples", lambda v: balance.analyse(e, samples=v), "samples", NUMBERS + [2.5]),
        (
            "analyse.max_order",
            lambda v: balance.analyse(e, max_order=v),
            "max_order",
            NUMBERS + [2.5],
        ),
        ("compare.results", lambda v: balance.compare(v), "results", COLLECTIONS + [[e], [tq]]),
        (
            "compare.reference",
            lambda v: balance.compare([r], reference=v),
            "reference",
            [NAN, 3, [], object(), "no such engine"],
        ),
        ("compare.power_w", lambda v: balance.compare([r], power_w=v), "power_w", NUMBERS),
        (
            "counterweights.engine",
            lambda v: balance.counterweights(v),
            "engine",
            COLLECTIONS + [tq],
        ),
        (
            "counterweights.planes",
            lambda v: balance.counterweights(e, planes=v),
            "planes",
            [
                NAN,
                INF,
                3,
                "x",
                [],
                [NAN],
                [INF],
                [0.0],
                [balance.Plane(NAN)],
                [balance.Plane(INF)],
                [balance.Plane("x")],
                [balance.Plane(0.0, 99)],
                [balance.Plane(0.0, 0)],
                # throw 1 of the fixture's engine is not at 5 m
                [balance.Plane(5.0, 1)],
                [0],
                [99],
                [1, 2, 3],
                [object()],
            ],
        ),
        (
            "counterweights.radius_m",
            lambda v: balance.counterweights(e, radius_m=v),
            "radius_m",
            NUMBERS,
        ),
        (
            "counterweights.balance_factor",
            lambda v: balance.counterweights(e, balance_factor=v),
            "balance_factor",
            ["x", NAN, INF, -1, 1e300, [], True, object()],
        ),
        (
            "counterweights.shaft_orders",
            lambda v: balance.counterweights(e, shaft_orders=v),
            "shaft_orders",
            [None, NAN, 3, "1", [NAN], [0], [99], [1.5], [True]],
        ),
        (
            "counterweights.samples",
            lambda v: balance.counterweights(e, samples=v),
            "samples",
            NUMBERS,
        ),
        (
            "regression.baseline",
            lambda v: balance.regression(v, balance.compare([r])),
            "baseline",
            COLLECTIONS + [{}, {"engines": []}],
        ),
        (
            "regression.current",
            lambda v: balance.regression(balance.compare([r]).to_dict(), v),
            "current",
            COLLECTIONS,
        ),
        (
            "regression.rtol",
            lambda v: balance.regression(
                balance.compare([r]).to_dict(), balance.compare([r]), rtol=v
            ),
            "rtol",
            NUMBERS[:1] + [NAN, INF, -1, 1e300],
        ),
        ("torque.engine", lambda v: balance.torque(v), "engine", COLLECTIONS + [r]),
        ("torque.samples", lambda v: balance.torque(d, samples=v), "samples", NUMBERS),
        ("torque.max_order", lambda v: balance.torque(d, max_order=v), "max_order", NUMBERS),
        (
            "torque.pressure",
            lambda v: balance.torque(d, pressure=v),
            "pressure",
            ["x", NAN, 3, [], gas, w["pressure"]],
        ),
        (
            "torque.bore_m",
            lambda v: balance.torque(d, pressure=w["curve"], bore_m=v),
            "bore_m",
            NUMBERS,
        ),
        (
            "torque.inertia_kgm2",
            lambda v: balance.torque(d, inertia_kgm2=v),
            "inertia_kgm2",
            NUMBERS,
        ),
        ("torque.target", lambda v: balance.torque(d, target=v), "target", NUMBERS + [0.5, 0.25]),
        (
            "torque.load",
            lambda v: balance.torque(d, load=v, inertia_kgm2=3.0),
            "load",
            [None, "brake", NAN, 3, [], ["propeller"]],
        ),
        (
            "steadiness.torque_nm",
            lambda v: balance.steadiness(v, 720.0, 3.0, 170.0),
            "torque_nm",
            COLLECTIONS + [np.full(64, NAN), np.full(64, 5.0), np.ones((8, 8)), np.arange(8) + 1j],
        ),
        (
            "steadiness.period_deg",
            lambda v: balance.steadiness(gas, v, 3.0, 170.0),
            "period_deg",
            NUMBERS + [500, 359.9, None],
        ),
        (
            "steadiness.inertia_kgm2",
            lambda v: balance.steadiness(gas, 720.0, v, 170.0),
            "inertia_kgm2",
            NUMBERS + [None],
        ),
        (
            "steadiness.speed_rad_s",
            lambda v: balance.steadiness(gas, 720.0, 3.0, v),
            "speed_rad_s",
            NUMBERS + [None],
        ),
        (
            "steadiness.load",
            lambda v: balance.steadiness(gas, 720.0, 3.0, 170.0, load=v),
            "load",
            [None, "brake", NAN, 3, [], np.array(["propeller"])],
        ),
        (
            "steadiness.reduced_mass_kgm2",
            lambda v: balance.steadiness(gas, 720.0, 3.0, 170.0, reduced_mass_kgm2=v),
            "reduced_mass_kgm2",
            [
                "x",
                NAN,
                3,
                [],
                np.ones(3),
                np.full(len(gas), NAN),
                -np.ones(len(gas)),
                np.ones(len(gas) + 1),
            ],
        ),
        (
            "flywheel_for.target",
            lambda v: balance.flywheel_for(v, gas, 720.0, 170.0),
            "target",
            NUMBERS + [None, 0.5],
        ),
        (
            "flywheel_for.torque_nm",
            lambda v: balance.flywheel_for(50, v, 720.0, 170.0),
            "torque_nm",
            COLLECTIONS,
        ),
        (
            "flywheel_for.period_deg",
            lambda v: balance.flywheel_for(50, gas, v, 170.0),
            "period_deg",
            NUMBERS + [500, None],
        ),
        (
            "flywheel_for.speed_rad_s",
            lambda v: balance.flywheel_for(50, gas, 720.0, v),
            "speed_rad_s",
            NUMBERS + [None],
        ),
        (
            "read_pressure_csv.path",
            lambda v: balance.read_pressure_csv(v),
            "path",
            [None, 3, NAN, [], True],
        ),
        (
            "read_pressure_csv.cycle_deg",
            lambda v: balance.read_pressure_csv(w["pressure"], v),
            "cycle_deg",
            NUMBERS + [500],
        ),
        (
            "read_cycle_csv.quantity",
            lambda v: balance.read_cycle_csv(w["pressure"], v),
            "quantity",
            [None, "force", 3, NAN, []],
        ),
        (
            "search.template",
            lambda v: balance.search(v, "M1", workers=1),
            "template",
            COLLECTIONS + [r],
        ),
        (
            "search.objective",
            lambda v: balance.search(t, v, workers=1),
            "objective",
            [
                3,
                NAN,
                "",
                "M1:nan",
                "M1:-1",
                "M1:1e300",
                "M9",
                "M0",
                "Q1",
                [],
                [3],
                [Term("M", 1, weight=NAN)],
                [Term("M", 1, weight=-1.0)],
                [Term("M", 1, weight=INF)],
                [Term("M", 99)],
                [Term("Q", 1)],
                [Term("M", 1, part="sideways")],
                [Term("M", 1), Term("M", 1)],
                [Term("M", True)],
            ],
        ),
        (
            "search.top",
            lambda v: balance.search(t, "M1", top=v, workers=1),
            "top",
            NUMBERS + [100_000, 2.0],
        ),
        (
            "search.workers",
            lambda v: balance.search(t, "M1", workers=v),
            "workers",
            NUMBERS + [10**6],
        ),
        (
            "search.step_deg",
            lambda v: balance.search(t, "M1", allow_uneven=True, step_deg=v, workers=1),
            "step_deg",
            NUMBERS + [7.0, 1e-3, None],
        ),
        (
            "search.limit",
            lambda v: balance.search(t, "M1", limit=v, workers=1),
            "limit",
            NUMBERS + [10, 10**16],
        ),
        (
            "search.restarts",
            lambda v: balance.search(t, "M1", heuristic=True, restarts=v),
            "restarts",
            NUMBERS + [10**7],
        ),
        (
            "search.seed",
            lambda v: balance.search(t, "M1", heuristic=True, restarts=2, seed=v),
            "seed",
            NUMBERS[:1] + [NAN, INF, -1, 1e300, 2**64, [], True],
        ),
        (
            "search.samples",
            lambda v: balance.search(t, "M1", samples=v, workers=1),
            "samples",
            NUMBERS,
        ),
        (
            "search.scheduler",
            lambda v: balance.search(t, "M1", scheduler=v, workers=1),
            "scheduler",
            [NAN, 3, [], object(), "not an address"],
        ),
        (
            "search.progress",
            lambda v: balance.search(t, "M1", progress=v, workers=1),
            "progress",
            ["x", 3, NAN, []],
        ),
        ("TorqueSet", lambda v: balance.TorqueSet(v).to_dict(), "results", COLLECTIONS + [[r]]),
        (
            "PinForce.order",
            lambda v: tq.pins[0].order(v),
            "order",
            ["x", None, NAN, INF, -1, 1e300, 0.25, 10**6, [], True],
        ),
        (
            "Series.order",
            lambda v: tq.total.order(v),
            "order",
            ["x", None, NAN, INF, -1, 0, 1e300, 0.25, 99, []],
        ),
        (
            "EngineResult.order",
            lambda v: r.order(v),
            "order",
            ["x", None, NAN, INF, -1, 0, 1e300, 2.5, 99, [], True],
        ),
        (
            "Throw.phase_rad",
            lambda v: balance.Throw(v, 0.0),
            "phase_rad",
            ["x", None, NAN, INF, 1e300, [], True],
        ),
        ("Throw.z_m", lambda v: balance.Throw(0.0, v), "z_m", ["x", None, NAN, INF, 1e300, []]),
        (
            "Cylinder.reciprocating_kg",
            lambda v: balance.Cylinder(1, 1, 1, 0.0, v),
            "reciprocating_kg",
            ["x", None, NAN, INF, -1, 1e300, []],
        ),
        (
            "Cylinder.number",
            lambda v: balance.Cylinder(v, 1, 1, 0.0, 1.0),
            "number",
            ["x", None, NAN, -1, 0, 2.5, [], True],
        ),
        ("Engine.speed_rad_s", lambda v: replace(e, speed_rad_s=v), "speed_rad_s", NUMBERS),
        (
            "Engine.crank_radius_m",
            lambda v: replace(e, crank_radius_m=v),
            "crank_radius_m",
            NUMBERS,
        ),
        ("Engine.rod_length_m", lambda v: replace(e, rod_length_m=v), "rod_length_m", NUMBERS),
        ("Engine.name", lambda v: replace(e, name=v), "name", [None, 3, "", "a\nb", "x" * 10**4]),
        ("Engine.cycle", lambda v: replace(e, cycle=v), "cycle", NUMBERS + [3]),
        ("Engine.throws", lambda v: replace(e, throws=v), "throws", COLLECTIONS),
        ("Engine.cylinders", lambda v: replace(e, cylinders=v), "cylinders", COLLECTIONS),
        (
            "Engine.firing_order",
            lambda v: replace(e, firing_order=v),
            "firing_order",
            [NAN, 3, "1342", (1, 2, 3), (1, 1, 2, 3), (1, 2, 3, 9)],
        ),
        # the engine's vertical, Engine.replace, main orders, shaft offsets, sweeps, PRU, family
        (
            "Engine.vertical_rad",
            lambda v: e.replace(vertical_rad=v),
            "vertical_rad",
            ["x", NAN, INF, 1e300, [], True],
        ),
        (
            "Engine.replace",
            lambda v: e.replace(**{v: 1.0}),
            "Engine.replace",
            ["speed", "noise_floor_n", "_by_number"],
        ),
        (
            "Engine.replace.rod_length_m",
            lambda v: e.replace(rod_length_m=v),
            "rod_length_m",
            NUMBERS,
        ),
        (
            "EngineResult.main_order",
            lambda v: r.main_order(v),
            "part",
            [None, "torque", 3, NAN, [], True],
        ),
        (
            "counterweights.shaft_offsets_m",
            lambda v: balance.counterweights(e, shaft_orders=[2], shaft_offsets_m=v),
            "shaft_offsets_m",
            [
                "x",
                NAN,
                3,
                [],
                (NAN, 0.0),
                (INF, 0.0),
                (0.1,),
                (0.1, 0.2, 0.3),
                ("x", 0.0),
                {7: (0.1, 0.0)},
            ],
        ),
        (
            "sweep.configuration",
            lambda v: balance.sweep(v, "speed", ["1000 rpm"]),
            "configuration",
            [None, 3, NAN, [], True, {"name": "a parsed file, not wrapped"}],
        ),
        (
            "sweep.parameter",
            lambda v: balance.sweep(CONFIGS / "inline-4-car.toml", v, ["1000 rpm"]),
            "parameter",
            [None, 3, NAN, [], "", "no_such_key", "masses", "throws[99].phase"],
        ),
        (
            "sweep.values",
            lambda v: balance.sweep(CONFIGS / "inline-4-car.toml", "speed", v),
            "values",
            [None, 3, NAN, [], "1000 rpm", [NAN]],
        ),
        # a value the key cannot take is refused in the file's words: file, key, value
        (
            "sweep.values.speed",
            lambda v: balance.sweep(CONFIGS / "inline-4-car.toml", "speed", v),
            "speed = ",
            [["fast"], ["1000 kg"], ["-5 rpm"], ["1e300 rpm"]],
        ),
        (
            "sweep.quantities",
            lambda v: balance.sweep(
                CONFIGS / "inline-4-car.toml", "speed", ["1000 rpm"], quantities=v
            ),
            "quantities",
            [3, NAN, ["F0"], ["X2"], ["F99"], [3], ["F2", "F2"]],
        ),
        (
            "sweep.load",
            lambda v: balance.sweep(CONFIGS / "inline-4-car.toml", "speed", ["1000 rpm"], load=v),
            "load",
            ["x", None, 3, NAN, [], True],
        ),
        (
            "sweep.overrides",
            lambda v: balance.sweep(
                CONFIGS / "inline-4-car.toml", "rod_length", ["140 mm"], overrides=v
            ),
            "overrides",
            [
                5,
                "speed",
                NAN,
                [],
                [("speed", "1000 rpm")],
                {"speed": 5},
                {3: "x"},
                {"sped": "1 rpm"},
                {"balance_factor": 0.5},
                {"rod_length": "150 mm"},
            ],
        ),
        (
            "sweep.progress",
            lambda v: balance.sweep(
                CONFIGS / "inline-4-car.toml", "speed", ["1000 rpm"], progress=v
            ),
            "progress",
            ["x", 5, NAN, [], True],
        ),
        (
            "sweep_grid.parameters",
            lambda v: balance.sweep_grid(
                CONFIGS / "inline-4-car.toml", v, [["1000 rpm", "2000 rpm"], ["140 mm", "150 mm"]]
            ),
            "parameters",
            [None, 3, "speed", ["speed"], ["speed", "speed"], [3, "speed"], ("a", "b", "c")],
        ),
        (
            "sweep_grid.values",
            lambda v: balance.sweep_grid(CONFIGS / "inline-4-car.toml", ["speed", "rod_length"], v),
            "values",
            [
                None,
                3,
                "x",
                [],
                [["1000 rpm"]],
                [["1000 rpm", "2000 rpm"], 3],
                [["1000 rpm", "2000 rpm"], ["140 mm"]],
            ],
        ),
        (
            "power_related_unbalance.result",
            lambda v: balance.power_related_unbalance(v),
            "result",
            COLLECTIONS + [e],
        ),
        (
            "power_related_unbalance.power_w",
            lambda v: balance.power_related_unbalance(r, power_w=v),
            "power_w",
            NUMBERS,
        ),
        (
            "power_related_unbalance.classes",
            lambda v: balance.power_related_unbalance(r, classes=v),
            "classes",
            ["x", 3, NAN, [], ((1, "a"),), ((60, 1), (120, 2), (220, 3), (INF, 4))],
        ),
        # a str is a file's path: read_configuration's messages name the file
        (
            "family.configuration",
            lambda v: balance.family(v, [6]),
            "configuration",
            [c for c in COLLECTIONS if not isinstance(c, str)] + [{"name": "a parsed file"}],
        ),
        (
            "family.cylinders",
            lambda v: balance.family(
                balance.read_configuration(CONFIGS / "marine-6-2stroke.toml"), v, workers=1
            ),
            "cylinders",
            COLLECTIONS + ["5-12", [1], [25], [6.0]],
        ),
        (
            "family.pitch_m",
            lambda v: balance.family(
                balance.read_configuration(CONFIGS / "marine-6-2stroke.toml"),
                [6],
                pitch_m=v,
                workers=1,
            ),
            "pitch_m",
            NUMBERS,
        ),
        (
            "Configuration",
            lambda v: balance.Configuration(v, "x.toml"),
            "must be the parsed TOML",
            [None, 3, [], "name = 'x'"],
        ),
        (
            "sweep.quantities.steadiness",
            lambda v: balance.sweep(
                CONFIGS / "inline-4-car.toml", "speed", ["1000 rpm"], quantities=v
            ),
            "inertia_kgm2",
            [["steadiness"]],
        ),
    ]


def all_cases():
    """(label, index) of every case, built without the fixture (for the test ids)."""
    labels = []
    for label, _, _, values in cases(
        {
            k: _Placeholder()
            for k in (
                "engine",
                "radial",
                "template",
                "result",
                "torques",
                "pressure",
                "curve",
                "folder",
            )
        }
    ):
        labels += [(label, i) for i in range(len(values))]
    return labels


class _Placeholder:
    """Stands for the fixture's objects while the test ids are built."""

    def __getattr__(self, name):
        return _Placeholder()

    def __getitem__(self, key):
        return _Placeholder()

    def __len__(self):
        return 8


def _shown(value):
    text = repr(value)
    return text if len(text) < 30 else text[:27] + "..."


@pytest.mark.parametrize(
    "label, index", all_cases(), ids=[f"{label}-{index}" for label, index in all_cases()]
)
def test_a_hostile_argument_is_one_balance_error_naming_it(world, label, index):
    case = next(c for c in cases(world) if c[0] == label)
    _, call, word, values = case
    value = values[index]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a SamplingWarning is not the point here
        with pytest.raises(balance.BalanceError) as caught:
            call(value)
    message = str(caught.value)
    assert word in message or caught.value.parameter == word, (label, _shown(value), message)
    assert "\n" not in message and len(message) < 600, message


def test_the_good_values_the_cases_replace_work(world):
    """Controls: each call above succeeds with a good value in place of the bad one."""
    e, d, t, r, tq = (world[k] for k in ("engine", "radial", "template", "result", "torques"))
    gas = tq.gas.curve
    assert (
        balance.loads(
            (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8"), name="x.toml"
        ).name
        == e.name
    )
    assert balance.find_configs(str(CONFIGS / "inline-4-car.toml")) == [
        CONFIGS / "inline-4-car.toml"
    ]
    assert balance.analyse(e, samples=np.int64(64), max_order=np.int64(8)).samples == 64
    assert balance.compare([r], reference=e.name).reference is not None
    assert balance.compare([r], power_w=np.float64(5e4)).power_w == 5e4
    assert (
        len(
            balance.counterweights(
                e, planes=[1, 4], radius_m=0.06, balance_factor=0.5, shaft_orders=[2]
            ).counterweights
        )
        == 2
    )
    assert balance.torque(
        d,
        pressure=world["curve"],
        bore_m=np.float64(0.1397),
        inertia_kgm2=np.int64(3),
        target=50,
        load="constant",
    ).steadiness
    speed = balance.steadiness(
        gas,
        np.int64(720),
        np.int64(3),
        np.float64(170.0),
        reduced_mass_kgm2=tq.reduced_mass.curve_kgm2,
    )
    assert speed.factor > 1
    assert balance.flywheel_for(np.float64(50), gas, 720, 170.0) > 0
    assert balance.read_pressure_csv(world["pressure"]).cycle_deg == 720.0
    assert balance.read_pressure_csv(str(world["pressure"]), 720).cycle_deg == 720.0
    found = balance.search(
        t,
        [Term("M", 1, weight=np.float64(2.0))],
        top=np.int64(2),
        workers=np.int64(1),
        limit=np.int64(10**6),
    )
    assert found.exhaustive and len(found.arrangements) == 2
    assert balance.TorqueSet([tq]).to_dict()["engines"]
    forward, backward = tq.pins[0].order(np.float64(1.5))
    assert abs(forward) + abs(backward) > 0
    assert tq.total.order(np.int64(3)) == tq.total.order(3.0)
    assert r.order(np.int64(2)) is r.order(2)
    assert e.replace(vertical_rad=np.float64(0.5)).vertical_axis_rad == 0.5
    assert r.main_order("moment") is None and r.main_order("force")["order"] == 2
    assert balance.counterweights(e, shaft_orders=[2], shaft_offsets_m=(0.1, 0.0)).balancer_shafts
    pru = balance.power_related_unbalance(r, power_w=np.float64(5e4))
    assert pru.power.watts == 5e4
    table = balance.family(
        balance.read_configuration(CONFIGS / "marine-6-2stroke.toml"),
        [np.int64(6)],
        pitch_m=np.float64(1.02),
        workers=1,
    )
    assert table.rows[0].cylinders == 6
    swept = balance.sweep(
        str(CONFIGS / "inline-4-car.toml"), "speed", ("1000 rpm", "2000 rpm"), quantities="F2"
    )
    assert len(swept.points) == 2
    grid = balance.sweep_grid(
        str(CONFIGS / "inline-4-car.toml"),
        ("speed", "rod_length"),
        (("1000 rpm", "2000 rpm"), np.array(["140 mm", "150 mm"])),
        quantities="F2",
        load="constant",
        overrides={"pin_offset": "1 mm"},
        progress=lambda done, total: None,
    )
    assert grid.shape == (2, 2)


@pytest.mark.parametrize("error", ["Series", "PinForce", "EngineResult"])
def test_an_order_a_result_lacks_is_still_a_key_error(world, error):
    """The README said KeyError; callers catching it keep working."""
    tq, r = world["torques"], world["result"]
    call = {
        "Series": lambda: tq.total.order(99),
        "PinForce": lambda: tq.pins[0].order(1e300),
        "EngineResult": lambda: r.order(99),
    }[error]
    with pytest.raises(KeyError):
        call()
    with pytest.raises(balance.AnalysisError, match="order"):
        call()
