"""Parameter sweeps: one configuration analysed again and again with one or two of its values
changed.

A parameter is a key of the configuration as written in the file (``rod_length``,
``banks[2].angle``, ``gas.imep``), or one a designer thinks in that is derived from those keys
(``rod_ratio``, ``stroke``, ``bore_pitch``: :mod:`.derived`). Each point sets the keys in the
parsed TOML and builds the engine with :func:`balance_cli.config.build`, so every value is
read and checked exactly as in a file, and a value that makes no engine is reported with the
file, the key and the value. The pseudo-parameter ``balance_factor`` instead balances the
point's engine with classic per-throw counterweights of that factor and reports what they
leave.

What is reported comes from the same records as ``compare``, ``counterweight`` and
``torque``: the quantities are read out of each point's ``to_dict()``-style records, so a
sweep agrees with those commands to the last digit.

``keys`` says what can be varied and how its values are written, ``derived`` the parameters
computed from the keys, ``values`` how values are checked and spaced, ``quantities`` what can
be reported, ``readout`` how a point's quantities are read, ``run`` the sweep's work and
``results`` what a sweep returns; :func:`sweep` (one parameter) and :func:`sweep_grid` (two)
are here.
"""

from collections.abc import Callable, Sequence

from ...analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES
from ...errors import SweepError
from .derived import DERIVED
from .keys import BALANCE_FACTOR, MAX_POINTS, SCHEMA, Parameter, parameter_of
from .quantities import DEFAULT_QUANTITIES, QUANTITY_NAMES, Quantity, quantities_of
from .results import SweepGrid, SweepResult
from .run import run_sweep
from .values import span

__all__ = [
    "SweepResult",
    "SweepGrid",
    "Parameter",
    "Quantity",
    "sweep",
    "sweep_grid",
    "span",
    "parameter_of",
    "quantities_of",
    "QUANTITY_NAMES",
    "DEFAULT_QUANTITIES",
    "BALANCE_FACTOR",
    "DERIVED",
    "SCHEMA",
    "MAX_POINTS",
]


def sweep(
    configuration,
    parameter: str,
    values: Sequence,
    quantities=None,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    *,
    inertia_kgm2: float | None = None,
    load: str = "propeller",
    overrides: "dict | None" = None,
    progress: "Callable[[int, int], None] | None" = None,
    mount_speeds_rpm=None,
) -> SweepResult:
    """Analyse ``configuration`` once per value of ``parameter``.

    Parameters
    ----------
    configuration : Configuration, str or PathLike
        a configuration (:func:`~balance_cli.read_configuration`, or
        ``balance.Configuration(data, path)`` of TOML parsed in code), or its file
    parameter : str
        a configuration key as written in the file: ``speed``, ``rod_length``,
        ``masses.rotating``, ``banks[2].angle``, ``throws[3].phase``, ``gas.imep``,
        ``cylinders[4].reciprocating``, ... (any number of the configuration; see
        :data:`SCHEMA`); a key of the [mounts] table, ``mounts.mass``,
        ``mounts.mount[2].stiffness[3]`` (the second mount's rate along z; a mount by number
        or name), ``mounts.mount[*].stiffness[3]`` (one value for every mount),
        ``mounts.mount[C].compression``, ``mounts.centre_of_gravity[3]``, ... (see
        :mod:`.mountkeys`); a parameter derived from the keys (:data:`DERIVED`): ``rod_ratio``
        (rod_length / crank_radius; sets rod_length, holds crank_radius), ``stroke``
        (2 × crank_radius; sets crank_radius, holds rod_length) or ``bore_pitch`` (the
        spacing of the throws' z; sets the throws' z, the first throw's held); or
        ``balance_factor`` (classic per-throw counterweights of that factor, 0 to 1, and what
        they leave)
    values : sequence
        as written in the file: text with a unit for a quantity ("140 mm", "3000 rpm"),
        numbers for angles (degrees), ratios and whole numbers (text holding a number is
        read as that number); :func:`span` makes evenly spaced ones
    quantities : str or sequence of str, optional
        what to report at each point (see :func:`quantities_of`); default the largest free
        force and moment after an ideal counterweight. Of the engine on its mounts
        (:mod:`.mountquantities`): ``mode_1`` to ``mode_6`` (Hz), ``roll_mode`` (the mode
        roll dominates; ``fore_aft``, ``lateral``, ``bounce``, ``pitch``, ``yaw`` alike),
        ``tra_purity`` (%), ``axes_angle`` (degrees), ``mount_A_force`` and
        ``mount_A_Fx``/``Fy``/``Fz`` (N: the largest over a cycle, orders up to
        ``max_order`` summed; a mount by name, spaces as _, or number)
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    inertia_kgm2 : float, optional
        flywheel inertia for the ``steadiness`` quantity, kg·m²
    load : str
        "propeller" or "constant", for the steadiness
    overrides : dict, optional
        other keys (or derived parameters) to set at every point, as written in the file
        (``{"speed": "3000 rpm"}``: the command line's ``--speed``); checked like the
        file's own values. The file's ``power`` is given at the file's speed: with another
        speed here, a PRU needs ``power`` here too
    progress : callable, optional
        ``progress(done, total)``, called with ``(0, total)`` before any work and after each
        step: ``total`` counts each point's engine built and checked (all of them first, so
        that a bad value is reported before any analysis), then each point analysed
    mount_speeds_rpm : sequence of float, optional
        the speeds, rpm, over which a mount's force quantity takes its largest; default each
        point's own speed

    Raises
    ------
    ConfigError
        the configuration itself cannot be read or built
    SweepError
        an unknown parameter or one the engine does not define (``parameter``), unusable
        values (``values``) or quantities (``quantities``; a mount quantity without a
        [mounts] table, a [mounts] key without a mount quantity), bad
        ``mount_speeds_rpm``, a steadiness without
        ``inertia_kgm2``, bad ``load``, ``overrides`` or ``progress``, a PRU without the
        power at the point's speed, or a point whose configuration is invalid (the message
        names the file, the key and the value; ``key`` and ``value`` say which)
    AnalysisError
        ``samples`` or ``max_order`` out of range
    """
    run = run_sweep(
        configuration,
        [parameter],
        [values],
        quantities,
        samples,
        max_order,
        inertia_kgm2,
        load,
        overrides,
        progress,
        grid=False,
        mount_speeds_rpm=mount_speeds_rpm,
    )
    return SweepResult(
        run["name"],
        run["config"],
        run["params"][0],
        run["values"][0],
        run["values_si"][0],
        run["quantities"],
        run["points"],
        run["engines"],
        **run["extras"],
    )


def sweep_grid(
    configuration,
    parameters: Sequence,
    values: Sequence,
    quantities=None,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    *,
    inertia_kgm2: float | None = None,
    load: str = "propeller",
    overrides: "dict | None" = None,
    progress: "Callable[[int, int], None] | None" = None,
    mount_speeds_rpm=None,
) -> SweepGrid:
    """Analyse ``configuration`` at every pair of values of two parameters.

    Parameters
    ----------
    configuration
        as for :func:`sweep`
    parameters : sequence of two str
        two parameters as :func:`sweep` takes them, which must not set the same key
        (``rod_ratio`` and ``rod_length`` both set rod_length). A derived parameter is set
        after the key it reads: ``stroke`` (or ``crank_radius``) with ``rod_ratio`` gives
        each point the ratio of its own crank radius
    values : sequence of two sequences
        each parameter's values, two or more each, as :func:`sweep` takes them; at most
        :data:`MAX_POINTS` pairs
    quantities, samples, max_order, inertia_kgm2, load, overrides, progress, mount_speeds_rpm
        as for :func:`sweep`

    Raises
    ------
    SweepError
        as for :func:`sweep`, with ``parameters`` for the parameters; a point's error names
        both keys and values (``key`` and ``value`` are then pairs)
    """
    if (
        isinstance(parameters, (str, bytes))
        or not isinstance(parameters, Sequence)
        or len(parameters) != 2
    ):
        raise SweepError(
            f"must be two parameters, such as ('rod_ratio', 'balance_factor'), got {parameters!r}",
            "parameters",
        )
    if isinstance(values, (str, bytes)) or not isinstance(values, Sequence) or len(values) != 2:
        raise SweepError(
            f"must be two lists of values, one per parameter, got {values!r}", "values"
        )
    run = run_sweep(
        configuration,
        list(parameters),
        list(values),
        quantities,
        samples,
        max_order,
        inertia_kgm2,
        load,
        overrides,
        progress,
        grid=True,
        mount_speeds_rpm=mount_speeds_rpm,
    )
    return SweepGrid(
        run["name"],
        run["config"],
        run["params"],
        run["values"],
        run["values_si"],
        run["quantities"],
        run["points"],
        run["engines"],
        **run["extras"],
    )
