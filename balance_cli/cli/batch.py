"""The engines a command works on: the files found, the engines loaded (at --speed), the
analysis settings checked, and the library run over them one by one, with a progress bar on a
terminal, warnings echoed once, and a library error naming its file.
"""

import contextlib
import sys
import warnings

import click

from ..analysis.results import analyse
from ..analysis.shaking import check_settings
from ..config import find_configs, load
from ..errors import SamplingWarning
from .group import reported
from .options import quantity_option

__all__ = [
    "progress",
    "progress_bar",
    "run_each",
    "inputs",
    "load_all",
    "settings",
    "analyse_all",
    "passed_over",
]


def progress(items, label):
    """A progress bar on a terminal for several items; nothing when output is not a terminal."""
    if len(items) > 1 and sys.stderr.isatty():
        return click.progressbar(items, label=label, file=sys.stderr)
    return contextlib.nullcontext(items)


def progress_bar(label):
    """A progress bar on standard error when it is a terminal, for work that reports
    ``(done, total)``: (callback or None, the context that closes the bar)."""
    if not sys.stderr.isatty():
        return None, contextlib.nullcontext()
    state: dict = {}

    def update(done, total):
        if "bar" not in state:
            state["bar"] = click.progressbar(length=total, label=label, file=sys.stderr)
            state["bar"].__enter__()
        state["bar"].update(done - state["bar"].pos)

    @contextlib.contextmanager
    def closing():
        try:
            yield
        finally:
            if "bar" in state:
                state["bar"].__exit__(None, None, None)

    return update, closing()


def run_each(items, label, work):
    """``work(item)`` for every item: a progress bar on a terminal, warnings echoed once on
    standard error after the bar, a library error as one line naming its file."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SamplingWarning)
        results = []
        try:
            with progress(items, label) as bar:
                for item in bar:
                    with reported(getattr(item, "engine", item)):
                        results.append(work(item))
        finally:
            # warnings of the engines done before an error are still worth seeing
            for w in caught:
                text = (
                    f"{w.message} (--samples)"
                    if issubclass(w.category, SamplingWarning)
                    else w.message
                )
                click.echo(f"warning: {text}", err=True)
    return results


def inputs(paths):
    """The configuration files under ``paths``, found before anything is computed."""
    with reported():
        return find_configs(paths)


def load_all(files, speed=None):
    """The engines of ``files``, at ``speed`` (the --speed text) when given."""
    speed_rad_s = quantity_option(speed, "--speed", "angular speed")
    with reported():
        engines = [load(f) for f in files]
    if speed_rad_s is None:
        return engines
    out = []
    for engine in engines:
        with reported(engine):
            out.append(engine.replace(speed_rad_s=speed_rad_s))
    return out


def settings(samples, max_order):
    with reported():
        check_settings(samples, max_order)


def analyse_all(engines, samples, max_order):
    return run_each(engines, "Analysing", lambda e: analyse(e, samples, max_order))


def passed_over(engines, takes, why, none_message):
    """Of several engines, those the command ``takes``; the others named on standard error
    with ``why`` (engine -> text), and an error when none is left. One engine alone is kept,
    for the command to refuse with its own message."""
    if len(engines) < 2:
        return engines
    for engine in engines:
        if not takes(engine):
            click.echo(f"note: {engine.config_path}: {why(engine)}; passed over", err=True)
    kept = [e for e in engines if takes(e)]
    if not kept:
        raise click.ClickException(none_message)
    return kept
