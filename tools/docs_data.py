"""Write the data files the documentation's how-to pages run their commands on.

Usage: python tools/docs_data.py [--check]   (--check: fail if a file would change)

- docs/data/pressure-4stroke.csv: a cylinder pressure curve as a measured one would be given
  (`balance torque --pressure`): the ABC Dragonfly's own [gas] cycle, absolute pressure in bar
  every degree over its 720° cycle from the firing top dead centre.
- docs/data/torque-dragonfly.csv: a torque curve (`balance steadiness --torque`): the
  Dragonfly's total torque at 1650 rpm (gas and inertia), N·m every 2° over 720°.

Both are computed with balance's own API, so they are what the library gives today; the pages
say where they come from.

- docs/data/workshop-inline-4.toml and workshop-inline-4-parts.csv: the workshop's example
  (`balance match`, `tolerance`, `bobweight`): an in-line 4 with a [tolerances] table, and four
  pistons and four rods weighed for it; written from the text below.
"""

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import balance_cli as balance  # noqa: E402
from balance_cli.analysis.gas import gas_load  # noqa: E402

DATA = ROOT / "docs" / "data"
DRAGONFLY = ROOT / "configs" / "abc-dragonfly.toml"


def pressure_csv(engine):
    """Cylinder 1's [gas] cycle, bar, every degree from its firing TDC."""
    curve = gas_load(engine, 256).curves[1]
    angles = np.arange(0, int(curve.cycle_deg))
    bar = curve.at(angles) / 1e5
    return "angle_deg,pressure_bar\n" + "".join(
        f"{a},{p:.4f}\n" for a, p in zip(angles, bar, strict=True)
    )


def torque_csv(engine):
    """The engine's total torque over its cycle, N·m, every 2° of throw 1's crank angle."""
    total = balance.torque(engine, bearings=False, guide=False).total
    angles = np.arange(0, int(engine.cycle_deg), 2)
    values = np.interp(angles, total.theta_deg, total.curve, period=engine.cycle_deg)
    return "angle_deg,torque_Nm\n" + "".join(
        f"{a},{t:.2f}\n" for a, t in zip(angles, values, strict=True)
    )


#: the workshop's example engine: the library's in-line 4 of car proportions with a rotating
#: mass per pin and the tolerance band of its production
WORKSHOP_ENGINE = """\
# An in-line 4 of car proportions (the library's inline-4-car, with a rotating mass per
# pin) and the tolerance band of its production: the workshop's how-to and tutorials match
# weighed parts to it (docs/data/workshop-inline-4-parts.csv) and draw runs from its band.
name = "In-line 4, car proportions"
cycle = 4
speed = "6000 rpm"
crank_radius = "43 mm"
rod_length = "143 mm"
firing_order = [1, 3, 4, 2]

[masses]
reciprocating = "550 g"   # piston, pin, rings and clips with the rod's small end
rotating = "560 g"        # the rod's big end

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 180
z = "88 mm"
[[throws]]
phase = 180
z = "176 mm"
[[throws]]
phase = 0
z = "264 mm"

[tolerances]               # one standard deviation of each scatter
reciprocating = "2 g"
rotating = "3 g"
crank_radius = "0.02 mm"
rod_length = "0.03 mm"
phase = 0.05
"""
#: four pistons and four rods weighed for it (kind,id,mass)
WORKSHOP_PARTS = """\
kind,id,mass
piston,P1,402.3 g
piston,P2,398.1 g
piston,P3,405.0 g
piston,P4,400.2 g
rod_small,R1,151.0 g
rod_big,R1,412.0 g
rod_small,R2,148.2 g
rod_big,R2,405.5 g
rod_small,R3,150.1 g
rod_big,R3,409.9 g
rod_small,R4,149.0 g
rod_big,R4,415.3 g
"""


def main(check=False):
    engine = balance.load(DRAGONFLY)
    files = {
        DATA / "pressure-4stroke.csv": pressure_csv(engine),
        DATA / "torque-dragonfly.csv": torque_csv(engine),
        DATA / "workshop-inline-4.toml": WORKSHOP_ENGINE,
        DATA / "workshop-inline-4-parts.csv": WORKSHOP_PARTS,
    }
    stale = [p for p, text in files.items() if not p.exists() or p.read_text() != text]
    if check:
        for path in stale:
            print(f"{path.relative_to(ROOT)} is out of date: run python tools/docs_data.py")
        return 1 if stale else 0
    DATA.mkdir(exist_ok=True)
    for path, text in files.items():
        path.write_text(text, encoding="utf-8")
        print(f"wrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(check="--check" in sys.argv[1:]))
