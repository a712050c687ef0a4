"""Inputs that slip by a unit or a duplicate (issue 51, item 3), as a user meets them: each case a small file,
one command in a fresh process, refused in one line naming the file, the key and the value, with exit code 2,
before any study or fit runs (nothing printed on stdout, nothing written)."""

import numpy as np
import pytest
from cli_helpers import ISO4, one_line_refusal, stackup_process

from stackup.engines import builtin_folder
from stackup.measure.coverage import synthetic_fitting_tests

pytestmark = pytest.mark.integration

BORE = 'process = { distribution = "normal", cpk = 1.33 }\n# Share of the bore'
#: SPC readings of a housing bore [mm], as a gauge prints them.
READINGS = [f"{50.009 + 0.002 * z:.4f}" for z in np.random.default_rng(51).standard_normal(30)]


def engine(old, new, *, encoding="utf-8", command=("schemes",)):
    """A copy of the example engine with one change, given to ``command`` (the main job for one case: it refuses
    as every command does, when it reads the engine; the others use a command that starts a second sooner)."""
    def write(folder):
        text = (builtin_folder() / "iso-example.toml").read_text()
        assert old in text
        (folder / "engine.toml").write_text(text.replace(old, new, 1), encoding=encoding)
        out = ["--out", folder / "out"] if command[0] == "compare" else []
        return [*command, "--engine", folder / "engine.toml", *out]
    return write


def readings(header, rows, *options):
    def write(folder):
        (folder / "bores.csv").write_text("\n".join([header, *rows]) + "\n")
        return ["measure", "fit", folder / "bores.csv", "--column", "bore", "--limits", "50.000", "50.018",
                "--resamples", "100", *options]
    return write


def fitting_tests(*, kelvin=False, scale=1.0):
    """Fitting tests of the example engine in mm, the command's default (temperatures in kelvin if asked), or of a
    bore ``scale`` times it."""
    def write(folder):
        table = synthetic_fitting_tests(6, 75e-3, np.random.default_rng(3))
        table = {k: np.asarray(v) * (1.0 if k == "temperature" else 1e3)
                 * (scale if k not in ("temperature", "shell_upper_crush", "shell_lower_crush") else 1.0)
                 for k, v in table.items()}
        table["temperature"] = table["temperature"] + (273.15 if kelvin else 0.0)
        lines = [",".join(table)] + [",".join(f"{table[k][i]:.9g}" for k in table) for i in range(6)]
        (folder / "tests.csv").write_text("\n".join(lines) + "\n")
        return ["measure", "swell", folder / "tests.csv"]
    return write


def given(args):
    return lambda folder: [a.format(folder=folder) if isinstance(a, str) else a for a in args]


CASES = {
    "throw angles in radians": (engine("throw_angles = [0, 180, 180, 0]", "throw_angles = [0, 3.14159, 3.14159, 0]",
                                       command=("compare", "--quick")),
                                ["engine.toml", "crank.throw_angles", "3.14159", "radians", "[0, 180, 180, 0]"]),
    "check stress in MPa": (engine("check_stress = 100e6", "check_stress = 100"),
                            ["engine.toml", "press_fit.check_stress", "100 Pa", "not MPa"]),
    "two widths of one bearing": (engine("bearing_width = 22.0", "bearing_width = 30.0"),
                                  ["engine.toml", "crank.bearing_width", "30 mm", "press_fit.length 22 mm"]),
    "mass in grams": (engine("reciprocating_mass = 0.75", "reciprocating_mass = 640"),
                      ["engine.toml", "crank.reciprocating_mass", "640 kg", "grams"]),
    "sigma of 1e-300": (engine(BORE, BORE.replace("cpk = 1.33", "mean = 50.009, sigma = 1e-300")),
                        ["engine.toml", "housing_bore.process.sigma", "1e-300 mm", "standard deviation"]),
    "cpk with mean and sigma": (engine(BORE, BORE.replace("cpk = 1.33", "cpk = 1.33, mean = 50.009, sigma = 0.002")),
                                ["engine.toml", "housing_bore.process", "either cpk", "not both"]),
    "process mean off its limits": (engine(BORE, BORE.replace("cpk = 1.33", "mean = 50.509, sigma = 0.002")),
                                    ["engine.toml", "housing_bore.process", "50.509 mm", "tolerance width"]),
    "lining over the wall": (engine("lining_thickness = 0.30", "lining_thickness = 2.5"),
                             ["engine.toml", "press_fit.lining_thickness", "2.5 mm", "1.991 mm"]),
    # a byte-order mark is read past: the refusal is the file's other slip, named with its key
    "BOM": (engine("check_stress = 100e6", "check_stress = 100", encoding="utf-8-sig"),
            ["engine.toml", "press_fit.check_stress"]),
    "scheme file as the engine": (given(["compare", "--quick", "--engine", ISO4, "--out", "{folder}/out"]),
                                  ["iso13778-4.toml", "is a scheme file", "--schemes"]),
    "engine file as a scheme": (given(["compare", "--quick", "--schemes", builtin_folder() / "iso-example.toml",
                                       "--out", "{folder}/out"]),
                                ["iso-example.toml", "is an engine file", "--engine"]),
    "readings in mm given as um": (readings("bore", READINGS, "--units", "um"),
                                   ["--limits", "[50, 50.018] µm", "units = 'mm'"]),
    "a column given twice": (readings("bore,bore", [f"{r},{r}" for r in READINGS]),
                             ["bores.csv", "column 'bore' is given 2 times"]),
    "a row with extra cells": (readings("bore", [*READINGS[:3], "50,011", *READINGS[3:]]),
                               ["bores.csv", "line 5", "2 cells, the header has 1"]),
    "figure in a missing folder": (readings("bore", READINGS, "--figure", "nofolder/x.png"),
                                   ["--figure", "'nofolder'", "does not exist"]),
    "fitting tests in kelvin": (fitting_tests(kelvin=True), ["tests.csv", "column 'temperature'", "kelvin"]),
    "default engine named": (fitting_tests(scale=1.2),
                             ["tests.csv", "column 'housing_bore'", "(engine: iso-example, the default"]),
}


@pytest.mark.parametrize("case", CASES)
def test_a_slip_is_refused_in_one_line_before_any_work(tmp_path, case):
    write, parts = CASES[case]
    args = write(tmp_path)
    result = stackup_process(*args, cwd=tmp_path, timeout=120)
    one_line_refusal(result, *parts)
    assert not (tmp_path / "out").exists() and not (tmp_path / "nofolder").exists()
