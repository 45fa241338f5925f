"""`make bench`: time balance's commands on the whole library against importing their libraries.

Each command runs beside its baseline in the same session, alternately, after a warm-up; the
ratio of the medians is what counts, so the machine's speed cancels out.

- ``balance compare configs --format json`` against importing numpy, click and tabulate
- ``balance torque configs --format json`` against the same
- ``balance report configs --html`` against importing those and matplotlib.pyplot, which
  every drawing command needs

  The library grows (21 engines when these targets were set, 50 now), so each is judged per
  engine: (command − baseline) / baseline / engines, at most what the first targets allowed
  at 21 engines: (2.5 − 1)/21 = 0.071 for compare and torque, (4 − 1)/21 = 0.143 for the
  report; the whole-library ratio is printed beside it.
- ``balance search templates/inline-12-2stroke.toml --objective M1,M2,M3,M4``: the exhaustive
  search of 19 958 400 distinct arrangements (target: under 5 s on two cores), beside a
  straightforward vectorised enumeration of every permutation of an in-line 10 (9! crank
  orders, scored the same way, no symmetry, no bounds); both print arrangements per second,
  and the ratio of the rates is the search's speed-up
- ``balance search`` of an in-line 14 two-stroke (the in-line 12 template at the same pitch,
  14 throws: 13!/4 ≈ 1.6e9 cranks to cover), ``--objective M1,M2,M3,M4``, beside the in-line
  12 in the same run: wall time and peak resident memory of the whole process tree (read
  from /proc while it runs: each process's high-water mark, and their sum), with the time of
  N = 10 to 14 and the growth from one to the next (target: the in-line 14 under 30 s and
  1 GB on two cores)
- ``balance family configs/marine-6-2stroke.toml --cylinders 5-12`` and ``5-14``: the
  project-guide table, every row searched exhaustively (target: under a minute on two
  cores)
- the search on a Dask LocalCluster of two worker processes (with distributed installed):
  the in-line 13's pieces and cranks a second per core, and what they make of an in-line 16
  and of a four-stroke V20 on a grid of 18° on 64 cores
- ``balance.torsion`` of a six-throw model
  (tests/validation/reference/opentorsion_ice/mendes2008.toml with a [gas] cycle): modes and
  the forced response at 100 speeds, orders ½ to 12, in one process (target: well under a
  second; at most 0.5 s)
- ``balance.mounts`` of configs/mounts/four-mount-coupled.toml: modes, axes, static
  deflections and the forced response at 100 speeds, orders ½ to 12 (24 orders), in one
  process (target: well under a second; at most 0.3 s)
- ``balance animate`` of a radial with link rods, a rotary, the cross-plane V8, the BRM H16 (two
  crankshafts) and the Jumo 205 (opposed pistons): each one's GIF at default settings and its
  HTML page, the time to write each and its size; the whole command for the V8's GIF (median
  of 3, start-up included) under 5 s, and every GIF under 2 MB
- ``balance.tolerance`` of the library's cross-plane V8 with every part and dimension of its
  ``[tolerances]`` scattered: 10 000 runs, each its own exact linkage (target: under 2 s), beside
  one ``balance.analyse`` of the same engine (the ratio says how many single analyses the
  10 000 runs cost)
- how often ``torque`` and ``torsional_vibration`` close the linkage (tools/closures.py)

``make bench BASE=/path/to/another/checkout`` (one with its own ``.venv``, as ``make setup``
builds it) also times that checkout's compare and torque of this library beside this one's,
alternately, and prints the ratio this/that: a change's effect measured in one run.
"""

import compileall
import itertools
import json
import math
import os
import re
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
        (
            "balance compare configs --format json",
            [BALANCE, "compare", "configs", "--format", "json"],
            'python -c "import numpy, click, tabulate"',
            [sys.executable, "-c", "import numpy, click, tabulate"],
            1.5 / 21,
            15,
        ),
        (
            "balance torque configs --format json",
            [BALANCE, "torque", "configs", "--format", "json"],
            'python -c "import numpy, click, tabulate"',
            [sys.executable, "-c", "import numpy, click, tabulate"],
            1.5 / 21,
            15,
        ),
        (
            "balance report configs --html",
            [BALANCE, "report", "configs", "--html", "-o", folder],
            'python -c "import numpy, click, tabulate, matplotlib.pyplot"',
            [sys.executable, "-c", "import numpy, click, tabulate, matplotlib.pyplot"],
            3.0 / 21,
            5,
        ),
    ]


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def _without_provenance(folder):
    """A copy of the library in ``folder`` without the ``sources`` and ``estimates`` keys
    (0.3.0): a checkout from before them refuses them, and they change no figure."""
    for path in (ROOT / "configs").rglob("*.toml"):
        target = Path(folder) / path.relative_to(ROOT)
        target.parent.mkdir(parents=True, exist_ok=True)
        kept, skipping = [], False
        for line in path.read_text(encoding="utf-8").splitlines(keepends=True):
            if not skipping and re.match(r"(sources|estimates) = \[", line):
                skipping = not line.rstrip().endswith("]")
                continue
            if skipping:
                skipping = line.strip() != "]"
                continue
            kept.append(line)
        target.write_text("".join(kept), encoding="utf-8")
    return str(Path(folder) / "configs")


def against(base, runs=15):
    """This checkout's compare and torque of the library beside another checkout's (``base``,
    with its own .venv), alternately, on the same files: the ratio of the medians,
    this/that."""
    other = str(Path(base).resolve() / ".venv" / "bin" / "balance")
    library = _without_provenance(tempfile.mkdtemp())
    for verb in ("compare", "torque"):
        ours_cmd = [BALANCE, verb, library, "--format", "json"]
        theirs_cmd = [other, verb, library, "--format", "json"]
        timed(ours_cmd)
        timed(theirs_cmd)
        ours, theirs = [], []
        for _ in range(runs):
            ours.append(timed(ours_cmd))
            theirs.append(timed(theirs_cmd))
        a, b = statistics.median(ours), statistics.median(theirs)
        print(f"{a * 1000:8.1f} ms  median of {runs}  balance {verb} configs (this checkout)")
        print(f"{b * 1000:8.1f} ms  median of {runs}  balance {verb} configs ({base})")
        print(f"ratio this/that {a / b:.3f}\n")


def naive_rate(n=10, objective_orders=(1, 2, 3, 4)):
    """Arrangements per second of the straightforward enumeration: every permutation of the
    phases of throws 2..n, the in-line moments M1..M4 as phasor sums, all at once in blocks."""
    import numpy as np

    lever = np.arange(n) - (n - 1) / 2
    start = time.perf_counter()
    count = 0
    perms = itertools.permutations(range(1, n))
    while True:
        block = np.array(list(itertools.islice(perms, 200_000)), dtype=np.int8)
        if not len(block):
            break
        phases = np.hstack([np.zeros((len(block), 1)), block]) * (2 * np.pi / n)
        score = sum(np.abs((lever * np.exp(1j * k * phases)).sum(axis=1)) for k in objective_orders)
        best = score.min()
        count += len(block)
    del best
    return count / (time.perf_counter() - start)


def median_run(command, runs=3):
    """(wall time, JSON document) of the median of ``runs`` runs of a command writing JSON."""
    results = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(command, cwd=ROOT, check=True, capture_output=True, text=True)
        results.append((time.perf_counter() - start, json.loads(done.stdout)))
    return sorted(results, key=lambda r: r[0])[runs // 2]


def search_bench():
    command = [
        BALANCE,
        "search",
        "templates/inline-12-2stroke.toml",
        "--objective",
        "M1,M2,M3,M4",
        "--format",
        "json",
    ]
    timed(command)
    wall, document = median_run(command)
    total = document["arrangements_total"]
    rate = total / wall
    naive = statistics.median(naive_rate() for _ in range(3))
    verdict = "ok" if wall < 5.0 else "TOO SLOW"
    print(
        f"{wall * 1000:8.1f} ms  median of 3  balance search templates/inline-12-2stroke.toml "
        f"--objective M1,M2,M3,M4 ({document['workers']} workers)"
    )
    print(
        f"          {total:,} arrangements ({document['arrangements_distinct']:,} distinct), "
        f"{document['evaluated']:,} evaluated, {document['pruned']:,} skipped by bound: "
        f"{rate:,.0f} arrangements/s"
    )
    print(
        f"          straightforward enumeration (in-line 10, every permutation): "
        f"{naive:,.0f} arrangements/s, so {total / naive:.0f} s for the in-line 12"
    )
    print(f"speed-up {rate / naive:.1f}; whole search {wall:.2f} s (target under 5 s): {verdict}\n")
    return wall >= 5.0


def family_bench():
    """The marine family table for 5 to 12 and 5 to 14 cylinders: every row searched
    exhaustively (target: under a minute on two cores)."""
    failed = False
    for counts, runs in (("5-12", 3), ("5-14", 1)):
        command = [
            BALANCE,
            "family",
            "configs/marine-6-2stroke.toml",
            "--cylinders",
            counts,
            "--format",
            "json",
        ]
        wall, document = median_run(command, runs)
        methods = {row["method"] for row in document["rows"]}
        verdict = "ok" if wall < 60.0 and methods == {"exhaustive"} else "TOO SLOW"
        print(
            f"{wall * 1000:8.1f} ms  median of {runs}  balance family "
            f"configs/marine-6-2stroke.toml --cylinders {counts} "
            f"({', '.join(sorted(methods))}; load {load()})"
        )
        print(
            f"family table of {len(document['rows'])} cylinder numbers in {wall:.2f} s (target "
            f"under 60 s, every row exhaustive): {verdict}\n"
        )
        failed |= verdict != "ok"
    return failed


def load():
    """The machine's load averages (1, 5 and 15 minutes), as uptime prints them."""
    try:
        return ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "unknown"


def _tree(pid):
    """The process ``pid`` and its descendants, as Linux lists them."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        try:
            with open(f"/proc/{p}/task/{p}/children", encoding="ascii") as f:
                todo += [int(c) for c in f.read().split()]
        except OSError:
            pass
    return out


def _memory_kb(pid):
    """(resident now, high-water mark) of a process, kB (0, 0 once it has gone)."""
    values = {}
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as f:
            for line in f:
                key, _, rest = line.partition(":")
                if key in ("VmRSS", "VmHWM"):
                    values[key] = int(rest.split()[0])
    except OSError:
        pass
    return values.get("VmRSS", 0), values.get("VmHWM", 0)


def measured(command):
    """(wall s, JSON document, peaks) of one run of ``command``; peaks: each process's
    high-water mark (kB, by pid, read from /proc every 20 ms while it runs) and the largest
    sum of the tree's resident memory seen at one moment. Linux only; elsewhere the peaks are
    empty."""
    start = time.perf_counter()
    process = subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True
    )
    peaks: dict = {}
    together = 0
    chunks = []
    import threading

    reader = threading.Thread(target=lambda: chunks.append(process.stdout.read()))
    reader.start()
    while process.poll() is None:
        now = 0
        for pid in _tree(process.pid):
            rss, hwm = _memory_kb(pid)
            now += rss
            peaks[pid] = max(peaks.get(pid, 0), hwm)
        together = max(together, now)
        time.sleep(0.02)
    reader.join()
    wall = time.perf_counter() - start
    if process.returncode:
        raise subprocess.CalledProcessError(process.returncode, command)
    return wall, json.loads("".join(chunks)), {"processes": peaks, "together": together}


def _inline_template(n, folder):
    """templates/inline-12-2stroke.toml with ``n`` throws at its pitch, written in ``folder``."""
    text = (ROOT / "templates" / "inline-12-2stroke.toml").read_text(encoding="utf-8")
    head = text.split("[[throws]]")[0].replace("In-line 12", f"In-line {n}")
    path = Path(folder) / f"inline-{n}-2stroke.toml"
    path.write_text(
        head + "".join(f'[[throws]]\nz = "{500 * j} mm"\n\n' for j in range(n)), encoding="utf-8"
    )
    return str(path)


def scale_bench():
    """The in-line 14's exhaustive search beside the in-line 12's, time and peak memory, and
    how the time grows from N = 10 to 14 (targets: 30 s and 1 GB for the 14 on two cores)."""
    times, together = {}, {}
    with tempfile.TemporaryDirectory() as folder:
        for n in (10, 11, 12, 13, 14):
            command = [
                BALANCE,
                "search",
                _inline_template(n, folder),
                "--objective",
                "M1,M2,M3,M4",
                "--format",
                "json",
                "--limit",
                str(10**12),
            ]
            runs = 3 if n in (12, 14) else 1
            results = sorted((measured(command) for _ in range(runs)), key=lambda r: r[0])
            wall, document, peaks = results[runs // 2]
            times[n] = wall
            together[n] = peaks["together"] / 1024
            largest = max(peaks["processes"].values(), default=0) / 1024
            each = ", ".join(f"{v / 1024:.0f}" for v in sorted(peaks["processes"].values()))
            cover = document["evaluated"] + document["pruned"]
            print(
                f"{wall * 1000:8.1f} ms  median of {runs}  in-line {n} two-stroke, M1,M2,M3,M4: "
                f"{cover:,} cranks covered, {document['evaluated']:,} scored "
                f"({document['workers']} workers; load {load()})"
            )
            if peaks["processes"]:
                print(
                    f"          peak resident memory: {largest:.0f} MB the largest process, "
                    f"{peaks['together'] / 1024:.0f} MB the tree at once (each process's "
                    f"peak, MB: {each})"
                )
    growth = ", ".join(f"{n}→{n + 1}: ×{times[n + 1] / times[n]:.1f}" for n in range(10, 14))
    # the growth from one cylinder to the next rises (the enumeration grows N-fold, the
    # bound prunes a little more each time): extrapolated from the last two steps
    step = times[14] / times[13]
    rise = step / (times[13] / times[12])
    # t15 = t14·step·rise, t16 = t15·step·rise²
    sixteen = times[14] * step**2 * rise**3
    # start-up (about 0.3 s) dominates N ≤ 13, so this understates: a rough lower figure
    print(
        f"growth of the time with N: {growth}; N = 16 projected: at least about "
        f"{sixteen:.0f} s (start-up dominates the smaller N)"
    )
    fast = times[14] <= 30.0
    small = together[14] <= 1024.0
    print(
        f"in-line 14 exhaustive in {times[14]:.1f} s and {together[14]:.0f} MB (targets at "
        f"most 30 s and 1 GB), in-line 12 {times[12]:.2f} s and {together[12]:.0f} MB: "
        f"{'ok' if fast and small else 'TOO SLOW' if not fast else 'TOO LARGE'}\n"
    )
    return not (fast and small)


def cluster_bench():
    """The search on a LocalCluster of two worker processes: cranks covered a second per
    core where the bound prunes (an in-line 14, M1,M2,M3,M4) and where it cannot (a V14 on
    an 18° grid of uneven cranks, every F_k and M_k), and what they make of larger searches
    on 64 cores."""
    try:
        import distributed
    except ImportError:
        print(
            "cluster: distributed is not installed (pip install 'engine-balance[cluster]'): "
            "skipped\n"
        )
        return False
    import tomllib

    import balance_cli as balance
    from balance_cli.config import build

    with tempfile.TemporaryDirectory() as folder:
        inline = balance.load_template(_inline_template(14, folder))
    v_family = ROOT / "templates" / "v-family-4stroke.toml"
    data = tomllib.loads(v_family.read_text(encoding="utf-8"))
    data["throws"] = [{"z": f"{530 * j} mm"} for j in range(7)]
    data.pop("power")
    v14 = build(data, str(v_family), template=True)
    cases = (
        ("in-line 14, M1,M2,M3,M4", inline, {"objective": "M1,M2,M3,M4"}),
        (
            "V14 on an 18° grid, every F_k and M_k",
            v14,
            {"allow_uneven": True, "step_deg": 18.0, "limit": 10**12},
        ),
    )
    rates = []
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        for name, template, options in cases:
            pieces: list = []

            def progress(done, total, pieces=pieces):
                pieces.append(done)

            start = time.perf_counter()
            found = balance.search(template, client=client, progress=progress, **options)
            wall = time.perf_counter() - start
            cores = found.workers
            covered = (found.evaluated + found.pruned) / wall / cores
            units = (pieces[-1] - 10) / wall / cores if pieces else 0.0  # the last 10: analyses
            rates.append(covered)
            print(
                f"{wall * 1000:8.1f} ms  {name} on a LocalCluster of {cores} worker processes "
                f"(load {load()}): {units:.0f} units and {covered:,.0f} cranks covered a second "
                "per core"
            )
    sixteen = math.factorial(15) // 4
    v20 = 20**9 // 4
    print(
        f"          64 cores at those rates: in-line 16 ({sixteen:.2g} cranks) at most "
        f"{sixteen / rates[0] / 64:.0f} s (the rate grows with N: the 14's is a floor); a "
        f"four-stroke V20 on an 18° grid, every F_k and M_k ({v20:.2g} cranks) about "
        f"{v20 / rates[1] / 64:.0f} s\n"
    )
    return False


def torsion_bench():
    """A six-throw model's full torsional sweep, timed in this process (median of 5)."""
    try:
        import opentorsion  # noqa: F401
    except ImportError:
        print(
            "torsion: openTorsion is not installed (pip install 'engine-balance[torsion]'): "
            "skipped\n"
        )
        return False
    import numpy as np

    import balance_cli as balance
    from balance_cli.torsion import torsional_vibration as torsion

    mendes = ROOT / "tests/validation/reference/opentorsion_ice/mendes2008.toml"
    text = mendes.read_text(encoding="utf-8")
    engine = balance.loads(
        text + '\n[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "15 bar"\n',
        "mendes2008 with [gas]",
    )
    speeds = np.linspace(600.0, 2400.0, 100)
    torsion(engine, speeds, 12)
    times = []
    for _ in range(5):
        start = time.perf_counter()
        torsion(engine, speeds, 12)
        times.append(time.perf_counter() - start)
    wall = statistics.median(times)
    verdict = "ok" if wall <= 0.5 else "TOO SLOW"
    print(
        f"{wall * 1000:8.1f} ms  median of 5  balance.torsion, six throws, 100 speeds, orders "
        f"1/2 to 12"
    )
    print(f"torsional sweep in {wall:.3f} s (target at most 0.5 s): {verdict}\n")
    return verdict != "ok"


def mounts_bench():
    """The coupled example's whole mount analysis at 100 speeds, orders ½ to 12, timed in this
    process (median of 5)."""
    import numpy as np

    import balance_cli as balance

    engine = balance.load(ROOT / "configs" / "mounts" / "four-mount-coupled.toml")
    speeds = np.linspace(300.0, 6000.0, 100)
    balance.mounts(engine, speeds, max_order=12)
    times = []
    for _ in range(5):
        start = time.perf_counter()
        balance.mounts(engine, speeds, max_order=12)
        times.append(time.perf_counter() - start)
    wall = statistics.median(times)
    verdict = "ok" if wall <= 0.3 else "TOO SLOW"
    print(f"{wall * 1000:8.1f} ms  median of 5  balance.mounts, 100 speeds, orders 1/2 to 12")
    print(f"mount analysis in {wall:.3f} s (target at most 0.3 s): {verdict}\n")
    return verdict != "ok"


#: the engines balance animate is shown on
ANIMATED = (
    "configs/tanaka-part3/5a-radial-9.toml",
    "configs/clerget-rotary.toml",
    "configs/today/v/v8-90-cross-plane.toml",
    "configs/today/h/brm-h16.toml",
    "configs/today/opposed-piston/junkers-jumo-205.toml",
)
_WROTE = re.compile(r"^wrote (\S+) \(([0-9.e-]+) s\)$")


def animate_bench():
    """Each engine's GIF and page: write time (what the command reports) and size; the V8's
    GIF command whole (median of 3) against 5 s; every GIF against 2 MB."""
    failed = False
    with tempfile.TemporaryDirectory() as folder:
        for config in ANIMATED:
            stem = Path(config).stem
            gif, page = Path(folder) / f"{stem}.gif", Path(folder) / f"{stem}.html"
            done = subprocess.run(
                [BALANCE, "animate", config, "-o", str(gif), "-o", str(page)],
                cwd=ROOT,
                check=True,
                capture_output=True,
                text=True,
            )
            took = dict(m.groups() for m in map(_WROTE.match, done.stderr.splitlines()) if m)
            for path in (gif, page):
                size = path.stat().st_size
                print(
                    f"{float(took[str(path)]) * 1000:8.1f} ms  balance animate {config} -o "
                    f"{path.name}: {size / 1e6:.2f} MB"
                )
                if path.suffix == ".gif" and size >= 2_000_000:
                    print(
                        f"          {path.name} is {size / 1e6:.2f} MB (target under 2 MB): TOO BIG"
                    )
                    failed = True
        v8 = [BALANCE, "animate", ANIMATED[2], "-o", str(Path(folder) / "v8.gif")]
        times = []
        for _ in range(4):
            start = time.perf_counter()
            subprocess.run(v8, cwd=ROOT, check=True, capture_output=True)
            times.append(time.perf_counter() - start)
        # the first run warms the caches up
        wall = statistics.median(times[1:])
    verdict = "ok" if wall < 5.0 else "TOO SLOW"
    print(
        f"{wall * 1000:8.1f} ms  median of 3  balance animate {ANIMATED[2]} -o v8.gif "
        f"(the whole command)"
    )
    print(f"the V8's GIF in {wall:.2f} s (target under 5 s): {verdict}\n")
    return failed or wall >= 5.0


def tolerance_bench():
    """10 000 runs of a V8's tolerance band, every dimension scattered, timed in this process
    (median of 5), beside one analysis of the engine."""
    import math

    import balance_cli as balance

    engine = balance.load(ROOT / "configs/today/v/v8-90-cross-plane.toml").edit(rotating="1.1 kg")
    band = balance.ToleranceBand(
        reciprocating_kg=0.002,
        rotating_kg=0.003,
        crank_radius_m=2e-5,
        rod_length_m=3e-5,
        phase_rad=math.radians(0.05),
        bank_angle_rad=math.radians(0.05),
        pin_offset_m=2e-5,
    )
    balance.tolerance(engine, band, runs=100)
    times, single = [], []
    for seed in range(5):
        start = time.perf_counter()
        balance.tolerance(engine, band, runs=10_000, seed=seed)
        times.append(time.perf_counter() - start)
        start = time.perf_counter()
        balance.analyse(engine.edit(speed=f"{6000 + seed} rpm"))  # a new engine: not cached
        single.append(time.perf_counter() - start)
    wall, one = statistics.median(times), statistics.median(single)
    verdict = "ok" if wall < 2.0 else "TOO SLOW"
    print(f"{wall * 1000:8.1f} ms  median of 5  balance.tolerance, V8, 10 000 runs, linkage")
    print(f"{one * 1000:8.1f} ms  median of 5  balance.analyse, the same V8 once")
    print(
        f"10 000 runs cost {wall / one:.0f} single analyses; {wall:.2f} s (target under 2 s): "
        f"{verdict}\n"
    )
    return verdict != "ok"


def main():
    # byte-compile balance first, as installing numpy compiled numpy: with
    # PYTHONDONTWRITEBYTECODE set (as on this project's machines) every run would otherwise
    # recompile the package's sources and time the compiler, not balance
    compileall.compile_dir(str(ROOT / "balance_cli"), quiet=1)
    failed = False
    engines = len(list((ROOT / "configs").rglob("*.toml")))
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
            each = (ratio - 1) / engines
            verdict = "ok" if each <= target else "TOO SLOW"
            print(f"{a * 1000:8.1f} ms  median of {runs}  {name}")
            print(f"{b * 1000:8.1f} ms  median of {runs}  {base_name}")
            print(
                f"ratio {ratio:.2f} for {engines} engines: {each:.3f} of the baseline an engine "
                f"({(a - b) / engines * 1000:.1f} ms; target at most {target:.3f}): {verdict}\n"
            )
            failed |= each > target
    if os.environ.get("BASE"):
        against(os.environ["BASE"])
    failed |= search_bench()
    failed |= scale_bench()
    failed |= family_bench()
    failed |= cluster_bench()
    failed |= torsion_bench()
    failed |= mounts_bench()
    failed |= animate_bench()
    failed |= tolerance_bench()
    subprocess.run([sys.executable, str(ROOT / "tools" / "closures.py")], cwd=ROOT, check=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
