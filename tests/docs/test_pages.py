"""The site's code stays true: the Python blocks of its pages run, its TOML engines load, its
``balance`` command lines run, and the galleries' scripts run — as tests/test_api.py does for
the README's blocks. (``make docs`` runs the scripts too; these need no Sphinx.)"""

import runpy
import shlex
import tomllib

import pytest
from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main
from tests.docs.pages import DOCS, PAGES, SCRIPTS, code_blocks
from tests.support import CONFIGS, ROOT


def with_blocks(language):
    pages = [p for p in PAGES if code_blocks(p, language)]
    return pytest.mark.parametrize("page", pages, ids=[str(p.relative_to(DOCS)) for p in pages])


@pytest.fixture
def checkout_folder(tmp_path, monkeypatch):
    """A folder of their own (they may write files), with configs/, templates/ and the pages'
    data files (docs/data/) beside them as in the checkout; docs/ itself is a folder of its
    own, so that a command drawing into docs/ does not replace the checkout's pictures."""
    (tmp_path / "configs").symlink_to(CONFIGS)
    (tmp_path / "templates").symlink_to(ROOT / "templates")
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "data").symlink_to(DOCS / "data")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_there_are_blocks_and_scripts_to_run():
    assert code_blocks(DOCS / "index.md", "python")
    assert len(code_blocks(DOCS / "howto" / "describe-an-engine.md", "toml")) == 8
    assert {p.name for p in SCRIPTS} >= {"plot_tanaka_v8.py", "plot_01_first_comparison.py"}


@with_blocks("python")
def test_the_python_blocks_run(page, checkout_folder):
    namespace: dict = {}
    for block in code_blocks(page, "python"):
        exec(compile(block, str(page), "exec"), namespace)


@with_blocks("toml")
def test_the_engines_load(page):
    engines = [b for b in code_blocks(page, "toml") if "name" in tomllib.loads(b)]
    for i, text in enumerate(engines, 1):
        engine = balance.loads(text, name=f"{page.name}, block {i}")
        # analysable too: the linkage closes over a revolution, the firing order fires
        assert balance.analyse(engine, max_order=4).max_order == 4


def command_lines(page):
    """The ``balance`` commands of a page's shell blocks, a line continued by a backslash
    joined to the next."""
    for language in ("sh", "console", "shell"):
        for block in code_blocks(page, language):
            for line in block.replace("\\\n", " ").splitlines():
                words = shlex.split(line.removeprefix("$ "), comments=True)
                if words[:1] == ["balance"]:
                    yield words[1:]


@pytest.mark.parametrize(
    "page",
    [p for p in PAGES if any(command_lines(p))],
    ids=lambda p: str(p.relative_to(DOCS)),
)
def test_the_command_lines_run(page, checkout_folder):
    for args in command_lines(page):
        result = CliRunner().invoke(main, args)
        assert result.exit_code == 0, (args, result.output)


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_the_gallery_scripts_run(script, checkout_folder):
    namespace = runpy.run_path(str(script), run_name="__main__")
    # each draws the picture its page shows: in Axes, or on the figure itself (the torques)
    assert namespace["fig"].axes or namespace["fig"].artists
