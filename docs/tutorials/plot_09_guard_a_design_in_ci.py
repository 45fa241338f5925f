"""
Guarding a design in CI with balance regress
============================================

Once a design's crank, firing order and masses are settled, its balance is something to keep:
a heavier piston, a longer rod or a mistyped phase should not move the free forces without
someone noticing. ``balance regress`` analyses the engines again and compares them with a
baseline that ``balance compare`` wrote; it exits with status 1 when anything moved beyond a
tight tolerance, which fails a CI job, and it writes what moved as a table, Markdown for the
job's summary, JSON for a program or JUnit XML for a CI's test report.

This tutorial does it in a temporary folder with an engine shipped with balance, the commands
run through click's test runner exactly as a shell would run them; a CI configuration closes
it.
"""

import contextlib
import json
import shlex
import shutil
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main

# %%
# The design: a folder with an engine
# -----------------------------------
#
# A repository holds its engines as TOML files; here ``design/inline-4-car.toml`` is a copy
# of the library's in-line four with car proportions (550 g reciprocating per cylinder).
work = Path(tempfile.mkdtemp(prefix="balance-ci-"))
design = work / "design"
design.mkdir()
shipped = Path(balance.read_configuration("library:inline-4-car").path)
engine_file = design / "inline-4-car.toml"
engine_file.write_text(shipped.read_text(encoding="utf-8"), encoding="utf-8")


def run(command, lines=None):
    """Run a ``balance`` command line in the work folder, as CI would; print it, its exit
    status and what it wrote (its first ``lines`` lines, if given); return click's result."""
    with contextlib.chdir(work):
        result = CliRunner().invoke(main, shlex.split(command)[1:])
    shown = "\n".join(result.output.splitlines()[:lines])
    print(f"$ {command}\n(exit status {result.exit_code})\n{shown}\n")
    return result


# %%
# The baseline
# ------------
#
# ``balance compare --format json`` writes the document a baseline is: every engine's forces
# and moments order by order, its firing, and the settings it was analysed with (samples a
# revolution, the highest order), which ``regress`` uses again. It is committed with the
# design.
run("balance compare design --format json -o design/baseline.json")
baseline = json.loads((design / "baseline.json").read_text(encoding="utf-8"))
print({key: baseline[key] for key in ("balance_version", "samples", "max_order")})
print([(e["name"], e["config"]) for e in baseline["engines"]])

# %%
# On every push CI runs ``balance regress`` against it. Nothing has changed yet: exit
# status 0, and the Markdown summary says so.
result = run("balance regress design/baseline.json --format markdown")
assert result.exit_code == 0

# %%
# A change that moves the balance
# -------------------------------
#
# Someone fits heavier pistons: 580 g instead of 550 g reciprocating per cylinder. The
# in-line four's flat crank cancels its first order whatever the masses, so the rotating
# masses play no part; every force it does leave (the orders 2, 4, 6, 8) is proportional to
# the reciprocating mass and grows by 30/550 = 5.45 %. ``regress`` fails the job (exit
# status 1) and its Markdown, written to the job's summary, lists each quantity that moved:
# baseline, now, the change, the relative change and the tolerance it exceeded (forces may
# move by 1e-9 of the engine's m_rec·r·ω²·n: rounding, nothing more).
text = engine_file.read_text(encoding="utf-8")
engine_file.write_text(text.replace('"550 g"', '"580 g"'), encoding="utf-8")
result = run("balance regress design/baseline.json --format markdown")
assert result.exit_code == 1

# %%
# The JSON form carries the same rows for a program to read. Every one moved by 30/550:
result = run("balance regress design/baseline.json --format json -o moved.json")
assert result.exit_code == 1
moved = json.loads((work / "moved.json").read_text(encoding="utf-8"))
changes = [row["relative_change"] for row in moved["rows"]]
# rtol: the eighth order's 0.2 N carries the FFT's rounding (about 1e-10 N), which shows in
# the eighth digit of its relative change
np.testing.assert_allclose(changes, 30 / 550, rtol=1e-6)
print(f"{len(changes)} quantities moved, each by {100 * 30 / 550:.2f} %")

# %%
# A design still being worked on can loosen the tolerance with ``--rtol``: a force may then
# move by that fraction of itself. 10 % lets the heavier pistons through, 5 % does not.
assert run("balance regress design/baseline.json --rtol 0.1").exit_code == 0
assert run("balance regress design/baseline.json --rtol 0.05", lines=1).exit_code == 1

# %%
# What moved, order by order, read from the JSON document: each order's largest force over a
# revolution (``force.max_N``) in the baseline and now, and its change against the two
# ``--rtol`` tried above.
largest = [row for row in moved["rows"] if row["quantity"] == "force.max_N"]
orders = np.array([row["order"] for row in largest])
fig, (forces, change) = plt.subplots(1, 2, figsize=(9, 3.6), layout="constrained")
forces.bar(orders - 0.2, [row["baseline"] for row in largest], 0.4, label="baseline (550 g)")
forces.bar(orders + 0.2, [row["now"] for row in largest], 0.4, label="now (580 g)")
forces.set(yscale="log", xticks=orders, xlabel="order", ylabel="largest force (N)")
forces.legend()
change.bar(orders, [100 * row["relative_change"] for row in largest], 0.6, color="C1")
for rtol, style in ((0.05, "--"), (0.1, ":")):
    change.axhline(100 * rtol, color="k", linestyle=style, label=f"--rtol {rtol:g}")
change.set(xticks=orders, xlabel="order", ylabel="change (%)", ylim=(0, 12.5))
change.legend(loc="upper left", ncols=2)
title = fig.suptitle(f"{moved['engines_checked'][0]}: what balance regress found moved")

# %%
# A change meant on purpose
# -------------------------
#
# When the heavier pistons are the design now, ``--update`` prints what changed and rewrites
# the baseline (exit status 0); the next check passes again. Commit the new baseline with
# the change, so the review sees both.
assert run("balance regress design/baseline.json --update", lines=1).exit_code == 0
assert run("balance regress design/baseline.json").exit_code == 0

# %%
# In CI
# -----
#
# On GitHub Actions, the Markdown goes to the job's summary and the JUnit XML to an
# artifact (other CI systems read the same JUnit file); the step fails with ``regress``'s
# exit status:
#
# .. code-block:: yaml
#
#    # .github/workflows/balance.yml
#    name: balance
#    on: [push, pull_request]
#    jobs:
#      regress:
#        runs-on: ubuntu-latest
#        steps:
#          - uses: actions/checkout@v4
#          - uses: actions/setup-python@v5
#            with:
#              python-version: "3.11"
#          - run: pip install engine-balance
#          - name: balance regression tables
#            run: |
#              status=0
#              balance regress design/baseline.json --format markdown -o summary.md || status=$?
#              cat summary.md >> "$GITHUB_STEP_SUMMARY"
#              balance regress design/baseline.json --format junit -o balance-junit.xml || true
#              exit $status
#          - uses: actions/upload-artifact@v4
#            if: always()
#            with:
#              name: balance-junit
#              path: balance-junit.xml
#
# Any other CI runs the same command and reads its exit status: 0 nothing moved, 1 something
# moved (or a file could not be read: one line says which), 2 a usage error.
#
# .. code-block:: sh
#
#    balance regress design/baseline.json --format junit -o balance-junit.xml
#
# and a change meant on purpose updates the baseline in the same commit:
#
# .. code-block:: sh
#
#    balance regress design/baseline.json --update
#    git commit -am "Heavier pistons: second order up 5.5 % (balance baseline updated)"
#
# balance guards its own engine library this way: ``tests/golden/compare.json`` is the
# baseline of every engine in ``configs/``, and the test suite runs
# ``balance regress tests/golden/compare.json configs``.

# %%
# (The temporary folder of this page goes.)
shutil.rmtree(work)
