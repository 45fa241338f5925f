"""The project-guide table of an engine family (`balance family`).

Independent expected values: for an in-line two-stroke with even firing, throws β_j at pitch d
and reciprocating mass m, the reciprocating first-order couple is m·r·ω²·|S₁|·cos along the
cylinders, with S_k = Σ (z_j − z̄)·e^{ikβ_j}; counterweights for the rotating masses and a
fraction c of the reciprocating ones leave (1 − c)·m·r·ω²·|S₁| vertical and c·m·r·ω²·|S₁|
horizontal (the guides' standard balance c = ½: half each way). The order-k couple (k ≥ 2) is
m·r·ω²·|B_k|·|S_k|, vertical (B_k from ``tests.support.exact_b``). A brute force over every
crank (throw 1 at 0°) finds the least M1V + M1H + M2V + M4V = m·r·ω²·(|S₁| + |B₂|·|S₂| +
|B₄|·|S₄|), what the family's default objective minimises."""

import cmath
import itertools
import json
import math

import pytest
from numpy.testing import assert_allclose

from balance_cli.config import read_configuration
from balance_cli.errors import BalanceError
from balance_cli.studies.family import family
from tests.support import CONFIGS, exact_b, invoke

MARINE = CONFIGS / "marine-6-2stroke.toml"
M, R, L, D, RPM = 8000.0, 1.2, 2.9, 1.02, 105.0
UNIT = M * R * (RPM * math.pi / 30) ** 2


def couples(phases_deg, orders=(1, 2, 4)):
    """|S_k| of a crank at the marine six's pitch, for k in ``orders``."""
    n = len(phases_deg)
    arms = [(j - (n - 1) / 2) * D for j in range(n)]
    return [
        abs(
            sum(
                a * cmath.exp(1j * k * math.radians(b))
                for a, b in zip(arms, phases_deg, strict=True)
            )
        )
        for k in orders
    ]


def brute_force(n):
    """The least |S₁| + |B₂|·|S₂| + |B₄|·|S₄| over every even-firing two-stroke crank of n
    throws."""
    b2, b4 = abs(exact_b(R / L, 2)), abs(exact_b(R / L, 4))
    best = math.inf
    for rest in itertools.permutations(range(1, n)):
        s1, s2, s4 = couples([0.0] + [360.0 * k / n for k in rest])
        best = min(best, s1 + b2 * s2 + b4 * s4)
    return best


@pytest.fixture(scope="module")
def table():
    return family(read_configuration(MARINE), range(5, 8), workers=1)


def test_each_row_is_the_least_couple_a_crank_can_have(table):
    b2, b4 = abs(exact_b(R / L, 2)), abs(exact_b(R / L, 4))
    # atol: a cancelled couple is rounding of phasors of the order of UNIT·d
    atol = 1e-6 * UNIT
    for row in table.rows:
        record = row.to_dict()
        s1, s2, s4 = couples(record["phases_deg"])
        assert_allclose(s1 + b2 * s2 + b4 * s4, brute_force(row.cylinders), rtol=1e-9, atol=1e-9)
        assert row.method == "exhaustive"
        assert record["first_order_balance"]["name"] == "standard"
        # the guides' standard balance: M1V = M1H, half the reciprocating couple each way
        assert_allclose(record["M1V_Nm"], UNIT * s1 / 2, rtol=1e-9, atol=atol)
        assert_allclose(record["M1H_Nm"], UNIT * s1 / 2, rtol=1e-9, atol=atol)
        assert_allclose(record["M1V_rotating_Nm"], UNIT * s1, rtol=1e-9, atol=atol)
        assert_allclose(record["M1H_rotating_Nm"], 0.0, atol=atol)
        assert_allclose(record["M2V_Nm"], UNIT * b2 * s2, rtol=1e-9, atol=atol)
        assert_allclose(record["M4V_Nm"], UNIT * b4 * s4, rtol=1e-9, atol=atol)
        assert record["M2H_Nm"] == 0.0 and record["M4H_Nm"] == 0.0


def test_six_cylinders_fire_as_the_project_guides_say_and_need_a_compensator(table):
    """The 6-cylinder's least couple is 1-5-3-4-2-6 (or the same crank read backwards): no first
    order, M2V = 2√3·d·m·r·ω²·|B₂| (2√3: |S₂|/d of that crank), PRU 124 N·m/kW at
    6 × 2380 kW, likely to need a second-order compensator (120 to 220)."""
    six = next(r for r in table.rows if r.cylinders == 6).to_dict()
    assert six["firing_order"] in ([1, 5, 3, 4, 2, 6], [1, 6, 2, 4, 3, 5])
    m2v = 2 * math.sqrt(3) * D * UNIT * abs(exact_b(R / L, 2))
    assert_allclose(six["M2V_Nm"], m2v, rtol=1e-9)
    second = six["pru"]["orders"][1]
    assert_allclose(second["vertical_Nm_per_kW"], m2v / 14280.0, rtol=1e-9)
    assert six["second_order_compensator"] is True and six["power_kW"] == 14280.0


def test_a_given_firing_order_is_taken(tmp_path):
    """6:1-4-2-6-3-5 has no second-order couple (its S₂ = 0) but a first-order one."""
    out = invoke(
        "family", MARINE, "--cylinders", "6", "--firing-order", "6:1-4-2-6-3-5", "--format", "json"
    )
    assert out.exit_code == 0, out.output
    (row,) = json.loads(out.output)["rows"]
    assert row["method"] == "given" and row["firing_order"] == [1, 4, 2, 6, 3, 5]
    s1, s2 = couples(row["phases_deg"], (1, 2))
    assert s2 < 1e-12 and row["M2V_Nm"] == 0.0
    assert_allclose([row["M1V_Nm"], row["M1H_Nm"]], [UNIT * s1 / 2] * 2, rtol=1e-9)
    assert_allclose(row["M1V_rotating_Nm"], UNIT * s1, rtol=1e-9)


def test_too_many_to_enumerate_is_searched_by_the_labelled_heuristic():
    rows = family(read_configuration(MARINE), [7], workers=1, limit=10).rows
    assert rows[0].method == "heuristic"


def test_table_csv_and_errors(tmp_path):
    text = invoke("family", MARINE, "--cylinders", "5,6", "--units", "kN").output
    assert "M2V (kN·m)" in text and "1 776" in text and "exhaustive" in text
    csv_text = invoke("family", MARINE, "--cylinders", "6", "--format", "csv").output
    assert csv_text.splitlines()[0].startswith(
        "cylinders,firing_order,method,score,first_order_balance_factor,M1V_Nm,M1H_Nm,M2V_Nm"
    )
    for args, words in (
        (["--cylinders", "x"], "--cylinders"),
        (["--cylinders", "1"], "--cylinders"),
        (["--firing-order", "6:1-2-3"], "--firing-order"),
        (["--firing-order", "six"], "--firing-order"),
        (["--pitch", "0 mm"], "--pitch"),
        (["--objective", "Q1"], ""),
    ):
        out = invoke("family", MARINE, *args)
        assert out.exit_code in (1, 2) and words in out.output, (args, out.output)
        assert "Traceback" not in out.output
    # three banks: neither an in-line nor a V family
    out = invoke("family", CONFIGS / "nakanishi-w12-60-2stroke.toml", "--cylinders", "6")
    assert out.exit_code == 1 and "in-line or V" in out.output
    out = invoke(
        "family", CONFIGS / "inline-4-car.toml", "--cylinders", "4", "--firing-order", "4:1-3-4-2"
    )
    assert out.exit_code == 1 and "two-stroke" in out.output


def test_the_h_type_moment_of_n_cylinders_is_found_at_order_n():
    """An N-cylinder two-stroke's H-type moment lies at order N (N × one cylinder's), above the
    default eighth order for nine cylinders: the family analyses the torques that far."""
    (row,) = family(read_configuration(MARINE), [9], workers=1).rows
    record = row.to_dict()
    assert record["h_type"]["order"] == 9 and record["h_type"]["amplitude_Nm"] > 0


def test_the_table_says_what_the_guide_forces_include_and_the_csv_has_the_balanced_pru():
    text = invoke("family", MARINE, "--cylinders", "5").output
    assert "guide-force moments from inertia only" in text
    csv_lines = invoke("family", MARINE, "--cylinders", "5", "--format", "csv").output.splitlines()
    header, values = csv_lines[0].split(","), csv_lines[1].split(",")
    row = dict(zip(header, values, strict=True))
    # the PRU of each first-order figure is its moment over 5 × 2380 kW
    for name in ("", "_standard", "_rotating", "_crank"):
        for d in "VH":
            assert_allclose(
                float(row[f"PRU_M1{d}{name}_Nm_per_kW"]),
                float(row[f"M1{d}{name}_Nm"]) / 11900.0,
                rtol=1e-12,
                atol=1e-12,
            )
    assert float(row["M1V_Nm"]) == float(row["M1H_Nm"]) == float(row["M1V_standard_Nm"])


def test_family_options_in_words():
    for args, words in (
        (["--cylinders", "12-5"], "runs backwards"),
        (["--cylinders", "6", "--firing-order", "7:1-2-3-4-5-6-7"], "not among the numbers asked"),
        (
            [
                "--cylinders",
                "6",
                "--firing-order",
                "6:1-5-3-4-2-6",
                "--firing-order",
                "6:1-4-2-6-3-5",
            ],
            "given twice",
        ),
    ):
        out = invoke("family", MARINE, *args)
        assert out.exit_code in (1, 2) and words in out.output, out.output


INLINE_3 = """name = "In-line 3, four-stroke"
cycle = 4
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"

[masses]
reciprocating = "500 g"
rotating = "300 g"

[[banks]]
angle = 0

[[throws]]
z = "0 mm"

[[throws]]
z = "90 mm"

[[throws]]
z = "180 mm"
"""


def test_without_a_power_the_first_order_is_still_under_the_balance_it_names(tmp_path):
    """An in-line three (throws 120° apart at pitch d, any order) has |S₁| = √3·d. With no
    power there is no PRU, but the moments are the same: under the standard balance
    M1V = M1H = m·r·ω²·√3·d/2; rotating only M1V = m·r·ω²·√3·d, M1H = 0; as the crank stands
    M1V = (m + m_rot)·r·ω²·√3·d, M1H = m_rot·r·ω²·√3·d (m = 0.5 kg, m_rot = 0.3 kg,
    r = 40 mm, d = 90 mm, 3000 rpm). The 0.2.0 table showed the crank's figures (M1H 1 682 N·m
    with r·ω² of this file's) under the balanced label."""
    path = tmp_path / "three.toml"
    path.write_text(INLINE_3, encoding="utf-8")
    unit = 0.040 * (3000 * math.pi / 30) ** 2 * math.sqrt(3) * 0.090  # r·ω²·√3·d
    (row,) = family(read_configuration(path), [3], workers=1).to_dict()["rows"]
    assert row["pru"] is None and row["power_kW"] is None
    by_hand = {
        "": (0.25, 0.25),
        "_standard": (0.25, 0.25),
        "_rotating": (0.5, 0.0),
        "_crank": (0.8, 0.3),
    }
    for name, (v, h) in by_hand.items():
        assert_allclose(
            [row[f"M1V{name}_Nm"], row[f"M1H{name}_Nm"]],
            [v * unit, h * unit],
            rtol=1e-9,
            atol=1e-9 * unit,
            err_msg=name,
        )
    # a balance factor of one's own: (1 − c) vertical, c horizontal
    (own,) = family(read_configuration(path), [3], workers=1, first_order_balance=0.3).rows
    record = own.to_dict()
    assert record["first_order_balance"] == {
        "name": "factor",
        "balance_factor": 0.3,
        "description": own.balance.description,
    }
    assert_allclose([record["M1V_Nm"], record["M1H_Nm"]], [0.35 * unit, 0.15 * unit], rtol=1e-9)
    text = invoke("family", path, "--cylinders", "3", "--first-order-balance", "crank").output
    assert "as the crank stands" in text


def test_the_default_objective_is_the_guides_couples_whatever_the_balance_factor(tmp_path):
    """M1V + M1H = 2·|M1⁻| under any balance factor: the same objective (and crank) for
    standard, rotating and 0.3; M1+ as the crank stands. Weights by hand: 2·F1/F2 and F4/F2
    of one throw, with F1 = |F1⁺| + |F1⁻| = (m_rot + m/2) + m/2 = m + m_rot and
    F_k = m·|B_k| for k ≥ 2 (per r·ω²)."""
    path = tmp_path / "three.toml"
    path.write_text(INLINE_3, encoding="utf-8")
    b2, b4 = abs(exact_b(40 / 140, 2)), abs(exact_b(40 / 140, 4))
    w1, w4 = 2 * (0.5 + 0.3) / (0.5 * b2), b4 / b2
    for balance in ("standard", "rotating", 0.3):
        objective = family(
            read_configuration(path), [3], workers=1, first_order_balance=balance
        ).objective
        terms = dict(t.partition(":")[::2] for t in objective.split(","))
        assert set(terms) == {"M1-", "M2", "M4"} and terms["M2"] == ""
        assert_allclose(float(terms["M1-"]), w1, rtol=1e-5)  # printed to 6 digits
        assert_allclose(float(terms["M4"]), w4, rtol=1e-5)
    crank = family(read_configuration(path), [3], workers=1, first_order_balance="crank")
    assert crank.objective.startswith("M1+:")


def test_family_progress_starts_at_once_and_moves_inside_each_count():
    calls = []
    family(
        read_configuration(MARINE), [5, 7], workers=1, progress=lambda d, t: calls.append((d, t))
    )
    assert calls[0] == (0, 2000) and calls[-1] == (2000, 2000)
    # the seven's search reports on its way: points strictly between 1000 and 2000
    assert any(1000 < d < 2000 for d, _ in calls)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)


def test_family_arguments_refused_in_words():
    configuration = read_configuration(MARINE)
    for kwargs, name in (
        ({"limit": 0}, "limit"),
        ({"limit": True}, "limit"),
        ({"objective": 5}, "objective"),
        ({"progress": "x"}, "progress"),
        ({"first_order_balance": 2}, "first_order_balance"),
    ):
        with pytest.raises(BalanceError, match=name):
            family(configuration, [5], workers=1, **kwargs)
    # an empty objective is the default one
    assert family(configuration, [5], workers=1, objective="").objective.startswith("M1-:")
    for text in ("5-", "-14", "5-,7"):
        out = invoke("family", MARINE, "--cylinders", text)
        assert out.exit_code == 2 and "both ends" in out.output, out.output
