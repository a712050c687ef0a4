"""Studies on dask: identical numbers in-process, in local processes and on a cluster (loopback only)."""

import threading

import pytest
import xarray as xr

from stackup import Study

pytestmark = pytest.mark.integration

KW = dict(n_engines=2500, mechanics_engines=20, crank_angle_step=8.0, history=True, progress=False, pilot_engines=3000,
          chunk_lots=1)


@pytest.fixture(scope="module")
def reference():
    return Study(**KW).run()


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        yield c


def test_local_processes_give_identical_numbers(reference):
    xr.testing.assert_identical(Study(**KW).run(scheduler="processes"), reference)


def test_a_cluster_of_two_workers_gives_identical_numbers(reference, client):
    xr.testing.assert_identical(Study(**KW).run(scheduler=client), reference)


def test_a_worker_lost_mid_run_is_retried_and_nothing_is_lost_or_counted_twice(reference, client):
    import os
    import signal

    pids = client.run(os.getpid)
    victim = next(iter(pids.values()))
    result = {}
    thread = threading.Thread(target=lambda: result.update(ds=Study(**KW).run(scheduler=client)))
    thread.start()
    os.kill(victim, signal.SIGKILL)  # the nanny starts a new worker; dask reschedules its tasks
    thread.join(timeout=300)
    assert "ds" in result
    xr.testing.assert_identical(result["ds"], reference)


def test_target_error_needs_the_in_process_scheduler():
    with pytest.raises(ValueError, match="scheduler: a study with target_error decides engine by engine"):
        Study(**{**KW, "target_error": 0.05}).run(scheduler="processes")


def test_unknown_scheduler():
    with pytest.raises(ValueError, match="scheduler: 'threads' is not None, 'processes' or a dask.distributed Client"):
        Study(**KW).run(scheduler="threads")


def test_streaming_summaries_are_identical_on_a_cluster(client):
    kw = dict(KW, history=False, keep="summaries")
    xr.testing.assert_identical(Study(**kw).run(scheduler=client), Study(**kw).run())


def test_a_study_streamed_into_a_store_from_a_cluster_is_identical(reference, client, tmp_path):
    stored = Study(**KW, store=str(tmp_path / "s.zarr")).run(scheduler=client)
    xr.testing.assert_identical(stored.load(), reference)
