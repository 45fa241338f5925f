"""The even-banks search (``even_banks``): each bank of a V engine fires evenly on its own, the
other bank's cylinder on each throw the bank angle after its partner, as the makers of
medium-speed V engines fire them (the Wärtsilä Vasa 32's 12V32 A1-B1-A5-B5-A3-B3-A6-B6-A2-B2-
A4-B4: bank A the 6R32's order). Checked against the firing angles the analysis finds for each
arrangement listed, a brute force over every crank, and the tabled enumeration."""

import cmath
import itertools
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.firing import firing_angles
from balance_cli.config import read_configuration
from balance_cli.cranksearch import search
from balance_cli.errors import AnalysisError
from tests.support import TEMPLATES, TODAY, invoke

V_FAMILY = TEMPLATES / "v-family-4stroke.toml"
#: the template's bank angle (banks at ∓27.5°) and throw pitch
BANK_DEG, PITCH_M = 55.0, 0.53


def v_template(throws):
    """The V family's template with ``throws`` throws at its pitch."""
    import tomllib

    from balance_cli.config import build

    data = tomllib.loads(V_FAMILY.read_text(encoding="utf-8"))
    data["throws"] = [{"z": f"{j * 530} mm"} for j in range(throws)]
    del data["power"]
    return build(data, str(V_FAMILY), template=True)


def bank_firing(engine):
    """Each bank's firing angles (degrees of a 720° cycle), and each B cylinder's angle after
    the A cylinder on its throw."""
    angles = firing_angles(engine)
    banks = {0: [], 1: []}
    partner = {}
    for c in engine.cylinders:
        banks[c.bank_index].append(angles[c.number])
        partner.setdefault(c.throw_index, {})[c.bank_index] = angles[c.number]
    after = [(p[1] - p[0]) % 720.0 for p in partner.values()]
    return banks, after


@pytest.mark.parametrize("throws", [6, 7, 8])
def test_every_arrangement_listed_fires_evenly_bank_by_bank(throws):
    """By hand: m cylinders a bank fire every 720/m degrees; the B cylinder the bank angle,
    55°, after its partner (the analysis's own firing angles, not the search's)."""
    found = search(v_template(throws), "M1,M2,M4", top=6, even_banks=True, workers=1)
    assert found.even_banks and found.exhaustive
    for arrangement in found.arrangements:
        banks, after = bank_firing(arrangement.engine)
        for angles in banks.values():
            gaps = np.diff(sorted(angles) + [min(angles) + 720.0])
            assert_allclose(gaps, 720.0 / throws, atol=1e-6)  # degrees, to TDC precision
        assert_allclose(after, BANK_DEG, atol=1e-6)
        assert not arrangement.result.firing.uniform  # 55° and 65° for the V12


def brute_force(throws, weights):
    """The least Σ w_k·|S_k|/d over every bank-even crank: phases multiples of 720/m for
    m even (each taken by two throws), of 360/m for m odd (each by one), throw 1 at 0°;
    S_k = Σ (z_j − z̄)·e^{ikβ_j}."""
    m = throws
    step, cap = (720.0 / m, 2) if m % 2 == 0 else (360.0 / m, 1)
    slots = round(360.0 / step)
    pool = [p for p in range(slots) for _ in range(cap)]
    pool.remove(0)
    arms = np.array([(j - (m - 1) / 2) for j in range(m)])
    best = math.inf
    for rest in set(itertools.permutations(pool)):
        beta = np.radians(step * np.array((0,) + rest))
        value = sum(w * abs((arms * np.exp(1j * k * beta)).sum()) for k, w in weights.items())
        best = min(best, value)
    return best


@pytest.mark.parametrize("throws", [6, 7, 8])
def test_the_best_bank_even_crank_is_the_brute_forces(throws):
    """A V's throws are alike, so its M_k is |S_k|/d whatever the bank angle: the search's
    best score is the brute force's least Σ w_k·|S_k|/d. The V12 and V16 have mirror-
    symmetric cranks with no free moment (0); the V14 has none."""
    weights = {1: 2.0, 2: 1.0, 4: 0.5}
    found = search(v_template(throws), "M1:2,M2,M4:0.5", top=1, even_banks=True, workers=1)
    expected = brute_force(throws, weights)
    # sums of a few unit phasors, exact to rounding
    assert_allclose(found.arrangements[0].score, expected, rtol=1e-9, atol=1e-9)
    assert (expected < 1e-9) == (throws % 2 == 0)


def test_streamed_and_tabled_agree_on_a_bank_even_v():
    for throws in (7, 9):
        template = v_template(throws)
        lists = [
            search(template, "M1,M2", top=8, even_banks=True, workers=1, enumeration=e)
            for e in ("tabled", "streamed")
        ]
        assert [a.firing_order for a in lists[0].arrangements] == [
            a.firing_order for a in lists[1].arrangements
        ]
        assert lists[0].evaluated + lists[0].pruned == lists[1].evaluated + lists[1].pruned


def test_counts_of_a_bank_even_v12():
    """By hand: bank A is an in-line six four-stroke (phases multiples of 120°, each taken
    twice, throw 1 at 0°): 5!/(1!·2!·2!) = 30 cranks, each with 2³/2 = 4 orders of which
    cylinder of a pair fires first: 120 arrangements; no reversal (it would turn the banks
    over)."""
    found = search(v_template(6), "M1", top=1, even_banks=True, workers=1)
    assert found.arrangements_total == 120
    assert found.firing_orders_per_crank == 4
    assert found.arrangements_distinct == 120
    assert not any("other way round" in s for s in found.symmetries)


def test_without_even_banks_a_55_degree_v_cannot_fire_evenly():
    with pytest.raises(AnalysisError, match="even_banks") as caught:
        search(v_template(6), "M1", workers=1)
    assert caught.value.parameter == "template"
    run = invoke("search", V_FAMILY)
    assert run.exit_code == 1 and "--even-banks" in run.output
    run = invoke("search", V_FAMILY, "--even-banks", "--top", "1", "--format", "json")
    assert run.exit_code == 0 and '"even_banks": true' in run.output


def test_even_banks_needs_a_cylinder_of_each_bank_on_every_throw():
    """A split-pin V6: each throw carries one cylinder, of one bank."""
    template = read_configuration(TODAY / "v" / "v6-90-split-pin.toml").as_template().template()
    with pytest.raises(AnalysisError, match="one cylinder of each of the 2 banks") as caught:
        search(template, "M1", even_banks=True, workers=1)
    assert caught.value.parameter == "even_banks"
    with pytest.raises(AnalysisError) as caught:
        search(v_template(6), "M1", even_banks=True, allow_uneven=True, step_deg=30)
    assert caught.value.parameter == "even_banks"
    with pytest.raises(AnalysisError) as caught:
        search(v_template(6), "M1", even_banks="yes")
    assert caught.value.parameter == "even_banks"


def test_an_in_line_template_with_even_banks_is_an_even_search():
    """One bank: firing evenly within it is firing evenly."""
    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    plain = search(template, "M1,M2", top=4, workers=1)
    banks = search(template, "M1,M2", top=4, workers=1, even_banks=True)
    assert [a.firing_order for a in banks.arrangements] == [
        a.firing_order for a in plain.arrangements
    ]
    assert not banks.even_banks and banks.to_dict()["even_firing"]


def test_the_v12s_crank_is_the_in_line_sixs():
    """The V12's best crank for M1, M2, M4 is the in-line six's 0-240-120-120-240-0 (or its
    mirror 0-120-240-240-120-0), free of every couple: Σ (z_j − z̄)·e^{ikβ_j} = 0 for k = 1, 2,
    4 by its symmetry about the middle."""
    found = search(v_template(6), "M1,M2,M4", top=2, even_banks=True, workers=1)
    assert {a.phases_deg for a in found.arrangements} <= {
        (0.0, 240.0, 120.0, 120.0, 240.0, 0.0),
        (0.0, 120.0, 240.0, 240.0, 120.0, 0.0),
    }
    phases = found.arrangements[0].phases_deg
    arms = [(j - 2.5) * PITCH_M for j in range(6)]
    for k in (1, 2, 4):
        s = sum(a * cmath.exp(1j * k * math.radians(p)) for a, p in zip(arms, phases, strict=True))
        assert abs(s) < 1e-12
