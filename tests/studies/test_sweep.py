"""Parameter sweeps: balance.sweep.

Expected values are computed here, independently of balance's kinematics and harmonics: the
exact slider-crank motion integrated by the trapezoidal rule, and closed forms of textbook
layouts (a 180° twin's primary couple, a single's counterweighted primary)."""

import json
import math
import re

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.config import reader as config_module
from balance_cli.studies.sweep import SCHEMA, span
from tests.support import CONFIGS, ROOT, SINGLE, TWIN, TWIN_PITCH, rad_s, write
from tests.support import TWIN_CRANK_RADIUS_M as R
from tests.support import TWIN_RECIPROCATING_KG as M_REC


def second_order_force(r, rod, m, omega, n=4096):
    """Amplitude of the exact second-order inertia force of one piston, N.

    x(θ) = r·cos θ + √(l² − r²·sin²θ) is the piston's exact position; its second harmonic a₂
    (x = Σ a_k·cos kθ) is taken by the trapezoidal rule over a revolution, which converges
    geometrically for a smooth periodic function (n = 4096 leaves errors of the size of
    (r/l)^n), and the
    force is m·ẍ's second harmonic, m·(2ω)²·|a₂|.
    """
    theta = np.arange(n) * 2 * np.pi / n
    x = r * np.cos(theta) + np.sqrt(rod**2 - (r * np.sin(theta)) ** 2)
    a2 = 2.0 / n * np.sum(x * np.cos(2 * theta))
    return m * (2 * omega) ** 2 * abs(a2)


def test_speed_sweep_follows_the_square_law_exactly(tmp_path):
    # every inertia force, free moment and inertia torque is m·(geometry)·ω²: the same engine at
    # another speed gives the same numbers times (ω/ω₀)², to rounding (rtol 1e-12: a handful
    # of ulps through one FFT and one multiplication by ω²)
    path = write(tmp_path, TWIN)
    speeds = ["1000 rpm", "2000 rpm", "3000 rpm", "4500 rpm", "7250 rpm"]
    names = [
        "F2",
        "F2V",
        "F2+",
        "F4",
        "F6",
        "M1",
        "M1V",
        "M1-",
        "largest_force",
        "largest_moment",
        "torque_range",
    ]
    result = balance.sweep(path, "speed", speeds, names + ["F1", "M2"])
    # a 180° twin: primaries opposite, secondaries in phase at ±pitch/2: exact zeros at any speed
    assert not result.series("F1").any() and not result.series("M2").any()
    omega = np.array([rad_s(float(s.split()[0])) for s in speeds])
    assert_allclose(result.values_si, omega, rtol=1e-15, atol=0)
    law = (omega / omega[0]) ** 2
    for name in names:
        series = result.series(name)
        assert series[0] > 0, f"{name} is zero: the law would hold trivially"
        assert_allclose(series / series[0], law, rtol=1e-12, atol=0, err_msg=name)
    # and the primary couple itself, by hand: two opposite primaries m·r·ω² (exactly r·cos θ:
    # the rod's square root has even harmonics only) TWIN_PITCH apart, all of it pitching
    couple = M_REC * R * omega**2 * TWIN_PITCH
    assert_allclose(result.series("M1"), couple, rtol=1e-12, atol=0)
    assert_allclose(result.series("M1V"), couple, rtol=1e-12, atol=0)


def test_rod_length_sweep_gives_the_exact_second_order_force(tmp_path):
    # balance (256 samples, FFT of the positions) against the trapezoidal integral above: both
    # exact to rounding for r/l ≤ 0.33, whose harmonics fall as (r/l)^k; rtol 1e-12 allows
    # for the two summations' rounding and nothing else (seen: 2e-14)
    path = write(tmp_path, SINGLE)
    lengths_mm = [120.0, 140.0, 170.0, 200.0, 260.0]
    result = balance.sweep(
        path, "rod_length", [f"{v:g} mm" for v in lengths_mm], ["F2", "F2V", "F2H", "F2+", "F2-"]
    )
    expected = np.array([second_order_force(R, v / 1000, M_REC, rad_s(3000)) for v in lengths_mm])
    assert_allclose(result.series("F2"), expected, rtol=1e-12, atol=0)
    # a line force along the cylinder axis, the engine's vertical: all of it vertical, split
    # evenly forward and backward (atol: the noise floor, 1e-9 of m·r·ω², writes zeros)
    assert_allclose(result.series("F2V"), expected, rtol=1e-12, atol=0)
    assert_allclose(result.series("F2H"), 0.0, rtol=0, atol=0)
    assert_allclose(result.series("F2+"), expected / 2, rtol=1e-12, atol=0)
    assert_allclose(result.series("F2-"), expected / 2, rtol=1e-12, atol=0)
    # the textbook's first approximation m·r·ω²·λ (λ = r/l) is within λ²-ish of it: a sanity
    # check that the independent integral is the force balance means
    approx = M_REC * R * rad_s(3000) ** 2 * R / (np.array(lengths_mm) / 1000)
    assert_allclose(expected, approx, rtol=0.05)


def test_balance_factor_moves_the_primary_from_vertical_to_horizontal(tmp_path):
    # a single with classic counterweights of factor f (f·m_rec opposite the pin, at crank
    # radius) keeps (1 − f)·m·r·ω² of its primary along the cylinder and gains f·m·r·ω² across
    # it: the textbook trade-off (rtol 1e-12: exact phasor sums; zeros below the noise floor)
    path = write(tmp_path, SINGLE)
    factors = [0.0, 0.25, 0.5, 0.75, 1.0]
    result = balance.sweep(path, "balance_factor", factors, "F1V,F1H,F1,F1+,F1-")
    unit = M_REC * R * rad_s(3000) ** 2
    f = np.array(factors)
    assert_allclose(result.series("F1V"), (1 - f) * unit, rtol=1e-12, atol=1e-9 * unit)
    assert_allclose(result.series("F1H"), f * unit, rtol=1e-12, atol=1e-9 * unit)
    assert_allclose(result.series("F1"), np.maximum(f, 1 - f) * unit, rtol=1e-12, atol=0)
    # the backward half of the reciprocating primary is untouched by any rotating mass
    assert_allclose(result.series("F1-"), unit / 2, rtol=1e-12, atol=0)
    assert_allclose(result.series("F1+"), abs(0.5 - f) * unit, rtol=1e-12, atol=1e-9 * unit)


def test_bank_angle_sweep_of_a_v_twin(tmp_path):
    # a V-twin on one throw: a piston on a bank at γ gives the primary m·r·ω²·cos(θ − γ)
    # along e^{iγ}, = m·r·ω²/2·(e^{iθ} + e^{2iγ}·e^{−iθ}): forward m·r·ω²/2 whatever γ,
    # backward m·r·ω²/2·e^{2iγ}. At 90° between the banks the backward parts cancel and the
    # primary is a rotating m·r·ω², the classic 90° V-twin (rtol 1e-12: exact phasor sums)
    text = SINGLE.replace(
        "[[banks]]\nangle = 0\n", "[[banks]]\nangle = -45\n[[banks]]\nangle = 45\n"
    )
    path = write(tmp_path, text)
    angles = [30.0, 60.0, 90.0, 120.0]
    result = balance.sweep(path, "banks[2].angle", angles, "F1+,F1-")
    unit = M_REC * R * rad_s(3000) ** 2
    # with the banks at −45° and γ, the forward phasor of each primary is m·r·ω²/2 (always at
    # the crank), the backward one m·r·ω²/2·e^{2iγ}
    expected_backward = [
        abs(0.5 * unit * (np.exp(2j * math.radians(-45)) + np.exp(2j * math.radians(g))))
        for g in angles
    ]
    assert_allclose(result.series("F1+"), unit, rtol=1e-12, atol=0)
    assert_allclose(result.series("F1-"), expected_backward, rtol=1e-12, atol=1e-9 * unit)
    assert result.values_si == tuple(math.radians(a) for a in angles)


def test_a_missing_key_the_format_allows_is_added(tmp_path):
    # pin_offset is optional; a 0 offset is the file as it is
    path = write(tmp_path, SINGLE)
    result = balance.sweep(path, "pin_offset", ["0 mm", "5 mm"], ["F1", "F2"])
    assert result.parameter.file_value is None and not result.parameter.in_file
    plain = balance.analyse(balance.load(path)).to_dict()["orders"]
    assert result.points[0]["F2_N"] == plain[1]["force"]["max_N"]
    assert result.points[1]["F2_N"] != result.points[0]["F2_N"]


def test_a_parsed_dict_is_swept_and_left_unchanged():
    data = config_module.parse_text(TWIN, "twin")
    before = json.dumps(data, sort_keys=True)
    configuration = balance.Configuration(data, "twin.toml")
    result = balance.sweep(configuration, "throws[2].z", ["90 mm", "120 mm"], "M1")
    assert json.dumps(data, sort_keys=True) == before
    assert result.config == "twin.toml"
    unit = M_REC * R * rad_s(3000) ** 2
    assert_allclose(result.series("M1"), [unit * 0.090, unit * 0.120], rtol=1e-12, atol=0)


def test_records_and_json_keys(tmp_path):
    path = write(tmp_path, TWIN)
    result = balance.sweep(path, "rod_length", span("140 mm", "0.2 m", 4), "F2,M1V,largest_force")
    assert result.values == ("140 mm", "160 mm", "180 mm", "200 mm")
    assert_allclose(result.values_si, [0.14, 0.16, 0.18, 0.2], rtol=1e-15, atol=0)
    records = result.records()
    assert [list(r) for r in records] == [
        ["value", "value_SI", "F2_N", "M1V_Nm", "largest_force_N"]
    ] * 4
    document = result.to_dict()
    assert set(document) == {
        "balance_version",
        "name",
        "config",
        "samples",
        "max_order",
        "speed_rpm",
        "overrides",
        "parameter",
        "quantities",
        "inertia_kgm2",
        "load",
        "mount_speeds_rpm",
        "points",
    }
    assert document["overrides"] == {} and document["speed_rpm"] == pytest.approx(3000, rel=1e-12)
    assert document["parameter"] == {
        "key": "rod_length",
        "kind": "length",
        "unit_SI": "m",
        "file_value": "140 mm",
        "changes": ["rod_length"],
        "meaning": None,
        "values": list(result.values),
        "values_SI": list(result.values_si),
    }
    assert [(q["name"], q["column"], q["unit"]) for q in document["quantities"]] == [
        ("F2", "F2_N", "N"),
        ("M1V", "M1V_Nm", "Nm"),
        ("largest_force", "largest_force_N", "N"),
    ]
    assert document["points"] == records
    json.dumps(document, allow_nan=False)  # plain JSON: no numpy scalars, no NaN
    # the sweep's point is compare's record of the same engine
    engine = balance.load(path)
    assert records[0]["F2_N"] == balance.analyse(engine).to_dict()["orders"][1]["force"]["max_N"]


def test_span_writes_values_as_the_file_does():
    assert span("140 mm", "0.2 m", 4) == ["140 mm", "160 mm", "180 mm", "200 mm"]
    assert span(0, 90, 4) == [0.0, 30.0, 60.0, 90.0]
    assert span("0.1", "0.3", 3) == [0.1, 0.2, 0.3]  # no 0.30000000000000004
    assert span("3000 rpm", "6000 rpm", 3) == ["3000 rpm", "4500 rpm", "6000 rpm"]
    for args, parameter in [
        (("1 mm", "2 kg", 3), "stop"),
        ((0, 0, 3), "stop"),
        ((0, 1, 1), "steps"),
        (("x", 1, 3), "start"),
        ((0, 1, 2.5), "steps"),
    ]:
        with pytest.raises(balance.SweepError) as caught:
            span(*args)
        assert caught.value.parameter == parameter


def test_schema_covers_every_key_of_the_configuration_format():
    # a key added to the format must be sweepable (or named as text) here too
    tables = {
        "": config_module.TOP_KEYS,
        "masses": config_module.MASS_KEYS,
        "parts": config_module.PART_KEYS,
        "gas": config_module.GAS_KEYS,
        "links": config_module.LINK_KEYS,
        "banks[]": config_module.BANK_KEYS,
        "throws[]": config_module.THROW_KEYS,
        "cylinders[]": config_module.CYLINDER_KEYS,
        "crankshafts[]": config_module.CRANKSHAFT_KEYS,
        "counterweights[]": config_module.COUNTERWEIGHT_KEYS,
        "shafts[]": config_module.SHAFT_KEYS,
    }
    text_or_tables = {
        "name",
        "source",
        "sources",
        "estimates",
        "frame",
        "firing_order",
        "masses",
        "parts",
        "gas",
        "banks",
        "throws",
        "links",
        "cylinders",
        "crankshafts",
        "counterweights",
        "shafts",
        "torsion",
        "mounts",
        "tolerances",
    }  # the shaft line's table is not swept; the mounts' keys have their own schema
    # (studies/sweep/mountkeys.py, checked against the reader in test_sweep_mounts.py); the
    # production scatter is read by balance tolerance, not swept
    # a shaft's [[shafts.masses]] are tables within its table: not swept
    nested = {"": text_or_tables, "shafts[]": {"masses"}}
    for table, keys in tables.items():
        extra = nested.get(table, set())
        assert set(SCHEMA[table]) | extra == set(keys), table


@pytest.mark.parametrize(
    "parameter, values, quantities, error_parameter, words",
    [
        ("rod_lenght", ["140 mm"], None, "parameter", "no such key"),
        ("banks[2].angle", [30], None, "parameter", "only banks[1]"),
        ("name", ["x"], None, "parameter", "not a number to vary"),
        ("gas.imep", ["8 bar"], None, "parameter", "no [gas] table"),
        ("throws.phase", [0], None, "parameter", "throws[1].phase"),
        ("rod_length", [140], None, "values", "with a unit"),
        ("throws[1].phase", ["10 deg"], None, "values", "without a unit"),
        ("rod_length", [], None, "values", "at least one"),
        ("speed", ["3000 rpm"], "F2X", "quantities", "not a quantity"),
        ("speed", ["3000 rpm"], "F9", "quantities", "orders analysed (1 to 8)"),
        ("speed", ["3000 rpm"], "steadiness", "inertia_kgm2", "steadiness"),
    ],
)
def test_library_errors_name_the_parameter(
    tmp_path, parameter, values, quantities, error_parameter, words
):
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(path, parameter, values, quantities)
    assert caught.value.parameter == error_parameter
    assert words in str(caught.value)


def test_a_bad_point_names_the_file_the_key_and_the_value(tmp_path):
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(path, "crank_radius", ["40 mm", "150 mm"])
    error = caught.value
    assert (error.key, error.value) == ("crank_radius", "150 mm")
    assert str(error).startswith(f"{path}: crank_radius = '150 mm': ")
    assert isinstance(error.cause, balance.ConfigError)


def test_steadiness_sweep_over_the_flywheel_file(tmp_path):
    # the Dragonfly has a [gas] table: at its own speed the sweep's point is what
    # balance.torque gives for the file itself, mean torque and steadiness alike
    result = balance.sweep(
        CONFIGS / "abc-dragonfly.toml",
        "speed",
        ["1400 rpm", "1650 rpm"],
        "torque_mean,steadiness",
        inertia_kgm2=3.0,
    )
    reference = balance.torque(balance.load(CONFIGS / "abc-dragonfly.toml"), inertia_kgm2=3.0)
    assert result.points[1]["torque_mean_Nm"] == reference.total.mean
    assert_allclose(result.points[1]["steadiness"], reference.steadiness.factor, rtol=1e-12)


def test_a_key_that_changes_nothing_is_refused():
    # the BRAMO's cylinders each give their own knuckle radius: [links]' default is never used
    with pytest.raises(balance.SweepError, match="changes nothing") as caught:
        balance.sweep(CONFIGS / "bramo-323.toml", "links.knuckle_radius", ["60 mm", "70 mm"])
    assert caught.value.parameter == "parameter"


def test_the_how_to_page_example_runs_as_written(monkeypatch):
    page = ROOT / "docs" / "howto" / "sweep.md"
    text = page.read_text(encoding="utf-8")
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    assert len(blocks) == 1
    monkeypatch.chdir(ROOT)
    exec(compile(blocks[0], str(page), "exec"), {})
    # and the pictures the page shows are there
    for picture in ("sweep-rod-length.png", "sweep-grid.png"):
        assert (ROOT / "docs" / picture).read_bytes().startswith(b"\x89PNG")


def test_overrides_set_other_keys_at_every_point(tmp_path):
    # --speed: the same sweep at another speed is the file's sweep times the speed ratio squared
    path = write(tmp_path, TWIN)
    at_file = balance.sweep(path, "rod_length", ["140 mm", "180 mm"], "F2,M1")
    at_half = balance.sweep(
        path, "rod_length", ["140 mm", "180 mm"], "F2,M1", overrides={"speed": "1500 rpm"}
    )
    assert at_half.speed_rpm == pytest.approx(1500, rel=1e-12)
    assert at_file.speed_rpm == pytest.approx(3000, rel=1e-12)
    for name in ("F2", "M1"):
        assert_allclose(at_half.series(name), at_file.series(name) / 4, rtol=1e-12, atol=0)
    assert at_half.to_dict()["overrides"] == {"speed": "1500 rpm"}
    for overrides in ({"sped": "1 rpm"}, {"speed": "-1 rpm"}, {"rod_length": "150 mm"}):
        with pytest.raises(balance.SweepError) as caught:
            balance.sweep(path, "rod_length", ["140 mm"], overrides=overrides)
        assert caught.value.parameter == "overrides"


MARINE = CONFIGS / "marine-6-2stroke.toml"  # 14 280 kW at 105 rpm, no [gas] table


def test_power_sweep_divides_the_moment(tmp_path):
    # `sweep --vary power` ended in KeyError 'power': PRU = M / P (kW), P as written
    powers_kw = [10000.0, 14280.0, 20000.0]
    result = balance.sweep(MARINE, "power", [f"{p:g} kW" for p in powers_kw], "PRU2V,M2V,PRU1H")
    assert result.parameter.unit_si == "W"
    assert_allclose(result.values_si, np.array(powers_kw) * 1e3, rtol=1e-15, atol=0)
    moment = result.series("M2V")
    assert moment[0] > 0 and np.all(moment == moment[0])  # the power moves no mass
    assert_allclose(result.series("PRU2V"), moment / powers_kw, rtol=1e-12, atol=0)
    json.dumps(result.to_dict(), allow_nan=False)
    with pytest.raises(balance.SweepError, match="power changes only the power related"):
        balance.sweep(MARINE, "power", ["1 MW"])


def test_the_files_power_stays_at_the_files_speed(tmp_path):
    # the file's 14 280 kW is given at 105 rpm: at 80 rpm (overrides, the CLI's --speed) the PRU
    # has no power, and saying so beats dividing by the power of another speed
    at_file = balance.sweep(MARINE, "rod_length", ["2900 mm", "3000 mm"], "PRU2V")
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(
            MARINE, "rod_length", ["2900 mm", "3000 mm"], "PRU2V", overrides={"speed": "80 rpm"}
        )
    assert caught.value.parameter == "overrides"
    assert "given at 105 rpm" in str(caught.value) and "set the power" in str(caught.value)
    # with the power at 80 rpm given too: the moment falls as the speed squared
    at_80 = balance.sweep(
        MARINE,
        "rod_length",
        ["2900 mm", "3000 mm"],
        "PRU2V",
        overrides={"speed": "80 rpm", "power": "8000 kW"},
    )
    expected = at_file.series("PRU2V") * (80 / 105) ** 2 * 14280 / 8000
    assert_allclose(at_80.series("PRU2V"), expected, rtol=1e-12, atol=0)
    # a speed sweep carries no power to other speeds: the point at 80 rpm is refused
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(MARINE, "speed", ["105 rpm", "80 rpm"], "PRU2V")
    assert caught.value.value == "80 rpm"
    assert "needs the power at the point's speed, 80 rpm, but the power is given at 105 rpm" in (
        str(caught.value)
    )
    # ... and a power given with the overrides is given at the overrides' speed
    with pytest.raises(balance.SweepError, match="given at 105 rpm"):
        balance.sweep(MARINE, "speed", ["105 rpm", "80 rpm"], "PRU2V", overrides={"power": "1 MW"})


def test_a_grid_of_speed_and_power(tmp_path):
    # each point's power is given at its own speed: PRU = M(n) / P, M ∝ n²
    speeds, powers = [80.0, 105.0], [8000.0, 14280.0]
    grid = balance.sweep_grid(
        MARINE,
        ["speed", "power"],
        [[f"{n:g} rpm" for n in speeds], [f"{p:g} kW" for p in powers]],
        "PRU2V",
    )
    at_file = balance.sweep(MARINE, "rod_length", ["2900 mm"], "PRU2V").series("PRU2V")[0]
    expected = [[at_file * (n / 105) ** 2 * 14280 / p for p in powers] for n in speeds]
    assert_allclose(grid.grid("PRU2V"), expected, rtol=1e-12, atol=0)


@pytest.mark.parametrize(
    "keyword, value, error",
    [
        ("load", "x", "load"),
        ("load", None, "load"),
        ("overrides", 5, "overrides"),
        ("overrides", ["speed"], "overrides"),
        ("overrides", {"speed": 5}, "overrides"),
        ("overrides", {3: "x"}, "overrides"),
        ("overrides", {"balance_factor": 0.5}, "overrides"),
        ("progress", "x", "progress"),
        ("progress", 5, "progress"),
        ("inertia_kgm2", -1.0, "inertia_kgm2"),
        ("inertia_kgm2", "x", "inertia_kgm2"),
    ],
)
def test_every_keyword_is_checked_before_any_work(tmp_path, keyword, value, error):
    # API arguments were accepted silently (load) or failed late with Python's own errors
    # (overrides=5: AttributeError; progress='x': TypeError after the whole sweep)
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(path, "rod_length", ["140 mm"], "F2", **{keyword: value})
    assert caught.value.parameter == error
    assert "\n" not in str(caught.value)
