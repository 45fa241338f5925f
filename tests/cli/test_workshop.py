"""balance match, balance tolerance and balance bobweight: their tables, JSON, CSV, --write and
--plot, and every error as one line with nothing written."""

import json

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from tests.support import CONFIGS, TODAY, check_refused, invoke, snapshot
from tests.workshop.test_match import INLINE_4, PARTS_CSV
from tests.workshop.test_tolerance import FLAT_4


@pytest.fixture
def shop(tmp_path):
    """A folder with an in-line 4, its weighed parts and a flat in-line 4 with a band."""
    (tmp_path / "engine.toml").write_text(INLINE_4, encoding="utf-8")
    (tmp_path / "parts.csv").write_text(PARTS_CSV, encoding="utf-8")
    (tmp_path / "band.toml").write_text(FLAT_4, encoding="utf-8")
    return tmp_path


def test_match_prints_the_assignment_and_writes_the_engine_as_matched(shop):
    written = shop / "matched.toml"
    result = invoke(
        "match", shop / "engine.toml", "--parts", shop / "parts.csv", "--write", written
    )
    assert result.exit_code == 0, result.output
    out = result.stdout
    assert "exhaustive: 288 of 576 assignments evaluated" in out
    assert "Assignment (matched, and the parts in the order given)" in out
    assert "The engine as assembled, as compare analyses it" in out
    matched = balance.load(written)
    assert matched.name == "In-line 4, as matched"
    api = balance.match(balance.load(shop / "engine.toml"), shop / "parts.csv")
    assert [c.reciprocating_kg for c in matched.cylinders] == pytest.approx(
        [c.reciprocating_kg for c in api.best.engine.cylinders], rel=1e-11
    )
    # the written file compares beside the original: a name of its own
    both = invoke("compare", shop / "engine.toml", written)
    assert both.exit_code == 0, both.output


def test_match_json_and_csv(shop):
    result = invoke(
        "match", shop / "engine.toml", "--parts", shop / "parts.csv", "--format", "json"
    )
    document = json.loads(result.stdout)
    assert document["method"] == "exhaustive" and document["assignments_total"] == 576
    assert document["best"]["assembled"]["name"] == "In-line 4, as matched"
    assert document["gain_N"] == pytest.approx(
        document["given"]["score_N"] - document["best"]["score_N"]
    )
    csv = invoke("match", shop / "engine.toml", "--parts", shop / "parts.csv", "--format", "csv")
    lines = csv.stdout.splitlines()
    assert lines[0] == "fitting,cylinder,throw,piston,rod,reciprocating_kg,rotating_kg"
    assert len(lines) == 1 + 8


def test_tolerance_prints_the_spread_and_draws_it(shop):
    picture = shop / "spread.png"
    result = invoke("tolerance", shop / "band.toml", "--runs", "500", "--plot", picture)
    assert result.exit_code == 0, result.output
    assert "500 runs (seed 0), one standard deviation of reciprocating 2 g" in result.stdout
    assert "Free force by order (N)" in result.stdout
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    document = json.loads(
        invoke("tolerance", shop / "band.toml", "--runs", "500", "--format", "json").stdout
    )
    assert document["runs"] == 500 and document["method"] == "masses"
    assert document["tolerances"]["reciprocating_kg"] == 0.002
    first = document["orders"][0]["force"]["vertical"]
    assert first["linear"]["model"] == "zero-mean"
    assert_allclose(first["linear"]["mean_N"], 54.1786582, rtol=1e-6)  # 2σ√(2/π)·r·ω², by hand


def test_bobweight_prints_the_sheet(shop):
    v8 = shop / "v8.toml"
    v8.write_text(
        (TODAY / "v" / "v8-90-cross-plane.toml")
        .read_text(encoding="utf-8")
        .replace('reciprocating = "0.75 kg"', 'reciprocating = "0.75 kg"\nrotating = "1.1 kg"'),
        encoding="utf-8",
    )
    result = invoke("bobweight", v8)
    assert result.exit_code == 0, result.output
    rows = [line.split() for line in result.stdout.splitlines() if line[:1] and line[0] in "1234"]
    assert [row[-1] for row in rows] == ["1850"] * 4  # 1.1 kg + ½·2·0.75 kg
    twin = invoke(
        "bobweight",
        TODAY / "inline" / "inline-2-360.toml",
        "--factors",
        "0.5,0.85",
        "--format",
        "json",
    )
    document = json.loads(twin.stdout)
    assert [t["factor"] for t in document["trade"]] == [0.5, 0.85]


@pytest.mark.parametrize(
    "args, words",
    [
        (["match", "{engine}", "--parts", "{bad}"], "bad.csv: line 2: kind 'pistn'"),
        (["match", "{engine}", "--parts", "{parts}", "--objective", "X2"], "--objective term X2"),
        (
            ["match", "{engine}", "--parts", "{parts}", "--limit", "10", "--write", "{engine}"],
            "is an input file",
        ),
        (["match", "{engine}", "--parts", "{parts}", "--write", "-"], "--write"),
        (["match", CONFIGS / "abc-dragonfly.toml", "--parts", "{parts}"], "--parts lists 4"),
        (["tolerance", "{engine}"], "[tolerances] are not given"),
        (["tolerance", "{band}", "--runs", "1"], "--runs must"),
        (["tolerance", "{band}", "--plot", "{folder}/x.txt"], "has '.txt'"),
        (["bobweight", CONFIGS / "clerget-rotary.toml"], "rotary"),
        (["bobweight", "{engine}", "--balance-factor", "2"], "--balance-factor must be a fraction"),
        (["bobweight", "{engine}", "--factors", "0.5,x"], "--factors"),
    ],
)
def test_errors_are_one_line_and_write_nothing(shop, args, words):
    (shop / "bad.csv").write_text("kind,id,mass\npistn,A,1 g\n", encoding="utf-8")
    names = {
        "{engine}": shop / "engine.toml",
        "{parts}": shop / "parts.csv",
        "{bad}": shop / "bad.csv",
        "{band}": shop / "band.toml",
    }
    filled = []
    for a in args:
        text = str(a)
        for key, value in names.items():
            text = text.replace(key, str(value))
        filled.append(text.replace("{folder}", str(shop)))
    before = snapshot(shop)
    result = invoke(*filled)
    code = 2 if "--write" in words or "--factors" in words else 1
    check_refused(result, code, words, before, shop)
