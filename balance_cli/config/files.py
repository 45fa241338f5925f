"""Configuration files and text to engines: one file, a text, a search template, the parsed data
of a file, and every configuration under a list of files and folders. Wherever a path is taken,
``library:NAME`` and ``template:NAME`` name a shipped one (:mod:`.library`)."""

import os
from collections.abc import Iterable
from pathlib import Path

from .. import checks
from ..errors import ConfigError
from ..model import Engine
from .builder import build
from .library import resolve
from .reader import parse_text, read_text

__all__ = ["load", "loads", "load_data", "as_template", "load_template", "find_configs",
           "load_many"]


def load(path: "str | os.PathLike[str]") -> Engine:
    """Read, check and build the engine described by the TOML file at ``path``.

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    return loads(read_text(Path(checks.path(path))), name=str(path))


def load_data(path: "str | os.PathLike[str]") -> dict:
    """The parsed TOML of the file at ``path``, checked as a configuration (its throws'
    phases may be given or not): what :func:`balance_cli.studies.family.family` repeats.

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    data = _read_data(path)
    build(as_template(data), str(path), template=True)
    return data


def as_template(data: dict) -> dict:
    """A configuration's parsed TOML without its throws' phases and firing order: a search
    template of the same engine."""
    template = {k: v for k, v in data.items() if k != "firing_order"}
    if isinstance(template.get("throws"), list):
        template["throws"] = [{k: v for k, v in t.items() if k != "phase"} if isinstance(t, dict)
                              else t for t in template["throws"]]
    return template


def load_template(path: "str | os.PathLike[str]") -> tuple[Engine, dict]:
    """Read a search template: a configuration whose ``[[throws]]`` give only ``z`` and which
    has no ``firing_order`` (``balance search`` chooses both). Returns the engine, every throw
    at phase 0, and the parsed TOML (for :func:`arrangement_toml`).

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    data = _read_data(path)
    return build(data, str(path), template=True), data


def _read_data(path):
    return parse_text(read_text(Path(checks.path(path))), str(path))


def loads(text: str, name: str = "<string>") -> Engine:
    """The engine described by TOML ``text``; ``name`` stands for the file in messages and
    becomes the engine's ``config_path``."""
    if not isinstance(name, str):
        error = ConfigError("<string>", "", f"name must be a str, got {type(name).__name__}")
        error.parameter = "name"
        raise error
    return build(parse_text(text, name), name)


def find_configs(paths: "Iterable[str | os.PathLike[str]]") -> list[Path]:
    """Expand files and folders (recursively, sorted by path) into a list of .toml files.

    A path that does not exist is kept (reading it says so); a folder that cannot be read, or
    holds no .toml file, is a ConfigError.
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]   # one path, not the characters of one
    try:
        paths = [resolve(checks.path(p, "paths")) for p in paths]
    except TypeError:
        error = ConfigError("<paths>", "", f"paths must be a list of file or folder paths, got "
                                           f"{type(paths).__name__}")
        error.parameter = "paths"
        raise error from None
    found = []
    for p in map(Path, paths):
        if not p.is_dir():
            found.append(p)
            continue
        files = []

        def unreadable(exc, folder=p):
            raise ConfigError(exc.filename or folder, "", f"cannot read the folder "
                              f"({exc.strerror or exc}); check its permissions") from None

        if not os.access(p, os.R_OK | os.X_OK):
            unreadable(PermissionError(13, "Permission denied", str(p)))
        for folder, subfolders, names in os.walk(p, onerror=unreadable):
            subfolders.sort()
            files += [Path(folder) / n for n in names
                      if n.endswith(".toml") and (Path(folder) / n).is_file()]
        if not files:
            raise ConfigError(p, "", "no .toml configuration found in this folder")
        found += sorted(files)
    return found


def load_many(paths: "Iterable[str | os.PathLike[str]]") -> list[Engine]:
    """Load every configuration under ``paths`` (see :func:`find_configs`)."""
    return [load(f) for f in find_configs(paths)]
