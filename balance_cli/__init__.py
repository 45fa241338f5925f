"""balance: compare reciprocating-engine layouts for mechanical balance, exactly, order by order.

The package is a library first; the ``balance`` command is a thin face of it::

    import balance_cli as balance

    engine = balance.load("configs/inline-4-car.toml")
    result = balance.analyse(engine, samples=256, max_order=8)
    result.order(2).force_forward          # complex phasor, N
    bal = balance.counterweights(engine, planes=[1, 4], radius_m=0.06)
    fig = balance.plot.locus([result])     # matplotlib Figure (balance.plot loads matplotlib)

Every error is a :class:`BalanceError`. SI units and radians inside; a parameter in another
unit says it in its name (``speed_rpm``, ``angle_deg``). Cylinders, throws, banks, crankshafts
and planes are numbered from 1, as in the files and the tables. See the documentation's "Use
balance from Python" and its API reference for every name, unit and exception.

The names below load on first use where they need what most commands do not (matplotlib for
:mod:`balance_cli.plot`, the search, sweeps, families, torsional vibration, mounts and the
workshop's matching, tolerances and bobweights), so that
``balance compare`` starts fast; ``dir(balance_cli)`` lists them all.
"""

import importlib

from .about import __version__
from .analysis.balancing import (
    Antivibrateur,
    Balance,
    BalancerShaft,
    Balances,
    Counterweight,
    Plane,
    RollingMoment,
    Shaft,
    ShaftMass,
)
from .analysis.counterweight import counterweights
from .analysis.cylinders import CylinderTorque, CylinderTorques, cylinder_torques
from .analysis.firing import Firing
from .analysis.guideforce import GuideForces
from .analysis.marine import (
    FirstOrderBalance,
    PowerRelatedUnbalance,
    first_order_balance,
    power_related_unbalance,
)
from .analysis.pins import PinForce
from .analysis.pressure import CycleCurve, PressureCurve, read_cycle_csv, read_pressure_csv
from .analysis.results import Comparison, EngineResult, analyse, compare
from .analysis.series import ReducedMass, Series
from .analysis.shaking import OrderComponents, Shaking
from .analysis.steadiness import Steadiness, flywheel_for, steadiness
from .analysis.torque import CrankshaftTorque, TorqueResult, TorqueSet, torque
from .config import (
    Configuration,
    find_configs,
    load,
    load_many,
    load_template,
    loads,
    read_configuration,
)
from .errors import (
    AnalysisError,
    BalanceError,
    ConfigError,
    CounterweightError,
    FiringError,
    ModelError,
    NotInResultError,
    OrderError,
    OutputError,
    PandasUnavailable,
    PlotError,
    RegressError,
    SamplingWarning,
    SweepError,
    TorsionUnavailable,
    UnitError,
)
from .model import (
    BalancerMass,
    BalancerShaftSpec,
    CounterweightMass,
    Crankshaft,
    Cylinder,
    Engine,
    GasCycle,
    Mount,
    MountSystem,
    Parts,
    ShaftDisk,
    Throw,
    ToleranceBand,
    TorsionModel,
)
from .studies.regress import Moved, Regression, regression
from .tabular import set_html_renderer

#: public names loaded on first use: name -> (module, attribute; None for the module itself)
_LAZY = {
    "plot": (".plot", None),
    "search": (".cranksearch", "search"),
    "SearchResult": (".cranksearch", "SearchResult"),
    "Arrangement": (".cranksearch", "Arrangement"),
    "Term": (".cranksearch", "Term"),
    "sweep": (".studies.sweep", "sweep"),
    "SweepResult": (".studies.sweep", "SweepResult"),
    "sweep_grid": (".studies.sweep", "sweep_grid"),
    "SweepGrid": (".studies.sweep", "SweepGrid"),
    "family": (".studies.family", "family"),
    "FamilyResult": (".studies.family", "FamilyResult"),
    "torsional_vibration": (".torsion", "torsional_vibration"),
    "TorsionResult": (".torsion", "TorsionResult"),
    "mounts": (".mounting", "mounts"),
    "MountResult": (".mounting", "MountResult"),
    "decouple": (".mounting", "decouple"),
    "Decoupling": (".mounting", "Decoupling"),
    "match": (".workshop", "match"),
    "MatchResult": (".workshop", "MatchResult"),
    "Fitting": (".workshop", "Fitting"),
    "PartSet": (".workshop", "PartSet"),
    "read_parts_csv": (".workshop", "read_parts_csv"),
    "tolerance": (".workshop", "tolerance"),
    "ToleranceResult": (".workshop", "ToleranceResult"),
    "bobweights": (".workshop", "bobweights"),
    "BobweightSheet": (".workshop", "BobweightSheet"),
}

#: the subpackages, reachable as attributes whether or not something has imported them yet
_PACKAGES = (
    "about",
    "analysis",
    "checks",
    "cli",
    "config",
    "cranksearch",
    "errors",
    "harmonics",
    "kinematics",
    "model",
    "mounting",
    "output",
    "report",
    "studies",
    "tabular",
    "tolerances",
    "torsion",
    "units",
    "workshop",
)

__all__ = [
    # the engine and where it comes from
    "load",
    "loads",
    "load_many",
    "load_template",
    "find_configs",
    "Configuration",
    "read_configuration",
    "Engine",
    "Cylinder",
    "Throw",
    "Crankshaft",
    "Parts",
    "GasCycle",
    "CounterweightMass",
    "BalancerMass",
    "BalancerShaftSpec",
    "TorsionModel",
    "ShaftDisk",
    "MountSystem",
    "Mount",
    "ToleranceBand",
    # shaking forces and moments, firing, comparison
    "analyse",
    "compare",
    "EngineResult",
    "Comparison",
    "Shaking",
    "OrderComponents",
    "Firing",
    "power_related_unbalance",
    "PowerRelatedUnbalance",
    "first_order_balance",
    "FirstOrderBalance",
    # counterweights and balancer shafts
    "counterweights",
    "Balance",
    "Balances",
    "Counterweight",
    "Plane",
    "Shaft",
    "ShaftMass",
    "BalancerShaft",
    "RollingMoment",
    "Antivibrateur",
    # torques, steadiness, gas pressure
    "torque",
    "TorqueResult",
    "TorqueSet",
    "Series",
    "ReducedMass",
    "PinForce",
    "CrankshaftTorque",
    "GuideForces",
    "cylinder_torques",
    "CylinderTorque",
    "CylinderTorques",
    "steadiness",
    "flywheel_for",
    "Steadiness",
    "read_pressure_csv",
    "read_cycle_csv",
    "PressureCurve",
    "CycleCurve",
    # studies, search, torsion, mounts, pictures (loaded on first use)
    "regression",
    "Regression",
    "Moved",
    *_LAZY,
    # errors and warnings
    "BalanceError",
    "ConfigError",
    "ModelError",
    "FiringError",
    "AnalysisError",
    "CounterweightError",
    "PlotError",
    "OutputError",
    "UnitError",
    "RegressError",
    "OrderError",
    "NotInResultError",
    "SweepError",
    "TorsionUnavailable",
    "PandasUnavailable",
    "SamplingWarning",
    "__version__",
]


def _result_html(result):
    """A result's HTML in Jupyter: the table the command line prints (the report layer, loaded
    when a notebook first shows a result)."""
    from .report.notebook import result_html

    return result_html(result)


# the results' layers lie below the report and cannot name it: the root, above every layer,
# hands them the renderer (balance_cli.tabular)
set_html_renderer(_result_html)


def __getattr__(name):
    if name in _LAZY:
        module, attribute = _LAZY[name]
        loaded = importlib.import_module(module, __name__)
        return loaded if attribute is None else getattr(loaded, attribute)
    if name in _PACKAGES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(__all__) | set(globals()))
