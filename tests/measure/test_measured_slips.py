"""Measured data: a column named twice, a row with a cell too many, limits in the wrong unit and temperatures in
kelvin are refused before any fit, naming the file, the column or line and what was expected (issue 51, item 3)."""

import numpy as np
import pytest

from stackup.commands._options import refused_in
from stackup.engines import builtin_folder
from stackup.measure import calibrate_housing, fit_csv
from stackup.measure._data import read_csv, tolerance_in_units
from stackup.measure.coverage import synthetic_fitting_tests


def test_a_column_named_twice_is_refused(tmp_path):
    path = tmp_path / "bores.csv"
    path.write_text("part,bore,bore\n1,50.009,50.010\n")
    with pytest.raises(ValueError, match=r"'bores.csv': column 'bore' is given 2 times in the header \(line 1\)"):
        read_csv(path, numeric=["bore"])


def test_a_row_with_a_cell_too_many_is_refused_with_its_line(tmp_path):
    path = tmp_path / "bores.csv"
    path.write_text("# bores of block 7\nbore\n50.009\n50,011\n50.010\n")
    with pytest.raises(ValueError, match=r"'bores.csv', line 4: 2 cells, the header has 1; a cell too many "
                                         r"\(a decimal comma\?\)"):
        read_csv(path, numeric=["bore"])
    path.write_text("bore,\n50.009,\n50.010\n")  # a trailing delimiter: an empty cell, no value lost
    assert read_csv(path, numeric=["bore"]).values["bore"].tolist() == [50.009, 50.010]
    path.write_text("bore;block\n50,009;1\n")  # semicolons: the comma is a decimal comma, one cell
    with pytest.raises(ValueError, match=r"decimals with a point"):
        read_csv(path, numeric=["bore"])


def test_an_engine_file_given_as_readings_is_named():
    with pytest.raises(ValueError, match=r"'iso-example.toml': is a TOML file \(an engine or scheme file\?\), not a "
                                         r"CSV file of readings"):
        read_csv(builtin_folder() / "iso-example.toml", numeric=["bore"])


@pytest.mark.parametrize("lo, hi, units, likely", [
    (50.000, 50.018, "um", "mm"),  # mm readings given as um: an 18 nm tolerance
    (50000.0, 50018.0, "mm", "um"),  # um readings given as mm: an 18 mm tolerance
    (0.050, 0.050018, "mm", "m"),
    (0.065, 0.090, "um", "mm"),  # a crush height in mm given as um
    (1.9685, 1.9692, "mm", "in"),  # a 50 mm bore's limits in inches
])
def test_limits_in_the_wrong_unit_are_named(lo, hi, units, likely):
    said = "inches" if likely == "in" else rf".* \(units = '{likely}'\)"
    with pytest.raises(ValueError, match=rf"limits: .* is a tolerance of .*; a drawing tolerance of a part of .* m is "
                                         rf".* m \(ISO 286-1's IT1\) to 2 mm wide: are the readings and limits in "
                                         rf"{said}"):
        tolerance_in_units(lo, hi, units)


@pytest.mark.parametrize("lo, hi, units", [(50.000, 50.018, "mm"), (65.0, 90.0, "um"), (1.970, 1.994, "mm"),
                                           (0.05, 0.050018, "m")])
def test_limits_of_real_parts_pass(lo, hi, units):
    assert tolerance_in_units(lo, hi, units) is None


def test_readings_in_inches_against_limits_in_mm_are_named(tmp_path):
    path = tmp_path / "bores.csv"
    path.write_text("bore\n" + "\n".join(f"{(50.009 + 0.002 * z) / 25.4:.5f}" for z in np.linspace(-2, 2, 30)))
    with pytest.raises(ValueError, match=r"'bores.csv', column 'bore': 30 values look like inches, not mm like the "
                                         r"limits \[50, 50.018\] .*; give them in mm \(inches x 25.4\)"):
        fit_csv(path, "bore", limits=(50.0, 50.018), units="mm", resamples=100)


def test_fitting_test_temperatures_in_kelvin_are_named():
    tests = synthetic_fitting_tests(6, 75e-3, np.random.default_rng(3))
    tests["temperature"] = np.asarray(tests["temperature"]) + 273.15
    with pytest.raises(ValueError, match=r"tests\['temperature'\], indices 0, 1.*: 2\d\d.\d+ degC is not a plausible "
                                         r"engine temperature \(-60 to 200 degC\); these look like kelvin"):
        calibrate_housing(tests, "iso-example")


def test_a_refusal_resting_on_the_default_engine_names_it():
    for engine, named in (("iso-example", True), ("my.toml", False)):
        with pytest.raises(ValueError) as refused, refused_in({}, engine=engine):
            raise ValueError("'t.csv', column 'housing_bore': 8 values more than 10 tolerance widths off the limits")
        assert ("(engine: iso-example, the default; give yours with --engine)" in str(refused.value)) is named
    with pytest.raises(ValueError, match=r"^--lot: a lot larger than the volume$"), \
            refused_in({"lot_engines": "--lot"}, engine="iso-example"):
        raise ValueError("lot_engines: a lot larger than the volume")  # an option's refusal: not the engine's
