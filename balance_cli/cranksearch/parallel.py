"""The exhaustive search's work shared out: among local processes (fork, a shared
threshold) or among the workers of a Dask cluster.
"""

from __future__ import annotations

import math
import os

from ..about import install_hint
from ..errors import AnalysisError
from .kernel import evaluate

__all__ = ["run_local", "run_cluster"]

_WORKER: dict = {}


def _init_worker(problem, top, shared):
    # Ctrl-C reaches every process of the terminal's group: the parent stops the pool, and a
    # worker's own KeyboardInterrupt would only print a stray traceback
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER.update(problem=problem, top=top, shared=shared)


def _worker_chunk(units):
    return evaluate(_WORKER["problem"], units, _WORKER["top"], shared=_WORKER["shared"])


def _cluster_chunk(problem, units, top, threshold):
    return evaluate(problem, units, top, threshold)


def _chunks(units, n):
    size = max(1, len(units) // n)
    return [units[i : i + size] for i in range(0, len(units), size)]


def _cores():
    """Cores this process may run on: more processes than these only share them."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def run_local(problem, units, top, workers, threshold, progress):
    """(chunks, processes that ran): the processes are capped at the cores and at the
    pieces of work, which is what helps (1000 asked took 4.5 s where two took 1 s)."""
    workers = min(workers, _cores())
    if workers <= 1 or len(units) < 2:
        out = []
        for piece in _chunks(units, 50):
            out.append(evaluate(problem, piece, top, threshold))
            threshold = min(threshold, _pool_threshold(out, top))
            if progress:
                progress(len(piece))
        return out, 1
    import multiprocessing
    import signal

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else None)
    shared = context.Value("d", threshold)
    out = []
    pieces = _chunks(units, 16 * workers)
    processes = min(workers, len(pieces))
    # forked workers ignore Ctrl-C from their first instruction (the initializer comes later)
    try:
        handler = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # not the main thread: signals are not ours to change
        handler = None
    try:
        pool = context.Pool(processes, _init_worker, (problem, top, shared))
    finally:
        if handler is not None:
            signal.signal(signal.SIGINT, handler)
    with pool:
        for piece, chunk in zip(pieces, pool.imap(_worker_chunk, pieces), strict=True):
            out.append(chunk)
            if progress:
                progress(len(piece))
    return out, processes


#: seconds to wait for a Dask scheduler to answer
_CONNECT_S = 10


def run_cluster(problem, units, top, threshold, scheduler, progress):
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise AnalysisError(
            f"needs the optional cluster support: {install_hint('cluster')} (dask distributed)",
            "scheduler",
        ) from None
    given = not isinstance(scheduler, str)  # a caller's Client: theirs to close
    client = scheduler if given else None
    try:
        if client is None:
            try:
                client = Client(scheduler, timeout=f"{_CONNECT_S}s")
            except (OSError, TimeoutError) as exc:
                raise AnalysisError(
                    f"{scheduler!r} did not answer within {_CONNECT_S} s ({exc}); "
                    "check that the scheduler runs there",
                    "scheduler",
                ) from None
            except (ValueError, TypeError):
                raise AnalysisError(
                    f"{scheduler!r} is not a scheduler address such as tcp://host:8786", "scheduler"
                ) from None
        remote = client.scatter(problem, broadcast=True)
        pieces = _chunks(units, 16 * max(1, sum(client.nthreads().values())))
        futures = [
            client.submit(_cluster_chunk, remote, piece, top, threshold, pure=False)
            for piece in pieces
        ]
        sizes = {f.key: len(p) for f, p in zip(futures, pieces, strict=True)}
        out = []
        for future in as_completed(futures):
            out.append(future.result())
            if progress:
                progress(sizes[future.key])
        return out, sum(client.nthreads().values())
    finally:
        if client is not None and not given:
            client.close()


def _pool_threshold(chunks, top):
    scores = sorted(s for c in chunks for s, _ in c.candidates)
    return scores[top - 1] if len(scores) >= top else math.inf
