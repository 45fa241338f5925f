"""Sphinx extension of balance's documentation site (listed in conf.py).

- References to the package's own names that the site does not document (a module's helper
  such as ``span`` or ``parse_objective``, a private-layer module such as
  ``balance_cli.analysis.gas``) are set as code, unlinked, when the name exists in the
  package; a name that exists nowhere stays a broken reference, which ``-n -W`` turns into an
  error. The check that a docstring names something real is kept; the site does not have to
  document every internal module.
- The public API and the commands are checked when the build finishes: every name of
  ``balance_cli.__all__`` is documented, and every command of the ``balance`` group.
- The ``engine-keys`` directive writes the configuration keys' tables (see engine_keys.py).
"""

import importlib
import pkgutil
import re

from docutils import nodes
from engine_keys import EngineKeysDirective, UnitsDirective
from sphinx.util import logging

import balance_cli

logger = logging.getLogger(__name__)

#: "…/file.py:docstring of balance_cli.studies.sweep.sweep" -> the documented object's name
_OWNER = re.compile(r"docstring of ([\w.]+)")

_modules: list = []
#: the references set as code (reported when the build finishes)
_unlinked_targets: set = set()


def _package_modules():
    """Every module of balance_cli, imported once (the fallback for short names)."""
    if not _modules:
        _modules.append(balance_cli)
        for info in pkgutil.walk_packages(balance_cli.__path__, "balance_cli."):
            try:
                _modules.append(importlib.import_module(info.name))
            except ImportError:  # an optional dependency's adapter: not a place to look
                continue
    return _modules


def _resolve(dotted):
    """True when ``dotted`` (a.b.c) names a module or an attribute chain of one."""
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for part in parts[cut:]:
            if hasattr(obj, part):
                obj = getattr(obj, part)
            elif part in getattr(obj, "__dataclass_fields__", {}):
                # a dataclass field without a default is no class attribute, but real
                obj = None
            else:
                break
        else:
            return True
    return False


def _exists(target, contexts):
    if _resolve(target) or any(_resolve(f"{c}.{target}") for c in contexts):
        return True
    head, *rest = target.split(".")
    for module in _package_modules():
        obj = getattr(module, head, None)
        for part in rest:
            obj = getattr(obj, part, None)
        if obj is not None:
            return True
    return False


def _unlinked(app, env, node, contnode):
    """A reference to a real but undocumented name of the package: code, not a link."""
    if node.get("refdomain") != "py":
        return None
    target = node.get("reftarget", "").lstrip("~.")
    if not target:
        return None
    contexts = [c for c in (node.get("py:module"), node.get("py:class")) if c]
    owner = _OWNER.search(str(node.source or ""))
    if owner:
        parts = owner.group(1).split(".")
        contexts += [".".join(parts[:i]) for i in range(len(parts), 0, -1)]
    if _exists(target, contexts):
        _unlinked_targets.add(target)
        return contnode
    return None


def _report(app, exception):
    if exception is None and _unlinked_targets:
        logger.info(
            "balance_docs: %d names of the package that the site does not document were set "
            "as code: %s",
            len(_unlinked_targets),
            ", ".join(sorted(_unlinked_targets)),
        )


def _check_documented(app, env):
    """Every public name and every command is on the site: a missing one is a warning."""
    objects = env.domains["py"].objects
    for name in balance_cli.__all__:
        if f"balance_cli.{name}" not in objects:
            logger.warning("balance_cli.%s is in __all__ but not documented", name)
    from balance_cli.cli import main

    sections = set().union(*getattr(env, "balance_sections", {}).values())
    for command in main.commands:
        if f"balance-{command}" not in sections:
            logger.warning("the command balance %s is not in the command-line reference", command)


def _collect_sections(app, doctree):
    """The ids of every section (sphinx-click's are "balance-compare", ...)."""
    env = app.env
    if not hasattr(env, "balance_sections"):
        env.balance_sections = {}
    env.balance_sections[env.docname] = {
        i for section in doctree.findall(nodes.section) for i in section["ids"]
    }


def _purge(app, env, docname):
    getattr(env, "balance_sections", {}).pop(docname, None)


def _merge(app, env, docnames, other):
    if not hasattr(env, "balance_sections"):
        env.balance_sections = {}
    env.balance_sections.update(getattr(other, "balance_sections", {}))


def setup(app):
    app.connect("missing-reference", _unlinked)
    app.connect("build-finished", _report)
    app.connect("doctree-read", _collect_sections)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("env-check-consistency", _check_documented)
    app.add_directive("engine-keys", EngineKeysDirective)
    app.add_directive("engine-units", UnitsDirective)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
