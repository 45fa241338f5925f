"""Every JSON document balance writes is valid under the schema of its version
(balance_cli/schemas), on the shipped library and on engines that switch on the optional keys;
between them the runs write every key each schema names; a schema is not vacuous (a key added
or dropped fails it); and the schema files are the ones tools/json_schemas.py writes, valid
Draft 2020-12 schemas, one for each document a command writes."""

import copy
import json
import math

import pytest
from jsonschema import Draft202012Validator

from balance_cli.cli import main
from balance_cli.output import DOCUMENT_VERSION, STEADINESS_VERSION
from balance_cli.schemas import DOCUMENTS, problem, schema, schema_name
from tests.support import CONFIGS, REFERENCE, TEMPLATES, TODAY, TWIN, invoke
from tests.workshop.test_match import DATA, INLINE_4, PARTS_CSV
from tests.workshop.test_tolerance import FLAT_4

CAR = CONFIGS / "inline-4-car.toml"
LANCHESTER = CONFIGS / "inline-4-car-lanchester.toml"
TRUCK = TODAY / "inline" / "inline-6-truck-diesel.toml"
MAN6 = CONFIGS / "man-s80mc-c7-6cyl.toml"
MENDES = REFERENCE / "opentorsion_ice" / "mendes2008.toml"

#: counterweights as built, one with its radius (a mass) and one without (m·ρ only), on the
#: twin of tests.support
BUILT = TWIN + (
    '\n[[counterweights]]\nthrow = 1\nmass = "0.2 kg"\nradius = "40 mm"\nangle = 180\n'
    '\n[[counterweights]]\nthrow = 2\nmass_radius = "0.008 kg*m"\nangle = 180\n'
)
#: a torque curve of mean 100 N·m and a second order of 50 N·m over one revolution
TORQUE_CSV = "angle_deg,torque_Nm\n" + "".join(
    f"{a},{100 + 50 * math.sin(math.radians(2 * a))!r}\n" for a in range(0, 360, 10)
)


def strict(text):
    """JSON as RFC 8259 has it: NaN and Infinity are refused."""

    def refuse(constant):
        raise AssertionError(f"{constant} in a JSON document")

    return json.loads(text, parse_constant=refuse)


def run(*args):
    result = invoke(*args, "--format", "json")
    assert result.exit_code in (0, 1), result.output  # regress: 1 when something moved
    return strict(result.stdout)


@pytest.fixture(scope="module")
def documents(tmp_path_factory):
    """document -> what the runs wrote: the whole library, and runs that add every optional
    key (a --speed, PRU under another balance, shafts, test masses, an antivibrateur,
    counterweights and shafts as built, gas, several crankshafts, a flywheel, uneven and
    heuristic searches, grids, a torsion choice, regress rows of every kind)."""
    folder = tmp_path_factory.mktemp("documents")
    built = folder / "built.toml"
    built.write_text(BUILT, encoding="utf-8")
    curve = folder / "torque.csv"
    curve.write_text(TORQUE_CSV, encoding="utf-8")
    baseline = folder / "baseline.json"
    baseline.write_text(json.dumps(run("compare", CAR, built)), encoding="utf-8")
    heavier = folder / "heavier.toml"
    heavier.write_text(
        BUILT.replace('reciprocating = "500 g"', 'reciprocating = "510 g"').replace(
            "firing_order = [1, 2]", "firing_order = [2, 1]"
        ),
        encoding="utf-8",
    )
    out = {
        "compare": [
            run("compare", CONFIGS),
            run("compare", CONFIGS / "tanaka-part3", "--speed", "3000 rpm"),
            run(
                "compare",
                MAN6,
                CONFIGS / "marine-6-2stroke.toml",
                "--power",
                "20000 kW",
                "--pru-orders",
                "1,2,4",
                "--first-order-balance",
                "0.3",
            ),
            run("compare", MAN6, "--first-order-balance", "crank", "--pru-orders", "2"),
        ],
        "counterweight": [
            run("counterweight", CONFIGS),
            # planes at axial positions that no throw sits at: no throw
            run("counterweight", built, "--test-masses", "--planes", "10 mm,80 mm"),
            run(
                "counterweight",
                CAR,
                LANCHESTER,
                "--shafts",
                "1,2",
                "--test-masses",
                "--shaft-offset",
                "100 mm,50 mm",
            ),
            run("counterweight", CONFIGS / "bramo-323.toml", "--antivibrateur"),
            run("counterweight", CAR, "--balance-factor", "0.5", "--radius", "50 mm"),
        ],
        "torque": [
            run("torque", CONFIGS),
            run("torque", TRUCK, "--inertia", "2 kg*m^2", "--target", "100"),
            run("torque", TRUCK, "--inertia", "2 kg*m^2", "--load", "constant"),
        ],
        "steadiness": [
            run("steadiness", "--torque", curve, "--inertia", "2 kg*m^2", "--speed", "1500 rpm"),
            run(
                "steadiness",
                "--torque",
                curve,
                "--inertia",
                "2 kg*m^2",
                "--speed",
                "1500 rpm",
                "--target",
                "50",
                "--load",
                "constant",
            ),
        ],
        "search": [
            # every shipped template (the in-line twelve's exhaustive search by its heuristic)
            *(
                # a V family's bank angle fires evenly only bank by bank: --even-banks
                run(
                    "search",
                    template,
                    "--top",
                    "3",
                    "--workers",
                    "1",
                    *(["--even-banks"] if template.name.startswith("v-family") else []),
                )
                for template in sorted(TEMPLATES.glob("*.toml"))
                if template.name != "inline-12-2stroke.toml"
            ),
            run(
                "search",
                TEMPLATES / "inline-6-4stroke.toml",
                "--top",
                "2",
                "--workers",
                "1",
                "--objective",
                "F1+,M2-:2,M1,H3,X2",
            ),
            # an uneven crank whose mirror image is another crank: mirror_of
            run(
                "search",
                TEMPLATES / "inline-6-4stroke.toml",
                "--top",
                "2",
                "--workers",
                "1",
                "--allow-uneven",
                "--step",
                "90",
            ),
            run(
                "search",
                TEMPLATES / "inline-12-2stroke.toml",
                "--top",
                "2",
                "--workers",
                "1",
                "--heuristic",
                "--restarts",
                "2",
            ),
        ],
        "family": [
            # a V family: major orders, firing within each bank
            run("family", TEMPLATES / "v-family-4stroke.toml", "--cylinders", "12-14"),
            run(
                "family",
                TEMPLATES / "marine-family-2stroke.toml",
                "--cylinders",
                "5-6",
                "--workers",
                "1",
            ),
            run(
                "family",
                TEMPLATES / "marine-family-2stroke.toml",
                "--cylinders",
                "4,6",
                "--workers",
                "1",
                "--first-order-balance",
                "crank",
                "--max-order",
                "3",
                "--firing-order",
                "4:1,3,2,4",
            ),
            # a family without a power: no PRU, nor a compensator's verdict
            run(
                "family",
                TEMPLATES / "inline-6-2stroke.toml",
                "--cylinders",
                "3,5",
                "--workers",
                "1",
            ),
        ],
        "sweep": [
            run("sweep", CAR, "--vary", "rod_length", "--values", "140 mm,150 mm"),
            run(
                "sweep",
                CAR,
                "--vary",
                "balance_factor",
                "--values",
                "0.5,1",
                "--vary",
                "crank_radius",
                "--values",
                "40 mm,43 mm",
                "--quantity",
                "F2,F2V,M1H,F1+,F2-,largest_force,largest_moment",
            ),
            run(
                "sweep",
                TRUCK,
                "--vary",
                "speed",
                "--from",
                "1000 rpm",
                "--to",
                "2000 rpm",
                "--steps",
                "3",
                "--quantity",
                "torque_mean,torque_max,torque_min,torque_range,steadiness,PRU1V,PRU2H",
                "--inertia",
                "2 kg*m^2",
            ),
            run("sweep", CAR, "--vary", "rod_ratio", "--values", "3,3.5"),
            run("sweep", CAR, "--vary", "balance_factor", "--values", "0,0.5,1"),
            run(
                "sweep", CAR, "--vary", "banks[1].angle", "--values", "0,10", "--speed", "5000 rpm"
            ),
            # the mount analysis's quantities over a [mounts] key, a mount's force over speeds
            run(
                "sweep",
                CONFIGS / "mounts" / "four-mount-symmetric.toml",
                "--vary",
                "mounts.mount[*].stiffness[3]",
                "--values",
                "150 N/mm,250 N/mm",
                "--quantity",
                "mode_1,bounce_mode,tra_purity,axes_angle,mount_front_left_force,mount_2_Fz",
                "--mount-speeds",
                "600:1200:300",
            ),
        ],
        # every file of the library's mounts folder: with and without a mean torque (the
        # genset's gas cycle, the car's power), inclined mounts, resonances crossed
        "mounts": [
            run("mounts", CONFIGS / "mounts", "--speeds", "300:1500:300"),
            run("mounts", CONFIGS / "mounts" / "four-mount-coupled.toml", "--decouple", "all"),
        ],
        "regress": [
            run("regress", baseline, CAR, built),
            # a mass and a firing order moved, an engine added and one removed
            run("regress", baseline, CAR, heavier, LANCHESTER, "--rtol", "0.001"),
        ],
    }
    out.update(_workshop(folder))
    try:
        import opentorsion  # noqa: F401
    except ImportError:
        pass  # the torsion extra: checked wherever it is installed (make test installs it)
    else:
        out["torsion"] = [
            run("torsion", TRUCK, CONFIGS / "mendes2008-mwm-6.toml", "--speeds", "1000:2000:500"),
            run(
                "torsion",
                MENDES,
                "--speeds",
                "1000:2000:500",
                "--criticals",
                "major",
                "--orders",
                "3,6",
                "--modes",
                "1",
            ),
        ]
    return out


def _workshop(folder):
    """match (default and terms objectives, pistons, rods or both, the heuristic, parts that
    weigh alike, an engine with a power and one without moments), tolerance (masses alone and
    dimensions) and bobweight (a chosen factor with parts, a twin's trade)."""
    engine = folder / "inline-4.toml"
    engine.write_text(INLINE_4, encoding="utf-8")
    both = folder / "parts.csv"
    both.write_text(PARTS_CSV, encoding="utf-8")
    rods = folder / "rods.csv"
    rods.write_text(
        "\n".join(line for line in PARTS_CSV.splitlines() if not line.startswith("piston")),
        encoding="utf-8",
    )
    alike = folder / "alike.csv"
    alike.write_text(
        "kind,id,mass\n" + "".join(f"piston,P{i},400 g\n" for i in range(4)), encoding="utf-8"
    )
    marine = folder / "marine.csv"
    marine.write_text(
        "kind,id,mass\n" + "".join(f"piston,P{i},{5000 + 7 * i * i} kg\n" for i in range(6)),
        encoding="utf-8",
    )
    band = folder / "band.toml"
    band.write_text(FLAT_4, encoding="utf-8")
    dimensions = folder / "dimensions.toml"
    dimensions.write_text(FLAT_4 + 'phase = 0.05\ncrank_radius = "0.02 mm"\n', encoding="utf-8")
    dragonfly = CONFIGS / "abc-dragonfly.toml"
    pistons = DATA / "dragonfly-table-iii-pistons.csv"
    return {
        "match": [
            run("match", engine, "--parts", both),
            run("match", engine, "--parts", both, "--objective", "F1,M1-:2", "--heuristic"),
            run("match", engine, "--parts", rods),
            run("match", engine, "--parts", alike),
            run("match", MAN6, "--parts", marine, "--objective", "F1,M1"),
            run("match", dragonfly, "--parts", pistons, "--objective", "F1"),
        ],
        "tolerance": [
            run("tolerance", band, "--runs", "200"),
            run("tolerance", dimensions, "--runs", "200", "--max-order", "2"),
        ],
        "bobweight": [
            run("bobweight", engine, "--parts", both, "--balance-factor", "0.6"),
            run("bobweight", TODAY / "inline" / "inline-2-360.toml"),
        ],
    }


def test_every_document_is_valid_under_its_schema(documents):
    for name, written in documents.items():
        for document in written:
            assert problem(document, name) is None, (name, problem(document, name))
            version = STEADINESS_VERSION if name == "steadiness" else DOCUMENT_VERSION
            assert document["balance_version"] == version


def _resolve(node, root):
    while "$ref" in node:
        node = root["$defs"][node["$ref"].removeprefix("#/$defs/")]
    return node


def named(node, root, path="$"):
    """Every key path a schema names: ``$.engines[].orders[].force.max_N``."""
    node = _resolve(node, root)
    out = set()
    for branch in node.get("anyOf", []) + [node[k] for k in ("then", "else") if k in node]:
        out |= named(branch, root, path)
    for key, child in node.get("properties", {}).items():
        out.add(f"{path}.{key}")
        out |= named(child, root, f"{path}.{key}")
    if isinstance(node.get("items"), dict):
        out |= named(node["items"], root, f"{path}[]")
    return out


def written_keys(value, path="$"):
    out = set()
    if isinstance(value, dict):
        for key, child in value.items():
            out.add(f"{path}.{key}")
            out |= written_keys(child, f"{path}.{key}")
    elif isinstance(value, list):
        for child in value:
            out |= written_keys(child, f"{path}[]")
    return out


def test_the_runs_write_every_key_of_each_schema(documents):
    """So that no part of a schema goes untried: what it names was written by some run (and
    so checked against it)."""
    for name, written in documents.items():
        root = schema(name)
        seen = set().union(*(written_keys(d) for d in written))
        never = named(root, root) - seen
        assert not never, f"{name}: no run wrote {sorted(never)}"


def test_every_nullable_key_is_written_as_null_and_as_a_value(documents):
    """Numbers vs null: each key a schema lets be null was seen both ways (in one of the places
    that use it, for a part several share), so that neither branch is a guess."""
    # what these runs write one way only, and why the schema still allows the other
    one_way = {
        # a reference engine without a counterweighted resultant: none in the library
        "$.engines[].percent_of_reference",
        "$.engines[].percent_of_reference_absolute",
        # not null from the command line, which always asks for the bearings and an inertia's
        # steadiness; the library's torque(bearings=False) and a constant torque write null
        "$.engines[].crankshafts[].main_bearings",
        "$.steadiness",
        "$.r_c",
        "$.r_v",
        "$.r_h",
        "$.engines[].steadiness.steadiness",
        "$.engines[].steadiness.r_c",
        "$.engines[].steadiness.r_v",
        "$.engines[].steadiness.r_h",
        # a family judges orders 1 and 2, and in-line cranks take counterweights: the nulls
        # of the PRU (as compare writes it) are compare's
        "$.rows[].pru.first_order",
        "$.rows[].pru.first_order.standard",
        "$.rows[].pru.first_order.rotating",
        "$.rows[].M1V_standard_Nm",
        "$.rows[].M1H_standard_Nm",
        "$.rows[].M1V_rotating_Nm",
        "$.rows[].M1H_rotating_Nm",
        # a guide-force moment of no order at all: none in these families
        "$.rows[].h_type",
        "$.rows[].x_type",
        # openTorsion gives the elastic part wherever these runs go
        "$.engines[].response[].free_end_elastic_deg",
        "$.engines[].response[].free_end_orders[].elastic_deg",
        # a row's values are null only where the current document (regression() takes a
        # dict) lacks a key; a relative change from a zero baseline
        "$.rows[].baseline",
        "$.rows[].now",
        "$.rows[].relative_change",
    }
    for name, written in documents.items():
        root = schema(name)
        seen: dict = {}
        for document in written:
            for path, value in _leaves(document):
                seen.setdefault(path, set()).add(value is None)
        places: dict = {}
        for where, path in _nullable(root, root):
            places.setdefault(where, set()).add(path)
        for where, paths in places.items():
            if paths & one_way:
                continue
            # match's engines as assembled are compare's entries, seen both ways in its runs
            if name == "match" and all(".assembled." in p for p in paths):
                continue
            both = set().union(*(seen.get(p, set()) for p in paths))
            assert both == {True, False}, (name, where, sorted(paths), both)


def _nullable(node, root, path="$", where="#"):
    """(schema location, document path) of each key that may be null; a part several keys
    share (``$defs``) has one location."""
    while "$ref" in node:
        where = node["$ref"]
        node = root["$defs"][where.removeprefix("#/$defs/")]
    out = set()
    kinds = node.get("type")
    if (isinstance(kinds, list) and "null" in kinds) or any(
        b.get("type") == "null" for b in node.get("anyOf", [])
    ):
        out.add((where, path))
    for branch in node.get("anyOf", []):
        if branch.get("type") != "null":
            out |= _nullable(branch, root, path, where)
    for key, child in node.get("properties", {}).items():
        out |= _nullable(child, root, f"{path}.{key}", f"{where}/{key}")
    if isinstance(node.get("items"), dict):
        out |= _nullable(node["items"], root, f"{path}[]", f"{where}[]")
    return out


def _leaves(value, path="$"):
    yield path, value
    if isinstance(value, dict):
        for key, child in value.items():
            yield from _leaves(child, f"{path}.{key}")
    elif isinstance(value, list):
        for child in value:
            yield from _leaves(child, f"{path}[]")


#: the list whose entries each document is made of
ENTRIES = {
    "compare": "engines",
    "counterweight": "engines",
    "torque": "engines",
    "torsion": "engines",
    "mounts": "engines",
    "regress": "rows",
    "search": "results",
    "family": "rows",
    "sweep": "points",
    "steadiness": None,
    "match": None,
    "tolerance": "orders",
    "bobweight": "pins",
}


def test_a_key_added_or_dropped_fails_the_schema(documents):
    """Not vacuous: at the top and in an entry, an extra key and each required key missing
    are problems that name the key and where it is."""
    for name, written in documents.items():
        document = next(d for d in written if not ENTRIES[name] or d[ENTRIES[name]])
        if ENTRIES[name]:  # one entry is enough, and quicker to check again and again
            document = {**document, ENTRIES[name]: document[ENTRIES[name]][:1]}
        extra = {**document, "unexpected": 1}
        found = problem(extra, name)
        assert found is not None and found.path == "$"
        assert found.message == "has 'unexpected', which the schema does not define"
        for key in schema(name)["required"]:
            less = {k: v for k, v in document.items() if k != key}
            found = problem(less, name)
            assert found is not None and (found.path, found.message) == ("$", f"lacks {key!r}")
        entries = ENTRIES[name]
        if entries is None:
            continue
        entry = document[entries][0]
        for change, words in (
            (lambda e: e.update(unexpected=1), "has 'unexpected'"),
            (lambda e: e.pop(next(iter(e))), f"lacks {next(iter(entry))!r}"),
        ):
            damaged = copy.deepcopy(document)
            change(damaged[entries][0])
            found = problem(damaged, name)
            assert found is not None and found.path == f"$.{entries}[0]", (name, found)
            assert found.message.startswith(words), (name, found)


def test_a_value_of_the_wrong_kind_fails_the_schema(documents):
    document = copy.deepcopy(documents["compare"][0])
    engine = document["engines"][0]
    for key, value, words in (
        ("speed_rpm", "3000 rpm", 'is "3000 rpm", not a number'),
        ("cylinders", 2.5, "is 2.5, not a whole number"),
        ("frame", "upright", 'is "upright", not one of "fixed", "rotary"'),
        ("sampling_ok", None, "is null, not true or false"),
        ("vertical_deg", 360.0, "is 360.0, not below 360"),
        ("largest_resultant_N", -1.0, "is -1.0, below 0"),
        ("power_kW", math.inf, "is not a finite number (JSON has no NaN, Infinity)"),
    ):
        found = problem({**document, "engines": [{**engine, key: value}]}, "compare")
        assert (found.path, found.message) == (f"$.engines[0].{key}", words)


def test_the_schema_files_are_current_and_valid():
    """balance_cli/schemas holds what tools/json_schemas.py writes (make schemas), each a
    valid Draft 2020-12 schema, one per document and version."""
    from tools import json_schemas

    made = json_schemas.schemas()
    files = {p.name for p in json_schemas.TARGET.glob("*.json")}
    assert files == set(made) == {schema_name(d, v) for d, vs in DOCUMENTS.items() for v in vs}
    for file, content in made.items():
        committed = (json_schemas.TARGET / file).read_text(encoding="utf-8")
        assert committed == json_schemas.render(content), f"{file} is stale: run make schemas"
        Draft202012Validator.check_schema(content)
        assert content["$schema"] == "https://json-schema.org/draft/2020-12/schema"


def test_every_command_that_writes_json_has_a_schema():
    commands = {
        name
        for name, command in main.commands.items()
        for p in command.params
        if p.name == "fmt" and "json" in getattr(p.type, "choices", ())
    }
    assert commands == set(DOCUMENTS)


def test_a_document_or_version_without_a_schema():
    with pytest.raises(KeyError, match="'report' is not a document balance writes"):
        schema("report")
    with pytest.raises(KeyError, match="the sweep document has no version 2"):
        problem({}, "sweep", 2)
