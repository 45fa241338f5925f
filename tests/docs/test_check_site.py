"""tools/check_site.py, which ``make docs`` runs on the built site: it finds a picture that does
not load and an error in a page's console, and passes a page that has neither (pages made
here, so that these tests need no Sphinx)."""

import matplotlib.pyplot as plt
import pytest

from tools import check_site

needs_chromium = pytest.mark.skipif(
    check_site.chromium() is None,
    reason="Debian's chromium is not installed (.ci/run installs it when the package index "
    "can be reached)",
)

PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title></head>
<body><h1>{title}</h1>{body}</body></html>
"""


@pytest.fixture
def site(tmp_path):
    """A small built site: an index, a picture in _images/ and pages in generated/tutorials/
    that show it as the gallery's pages do (a path relative to the page)."""
    root = tmp_path / "html"
    (root / "_images").mkdir(parents=True)
    fig, ax = plt.subplots(figsize=(2, 1))
    ax.plot([0, 1], [0, 1])
    fig.savefig(root / "_images" / "curve.png")
    (root / "index.html").write_text(PAGE.format(title="index", body=""), encoding="utf-8")
    pages = root / "generated" / "tutorials"
    pages.mkdir(parents=True)
    good = '<img src="../../_images/curve.png" alt="a curve">'
    (pages / "good.html").write_text(PAGE.format(title="good", body=good), encoding="utf-8")
    bad = (
        good
        + '<img src="../../_images/missing.png" alt="nothing">'
        + '<script>console.error("boom")</script>'
        + "<script>undefinedFunction()</script>"
    )
    (pages / "bad.html").write_text(PAGE.format(title="bad", body=bad), encoding="utf-8")
    return root


def test_the_probe_goes_first_in_the_head_with_a_base_at_the_page_folder(tmp_path):
    text = check_site.probed(PAGE.format(title="t", body="<p>x</p>"), tmp_path)
    head = text[text.index("<head>") + len("<head>") :]
    assert head.startswith(f'<base href="{tmp_path.as_uri()}/"><script>')
    assert head.index(check_site.REPORT_ID) < head.index("<meta charset")
    with pytest.raises(ValueError, match="no <head>"):
        check_site.probed("<html><body></body></html>", tmp_path)


def test_without_chromium_the_check_says_why_and_passes(site, monkeypatch, capsys):
    monkeypatch.setattr(check_site, "chromium", lambda: None)
    assert check_site.main([str(site)]) == 0
    assert "skipped: Chromium is not installed" in capsys.readouterr().out


def test_without_a_built_site_the_check_fails_in_one_line(tmp_path, capsys):
    assert check_site.main([str(tmp_path / "nothing")]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out == [
        f"check_site: {tmp_path / 'nothing'}: no built site there; build it with make docs"
    ]


@needs_chromium
def test_a_page_whose_pictures_load_passes(site, capsys):
    assert check_site.main([str(site), "generated/tutorials/good.html"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == (
        "check_site: generated/tutorials/good.html: 1 of 1 pictures loaded, no console error"
    )


@needs_chromium
def test_a_broken_picture_and_console_errors_fail(site, capsys):
    assert check_site.main([str(site), "generated/tutorials/bad.html"]) == 1
    page, summary = capsys.readouterr().out.splitlines()
    assert summary == "check_site: 1 of 1 pages failed"
    problems = page.removeprefix("check_site: generated/tutorials/bad.html: ").split("; ")
    # the picture once (not again as a resource that failed), then the errors in their order
    assert problems[:2] == [
        "picture '../../_images/missing.png' did not load",
        "console.error: boom",
    ]
    assert problems[2].startswith("uncaught: ") and "undefinedFunction" in problems[2]
    assert len(problems) == 3
