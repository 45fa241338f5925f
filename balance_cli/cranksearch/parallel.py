"""The exhaustive search's work shared out: among local processes (fork, a shared
threshold) or among the workers of a Dask cluster (one task per piece of work, a window of
them in flight, each sent with the best threshold known when it leaves), the results merged
as they come back.
"""

from __future__ import annotations

import gc
import math
import os

from ..about import install_hint
from ..errors import AnalysisError
from .kernel import Pool

__all__ = ["Reduction", "pieces_of", "run_local", "run_cluster"]

_WORKER: dict = {}


class Reduction:
    """The best classes of every piece returned so far, merged as each comes back (the
    parent never holds more than the pool), with the counts the proof adds up."""

    def __init__(self, problem, top):
        self.pool = Pool(problem, top)
        self.top = top
        self.evaluated = self.pruned = 0
        self.truncated = False
        self.pieces = 0

    def add(self, chunk):
        for score, key in chunk.candidates:
            self.pool.offer(score, key)
        self.evaluated += chunk.evaluated
        self.pruned += chunk.pruned
        self.truncated |= chunk.truncated
        self.pieces += 1

    @property
    def threshold(self):
        """The K-th best score returned so far (inf before K classes): a bound every worker
        may prune with."""
        scores = sorted(self.pool.best.values())
        return scores[self.top - 1] if len(scores) >= self.top else math.inf


def _init_worker(problem, top, shared, evaluate):
    # Ctrl-C reaches every process of the terminal's group: the parent stops the pool, and a
    # worker's own KeyboardInterrupt would only print a stray traceback
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER.update(problem=problem, top=top, shared=shared, evaluate=evaluate)


def _worker_chunk(units):
    w = _WORKER
    return w["evaluate"](w["problem"], units, w["top"], shared=w["shared"])


def _cluster_chunk(evaluate, problem, units, top, threshold):
    _keep_freed_memory()
    return evaluate(problem, units, top, threshold)


#: glibc's mallopt parameters (malloc.h)
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3


def _keep_freed_memory():
    """Let this process's allocator keep what the search frees, once per process.

    Dask starts its workers with MALLOC_TRIM_THRESHOLD_=65536, to hand freed memory back to
    the system at once; glibc then maps every array above 128 kB afresh and unmaps it when
    freed, and the search's pieces (a megabyte each, made and dropped thousands of times a
    second) paid a page fault for every page: an in-line 14 took 3.6 core-seconds on a
    LocalCluster where the same processes without it took 1.2 (and 3.65 s locally with the
    variable set). Up to 32 MB arrays are taken from the heap again and 64 MB of it kept.
    Nothing happens where glibc is not the C library."""
    if _WORKER.get("tuned"):
        return
    _WORKER["tuned"] = True
    try:
        import ctypes

        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(_M_MMAP_THRESHOLD, 32 << 20)
        libc.mallopt(_M_TRIM_THRESHOLD, 64 << 20)
    except (OSError, AttributeError):
        pass


def pieces_of(units, weights, n):
    """``units`` cut into about ``n`` consecutive pieces of about equal weight (work)."""
    total = sum(weights) or 1
    share = total / max(n, 1)
    pieces, piece, held = [], [], 0.0
    for unit, weight in zip(units, weights, strict=True):
        piece.append(unit)
        held += weight
        if held >= share:
            pieces.append(piece)
            piece, held = [], 0.0
    if piece:
        pieces.append(piece)
    return pieces


def _cores():
    """Cores this process may run on: more processes than these only share them."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def run_local(problem, units, weights, top, workers, evaluate, progress):
    """(reduction, processes that ran): the processes are capped at the cores and at the
    pieces of work, which is what helps (1000 asked took 4.5 s where two took 1 s)."""
    workers = min(workers, _cores())
    reduction = Reduction(problem, top)
    if workers <= 1 or len(units) < 2:
        for piece in pieces_of(units, weights, 50):
            reduction.add(evaluate(problem, piece, top, reduction.threshold))
            if progress:
                progress(len(piece))
        return reduction, 1
    import multiprocessing
    import signal

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else None)
    shared = context.Value("d", math.inf)
    pieces = pieces_of(units, weights, 32 * workers)
    processes = min(workers, len(pieces))
    # forked workers ignore Ctrl-C from their first instruction (the initializer comes later)
    try:
        handler = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # not the main thread: signals are not ours to change
        handler = None
    try:
        pool = context.Pool(processes, _init_worker, (problem, top, shared, evaluate))
    finally:
        if handler is not None:
            signal.signal(signal.SIGINT, handler)
    with pool:
        for piece, chunk in zip(pieces, pool.imap(_worker_chunk, pieces), strict=True):
            reduction.add(chunk)
            if progress:
                progress(len(piece))
    return reduction, processes


#: seconds to wait for a Dask scheduler to answer
_CONNECT_S = 10
#: pieces in flight for each thread of the cluster: enough to keep every worker busy while
#: results come back, few enough that each leaves with a recent threshold
_IN_FLIGHT = 2


def connect(scheduler):
    """A Client of the scheduler at ``scheduler`` (an address such as tcp://host:8786)."""
    try:
        from distributed import Client
        from distributed.comm.addressing import parse_address, parse_host_port
        from distributed.comm.registry import get_backend
    except ImportError:
        raise AnalysisError(
            f"needs the optional cluster support: {install_hint('cluster')} (dask distributed)",
            "scheduler",
        ) from None
    bad = AnalysisError(
        f"{scheduler!r} is not a scheduler address such as tcp://host:8786", "scheduler"
    )
    # the address read before any Client is made: a Client that fails half-built is left to
    # the garbage collector, whose clean-up waits on a lock all of distributed's event loops
    # share, forever when the collection runs while another loop starts or stops
    try:
        scheme, location = parse_address(scheduler)
        get_backend(scheme)
        if scheme in ("tcp", "tls"):
            parse_host_port(location)
    except (ValueError, TypeError):
        raise bad from None
    failure = None
    try:
        return Client(scheduler, timeout=f"{_CONNECT_S}s", set_as_default=False)
    except (OSError, TimeoutError) as exc:
        failure = AnalysisError(
            f"{scheduler!r} did not answer within {_CONNECT_S} s ({exc}); "
            "check that the scheduler runs there",
            "scheduler",
        )
    except (ValueError, TypeError):
        failure = bad
    # the half-built Client collected now, while no event loop is starting or stopping
    gc.collect()
    raise failure


def run_cluster(problem, units, weights, top, evaluate, scheduler, progress, parameter):
    """(reduction, threads of the cluster): each piece one task, a window of them in flight.

    A worker lost mid-run costs only the pieces it held: the scheduler runs them again on
    the others (results already returned are merged here and not asked for again); a piece
    that has killed its worker too often is reported as an error naming ``parameter``.
    """
    given = not isinstance(scheduler, str)  # a caller's Client: theirs to close
    if given:
        client = scheduler
    else:
        client = connect(scheduler)
    try:
        from distributed import as_completed

        threads = max(1, sum(client.nthreads().values()))
        remote = client.scatter(problem, broadcast=True)
        pieces = iter(pieces_of(units, weights, 64 * threads))
        reduction = Reduction(problem, top)
        sizes = {}
        flowing = as_completed()

        def submit():
            piece = next(pieces, None)
            if piece is None:
                return
            future = client.submit(
                _cluster_chunk, evaluate, remote, piece, top, reduction.threshold, pure=False
            )
            sizes[future.key] = len(piece)
            flowing.add(future)

        for _ in range(_IN_FLIGHT * threads):
            submit()
        for future in flowing:
            try:
                chunk = future.result()
            except Exception as exc:  # noqa: BLE001 - a task's error, raised here by Dask
                raise AnalysisError(
                    f"lost a piece of the search on the cluster ({type(exc).__name__}: {exc})",
                    parameter,
                ) from None
            reduction.add(chunk)
            if progress:
                progress(sizes.pop(future.key))
            future.release()
            submit()
        return reduction, threads
    finally:
        if not given:
            client.close()
