"""Regression tables from Python (balance.regression): what moved between a baseline and now."""

import json

import pytest

import balance_cli
import balance_cli as balance
from balance_cli.studies.regress import regression as regress
from tests.support import CONFIGS


def test_regress_from_python():
    """The library function on a document: a phase that turns is a row; one of a phasor at
    the noise level is not."""
    import balance_cli as balance

    comparison = balance.compare([balance.analyse(balance.load(CONFIGS / "abc-dragonfly.toml"))])
    baseline = comparison.to_dict()
    changed = json.loads(json.dumps(baseline))
    second = changed["engines"][0]["orders"][1]["force"]
    second["forward_deg"] = (second["forward_deg"] + 0.5) % 360
    rows = regress(baseline, changed).rows
    assert [(r.order, r.quantity) for r in rows] == [(2, "force.forward_deg")]
    assert rows[0].change == pytest.approx(0.5, abs=1e-9)
    assert not regress(baseline, comparison).moved


def test_regression_refuses_engines_analysed_otherwise():
    engine = balance.load(CONFIGS / "inline-4-car.toml")
    baseline = balance.compare([balance.analyse(engine)]).to_dict()
    with pytest.raises(balance.RegressError, match="analysed with max_order = 10"):
        balance.regression(baseline, balance.compare([balance.analyse(engine, max_order=10)]))
    assert not balance.regression(
        baseline, balance_cli.studies.regress.reanalyse(baseline, [engine])
    ).moved


def test_rtol_loosens_a_firing_angle_by_radians_not_by_its_size():
    document = balance.compare(
        [balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))]
    ).to_dict()
    moved = json.loads(json.dumps(document))
    moved["engines"][0]["firing"]["angles_deg"][3] += 0.5  # 540° -> 540.5°
    rows = balance.regression(document, moved, rtol=0.005).rows  # 0.005 rad = 0.29°
    assert [r.quantity for r in rows] == ["firing angle of cylinder 2"]
    assert rows[0].change == pytest.approx(0.5) and rows[0].relative_change is None
    assert not balance.regression(document, moved, rtol=0.01).moved  # 0.57°
