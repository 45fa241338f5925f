"""How often an analysis closes an engine's linkage: `python tools/closures.py` (and `make bench`).

Closing the linkage (``balance_cli.kinematics.linkage.close_linkage``) is the costly step of
every analysis; the kinematic state closes it once per engine and sampling grid. Each count is
taken in a fresh process, so that nothing is already kept:

- the Mendes et al. (2008) six-cylinder diesel
  (tests/validation/reference/opentorsion_ice/mendes2008.toml) with a parametric [gas] cycle:
  ``balance.torque`` (the state, the fine grid of the gas cycle, and one virtual shift of each
  of the six crank pins: 8) and ``balance.torsional_vibration`` (the state and the fine
  grid: 2);
- the Junkers Jumo 205 (twelve throws on two crankshafts, opposed pistons, [gas]):
  ``balance.torque`` (the state, four for the inner dead centres, the fine grid, and twelve pins).
"""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GAS = '\n[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "15 bar"\n'
CASES = [
    (
        "Mendes diesel with [gas]",
        "tests/validation/reference/opentorsion_ice/mendes2008.toml",
        GAS,
        "torque",
    ),
    (
        "Mendes diesel with [gas]",
        "tests/validation/reference/opentorsion_ice/mendes2008.toml",
        GAS,
        "torsional_vibration",
    ),
    ("Jumo 205", "configs/today/opposed-piston/junkers-jumo-205.toml", "", "torque"),
]

# counts the calls of close_linkage while one analysis runs (every closing goes through it)
PROBE = """
import sys
from pathlib import Path
import balance_cli as balance
from balance_cli.kinematics import linkage

engine = balance.loads(Path(sys.argv[1]).read_text(encoding="utf-8") + sys.argv[2], sys.argv[1])
closed = linkage.close_linkage
count = 0

def counting(*args, **kwargs):
    global count
    count += 1
    return closed(*args, **kwargs)

linkage.close_linkage = counting
getattr(balance, sys.argv[3])(engine)
print(count)
"""


def count(path, extra, call):
    """Closings of the linkage by ``balance.<call>(engine)`` in a fresh process."""
    done = subprocess.run(
        [sys.executable, "-c", PROBE, str(ROOT / path), extra, call],
        cwd=ROOT,
        check=True,
        capture_output=True,
        text=True,
    )
    return int(done.stdout.split()[-1])


def main():
    for name, path, extra, call in CASES:
        print(f"{count(path, extra, call):4d}  closings of the linkage by {call}() of the {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
