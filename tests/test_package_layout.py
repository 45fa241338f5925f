"""The package's shape: modules of one idea and a few hundred lines, no module taking another's
private names. The layers and the absence of cycles are import-linter's contracts in
pyproject.toml (`make lint`); these are the rules it does not state."""

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "balance_cli"
#: the most lines a module may have: one idea, a few hundred lines (DESIGN.md)
MOST_LINES = 500


def modules():
    return sorted(PACKAGE.rglob("*.py"))


def private_imports(path):
    """(module, name) of every ``from X import _name`` in ``path`` (dunder names are not
    private)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return [
        (node.module or "." * node.level, alias.name)
        for node in ast.walk(tree)
        if isinstance(node, ast.ImportFrom)
        for alias in node.names
        if alias.name.startswith("_") and not alias.name.startswith("__")
    ]


def test_there_are_modules_to_check():
    assert len(modules()) > 50


def test_every_module_is_at_most_500_lines():
    long = [
        f"{p.relative_to(PACKAGE.parent)}: {n} lines"
        for p in modules()
        if (n := p.read_text(encoding="utf-8").count("\n")) > MOST_LINES
    ]
    assert not long, "split these by idea:\n" + "\n".join(long)


def test_no_module_imports_another_modules_private_name():
    found = [
        f"{p.relative_to(PACKAGE.parent)}: {name} from {module}"
        for p in modules()
        for module, name in private_imports(p)
    ]
    assert not found, "make these public in their home module:\n" + "\n".join(found)


def test_the_private_import_check_finds_one(tmp_path):
    """The check above can fail: a module that takes a private name is caught."""
    probe = tmp_path / "probe.py"
    probe.write_text("from .kinematics.linkage import _slider\nfrom . import __version__\n")
    assert private_imports(probe) == [("kinematics.linkage", "_slider")]
