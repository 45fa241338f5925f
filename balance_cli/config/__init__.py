"""Configuration format version 1: TOML -> :class:`~balance_cli.model.Engine`.

Every error names the file, the key (``banks[3].angle``) and what to do about it. Unknown keys
are errors: a typo must not be silently ignored. This package reads values (types, units,
ranges, signs); the rules that relate values to each other (a rod longer than the crank, link
rods on master rods of their own throw, one cylinder per bore, a firing order that lists every
cylinder) are the model's, whose messages are translated here into the file's key names;
only the uniqueness of cylinder numbers is checked here too, because the key of a listed
cylinder is found by its number.

Modules: :mod:`.reader` (the text, its TOML, and typed values with units), :mod:`.builder`
(the Engine from parsed data), :mod:`.sections` (crankshafts, counterweights and shafts,
parts, gas, torsion), :mod:`.mounts` (the engine on its mounts), :mod:`.files` (files and
folders to engines and configurations), :mod:`.library` (the shipped engines and templates,
named ``library:`` and ``template:``), :mod:`.provenance` (a file's ``sources`` and
``estimates``) and :mod:`.write` (configurations written back as TOML).
"""

from .builder import build
from .files import (
    Configuration,
    as_template,
    find_configs,
    load,
    load_many,
    load_template,
    loads,
    read_configuration,
)
from .library import library_folder, resolve, templates_folder
from .provenance import Note, Provenance, number_paths, read_provenance
from .reader import parse_text, read_text
from .write import WRITE_DIGITS, arrangement_toml, as_built_toml

__all__ = [
    "load",
    "loads",
    "build",
    "find_configs",
    "load_many",
    "load_template",
    "Configuration",
    "read_configuration",
    "arrangement_toml",
    "as_built_toml",
    "WRITE_DIGITS",
    "as_template",
    "read_text",
    "parse_text",
    "library_folder",
    "templates_folder",
    "resolve",
    "Provenance",
    "Note",
    "read_provenance",
    "number_paths",
]
