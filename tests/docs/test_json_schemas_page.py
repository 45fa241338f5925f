"""The site's JSON pages and the schema files agree: the JSON page links every schema file and
lists every document that has one, the schemas page shows each file, and each document's table
on the JSON page names the keys its schema names, the ones it calls *always* being those the
schema requires."""

import re

from balance_cli.schemas import DOCUMENTS, schema, schema_name
from tests.docs.pages import DOCS
from tests.docs.test_json_page import documented

JSON_PAGE = DOCS / "reference" / "json.md"
SCHEMAS_PAGE = DOCS / "reference" / "schemas.md"
FILES = {schema_name(d, v) for d, versions in DOCUMENTS.items() for v in versions}
FOLDER = DOCS.parent / "balance_cli" / "schemas"


def test_the_json_page_links_every_schema_file():
    text = JSON_PAGE.read_text(encoding="utf-8")
    links = re.findall(r"\{download\}`([^`<]+?) <\.\./\.\./balance_cli/schemas/([^>]+)>`", text)
    assert sorted(name for name, _ in links) == sorted(FILES)
    assert all(name == file for name, file in links)
    # each row: the document, its version, its file
    rows = re.findall(r"^\| (\w+) \| (\d+) \| \{download\}`([^` ]+)", text, re.M)
    assert sorted(rows) == sorted(
        (d, str(v), schema_name(d, v)) for d, versions in DOCUMENTS.items() for v in versions
    )


def test_the_schemas_page_shows_every_schema_file():
    text = SCHEMAS_PAGE.read_text(encoding="utf-8")
    shown = re.findall(r"^```\{literalinclude\} \.\./\.\./balance_cli/schemas/(\S+)$", text, re.M)
    assert sorted(shown) == sorted(FILES)
    headings = re.findall(r"^## (\w+), version (\d+)$", text, re.M)
    assert sorted(schema_name(d, int(v)) for d, v in headings) == sorted(FILES)
    assert {p.name for p in FOLDER.glob("*.json")} == FILES


def test_every_document_of_the_json_page_has_a_schema():
    assert set(documented()) == set(DOCUMENTS)


def _resolve(node, root):
    while "$ref" in node:
        node = root["$defs"][node["$ref"].removeprefix("#/$defs/")]
    return node


def _keys(node, root):
    """(every key, the required keys) of an object schema, its if/then/else branches too."""
    node = _resolve(node, root)
    names, required = set(node.get("properties", {})), set(node.get("required", []))
    for branch in [node[k] for k in ("then", "else") if k in node]:
        more, _ = _keys(branch, root)
        names |= more
    return names, required


def _items(node, root, key):
    """The schema of the entries of the list ``key`` of ``node``, its branches' too."""
    node = _resolve(node, root)
    found = []
    listed = node.get("properties", {}).get(key)
    if listed is not None and isinstance(_resolve(listed, root).get("items"), dict):
        found.append(_resolve(listed, root)["items"])
    for branch in [node[k] for k in ("then", "else") if k in node]:
        found += _items(branch, root, key)
    return found


def test_each_table_names_the_keys_of_its_schema():
    """The JSON page's *always* is the schema's *required*, at the top and in each list whose
    entries the page lists; a key the page names conditionally is in the schema, not required."""
    for name, page in documented().items():
        root = schema(name)
        top = {k for k in page if "[]" not in k}
        names, required = _keys(root, root)
        assert top == names, (name, sorted(top ^ names))
        assert {k for k in top if page[k] == "always"} == required, name
        for key in {k.split("[]")[0] for k in page if "[]" in k}:
            listed = {
                k.split("[].", 1)[1]: when for k, when in page.items() if k.startswith(f"{key}[].")
            }
            entries = _items(root, root, key)
            assert entries, (name, key)
            names, required = set(), None
            for entry in entries:
                more, needed = _keys(entry, root)
                names |= more
                required = needed if required is None else required & needed
            if "*" in listed:  # a wildcard row: the page names some keys, in words the rest
                assert set(listed) - {"*"} <= names, (name, key)
                continue
            assert set(listed) == names, (name, key, sorted(set(listed) ^ names))
            assert {k for k, when in listed.items() if when == "always"} == required, (name, key)
