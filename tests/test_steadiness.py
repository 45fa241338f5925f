"""The steadiness factor (Margoulis 1920) and the torque and steadiness commands."""

import csv
import io
import json
import math
import os

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.errors import AnalysisError
from balance_cli.analysis.steadiness import flywheel_for, steadiness
from tests.support import CONFIGS

OMEGA = 2 * math.pi * 1200 / 60


def sinusoid(cylinders=4, mean=80.0, spread=120.0, samples=4096):
    """Margoulis's (3): C = C_m + (ΔC/2)·sin(Nθ/2) over a four-stroke's 720°."""
    theta = np.arange(samples) * 4 * math.pi / samples
    return mean + spread / 2 * np.sin(cylinders * theta / 2)


@pytest.mark.parametrize("inertia", [0.1, 0.3, 1.0])
def test_propeller_load_converges_to_r_h(inertia):
    """Margoulis §§ 3–4: with a propeller (ℓω², ℓ = C_m/ω²) the integrated steadiness is
    r_h = √(r_c² + r_v²); the closed form neglects the speed's own variation in ω², an error
    of order 1/r_h: within 1 % for r_h > 20."""
    result = steadiness(sinusoid(), 720.0, inertia, OMEGA, "propeller")
    factors = result.margoulis()
    assert factors["r_h"] > 20
    assert_allclose(result.factor, factors["r_h"], rtol=0.01)
    # the closed forms by hand: r_c = ω²·N·I/(2ΔC), r_v = 2C_m/ΔC
    assert_allclose(factors["r_c"], result.mean_speed_rad_s**2 * 4 * inertia / 240.0, rtol=1e-12)
    assert_allclose(factors["r_v"], 2 * 80.0 / 120.0, rtol=1e-12)


@pytest.mark.parametrize("inertia", [0.05, 1.0])
def test_constant_load_converges_to_r_c(inertia):
    result = steadiness(sinusoid(), 720.0, inertia, OMEGA, "constant")
    assert_allclose(result.factor, result.margoulis()["r_c"], rtol=0.01)
    assert_allclose(result.mean_speed_rad_s, OMEGA, rtol=1e-9)


def test_r_v_over_r_c_is_four_ell_over_n_i():
    """(17): r_v/r_c = 4ℓ/(N·I), with ℓ = C_m/ω²; (20)–(21): for N = 4, β = 0.005 to 0.01 and
    K = 0.003 (ℓ = 0.04·β·D⁵, I = K·D⁵) that is 0.0667 to 0.1333 (his text prints 0.065 to 0.130,
    see the validation records)."""
    result = steadiness(sinusoid(), 720.0, 0.3, OMEGA, "propeller")
    factors = result.margoulis()
    ell = 80.0 / result.mean_speed_rad_s**2
    assert_allclose(factors["r_v"] / factors["r_c"], 4 * ell / (4 * 0.3), rtol=1e-12)
    for beta, expected in ((0.005, 0.0667), (0.01, 0.1333)):
        assert abs(4 * 0.04 * beta / (0.003 * 4) - expected) < 5e-5


def test_margoulis_printed_r_h_formula_is_not_dimensionally_right():
    """(4) and (12) as transcribed: r_h = C_m/ΔC·√(I·N² + 16ℓ²)/(2ℓ). (13)–(16) need
    √(I²·N² + 16ℓ²): only that one equals √(r_c² + r_v²) (erratum M1)."""
    inertia, mean, spread = 0.3, 80.0, 120.0
    ell = mean / OMEGA**2
    r_c, r_v = OMEGA**2 * 4 * inertia / (2 * spread), 2 * mean / spread
    corrected = mean / spread * math.sqrt(inertia**2 * 16 + 16 * ell**2) / (2 * ell)
    printed = mean / spread * math.sqrt(inertia * 16 + 16 * ell**2) / (2 * ell)
    assert_allclose(corrected, math.hypot(r_c, r_v), rtol=1e-12)
    assert abs(printed - math.hypot(r_c, r_v)) > 0.1 * math.hypot(r_c, r_v)


def test_flywheel_for_a_target():
    """The inertia of steadiness 50 under a constant load: ≈ 50·2ΔC/(ω²N) (r_c), by brentq on
    the integrated factor."""
    torque = sinusoid()
    inertia = flywheel_for(50.0, torque, 720.0, OMEGA, "constant")
    assert_allclose(steadiness(torque, 720.0, inertia, OMEGA, "constant").factor, 50.0, rtol=1e-8)
    assert_allclose(inertia, 50 * 2 * 120.0 / (OMEGA**2 * 4), rtol=0.01)


@pytest.mark.parametrize("kwargs, words", [
    (dict(inertia_kgm2=0.0), "inertia_kgm2 must be a number greater than zero"),
    (dict(inertia_kgm2=math.inf), "inertia_kgm2 is invalid"),
    (dict(speed_rad_s=-3.0), "speed_rad_s must be a number greater than zero"),
    (dict(load="brake"), "load must be one of propeller, constant"),
    (dict(torque_nm=[1.0, 2.0]), "torque_nm must be at least 8 finite values"),
    (dict(torque_nm=-sinusoid()), "torque_nm has a mean of -80 N·m: a propeller absorbs"),
    (dict(inertia_kgm2=1e-9), "inertia_kgm2 is too small for this torque"),
])
def test_steadiness_refuses_what_cannot_be(kwargs, words):
    arguments = dict(torque_nm=sinusoid(), period_deg=720.0, inertia_kgm2=0.3, speed_rad_s=OMEGA,
                     load="propeller")
    arguments.update(kwargs)
    with pytest.raises(AnalysisError, match=words):
        steadiness(**arguments)


def invoke(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def write_torque(path, values, cycle=720.0, unit="Nm"):
    angles = np.arange(len(values)) * cycle / len(values)
    lines = [f"angle_deg,torque_{unit}"] + [f"{float(a)!r},{float(v)!r}" for a, v in zip(angles, values)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_steadiness_command(tmp_path):
    path = write_torque(tmp_path / "t.csv", sinusoid(samples=720))
    result = invoke("steadiness", "--torque", path, "--inertia", "0.3 kg*m^2", "--speed", "1200 rpm",
                    "--format", "json", "--target", "50")
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert_allclose(document["steadiness"], document["r_h"], rtol=0.01)
    assert document["order"] == 2.0 and document["load"] == "propeller"
    assert document["inertia_for_target_kgm2"] > 0
    text = invoke("steadiness", "--torque", path, "--inertia", "0.3 kg m2", "--speed", "1200 rpm")
    assert "steadiness ω_m/(ω_max − ω_min)" in text.stdout


@pytest.mark.parametrize("content, words", [
    ("angle_deg,torque_Nm\n0,1\n10,2\n5,3\n20,1\n30,1\n40,1\n50,1\n60,1\n", "line 4: goes back"),
    ("angle_deg,torque_Nm\n0,1\n0,2\n10,3\n20,1\n30,1\n40,1\n50,1\n60,1\n", "line 3: repeats the angle"),
    ("angle_deg,torque\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)), "name it torque_<unit>"),
    ("angle_deg,torque_furlong\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)), "unknown unit 'furlong'"),
    ("angle_deg,torque_Nm\n" + "".join(f"{a},1\n" for a in range(0, 200, 10)), "cover 190°, not one 360° cycle"),
    ("angle_deg,torque_Nm,x\n0,1,2\n", "the header must name two columns"),
    ("angle_deg,torque_Nm\n0,1\n10\n", "line 3: has 1 column; give two"),
    ("angle_deg,torque_Nm\n" + "".join(f"{a},{1e300 if a == 30 else 1}\n" for a in range(0, 360, 10)),
     "line 5: 1e+300 Nm is outside the torques balance accepts"),
    ("time_ms,torque_Nm\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)),
     "the first column is 'time_ms'; name it angle_deg"),
    ("angle_deg,torque_Nm\n0,\"32,5\"\n", "with a decimal point (12.5, not 12,5)"),
    ("angle_deg,torque_Nm\n" + "".join(f"{a},100\n" for a in range(0, 360, 10)),
     "does not vary over the cycle"),
    ("angle_deg,torque_Nm\n" + "".join(f"{a},{100 if a < 180 else -100}\n" for a in range(0, 360, 10)),
     "has a mean of 0 N·m: a propeller absorbs only a positive mean torque"),
    ("angle_deg,torque_Nm\n0,one\n", "line 2: cannot read"),
    ("", "is empty"),
])
def test_bad_torque_files(tmp_path, content, words):
    path = tmp_path / "t.csv"
    path.write_text(content, encoding="utf-8")
    result = invoke("steadiness", "--torque", path, "--inertia", "1 kg*m^2", "--speed", "1000 rpm")
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr.count("\n") == 1 and words in result.stderr and str(path) in result.stderr


@pytest.mark.parametrize("content, words", [
    ("angle_deg,pressure_bar\n" + "".join(f"{a},{-1 if a == 40 else 5}\n" for a in range(0, 720, 10)),
     "line 6: pressure -1 bar is negative"),
    ("angle_deg,pressure_bar\n" + "".join(f"{a},5\n" for a in range(0, 360, 10)),
     "--pressure covers 360°, but 'In-line 4, car proportions' is a 4-stroke (720°)"),
    ("angle_deg,pressure_bar\n" + "".join(f"{a},{1e200 if a == 30 else 5}\n" for a in range(0, 720, 10)),
     "line 5: 1e+200 bar is outside the pressures balance accepts"),
    ("angle_deg,pressure_psx\n0,1\n", "unknown unit 'psx'"),
])
def test_bad_pressure_files(tmp_path, content, words):
    path = tmp_path / "p.csv"
    path.write_text(content, encoding="utf-8")
    result = invoke("torque", CONFIGS / "inline-4-car.toml", "--pressure", path, "--bore", "86 mm")
    assert result.exit_code == 1 and result.stderr.count("\n") == 1 and words in result.stderr


def test_torque_command_table_json_csv(tmp_path):
    table = invoke("torque", CONFIGS / "bramo-323.toml")
    assert table.exit_code == 0, table.output
    assert "Reduced mass μ" in table.stdout and "tilting" in table.stdout
    result = invoke("torque", CONFIGS / "bramo-323.toml", CONFIGS / "inline-4-car.toml",
                    "--format", "json", "--max-order", "4")
    document = json.loads(result.stdout)
    (bramo, car) = document["engines"]
    assert set(bramo) >= {"name", "config", "cycle", "speed_rpm", "period_deg", "reduced_mass",
                          "inertia", "frame", "tilting", "gas", "total", "bearing"}
    assert bramo["period_deg"] == 720.0 and bramo["gas"] is None
    assert [o["order"] for o in bramo["inertia"]["orders"]] == [0.5 * k for k in range(1, 9)]
    assert set(bramo["inertia"]["orders"][1]) == {"order", "cos_Nm", "sin_Nm", "amplitude_Nm", "phase_deg"}
    pin = bramo["bearing"]["crank_pins"][0]
    assert set(pin["orders"][2]["force"]) >= {"forward_N", "backward_N", "max_N", "min_N", "axis_deg"}
    engine = balance.load(CONFIGS / "bramo-323.toml")
    from balance_cli.analysis.torque import torque
    assert bramo == torque(engine, max_order=4).to_dict()   # the JSON is the result's to_dict
    csv_text = invoke("torque", CONFIGS / "inline-4-car.toml", "--format", "csv", "--units", "kgf").stdout
    assert csv_text.startswith("engine,config,torque,order,cos_kgfm")
    rows = list(csv.reader(io.StringIO(csv_text)))
    numbers = [cell for row in rows[1:] for cell in row[3:] if cell]
    assert numbers and all(float(cell) == float(cell) for cell in numbers)   # plain numbers only
    # the order rows read back as the JSON's values, in kgf·m
    car = balance.load(CONFIGS / "inline-4-car.toml")
    from balance_cli.analysis.torque import torque as torque_of
    inertia = torque_of(car).inertia
    second = next(row for row in rows if row[2] == "inertia" and float(row[3]) == 2.0)
    assert_allclose(float(second[5]), inertia.order(2)[1] / 9.80665, rtol=1e-12)


def test_torque_with_gas_and_a_flywheel(tmp_path):
    path = tmp_path / "p.csv"
    angles = np.arange(0, 720, 2.0)
    pressure = 1.0 + 40.0 * np.exp(-((angles + 360) % 720 - 380.0) ** 2 / 400.0)  # a burst after TDC
    path.write_text("angle_deg,pressure_bar\n" + "".join(f"{a},{p}\n" for a, p in zip(angles, pressure)))
    result = invoke("torque", CONFIGS / "inline-4-car.toml", "--pressure", path, "--bore", "86 mm",
                    "--inertia", "0.15 kg*m^2", "--target", "100", "--format", "json")
    assert result.exit_code == 0, result.output
    (car,) = json.loads(result.stdout)["engines"]
    assert car["gas"]["mean_Nm"] > 0 and car["steadiness"]["steadiness"] > 1
    assert car["steadiness"]["flywheel_for_target_kgm2"] > 0
    # no gas: a steadiness cannot be asked for
    result = invoke("torque", CONFIGS / "inline-4-car.toml", "--inertia", "0.15 kg*m^2")
    assert result.exit_code == 1 and "--inertia needs a gas torque to drive the engine" in result.stderr


def test_a_fifo_is_not_read_as_a_pressure_or_torque_file(tmp_path):
    fifo = tmp_path / "p.csv"
    os.mkfifo(fifo)
    for args in (("torque", CONFIGS / "inline-4-car.toml", "--pressure", fifo, "--bore", "86 mm"),
                 ("steadiness", "--torque", fifo, "--inertia", "1 kg*m^2", "--speed", "1000 rpm")):
        result = invoke(*args)
        assert result.exit_code == 1 and "is not a regular file" in result.stderr


@pytest.mark.parametrize("args, code, words", [
    (("--bore", "86 mm"), 2, "--bore applies with --pressure only"),
    (("--inertia", "1 kg*m^2", "--format", "csv"), 2, "not csv"),
    (("--inertia", "0 kg*m^2"), 1, "--inertia: must be greater than zero, got '0 kg*m^2'"),
])
def test_torque_options_that_cannot_apply(args, code, words):
    result = invoke("torque", CONFIGS / "abc-dragonfly.toml", *args)
    assert result.exit_code == code and words in result.stderr and "Traceback" not in result.output


def test_a_target_below_the_least_steadiness_is_refused_not_met_at_the_stall():
    """Below some inertia the engine stops; the steadiness just above that edge is the least
    there is, and a lower target cannot be met (it used to return the edge)."""
    curve = sinusoid(mean=80.0, spread=400.0)
    least = steadiness(curve, 720.0, 0.05, OMEGA, "constant").factor
    with pytest.raises(AnalysisError, match="below the least steadiness"):
        flywheel_for(0.6, curve, 720.0, OMEGA, "constant")
    found = flywheel_for(2 * least, curve, 720.0, OMEGA, "constant")
    assert_allclose(steadiness(curve, 720.0, found, OMEGA, "constant").factor, 2 * least, rtol=1e-6)


def test_a_motored_cycle_cannot_drive_a_propeller(tmp_path):
    text = (CONFIGS / "abc-dragonfly.toml").read_text(encoding="utf-8").replace('imep = "9 bar"\n', "")
    config = tmp_path / "motored.toml"
    config.write_text(text, encoding="utf-8")
    result = invoke("torque", config, "--inertia", "3 kg*m^2")
    assert result.exit_code == 1
    assert "--inertia needs an engine that drives its propeller" in result.stderr
    assert "(a motored cycle?)" in result.stderr


def test_a_target_that_needs_no_flywheel_says_so():
    result = invoke("torque", CONFIGS / "abc-dragonfly.toml", "--target", "0.8")
    assert result.exit_code == 0, result.output
    assert "The target steadiness needs no flywheel." in result.stdout
    assert "With no flywheel (the moving parts' own inertia)" in result.stdout
