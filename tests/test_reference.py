"""Every published figure of the source papers (tests/reference/*.toml) against balance."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "reference"))

import evaluate  # noqa: E402
from balance_cli import load  # noqa: E402

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
                f"(tolerance {row.tolerance:.3g})")
    else:
        assert row.agrees, (
            f"{row.id} ({row.where}): published {row.published:.6g}, ours {row.ours:.6g}, "
            f"deviation {row.deviation:+.3g} beyond {row.tolerance:.3g} ({row.reason})")


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


def test_enough_figures_per_paper():
    counts = {}
    for row in ROWS:
        counts[row.paper] = counts.get(row.paper, 0) + 1
    assert counts["tanaka1925"] >= 60 and counts["fraeys1949"] >= 20
    assert counts["nakanishi1932"] >= 10 and counts["lecture-notes"] >= 5


def test_bramo_config_uses_the_reduced_masses_of_table_ix():
    """The library's BRAMO 323 carries Fraeys de Veubeke's point masses (Table IX, as printed)."""
    engine = load(evaluate.ROOT / "configs" / "bramo-323.toml")
    master = engine.cylinder(1)
    links = [c for c in engine.cylinders if c.is_link]
    assert master.reciprocating_kg == pytest.approx(2.972 + 1.3186, abs=1e-9)   # p + B·K
    assert engine.rotating_kg == pytest.approx(9.2214, abs=1e-9)                # B(1 − K)
    assert all(c.reciprocating_kg == pytest.approx(3.7239, abs=1e-9) for c in links)  # p + b·k
    assert all(c.knuckle_kg == pytest.approx(0.6681, abs=1e-9) for c in links)        # b(1 − k)


def test_validation_report_is_current():
    """docs/VALIDATION.md is generated from these records (make validate) and committed."""
    sys.path.insert(0, str(evaluate.ROOT / "tools"))
    import validation_report

    committed = validation_report.TARGET.read_text(encoding="utf-8")
    assert committed == validation_report.render(), "docs/VALIDATION.md is out of date: run make validate"
