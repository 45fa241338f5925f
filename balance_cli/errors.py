"""Every error and warning balance raises, under one base a caller can catch.

Library errors name the library's own parameters (``radius_m must be greater than zero``);
front ends put their own names in place of them: the configuration reader its keys, the
command line its flags. An error that concerns one parameter keeps it in ``parameter`` and the
rest of the sentence in ``problem``, so a front end can say ``--radius must be greater than
zero`` without parsing the message.
"""

__all__ = [
    "BalanceError",
    "UnitError",
    "ConfigError",
    "ModelError",
    "FiringError",
    "AnalysisError",
    "CounterweightError",
    "PlotError",
    "OutputError",
    "SamplingWarning",
    "OrderError",
    "SweepError",
    "RegressError",
    "TorsionUnavailable",
    "PandasUnavailable",
    "NotInResultError",
]


class BalanceError(Exception):
    """Base of every error balance raises.

    Parameters
    ----------
    problem : str
        what is wrong and what to do about it
    parameter : str, optional
        the parameter (function argument or model field) the problem is about; when given,
        the message reads ``"<parameter> <problem>"``
    """

    def __init__(self, problem, parameter=None):
        self.problem, self.parameter = problem, parameter
        super().__init__(f"{parameter} {problem}" if parameter else problem)

    def named(self, names):
        """The message with ``parameter`` replaced by ``names[parameter]`` where it has one."""
        if self.parameter and self.parameter in names:
            return f"{names[self.parameter]} {self.problem}"
        return str(self)


class UnitError(BalanceError, ValueError):
    """A value whose unit is missing, unknown or of the wrong dimension, or whose number is not
    finite or outside the range balance accepts."""


class ModelError(BalanceError, ValueError):
    """An engine that cannot exist: a field out of range, a bad reference, two cylinders in one
    bore, a firing order that is not a permutation, a linkage that cannot be assembled.

    ``cylinder`` is the number of the cylinder concerned, when there is one.
    """

    def __init__(self, problem, parameter=None, cylinder=None):
        self.cylinder = cylinder
        super().__init__(problem, parameter)


class ConfigError(BalanceError, ValueError):
    """A configuration that cannot be read; the message names the file, the key and the fix."""

    def __init__(self, path, key, problem):
        self.path, self.key = str(path), key
        where = f"{self.path}: {key}: " if key else f"{self.path}: "
        super().__init__(problem)
        self.args = (where + problem,)

    def __str__(self):
        return self.args[0]


class FiringError(BalanceError, ValueError):
    """A firing order that does not fit the crank."""


class AnalysisError(BalanceError, ValueError):
    """Analysis settings that cannot work (too few samples for the orders asked, say)."""


class NotInResultError(AnalysisError, KeyError):
    """Something a result does not hold: an order (:class:`OrderError`), a cylinder
    (``CylinderTorques.cylinder(n)``), a quantity (``SweepResult.series(q)``); a KeyError too,
    as a lookup's error is."""

    def __str__(self):
        return self.args[0]  # a KeyError's own str() would quote the message


class OrderError(NotInResultError):
    """An order that a result does not hold (``result.order(k)``)."""


class CounterweightError(BalanceError, ValueError):
    """A balancing request that cannot be carried out (bad planes, radius, orders)."""


class PlotError(BalanceError, ValueError):
    """A picture that cannot be drawn as asked (no engines, unknown units or file format)."""


class OutputError(BalanceError, OSError):
    """An output that cannot be written; nothing was left behind."""

    def __str__(self):
        return self.problem


class SamplingWarning(UserWarning):
    """The sampling is too coarse for the orders asked for.

    Attributes
    ----------
    samples : int or None
        the samples a revolution found too few
    excess : float or None
        what was found too large, as a fraction: the aliasing error bound of the inertia
        forces (:func:`balance_cli.harmonics.check_sampling`) or the move of the mean gas
        torque on a finer sampling (:func:`balance_cli.analysis.gas.check_gas_sampling`)
    """

    def __init__(self, message, samples=None, excess=None):
        super().__init__(message)
        self.samples, self.excess = samples, excess


class SweepError(BalanceError, ValueError):
    """A sweep that cannot be run: a parameter the configuration has no key for, values or
    quantities that cannot be used, or a point whose configuration is invalid (then ``key`` and
    ``value`` say which, ``cause`` is the error the configuration gave, and the message names
    the file, the key and the value)."""

    def __init__(self, problem, parameter=None, key=None, value=None, cause=None):
        self.key, self.value, self.cause = key, value, cause
        super().__init__(problem, parameter)


class RegressError(BalanceError, ValueError):
    """A baseline that is not a comparison balance can check against."""


class TorsionUnavailable(BalanceError, ImportError):
    """openTorsion, which torsional vibration needs, is not installed."""


class PandasUnavailable(BalanceError, ImportError):
    """pandas, which a result's ``to_pandas()`` needs, is not installed (``records()`` gives
    the same rows without it)."""
