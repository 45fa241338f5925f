"""The reference cannot drift from the code: every public name of the library is on the API
page once, and every command of ``balance`` on the command-line page. (The site's build
checks the same on what Sphinx generated: a name or a command it did not document is a
warning, and warnings fail ``make docs``.)"""

import re

import balance_cli
from balance_cli.cli import main
from tests.docs.pages import DOCS

API = DOCS / "reference" / "api.rst"
CLI = DOCS / "reference" / "cli.rst"


def api_names():
    """Every name the API page documents: the entries of its autosummary tables and the
    objects of its auto directives."""
    names = []
    lines = API.read_text(encoding="utf-8").splitlines()
    in_table = False
    for line in lines:
        if line.startswith(".. autosummary::"):
            in_table = True
            continue
        if in_table:
            if line.strip() and not line.startswith(" "):
                in_table = False
            elif line.strip() and not line.strip().startswith(":"):
                names.append(line.strip())
        match = re.match(r"^\.\. auto(?:data|function|class|exception|module):: (\S+)", line)
        if match:
            names.append(match.group(1))
    return names


def test_every_public_name_is_on_the_api_page_once():
    names = api_names()
    assert sorted(names) == sorted(balance_cli.__all__)
    assert len(names) == len(set(names))


def click_directive():
    text = CLI.read_text(encoding="utf-8")
    match = re.search(r"^\.\. click:: (\S+)\n((?:[ \t]+:[^\n]*\n?)*)", text, re.M)
    assert match, "the command-line page has no click directive"
    options = dict(re.findall(r":([\w-]+):[ \t]*([^\n]*)", match.group(2)))
    return match.group(1), options


def test_the_command_line_page_documents_every_command_with_its_options():
    target, options = click_directive()
    assert target == "balance_cli.cli.group:main"
    assert options["prog"] == "balance"
    # nested full: each command's own section with its options and arguments
    assert options["nested"] == "full"
    listed = [c.strip() for c in options["commands"].split(",")]
    assert sorted(listed) == sorted(main.commands)
    assert len(listed) == len(set(listed))


def test_importing_the_cli_package_registers_every_command():
    """sphinx-click imports balance_cli.cli.group, whose package imports every command
    module first: the group it finds has them all."""
    from balance_cli.cli import group

    assert group.main is main
    assert {"compare", "validate", "torsion", "sweep", "family"} <= set(group.main.commands)
