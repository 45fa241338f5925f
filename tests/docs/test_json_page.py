"""The JSON documents page lists what the commands write: each document's top-level keys and
its entries' keys, every key the page calls *always* in every run, every other key in the run
that adds it, and nothing the page does not list."""

import json
import re

import pytest
from click.testing import CliRunner

from balance_cli.cli import main
from tests.docs.pages import DOCS
from tests.support import CONFIGS, REFERENCE, TEMPLATES, V8
from tests.workshop.test_match import INLINE_4, PARTS_CSV
from tests.workshop.test_tolerance import FLAT_4

PAGE = DOCS / "reference" / "json.md"
CAR = CONFIGS / "inline-4-car.toml"


def documented():
    """document -> {key path: when it is present}, from the page's tables."""
    out: dict = {}
    document = None
    for line in PAGE.read_text(encoding="utf-8").splitlines():
        heading = re.match(r"^## (\w+)$", line)
        if heading:
            document = out.setdefault(heading.group(1), {})
        row = re.match(r"^\| `([^`]+)` \| ([^|]+) \|", line)
        if row and document is not None:
            document[row.group(1)] = row.group(2).strip()
    return out


def written(document, entries):
    """The key paths of a document: its top-level keys and the keys of the entries of its
    lists named in ``entries`` (``engines[].name``); the page gives other lists' keys in
    words."""
    keys = set(document)
    for key in entries:
        keys |= {f"{key}[].{k}" for entry in document.get(key) or () for k in entry}
    return keys


def run(*args):
    result = CliRunner().invoke(main, [str(a) for a in (*args, "--format", "json")])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


@pytest.fixture
def runs(tmp_path):
    """Each document as written by runs that, between them, add every conditional key."""
    torque_csv = tmp_path / "torque.csv"
    # a torque curve of mean 100 N·m and a second order of 50 N·m over one revolution
    torque_csv.write_text(
        "angle_deg,torque_Nm\n"
        + "".join(f"{a},{100 + 50 * (1 if a % 180 < 90 else -1)}\n" for a in range(0, 360, 10)),
        encoding="utf-8",
    )
    baseline = tmp_path / "baseline.json"
    baseline.write_text(json.dumps(run("compare", CAR)), encoding="utf-8")
    out = {
        "compare": [run("compare", V8), run("compare", V8, "--speed", "3000 rpm")],
        "counterweight": [
            run("counterweight", CAR),
            run("counterweight", CAR, "--shafts", "2", "--test-masses"),
            run("counterweight", CONFIGS / "inline-4-car-lanchester.toml"),
        ],
        "torque": [run("torque", CAR)],
        "mounts": [
            run("mounts", CONFIGS / "mounts" / "four-mount-coupled.toml", "--speeds", "500,1000"),
            run(
                "mounts",
                CONFIGS / "mounts" / "four-mount-coupled.toml",
                "--speeds",
                "500",
                "--decouple",
                "all",
            ),
        ],
        "steadiness": [
            run(
                "steadiness", "--torque", torque_csv, "--inertia", "2 kg*m^2", "--speed", "1500 rpm"
            )
        ],
        "regress": [run("regress", baseline, CAR)],
        "search": [
            run("search", TEMPLATES / "inline-3-2stroke.toml", "--top", "1", "--workers", "1")
        ],
        "family": [
            run(
                "family",
                TEMPLATES / "marine-family-2stroke.toml",
                "--cylinders",
                "5-6",
                "--workers",
                "1",
            )
        ],
        "sweep": [
            run("sweep", CAR, "--vary", "rod_length", "--values", "140 mm,150 mm"),
            run(
                "sweep",
                CONFIGS / "mounts" / "four-mount-coupled.toml",
                "--vary",
                "mounts.mount[A].stiffness[3]",
                "--values",
                "200 N/mm,300 N/mm",
                "--quantity",
                "mode_1,roll_mode,tra_purity,axes_angle,mount_A_force,mount_D_Fz",
                "--mount-speeds",
                "500,1000",
            ),
            run(
                "sweep",
                CAR,
                "--vary",
                "rod_length",
                "--values",
                "140 mm,150 mm",
                "--vary",
                "crank_radius",
                "--values",
                "40 mm,43 mm",
            ),
        ],
    }
    shop = tmp_path / "shop"
    shop.mkdir()
    (shop / "engine.toml").write_text(INLINE_4, encoding="utf-8")
    (shop / "parts.csv").write_text(PARTS_CSV, encoding="utf-8")
    (shop / "band.toml").write_text(FLAT_4, encoding="utf-8")
    out["match"] = [run("match", shop / "engine.toml", "--parts", shop / "parts.csv")]
    out["tolerance"] = [run("tolerance", shop / "band.toml", "--runs", "200")]
    out["bobweight"] = [run("bobweight", shop / "engine.toml")]
    try:
        import opentorsion  # noqa: F401
    except ImportError:
        pass  # the torsion extra: checked wherever it is installed (make test installs it)
    else:
        mendes = REFERENCE / "opentorsion_ice" / "mendes2008.toml"
        out["torsion"] = [run("torsion", mendes, "--speeds", "1000,2000")]
    return out


def test_the_page_documents_every_json_command():
    commands = {
        name
        for name, command in main.commands.items()
        for p in command.params
        if p.name == "fmt" and "json" in getattr(p.type, "choices", ())
    }
    assert commands and commands <= set(documented())


def test_every_document_is_what_the_page_lists(runs):
    pages = documented()
    for name, documents in runs.items():
        page = pages[name]
        wildcards = {k.removesuffix("*") for k in page if k.endswith("*")}
        entries = {k.split("[]")[0] for k in page if "[]" in k}
        seen = set()
        for document in documents:
            keys = written(document, entries)
            seen |= keys
            unlisted = {k for k in keys - set(page) if not any(k.startswith(w) for w in wildcards)}
            assert not unlisted, f"{name} writes keys the page does not list: {sorted(unlisted)}"
            always = {k for k, when in page.items() if when == "always" and not k.endswith("*")}
            assert always <= keys, f"{name} lacks: {sorted(always - keys)}"
        never = {k for k in page if not k.endswith("*")} - seen
        assert not never, f"{name}: no run wrote {sorted(never)}"
