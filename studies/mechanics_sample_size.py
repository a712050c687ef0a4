"""How many engines the mechanical chain needs for the main job's film and life percentiles.

Runs the main job's study (``iso-example``, the six ISO schemes, default film
method) with a large mechanical sample and reports, per scheme, the relative
95 % half-width of life B10 and of the cycle-minimum film's P1 and P5 over the
bearings of the first n engines (distribution-free order-statistic intervals,
:func:`stackup.stats.quantile_ci`, as the report's tables), against n.

    python studies/mechanics_sample_size.py [--engines 1500]

Writes reports/mechanics_sample_size.md.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _common import environment, write_report

from stackup.stats import quantile_ci
from stackup.study import Study

TARGET = 0.05
QUANTITIES = {"life B10": ("life", 0.10, 1 / 3600), "h_min P1": ("h_min", 0.01, 1e6),
              "h_min P5": ("h_min", 0.05, 1e6)}


def half_width(values, q):
    """Largest distance of the 95 % interval's ends from the estimate, relative to it."""
    est, lo, hi = quantile_ci(values, q)
    return max(est - lo, hi - est) / abs(est)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", type=int, default=1500)
    parser.add_argument("--out", default="reports/mechanics_sample_size.md")
    args = parser.parse_args(argv)
    t0 = time.perf_counter()
    study = Study(n_engines=args.engines, mechanics_engines=args.engines, progress=False)
    ds = study.run()
    seconds = time.perf_counter() - t0
    sizes = [n for n in (100, 200, 300, 400, 600, 800, 1000, 1200, 1500, 2000, 3000) if n <= args.engines]
    lines = ["# Engines the mechanical chain needs: life B10 and h_min percentiles to ±5 %", "",
             f"{environment()}. Main job's study (`iso-example`, six ISO schemes, film method "
             f"`{ds.attrs['film_method_used']}`), {args.engines} engines through the mechanical chain in "
             f"{seconds:.0f} s. Relative 95 % half-width (larger side) of each percentile over the bearings of the "
             "first n engines (every engine's five bearings pooled, as the report's per-scheme table):", ""]
    need = {}
    for label, (name, q, scale) in QUANTITIES.items():
        lines += [f"## {label}", "", "| engines | " + " | ".join(map(str, ds.scheme.values)) + " |",
                  "|---|" + "---|" * ds.sizes["scheme"]]
        for n in sizes:
            row = []
            for i in range(ds.sizes["scheme"]):
                v = ds[name].values[i, :n].ravel() * scale
                w = half_width(v[np.isfinite(v)], q)
                row.append(f"{100 * w:.1f} %")
                if w <= TARGET and (label, i) not in need:
                    need[(label, i)] = n
            lines.append(f"| {n} | " + " | ".join(row) + " |")
        values = [f"{float(np.nanquantile(ds[name].values[i].ravel() * scale, q)):.3g}"
                  for i in range(ds.sizes["scheme"])]
        lines += ["", f"Estimate at {args.engines} engines: " + ", ".join(values) + ".", ""]
    lines += ["## Engines needed for ±5 %", "",
              "| quantity | " + " | ".join(map(str, ds.scheme.values)) + " |", "|---|" + "---|" * ds.sizes["scheme"]]
    for label in QUANTITIES:
        lines.append(f"| {label} | " + " | ".join(str(need.get((label, i), f"> {args.engines}"))
                                                  for i in range(ds.sizes["scheme"])) + " |")
    lines += ["", "Reproduce: `python studies/mechanics_sample_size.py`."]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
