"""Scaling benchmark: streaming studies in-process against two local dask workers, memory, and 10^9 bearings.

Scheme iso13778-4 on the example engine. Throughput of the clearance stages
(streaming summaries, bearings per second) and of the full chain (beam,
film, life; engine-cycles per second) in-process and on a LocalCluster of 2
single-threaded worker processes on loopback, once with dask's default worker
environment and once with stackup's malloc settings (``WORKER_MALLOC``, what
``scheduler="processes"`` uses); each the best of ``--repeat`` runs after a
warm-up that reaches every worker, ratios against in-process in the same run.
Peak memory (VmHWM of a fresh process; ``ru_maxrss`` would start from the
parent's resident memory) of streaming studies at
10^7 and 10^8 bearings, and of studies kept whole in a Zarr store (out of
core) at two sizes. Finally a real run of 10^9 bearings with
``scheduler="processes"`` streaming its summaries into a Zarr store.

    python studies/bench_scale.py [--large 100000000] [--billion 1000000000]

Writes reports/bench_scale.md.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path

from _common import environment, write_report

SCHEME = "iso13778-4"
BEARINGS_PER_ENGINE = 5


def study(bearings, **kw):
    from stackup import Study

    return Study(n_engines=bearings // BEARINGS_PER_ENGINE, schemes=(SCHEME,), progress=False, **kw)


def streaming(bearings, scheduler=None, store=None, keep="summaries"):
    t0 = time.perf_counter()
    study(bearings, mechanics_engines=0, keep=keep, store=store).run(scheduler=scheduler)
    return time.perf_counter() - t0


#: Shell lot of the full-chain runs [engines]: one lot per chunk, so 1000 engines make 10 chunks to share out.
CHAIN_LOT = 100


def chain_engine():
    """The example engine with shell lots of CHAIN_LOT engines (a file next to the other temporary files)."""
    from importlib.resources import files

    text = (files("stackup") / "data" / "engines" / "iso-example.toml").read_text()
    path = Path(tempfile.gettempdir()) / f"iso-example-lot{CHAIN_LOT}.toml"
    path.write_text(text.replace("lot_engines = 1000", f"lot_engines = {CHAIN_LOT}"))
    return str(path)


def chain(engines, scheduler=None):
    t0 = time.perf_counter()
    study(engines * BEARINGS_PER_ENGINE, engine=chain_engine(), mechanics_engines=engines, chunk_lots=1).run(
        scheduler=scheduler)
    return time.perf_counter() - t0


def best(fn, repeat):
    return min(fn() for _ in range(repeat))


def peak_memory():
    """Peak resident memory of this process [MiB].

    VmHWM of /proc: unlike ``ru_maxrss``, it does not start from the parent's
    resident memory at the fork that started this process.
    """
    with open("/proc/self/status") as status:
        return next(int(line.split()[1]) for line in status if line.startswith("VmHWM:")) / 1024


@contextmanager
def two_workers(config):
    """A Client of a LocalCluster of 2 single-threaded worker processes on loopback, under dask ``config``."""
    import dask
    from distributed import Client, LocalCluster

    with dask.config.set(config), LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                               dashboard_address=None) as cluster, Client(cluster) as client:
        yield client


def on_two_workers(bearings, store):
    """A streaming study on a LocalCluster like ``scheduler="processes"`` starts: (seconds, largest worker peak [MiB])."""
    from stackup.study import WORKER_MALLOC

    with two_workers(WORKER_MALLOC) as client:
        seconds = streaming(bearings, scheduler=client, store=store)
        return seconds, max(client.run(peak_memory).values())


def in_process_rates(probe, chain_engines, repeat):
    """Best times [s] in this process of the clearance stages and of the full chain, after a warm-up."""
    streaming(50_000)  # compile and warm caches
    return best(lambda: streaming(probe), repeat), best(lambda: chain(chain_engines), repeat)


def with_peak(result):
    """(seconds, peak memory of this process [MiB], worker peak [MiB] or None) once ``result`` is in."""
    seconds, workers = result if isinstance(result, tuple) else (result, None)
    return seconds, peak_memory(), workers


def in_fresh_process(expression, env=None):
    """The value of ``expression`` (source text, JSON-able) evaluated in a fresh process importing this module."""
    code = ("import json, sys; sys.path.insert(0, 'studies'); from bench_scale import *; "
            f"print(json.dumps({expression}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env).stdout
    return json.loads(out.strip().splitlines()[-1])


def folder_size(path):
    return sum(p.stat().st_size for p in Path(path).rglob("*") if p.is_file()) / 2**20


def throughput(args):
    """Rates in-process and on two workers with dask's and with stackup's worker environment."""
    from stackup.study import WORKER_MALLOC

    rows = {"in-process": in_process_rates(args.probe, args.chain_engines, args.repeat)}
    # the same in a fresh process started with WORKER_MALLOC's settings in its environment
    environ = {**os.environ, **{key.rsplit(".", 1)[1]: str(value) for key, value in WORKER_MALLOC.items()}}
    rows["in-process, WORKER_MALLOC in the environment"] = tuple(in_fresh_process(
        f"in_process_rates({args.probe}, {args.chain_engines}, {args.repeat})", env=environ))
    for label, config in (("2 workers, dask's default environment", {}), ("2 workers, WORKER_MALLOC", WORKER_MALLOC)):
        with two_workers(config) as client:
            streaming(args.probe, scheduler=client)  # every worker compiles and builds the study context
            chain(args.chain_engines, scheduler=client)
            rows[label] = (best(lambda: streaming(args.probe, scheduler=client), args.repeat),
                           best(lambda: chain(args.chain_engines, scheduler=client), args.repeat))
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--probe", type=int, default=2_000_000, help="bearings of the throughput runs")
    parser.add_argument("--chain-engines", type=int, default=600)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--medium", type=int, default=10_000_000)
    parser.add_argument("--large", type=int, default=100_000_000)
    parser.add_argument("--stored", type=int, nargs=2, default=[1_000_000, 4_000_000],
                        help="bearings of the two studies kept whole in a Zarr store")
    parser.add_argument("--billion", type=int, default=1_000_000_000, help="bearings of the largest run; 0 skips it")
    args = parser.parse_args(argv)

    rows = throughput(args)
    base = rows["in-process"]
    lines = [
        "# Scaling: streaming studies on dask",
        "",
        f"{environment()}. Scheme {SCHEME}, example engine ({BEARINGS_PER_ENGINE} bearings per engine). "
        "2 workers = `distributed.LocalCluster(n_workers=2, threads_per_worker=1)` on loopback; the machine has "
        "2 cores, shared with the client and the scheduler. Best of "
        f"{args.repeat} runs after a warm-up on every worker; ratios against in-process in the same run.",
        "",
        f"| where | clearance stages [bearings/s] ({args.probe:,} bearings, `keep='summaries'`) | ratio "
        f"| full chain: beam, film, life [engine-cycles/s] ({args.chain_engines:,} engines, "
        f"chunks of {CHAIN_LOT}) | ratio |",
        "|---|---|---|---|---|",
    ]
    for label, (t_clear, t_chain) in rows.items():
        lines.append(f"| {label} | {args.probe / t_clear:,.0f} | {base[0] / t_clear:.2f} "
                     f"| {args.chain_engines / t_chain:.1f} | {base[1] / t_chain:.2f} |")
    lines += [
        "",
        "In-process, the numba kernels of the press fit and the crankshaft run on both cores; a worker runs "
        "them on one thread. dask's nanny starts workers with `MALLOC_TRIM_THRESHOLD_=65536`, which also fixes "
        "glibc's mmap threshold at 128 kB, so each large array of a chunk is a fresh mmap with its page faults; "
        "`stackup.study.WORKER_MALLOC` (heap up to 16 MiB, trim past 64 MiB) is what `scheduler=\"processes\"` "
        "sets, and what to set on the workers of your own cluster. The same settings in the environment of an "
        "in-process run (`MALLOC_MMAP_THRESHOLD_=16777216 MALLOC_TRIM_THRESHOLD_=67108864`) show what glibc's "
        "default costs there; the 2-worker ratio against that row is the gain from the second core.",
        "",
        "| study (in a fresh process, in-process scheduler) | time [s] | peak memory (VmHWM) [MiB] | store [MiB] |",
        "|---|---|---|---|",
    ]
    for bearings in (args.medium, args.large):
        t, rss, _ = in_fresh_process(f"with_peak(streaming({bearings}))")
        lines.append(f"| {bearings:,} bearings, streaming summaries | {t:.0f} | {rss:.0f} | — |")
    work = Path(tempfile.mkdtemp(prefix="bench_scale-"))
    try:
        for bearings in args.stored:
            store = work / f"whole-{bearings}.zarr"
            t, rss, _ = in_fresh_process(
                f"with_peak(streaming({bearings}, store={str(store)!r}, keep='everything'))")
            lines.append(f"| {bearings:,} bearings, every engine kept in a Zarr store | {t:.0f} | {rss:.0f} "
                         f"| {folder_size(store):,.0f} |")
        if args.billion:
            store = work / "billion.zarr"
            t, rss, workers = in_fresh_process(f"with_peak(on_two_workers({args.billion}, store={str(store)!r}))")
            lines += [
                "",
                f"A real run of {args.billion:,} bearings (`keep='summaries'`, 2 workers with `WORKER_MALLOC` as "
                "`scheduler='processes'` starts them, summaries streamed into a Zarr store): "
                f"{t / 60:.1f} min ({args.billion / t:,.0f} bearings/s), "
                f"peak memory {rss:.0f} MiB in the client and {workers:.0f} MiB in the largest worker; "
                f"the store holds {folder_size(store):,.2f} MiB (the running total of the summaries).",
            ]
    finally:
        shutil.rmtree(work, ignore_errors=True)
    lines += ["", "Reproduce: `python studies/bench_scale.py`."]
    write_report("reports/bench_scale.md", lines)


if __name__ == "__main__":
    main()
