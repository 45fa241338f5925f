"""The README is the front door: short, its two commands on the first screen, its commands
true, its links pointing at files that exist; the data files the pages run on are current."""

import re
import runpy
import shlex

from click.testing import CliRunner

from balance_cli.cli import main
from tests.docs.pages import DOCS, code_blocks
from tests.docs.test_pages import checkout_folder  # noqa: F401  (a fixture)
from tests.support import ROOT

README = ROOT / "README.md"


def test_the_readme_is_a_front_door():
    lines = README.read_text(encoding="utf-8").splitlines()
    # the "at most about 200 lines"
    assert len(lines) <= 210
    # the two commands a newcomer runs first, on the first screen (a terminal's 24 lines)
    first_screen = "\n".join(lines[:24])
    assert "make demo" in first_screen and "make test" in first_screen
    # and where the rest went: the site, and how to build it
    text = "\n".join(lines)
    assert "make docs" in text and "docs/_build/html" in text


def test_the_readmes_relative_links_point_at_files(tmp_path):
    text = README.read_text(encoding="utf-8")
    targets = re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text)
    local = [t for t in targets if not re.match(r"[a-z]+:", t)]
    assert len(local) > 20  # the site's pages, the picture, CONTRIBUTING, LICENSE
    missing = [t for t in local if not (ROOT / t).exists()]
    assert not missing


def test_the_readmes_commands_and_python_run(checkout_folder):  # noqa: F811
    text = README.read_text(encoding="utf-8")
    commands = [
        shlex.split(line, comments=True)[1:]
        for block in re.findall(r"^```sh\n(.*?)^```", text, flags=re.S | re.M)
        for line in block.splitlines()
        if line.startswith("balance ")
    ]
    assert len(commands) >= 4
    for args in commands:
        result = CliRunner().invoke(main, args)
        assert result.exit_code == 0, (args, result.output)
    for block in code_blocks(README, "python"):
        exec(compile(block, str(README), "exec"), {})
    assert (checkout_folder / "docs" / "tour-locus.png").read_bytes().startswith(b"\x89PNG")


def test_the_pages_data_files_are_current():
    """docs/data/ is what tools/docs_data.py writes from the library today."""
    tool = runpy.run_path(str(ROOT / "tools" / "docs_data.py"), run_name="docs_data")
    assert tool["main"](check=True) == 0
    assert {p.name for p in (DOCS / "data").iterdir()} == {
        "pressure-4stroke.csv",
        "torque-dragonfly.csv",
        "workshop-inline-4.toml",
        "workshop-inline-4-parts.csv",
    }
