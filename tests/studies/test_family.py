"""The project-guide table of an engine family (`balance family`).

Independent expected values: for an in-line two-stroke with even firing, throws β_j at pitch d
and reciprocating mass m, the first-order couple left with the rotating masses balanced is
m·r·ω²·|S₁| and the second-order one m·r·ω²·|B₂|·|S₂|, with S_k = Σ (z_j − z̄)·e^{ikβ_j}
(each cylinder's primary and secondary forces lie along its axis; B₂ from
``tests.support.exact_b``). A brute force over every crank (throw 1 at 0°) finds the least
|S₁| + |B₂|·|S₂|, what the family's default objective minimises."""

import cmath
import itertools
import json
import math

import pytest
from numpy.testing import assert_allclose

from balance_cli.config import read_configuration
from balance_cli.studies.family import family
from tests.support import CONFIGS, exact_b, invoke

MARINE = CONFIGS / "marine-6-2stroke.toml"
M, R, L, D, RPM = 8000.0, 1.2, 2.9, 1.02, 105.0
UNIT = M * R * (RPM * math.pi / 30) ** 2


def couples(phases_deg):
    """|S₁| and |S₂| of a crank at the marine six's pitch."""
    n = len(phases_deg)
    arms = [(j - (n - 1) / 2) * D for j in range(n)]
    return [
        abs(
            sum(
                a * cmath.exp(1j * k * math.radians(b))
                for a, b in zip(arms, phases_deg, strict=True)
            )
        )
        for k in (1, 2)
    ]


def brute_force(n):
    """The least |S₁| + |B₂|·|S₂| over every even-firing two-stroke crank of n throws."""
    b2 = abs(exact_b(R / L, 2))
    best = math.inf
    for rest in itertools.permutations(range(1, n)):
        s1, s2 = couples([0.0] + [360.0 * k / n for k in rest])
        best = min(best, s1 + b2 * s2)
    return best


@pytest.fixture(scope="module")
def table():
    return family(read_configuration(MARINE), range(5, 8), workers=1)


def test_each_row_is_the_least_couple_a_crank_can_have(table):
    b2 = abs(exact_b(R / L, 2))
    for row in table.rows:
        record = row.to_dict()
        s1, s2 = couples(record["phases_deg"])
        assert_allclose(s1 + b2 * s2, brute_force(row.cylinders), rtol=1e-9, atol=1e-9)
        assert row.method == "exhaustive"
        assert_allclose(record["M1V_balanced_Nm"], UNIT * s1, rtol=1e-9, atol=1e-6 * UNIT)
        assert_allclose(record["M2V_Nm"], UNIT * b2 * s2, rtol=1e-9, atol=1e-6 * UNIT)
        assert record["M1H_balanced_Nm"] == 0.0 and record["M2H_Nm"] == 0.0


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
    s1, s2 = couples(row["phases_deg"])
    assert s2 < 1e-12 and row["M2V_Nm"] == 0.0
    assert_allclose(row["M1V_balanced_Nm"], UNIT * s1, rtol=1e-9)


def test_too_many_to_enumerate_is_searched_by_the_labelled_heuristic():
    rows = family(read_configuration(MARINE), [7], workers=1, limit=10).rows
    assert rows[0].method == "heuristic"


def test_table_csv_and_errors(tmp_path):
    text = invoke("family", MARINE, "--cylinders", "5,6", "--units", "kN").output
    assert "M2V (kN·m)" in text and "1 776" in text and "exhaustive" in text
    csv_text = invoke("family", MARINE, "--cylinders", "6", "--format", "csv").output
    assert csv_text.splitlines()[0].startswith("cylinders,firing_order,method,score,M1V_Nm")
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
    out = invoke("family", CONFIGS / "nakanishi-v12-90-2stroke.toml", "--cylinders", "6")
    assert out.exit_code == 1 and "in-line" in out.output
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
    # the table's PRU M1V* is the balanced one: M1V_balanced / (5 × 2380 kW)
    assert_allclose(
        float(row["PRU_M1V_balanced_Nm_per_kW"]),
        float(row["M1V_balanced_Nm"]) / 11900.0,
        rtol=1e-12,
    )


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
