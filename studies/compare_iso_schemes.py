"""The main job as a study script: ISO 13778 schemes 1-6 and a designed scheme on the built-in example engine.

    python studies/compare_iso_schemes.py [--n 100000] [--seed 0] [--out reports/reference/compare]

The same as ``stackup compare`` (it runs that command): the designer, the
study, its declared scenarios, the tails and the Sobol indices; the
comparison is saved in one compact netCDF file and the report is written
from that file. Its default output is the reference report kept in git
(the dataset itself is not tracked).
"""

import argparse
import sys

from stackup.cli import main

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="reports/reference/compare")
    args = parser.parse_args()
    sys.exit(main(["compare", "--n", str(args.n), "--seed", str(args.seed), "--out", args.out, "--force"]))
