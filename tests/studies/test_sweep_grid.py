"""Two-parameter sweeps (balance.sweep_grid), and the progress every sweep reports.

A grid is checked against closed forms of a single cylinder (the balance factor's trade of
vertical for horizontal primary, the exact series of the secondary) and against a second
method: single-parameter sweeps with the other parameter held by ``overrides``."""

import json

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.studies.sweep import run as sweep_module
from tests.studies.test_sweep_derived import exact_series_a2
from tests.support import SINGLE, TWIN, rad_s, write
from tests.support import TWIN_CRANK_RADIUS_M as R
from tests.support import TWIN_RECIPROCATING_KG as M_REC

UNIT = M_REC * R * rad_s(3000) ** 2


def test_balance_factor_by_rod_ratio_of_a_single(tmp_path):
    # classic counterweights of factor f leave (1 − f)·m·r·ω² of the primary along the cylinder
    # and put f·m·r·ω² across it, whatever the rod; the secondary m·r·ω²·A₂(1/ratio) is the
    # rod's alone and no rotating counterweight touches it (rtol 1e-12 for exact phasor sums,
    # 2e-5 for the series' truncation at λ ≤ 1/3, atol the noise floor's zeros)
    path = write(tmp_path, SINGLE)
    factors, ratios = [0.0, 0.25, 0.5, 1.0], [3.0, 4.0, 5.0]
    grid = balance.sweep_grid(
        path, ["balance_factor", "rod_ratio"], [factors, ratios], "F1V,F1H,F2"
    )
    assert grid.shape == (4, 3)
    f = np.array(factors)[:, None] * np.ones(3)
    assert_allclose(grid.grid("F1V"), (1 - f) * UNIT, rtol=1e-12, atol=1e-9 * UNIT)
    assert_allclose(grid.grid("F1H"), f * UNIT, rtol=1e-12, atol=1e-9 * UNIT)
    secondary = UNIT * exact_series_a2(1 / np.array(ratios))
    assert_allclose(grid.grid("F2"), np.ones((4, 1)) * secondary, rtol=2e-5, atol=0)
    # the row-major order: the second parameter varies fastest
    assert [(p["value_1"], p["value_2"]) for p in grid.points[:4]] == [
        (0.0, 3.0),
        (0.0, 4.0),
        (0.0, 5.0),
        (0.25, 3.0),
    ]


def test_a_grid_is_the_single_sweeps_at_the_same_points(tmp_path):
    # second method: each row of speed × rod_length is the rod_length sweep at that speed, each
    # row of stroke × rod_ratio the ratio sweep with the stroke held by overrides (the same
    # engines analysed by the same code: equal to the last digit)
    path = write(tmp_path, TWIN)
    speeds, rods = ["1500 rpm", "3000 rpm"], ["130 mm", "150 mm", "170 mm"]
    grid = balance.sweep_grid(path, ["speed", "rod_length"], [speeds, rods], "F2,M1,F4")
    for i, speed in enumerate(speeds):
        row = balance.sweep(path, "rod_length", rods, "F2,M1,F4", overrides={"speed": speed})
        for name in ("F2", "M1", "F4"):
            assert list(grid.grid(name)[i]) == list(row.series(name)), (speed, name)
    strokes, ratios = ["70 mm", "90 mm"], [3.0, 3.5, 4.5]
    grid = balance.sweep_grid(path, ["stroke", "rod_ratio"], [strokes, ratios], "F2")
    for i, stroke in enumerate(strokes):
        row = balance.sweep(path, "rod_ratio", ratios, "F2", overrides={"stroke": stroke})
        assert list(grid.grid("F2")[i]) == list(row.series("F2"))
    # and the ratio is of the point's own crank radius: l = ratio × stroke / 2
    rod = [e.rod_length_m for e in grid.engines]
    assert_allclose(rod, [k * s / 2 for s in (0.070, 0.090) for k in ratios], rtol=1e-15)


def test_grid_records_and_json(tmp_path):
    path = write(tmp_path, TWIN)
    grid = balance.sweep_grid(
        path, ["rod_ratio", "balance_factor"], [[3.0, 4.0], [0.0, 0.5, 1.0]], "F1,M1"
    )
    document = grid.to_dict()
    assert set(document) == {
        "balance_version",
        "name",
        "config",
        "samples",
        "max_order",
        "speed_rpm",
        "overrides",
        "parameters",
        "shape",
        "quantities",
        "inertia_kgm2",
        "load",
        "mount_speeds_rpm",
        "points",
    }
    assert document["shape"] == [2, 3]
    first, second = document["parameters"]
    assert first["key"] == "rod_ratio" and first["changes"] == ["rod_length"]
    assert first["file_value"] == pytest.approx(3.5, rel=1e-15)  # 140 mm / 40 mm
    assert second["key"] == "balance_factor" and second["changes"] == []
    assert second["values"] == [0.0, 0.5, 1.0] and second["kind"] == "fraction"
    assert len(document["points"]) == 6
    assert list(document["points"][0]) == [
        "value_1",
        "value_1_SI",
        "value_2",
        "value_2_SI",
        "F1_N",
        "M1_Nm",
    ]
    json.dumps(document, allow_nan=False)
    # a 180° twin's primary couple m·r·ω²·pitch; counterweights of factor f on each throw
    # leave (1 − f) of it pitching and put f of it yawing: its ellipse's max is max(f, 1 − f)
    expected = UNIT * 0.090 * np.maximum([0.0, 0.5, 1.0], [1.0, 0.5, 0.0])
    assert_allclose(grid.grid("M1"), [expected, expected], rtol=1e-12, atol=1e-9 * UNIT)
    with pytest.raises(balance.NotInResultError):
        grid.grid("F9")


@pytest.mark.parametrize(
    "parameters, values, overrides, error, words",
    [
        (["speed", "speed"], None, None, "parameters", "names 'speed' twice"),
        (["rod_ratio", "rod_length"], None, None, "parameters", "both change rod_length"),
        (["stroke", "crank_radius"], None, None, "parameters", "both change crank_radius"),
        (["bore_pitch", "throws[2].z"], None, None, "parameters", "both change throws[2].z"),
        ("speed", None, None, "parameters", "must be two parameters"),
        (["speed"], None, None, "parameters", "must be two parameters"),
        (["speed", "rod_lenght"], None, None, "parameters", "no such key"),
        (["speed", "rod_length"], [["1000 rpm"], ["140 mm"]], None, "values", "two or more"),
        (["speed", "rod_length"], "x", None, "values", "two lists of values"),
        (
            ["speed", "rod_length"],
            [[f"{n} rpm" for n in range(1000, 1200)], [f"{n} mm" for n in range(100, 160)]],
            None,
            "values",
            "200 × 60 = 12000 points",
        ),
        (["speed", "rod_ratio"], None, {"rod_length": "150 mm"}, "overrides", "changes rod_length"),
        (["speed", "rod_length"], None, {"stroke": "1 kg"}, "overrides", "is a mass"),
    ],
)
def test_grid_errors_name_the_argument(tmp_path, parameters, values, overrides, error, words):
    path = write(tmp_path, TWIN)
    if values is None:
        values = [[f"{n} rpm" for n in (1000, 2000)], [3.0, 4.0]]
        if parameters[1:] and parameters[1] in ("rod_length", "throws[2].z", "crank_radius"):
            values[1] = ["140 mm", "150 mm"]
        if parameters[0] in ("rod_ratio", "stroke", "bore_pitch"):
            values[0] = [3.0, 4.0] if parameters[0] == "rod_ratio" else ["80 mm", "90 mm"]
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep_grid(path, parameters, values, "F2", overrides=overrides)
    assert caught.value.parameter == error, str(caught.value)
    assert words in str(caught.value)


def test_a_bad_pair_names_both_keys_and_values(tmp_path):
    # a 100 mm crank on a rod of ratio 1: the rod cannot reach the cylinder's axis
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep_grid(path, ["crank_radius", "rod_ratio"], [["40 mm", "100 mm"], [3.0, 1.0]])
    error = caught.value
    assert error.key == ("crank_radius", "rod_ratio") and error.value == ("40 mm", 1.0)
    assert str(error).startswith(f"{path}: crank_radius = '40 mm', rod_ratio = 1: rod_length ")


def test_progress_reports_at_once_then_every_step(tmp_path, monkeypatch):
    # the first report comes before any point's engine is built or analysed (a 10 000-point
    # sweep showed nothing for 19 s): events are recorded by a fake progress and by the
    # build and analyse the sweep calls
    path = write(tmp_path, TWIN)
    events = []
    build, analyse = sweep_module.build, sweep_module.analyse
    monkeypatch.setattr(sweep_module, "build", lambda *a: events.append("build") or build(*a))
    monkeypatch.setattr(sweep_module, "analyse", lambda *a: events.append("analyse") or analyse(*a))
    balance.sweep(
        path,
        "speed",
        ["1000 rpm", "1500 rpm", "2000 rpm"],
        progress=lambda done, total: events.append((done, total)),
    )
    # the file is built first; then (0, total) at once; then three engines built and three
    # points analysed, each one step
    first = events.index((0, 6))
    assert events[:first] == ["build"]
    steps = [e for e in events if isinstance(e, tuple)]
    assert steps == [(k, 6) for k in range(7)]
    assert events[first:] == [
        (0, 6),
        *[x for k in (1, 2, 3) for x in ("build", (k, 6))],
        *[x for k in (4, 5, 6) for x in ("analyse", (k, 6))],
    ]


def test_progress_of_a_failing_sweep_came_first(tmp_path):
    # a bad last value stops the sweep; the caller's bar had been shown already
    path = write(tmp_path, TWIN)
    calls = []
    with pytest.raises(balance.SweepError):
        balance.sweep(
            path, "rod_length", ["140 mm", "150 mm", "20 mm"], progress=lambda *a: calls.append(a)
        )
    assert calls == [(0, 6), (1, 6), (2, 6)]


def test_progress_of_a_grid_with_the_balance_factor(tmp_path):
    # the balance factor changes no key: two engines (one per ratio), then six points
    path = write(tmp_path, TWIN)
    calls = []
    balance.sweep_grid(
        path,
        ["rod_ratio", "balance_factor"],
        [[3.0, 4.0], [0.0, 0.5, 1.0]],
        progress=lambda *a: calls.append(a),
    )
    assert calls == [(k, 8) for k in range(9)]
