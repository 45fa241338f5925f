"""`make bench`: time `balance compare configs --format json` against importing its libraries.

Both commands run in the same session, alternately, after a warm-up; the ratio of the
medians is what counts (target: at most 2.5), so the machine's speed cancels out.
"""

import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BALANCE = Path(sys.executable).parent / "balance"
TARGET = 2.5
RUNS = 15

COMMANDS = {
    "balance compare configs --format json": [str(BALANCE), "compare", "configs", "--format", "json"],
    'python -c "import numpy, click, tabulate"': [sys.executable, "-c", "import numpy, click, tabulate"],
}


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    for command in COMMANDS.values():
        timed(command)
    times = {name: [] for name in COMMANDS}
    for _ in range(RUNS):
        for name, command in COMMANDS.items():
            times[name].append(timed(command))
    medians = {name: statistics.median(t) for name, t in times.items()}
    for name, median in medians.items():
        print(f"{median * 1000:8.1f} ms  median of {RUNS}  {name}")
    compare, baseline = medians.values()
    ratio = compare / baseline
    verdict = "ok" if ratio <= TARGET else "TOO SLOW"
    print(f"ratio {ratio:.2f} (target at most {TARGET}): {verdict}")
    return 0 if ratio <= TARGET else 1


if __name__ == "__main__":
    sys.exit(main())
