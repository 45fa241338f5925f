"""Torques and speed: balance torque (torques at constant speed, and the steadiness with a
flywheel) and balance steadiness (the speed over a measured torque curve).
"""

from pathlib import Path

import click
import numpy as np

from ..output import STEADINESS_VERSION
from ..report.csvfile import torque_csv
from ..report.torque import steadiness_text, torque_tables
from ..units import Scale
from . import batch
from .batch import load_all, run_each, settings
from .dispatch import emit, guard
from .group import main, reported
from .options import (
    FORMAT,
    INPUTS,
    LOAD,
    MAX_ORDER,
    OUTPUT,
    SAMPLES,
    SPEED,
    UNIT_CHOICE,
    quantity_option,
)

__all__ = ["torque", "steadiness"]


@main.command()
@INPUTS
@click.option(
    "--pressure",
    metavar="FILE.csv",
    help="Cylinder pressure over one cycle from the firing top dead centre: a header "
    "angle_deg,pressure_bar (or another pressure unit), one row per angle; the same "
    "curve for every cylinder at its own firing angle. Default: the configuration's "
    "[gas] cycle, if it has one.",
)
@click.option(
    "--bore",
    metavar="LENGTH",
    help="Cylinder bore for --pressure, e.g. '154 mm' (default the [gas] bore).",
)
@click.option(
    "--inertia",
    metavar="I",
    help="Flywheel and propeller inertia, e.g. '2.5 kg*m^2': "
    "integrate the speed over the cycle and give the "
    "steadiness (needs a gas torque).",
)
@click.option(
    "--target",
    type=float,
    metavar="R",
    help="Also give the flywheel inertia that reaches steadiness R.",
)
@LOAD
@SAMPLES
@MAX_ORDER
@click.option(
    "--units",
    type=UNIT_CHOICE,
    default="N",
    show_default=True,
    help="Units of torques (N·m, kN·m, MN·m, kgf·m or lbf·ft) and forces (N, kN, MN, "
    "kgf or lbf) in the tables; JSON stays SI.",
)
@SPEED
@FORMAT
@OUTPUT
def torque(
    paths, pressure, bore, inertia, target, load, samples, max_order, units, speed, fmt, output
):
    """Torques at constant speed: inertia, gas, total, the rods' tilting couple and the frame
    reaction, order by order; the reduced mass; the forces on the crank pins and main bearings.

    With --inertia (or --target), the speed over the cycle with a flywheel and a load, and its
    steadiness (Margoulis).
    """
    from ..analysis.pressure import read_pressure_csv
    from ..analysis.torque import TorqueSet
    from ..analysis.torque import torque as torque_of

    if bore is not None and pressure is None:
        raise click.UsageError(
            "--bore applies with --pressure only (a [gas] table gives its own bore)"
        )
    if fmt == "csv" and (inertia is not None or target is not None):
        raise click.UsageError(
            "the steadiness of --inertia and --target is written by --format "
            "table, markdown and json, not csv"
        )
    files = batch.inputs(paths)
    inputs = files + ([Path(pressure)] if pressure else [])
    guard([output], inputs)
    settings(samples, max_order)
    bore_m = quantity_option(bore, "--bore", "length")
    inertia_kgm2 = quantity_option(inertia, "--inertia", "moment of inertia")
    engines = load_all(files, speed)
    curve = None
    if pressure is not None:
        with reported():
            # the cycle the file spans; an engine of the other cycle is refused by name
            curve = read_pressure_csv(pressure, None)

    def work(engine):
        return torque_of(engine, samples, max_order, curve, bore_m, inertia_kgm2, load, target)

    results = run_each(engines, "Torques", work)
    scale = Scale.of(True, units)
    emit(
        output,
        fmt,
        json=lambda: TorqueSet(tuple(results)).to_dict(),
        csv=lambda: torque_csv(results, scale),
        table=lambda: torque_tables(results, scale, fmt),
    )


@main.command()
@click.option(
    "--torque",
    "torque_file",
    required=True,
    metavar="FILE.csv",
    help="Driving torque over one cycle: a header angle_deg,torque_Nm (or another "
    "torque unit), one row per crank angle; the cycle is 360° or 720° as the "
    "angles span.",
)
@click.option(
    "--inertia",
    required=True,
    metavar="I",
    help="Flywheel and propeller inertia with the engine's moving parts, e.g. '2.5 kg*m^2'.",
)
@click.option("--speed", required=True, metavar="SPEED", help="Mean speed, e.g. '1650 rpm'.")
@LOAD
@click.option(
    "--target", type=float, metavar="R", help="Also give the inertia that reaches steadiness R."
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["table", "markdown", "json"]),
    default="table",
    show_default=True,
    help="Output format.",
)
@OUTPUT
def steadiness(torque_file, inertia, speed, load, target, fmt, output):
    """Speed fluctuation of an engine set driven by a measured torque curve: the periodic speed,
    the steadiness ω_m/(ω_max − ω_min), and Margoulis's closed forms r_c, r_v, r_h."""
    from ..analysis.pressure import read_cycle_csv
    from ..analysis.steadiness import flywheel_for
    from ..analysis.steadiness import steadiness as steadiness_of

    guard([output], [Path(torque_file)])
    inertia_kgm2 = quantity_option(inertia, "--inertia", "moment of inertia")
    speed_rad_s = quantity_option(speed, "--speed", "angular speed")
    with reported(flags={"torque_nm": f"--torque {torque_file}"}):
        curve = read_cycle_csv(torque_file, "torque")
        angles, values, cycle = curve.angles_deg, curve.values, curve.cycle_deg
        # an even grid for the integration, the curve linear between the file's points
        grid = np.arange(4096) * cycle / 4096
        torque_nm = np.interp(grid, angles, values, period=cycle)
        speed = steadiness_of(torque_nm, cycle, inertia_kgm2, speed_rad_s, load)
        flywheel = (
            None if target is None else flywheel_for(target, torque_nm, cycle, speed_rad_s, load)
        )
    document = {
        "balance_version": STEADINESS_VERSION,
        "torque_file": str(torque_file),
        "cycle_deg": cycle,
        **speed.to_dict(),
        "inertia_for_target_kgm2": flywheel,
    }
    emit(output, fmt, json=lambda: document, table=lambda: steadiness_text(speed, flywheel) + "\n")
