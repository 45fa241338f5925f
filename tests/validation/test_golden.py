"""CI regression tables: the whole library against tests/golden/compare.json, checked by
`balance regress` itself (one implementation for the project and its users).

Tolerances (balance_cli.studies.regress): 1e-9 of each engine's m_rec·r·ω²·n for forces and moments
(rounding differs between machines far below that), 1e-6° for phases of phasors above 1e-6 of
it, 1e-4° for firing angles (the TDC search is good to about 2e-6°).
`make regress-update` rewrites the file after an intended change.
"""

import copy
import json

from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.studies.regress import regression as regress
from tests.support import ROOT

GOLDEN = ROOT / "tests" / "golden" / "compare.json"


def test_library_matches_golden_tables(monkeypatch):
    monkeypatch.chdir(ROOT)  # the golden file names its configurations from the repository root
    result = CliRunner().invoke(main, ["regress", "tests/golden/compare.json", "configs"])
    assert result.exit_code == 0, (
        "golden tables moved (make regress-update if intended):\n" + result.output
    )
    # every engine of the library is checked (counted, not written down: the library grows)
    library = len(balance.find_configs([ROOT / "configs"]))
    assert len(json.loads(GOLDEN.read_text(encoding="utf-8"))["engines"]) == library
    assert f"nothing moved beyond tolerance ({library} engines checked" in result.stdout


def test_a_moved_value_is_reported_by_engine_order_and_quantity():
    golden = json.loads(GOLDEN.read_text(encoding="utf-8"))
    changed = copy.deepcopy(golden)
    engine = changed["engines"][0]
    engine["orders"][1]["force"]["max_N"] *= 1.001
    engine["firing"]["order"] = engine["firing"]["order"][::-1]
    rows = regress(golden, changed).rows
    assert {(r.engine, r.order, r.quantity) for r in rows} == {
        (engine["name"], 2, "force.max_N"),
        (engine["name"], None, "firing order"),
    }
    # rounding noise far below the tolerance is not reported
    quiet = copy.deepcopy(golden)
    quiet["engines"][0]["orders"][1]["force"]["max_N"] *= 1 + 1e-13
    assert not regress(golden, quiet).moved
