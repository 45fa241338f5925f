"""balance animate: the files it writes, and its errors (one line, exit status 1, nothing
written)."""

import pytest
from PIL import Image

from tests.support import CONFIGS, PART3, invoke

V8 = CONFIGS / "today" / "v" / "v8-90-cross-plane.toml"


def test_a_gif_and_a_page(tmp_path):
    gif, page = tmp_path / "v8.gif", tmp_path / "v8.html"
    result = invoke("animate", V8, "-o", gif, "-o", page, "--frames", "16", "--orders", "1,2,4")
    assert result.exit_code == 0, result.output
    assert f"wrote {gif} (" in result.stderr and f"wrote {page} (" in result.stderr
    with Image.open(gif) as movie:
        assert movie.n_frames == 16
    text = page.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>") and '"shown":[1,2,4]' in text
    # the page has its own frames, 180 a revolution, whatever the movie's
    assert '"frames":180' in text


def test_the_library_and_its_speed(tmp_path):
    page = tmp_path / "clerget.html"
    result = invoke("animate", "library:clerget-rotary", "-o", page, "--speed", "1000 rpm")
    assert result.exit_code == 0, result.output
    assert '"rotary":true' in page.read_text(encoding="utf-8")
    assert '"speedRpm":1000.0' in page.read_text(encoding="utf-8")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-o", "a.png"], "--output 'a.png' has '.png'; end the file name in .gif, .mp4 or .html"),
        (["-o", "a.gif", "--orders", "0"], "--orders must be whole numbers from 1 to 8"),
        (["-o", "a.gif", "--orders", "9", "--max-order", "8"], "--orders must be whole numbers"),
        (["-o", "a.gif", "--frames", "25"], "--frames must be a whole number a revolution"),
        (["-o", "a.gif", "--fps", "0"], "--fps must be a number of frames a second"),
    ],
)
def test_bad_options(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    result = invoke("animate", V8, *args)
    assert result.exit_code == 1, result.output
    assert message in result.stderr
    assert "Traceback" not in result.output and len(result.stderr.splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_an_mp4_without_ffmpeg_says_so_before_writing_anything(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("shutil.which", lambda name: None)
    result = invoke("animate", V8, "-o", "v8.gif", "-o", "v8.mp4")
    assert result.exit_code == 1
    assert result.stderr == (
        "Error: --output 'v8.mp4': an .mp4 is written by ffmpeg, which is not installed (not "
        "on PATH); install ffmpeg, or write a .gif (Pillow) or an .html page\n"
    )
    assert list(tmp_path.iterdir()) == []


def test_one_engine_only_and_never_over_its_file(tmp_path):
    result = invoke("animate", PART3, "-o", tmp_path / "a.gif")
    assert result.exit_code == 1
    assert "holds 9 engines; animate draws one: give one file" in result.stderr
    copy = tmp_path / "v8.html"
    copy.write_text(V8.read_text(encoding="utf-8"), encoding="utf-8")
    result = invoke("animate", copy, "-o", copy)
    assert result.exit_code == 1 and "is an input file" in result.stderr
    result = invoke("animate", "-o", "x.gif")
    assert result.exit_code == 2 and "Missing argument 'FILE'" in result.output
