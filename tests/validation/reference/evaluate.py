"""Evaluate the published figures of the source papers against balance's exact results.

Each ``*.toml`` file beside this module holds one paper: a ``[paper]`` table, optional
``[frames.NAME]`` tables (how the paper's axes and crank angle relate to ours) and
``[[figure]]`` records, one per published number. ``errata.toml`` lists the misprints the
records point to. See README.md here for the record format.

Used by ``tests/validation/test_reference.py`` and by ``tools/validation_report.py`` (``make
validate``).
"""

import dataclasses
import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np

from balance_cli import analyse, load
from balance_cli.analysis.marine import power_related_unbalance
from balance_cli.analysis.steadiness import steadiness
from balance_cli.analysis.torque import torque
from balance_cli.kinematics.linkage import close_linkage as linkage
from balance_cli.model import Cylinder, Engine, Throw
from balance_cli.units import STANDARD_GRAVITY

from . import fraeys_series

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent.parent

__all__ = ["Row", "papers", "errata", "evaluate", "rows"]


@dataclasses.dataclass(frozen=True)
class Row:
    id: str
    paper: str
    where: str
    quantity: str
    unit: str
    published: float
    ours: float
    tolerance: float
    reason: str
    erratum: str
    corrected: float | None

    @property
    def deviation(self):
        return self.ours - self.published

    @property
    def agrees(self):
        return abs(self.deviation) <= self.tolerance

    @property
    def corrected_agrees(self):
        return self.corrected is not None and abs(self.ours - self.corrected) <= self.tolerance

    @property
    def verdict(self):
        if self.agrees:
            return "agrees"
        if self.erratum:
            return f"erratum {self.erratum}"
        return "DISAGREES"


def papers():
    """Every paper file: its [paper] table, frames and figures."""
    out = []
    for path in sorted(HERE.glob("*.toml")):
        if path.name in ("errata.toml", "own_errors.toml"):
            continue
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        data["file"] = path.name
        out.append(data)
    return out


def errata():
    return tomllib.loads((HERE / "errata.toml").read_text(encoding="utf-8"))["erratum"]


def own_errors():
    """balance's own errors, found against the published data and corrected."""
    return tomllib.loads((HERE / "own_errors.toml").read_text(encoding="utf-8"))["error"]


# ---------------------------------------------------------------- engines and variants


@cache
def _engine(config):
    return load(ROOT / config)


def _variant(record):
    """The record's engine with its overrides applied (masses, knuckle radii, ...)."""
    engine = _engine(record["config"])
    cylinders = engine.cylinders
    if "reciprocating" in record.get("variant", []):
        cylinders = tuple(dataclasses.replace(c, knuckle_kg=0.0) for c in cylinders)
        engine = dataclasses.replace(engine, rotating_kg=0.0, cylinders=cylinders)
    if "single-obliquity" in record.get("variant", []):
        # every link rod replaced by a plain rod of the master's length on the same pin
        cylinders = tuple(
            dataclasses.replace(
                c,
                master=None,
                link_length_m=0.0,
                knuckle_radius_m=0.0,
                knuckle_angle_rad=0.0,
                knuckle_kg=0.0,
            )
            for c in cylinders
        )
        engine = dataclasses.replace(engine, cylinders=cylinders)
    if "masses_g" in record:
        cylinders = tuple(
            dataclasses.replace(c, reciprocating_kg=m / 1000.0)
            for c, m in zip(cylinders, record["masses_g"], strict=True)
        )
        engine = dataclasses.replace(engine, cylinders=cylinders)
    if "rod_inertias_kgm2" in record:
        # added to each cylinder's own (in number order): Tanaka's I_B and Φ corrections
        cylinders = tuple(
            dataclasses.replace(c, rod_inertia_kgm2=c.rod_inertia_kgm2 + extra)
            for c, extra in zip(cylinders, record["rod_inertias_kgm2"], strict=True)
        )
        engine = dataclasses.replace(engine, cylinders=cylinders)
    if "knuckle_radii_mm" in record:
        cylinders = tuple(
            dataclasses.replace(c, knuckle_radius_m=a / 1000.0) if c.is_link else c
            for c, a in zip(cylinders, record["knuckle_radii_mm"], strict=True)
        )
        engine = dataclasses.replace(engine, cylinders=cylinders)
    return engine


def _base(record):
    """The record's engine without the overrides that a difference is taken against."""
    return _variant(
        {
            k: v
            for k, v in record.items()
            if k not in ("masses_g", "knuckle_radii_mm", "rod_inertias_kgm2")
        }
    )


@cache
def _analysed(engine, samples, max_order):
    return analyse(engine, samples, max_order)


def _result(engine, record):
    return _analysed(engine, record.get("samples", 256), record.get("max_order", 8))


@cache
def _torqued(engine, samples, max_order):
    return torque(engine, samples, max_order)


def _torque_result(engine, record):
    return _torqued(engine, record.get("samples", 256), record.get("max_order", 8))


# ---------------------------------------------------------------- units and frames


def _unit(name, engine, result):
    """Divisor turning newtons (or N·m) into the record's unit."""
    if name == "per_cylinder":
        return result.per_cylinder_unit_n
    if name == "per_cylinder_Nm":  # torques per m_rec·r²·ω²·n
        return engine.per_cylinder_unit_n * engine.crank_radius_m
    return {
        "N": 1.0,
        "Nm": 1.0,
        # phases and ratios: the scale cancels
        "": 1.0,
        "deg": 1.0,
        "kgf": STANDARD_GRAVITY,
        "kgfm": STANDARD_GRAVITY,
        # Fraeys de Veubeke's "kg": a force divided by R·Ω² (his unit of Table XII)
        "kg_RW2": engine.crank_radius_m * engine.speed_rad_s**2,
    }[name]


def _in_frame(forward, backward, k, frame):
    """Phasors of order k in the paper's crank angle θ_P = sign·(θ − zero)."""
    zero = math.radians(frame.get("zero_deg", 0.0))
    forward = forward * np.exp(1j * k * zero)
    backward = backward * np.exp(-1j * k * zero)
    if frame.get("sign", 1) == -1:
        forward, backward = backward, forward
    return forward, backward


_DIRECTIONS = {"along": 1.0, "across": 1j, "-along": -1.0, "-across": -1j}


def _component(forward, backward, axis, frame):
    """Coefficients (a, b) of a·cos kθ_P + b·sin kθ_P for the paper's X or Y axis."""
    u = _DIRECTIONS[frame[axis]]
    p, m = forward * np.conj(u), backward * np.conj(u)
    return p.real + m.real, m.imag - p.imag


# ---------------------------------------------------------------- quantities


def _order_phasors(record, kind="force"):
    k = record["order"]
    engine = _variant(record)
    result = _result(engine, record)
    o = result.shaking.orders[k - 1]
    f, b = (
        (o.force_forward, o.force_backward)
        if kind == "force"
        else (o.moment_forward, o.moment_backward)
    )
    if record.get("difference"):
        base = _result(_base(record), record).shaking.orders[k - 1]
        bf, bb = (
            (base.force_forward, base.force_backward)
            if kind == "force"
            else (base.moment_forward, base.moment_backward)
        )
        f, b = f - bf, b - bb
    scale = _unit(record["unit"], engine, result)
    return f / scale, b / scale, k


def _quantity(record, frames):
    words = record["quantity"].split()
    kind = words[0]
    frame = frames.get(record.get("frame", ""), {})
    if kind in ("X", "Y"):
        f, b, k = _order_phasors(record)
        a, s = _component(*_in_frame(f, b, k, frame), kind, frame)
        form = words[1]
        # phases of a vanishing component are noise: report them as 0
        if form == "cos":
            return a
        if form == "sin":
            return s
        if form == "amplitude":
            return math.hypot(a, s)
        if form == "phase":  # a·cos + s·sin = R·cos(kθ + φ)
            return math.degrees(math.atan2(-s, a))
        if form == "sinphase":  # a·cos + s·sin = R·sin(kθ + φ)
            return math.degrees(math.atan2(a, s)) % 360.0
    if kind in ("forward", "backward", "max", "min"):
        f, b, _ = _order_phasors(record)
        return {
            "forward": abs(f),
            "backward": abs(b),
            "max": abs(f) + abs(b),
            "min": abs(abs(f) - abs(b)),
        }[kind]
    if kind == "re":  # signed real part: Fraeys de Veubeke's S_k, S_−k
        f, b, _ = _order_phasors(record)
        return (f if words[1] == "forward" else b).real
    if kind == "moment":
        f, b, _ = _order_phasors(record, "moment")
        if words[1] == "forward":
            return abs(f)
        if words[1] == "max":
            return abs(f) + abs(b)
        if words[1] == "ratio":  # |across/along| of the forward moment phasor
            return abs(f.imag / f.real)
    if kind == "mean":
        engine = _variant(record)
        result = _result(engine, record)
        return abs(result.shaking.force_coefficients[0]) / _unit(record["unit"], engine, result)
    if kind == "percent":
        reference = _result(_engine(record["reference"]), record)
        return _result(_variant(record), record).percent_of(reference)
    if kind == "interval":
        intervals = _result(_variant(record), record).firing.intervals_deg
        return {"max": max(intervals), "min": min(intervals)}[words[1]]
    if kind == "lead":  # an opposed-piston bore's exhaust lead, degrees
        lead = _lead(_variant(record), int(words[1]))
        # "lead N opposed": the opposed (second) piston's lead over the first
        return (-lead) % 360.0 if words[2:] == ["opposed"] else lead
    if kind == "split":  # the angle between two throws' pins, degrees in [0, 360)
        engine = _variant(record)
        a, b = (engine.throws[int(w) - 1].phase_rad for w in words[1:3])
        return math.degrees(b - a) % 360.0
    if kind == "torque":
        return _torque_quantity(record, words[1:])
    if kind == "fraeys":
        return _fraeys_coefficient(record, words[1], int(words[2]))
    if kind == "margoulis":
        return _margoulis(record, words[1])
    if kind == "fraeys-series":
        return fraeys_series.series(record.get("series_order", 3))[words[1]][int(words[2])]
    if kind == "link":
        return _link_first_harmonic(record)[words[1]]
    if kind == "reduction":
        return _fraeys_reduction(record["data"])[words[1]]
    if kind == "gamma":
        return _gamma_sum(
            record["radii_mm"], record["crank_radius_mm"], int(words[1]), int(words[2])
        )
    if kind == "series":
        return _series_check(words[1], record)
    if kind == "pru":
        if len(words) == 5 and words[3] == "/":  # "pru V 1 / 2": order 1's over order 2's
            return _pru(record, words[1], int(words[2])) / _pru(record, words[1], int(words[4]))
        return _pru(record, words[1], int(words[2]))
    if kind == "torsion":
        return _torsion(words[1], int(words[2]), record.get("speeds_rpm"))
    raise ValueError(f"{record['id']}: unknown quantity {record['quantity']!r}")


def _lead(engine, number):
    """How many degrees the dead centre of cylinder ``number``'s first piston comes before its
    opposed piston's, each found as the maximum of its own exact travel on a 0.001° grid."""
    import numpy as np

    from balance_cli.kinematics.linkage import close_linkage as linkage

    theta = np.radians(np.arange(0.0, 360.0, 0.001))
    link = linkage(engine, theta, [number])
    own = link.opposed[number][1]
    first = link.travel[number] - own
    return (math.degrees(theta[np.argmax(own)] - theta[np.argmax(first)])) % 360.0


@cache
def _torsion_response(speeds):
    from .opentorsion_ice import compare

    peak, summed, frequencies = compare.response(np.array(speeds))
    return compare, summed, frequencies


def _torsion(form, figure, speeds_rpm):
    """``torsion resonance 31``: the speed of the largest vibratory torque (the orders'
    amplitudes summed, as openTorsion's example sets it beside the measurement) in the
    section of the paper's Fig. 31 (flywheel–6th cylinder) or 32 (pulley–gear train) among
    ``speeds_rpm``; ``torsion torque 31``: that largest torque (one speed: the torque there),
    N·m."""
    compare, summed, _ = _torsion_response(tuple(float(v) for v in speeds_rpm))
    values = summed[compare.FIG31 if figure == 31 else compare.FIG32]
    if form == "resonance":
        return float(speeds_rpm[int(np.argmax(values))])
    return float(values.max())


def _pru(record, part, k):
    """``pru V K``, ``pru H K``, ``pru max K``: the power related unbalance (N·m/kW) of the
    order-K pitching (V) or yawing (H) moment, or the larger of the two, from the library's
    :func:`power_related_unbalance` and the configuration's ``power``. With ``over`` (a second
    configuration), the ratio of the two engines' PRU: the project guides tabulate one engine
    type at several cylinder numbers, and a ratio cancels the maker's masses and dimensions
    that are common to the family, leaving the firing orders and cylinder numbers. The first
    order is judged under the project guides' standard balance (the library's default)."""

    def value(config):
        engine = _variant({**record, "config": config})
        pru = power_related_unbalance(_result(engine, record), orders=(k,))
        if not pru.available:
            raise ValueError(f"{record['id']}: no PRU for {config}: {pru.note}")
        entry = pru.orders[0]
        v, h = entry["vertical_Nm_per_kW"], entry["horizontal_Nm_per_kW"]
        return {"V": v, "H": h, "max": max(v, h)}[part]

    ours = value(record["config"])
    return ours / value(record["over"]) if "over" in record else ours


def _torque_value(result, part, words):
    series = getattr(result, part) if part != "reduced_mass" else None
    form = words[0]
    if form in ("sin", "cos"):
        cos, sin = series.order(int(words[1]))
        return sin if form == "sin" else cos
    if form == "largest_below":  # the largest amplitude of the orders below K
        return max(math.hypot(c, s) for k, c, s in series.orders if k < float(words[1]))
    if form == "variation":  # (max − min)/mean of the reduced mass
        mu = result.reduced_mass.curve_kgm2
        return (mu.max() - mu.min()) / mu.mean()
    if form == "ratio":  # |sin K2 / sin K1|
        return abs(series.order(int(words[2]))[1] / series.order(int(words[1]))[1])
    return {"max": series.max, "min": series.min, "mean": series.mean}[form]


def _torque_quantity(record, words):
    """``torque PART sin|cos K``, ``torque PART max|min|mean``, ``torque PART ratio K1 K2``
    (PART: inertia, frame, tilting, total), N·m in the record's unit; with ``difference``, the
    changed engine's minus the unchanged one's (torques are linear in the masses and rod
    inertias, so a difference is the part those changes contribute)."""
    # the papers' torques are of the moving parts alone: no gas, even where the engine has a cycle
    engine = dataclasses.replace(_variant(record), gas=None)
    part, rest = words[0], words[1:]
    value = _torque_value(_torque_result(engine, record), part, rest)
    if record.get("difference"):
        base = dataclasses.replace(_base(record), gas=None)
        value -= _torque_value(_torque_result(base, record), part, rest)
    if rest[0] in ("ratio", "variation"):
        return value
    if record["unit"] == "%":  # of a torque the paper gives, ``percent_of_kgfm``
        return 100.0 * value / STANDARD_GRAVITY / record["percent_of_kgfm"]
    return value / _unit(record["unit"], engine, None)


def _fraeys_coefficient(record, name, k):
    """Fraeys de Veubeke's U_k, V_k, R_k, T_k (kg: torques per R²Ω², forces per RΩ²) from the
    library: μ(θ) = 2R²(U₀ + Σ U_k/k·cos kθ), so the inertia torque −½Ω²dμ/dθ = R²Ω²·Σ U_k·sin kθ;
    the tilting couple R²Ω²·Σ V_k·sin kθ; the radial pin force RΩ²(R₀ + Σ R_k cos kθ); the pin
    force in the fixed frame RΩ²·Σ T_k·e^{ikθ}."""
    engine = _variant(record)
    result = _torque_result(engine, record)
    r, w = engine.crank_radius_m, engine.speed_rad_s
    if name == "U":
        return (
            result.reduced_mass.mean_kgm2 / (2 * r**2)
            if k == 0
            else result.inertia.order(k)[1] / (r * w) ** 2
        )
    if name == "V":
        return result.tilting.order(k)[1] / (r * w) ** 2
    pin = result.pins[0]
    if name == "R":
        return (pin.radial.mean if k == 0 else pin.radial.order(k)[0]) / (r * w**2)
    if name == "T":
        forward, backward = pin.order(abs(k))
        return (forward if k >= 0 else backward).real / (r * w**2)
    raise ValueError(name)


def _sinusoid(cylinders, mean, spread, samples=4096):
    """Margoulis's (3): C = C_m + (ΔC/2)·sin(Nθ/2) over a four-stroke's 720°."""
    theta = np.arange(samples) * 4 * np.pi / samples
    return mean + spread / 2 * np.sin(cylinders * theta / 2)


def _margoulis(record, form):
    """``margoulis rv_over_rc`` (N·r_v/r_c with ``_times_N``): the library's closed forms for a
    propeller of ℓ = 0.04·β·D⁵ and I = K·D⁵ (his (18), (19); D = 1, technical units: the g
    they carry cancels); ``margoulis integrated``: the library's integrated steadiness for
    ``cylinders``, ``inertia_kgm2``, ``mean_torque_Nm``, ``torque_range_Nm``, ``speed_rpm``,
    ``load``."""
    n = record["cylinders"]
    if form.startswith("rv_over_rc"):
        omega = 100.0
        ell, inertia = 0.04 * record["beta"], record["K"]
        mean = ell * omega**2
        # a torque range small enough that r_c ≈ 100: the mean speed stays the nominal one
        spread = omega**2 * n * inertia / 200.0
        factors = steadiness(
            _sinusoid(n, mean, spread), 720.0, inertia, omega, "propeller"
        ).margoulis()
        ratio = factors["r_v"] / factors["r_c"]
        return ratio * n if form.endswith("times_N") else ratio
    if form == "integrated":
        omega = record["speed_rpm"] * 2 * np.pi / 60
        curve = _sinusoid(n, record["mean_torque_Nm"], record["torque_range_Nm"])
        return steadiness(curve, 720.0, record["inertia_kgm2"], omega, record["load"]).factor
    raise ValueError(form)


def _link_first_harmonic(record):
    """Tanaka's k and α: sin φ' = k·sin(θ_T + α) fitted, as a first harmonic, to the exact
    lean of a link rod at φ from its master (θ_T = −θ, Tanaka's sense of angles)."""
    engine = _engine(record["config"])
    phi = math.radians(record["phi_deg"])
    master = engine.cylinder(1)
    link = next(c for c in engine.cylinders if c.is_link)
    # the knuckle pin's path depends on the master rod alone, not on the link's own axis: the
    # probe's link cylinder gets an axis a quarter turn away, since two banks may not coincide
    # (Table I starts at φ = 0)
    probe = dataclasses.replace(
        engine,
        bank_angles_rad=(0.0, phi + math.pi / 2),
        throws=engine.throws[:1],
        firing_order=None,
        cylinders=(
            dataclasses.replace(master, bank=1),
            dataclasses.replace(
                link,
                number=2,
                bank=2,
                master=1,
                knuckle_angle_rad=phi,
                **(
                    {"knuckle_radius_m": record["knuckle_radius_mm"] / 1000}
                    if "knuckle_radius_mm" in record
                    else {}
                ),
            ),
        ),
    )
    samples = 256
    theta = 2 * np.pi * np.arange(samples) / samples
    knuckle = linkage(probe, theta).knuckle[2]
    lean = -(knuckle * np.exp(-1j * phi)).imag / link.link_length_m  # sin φ'
    c1 = np.fft.fft(lean)[1] / samples
    # lean = A cos θ + B sin θ with A = 2 Re c1, B = −2 Im c1; in θ_T = −θ: A cos θ_T − B sin θ_T
    a, b = 2 * c1.real, 2 * c1.imag
    alpha = math.degrees(math.atan2(a, b)) % 360.0
    return {"k": math.hypot(a, b), "alpha": alpha - 360.0 if alpha > 359.0 else alpha}


def _fraeys_reduction(data):
    """Fraeys de Veubeke § 8, formulas (13)-(17), from the part data of Table VIII."""
    big_l, h_master, l_link, h_link = data["L_mm"], data["H_mm"], data["l_mm"], data["h_mm"]
    master, link, piston = data["B_kg"], data["b_kg"], data["p_kg"]
    radii = data["r_mm"]  # knuckle radii of the link cylinders, at ψ = 40°·(n − 1)
    psi = [math.radians(40 * n) for n in range(1, len(radii) + 1)]
    big_k, k = h_master / big_l, h_link / l_link
    m = (
        -link * (1 - k) / big_l * sum(r * math.cos(p) for r, p in zip(radii, psi, strict=True))
    )  # (13)
    return {
        "K": big_k,
        "k": k,
        "BK": master * big_k,
        "bk": link * k,
        "B(1-K)": master * (1 - big_k),
        "b(1-k)": link * (1 - k),
        "m": m,
        "a": piston + link * k,  # (14)
        "A": master * big_k - link * k - m,  # (15)
        "D": master * (1 - big_k) + len(radii) * link * (1 - k) + m,  # (17)
    }


def _gamma_sum(radii_mm, crank_radius_mm, power, k):
    """Fraeys de Veubeke's Table VII sums Σ γ_n^power·cos kψ_n, γ_n = r_n/R, ψ_n = 40°(n − 1)."""
    return sum(
        (r / crank_radius_mm) ** power * math.cos(math.radians(40 * n * k))
        for n, r in enumerate(radii_mm)
    )


def _series_check(name, record):
    """Coefficients of the classic series, measured on the exact slider-crank."""
    q = record.get("q", 0.25)
    engine = Engine(
        name="slider-crank",
        cycle=4,
        speed_rad_s=1.0,
        crank_radius_m=q,
        rod_length_m=1.0,
        bank_angles_rad=(0.0,),
        throws=(Throw(0.0),),
        cylinders=(Cylinder(1, 1, 1, 0.0, 1.0),),
    )
    samples = 256
    theta = 2 * np.pi * np.arange(samples) / samples
    travel = linkage(engine, theta).travel[1]  # = q·cos θ + √(1 − q² sin²θ)
    c = np.fft.fft(travel - q * np.cos(theta)).real / samples
    a2 = 2 * c[2]
    if name == "A2_q6":  # (A2 − q²/4 − q⁴/16)/q⁶ → the q⁶ coefficient as q → 0
        return (a2 - q**2 / 4 - q**4 / 16) / q**6
    if name == "B2":  # acceleration coefficient of cos 2θ, per r·ω²
        return 4 * a2 / q
    raise ValueError(name)


def evaluate(record, paper):
    """One figure of ``paper`` (a parsed paper file) against balance."""
    frames = paper.get("frames", {})
    if "data" in paper and "data" not in record:
        record = {**record, "data": paper["data"]}
    return Row(
        id=record["id"],
        paper=paper["paper"]["key"],
        where=record["where"],
        quantity=record["quantity"],
        unit=record.get("unit", ""),
        published=float(record["published"]),
        ours=float(_quantity(record, frames)),
        tolerance=float(record["tolerance"]),
        reason=record["reason"],
        erratum=record.get("erratum", ""),
        corrected=record.get("corrected"),
    )


def rows():
    """Every figure of every paper, evaluated."""
    return [evaluate(record, paper) for paper in papers() for record in paper["figure"]]
