"""`make bench`: time balance's commands on the whole library against importing their libraries.

Each command runs beside its baseline in the same session, alternately, after a warm-up; the
ratio of the medians is what counts, so the machine's speed cancels out.

- ``balance compare configs --format json`` against importing numpy, click and tabulate
  (target: at most 2.5)
- ``balance torque configs --format json`` against the same (target: at most 2.5)
- ``balance report configs --html`` against importing those and matplotlib.pyplot, which
  every drawing command needs (target: at most 4)
"""

import compileall
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BALANCE = str(Path(sys.executable).parent / "balance")


def benchmarks(folder):
    return [
        ("balance compare configs --format json", [BALANCE, "compare", "configs", "--format", "json"],
         'python -c "import numpy, click, tabulate"',
         [sys.executable, "-c", "import numpy, click, tabulate"], 2.5, 15),
        ("balance torque configs --format json", [BALANCE, "torque", "configs", "--format", "json"],
         'python -c "import numpy, click, tabulate"',
         [sys.executable, "-c", "import numpy, click, tabulate"], 2.5, 15),
        ("balance report configs --html", [BALANCE, "report", "configs", "--html", "-o", folder],
         'python -c "import numpy, click, tabulate, matplotlib.pyplot"',
         [sys.executable, "-c", "import numpy, click, tabulate, matplotlib.pyplot"], 4.0, 5),
    ]


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    # byte-compile balance first, as installing numpy compiled numpy: with
    # PYTHONDONTWRITEBYTECODE set (as on this project's machines) every run would otherwise
    # recompile the package's sources and time the compiler, not balance
    compileall.compile_dir(str(ROOT / "balance_cli"), quiet=1)
    failed = False
    with tempfile.TemporaryDirectory() as folder:
        for name, command, base_name, baseline, target, runs in benchmarks(folder + "/report"):
            timed(command)
            timed(baseline)
            ours, theirs = [], []
            for _ in range(runs):
                ours.append(timed(command))
                theirs.append(timed(baseline))
            a, b = statistics.median(ours), statistics.median(theirs)
            ratio = a / b
            verdict = "ok" if ratio <= target else "TOO SLOW"
            print(f"{a * 1000:8.1f} ms  median of {runs}  {name}")
            print(f"{b * 1000:8.1f} ms  median of {runs}  {base_name}")
            print(f"ratio {ratio:.2f} (target at most {target}): {verdict}\n")
            failed |= ratio > target
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
