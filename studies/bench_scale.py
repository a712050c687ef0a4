"""Scaling benchmark: streaming studies in-process against two local dask workers, and peak memory.

Scheme iso13778-4 on the example engine. Clearance stages (streaming
summaries): bearings per second in-process and on a LocalCluster of 2 worker
processes (loopback); peak memory (maximum resident set of a fresh process)
of streaming studies of 10^7 and 10^8 bearings; the time a run of 10^9
bearings takes here, extrapolated. Full chain (beam, film, life): engine-
cycles per second in-process and on the 2 workers. Ratios in the same run.

    python studies/bench_scale.py [--large 100000000]

Writes reports/bench_scale.md.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time

from _common import environment, write_report

SCHEME = "iso13778-4"
BEARINGS_PER_ENGINE = 5


def streaming(engines, scheduler=None, chunk_lots=20):
    from stackup import Study

    t0 = time.perf_counter()
    Study(n_engines=engines, schemes=(SCHEME,), mechanics_engines=0, keep="summaries", chunk_lots=chunk_lots,
          progress=False).run(scheduler=scheduler)
    return time.perf_counter() - t0


def chain(engines, scheduler=None):
    from stackup import Study

    t0 = time.perf_counter()
    Study(n_engines=engines, schemes=(SCHEME,), mechanics_engines=engines, chunk_lots=1, progress=False).run(
        scheduler=scheduler)
    return time.perf_counter() - t0


def peak_rss(bearings):
    """Run a streaming study of ``bearings`` in a fresh process; return (seconds, peak RSS in MiB)."""
    code = ("import resource, time, json, sys; sys.path.insert(0, 'studies'); from bench_scale import streaming; "
            f"t = streaming({bearings // BEARINGS_PER_ENGINE}); "
            "print(json.dumps([t, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024]))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--medium", type=int, default=10_000_000)
    parser.add_argument("--large", type=int, default=100_000_000)
    parser.add_argument("--chain-engines", type=int, default=2000)
    args = parser.parse_args(argv)
    from distributed import Client, LocalCluster

    probe = 2_000_000  # bearings for the throughput rows
    streaming(2000)  # compile and warm caches
    t_in = streaming(probe // BEARINGS_PER_ENGINE)
    t_chain_in = chain(args.chain_engines)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as client:
        streaming(2000, scheduler=client)
        t_two = streaming(probe // BEARINGS_PER_ENGINE, scheduler=client)
        chain(200, scheduler=client)
        t_chain_two = chain(args.chain_engines, scheduler=client)
    medium = peak_rss(args.medium)
    large = peak_rss(args.large)
    rate_in, rate_two = probe / t_in, probe / t_two
    lines = [
        "# Scaling: streaming studies on dask",
        "",
        f"{environment()}. Scheme {SCHEME}, example engine ({BEARINGS_PER_ENGINE} bearings per engine). "
        "Streaming summaries (`keep='summaries'`); 2 workers = `distributed.LocalCluster(n_workers=2, "
        "threads_per_worker=1)` on loopback; the machine has 2 cores.",
        "",
        "| stage | in-process | 2 local workers | ratio |",
        "|---|---|---|---|",
        f"| clearance stages [bearings/s] ({probe:,} bearings) | {rate_in:,.0f} | {rate_two:,.0f} | {rate_two / rate_in:.2f} |",
        f"| full chain: beam, film, life [engine-cycles/s] ({args.chain_engines:,} engines) | "
        f"{args.chain_engines / t_chain_in:.1f} | {args.chain_engines / t_chain_two:.1f} | {t_chain_in / t_chain_two:.2f} |",
        "",
        "| streaming study (in-process) | time [s] | peak memory (max RSS) [MiB] |",
        "|---|---|---|",
        f"| {args.medium:,.0f} bearings | {medium[0]:.0f} | {medium[1]:.0f} |",
        f"| {args.large:,.0f} bearings | {large[0]:.0f} | {large[1]:.0f} |",
        "",
        f"A run of 10^9 bearings here: about {1e9 / args.large * large[0] / 60:.0f} min in-process, "
        f"{1e9 / rate_two / 60:.0f} min on the 2 workers (extrapolated from the rows above), in flat memory.",
        "",
        "Reproduce: `python studies/bench_scale.py`.",
    ]
    write_report("reports/bench_scale.md", lines)


if __name__ == "__main__":
    main()
