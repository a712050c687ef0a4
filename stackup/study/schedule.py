"""Where the chunks of a study run: in this process, in local worker processes, or on a dask cluster.

Chunks are seeded from one SeedSequence (one child per production lot), so
the numbers are identical on all three; results stream back as chunks
finish, with at most two chunks per worker thread in flight.
"""

from __future__ import annotations

import contextlib
import itertools
import os

#: glibc malloc settings for the worker processes of ``scheduler="processes"`` (dask config keys).
#: The dask nanny sets MALLOC_TRIM_THRESHOLD_=65536, which also fixes glibc's mmap threshold at
#: 128 kB, so every large numpy array of a chunk is a fresh mmap with its page faults. Arrays up to 16 MiB
#: from the heap, trimmed past 64 MiB, cost less CPU time per chunk (measured in reports/bench_scale.md); set
#: the same keys for the workers of your own cluster.
WORKER_MALLOC = {
    "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 64 * 2**20,
    "distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": 16 * 2**20,
}


def check_scheduler(scheduler, study):
    """Refuse a scheduler that is not None, "processes" or a Client, or one a target_error study cannot use."""
    if scheduler is not None and study.target_error:
        raise ValueError("scheduler: a study with target_error decides engine by engine in order; "
                         "run it with scheduler=None")
    if scheduler is not None and scheduler != "processes" and not (hasattr(scheduler, "submit")
                                                                  and hasattr(scheduler, "nthreads")):
        raise ValueError(f"scheduler: {scheduler!r} is not None, 'processes' or a dask.distributed Client")


def results(study, firsts, scheduler, progress):
    """Yield the result of each chunk ``first`` in ``firsts`` as it finishes; in order in this process.

    ``progress`` is the sink's :class:`~stackup.study.sinks.Progress`; a
    ``target_error`` study (in this process only) hands it to each chunk.
    """
    if scheduler is None:
        for first in firsts:
            yield study.chunk(first, progress.for_next_chunk() if study.target_error else None)
    elif scheduler == "processes":
        with local_cluster() as client:
            yield from _stream(study, firsts, client)
    else:
        yield from _stream(study, firsts, scheduler)


@contextlib.contextmanager
def local_cluster():
    """A Client of a dask cluster on this machine: one single-threaded worker per core, WORKER_MALLOC set."""
    from distributed import Client, LocalCluster

    import dask

    with dask.config.set(WORKER_MALLOC), LocalCluster(
            n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True, host="127.0.0.1",
            dashboard_address=None) as cluster, Client(cluster) as client:
        yield client


def _chunk_task(study, first):
    """A chunk computed where the scheduler puts it (module level, so it pickles).

    A worker is one core: the numba kernels run on one thread there, so
    workers do not oversubscribe the machine.
    """
    import numba

    numba.set_num_threads(1)
    return study.chunk(first)


def _stream(study, firsts, client):
    """Chunks on a dask cluster, at most two per worker thread in flight, yielded as they finish.

    A bounded window keeps memory flat on the workers and here however many
    chunks a study has; a chunk lost with its worker is recomputed by dask.
    """
    from distributed import as_completed

    pending = iter(firsts)
    window = 2 * max(1, sum(client.nthreads().values()))
    futures = as_completed([client.submit(_chunk_task, study, first, pure=False)
                            for first in itertools.islice(pending, window)], with_results=True)
    for future, result in futures:
        yield result
        future.release()
        for first in itertools.islice(pending, 1):
            futures.add(client.submit(_chunk_task, study, first, pure=False))
