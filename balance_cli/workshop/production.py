"""balance tolerance: what a tolerance band leaves across a production run.

Every run is the engine's own exact harmonic analysis with its parts and dimensions drawn from
the band (:class:`~balance_cli.model.ToleranceBand`), all runs at once (:mod:`.runs`): with
masses only scattered, each run is the runs' masses times the engine's response to one
kilogram at each point mass (forces are linear in the masses: exact); with dimensions
scattered too, each run's linkage is closed exactly, batched. For each order: the spread of
the free force's and moment's vertical and horizontal amplitudes and of their largest value
over a revolution (|X⁺| + |X⁻|), and of the largest resultant force and moment over a
revolution (all orders); beside the Monte Carlo, the closed-form spread of the amplitudes'
linear part (:mod:`.spread`), so that a user sees both agree where the scatter is small.
"""

import math
import time
from dataclasses import dataclass, field

import numpy as np

from .. import checks
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings, directional
from ..errors import AnalysisError
from ..harmonics import synthesize
from ..model import Engine, ToleranceBand
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular
from .basis import unit_basis
from .runs import Draws, draw, geometry_of, run_coefficients
from .spread import Stats, linear_of, stats_of

__all__ = ["tolerance", "ToleranceResult", "OrderSpread", "DEFAULT_RUNS"]

DEFAULT_RUNS = 10_000
#: the most runs taken (memory: a few hundred bytes a run and order)
_MOST_RUNS = 10_000_000
#: complex numbers of positions closed at a time (memory: 16 bytes each)
_BLOCK = 1 << 22
#: the grid of the largest resultant over a revolution: the samples, this many times finer
_UPSAMPLE = 2
#: a dimension's central difference step, in its standard deviations
_STEP = 1e-2
_COMPONENTS = ("vertical", "horizontal", "max")


@dataclass(frozen=True)
class OrderSpread:
    """One order's spread: Monte Carlo :class:`~.spread.Stats` of the force's (N) and
    moment's (N·m) ``vertical``, ``horizontal`` and ``max`` (|X⁺| + |X⁻|) amplitudes, and the
    closed-form :class:`~.spread.Linear` of the vertical and horizontal ones."""

    order: int
    force: dict
    moment: dict
    linear_force: dict
    linear_moment: dict

    def to_dict(self) -> dict:
        out: dict = {"order": self.order}
        for part, unit, stats, linear in (
            ("force", "N", self.force, self.linear_force),
            ("moment", "Nm", self.moment, self.linear_moment),
        ):
            out[part] = {
                name: {
                    **stats[name].to_dict(unit),
                    **({"linear": linear[name].to_dict(unit)} if name in linear else {}),
                }
                for name in _COMPONENTS
            }
        return out


@dataclass(frozen=True)
class ToleranceResult(Tabular):
    """What :func:`tolerance` found.

    Attributes
    ----------
    engine : Engine
    band : ToleranceBand
    runs, seed, samples, max_order : int
    method : str
        "masses" (masses only scattered: linear, exact) or "linkage" (each run's linkage
        closed)
    orders : tuple of OrderSpread
        orders 1..max_order
    largest_force, largest_moment : Stats
        the largest resultant force (N) and free moment (N·m) over a revolution, all orders
    values : dict
        the runs' values, for pictures: ``"force_vertical"``, ... ``"moment_max"`` arrays
        (runs, max_order); ``"largest_force"``, ``"largest_moment"`` arrays (runs,)
    elapsed_s : float
    """

    engine: Engine
    band: ToleranceBand
    runs: int
    seed: int
    samples: int
    max_order: int
    method: str
    orders: tuple
    largest_force: Stats
    largest_moment: Stats
    elapsed_s: float
    values: dict = field(repr=False, compare=False)

    def order(self, k: int) -> OrderSpread:
        if (
            isinstance(k, bool)
            or not isinstance(k, (int, np.integer))
            or not 1 <= k <= len(self.orders)
        ):
            raise AnalysisError(f"is not among the orders analysed (1 to {len(self.orders)})", "k")
        return self.orders[k - 1]

    def records(self) -> list:
        """One row per order: ``order``, then for the force (N) and moment (N·m), each of its
        vertical, horizontal and max amplitudes: ``force_vertical_mean_N``, ``_median_``,
        ``_p95_``, ``_p99_``, ``_max_``, and the closed form's ``force_vertical_linear_mean_N``
        and ``_linear_p95_`` (vertical and horizontal)."""
        rows = []
        for spread in self.orders:
            row = {"order": spread.order}
            for part, unit, stats, linear in (
                ("force", "N", spread.force, spread.linear_force),
                ("moment", "Nm", spread.moment, spread.linear_moment),
            ):
                for name in _COMPONENTS:
                    s = stats[name]
                    for key in ("mean", "median", "p95", "p99", "max"):
                        row[f"{part}_{name}_{key}_{unit}"] = getattr(s, key)
                    if name in linear:
                        row[f"{part}_{name}_linear_mean_{unit}"] = linear[name].mean
                        row[f"{part}_{name}_linear_p95_{unit}"] = linear[name].p95
            rows.append(row)
        return rows

    def to_dict(self) -> dict:
        """What ``balance tolerance --format json`` writes."""
        band = self.band
        return {
            "balance_version": DOCUMENT_VERSION,
            "engine": self.engine.name,
            "config": self.engine.config_path,
            "runs": self.runs,
            "seed": self.seed,
            "samples": self.samples,
            "max_order": self.max_order,
            "method": self.method,
            "elapsed_s": self.elapsed_s,
            "tolerances": {
                "reciprocating_kg": band.reciprocating_kg,
                "rotating_kg": band.rotating_kg,
                "crank_radius_m": band.crank_radius_m,
                "rod_length_m": band.rod_length_m,
                "phase_deg": math.degrees(band.phase_rad),
                "bank_angle_deg": math.degrees(band.bank_angle_rad),
                "pin_offset_m": band.pin_offset_m,
            },
            "largest_force": self.largest_force.to_dict("N"),
            "largest_moment": self.largest_moment.to_dict("Nm"),
            "orders": [o.to_dict() for o in self.orders],
        }


def _amplitudes(engine, force, moment, max_order):
    """Per run and order: the vertical, horizontal and max amplitudes of force and moment."""
    k = np.arange(1, max_order + 1)
    out = {}
    for part, coefficients in (("force", force), ("moment", moment)):
        forward, backward = coefficients[:, k], coefficients[:, -k]
        vertical, horizontal = directional(forward, backward, engine.vertical_axis_rad)
        out[f"{part}_vertical"] = np.abs(vertical)
        out[f"{part}_horizontal"] = np.abs(horizontal)
        out[f"{part}_max"] = np.abs(forward) + np.abs(backward)
    return out


def _chunks(engine, runs, samples):
    points = (engine.n_cylinders + len(engine.throws)) * samples
    size = max(1, _BLOCK // points)
    return [slice(s, min(s + size, runs)) for s in range(0, runs, size)]


def _sliced(draws, rows):
    geometry = draws.geometry
    if geometry is not None:
        geometry = type(geometry)(
            *(getattr(geometry, f)[rows] for f in geometry.__dataclass_fields__)
        )
    return Draws(draws.reciprocating[rows], draws.rotating[rows], geometry)


def _perturbed(band, nominal):
    """Runs at the nominal engine with each scattered value moved by ±_STEP of its standard
    deviation: (draws of 2·P runs, each value's standard deviation and its step)."""
    geometry = nominal.geometry
    fields = [("reciprocating", band.reciprocating_kg), ("rotating", band.rotating_kg)]
    if geometry is not None:
        fields += [
            ("radius", band.crank_radius_m),
            ("phase", band.phase_rad),
            ("bank", band.bank_angle_rad),
            ("rod", band.rod_length_m),
            ("offset", band.pin_offset_m),
        ]
    moves = []
    for name, sigma in fields:
        if sigma <= 0.0:
            continue
        width = (
            getattr(nominal, name)
            if name in ("reciprocating", "rotating")
            else getattr(geometry, name)
        ).shape[1]
        for j in range(width):
            if name == "phase" and j == 0:
                continue
            moves.append((name, j, sigma))
    arrays = {"reciprocating": nominal.reciprocating, "rotating": nominal.rotating}
    if geometry is not None:
        arrays.update({f: getattr(geometry, f) for f in geometry.__dataclass_fields__})
    stacked = {name: np.repeat(a, 2 * len(moves), axis=0) for name, a in arrays.items()}
    for i, (name, j, sigma) in enumerate(moves):
        stacked[name][2 * i, j] += _STEP * sigma
        stacked[name][2 * i + 1, j] -= _STEP * sigma
    out_geometry = None
    if geometry is not None:
        out_geometry = type(geometry)(**{f: stacked[f] for f in geometry.__dataclass_fields__})
    return Draws(stacked["reciprocating"], stacked["rotating"], out_geometry), moves


def _linear(engine, band, basis, samples, max_order):
    """The closed-form spread of each order's vertical and horizontal amplitudes: their
    gradients per standard deviation of each scattered value, by central differences (exact
    for the masses, on which they depend linearly)."""
    nominal = Draws(
        np.array([[c.reciprocating_kg for c in engine.cylinders]]),
        np.array([[engine.rotating_of(i) for i in range(len(engine.throws))]]),
        geometry_of(engine) if band.geometric else None,
    )
    moved, _ = _perturbed(band, nominal)
    centre = run_coefficients(engine, nominal, samples, basis)
    shifted = run_coefficients(engine, moved, samples, basis)
    k = np.arange(1, max_order + 1)
    out = {}
    for part, base, coefficients, floor in (
        ("force", centre[0], shifted[0], engine.noise_floor_n),
        ("moment", centre[1], shifted[1], engine.noise_floor_nm),
    ):
        nominal_parts = directional(base[0, k], base[0, -k], engine.vertical_axis_rad)
        moved_parts = directional(coefficients[:, k], coefficients[:, -k], engine.vertical_axis_rad)
        for name, q0, q in zip(("vertical", "horizontal"), nominal_parts, moved_parts, strict=True):
            gradients = (q[0::2] - q[1::2]) / (2 * _STEP)
            out[(part, name)] = [linear_of(q0[i], gradients[:, i], floor) for i in range(len(k))]
    return out


def tolerance(
    engine: Engine,
    tolerances: ToleranceBand | None = None,
    runs: int = DEFAULT_RUNS,
    seed: int = 0,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    progress=None,
) -> ToleranceResult:
    """What the tolerance band of ``engine`` leaves across ``runs`` engines.

    Parameters
    ----------
    engine : Engine
    tolerances : ToleranceBand, optional
        the band; default the engine's own (``[tolerances]`` of its configuration)
    runs : int
        engines drawn (2 to 10 000 000)
    seed : int
        of the random draws: the same seed draws the same engines
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    progress : callable, optional
        called with (done, total) runs as the work goes on

    Raises
    ------
    AnalysisError
        naming the parameter: no band, a band that scatters nothing, a scatter so wide that a
        rod cannot reach its axis, dimensions scattered on an opposed-piston engine
    """
    start = time.perf_counter()
    checks.instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    band = engine.tolerances if tolerances is None else tolerances
    if band is None:
        raise AnalysisError(
            f"are not given, and {engine.name!r} has none: give its configuration a "
            '[tolerances] table (one standard deviation each, such as reciprocating = "2 g")',
            "tolerances",
        )
    checks.instance(band, ToleranceBand, "tolerances")
    if band.empty:
        raise AnalysisError("scatter nothing: give one standard deviation at least", "tolerances")
    runs = checks.whole(runs, "runs", 2, _MOST_RUNS)
    seed = checks.whole(seed, "seed", 0, 2**63 - 1)
    basis = unit_basis(engine, samples, max_order)
    draws = draw(engine, band, runs, np.random.default_rng(seed))
    values: dict = {}
    largest_force, largest_moment = [], []
    done = 0
    for rows in _chunks(engine, runs, samples):
        force, moment = run_coefficients(engine, _sliced(draws, rows), samples, basis)
        for name, array in _amplitudes(engine, force, moment, max_order).items():
            values.setdefault(name, []).append(array)
        largest_force.append(np.abs(synthesize(force, _UPSAMPLE)).max(axis=1))
        largest_moment.append(np.abs(synthesize(moment, _UPSAMPLE)).max(axis=1))
        done = rows.stop
        if progress is not None:
            progress(done, runs)
    values = {name: np.concatenate(parts) for name, parts in values.items()}
    values["largest_force"] = np.concatenate(largest_force)
    values["largest_moment"] = np.concatenate(largest_moment)
    linear = _linear(engine, band, basis, samples, max_order)
    orders = []
    for i in range(max_order):
        stats = {
            part: {name: stats_of(values[f"{part}_{name}"][:, i]) for name in _COMPONENTS}
            for part in ("force", "moment")
        }
        orders.append(
            OrderSpread(
                order=i + 1,
                force=stats["force"],
                moment=stats["moment"],
                linear_force={n: linear[("force", n)][i] for n in ("vertical", "horizontal")},
                linear_moment={n: linear[("moment", n)][i] for n in ("vertical", "horizontal")},
            )
        )
    return ToleranceResult(
        engine=engine,
        band=band,
        runs=runs,
        seed=seed,
        samples=samples,
        max_order=max_order,
        method="masses" if draws.geometry is None else "linkage",
        orders=tuple(orders),
        largest_force=stats_of(values["largest_force"]),
        largest_moment=stats_of(values["largest_moment"]),
        elapsed_s=time.perf_counter() - start,
        values=values,
    )
