"""Pictures of torsional vibration: the largest peak labelled whatever its order, the
criticals the cylinders cannot excite drawn apart."""

import numpy as np

import balance_cli as balance
from balance_cli.plot import campbell, torque_speed
from balance_cli.units import Scale
from tests.support import ROOT

MENDES = ROOT / "configs" / "mendes2008-mwm-6.toml"


def texts(fig):
    return [t.get_text() for ax in fig.axes for t in ax.texts]


def test_the_largest_peak_is_labelled_even_of_a_minor_order():
    """Above the 6th-order critical the Mendes six's largest torque is the 4.5th order of mode
    1 (a minor order, at 60·216.58/4.5 = 2 888 rpm: tests/torsion/test_criticals.py); the
    picture names it even when only the major criticals are kept (those are the ones marked
    with lines)."""
    result = balance.torsional_vibration(balance.load(MENDES), np.arange(2500.0, 3101.0, 10.0))
    fig = torque_speed(result.filtered("major"))
    (label,) = [t for t in texts(fig) if t.startswith("order ")]
    assert label.startswith("order 4.5 (minor), mode 1 (2888 rpm):")
    peak = result.torque_nm.max()
    assert f"{peak:.4g} N·m at 2890 rpm" in label and "throw 4–throw 5" in label
    # in another unit, the figure in it
    fig = torque_speed(result, scale=Scale.of(False, "kN"))
    assert any(f"{peak / 1000:.4g} kN·m" in t for t in texts(fig))


def test_campbell_draws_criticals_the_cylinders_cannot_excite_apart():
    """The three-inertia line with its throw at mode 1's node (tests/torsion/test_nodes.py):
    mode 1's criticals are grey crosses, mode 2's red circles."""
    from tests.torsion.test_nodes import MAX_ORDER, THREE

    result = balance.torsional_vibration(balance.loads(THREE), None, MAX_ORDER).filtered("all")
    fig = campbell(result)
    markers = [line.get_marker() for line in fig.axes[0].lines]
    assert markers.count("x") == sum(not c.excited for c in result.criticals) > 0
    assert markers.count("o") == sum(c.excited for c in result.criticals)
