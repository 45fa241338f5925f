"""The configuration keys of "Describe an engine" are the reader's: the same keys, table by
table; each key's unit (dimension) and default what the reader asks for when it reads the
page's own examples; every key shown in an example, and every example value readable."""

import functools
import math
import re
import tomllib

import pytest

import balance_cli as balance
from balance_cli.config.reader import Reader
from balance_cli.studies.sweep import SCHEMA
from balance_cli.units import DIMENSIONS, parse_quantity
from tests.docs.pages import DOCS, code_blocks, keys_table

PAGE = DOCS / "howto" / "describe-an-engine.md"
kt = keys_table()


def documented():
    """(table path, key) -> Key, every place a key is read included."""
    return {
        (path, key.name): key for t in kt.tables() for path in t.paths for key in t.keys.values()
    }


def examples():
    return code_blocks(PAGE, "toml")


def test_the_page_lists_exactly_the_readers_keys():
    assert kt.mismatches() == []
    # and the comparison itself sees a difference: a key taken away is reported
    tables = kt.tables()
    first = tables[0]
    fewer = [type(first)(first.path, first.reader, first.title, dict(list(first.keys.items())[1:]))]
    assert any("the reader accepts name" in p for p in kt.mismatches(fewer + tables[1:]))


def test_every_reader_key_set_has_its_table():
    assert {t.reader for t in kt.tables()} == set(kt.reader_key_sets())


def toml_paths(data, prefix=""):
    """(table path, key) of every key in parsed TOML, arrays of tables as ``name[]``."""
    for key, value in data.items():
        yield prefix.rstrip("."), key
        if isinstance(value, dict):
            yield from toml_paths(value, f"{prefix}{key}.")
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for item in value:
                yield from toml_paths(item, f"{prefix}{key}[].")


def test_every_key_is_shown_in_an_example_of_the_page():
    shown = {p for text in examples() for p in toml_paths(tomllib.loads(text))}
    missing = {
        (t.title, key)
        for t in kt.tables()
        for key in t.keys
        if not any((path, key) in shown for path in t.paths)
    }
    assert not missing


def test_every_example_value_is_written_as_its_kind_says():
    for (path, name), key in documented().items():
        value = tomllib.loads(f"v = {key.example}")["v"] if key.example[:1] != "[" else None
        # a key of several values (a position's x, y, z) shows a list: each is of its kind
        values = tomllib.loads(f"v = {key.example}")["v"] if key.values else [value]
        assert isinstance(values, list) and values, (path, name)
        for value in values:
            if key.kind in DIMENSIONS:
                assert math.isfinite(parse_quantity(value, key.kind)), (path, name)
            elif key.kind in ("degrees", "number"):
                assert isinstance(value, (int, float)) and not isinstance(value, bool), (path, name)
            elif key.kind == "integer":
                assert isinstance(value, int), (path, name)
            elif key.kind == "text":
                assert isinstance(value, str), (path, name)


#: the sweep's table of numeric keys names its kinds in other words
_SWEEP_KINDS = {"angle": "degrees", "number": "number", "whole number": "integer"}


def test_the_kinds_agree_with_the_sweeps_own_table_of_keys():
    """balance_cli.studies.sweep.SCHEMA lists every numeric key with its kind, written apart
    from the reader: a second source for the units."""
    keys = documented()
    for table, entries in SCHEMA.items():
        for name, kind in entries.items():
            assert keys[(table, name)].kind == _SWEEP_KINDS.get(kind, kind), (table, name)


@pytest.fixture
def reads(monkeypatch):
    """Every value the reader reads while the page's examples load: (table path, key, how,
    dimension, default)."""
    calls = []

    def recording(method, how):
        @functools.wraps(method)
        def wrapper(self, key, *args, **kwargs):
            dimension = args[0] if how == "quantity" and args else kwargs.get("dimension")
            default = kwargs.get("default")
            table = re.sub(r"\[\d+\]", "[]", self.prefix).rstrip(".")
            calls.append((table, re.sub(r"\[\d+\]$", "", key), how, dimension, default))
            return method(self, key, *args, **kwargs)

        return wrapper

    for how in ("quantity", "degrees", "real", "integer", "string"):
        monkeypatch.setattr(Reader, how, recording(getattr(Reader, how), how))
    for i, text in enumerate(examples(), 1):
        balance.loads(text, name=f"describe-an-engine.md, example {i}")
    return calls


#: what each kind of key is read with
_READ_AS = {
    "degrees": {"degrees", "real"},
    "number": {"real"},
    "integer": {"integer"},
    "text": {"string"},
}


def test_the_reader_reads_each_key_with_the_pages_unit(reads):
    keys = documented()
    assert len(reads) > 150
    for table, name, how, dimension, _ in reads:
        key = keys[(table, name)]
        if how == "quantity":
            assert key.kind == dimension, (table, name)
        else:
            assert how in _READ_AS[key.kind], (table, name, how)


def test_the_pages_defaults_are_the_readers(reads):
    keys = documented()
    checked = 0
    for table, name, _, _, default in reads:
        key = keys[(table, name)]
        if default is None or key.default_note:
            continue  # no default, or one that is another key's value (the page says which)
        assert key.default is not None, f"{table}.{name}: the reader's default {default!r}"
        if isinstance(default, str):
            assert key.default_value == default, (table, name)
        else:
            # rtol: a unit's factor (1 atm = 101 325 Pa, 1 bar) times the number, one rounding
            assert key.default_value == pytest.approx(default, rel=1e-12, abs=0.0), (table, name)
        checked += 1
    assert checked > 20
