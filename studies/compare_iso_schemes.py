"""Compare ISO 13778 schemes 1-6 on the built-in example engine (the main job) as a study script.

    python studies/compare_iso_schemes.py [--n 100000] [--seed 0] [--out reports/compare]

The same as ``stackup compare``, through the library: :func:`stackup.compare`
runs the study, its declared scenarios and the sensitivity; the comparison is
saved in one compact netCDF file and the report is written from that file.
"""

import argparse

import stackup
from stackup.io import open_comparison, save_comparison
from stackup.report import write_report

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="reports/compare")
    args = parser.parse_args()
    path = save_comparison(stackup.compare(n_engines=args.n, seed=args.seed), f"{args.out}/compare.nc")
    saved = open_comparison(path)  # the report is a function of the saved datasets
    report = write_report(saved.dataset, args.out, scenarios=saved.scenarios, sensitivity=saved.sensitivity, tails=saved.tails,
                          dataset_file=path.name)
    print(f"dataset: {path}\nreport:  {report}")
