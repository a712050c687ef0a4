"""Compare ISO 13778 schemes 1-6 on the built-in example engine (the main job).

    python studies/compare_iso_schemes.py [--n 100000] [--seed 0] [--out reports/compare]

Same as ``stackup compare``: writes the dataset (netCDF) and the report with
its figures.
"""

import sys

from stackup.cli import main

if __name__ == "__main__":
    sys.exit(main(["compare", *sys.argv[1:]]))
