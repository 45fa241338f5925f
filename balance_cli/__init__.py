"""balance: compare reciprocating-engine layouts for mechanical balance, exactly, order by order.

The package is a library first; the ``balance`` command is a thin face of it::

    import balance_cli as balance

    engine = balance.load("configs/inline-4-car.toml")
    result = balance.analyse(engine, samples=256, max_order=8)
    result.order(2).force_forward          # complex phasor, N
    bal = balance.counterweights(engine, planes=[1, 4], radius_m=0.06)
    fig = balance.plot.locus([result])     # matplotlib Figure (balance.plot loads matplotlib)

Every error is a :class:`BalanceError`. SI units and radians throughout; see the README's
"Python API" for every name, unit and exception.
"""

__version__ = "0.1.0"

from .analysis.results import Comparison, EngineResult, analyse, compare  # noqa: E402
from .config import find_configs, load, load_many, load_template, loads  # noqa: E402
from .analysis.balancing import Antivibrateur, Balance, Counterweight, Plane, Shaft
from .analysis.counterweight import counterweights
from .errors import (AnalysisError, BalanceError, ConfigError, CounterweightError, FiringError,
                     ModelError, OrderError, OutputError, PlotError, SamplingWarning, UnitError)
from .analysis.firing import Firing  # noqa: E402
from .analysis.pressure import PressureCurve, read_cycle_csv, read_pressure_csv  # noqa: E402
from .model import Cylinder, Engine, GasCycle, Parts, Throw  # noqa: E402
from .studies.regress import Moved, Regression, RegressError, regression  # noqa: E402
from .analysis.shaking import OrderComponents, Shaking  # noqa: E402
from .analysis.steadiness import Steadiness, flywheel_for, steadiness  # noqa: E402
from .analysis.pins import PinForce  # noqa: E402
from .analysis.series import ReducedMass, Series  # noqa: E402
from .analysis.torque import TorqueResult, TorqueSet, torque  # noqa: E402

__all__ = [
    "load", "loads", "load_many", "find_configs", "analyse", "compare", "counterweights",
    "regression", "plot", "Regression", "Moved",
    "torque", "TorqueResult", "TorqueSet", "Series", "ReducedMass", "PinForce",
    "steadiness", "flywheel_for", "Steadiness", "read_pressure_csv", "read_cycle_csv",
    "PressureCurve", "Parts", "GasCycle", "search", "load_template", "SearchResult",
    "Arrangement", "Term",
    "Engine", "Cylinder", "Throw", "EngineResult", "Comparison", "Shaking", "OrderComponents",
    "Firing", "Balance", "Counterweight", "Plane", "Shaft", "Antivibrateur",
    "BalanceError", "ConfigError", "ModelError", "FiringError", "AnalysisError",
    "CounterweightError", "PlotError", "OutputError", "UnitError", "RegressError", "OrderError",
    "SamplingWarning",
]


#: names loaded on first use: commands that neither draw nor search start without them
_LAZY = {"plot": (".plot", None), "search": (".cranksearch", "search"),
         "SearchResult": (".cranksearch", "SearchResult"),
         "Arrangement": (".cranksearch", "Arrangement"), "Term": (".cranksearch", "Term")}

# the sweep loads on first use too; a statement of its own keeps merges of the lists above simple
_LAZY.update({"sweep": (".studies.sweep", "sweep"), "SweepResult": (".studies.sweep", "SweepResult"),
              "family": (".studies.family", "family"), "FamilyResult": (".studies.family", "FamilyResult"),
              "GuideForces": (".analysis.guideforce", "GuideForces")})
__all__ += ["sweep", "SweepResult", "SweepError", "family", "FamilyResult", "GuideForces",
            "load_data", "power_related_unbalance", "PowerRelatedUnbalance"]
from .config import load_data  # noqa: E402
from .analysis.marine import PowerRelatedUnbalance, power_related_unbalance  # noqa: E402
from .errors import SweepError  # noqa: E402
# counterweights and balancer shafts as built (a statement of its own, for the same reason)
__all__ += ["CounterweightMass", "BalancerMass", "BalancerShaftSpec"]
from .model import BalancerMass, BalancerShaftSpec, CounterweightMass  # noqa: E402

# torsional vibration (openTorsion, an optional extra) on first use too; not named "torsion",
# which is its module's name
_LAZY.update({"torsional_vibration": (".torsion", "torsional_vibration"),
              "TorsionResult": (".torsion", "TorsionResult"),
              "TorsionUnavailable": (".errors", "TorsionUnavailable"),
              "cylinder_torques": (".analysis.cylinders", "cylinder_torques"),
              "CylinderTorque": (".analysis.cylinders", "CylinderTorque"),
              "TorsionModel": (".model", "TorsionModel"), "ShaftDisk": (".model", "ShaftDisk")})
__all__ += ["torsional_vibration", "TorsionResult", "TorsionUnavailable", "cylinder_torques",
            "CylinderTorque", "TorsionModel", "ShaftDisk"]


def __getattr__(name):
    # balance.plot imports matplotlib, which the commands that do not draw never load
    if name in _LAZY:
        import importlib

        module, attribute = _LAZY[name]
        loaded = importlib.import_module(module, __name__)
        return loaded if attribute is None else getattr(loaded, attribute)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

# several crankshafts (issue 19): a statement of its own, as above
from .model import Crankshaft  # noqa: E402
from .analysis.torque import CrankshaftTorque  # noqa: E402
__all__ += ["Crankshaft", "CrankshaftTorque"]
