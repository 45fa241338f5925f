"""The search on a Dask distributed cluster: a LocalCluster of several worker processes on
this machine finds what one process finds, from a scheduler address or a Client, and a worker
killed mid-run costs only the pieces it held."""

import math
import os
import signal
import sys

import pytest

from balance_cli.cranksearch import search
from balance_cli.errors import AnalysisError
from tests.cranksearch.test_search import inline_template

distributed = pytest.importorskip("distributed")

OBJECTIVE = "M1,M2,M3,M4"


def cluster(workers=3):
    return distributed.LocalCluster(
        n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0"
    )


@pytest.fixture(scope="module")
def client():
    with cluster() as running, distributed.Client(running) as connected:
        yield connected


def same(remote, local):
    """The same list (orders, phases, scores to the last bit: each pair is scored by the same
    code on the same numbers) and the same pairs covered: every piece counted once."""
    assert [a.firing_order for a in remote.arrangements] == [
        a.firing_order for a in local.arrangements
    ]
    assert [a.phases_deg for a in remote.arrangements] == [a.phases_deg for a in local.arrangements]
    assert [a.score for a in remote.arrangements] == [a.score for a in local.arrangements]
    assert remote.evaluated + remote.pruned == local.evaluated + local.pruned
    assert remote.exhaustive


@pytest.mark.heavy
def test_processes_and_a_scheduler_address_find_what_one_process_finds(client):
    eight = inline_template(8, 2)
    one = search(eight, "M1,M2,M4", top=12, workers=1)
    two = search(eight, "M1,M2,M4", top=12, workers=2)
    remote = search(eight, "M1,M2,M4", top=12, scheduler=client.scheduler.address)
    for other in (two, remote):
        same(other, one)
        assert other.arrangements_distinct == one.arrangements_distinct == math.factorial(7) // 2
    assert remote.workers == 3  # the cluster's threads


@pytest.mark.heavy
@pytest.mark.parametrize("n", [12, 13])
def test_a_cluster_client_finds_what_one_process_finds(client, n):
    """In-line 12 and 13 (12!/4 ≈ 1.2e8 cranks), each piece of work a task on three worker
    processes, the results merged as they come back."""
    template = inline_template(n, 2)
    local = search(template, OBJECTIVE, workers=1)
    calls = []
    remote = search(template, OBJECTIVE, client=client, progress=lambda *a: calls.append(a))
    same(remote, local)
    # progress as each task completes, from nothing to the whole
    assert calls[-1][0] == calls[-1][1] and len(calls) > 10


@pytest.mark.heavy
def test_a_worker_killed_mid_run_costs_only_its_pieces():
    """One of three worker processes killed (SIGKILL, by its process id) while it computes:
    the scheduler runs the pieces it held again on the others, the search is still exhaustive
    and lists what one process lists, and no piece is computed again beyond those the dead
    worker held (running, or finished but not yet collected)."""
    template = inline_template(12, 2)
    local = search(template, OBJECTIVE, workers=1)
    with cluster() as running, distributed.Client(running) as client:
        pids = client.run(os.getpid)
        killed = []

        def progress(done, total):
            if killed or done < 3:
                return
            busy = [w for w, keys in client.processing().items() if keys]
            if not busy:
                return
            victim = busy[0]
            held = len(client.processing()[victim]) + len(client.has_what()[victim])
            os.kill(pids[victim], signal.SIGKILL)
            killed.append((victim, held))

        with distributed.get_task_stream(client) as stream:
            remote = search(template, OBJECTIVE, client=client, progress=progress)
    assert killed, "no worker was busy to kill"
    same(remote, local)
    keys = [record["key"] for record in stream.data]
    again = len(keys) - len(set(keys))
    assert again <= killed[0][1]


def test_a_client_and_a_scheduler_are_one_too_many(client):
    with pytest.raises(AnalysisError) as caught:
        search(inline_template(4, 2), "M1", client=client, scheduler="tcp://127.0.0.1:1")
    assert caught.value.parameter == "client"
    with pytest.raises(AnalysisError, match="must be a distributed.Client") as caught:
        search(inline_template(4, 2), "M1", client="tcp://127.0.0.1:1")
    assert caught.value.parameter == "client"
    with pytest.raises(AnalysisError, match="heuristic search runs in this process") as caught:
        search(inline_template(4, 2), "M1", client=client, heuristic=True)
    assert caught.value.parameter == "client"


def test_without_dask_a_scheduler_names_the_extra_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed fails
    with pytest.raises(AnalysisError, match=r"pip install 'engine-balance\[cluster\]'") as caught:
        search(inline_template(4, 2), "M1", scheduler="tcp://127.0.0.1:1")
    assert caught.value.parameter == "scheduler"
