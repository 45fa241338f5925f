"""The classic papers' tutorial (docs/tutorials/plot_08_classic_papers.py) states figures of
Tanaka (1925) and Nakanishi (1932) beside balance's values: they must be the validation
records' own (printed value, tolerance, correction), and the tutorial's way to the value (an
amplitude from the forward and backward phasors, the library's Part III rotary for Part II's
Clerget) must give what the validation computes in the paper's own axes."""

import runpy

import pytest
from numpy.testing import assert_allclose

from tests.docs.pages import DOCS
from tests.validation.reference import evaluate

SCRIPT = DOCS / "tutorials" / "plot_08_classic_papers.py"


@pytest.fixture(scope="module")
def tutorial():
    return runpy.run_path(str(SCRIPT), run_name="__main__")


@pytest.fixture(scope="module")
def records():
    """Every figure record by id, with the paper it belongs to."""
    return {
        record["id"]: (record, paper) for paper in evaluate.papers() for record in paper["figure"]
    }


def test_the_figures_are_the_records(tutorial, records):
    figures = tutorial["FIGURES"]
    assert {figure[:3] for figure in figures} == {"T-I", "N-V", "N-W"}  # both papers
    for figure, stated in figures.items():
        record, _ = records[figure]
        # transcribed literals: equal to the last digit
        assert stated[:2] == (record["published"], record["tolerance"]), figure
        if len(stated) == 3:
            assert record.get("erratum") and stated[2] == record["corrected"], figure
        else:
            assert "erratum" not in record, figure
    # the errata the text names
    assert records["T-III-62-Y-formula"][0]["erratum"] == "T1"
    assert records["T-II-third"][0]["erratum"] == "T3"


def test_the_tutorial_computes_what_the_validation_does(tutorial, records):
    ours = tutorial["OURS"]
    assert set(ours) == set(tutorial["FIGURES"])  # every figure was checked
    for figure, value in ours.items():
        row = evaluate.evaluate(*records[figure])
        # the same exact quantity two ways (sizes here, signed components in the paper's axes
        # there; the Clerget with its reciprocating masses alone, or the library's Part III
        # rotary): they differ by rounding
        assert_allclose(value, abs(row.ours), rtol=1e-9, atol=1e-12, err_msg=figure)
