"""A V engine family (`balance family` on a template of two banks): the medium-speed makers'
criteria, each checked by hand.

- Each bank fires evenly on its own: m cylinders a bank every 720/m degrees, the B cylinder
  of each throw the bank angle Δ (55°) or Δ + 360° after its partner (the Vasa 32's firing
  orders are bank by bank an in-line engine's, B following A).
- Free moments: identical throws make every order's couple |S_k| = |Σ (z_j − z̄)·e^{ikβ_j}|
  times one throw's figures, so the default objective, the search's M_k weighted by the
  couples c_k of two throws |S_k| = 1 m apart, is M1V + M1H + M2V + M2H + M4V + M4H over
  c₂·d; the V12, V16 and V20 cranks (the in-line 6, 8, 10's, symmetric about the middle) have
  none.
- Torsional major orders: at k = j·m/2 every cylinder of a bank fires in phase and the two
  banks add as |1 + e^{ik·Δ}|/2 = |cos(k·Δ/2)|; where k is a half order the two ways the banks
  can follow each other differ (Δ = 55° or 415°), and the lesser is taken.
"""

import cmath
import json
import math
import tomllib

import numpy as np
import pytest
from numpy.testing import assert_allclose

from balance_cli.analysis.firing import firing_angles
from balance_cli.config import read_configuration, read_provenance
from balance_cli.errors import AnalysisError
from balance_cli.studies.family import family
from tests.support import TEMPLATES, invoke

V_FAMILY = TEMPLATES / "v-family-4stroke.toml"
BANK_DEG, PITCH_M = 55.0, 0.53


@pytest.fixture(scope="module")
def table():
    return family(read_configuration(V_FAMILY), range(12, 21, 2), workers=1)


def s_k(phases_deg, k):
    """|Σ (z_j − z̄)·e^{ikβ_j}|, m."""
    n = len(phases_deg)
    return abs(
        sum(
            (j - (n - 1) / 2) * PITCH_M * cmath.exp(1j * k * math.radians(p))
            for j, p in enumerate(phases_deg)
        )
    )


def test_each_bank_fires_evenly_and_b_follows_a(table):
    for row in table.rows:
        engine = row.result.engine
        m = row.cylinders // 2
        angles = firing_angles(engine)
        by_throw: dict = {}
        for c in engine.cylinders:
            by_throw.setdefault(c.throw_index, {})[c.bank_index] = angles[c.number]
        for bank in (0, 1):
            own = sorted(a[bank] for a in by_throw.values())
            gaps = np.diff(own + [own[0] + 720.0])
            assert_allclose(gaps, 720.0 / m, atol=1e-6)  # degrees, to TDC precision
        after = {round((a[1] - a[0]) % 720.0, 6) for a in by_throw.values()}
        assert after in ({BANK_DEG}, {BANK_DEG + 360.0})


def test_v12_v16_v20_are_free_of_moments_and_v14_v18_are_not(table):
    for row in table.rows:
        record = row.to_dict()
        moments = [record[f"M{k}{d}_Nm"] for k in (1, 2, 4) for d in "VH"]
        phases = record["phases_deg"]
        if row.cylinders // 2 % 2 == 0:
            assert max(abs(s_k(phases, k)) for k in (1, 2, 4)) < 1e-12
            assert_allclose(moments, 0.0, atol=1e-6)  # N·m, of moments of tens of kN·m
        else:
            assert min(s_k(phases, k) for k in (1, 2)) > 0.01


def test_the_objective_is_the_sum_of_the_tabled_moments(table):
    """score·c₂·d = M1V + M1H + M2V + M2H + M4V + M4H; c₂ from the V14's own row, M2V + M2H over
    its |S₂| (by hand from its phases); then the V18 must agree with the same c₂."""
    rows = {row.cylinders: row.to_dict() for row in table.rows}
    v14 = rows[14]
    c2 = (v14["M2V_Nm"] + v14["M2H_Nm"]) / s_k(v14["phases_deg"], 2)
    for n in (14, 18):
        record = rows[n]
        total = sum(record[f"M{k}{d}_Nm"] for k in (1, 2, 4) for d in "VH")
        # the score's weights are printed to six digits
        assert_allclose(record["score"] * c2 * PITCH_M, total, rtol=1e-5)


def test_the_major_orders_are_the_banks_cosines(table):
    """k = j·m/2; |cos(k·Δ/2)| with Δ = 55° or 415°, the lesser at the first major order."""
    for row in table.rows:
        m = row.cylinders // 2
        (k1, v1), (k2, v2) = row.majors
        assert_allclose([k1, k2], [m / 2, m])
        options = [
            [abs(math.cos(math.radians(k * delta / 2))) for k in (k1, k2)]
            for delta in (BANK_DEG, BANK_DEG + 360.0)
        ]
        expected = min(options, key=lambda o: [round(x, 9) for x in o])
        assert_allclose([v1, v2], expected, atol=1e-9)
    majors = {row.cylinders: row.majors for row in table.rows}
    # by hand: the V14's first major order 3.5: |cos(96.25°)| = 0.1089, not |cos(726.25°)|
    assert_allclose(majors[14][0][1], abs(math.cos(math.radians(96.25))), atol=1e-9)
    assert_allclose(majors[12][0][1], abs(math.cos(math.radians(82.5))), atol=1e-9)


def test_the_template_says_where_each_number_comes_from():
    data = tomllib.loads(V_FAMILY.read_text(encoding="utf-8"))
    provenance = read_provenance(data, "templates/v-family-4stroke.toml")
    assert provenance.sources
    assert provenance.unknown_selectors(data) == []
    assert provenance.unsourced(data) == []
    # the published figures: the Vasa 32's stroke and 420 kW a cylinder at 750 rpm
    assert data["crank_radius"] == "175 mm" and data["speed"] == "750 rpm"
    assert data["power"] == f"{420 * 12} kW"


def test_the_command_takes_the_even_numbers_of_a_range():
    run = invoke("family", V_FAMILY, "--format", "json", "--workers", "1")
    assert run.exit_code == 0, run.output
    document = json.loads(run.output)
    assert [r["cylinders"] for r in document["rows"]] == [12, 14, 16, 18, 20]
    assert document["firing"] == "even within each bank"
    text = invoke("family", V_FAMILY, "--cylinders", "12,14", "--workers", "1").output
    assert "Major orders (vector sum)" in text and "3: 0.131, 6: 0.966" in text
    odd = invoke("family", V_FAMILY, "--cylinders", "13")
    assert odd.exit_code == 1 and "--cylinders must be even for a V family" in odd.output


def test_a_v_family_takes_no_given_firing_order():
    with pytest.raises(AnalysisError) as caught:
        family(read_configuration(V_FAMILY), [12], firing_orders={12: list(range(1, 13))})
    assert caught.value.parameter == "firing_orders"
