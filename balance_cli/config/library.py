"""The engine library and the search templates that ship with balance, and the names that
reach them from any folder: ``library:NAME`` and ``template:NAME``.

``library:`` alone is the whole library (the checkout's ``configs/``), ``library:tanaka-part3``
one of its folders, ``library:today/v/v8-90-cross-plane.toml`` one engine; ``template:NAME``
is one search template of ``templates/`` (a template is not a configuration: ``template:``
alone, which no command could take whole, is refused with the list of templates). A file's
``.toml`` may be left out. A name is a ``str``; anything else (a ``Path``) is taken as a path.

Where they are: an installed package carries them as package data, the folders
``balance_cli/library`` and ``balance_cli/templates`` beside this package's modules
(``pyproject.toml`` maps them from the checkout's ``configs/`` and ``templates/``). Run from a
checkout (an editable install, or the source tree itself) they are the checkout's folders.
"""

import os
from pathlib import Path

from ..about import DISTRIBUTION
from ..errors import ConfigError

__all__ = ["LIBRARY", "TEMPLATE", "library_folder", "templates_folder", "resolve"]

#: the prefixes of the names of shipped files and folders
LIBRARY, TEMPLATE = "library:", "template:"

_PACKAGE = Path(__file__).resolve().parent.parent  # balance_cli/
_CHECKOUT = _PACKAGE.parent


def library_folder() -> Path:
    """The folder of the shipped engine library (what ``library:`` names)."""
    return _shipped("library", "configs", LIBRARY)


def templates_folder() -> Path:
    """The folder of the shipped search templates (what ``template:`` names)."""
    return _shipped("templates", "templates", TEMPLATE)


def _shipped(installed: str, checkout: str, prefix: str) -> Path:
    if (_PACKAGE / installed).is_dir():
        return _PACKAGE / installed
    if (_CHECKOUT / "pyproject.toml").is_file() and (_CHECKOUT / checkout).is_dir():
        return _CHECKOUT / checkout
    raise ConfigError(
        _PACKAGE / installed,
        "",
        f"missing from this copy of balance (what {prefix} names); reinstall {DISTRIBUTION}",
    )


def resolve(path: "str | os.PathLike[str]") -> "str | os.PathLike[str]":
    """``path`` itself, or the shipped file or folder that a ``library:`` or ``template:``
    name stands for.

    Raises
    ------
    ConfigError
        naming the name and listing what the library (or its folder on the way) holds
    """
    if isinstance(path, str):
        if path.startswith(LIBRARY):
            return _find(path, LIBRARY, library_folder(), "engine library")
        if path.startswith(TEMPLATE):
            if not path[len(TEMPLATE) :].strip(" /"):
                folder = templates_folder()
                names = sorted(p.stem for p in folder.glob("*.toml"))
                raise ConfigError(
                    path, "", f"names no template; give one of template:{', template:'.join(names)}"
                )
            return _find(path, TEMPLATE, templates_folder(), "search templates")
    return path


def _find(name: str, prefix: str, root: Path, what: str) -> Path:
    parts = [
        p for p in name[len(prefix) :].strip().replace("\\", "/").split("/") if p not in ("", ".")
    ]
    if ".." in parts:
        raise ConfigError(
            name,
            "",
            f"'..' leads out of the shipped {what}; name a file or "
            f"folder inside it ({prefix} is all of it)",
        )
    target = root.joinpath(*parts)
    if target.exists():
        return target
    if parts and target.with_name(target.name + ".toml").is_file():
        return target.with_name(target.name + ".toml")
    folder = root  # the deepest folder on the way that exists: what it holds is worth seeing
    for part in parts[:-1]:
        if not (folder / part).is_dir():
            break
        folder = folder / part
    where = prefix + "/".join(folder.relative_to(root).parts)
    entries = sorted(folder.iterdir(), key=lambda e: (not e.is_dir(), e.name))
    held = [
        f"{e.name}/" if e.is_dir() else e.name
        for e in entries
        if not e.name.startswith((".", "_")) and (e.is_dir() or e.suffix == ".toml")
    ]
    raise ConfigError(
        name, "", f"not in the shipped {what}; {where} holds {', '.join(held) or 'nothing'}"
    )
