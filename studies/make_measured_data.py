"""SYNTHETIC measurement files for the measured-data study: drawn from stated true processes, not measured.

Writes ``studies/data/synthetic_*.csv`` around the ISO 13778 example engine's
drawing (housing bore 50.000-50.018 mm, journal 46.000-46.018 mm, crush height
0.065-0.090 mm), each file and its header comment saying it is synthetic and
from which true process:

- ``synthetic_housing_bores.csv``: 60 blocks x 5 bores from two line-boring
  machines (a mixture of two normals), 30 % of the variance common to a block;
- ``synthetic_journals.csv``: 60 crankshafts x 5 journals ground to size
  (a skew-normal), 20 % common to a crankshaft;
- ``synthetic_crush_heights.csv``: 200 shells in order of manufacture, the
  crush height drifting with tool wear;
- ``synthetic_fitting_tests.csv``: 12 fitting tests of a housing whose
  equivalent outer diameter is 75 mm (the engine file assumes 90 mm).

Every reading has the gauge's repeatability (0.5 um; crush heights and the
assembled bore 1 um); readings of parts are rounded to 0.1 um.

    python studies/make_measured_data.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from stackup.measure.coverage import TEST_NOISE, synthetic_fitting_tests, synthetic_readings
from stackup.tolerances import Gauge, Mixture, Normal, SkewNormal, ToolWear

DATA = Path(__file__).parent / "data"
SEED = 2017  # the year of ISO 13778
MM = 1e-3

#: The true processes [m], their groups and shared shares, the drawing limits [m]: what the files are made from.
TRUTH = {
    "housing_bores": dict(column="housing_bore", group="block", limits=(50.000 * MM, 50.018 * MM), shared=0.3,
                          process=Mixture((Normal(50.0065 * MM, 0.0014 * MM), Normal(50.0115 * MM, 0.0016 * MM)),
                                          (0.55, 0.45)),
                          words="two line-boring machines: 55 % normal(50.0065 mm, 0.0014 mm), 45 % "
                                "normal(50.0115 mm, 0.0016 mm); shared 0.3 within a block"),
    "journals": dict(column="journal_d", group="crankshaft", limits=(46.000 * MM, 46.018 * MM), shared=0.2,
                     process=SkewNormal(46.0095 * MM, 0.0021 * MM, -0.6),
                     words="ground to size: skew-normal, mean 46.0095 mm, sigma 0.0021 mm, skewness -0.6; "
                           "shared 0.2 within a crankshaft"),
    "crush_heights": dict(column="crush_height", group=None, limits=(0.065 * MM, 0.090 * MM), shared=0.0,
                          process=ToolWear(0.0735 * MM, 0.0815 * MM, 0.0015 * MM),
                          words="tool wear: mean drifting from 0.0735 mm (first shell) to 0.0815 mm (last), "
                                "sigma 0.0015 mm"),
}
#: The fitting tests' true housing outer diameter [m] and their number.
TRUE_OUTER, TESTS = 75.0 * MM, 12
GAUGE = Gauge(repeatability=0.0005 * MM, resolution=0.0001 * MM)


def header(name, words, gauge, units):
    return [f"# SYNTHETIC {name}, not measurements: made by studies/make_measured_data.py (seed {SEED})",
            f"# from the true process: {words}.",
            f"# {gauge}; lengths in {units}."]


def write_readings(rng):
    for name, spec in TRUTH.items():
        groups = 60 if spec["group"] else 200
        per_group = 5 if spec["group"] else 1
        gauge = GAUGE if name != "crush_heights" else Gauge(repeatability=0.001 * MM, resolution=0.0001 * MM)
        x, group, order = synthetic_readings(spec["process"], rng, groups=groups, per_group=per_group,
                                             shared=spec["shared"], gauge=gauge, limits=spec["limits"])
        lines = header(name.replace("_", " "), spec["words"], f"Gauge repeatability {gauge.repeatability / MM:g} "
                       f"mm, read-out {gauge.resolution / MM:g} mm", "mm")
        if spec["group"]:
            lines.append(f"{spec['group']},position,{spec['column']}")
            lines += [f"{spec['group'][0].upper()}{g + 1:03d},{k % per_group + 1},{v / MM:.4f}"
                      for k, (g, v) in enumerate(zip(group, x))]
        else:
            lines.append(f"sequence,{spec['column']}")
            lines += [f"{k + 1},{v / MM:.4f}" for k, v in zip(order, x)]
        write(DATA / f"synthetic_{name}.csv", lines)


def write_tests(rng):
    table = synthetic_fitting_tests(TESTS, TRUE_OUTER, rng)
    noise = ", ".join(f"{k} {v * 1e6:g} um" for k, v in TEST_NOISE.items())
    lines = header("fitting tests", f"stackup.fit.press_fit on the iso-example engine with a housing outer diameter "
                   f"of {TRUE_OUTER / MM:g} mm", f"Gauge noise {noise}", "m, temperature in degC")
    columns = list(table)
    lines.append(",".join(columns))
    for i in range(TESTS):
        lines.append(",".join(f"{table[c][i]:.1f}" if c == "temperature" else f"{table[c][i]:.8f}" for c in columns))
    write(DATA / "synthetic_fitting_tests.csv", lines)


def write(path, lines):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    print(f"wrote {path}")


def main():
    rng = np.random.default_rng(SEED)
    write_readings(rng)
    write_tests(rng)


if __name__ == "__main__":
    main()
