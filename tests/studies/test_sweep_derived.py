"""Sweeps of the parameters a designer thinks in: rod_ratio, stroke, bore_pitch.

Each is set through the file's own keys; the expected values here come from closed forms of
the slider crank (the exact series of the second-order force), the trapezoidal integral of the
exact piston motion, a hand-built configuration with the changed keys written out, and the
primary couple of a 180° twin."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.studies.sweep import DERIVED, SCHEMA, parameter_of
from balance_cli.studies.sweep.keys import BALANCE_FACTOR
from tests.studies.test_sweep import second_order_force
from tests.support import JUMO, LINKED, ROOT, SINGLE, TWIN, TWIN_PITCH, rad_s, replaced, write
from tests.support import TWIN_CRANK_RADIUS_M as R
from tests.support import TWIN_RECIPROCATING_KG as M_REC

#: SINGLE's and TWIN's m·r·ω² at 3000 rpm, N
UNIT = M_REC * R * rad_s(3000) ** 2
ROD = 0.140  # their rod length, m


def exact_series_a2(lam):
    """The second-order coefficient of a piston's acceleration on a rod of ratio λ = r/l,
    ẍ = −r·ω²·(cos θ + A₂·cos 2θ − ...): A₂ = λ + λ³/4 + 15λ⁵/128 + 35λ⁷/512 (Taylor series
    of √(1 − λ²·sin²θ) taken to λ⁸; the next term, about 0.045·λ⁹, is the truncation)."""
    return lam + lam**3 / 4 + 15 * lam**5 / 128 + 35 * lam**7 / 512


def test_rod_ratio_sets_the_rod_length_and_holds_the_crank(tmp_path):
    # an in-line single: F2 = m·r·ω²·A₂(λ) with λ = 1/ratio; for ratios from 3, λ ≤ 1/3 and
    # the series' truncation is below 0.045·λ⁹/λ ≈ 7e-6 of it (rtol 2e-5); the trapezoidal
    # integral of the exact motion is exact to rounding (rtol 1e-12)
    path = write(tmp_path, SINGLE)
    ratios = [3.0, 3.5, 4.0, 5.0, 6.0]
    result = balance.sweep(path, "rod_ratio", ratios, "F1,F2,F2V")
    lam = 1 / np.array(ratios)
    assert_allclose(result.series("F2"), UNIT * exact_series_a2(lam), rtol=2e-5, atol=0)
    integral = [second_order_force(R, k * R, M_REC, rad_s(3000)) for k in ratios]
    assert_allclose(result.series("F2"), integral, rtol=1e-12, atol=0)
    assert_allclose(result.series("F2V"), integral, rtol=1e-12, atol=0)
    # the rod's square root has even harmonics only: the primary is m·r·ω² at any ratio
    assert_allclose(result.series("F1"), UNIT, rtol=1e-12, atol=0)
    # which key moved: the rod, l = ratio × 40 mm; the crank stayed
    assert_allclose([e.rod_length_m for e in result.engines], np.array(ratios) * R, rtol=1e-15)
    assert {e.crank_radius_m for e in result.engines} == {R}
    p = result.parameter
    assert (p.key, p.kind, p.unit_si, p.changes) == ("rod_ratio", "number", "", ("rod_length",))
    assert p.file_value == pytest.approx(ROD / R, rel=1e-15)  # 140 mm / 40 mm = 3.5
    assert "holds crank_radius" in p.meaning


def test_stroke_sets_the_crank_radius_and_holds_the_rod(tmp_path):
    # r = s/2 at a rod of 140 mm: the primary is exactly m·(s/2)·ω², the secondary the exact
    # integral's at that crank radius and rod (rtol 1e-12: rounding only)
    path = write(tmp_path, SINGLE)
    strokes_mm = [60.0, 70.0, 80.0, 90.0, 100.0]
    result = balance.sweep(path, "stroke", [f"{s:g} mm" for s in strokes_mm], "F1,F2")
    r = np.array(strokes_mm) / 2000
    omega = rad_s(3000)
    assert_allclose(result.series("F1"), M_REC * r * omega**2, rtol=1e-12, atol=0)
    expected = [second_order_force(x, ROD, M_REC, omega) for x in r]
    assert_allclose(result.series("F2"), expected, rtol=1e-12, atol=0)
    assert_allclose([e.crank_radius_m for e in result.engines], r, rtol=1e-15)
    assert {e.rod_length_m for e in result.engines} == {ROD}
    assert result.parameter.file_value == "80 mm"  # twice the file's 40 mm crank radius
    assert_allclose(result.values_si, np.array(strokes_mm) / 1000, rtol=1e-15)


def test_bore_pitch_moves_the_throws_and_scales_the_primary_couple(tmp_path):
    # a 180° twin: the primaries m·r·ω² are opposite, one pitch apart: M1 = m·r·ω²·p exactly
    path = write(tmp_path, TWIN)
    pitches_mm = [60.0, 90.0, 120.0, 150.0]
    result = balance.sweep(path, "bore_pitch", [f"{p:g} mm" for p in pitches_mm], "M1,F1")
    p = np.array(pitches_mm) / 1000
    assert_allclose(result.series("M1"), UNIT * p, rtol=1e-12, atol=0)
    assert not result.series("F1").any()
    assert [[t.z_m for t in e.throws] for e in result.engines] == [[0.0, x] for x in p]
    assert result.parameter.file_value == f"{TWIN_PITCH * 1000:g} mm"


#: a 90° V4 on two throws 100 mm apart, the cylinders of each throw side by side (their own
#: z, 12 mm either side of it), and a counterweight 30 mm behind the second throw
V4 = """\
name = "test V4"
cycle = 4
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"

[masses]
reciprocating = "500 g"
rotating = "300 g"

[[banks]]
angle = -45
[[banks]]
angle = 45

[[throws]]
phase = 0
z = "{z1}"
[[throws]]
phase = 180
z = "{z2}"

[[cylinders]]
number = 1
bank = 1
throw = 1
z = "{c1}"
[[cylinders]]
number = 2
bank = 2
throw = 1
z = "{c2}"
[[cylinders]]
number = 3
bank = 1
throw = 2
z = "{c3}"
[[cylinders]]
number = 4
bank = 2
throw = 2
z = "{c4}"

[[counterweights]]
throw = 2
mass = "200 g"
radius = "30 mm"
angle = 180
z = "{w}"
"""


def test_bore_pitch_against_a_hand_built_file(tmp_path):
    # at a pitch of 130 mm the throws sit at 20 and 150 mm (the first held), the cylinders
    # 12 mm either side of theirs, the counterweight 30 mm behind the second throw: that file,
    # written out by hand, is the engine the sweep builds (records equal to the last digit:
    # the same engine analysed twice)
    def v4(z1, z2, c1, c2, c3, c4, w):
        return V4.format(z1=z1, z2=z2, c1=c1, c2=c2, c3=c3, c4=c4, w=w)

    path = write(tmp_path, v4("20 mm", "120 mm", "8 mm", "32 mm", "108 mm", "132 mm", "150 mm"))
    result = balance.sweep(path, "bore_pitch", ["100 mm", "130 mm"], "M1,M2,F1,largest_moment")
    by_hand = write(
        tmp_path,
        v4("20 mm", "150 mm", "8 mm", "32 mm", "138 mm", "162 mm", "180 mm"),
        "by-hand.toml",
    )
    engine = balance.load(by_hand)
    swept = result.engines[1]
    assert_allclose([t.z_m for t in swept.throws], [0.020, 0.150], rtol=1e-12)
    assert_allclose([c.z_m for c in swept.cylinders], [0.008, 0.032, 0.138, 0.162], rtol=1e-12)
    assert_allclose([w.z_m for w in swept.counterweights], [0.180], rtol=1e-12)
    records = balance.analyse(engine).to_dict()["orders"]
    for name, order, part in (("M1", 1, "moment"), ("M2", 2, "moment"), ("F1", 1, "force")):
        unit = "Nm" if part == "moment" else "N"
        assert_allclose(
            result.points[1][f"{name}_{unit}"],
            records[order - 1][part][f"max_{unit}"],
            rtol=1e-12,
            atol=1e-9 * UNIT,
        )
    # and at the file's own pitch, the file itself
    assert result.parameter.file_value == "100 mm"
    plain = balance.analyse(balance.load(path)).to_dict()["orders"]
    assert result.points[0]["M1_Nm"] == plain[0]["moment"]["max_Nm"]


def test_bore_pitch_of_two_crankshafts_moves_both(tmp_path):
    # the Jumo 205's two crankshafts carry six throws each at 150 mm: a pitch of 170 mm puts
    # the k-th throw of each at k·170 mm
    result = balance.sweep(ROOT / JUMO, "bore_pitch", ["150 mm", "170 mm"], "M1")
    assert result.parameter.file_value == "150 mm"
    z = [t.z_m for t in result.engines[1].throws]
    assert_allclose(z, [k * 0.170 for k in range(6)] * 2, rtol=1e-12, atol=1e-15)
    assert [t.crankshaft_index for t in result.engines[1].throws] == [0] * 6 + [1] * 6


@pytest.mark.parametrize(
    "text, parameter, words",
    [
        (LINKED, "rod_ratio", "link rods ([links])"),
        (SINGLE, "bore_pitch", "one throw on each crankshaft"),
        (
            TWIN.replace("firing_order = [1, 2]\n", "") + '[[throws]]\nphase = 90\nz = "200 mm"\n',
            "bore_pitch",
            "not evenly spaced (gaps 90 mm, 110 mm)",
        ),
        (replaced('z = "90 mm"', 'z = "0 mm"'), "bore_pitch", "all sit at one z"),
    ],
)
def test_a_derived_parameter_the_engine_does_not_define_is_refused(
    tmp_path, text, parameter, words
):
    path = write(tmp_path, text)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(path, parameter, [3.0] if parameter == "rod_ratio" else ["100 mm"])
    assert caught.value.parameter == "parameter"
    assert f"'{parameter}' is not defined for {path}: " in str(caught.value)
    assert words in str(caught.value)
    assert "\n" not in str(caught.value)


def test_link_rods_on_a_listed_cylinder_refuse_the_rod_ratio(tmp_path):
    # [[cylinders]] naming a master are link rods too
    text = TWIN.replace("firing_order = [1, 2]\n", "") + (
        "[[banks]]\nangle = 60\n"
        "[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n"
        "[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 1\nmaster = 1\n"
        'link_length = "110 mm"\nknuckle_radius = "30 mm"\n'
        "[[cylinders]]\nnumber = 3\nbank = 1\nthrow = 2\n"
    )
    path = write(tmp_path, text)
    balance.load(path)  # a valid engine
    with pytest.raises(balance.SweepError, match=r"cylinders\[2\].master"):
        balance.sweep(path, "rod_ratio", [3.0])


def test_bore_pitch_of_uneven_crankshafts_is_refused(tmp_path):
    text = (
        TWIN.replace("firing_order = [1, 2]\n", "")
        + "[[crankshafts]]\n[[crankshafts]]\n"
        + 'x = "300 mm"\n'
        + '[[throws]]\nphase = 0\nz = "0 mm"\ncrankshaft = 2\n'
        + '[[throws]]\nphase = 180\nz = "80 mm"\ncrankshaft = 2\n'
    )
    text = text.replace("[[banks]]\nangle = 0\n", "[[banks]]\nangle = 0\n", 1)
    path = write(tmp_path, text)
    balance.load(path)
    with pytest.raises(balance.SweepError, match="crankshaft 1 are 90 mm apart and those of "):
        balance.sweep(path, "bore_pitch", ["100 mm"])


@pytest.mark.parametrize(
    "parameter, value, words",
    [
        ("rod_ratio", 0.9, "rod_length of 0.036 m is not longer than the crank radius"),
        ("rod_ratio", -2.0, "must be a ratio greater than zero"),
        ("stroke", "-80 mm", "must be greater than zero"),
        ("stroke", "80 kg", "is a mass"),
        ("bore_pitch", "0 mm", "must be greater than zero"),
        ("rod_ratio", "3 mm", "written without a unit"),
    ],
)
def test_a_derived_value_that_makes_no_engine_names_the_parameter(
    tmp_path, parameter, value, words
):
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError) as caught:
        balance.sweep(path, parameter, [value])
    assert words in str(caught.value)
    assert "\n" not in str(caught.value)


def test_every_kind_has_an_si_unit():
    # `--vary power` ended in KeyError 'power' when JSON and CSV asked for its SI unit
    data = {"crank_radius": "40 mm", "rod_length": "140 mm"}
    kinds = {kind for table in SCHEMA.values() for kind in table.values()}
    kinds |= {d.kind for d in DERIVED.values()}
    for kind in kinds:
        assert isinstance(balance.studies.sweep.Parameter("x", kind, ()).unit_si, str), kind
    assert parameter_of(data, "power").unit_si == "W"
    assert parameter_of(data, BALANCE_FACTOR).changes == ()


def test_an_unknown_key_lists_the_derived_parameters(tmp_path):
    path = write(tmp_path, TWIN)
    with pytest.raises(balance.SweepError, match="rod_ratio, stroke, bore_pitch"):
        balance.sweep(path, "rod_ratoi", [3.0])


def test_rod_ratio_as_an_override_follows_a_varied_crank_radius(tmp_path):
    # the derived parameter is set after the key it reads: l = 3.5 × r at every r
    path = write(tmp_path, SINGLE)
    radii = [0.030, 0.040, 0.050]
    result = balance.sweep(
        path,
        "crank_radius",
        [f"{r * 1000:g} mm" for r in radii],
        "F2",
        overrides={"rod_ratio": 3.5},
    )
    assert_allclose([e.rod_length_m for e in result.engines], np.array(radii) * 3.5, rtol=1e-15)
    # at one λ the secondary scales with r: m·r·ω²·A₂(1/3.5)
    expected = M_REC * np.array(radii) * rad_s(3000) ** 2 * exact_series_a2(1 / 3.5)
    assert_allclose(result.series("F2"), expected, rtol=2e-5, atol=0)
    assert math.isclose(result.to_dict()["overrides"]["rod_ratio"], 3.5)


@pytest.mark.parametrize("parameter", ["rod_ratio", "stroke", "bore_pitch"])
def test_the_files_own_value_gives_the_file_itself(tmp_path, parameter):
    # the value a derived parameter has in the file writes the file's keys back unchanged (a
    # rod or throw already where the value puts it, to rounding, keeps its text): the point is
    # compare's record of the file, to the last digit
    path = write(tmp_path, TWIN)
    data = balance.read_configuration(path).data
    own = parameter_of(data, parameter, str(path)).file_value
    result = balance.sweep(path, parameter, [own], "F2,M1,F4")
    records = balance.analyse(balance.load(path)).to_dict()["orders"]
    assert result.points[0]["F2_N"] == records[1]["force"]["max_N"]
    assert result.points[0]["F4_N"] == records[3]["force"]["max_N"]
    assert result.points[0]["M1_Nm"] == records[0]["moment"]["max_Nm"]
    assert result.engines[0] == balance.load(path)
