"""The engine's power and the power related unbalance (PRU).

Expected values: hand arithmetic (PRU = moment / power), the slider-crank harmonic B₂ of
``tests.support.exact_b`` (apart from the library), the 180° twin's couples derived by hand,
the indicated power against the torque module's mean gas torque (a second method: virtual work
on the exact travel), and the horsepower's definitions."""

import json
import math

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.marine import DEFAULT_PRU_CLASSES, check_classes, pru_class
from balance_cli.units import parse_quantity
from tests.support import CONFIGS, TWIN, exact_b, invoke, write

MARINE = CONFIGS / "marine-6-2stroke.toml"


def test_horsepower_and_pferdestaerke_by_their_definitions():
    """1 hp = 550 ft·lbf/s = 550 × 0.3048 m × 0.45359237 kg × 9.80665 m/s² = 745.69987158227 W;
    1 PS = 75 kgf·m/s = 735.49875 W."""
    assert_allclose(parse_quantity("1 hp", "power"), 745.69987158227022, rtol=1e-15)
    assert_allclose(parse_quantity("1 PS", "power"), 735.49875, rtol=1e-15)
    assert parse_quantity("21 MW", "power") == 21e6
    with pytest.raises(balance.UnitError, match="power is needed"):
        parse_quantity("21 kg", "power")


def test_marine_six_pru_of_its_second_order_couple():
    """Firing 1-5-3-4-2-6 (throws 0, 120, 240, 180, 300, 60° at pitch d = 1.02 m): the order-2
    phasors e^{2iβ} weighted by z − z̄ add up to 2√3·d (the search's M2 = 2√3), along the
    cylinder axis: M2V = 2√3·d·m·r·ω²·|B₂|, with m = 8000 kg, r = 1.2 m, l = 2.9 m at 105 rpm
    (rotating masses have no second order). PRU = M2V / 14 280 kW, "likely" (120 to 220)."""
    omega = 105 * math.pi / 30
    m2v = 2 * math.sqrt(3) * 1.02 * 8000 * 1.2 * omega**2 * abs(exact_b(1.2 / 2.9, 2))
    record = balance.analyse(balance.load(MARINE)).to_dict()
    pru = record["pru"]
    assert pru["power_kW"] == 14280.0 and pru["power_source"] == "given"
    second = pru["orders"][1]
    assert_allclose(second["vertical_Nm"], m2v, rtol=1e-9)
    assert_allclose(second["vertical_Nm_per_kW"], m2v / 14280.0, rtol=1e-9)
    assert 120 < second["vertical_Nm_per_kW"] < 220 and second["vertical_class"] == "likely"
    assert second["horizontal_Nm"] == 0.0 and second["horizontal_class"] == "not relevant"
    # the first order of this firing order is zero, with and without counterweights
    assert pru["orders"][0]["vertical_Nm"] == 0.0
    for name in ("standard", "rotating", "crank"):
        assert pru["first_order"][name]["vertical_Nm"] == 0.0, name


def test_twin_first_order_under_each_balance_by_hand():
    """180° twin, pitch d, reciprocating m and rotating m_rot per throw. About z̄ the rotating
    masses make −d·m_rot·r·ω²·e^{iθ} (turning) and the reciprocating ones −d·m·r·ω²·cos θ (along
    the cylinder axis). Counterweights carrying m_rot + c·m per throw turn against the first and
    cancel −d·c·m·r·ω²·e^{iθ} of it: what stays is (1 − c)·m·cos θ along the axis and c·m·sin θ
    across it, so M1V = (1 − c)·m·r·ω²·d and M1H = c·m·r·ω²·d. As the crank stands (no
    counterweights) M1V = (m + m_rot)·r·ω²·d and M1H = m_rot·r·ω²·d. With m = 0.5 kg and
    m_rot = 0.3 kg: standard (c = ½) 0.25, 0.25; rotating (c = 0) 0.5, 0; crank 0.8, 0.3;
    c = 0.3 gives 0.35, 0.15 (in units of r·ω²·d). PRU divides by the power: 50 kW."""
    text = TWIN.replace('reciprocating = "500 g"', 'reciprocating = "500 g"\nrotating = "300 g"')
    engine = balance.loads('power = "50 kW"\n' + text)
    unit = 0.040 * (3000 * math.pi / 30) ** 2 * 0.090  # r·ω²·d
    result = balance.analyse(engine)
    pru = result.to_dict()["pru"]
    by_hand = {"standard": (0.25, 0.25), "rotating": (0.5, 0.0), "crank": (0.8, 0.3)}
    assert pru["first_order_balance"]["name"] == "standard"
    assert pru["first_order_balance"]["balance_factor"] == 0.5
    for name, (v, h) in by_hand.items():
        entry = pru["first_order"][name]
        # atol: the zero horizontal moment of "rotating" is rounding of 3e-2 N·m phasors
        assert_allclose(
            [entry["vertical_Nm"], entry["horizontal_Nm"]],
            [v * unit, h * unit],
            rtol=1e-9,
            atol=1e-12 * unit,
        )
    first = pru["orders"][0]
    assert_allclose([first["vertical_Nm"], first["horizontal_Nm"]], [0.25 * unit] * 2, rtol=1e-9)
    assert_allclose(first["vertical_Nm_per_kW"], 0.25 * unit / 50.0, rtol=1e-9)
    own = result.power_related_unbalance(balance=0.3).orders[0]
    assert_allclose(
        [own["vertical_Nm"], own["horizontal_Nm"]], [0.35 * unit, 0.15 * unit], rtol=1e-9
    )
    named = balance.power_related_unbalance(result, balance=0.0)
    assert named.balance.name == "rotating" and named.orders[0] == pru["first_order"]["rotating"]


def test_first_order_balance_on_the_command_line_and_its_refusals(tmp_path):
    """--first-order-balance picks the first order of compare's PRU; bad values are one
    line naming the option."""
    text = TWIN.replace('reciprocating = "500 g"', 'reciprocating = "500 g"\nrotating = "300 g"')
    unit = 0.040 * (3000 * math.pi / 30) ** 2 * 0.090
    twin = write(tmp_path, 'power = "50 kW"\n' + text)
    for value, (v, h) in (("crank", (0.8, 0.3)), ("0.3", (0.35, 0.15)), ("rotating", (0.5, 0))):
        out = invoke("compare", twin, "--first-order-balance", value, "--format", "json")
        assert out.exit_code == 0, out.output
        first = json.loads(out.output)["engines"][0]["pru"]["orders"][0]
        assert_allclose(
            [first["vertical_Nm"], first["horizontal_Nm"]],
            [v * unit, h * unit],
            rtol=1e-9,
            atol=1e-12 * unit,
        )
    for bad in ("1.5", "-0.1", "half", "nan"):
        target = tmp_path / "x.json"
        out = invoke("compare", MARINE, "--first-order-balance", bad, "--output", target)
        assert out.exit_code == 1 and "--first-order-balance" in out.output, out.output
        assert not target.exists()
        assert "Traceback" not in out.output and len(out.output.strip().splitlines()) == 1
    for bad in (True, 2, "x", None, [0.5]):
        with pytest.raises(balance.AnalysisError, match="first_order_balance"):
            balance.first_order_balance(bad)


def test_indicated_power_is_the_mean_gas_torque_times_the_speed():
    """The Dragonfly's [gas] cycle: imep · Σ swept volumes · cycles a second, against the
    torque module's mean gas torque × ω (virtual work on the exact travel, 2048 samples: the
    mean converges to about 1e-6)."""
    engine = balance.load(CONFIGS / "abc-dragonfly.toml")
    pru = balance.analyse(engine).to_dict()["pru"]
    assert pru["power_source"] == "indicated"
    gas = balance.torque(engine, samples=2048).gas
    assert_allclose(pru["power_kW"] * 1e3, gas.mean * engine.speed_rad_s, rtol=1e-5)


def test_a_power_given_at_another_speed_is_not_used_unless_given_again():
    """The project guides scale moments with n², but the power's law is the user's to say:
    analysed at 90 rpm, the file's 105 rpm power gives no PRU, and says why; --power gives
    the power at 90 rpm."""
    slow = json.loads(invoke("compare", MARINE, "--speed", "90 rpm", "--format", "json").output)
    record = slow["engines"][0]
    assert record["pru"] is None and "105 rpm" in record["pru_note"]
    text = invoke("compare", MARINE, "--speed", "90 rpm").output
    assert "Not computed: the power is given at 105 rpm" in text
    given = json.loads(
        invoke(
            "compare", MARINE, "--speed", "90 rpm", "--power", "12000 kW", "--format", "json"
        ).output
    )["engines"][0]
    assert given["pru"]["power_source"] == "option" and given["power_kW"] == 12000.0
    # the moment follows n²: (90/105)² of the file speed's
    fast = balance.analyse(balance.load(MARINE)).to_dict()["pru"]["orders"][1]["vertical_Nm"]
    assert_allclose(given["pru"]["orders"][1]["vertical_Nm"], fast * (90 / 105) ** 2, rtol=1e-12)


def test_classes_by_default_and_set():
    assert [pru_class(v) for v in (0, 59.9, 60, 119, 120, 219.9, 220, 1e6)] == [
        "not relevant",
        "not relevant",
        "unlikely",
        "unlikely",
        "likely",
        "likely",
        "most likely",
        "most likely",
    ]
    assert DEFAULT_PRU_CLASSES[:3] == (
        (60.0, "not relevant"),
        (120.0, "unlikely"),
        (220.0, "likely"),
    )
    classes = check_classes((50, 100, 150))
    assert pru_class(124.4, classes) == "likely"
    for bad in ((100, 50, 200), (60, 120), (0, 1, 2), ("x", 1, 2), (math.nan, 1, 2)):
        with pytest.raises(balance.AnalysisError, match="pru_classes"):
            check_classes(bad)
    out = invoke("compare", MARINE, "--pru-classes", "100,50,200")
    assert out.exit_code == 1 and "--pru-classes" in out.output and "Traceback" not in out.output
    out = invoke("compare", MARINE, "--pru-classes", "50,100,150")
    assert out.exit_code == 0 and "124.4 (likely)" in out.output


def test_pru_orders_and_errors():
    record = json.loads(
        invoke("compare", MARINE, "--pru-orders", "2,4", "--format", "json").output
    )["engines"][0]
    assert [e["order"] for e in record["pru"]["orders"]] == [2, 4]
    for bad in ("0", "9", "x"):
        out = invoke("compare", MARINE, "--pru-orders", bad)
        assert out.exit_code in (1, 2) and "--pru-orders" in out.output
    for bad in ("0 kW", "-5 kW", "5 kg", "fast"):
        out = invoke("compare", MARINE, "--power", bad)
        assert out.exit_code == 1 and "--power" in out.output and "Traceback" not in out.output
    with pytest.raises(balance.ConfigError, match="power"):
        balance.loads('power = "5 kg"\n' + TWIN)


def test_no_power_no_table_and_a_rotary_has_no_balanced_first_order():
    out = invoke("compare", CONFIGS / "inline-4-car.toml")
    assert "Power related unbalance" not in out.output
    record = json.loads(
        invoke(
            "compare", CONFIGS / "clerget-rotary.toml", "--power", "97 kW", "--format", "json"
        ).output
    )["engines"][0]
    # a rotary's crank does not turn: no counterweights, so its first order as it stands
    pru = record["pru"]
    assert pru["first_order"]["standard"] is None and pru["first_order"]["rotating"] is None
    assert pru["first_order_balance"]["name"] == "crank"
    assert pru["orders"][0] == pru["first_order"]["crank"]


def test_milliwatts_and_megawatts_are_not_guessed():
    for text in ("14280 mW", "14.28 mw"):
        with pytest.raises(balance.UnitError, match="milli"):
            parse_quantity(text, "power")
    assert parse_quantity("14.28 MW", "power") == pytest.approx(14.28e6, rel=1e-15)


def test_an_order_asked_twice_is_judged_once():
    record = json.loads(
        invoke("compare", MARINE, "--pru-orders", "2,2", "--format", "json").output
    )["engines"][0]
    assert [e["order"] for e in record["pru"]["orders"]] == [2]


def test_a_sweep_of_power_gives_the_pru_by_hand():
    """PRU2V = M2V / P at every point; the power alone changes nothing else, so a sweep of it
    without a PRU quantity is refused; a sweep of speed does not carry the file's power to
    other speeds."""
    swept = balance.sweep(str(MARINE), "power", ["10 MW", "20 MW"], quantities="M2V,PRU2V")
    for point, kw in zip(swept.points, (1e4, 2e4), strict=True):
        assert_allclose(point["PRU2V_Nm_per_kW"], point["M2V_Nm"] / kw, rtol=1e-12)
    with pytest.raises(balance.SweepError, match="PRU"):
        balance.sweep(str(MARINE), "power", ["10 MW", "20 MW"], quantities="M2V")
    with pytest.raises(balance.SweepError, match="given at 105 rpm"):
        balance.sweep(str(MARINE), "speed", ["90 rpm", "105 rpm"], quantities="PRU2V")


def test_torque_gives_the_indicated_power_of_a_pressure_file_or_gas_cycle(tmp_path):
    """balance torque's indicated power is the mean gas torque × ω; for the Dragonfly's [gas]
    cycle it is compare's imep · swept volume · cycles a second (the gas torque at 256 samples
    is converged to about 5e-5)."""
    engine = balance.load(CONFIGS / "abc-dragonfly.toml")
    torques = balance.torque(engine)
    assert_allclose(
        torques.indicated_power_kw, torques.gas.mean * engine.speed_rad_s / 1e3, rtol=1e-15
    )
    compared = balance.analyse(engine).to_dict()["power_kW"]
    assert_allclose(torques.indicated_power_kw, compared, rtol=1e-4)
    document = json.loads(
        invoke("torque", CONFIGS / "abc-dragonfly.toml", "--format", "json").output
    )
    assert_allclose(
        document["engines"][0]["indicated_power_kW"], torques.indicated_power_kw, rtol=1e-12
    )
    assert (
        "Indicated power (mean gas torque × ω): 282.1 kW."
        in invoke("torque", CONFIGS / "abc-dragonfly.toml").output
    )
    assert (
        json.loads(invoke("torque", CONFIGS / "inline-4-car.toml", "--format", "json").output)[
            "engines"
        ][0]["indicated_power_kW"]
        is None
    )
