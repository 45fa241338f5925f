"""openTorsion's example, the Mendes et al. (2008) six-cylinder diesel: its natural
frequencies by a Holzer table and by a second eigen-solver, and its resonance."""

import math

import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.torsion import torsional_vibration as torsion
from tests.support import REFERENCE, holzer


def test_mendes_model_frequencies_by_holzer():
    """The openTorsion example's nine-inertia model of Mendes et al. (2008), Fig. 4: every
    natural frequency balance reports leaves no residual torque in a Holzer table (a
    bisection on the residual's sign change finds the same roots, written apart from
    openTorsion)."""
    from scipy.optimize import brentq

    engine = balance.load(REFERENCE / "opentorsion_ice" / "mendes2008.toml")
    result = torsion(engine, [2000.0], 12)
    j = list(result.inertia_kgm2)
    k = list(result.stiffness_nm_rad)
    assert len(j) == 9 and len(result.modes) == 8
    for mode in result.modes:
        w2 = (2 * math.pi * mode.frequency_hz) ** 2
        # bracket the root by ±0.1 % and find it from the residual alone
        root = brentq(lambda x: holzer(j, k, x)[1], w2 * 0.999, w2 * 1.001, xtol=1e-9 * w2)
        assert_allclose(w2, root, rtol=1e-8)
    # the first mode's 6th-order critical is the measured resonance of Fig. 31, 2 149 rpm
    # (tests/reference/opentorsion_ice), within the figure's digitising and the model's
    # own error: 2 %
    assert_allclose(60 * result.modes[0].frequency_hz / 6, 2149.3, rtol=0.02)


def test_the_mendes_models_natural_frequencies_by_a_second_eigen_solver():
    """The nine-inertia line of openTorsion's example (the paper's Fig. 4), its J and k typed
    in here from the example's source, solved as the generalised eigenproblem K·x = ω²·M·x by
    scipy: openTorsion's frequencies through balance agree to rounding."""
    from scipy.linalg import eigh

    J = [0.0170, 0.0090, 0.0467, 0.0327, 0.0467, 0.0467, 0.0327, 0.0487, 2.0750]
    k = [1.106e6, 1.631e6, 1.253e6, 1.253e6, 1.678e6, 1.253e6, 1.253e6, 1.976e6]
    K = np.zeros((9, 9))
    for i, ki in enumerate(k):
        K[i : i + 2, i : i + 2] += ki * np.array([[1, -1], [-1, 1]])
    w2 = eigh(K, np.diag(J), eigvals_only=True)
    expected = np.sqrt(np.clip(w2[1:], 0, None)) / (2 * math.pi)  # the rigid mode left out
    path = REFERENCE / "opentorsion_ice/mendes2008.toml"
    result = balance.torsional_vibration(balance.load(path), [2000.0])
    assert_allclose([m.frequency_hz for m in result.modes], expected, rtol=1e-9)
    assert_allclose(expected[0], 216.6, atol=0.05)  # the first mode the validation speaks of


def test_resonances_marked_at_the_nearest_speed():
    """A critical belongs to the sweep's speed nearest it: the 6th order of the Mendes six's
    first mode (216.6 Hz·60/6 ≈ 2166 rpm, between 2150 and 2200) to 2150 rpm only."""
    engine = balance.load(REFERENCE / "opentorsion_ice" / "mendes2008.toml")
    result = torsion(engine, [2100.0, 2150.0, 2200.0], 12)
    (critical,) = [c for c in result.criticals if c.order == 6]
    assert 2150 < critical.speed_rpm < 2175
    assert critical in result.near(2150.0)
    assert critical not in result.near(2100.0) + result.near(2200.0)
    entry = result.to_dict()["response"][1]
    assert {"mode": 1, "order": 6.0} in entry["criticals"]
