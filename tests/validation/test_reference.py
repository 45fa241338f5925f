"""Every published figure of the source papers (tests/validation/reference/*.toml) against
balance."""

import pytest

from balance_cli import load
from tests.validation.reference import evaluate

ROWS = evaluate.rows()
ERRATA = {e["id"]: e for e in evaluate.errata()}


@pytest.mark.parametrize("row", ROWS, ids=[r.id for r in ROWS])
def test_published_figure(row):
    """A figure agrees within its stated tolerance, or it is a traced erratum: then it must
    disagree (else the erratum is wrong), and agree with the corrected value where one is given."""
    if row.erratum:
        assert row.erratum in ERRATA, f"{row.id} names unknown erratum {row.erratum}"
        assert not row.agrees, f"{row.id}: agrees after all; erratum {row.erratum} is not borne out"
        if row.corrected is not None:
            assert row.corrected_agrees, (
                f"{row.id}: ours {row.ours:.6g} against corrected {row.corrected:.6g} "
                f"(tolerance {row.tolerance:.3g})"
            )
    else:
        assert row.agrees, (
            f"{row.id} ({row.where}): published {row.published:.6g}, ours {row.ours:.6g}, "
            f"deviation {row.deviation:+.3g} beyond {row.tolerance:.3g} ({row.reason})"
        )


def test_records_are_well_formed():
    ids = [r.id for r in ROWS]
    assert len(ids) == len(set(ids)), "duplicate record ids"
    for row in ROWS:
        assert row.reason and row.where and row.tolerance > 0


def test_every_erratum_is_used_and_the_known_ones_are_all_checked():
    used = {r.erratum for r in ROWS if r.erratum}
    assert used == set(ERRATA)
    # the errata listed in shared/seeds/INDEX.md
    assert {"T1", "T2", "T3", "T5", "F1"} <= used
    assert all(e["status"] in {"confirmed", "refuted", "new"} for e in ERRATA.values())
    assert all(
        e.get("verdict", "misprint") in {"misprint", "slip", "truncation", "sign", "unexplained"}
        for e in ERRATA.values()
    )


def test_our_own_errors_point_at_records_that_now_agree():
    by_id = {r.id: r for r in ROWS}
    for error in evaluate.own_errors():
        assert error["records"], error["id"]
        for record in error["records"]:
            assert record in by_id and by_id[record].agrees, (error["id"], record)


def test_enough_figures_per_paper():
    counts = {}
    for row in ROWS:
        counts[row.paper] = counts.get(row.paper, 0) + 1
    assert counts["tanaka1925"] >= 60 and counts["fraeys1949"] >= 20
    assert counts["nakanishi1932"] >= 10 and counts["lecture-notes"] >= 5
    assert counts["margoulis1920"] >= 5


def test_bramo_config_derives_fraeys_de_veubekes_point_masses_from_table_viii():
    """The library's BRAMO 323 gives Table VIII's parts; the configuration reader's two-point
    reduction equals the reference evaluator's own § 8 formulas (written apart from the
    library) to rounding, and Table IX as printed to its slips of 0.0005 kg (records F-IX-*)."""
    engine = load(evaluate.ROOT / "configs" / "bramo-323.toml")
    paper = next(p for p in evaluate.papers() if p["paper"]["key"] == "fraeys1949")
    data = paper["data"]
    reduction = evaluate._fraeys_reduction(data)
    master = engine.cylinder(1)
    links = [c for c in engine.cylinders if c.is_link]
    assert master.reciprocating_kg == pytest.approx(data["p_kg"] + reduction["BK"], abs=1e-12)
    assert engine.rotating_kg == pytest.approx(reduction["B(1-K)"], abs=1e-12)
    assert all(c.reciprocating_kg == pytest.approx(reduction["a"], abs=1e-12) for c in links)
    assert all(c.knuckle_kg == pytest.approx(reduction["b(1-k)"], abs=1e-12) for c in links)
    for ours, printed in (
        (master.reciprocating_kg, 2.972 + 1.3186),
        (engine.rotating_kg, 9.2214),
        (links[0].reciprocating_kg, 3.7239),
        (links[0].knuckle_kg, 0.6681),
    ):
        assert ours == pytest.approx(printed, abs=0.0006)


def test_validation_report_is_current():
    """docs/VALIDATION.md is generated from these records (make validate) and committed."""
    from tools import validation_report

    committed = validation_report.TARGET.read_text(encoding="utf-8")
    assert committed == validation_report.render(), (
        "docs/VALIDATION.md is out of date: run make validate"
    )
