"""Engine and scheme files: a value in the wrong unit, or given twice, is refused naming the file, the key, the
value and what was expected (issue 51, item 3); the built-in engines and the test data pass every check."""

from pathlib import Path

import numpy as np
import pytest

from stackup import _validate as check
from stackup.engines import builtin_folder, load_engine
from stackup.schemes import builtin_folder as scheme_folder
from stackup.schemes import load as load_scheme
from stackup.tolerances import process_from_spec

DATA = Path(__file__).parents[1] / "data"  # the tests' own files, wherever the package is installed
ISO4 = scheme_folder() / "iso13778-4.toml"
BORE = "process = { distribution = \"normal\", cpk = 1.33 }\n# Share of the bore"


def engine_file(tmp_path, old, new, *, name="engine.toml", encoding="utf-8"):
    text = (builtin_folder() / "iso-example.toml").read_text()
    assert old in text
    path = tmp_path / name
    path.write_text(text.replace(old, new, 1), encoding=encoding)
    return path


@pytest.mark.parametrize("old, new, message", [
    ("throw_angles = [0, 180, 180, 0]", "throw_angles = [0, 3.14159, 3.14159, 0]",
     r"key crank.throw_angles: \[0, 3.14159, 3.14159, 0\] look like radians .* \[0, 180, 180, 0\]"),
    ("groove_arc = [90.0, 270.0]", "groove_arc = [1.5708, 4.7124]", r"key oil_feed.groove_arc: .* look like radians"),
    ("check_stress = 100e6", "check_stress = 100", r"key press_fit.check_stress: 100 Pa is not a plausible .* not MPa"),
    ("reciprocating_mass = 0.75", "reciprocating_mass = 640",
     r"key crank.reciprocating_mass: 640 kg is not a plausible .* 76 mm cylinder bore \(0.0878 to 8.78 kg\); .*grams"),
    ("rotating_mass = 0.60", "rotating_mass = 600", r"key crank.rotating_mass: 600 kg .*grams"),
    ("supply_pressure = 0.35e6", "supply_pressure = 3.5", r"key oil_feed.supply_pressure: 3.5 Pa .*bar"),
    ("cold_temperature = -25.0", "cold_temperature = 248.15", r"key press_fit.cold_temperature: 248.15 degC .*kelvin"),
    ("assembly_temperature = 20.0", "assembly_temperature = 293.15",
     r"key press_fit.assembly_temperature: 293.15 degC .*kelvin"),
    ("peak_pressure = 13.0e6", "peak_pressure = 130", r"key crank.peak_pressure: 130 Pa .*150 bar = 15 MPa"),
    ("temperature = 100.0 ", "temperature = 373.15 ", r"key press_fit.temperature: 373.15 degC .*kelvin"),
    ("supply_temperature = 90.0", "supply_temperature = 363.15", r"key oil.supply_temperature: 363.15 degC .*kelvin"),
    (BORE, BORE.replace("cpk = 1.33", "mean = 50.009, sigma = 0.5"),
     r"key housing_bore.process: its standard deviation 0.5 mm is wider than the tolerance 0.018 mm"),
    ("life_hours = 1000.0", "life_hours = 3.6e6", r"key targets.life_hours: 3.6e\+06 h .*seconds / 3600"),
    ("linear_compliance_um_per_kN = [1.0204081632653061,", "linear_compliance_um_per_kN = [1.02e-9,",
     r"key supports.linear_compliance_um_per_kN: 1.02e-09 um/kN is not a plausible housing compliance"),
    ("bearing_width = 22.0", "bearing_width = 30.0",
     r"key crank.bearing_width: 30 mm differs from press_fit.length 22 mm; a bearing has one width"),
    ("lining_thickness = 0.30", "lining_thickness = 2.5",
     r"key press_fit.lining_thickness: 2.5 mm is not below 0.9955 mm, 0.5 of a shell wall of at most 1.991 mm"),
    ("lining_thickness = 0.30", "lining_thickness = 1.0",
     r"key press_fit.lining_thickness: 1 mm is not below 0.9955 mm"),
    (BORE, BORE.replace("cpk = 1.33", "cpk = 1.33, mean = 50.009, sigma = 0.002"),
     r"key housing_bore.process: give either cpk \(with cp, side\) or mean and sigma, not both"),
    (BORE, BORE.replace("cpk = 1.33", "mean = 50.509, sigma = 0.002"),
     r"key housing_bore.process: its median 50.509 mm lies 0.491 mm \(27.3 tolerance widths\) above the upper"),
    (BORE, BORE.replace("cpk = 1.33", "mean = 50.009, sigma = 1e-300"),
     r"key housing_bore.process.sigma: 1e-300 mm is not a plausible process standard deviation"),
])
def test_a_value_in_the_wrong_unit_is_refused_naming_file_key_and_value(tmp_path, old, new, message):
    with pytest.raises(ValueError, match=r"engine file 'engine.toml', " + message):
        load_engine(engine_file(tmp_path, old, new))


@pytest.mark.parametrize("old, new", [
    ("bearing_width = 22.0              # [mm]\n", ""),  # one width, written once: the shells'
    ("bearing_width = 22.0", "bearing_width = 22.05"),  # the same width, rounded otherwise
    (BORE, BORE.replace("cpk = 1.33", "mean = 50.030, sigma = 0.002")),  # off-centre, within a tolerance width
    ("throw_angles = [0, 180, 180, 0]", "throw_angles = [0, 180, 180, 360]"),
])
def test_plausible_but_unusual_values_load(tmp_path, old, new):
    engine = load_engine(engine_file(tmp_path, old, new))
    assert engine.crank.bearing_width == pytest.approx(engine.press_fit.bearing_width, rel=5e-3)


def test_a_utf8_byte_order_mark_is_accepted(tmp_path):
    path = engine_file(tmp_path, "name = ", "name = ", encoding="utf-8-sig")
    assert path.read_bytes().startswith(b"\xef\xbb\xbf")
    read, builtin = load_engine(path), load_engine("iso-example")
    assert (read.housing_bore, read.press_fit, read.crank.throw_angles) == \
        (builtin.housing_bore, builtin.press_fit, builtin.crank.throw_angles)


def test_a_utf16_file_is_named_as_such(tmp_path):
    path = engine_file(tmp_path, "name = ", "name = ", encoding="utf-16")
    with pytest.raises(ValueError, match=r"engine file '.*engine.toml': is UTF-16 text .*; save it as UTF-8"):
        load_engine(path)


def test_a_scheme_file_given_as_the_engine_and_back_is_named():
    with pytest.raises(ValueError, match=r"engine file 'iso13778-4.toml': is a scheme file \(it has \[housing\], "
                                         r"\[journal\], \[shell\], \[pairing\]\), not an engine file; give it as a "
                                         r"scheme \(compare --schemes"):
        load_engine(ISO4)
    with pytest.raises(ValueError, match=r"scheme file 'iso-example.toml': is an engine file \(it has main_bearings,"
                                         r".*\), not a scheme file; give it as the engine \(--engine\)"):
        load_scheme(builtin_folder() / "iso-example.toml")


def test_a_file_of_another_kind_is_named(tmp_path):
    materials = builtin_folder().parent / "materials.toml"
    with pytest.raises(ValueError, match=r"engine file 'materials.toml': is not an engine file \(none of main_bearings, "
                                         r"\[housing_bore\], \[journal_d\]; it has units, steel, steel-back"):
        load_engine(materials)
    with pytest.raises(ValueError, match=r"scheme file 'materials.toml': is not a scheme file \(none of \[housing\]"):
        load_scheme(materials)
    readings = tmp_path / "bores.csv"
    readings.write_text("bore\n50.009\n")
    with pytest.raises(ValueError, match=r"engine file '.*bores.csv': is a .csv file, not a TOML engine file"):
        load_engine(readings)


@pytest.mark.parametrize("path", [*sorted(builtin_folder().glob("*.toml")), *sorted(DATA.glob("*.toml"))],
                         ids=lambda p: p.name)
def test_every_builtin_engine_and_test_file_passes_the_plausibility_checks(path):
    assert load_engine(path).main_bearings >= 2


@pytest.mark.parametrize("angles, refused", [
    ([0, 3.14159, 3.14159, 0], True), ([0, 2.0944, 4.1888], True), ([0.0, 0.0, 0.0], False), ([0], False),
    ([0, 180, 180, 0], False), ([0, 90, 270, 180], False), ([0, 12.4], False), ([-3.1, 3.1], True),
])
def test_radians_are_told_from_degrees(angles, refused):
    if refused:
        with pytest.raises(ValueError, match=r"throws: \[.*\] look like radians"):
            check.degrees_not_radians("throws", angles)
    else:
        assert check.degrees_not_radians("throws", angles) == angles


def test_a_plausible_range_scales_with_another_input_and_names_it():
    masses = check.PLAUSIBLE["cylinder_mass"]
    bore = 0.076
    assert masses.check("m", 0.75, scale=bore**-3) == 0.75
    with pytest.raises(ValueError, match=r"m: 750 kg is not a plausible mass of one cylinder's parts for a 76 mm bore "
                                         r"\(0.0878 to 8.78 kg\); give it in kg"):
        masses.check("m", 750, scale=bore**-3, of=" for a 76 mm bore")
    for name, plausible in check.PLAUSIBLE.items():  # a range, with the slip it catches said
        assert plausible.lo < plausible.hi and plausible.hint, name


def test_process_sigma_is_checked_in_the_files_units():
    with pytest.raises(ValueError, match=r"bore.sigma: 2 mm is not a plausible process standard deviation "
                                         r"\(1e-06 to 1 mm\)"):
        process_from_spec({"mean": 50.0, "sigma": 2.0}, lo=50e-3, hi=50.018e-3, scale=1e-3, field="bore")
    process = process_from_spec({"mean": 50.009, "sigma": 0.002}, lo=50e-3, hi=50.018e-3, scale=1e-3, field="bore")
    assert process.sigma == pytest.approx(2e-6) and np.isclose(process.mean, 50.009e-3)
