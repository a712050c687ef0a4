"""The main job as a study script: ISO 13778 schemes 1-6 and a designed scheme on a built-in engine.

    python studies/compare_iso_schemes.py [--engine iso-example] [--n 100000] [--seed 0] [--out DIR]

The same folder as ``stackup compare`` writes (both call :func:`stackup.comparison.run`): the designer, the study,
its declared scenarios, the tails and the Sobol indices; the comparison is saved in one netCDF file and the report
is written from that file. Its default output is the reference report kept in git (the dataset itself is not
tracked): ``reports/reference/compare`` for the example engine, ``reports/reference/compare-ENGINE`` for another
(``--engine nef-6``: the heavy-duty inline six).
"""

import argparse

import stackup.comparison

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engine", default="iso-example")
    parser.add_argument("--n", type=int, default=stackup.comparison.COMPARE_ENGINES)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out")
    args = parser.parse_args()
    out = args.out or "reports/reference/compare" + ("" if args.engine == "iso-example" else f"-{args.engine}")
    written = stackup.comparison.run(out, engine=args.engine, n_engines=args.n, seed=args.seed, force=True, log=print)
    print(f"{written.report} in {written.seconds:.0f} s\nverdict: {written.verdict}")
