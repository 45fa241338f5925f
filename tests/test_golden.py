"""CI regression tables: the whole library's comparison against tests/golden/compare.json.

On a difference the failure lists which engine, order and quantity moved and by how much.
Tolerance: 1e-9 of each engine's m_rec·r·ω²·n for forces and moments (rounding differs
between machines far below that), 1e-6° for phases of phasors above 1e-6 of it, 1e-4° for
firing angles (the TDC search is good to about 2e-6°).
`make regress-update` rewrites the file after an intended change.
"""

import copy
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))

import regress  # noqa: E402


def test_library_matches_golden_tables():
    golden = json.loads(regress.GOLDEN.read_text(encoding="utf-8"))
    moved = regress.differences(golden, regress.current())
    assert not moved, "golden tables moved (make regress-update if intended):\n" + "\n".join(moved)


def test_a_moved_value_is_reported_by_engine_order_and_quantity():
    golden = json.loads(regress.GOLDEN.read_text(encoding="utf-8"))
    changed = copy.deepcopy(golden)
    engine = changed["engines"][0]
    engine["orders"][1]["force"]["max_N"] *= 1.001
    engine["firing"]["order"] = engine["firing"]["order"][::-1]
    moved = regress.differences(golden, changed)
    assert any(line.startswith(f"{engine['name']} order 2.force.max_N:") for line in moved)
    assert any(".firing.order" in line for line in moved)
    # rounding noise far below the tolerance is not reported
    quiet = copy.deepcopy(golden)
    quiet["engines"][0]["orders"][1]["force"]["max_N"] *= 1 + 1e-13
    assert regress.differences(golden, quiet) == []
