"""Choosing criticals (kind, orders, modes), the sweep's largest peak and what makes it, mode
shapes scaled to their largest amplitude, and the torsion functions' argument checks."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import AnalysisError
from balance_cli.torsion import phase_vector_sum
from tests.support import INLINE6, REFERENCE, ROOT, TORSION6

MENDES = ROOT / "configs" / "mendes2008-mwm-6.toml"


@pytest.fixture(scope="module")
def six():
    return balance.torsional_vibration(balance.loads(INLINE6 + TORSION6), None, 12)


def test_major_keeps_the_excited_criticals_of_orders_that_put_every_cylinder_in_phase(six):
    """An even-firing four-stroke six fires every 120°: order k puts every cylinder in phase
    when k·120° is a multiple of 360°, k = 3, 6, 9, 12 (test_torsion's geometric series)."""
    major = six.filtered("major").criticals
    assert major and {c.order for c in major} <= {3.0, 6.0, 9.0, 12.0}
    assert all(c.excited for c in major)
    assert {c.order for c in six.criticals if c.order % 3 == 0} == {c.order for c in major}
    assert six.filtered("major").selection == {"kind": "major", "orders": None, "modes": None}


def test_orders_and_modes_keep_those_only(six):
    chosen = six.filtered("all", orders=[4.5, 6], modes=[1])
    assert chosen.criticals
    assert {(c.order, c.mode) for c in chosen.criticals} == {
        (c.order, c.mode) for c in six.criticals if c.order in (4.5, 6.0) and c.mode == 1
    }
    # the response and the modes are kept whole
    assert chosen.modes == six.modes and chosen.torque_nm is six.torque_nm
    assert chosen.to_dict()["criticals_chosen"] == {
        "kind": "all",
        "orders": [4.5, 6.0],
        "modes": [1],
    }


@pytest.mark.parametrize(
    "kwargs, parameter, words",
    [
        (dict(criticals="minor"), "criticals", "excited, major, all"),
        (dict(orders=[4.25]), "orders", "steps of ½"),
        (dict(orders=[13]), "orders", "0.5 to 12"),
        (dict(orders="6"), "orders", "list of orders"),
        (dict(orders=[True]), "orders", "True"),
        (dict(orders=[]), "orders", "one order or more"),
        (dict(modes=[0]), "modes", "modes 1 to"),
        (dict(modes=[99]), "modes", "modes 1 to"),
        (dict(modes=[1.5]), "modes", "1.5"),
    ],
)
def test_filters_refuse_what_the_result_does_not_hold(six, kwargs, parameter, words):
    with pytest.raises(AnalysisError) as caught:
        six.filtered(**kwargs)
    assert caught.value.parameter == parameter and words in str(caught.value)


def test_the_largest_peak_of_a_minor_order_is_found():
    """The Mendes six above its 6th-order critical (2 500-3 100 rpm): its largest torque is the
    first mode's 4.5th-order resonance, at 60·f₁/4.5 = 60·216.58/4.5 = 2 888 rpm, a minor order
    (4.5·120° = 540° is not a multiple of 360°); the peak names it whatever criticals the
    result keeps."""
    result = balance.torsional_vibration(balance.load(MENDES), np.arange(2500.0, 3101.0, 10.0))
    for shown in (result, result.filtered("major")):
        peak = shown.peak()
        assert (peak.order, peak.mode, peak.major) == (4.5, 1, False)
        assert_allclose(peak.critical_rpm, 60 * shown.modes[0].frequency_hz / 4.5, rtol=1e-12)
        # the peak is the sweep's largest torque and sits within one 10 rpm step of the critical
        assert peak.torque_nm == result.torque_nm.max()
        assert abs(peak.speed_rpm - peak.critical_rpm) <= 10
    assert result.to_dict()["peak"]["order"] == 4.5


def test_modes_are_scaled_by_their_whole_shape():
    """The nine-inertia Mendes line's eigenvectors by a second solver (scipy's symmetric
    generalised eigh, J and k typed in from openTorsion's example), each divided by its
    largest-magnitude entry by hand and entries below 1e-8 of it set to zero (the flywheel's
    −6.7e-9 in mode 8; the stated MODE_FLOOR): the reported shapes agree, and every shape's
    largest
    amplitude is +1 (the 8th mode's throws move less than its gear train: scaled by the
    throws' largest, the gear train came out −8.25)."""
    from scipy.linalg import eigh

    inertias = [0.0170, 0.0090, 0.0467, 0.0327, 0.0467, 0.0467, 0.0327, 0.0487, 2.0750]
    k = [1.106e6, 1.631e6, 1.253e6, 1.253e6, 1.678e6, 1.253e6, 1.253e6, 1.976e6]
    stiffness = np.zeros((9, 9))
    for i, ki in enumerate(k):
        stiffness[i : i + 2, i : i + 2] += ki * np.array([[1, -1], [-1, 1]])
    _, vectors = eigh(stiffness, np.diag(inertias))
    engine = balance.load(REFERENCE / "opentorsion_ice" / "mendes2008.toml")
    result = balance.torsional_vibration(engine, [2000.0])
    for mode, vector in zip(result.modes, vectors[:, 1:].T, strict=True):
        by_hand = vector / vector[np.argmax(np.abs(vector))]
        by_hand[np.abs(by_hand) < 1e-8] = 0.0
        # well separated modes of a 9×9 pencil: the solvers agree to about 1e-12 of the largest
        assert_allclose(mode.shape, by_hand, atol=1e-9)
        assert max(abs(mode.shape)) == 1.0 and mode.shape[np.argmax(abs(mode.shape))] == 1.0
    assert_allclose(result.modes[7].shape[1], 1.0)


@pytest.mark.parametrize(
    "args, parameter",
    [
        (([1.0, 1.0], [0.0], 1), "firing_deg"),
        (([1.0, math.nan], [0.0, 120.0], 1), "amplitudes"),
        (([1.0, 1.0], [0.0, math.inf], 1), "firing_deg"),
        (([1.0], [0.0], math.nan), "order"),
        (([1.0], [0.0], True), "order"),
        ((["a"], [0.0], 1), "amplitudes"),
    ],
)
def test_phase_vector_sum_checks_its_arguments(args, parameter):
    with pytest.raises(AnalysisError) as caught:
        phase_vector_sum(*args)
    assert caught.value.parameter == parameter


@pytest.mark.parametrize(
    "speeds", [[True], [1000.0, True], np.array([True]), [1000.0, "x"], "1000", [[1000.0]]]
)
def test_speeds_that_are_not_numbers_are_refused(speeds):
    """``speeds_rpm=[True]`` was once taken as 1 rpm."""
    engine = balance.loads(INLINE6 + TORSION6)
    with pytest.raises(AnalysisError) as caught:
        balance.torsional_vibration(engine, speeds)
    assert caught.value.parameter == "speeds_rpm"


def test_one_speed_alone_is_a_sweep_of_one():
    engine = balance.loads(INLINE6 + TORSION6)
    result = balance.torsional_vibration(engine, 1500, 6)
    assert_allclose(result.speeds_rpm, [1500.0], rtol=0)
