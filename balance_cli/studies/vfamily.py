"""The V engine family's own rules: how the makers of medium-speed V engines fire their banks
and what they weigh (:func:`balance_cli.studies.family.family` on a template of two banks).

Each bank fires evenly on its own, its firing order an in-line engine's, and the other bank's
cylinder on each throw follows its partner by the bank angle Δ (or Δ and a revolution): the
Wärtsilä Vasa 32 project guide's 12V32 fires A1-B1-A5-B5-A3-B3-A6-B6-A2-B2-A4-B4, bank A the
6R32's 1-5-3-6-2-4. The crank is the one with the least free moments, and of the two ways the
banks can follow each other the one that excites the torsional major orders least: the orders
at which every cylinder of a bank fires in phase, where the two banks add as
|1 + e^{ik·Δ}|/2.
"""

import math

import numpy as np

from ..analysis import marine
from ..analysis.firing import firing_angles
from ..analysis.results import analyse
from ..config import build

__all__ = ["v_objective", "major_orders", "bank_phasing"]


def _one_throw_couples(data, path, samples, max_order, balance):
    """c_k for k = 1, 2, 4 (within ``max_order``): the pitching plus yawing order-k couple
    (N·m) of an engine of the family's throws per metre of |S_k| = |Σ (z_j − z̄)·e^{ikβ_j}|.

    Identical throws turned by β_j make each order's free couple |S_k| times one throw's force
    phasors (forward, and backward turned the other way), so its vertical and horizontal
    amplitudes are |S_k| times fixed figures, whatever the banks. Measured on two throws 1 m
    apart at 0° and 180°/k (|S_k| = 1 m exactly), the first order under ``balance``."""
    one = {k: v for k, v in data.items() if k not in ("throws", "power", "firing_order")}
    out = {}
    for k in (1, 2, 4):
        if k > max(2, max_order):
            continue
        case = {**one, "throws": [{"z": "0 m", "phase": 0.0}, {"z": "1 m", "phase": 180.0 / k}]}
        result = analyse(build(case, path), samples, max(k, 2))
        if k == 1:
            moment = marine.first_order_moments(result, balance)
            assert moment is not None  # one crankshaft, not a rotary: counterweights apply
        else:
            moment = result.order_records()[k - 1]["moment"]
        out[k] = moment["vertical_Nm"] + moment["horizontal_Nm"]
    return out


def v_objective(data, path, samples, max_order, balance):
    """A V family's default objective: M1V + M1H + M2V + M2H + M4V + M4H in N·m (per pitch),
    the search's M_k (|S_k| over the pitch, for identical throws) weighted by their couples
    c_k over c_2 (:func:`_one_throw_couples`)."""
    c = _one_throw_couples(data, path, samples, max_order, balance)
    scale = c.get(2) or max(c.values())
    if scale == 0.0:
        return "M1,M2"
    terms = []
    for k, value in c.items():
        if value > 0.0:
            terms.append(f"M{k}" if value == scale else f"M{k}:{value / scale:.6g}")
    return ",".join(terms)


def major_orders(engine, banks=1, count=2):
    """The engine's first ``count`` major orders of one bank, with their vector sums:
    ((order, |Σ_c e^{ik·φ_c}| / n), ...) over the cylinders' firing angles φ_c (equal
    cylinders, a rigid shaft: 1 where every cylinder fires in phase).

    A bank of m cylinders fires every cycle/m degrees, so its cylinders are in phase at the
    orders k = j·m·360/cycle (j = 1, 2, ...: for a four-stroke m/2, m, ...). An in-line
    engine's sum is 1 there; a V engine's two banks, Δ apart, give |1 + e^{ik·Δ}| / 2, the
    torsional excitation the makers weigh when they choose how the banks follow each other.
    """
    angles = np.radians(list(firing_angles(engine).values()))
    per_bank = engine.n_cylinders / banks
    step = per_bank * 360.0 / engine.cycle_deg
    out = []
    for j in range(1, count + 1):
        k = j * step
        total = abs(np.exp(1j * k * angles).sum()) / engine.n_cylinders
        out.append((float(k), float(total)))
    return tuple(out)


def bank_phasing(result, case, path, samples, max_order):
    """Of the two ways a V's banks can follow each other (bank B's cylinder the bank angle
    after its partner, or that and a revolution), the one whose first major orders are
    excited least (the first, then the second; ties keep the search's): (result, majors)."""
    engine = result.engine
    majors = major_orders(engine, 2)
    if engine.cycle != 4:
        return result, majors
    bank_a = {c.number for c in engine.cylinders if c.bank_index == 0}
    angles = firing_angles(engine)
    turned = {c: (a if c in bank_a else (a + 360.0) % 720.0) for c, a in angles.items()}
    order = sorted(turned, key=lambda c: (turned[c] - turned[1]) % 720.0)
    other = {
        **case,
        "throws": [
            {**t, "phase": math.degrees(throw.phase_rad) % 360.0}
            for t, throw in zip(case["throws"], engine.throws, strict=True)
        ],
        "firing_order": order,
    }
    alternative = analyse(build(other, path), samples, max_order)
    theirs = major_orders(alternative.engine, 2)
    if [round(v, 9) for _, v in theirs] < [round(v, 9) for _, v in majors]:
        return alternative, theirs
    return result, majors
