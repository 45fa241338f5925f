"""Regressions found by reviewing the library after issues 8 and 9 (each failed before its fix)."""

import dataclasses
import json
import math

import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli
import balance_cli as balance
from balance_cli.cli import main
from balance_cli.model import Throw
from tests.support import CONFIGS, make_engine

BRAMO = CONFIGS / "bramo-323.toml"


def invoke(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def test_antivibrateur_mass_counts_with_a_balance_factor():
    """The rotor rides on the crank pin: sized by a balance factor, the counterweight must carry
    it too, so the first order left is the same with and without the rotor."""
    engine = balance.load(BRAMO)
    plain = balance.counterweights(engine, balance_factor=0.5)
    rotor = balance.counterweights(engine, balance_factor=0.5, antivibrateur_radius_m=0.04)
    unit = engine.per_cylinder_unit_n
    for a, b in ((plain.residual.order(1).force_forward, rotor.residual.order(1).force_forward),
                 (plain.residual.order(1).force_backward, rotor.residual.order(1).force_backward)):
        assert abs(a - b) < 1e-9 * unit
    assert_allclose(rotor.counterweights[0].mass_kg - plain.counterweights[0].mass_kg,
                    rotor.antivibrateur.mass_kg * engine.crank_radius_m / rotor.counterweights[0].radius_m,
                    rtol=1e-9)


def test_counterweight_angle_is_measured_from_throw_one():
    """A single with its throw at 90° from the reference axis (throw 1's phase 90°): the
    counterweight sits opposite the throw, 180° from it as a throw phase is measured."""
    engine = make_engine([0], [(90, 0.0)], rotating=1.0)
    (weight,) = balance.counterweights(engine).counterweights
    assert_allclose(weight.angle_deg, 180.0, atol=1e-9)


@pytest.mark.parametrize("command", [["plot", "--kind", "star", "-o", "s.png"],
                                     ["report", "-o", "rep"]])
def test_max_order_one_draws_the_first_order_star(tmp_path, monkeypatch, command):
    monkeypatch.chdir(tmp_path)
    result = invoke(command[0], CONFIGS / "inline-4-car.toml", "--max-order", "1", *command[1:])
    assert result.exit_code == 0, result.output


def test_plot_order_outside_the_analysis_is_a_plot_error():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"), max_order=2)
    for call in (lambda: balance.plot.star([result], order=3),
                 lambda: balance.plot.locus([result], order=0),
                 lambda: balance.plot.star_chains(result, 5)):
        with pytest.raises(balance.PlotError, match="is not among the orders analysed"):
            call()


def test_a_plane_in_a_foreign_digit_is_one_error_line(tmp_path):
    result = invoke("counterweight", CONFIGS / "inline-4-car.toml", "--planes", "¹")
    assert result.exit_code == 1 and result.stderr.count("\n") == 1
    assert "--planes: cannot read '¹'" in result.stderr


def test_locus_points_must_fit_the_samples():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))
    assert len(result.shaking.locus()) == 4 * 256
    for points in (0, -4, 100, 2.5):
        with pytest.raises(balance.AnalysisError, match="points must be a positive multiple"):
            result.shaking.locus(points=points)


def test_engine_fields_given_as_lists_become_tuples():
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    listed = dataclasses.replace(engine, throws=list(engine.throws), cylinders=list(engine.cylinders),
                                 firing_order=[1, 2])
    assert listed.throws == engine.throws and hash(listed)
    assert balance.analyse(listed).order(2) == balance.analyse(engine).order(2)
    with pytest.raises(balance.ModelError, match="Throw objects"):
        dataclasses.replace(engine, throws=((0.0, 0.0),))
    with pytest.raises(balance.ModelError, match="firing_order"):
        dataclasses.replace(engine, firing_order=(1, "2"))
    with pytest.raises(balance.ModelError, match="cycle must be 2 or 4"):
        dataclasses.replace(engine, cycle=4.0)
    assert Throw(0.0).z_m == 0.0


@pytest.mark.parametrize("damage, words", [
    (lambda e: e["orders"][0].pop("force"), "has an order that is not"),
    (lambda e: e.update(orders="x"), "has no list of orders"),
    (lambda e: e.update(name=["a"]), "has a name or config that is not text"),
    (lambda e: e["orders"][0]["force"].update(max_N=math.nan), "has an order that is not"),
    (lambda e: e.update(unit_force_N=-1.0), "has no positive unit_force_N"),
    (lambda e: e["firing"].update(order=None), "has no firing order"),
])
def test_a_damaged_baseline_is_one_error_line(tmp_path, damage, words):
    document = balance.compare([balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))]).to_dict()
    damage(document["engines"][0])
    baseline = tmp_path / "b.json"
    baseline.write_text(json.dumps(document), encoding="utf-8")
    result = invoke("regress", baseline, CONFIGS / "inline-4-car.toml")
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr.count("\n") == 1 and words in result.stderr


def test_regression_refuses_engines_analysed_otherwise():
    engine = balance.load(CONFIGS / "inline-4-car.toml")
    baseline = balance.compare([balance.analyse(engine)]).to_dict()
    with pytest.raises(balance.RegressError, match="analysed with max_order = 10"):
        balance.regression(baseline, balance.compare([balance.analyse(engine, max_order=10)]))
    assert not balance.regression(baseline, balance_cli.studies.regress.reanalyse(baseline, [engine])).moved


def test_rtol_loosens_a_firing_angle_by_radians_not_by_its_size():
    document = balance.compare([balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))]).to_dict()
    moved = json.loads(json.dumps(document))
    moved["engines"][0]["firing"]["angles_deg"][3] += 0.5          # 540° -> 540.5°
    rows = balance.regression(document, moved, rtol=0.005).rows   # 0.005 rad = 0.29°
    assert [r.quantity for r in rows] == ["firing angle of cylinder 2"]
    assert rows[0].change == pytest.approx(0.5) and rows[0].relative_change is None
    assert not balance.regression(document, moved, rtol=0.01).moved   # 0.57°


def test_tdc_search_memory_is_linear_in_cylinders():
    """piston_travel of chosen cylinders computes only those (and their masters): the TDC
    refinement of a 400-cylinder grid needs arrays of 101 angles, not 400 × 400 × 101."""
    engine = make_engine([3.6 * i for i in range(20)], [(18 * t, 0.05 * t) for t in range(20)],
                         cycle=2)
    travel = balance_cli.kinematics.linkage.piston_travel(engine, [0.0, 0.1], [7])
    assert list(travel) == [7]
    tdc = balance_cli.kinematics.tdc_angles(engine)
    assert len(tdc) == 400
    cylinder = engine.cylinder(27)   # bank 2 (3.6°), throw 7 (108°): TDC at 3.6 − 108 mod 360
    assert_allclose(tdc[27], (3.6 - 108.0) % 360, atol=1e-5)
    assert cylinder.bank == 2


def test_a_report_says_when_samples_are_too_few(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke("report", CONFIGS / "inline-4-marine.toml", "-o", "rep", "--samples", "16",
                    "--max-order", "3")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "rep" / "report.md").read_text(encoding="utf-8")
    assert "1 engine, 16 samples" in text
    assert "Warning: 16 samples a revolution are too few for In-line 4 marine" in text
    assert "warning:" in result.stderr and "wrote rep/report.md" in result.stderr
    assert result.stdout == ""


def test_negative_zero_reads_as_zero(tmp_path):
    result = invoke("counterweight", CONFIGS / "inline-4-car.toml", "--balance-factor", "-0",
                    "--format", "json")
    assert '"balance_factor": 0.0' in result.stdout
    config = tmp_path / "e.toml"
    config.write_text((CONFIGS / "inline-4-car.toml").read_text().replace(
        "[[banks]]\nangle = 0", "[[banks]]\nangle = -0.0"), encoding="utf-8")
    assert "(-0°)" not in invoke("show", config).stdout


def test_shafts_for_a_zero_order_say_none_are_needed():
    result = invoke("counterweight", CONFIGS / "tanaka-part3" / "3-inline-6.toml", "--shafts", "3")
    assert result.exit_code == 0
    assert "Balancer shafts: none needed; the orders asked for are already zero." in result.stdout


def test_regress_finds_configurations_from_the_baselines_folders(tmp_path, monkeypatch):
    """The README's CI example: a baseline written at the repository's root, kept in design/,
    naming design/x.toml, checked from inside design/."""
    design = tmp_path / "design"
    design.mkdir()
    (design / "car.toml").write_text((CONFIGS / "inline-4-car.toml").read_text(), encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert invoke("compare", "design", "--format", "json", "-o", "design/baseline.json").exit_code == 0
    monkeypatch.chdir(design)
    result = invoke("regress", "baseline.json")
    assert result.exit_code == 0, result.output


def test_a_single_engine_grid_picture_is_wide_enough_for_its_title():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))
    for draw in (balance.plot.star, balance.plot.firing):
        width, _ = draw([result]).get_size_inches()
        assert width == balance.plot.MIN_WIDTH_IN
