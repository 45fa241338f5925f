"""Configuration files and text to engines: one file, a text, a search template, a
configuration as written (:class:`Configuration`), and every configuration under a list of
files and folders. Wherever a path is taken, ``library:NAME`` and ``template:NAME`` name a
shipped one (:mod:`.library`)."""

import copy
import os
from collections.abc import Iterable
from pathlib import Path

from .. import checks
from ..errors import ConfigError
from ..model import Engine
from .builder import build
from .library import resolve
from .provenance import Provenance, read_provenance
from .reader import parse_text, read_text

__all__ = [
    "load",
    "loads",
    "Configuration",
    "read_configuration",
    "as_template",
    "load_template",
    "find_configs",
    "load_many",
]


def load(path: "str | os.PathLike[str]") -> Engine:
    """Read, check and build the engine described by the TOML file at ``path``.

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    return loads(read_text(Path(checks.path(path))), name=str(path))


class Configuration:
    """A configuration as written: its parsed TOML (``data``) and where it came from (``path``,
    which messages name).

    An analysis starts from the :class:`~balance_cli.Engine` it describes (:meth:`engine`); a
    study that varies its keys (:func:`~balance_cli.sweep`) or repeats its cylinders
    (:func:`~balance_cli.family`) starts from the configuration itself. It keeps its own copy
    of what was given, and ``data`` gives a copy of that: changing either dict afterwards
    changes nothing here.

    Raises
    ------
    ConfigError
        ``data`` is not a table of keys, or ``path`` not text
    """

    __slots__ = ("_data", "_path")

    def __init__(self, data: dict, path: str = "<config>"):
        if not isinstance(path, str):
            raise ConfigError("<config>", "", f"path must be text, got {type(path).__name__}")
        if not isinstance(data, dict):
            raise ConfigError(
                path,
                "",
                f"data must be the parsed TOML of a configuration (a dict), got "
                f"{type(data).__name__}",
            )
        self._data = copy.deepcopy(data)
        self._path = path

    @property
    def data(self) -> dict:
        """The parsed TOML, a copy."""
        return copy.deepcopy(self._data)

    @property
    def path(self) -> str:
        return self._path

    def __eq__(self, other):
        if not isinstance(other, Configuration):
            return NotImplemented
        return (self._path, self._data) == (other._path, other._data)

    __hash__ = None  # type: ignore[assignment]  # equal by value, and its data is a dict

    def __repr__(self):
        return f"Configuration(path={self._path!r}, name={self._data.get('name')!r})"

    @property
    def provenance(self) -> Provenance:
        """Its ``sources`` and ``estimates`` (ConfigError where their form is wrong)."""
        return read_provenance(self._data, self._path)

    def engine(self) -> Engine:
        """The engine it describes (ConfigError naming the file, the key and the fix)."""
        return build(self.data, self._path)

    def template(self) -> Engine:
        """The engine of a search template (its ``[[throws]]`` give only ``z``, and it has no
        ``firing_order``: the search chooses both), every throw at phase 0."""
        return build(self.data, self._path, template=True)

    def as_template(self) -> "Configuration":
        """The same configuration without its throws' phases and firing order: a search
        template of the same engine."""
        return Configuration(as_template(self._data), self._path)

    def to_dict(self) -> dict:
        return {"path": self._path, "data": self.data}


def read_configuration(path: "str | os.PathLike[str]") -> Configuration:
    """The :class:`Configuration` in the file at ``path``, checked as a configuration (its
    throws' phases may be given or not: a family or a search may start from it).

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    configuration = Configuration(_read_data(path), str(path))
    configuration.as_template().template()
    return configuration


def as_template(data: dict) -> dict:
    """A configuration's parsed TOML without its throws' phases and firing order: a search
    template of the same engine."""
    template = {k: v for k, v in data.items() if k != "firing_order"}
    if isinstance(template.get("throws"), list):
        template["throws"] = [
            {k: v for k, v in t.items() if k != "phase"} if isinstance(t, dict) else t
            for t in template["throws"]
        ]
    return template


def load_template(path: "str | os.PathLike[str]") -> Engine:
    """Read a search template: a configuration whose ``[[throws]]`` give only ``z`` and which
    has no ``firing_order`` (``balance search`` chooses both). Returns its engine, every throw
    at phase 0 (:func:`read_configuration` gives the parsed file too, for writing
    arrangements).

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    path = resolve(path)
    return Configuration(_read_data(path), str(path)).template()


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
        paths = [paths]  # one path, not the characters of one
    try:
        paths = [resolve(checks.path(p, "paths")) for p in paths]
    except TypeError:
        error = ConfigError(
            "<paths>",
            "",
            f"paths must be a list of file or folder paths, got {type(paths).__name__}",
        )
        error.parameter = "paths"
        raise error from None
    found = []
    for p in map(Path, paths):
        if not p.is_dir():
            found.append(p)
            continue
        files = []

        def unreadable(exc, folder=p):
            raise ConfigError(
                exc.filename or folder,
                "",
                f"cannot read the folder ({exc.strerror or exc}); check its permissions",
            ) from None

        if not os.access(p, os.R_OK | os.X_OK):
            unreadable(PermissionError(13, "Permission denied", str(p)))
        for folder, subfolders, names in os.walk(p, onerror=unreadable):
            subfolders.sort()
            files += [
                Path(folder) / n
                for n in names
                if n.endswith(".toml") and (Path(folder) / n).is_file()
            ]
        if not files:
            raise ConfigError(p, "", "no .toml configuration found in this folder")
        found += sorted(files)
    return found


def load_many(paths: "Iterable[str | os.PathLike[str]]") -> list[Engine]:
    """Load every configuration under ``paths`` (see :func:`find_configs`)."""
    return [load(f) for f in find_configs(paths)]
