"""The JSON Schemas of the documents balance writes, and checking a document against its own.

Every document balance writes (``--format json`` of compare, counterweight, torque, torsion,
mounts, steadiness, regress, search, family, sweep, match, tolerance and bobweight) carries its
format's version in ``balance_version``; its schema is the file ``DOCUMENT.vVERSION.json`` beside
this module (Draft 2020-12), installed with the package. A schema of a version balance writes
is closed: a key it does not name fails it. The compare document's versions 1 and 2 have the
schemas of what ``balance regress`` reads of a baseline that old, open to other keys.
``tools/json_schemas.py`` writes the files (``make schemas``).

>>> from balance_cli.schemas import schema
>>> schema("compare", 3)["title"]
'balance compare document, version 3'
"""

import json
import math
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from ..output import DOCUMENT_VERSION, READABLE_VERSIONS, STEADINESS_VERSION

__all__ = ["DOCUMENTS", "Problem", "schema", "schema_name", "problem"]

#: every document and the versions whose schemas ship: the last is the version balance writes
DOCUMENTS = {
    "compare": READABLE_VERSIONS,
    **{
        name: (DOCUMENT_VERSION,)
        for name in (
            "counterweight",
            "torque",
            "torsion",
            "mounts",
            "regress",
            "search",
            "family",
            "sweep",
            "match",
            "tolerance",
            "bobweight",
        )
    },
    "steadiness": (STEADINESS_VERSION,),
}

_FOLDER = Path(__file__).resolve().parent
#: how a JSON type is named in a message
_TYPES = {
    "number": "a number",
    "integer": "a whole number",
    "string": "text",
    "boolean": "true or false",
    "null": "null",
    "object": "an object",
    "array": "a list",
}


def schema_name(document: str, version: int) -> str:
    """The file name of a document's schema: ``compare.v3.json``."""
    return f"{document}.v{version}.json"


def _check(document, version):
    if document not in DOCUMENTS:
        raise KeyError(f"{document!r} is not a document balance writes ({', '.join(DOCUMENTS)})")
    if version not in DOCUMENTS[document]:
        known = ", ".join(map(str, DOCUMENTS[document]))
        raise KeyError(f"the {document} document has no version {version!r} (it has {known})")


@cache
def _text(document: str, version: int) -> str:
    _check(document, version)
    return (_FOLDER / schema_name(document, version)).read_text(encoding="utf-8")


def schema(document: str, version: int | None = None) -> dict:
    """The JSON Schema (a new dict) of ``document`` ("compare", "sweep", ...) at ``version``
    (default: the version balance writes). KeyError for a document or version that has none."""
    if version is None:
        version = DOCUMENTS[document][-1] if document in DOCUMENTS else 0
    return json.loads(_text(document, version))


@cache
def _validator(document, version):
    # jsonschema only when a document is checked: the commands that write need none of it
    from jsonschema import Draft202012Validator

    return Draft202012Validator(json.loads(_text(document, version)))


@dataclass(frozen=True)
class Problem:
    """What is wrong with a document: where (a JSON path, ``$.engines[0].orders[1]``), what
    (``lacks 'force'``) and the schema it breaks (``compare.v3.json``)."""

    path: str
    message: str
    schema: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}"


def _json_path(parts) -> str:
    """A JSON path from keys and indexes: ``$.engines[0].name``."""
    out = "$"
    for part in parts:
        if isinstance(part, int):
            out += f"[{part}]"
        elif part.isidentifier():
            out += f".{part}"
        else:
            out += f"[{json.dumps(part, ensure_ascii=False)}]"
    return out


def _shown(value) -> str:
    """A value as JSON writes it, cut short."""
    try:
        text = json.dumps(value, ensure_ascii=False, allow_nan=True)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _non_finite(value, parts=()):
    """The path of the first number that is not finite (NaN and Infinity are not JSON)."""
    if isinstance(value, float) and not math.isfinite(value):
        return parts
    if isinstance(value, dict):
        items = list(value.items())
    elif isinstance(value, (list, tuple)):
        items = list(enumerate(value))
    else:
        return None
    for key, item in items:
        found = _non_finite(item, (*parts, key))
        if found is not None:
            return found
    return None


#: what a value breaking one of these keywords is, in words: its value against the schema's
_BOUNDS = {
    "const": "is {value}, not {wanted}",
    "minimum": "is {value}, below {wanted}",
    "exclusiveMinimum": "is {value}, not above {wanted}",
    "maximum": "is {value}, above {wanted}",
    "exclusiveMaximum": "is {value}, not below {wanted}",
    "multipleOf": "is {value}, not a multiple of {wanted}",
}


def _words(error) -> str:
    """A schema error in words: what the value is and what the schema wants."""
    kind, wanted, value = error.validator, error.validator_value, error.instance
    if kind == "required":
        # one error per key missing: say every key the object lacks at once
        return "lacks " + ", ".join(repr(k) for k in wanted if k not in value)
    if kind == "additionalProperties":
        allowed = set(error.schema.get("properties", {}))
        patterns = error.schema.get("patternProperties", {})
        extra = [
            k for k in value if k not in allowed and not any(re.search(p, k) for p in patterns)
        ]
        return f"has {', '.join(repr(k) for k in extra)}, which the schema does not define"
    if kind == "type":
        types = [wanted] if isinstance(wanted, str) else list(wanted)
        return f"is {_shown(value)}, not {' or '.join(_TYPES.get(t, t) for t in types)}"
    if kind in _BOUNDS:
        return _BOUNDS[kind].format(value=_shown(value), wanted=_shown(wanted))
    if kind == "enum":
        return f"is {_shown(value)}, not one of {', '.join(_shown(w) for w in wanted)}"
    if kind == "minItems":
        return f"has {len(value)} items, fewer than {wanted}"
    if kind == "maxItems":
        return f"has {len(value)} items, more than {wanted}"
    if kind == "pattern":
        return f"is {_shown(value)}, which is not of the form {wanted}"
    if kind == "not" and isinstance(wanted, dict) and "required" in wanted:
        keys = ", ".join(repr(k) for k in wanted["required"])
        return f"has {keys}: {wanted.get('description', 'which goes with none of its other keys')}"
    return error.message


def _version_of(instance, document) -> int:
    """The version ``instance`` names, where ``document`` has a schema of it; else the one
    balance writes (whose schema then says what is wrong with the one named)."""
    named = instance.get("balance_version") if isinstance(instance, dict) else None
    versions = DOCUMENTS.get(document, (0,))
    return named if type(named) is int and named in versions else versions[-1]


def problem(instance, document: str, version: int | None = None) -> "Problem | None":
    """The first thing wrong with ``instance`` (a document read from JSON) as ``document``
    of ``version`` (default: the version ``instance`` names in ``balance_version``, else the
    version balance writes): a :class:`Problem`, or None when the schema holds. A number that
    is not finite (NaN, Infinity: not JSON) is a problem too.

    Raises
    ------
    KeyError
        a document or version without a schema
    """
    if version is None:
        version = _version_of(instance, document)
    _check(document, version)
    name = schema_name(document, version)
    from jsonschema.exceptions import best_match

    error = best_match(_validator(document, version).iter_errors(instance))
    # a value that may be null, or an object of its own, fails both: say what is wrong with it
    # as the object (best_match leaves "not valid under any of the given schemas")
    while error is not None and error.validator in ("anyOf", "oneOf") and error.context:
        inner = [e for e in error.context if e.validator != "type" or e.validator_value != "null"]
        if not inner:
            break
        error = best_match(inner)
    if error is not None:
        return Problem(_json_path(error.absolute_path), _words(error), name)
    where = _non_finite(instance)
    if where is not None:
        return Problem(
            _json_path(where), "is not a finite number (JSON has no NaN, Infinity)", name
        )
    return None
