"""The quantities of one analysed point, read from the records ``compare``, ``counterweight``
and ``torque`` write, so that a sweep agrees with those commands to the last digit."""

from ...analysis.counterweight import counterweights
from ...errors import SweepError

__all__ = ["measure"]


def measure(result, wanted, balance_factor, samples, max_order, torque_of, inertia, load):
    """Every quantity of ``wanted`` at one point, SI.

    ``result`` is the point's analysis; ``balance_factor`` (or None) the factor of classic
    per-throw counterweights whose residual replaces the engine's shaking; ``torque_of`` the
    torque analysis when a torque or the steadiness is wanted (else None).
    """
    engine = result.engine
    if balance_factor is not None:
        shaking = counterweights(result, balance_factor=balance_factor).residual
        largest_force = _above(shaking.largest_force(), engine.noise_floor_n)
        largest_moment = _above(shaking.largest_moment(), engine.noise_floor_nm)
    else:
        shaking = result.shaking
        largest_force, largest_moment = (
            result.counterweighted_force_n,
            result.counterweighted_moment_nm,
        )
    orders = shaking.records(engine)
    torques = None
    if torque_of is not None:
        steady = any(q.kind == "steadiness" for q in wanted)
        torques = torque_of(
            engine,
            samples,
            max_order,
            inertia_kgm2=inertia if steady else None,
            load=load,
            bearings=False,
            guide=False,
        )
    record = {}
    for q in wanted:
        if q.kind == "pru":
            pru = result.power_related_unbalance(orders=(q.order,))
            if not pru.available:
                raise SweepError(f"{q.name} at this point: {pru.note}", "quantities")
            record[q.column] = pru.orders[0][f"{q.part}_Nm_per_kW"]
        elif q.order is not None:
            record[q.column] = orders[q.order - 1][q.kind][f"{q.part}_{q.unit}"]
        elif q.name == "largest_force":
            record[q.column] = largest_force
        elif q.name == "largest_moment":
            record[q.column] = largest_moment
        else:
            # the steadiness or a torque: the sweep gives torque_of when one is wanted
            assert torques is not None
            if q.name == "steadiness":
                record[q.column] = torques.steadiness.factor
            else:
                total = torques.total
                record[q.column] = {
                    "torque_mean": total.mean,
                    "torque_max": total.max,
                    "torque_min": total.min,
                    "torque_range": total.range,
                }[q.name]
    return record


def _above(value, floor):
    return value if value >= floor else 0.0
