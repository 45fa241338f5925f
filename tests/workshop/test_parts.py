"""Reading a parts file (kind,id,mass): pistons and rods in the file's order, masses in any
unit; every line that cannot be read named with the fix. And the configuration's per-throw
rotating mass, which a matched engine is written with."""

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import ConfigError
from tests.support import TWIN

GOOD = """\
kind,id,mass
piston,A,512.4 g
rod_small,R1,150 g
piston,B,0.5101 kg
rod_big,R1,420 g
rod_small,R2,151 g
rod_big,R2,418.5 g

"""


def parts(tmp_path, text):
    path = tmp_path / "parts.csv"
    path.write_text(text, encoding="utf-8")
    return path


def test_pistons_and_rods_in_the_files_order(tmp_path):
    read = balance.read_parts_csv(parts(tmp_path, GOOD))
    assert [p.id for p in read.pistons] == ["A", "B"]
    assert_allclose([p.mass_kg for p in read.pistons], [0.5124, 0.5101], rtol=1e-12)
    assert [(r.id, r.small_end_kg, r.big_end_kg) for r in read.rods] == [
        ("R1", pytest.approx(0.150), pytest.approx(0.420)),
        ("R2", pytest.approx(0.151), pytest.approx(0.4185)),
    ]
    assert read.kinds == ("pistons", "rods")
    kinds = [r["kind"] for r in read.records()]
    assert kinds == ["piston", "piston", "rod_small", "rod_big", "rod_small", "rod_big"]


@pytest.mark.parametrize(
    "text, words",
    [
        ("kind,id,mass,note\npiston,A,1 g,x\n", "line 1: the header is 'kind,id,mass,note'"),
        ("kind,id\n", "line 1: the header is 'kind,id'"),
        ("kind,id,mass\npistn,A,1 g\n", "line 2: kind 'pistn' is not one of piston, rod_small"),
        ("kind,id,mass\npiston,A,500\n", "line 2: mass:"),
        ("kind,id,mass\npiston,A,1 g,extra\n", "line 2: has 4 columns"),
        ("kind,id,mass\npiston,,1 g\n", "line 2: has no id"),
        ("kind,id,mass\npiston,A,0 g\n", "line 2: mass '0 g' must be greater than zero"),
        ("kind,id,mass\npiston,A,1 g\npiston,A,2 g\n", "line 3: piston 'A' is given twice"),
        ("kind,id,mass\nrod_small,R,1 g\n", "line 2: rod 'R' has no rod_big row"),
        (
            "kind,id,mass\nrod_big,R,1 g\nrod_small,R,1 g\nrod_big,R,2 g\n",
            "line 4: the rod_big of rod 'R' is given twice",
        ),
        ("kind,id,mass\n", "lists no part"),
        ("", "is empty; give a header kind,id,mass"),
    ],
)
def test_a_line_that_cannot_be_read_is_named(tmp_path, text, words):
    path = parts(tmp_path, text)
    with pytest.raises(ConfigError) as caught:
        balance.read_parts_csv(path)
    message = str(caught.value)
    assert message.startswith(str(path)) and words in message and "\n" not in message


def test_a_throws_own_rotating_mass_overrides_the_engines(tmp_path):
    """[[throws]] rotating: that pin's big ends; the first-order forward force of a 180° twin
    with 400 g and 420 g at its pins is (420 − 400) g·r·ω² (they pull opposite ways)."""
    text = TWIN.replace('reciprocating = "500 g"', 'reciprocating = "500 g"\nrotating = "400 g"')
    text = text.replace('phase = 180\nz = "90 mm"', 'phase = 180\nz = "90 mm"\nrotating = "420 g"')
    engine = balance.loads(text, "twin.toml")
    assert engine.rotating_of(0) == 0.4 and engine.rotating_of(1) == 0.42
    forward = balance.analyse(engine).order(1).force_forward
    omega = 3000 * 3.141592653589793 / 30
    assert_allclose(abs(forward), 0.02 * 0.040 * omega**2, rtol=1e-9)  # an FFT's first order
    edited = engine.edit(throw=1, rotating="420 g")
    assert edited.rotating_of(0) == pytest.approx(0.42)
    with pytest.raises(ConfigError, match=r"throws\[2\]\.rotating: must not be negative"):
        balance.loads(text.replace('rotating = "420 g"', 'rotating = "-1 g"'), "t.toml")
