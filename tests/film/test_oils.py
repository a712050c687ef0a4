"""Oils as data: the built-in grades against SAE J300 and their own numbers, and a user's oils file."""

import tomllib
from importlib import resources

import pytest

from stackup.engines import engine_files, engine_path, load_engine
from stackup.film import oil

BUILTIN = tomllib.loads((resources.files("stackup") / "data" / "oils.toml").read_text(encoding="utf-8"))

#: SAE J300 (2015), table 2: kinematic viscosity at 100 degC [cSt], low and high (exclusive), and the least
#: HTHS viscosity at 150 degC [mPa s] of each high-temperature grade (SAE 40: 3.5 for 0W-, 5W- and 10W-40, 3.7
#: for 15W-40). Independent of the oils file: a grade whose numbers leave J300 fails here.
J300 = {"16": (6.1, 8.2, 2.3), "20": (6.9, 9.3, 2.6), "30": (9.3, 12.5, 2.9), "40": (12.5, 16.3, 3.5),
        "15W-40": (12.5, 16.3, 3.7)}


def j300_limits(name):
    grade = name.removeprefix("SAE-")
    return J300.get(grade) or J300[grade.split("-")[-1]]


def test_the_built_in_grades_run_from_0w16_to_15w40():
    assert {"SAE-0W-16", "SAE-0W-20", "SAE-5W-30", "SAE-5W-40", "SAE-10W-40", "SAE-15W-40"} <= set(oil.available())


@pytest.mark.parametrize("name", sorted(BUILTIN))
def test_each_grade_lies_inside_its_j300_limits_and_says_it_is_assumed(name):
    entry = BUILTIN[name]
    lo, hi, hths = j300_limits(name)
    assert lo <= entry["kv100"] * 1e6 < hi
    assert entry["hths150"] * 1e3 >= hths
    assert entry["assumed"] and entry["source"].startswith("assumed:") and oil.get(name).assumed


@pytest.mark.parametrize("name", sorted(BUILTIN))
def test_the_vogel_constants_give_back_the_files_kv40_kv100_and_hths(name):
    entry, o = BUILTIN[name], oil.get(name)
    for t, kv in ((40.0, entry["kv40"]), (100.0, entry["kv100"])):
        assert float(o.low_shear_viscosity(t)) / float(o.density(t)) == pytest.approx(kv, rel=1e-6), t
    if entry["multigrade"]:
        assert float(o.viscosity(150.0, shear_rate=1e6)) == pytest.approx(entry["hths150"], rel=1e-9)


USER_OIL = """
["Acme-0W-20"]   # Acme Longlife 0W-20, product data sheet 2024
kv40 = 45.1e-6
kv100 = 8.6e-6
hths150 = 2.7e-3
density15 = 842.0
multigrade = true
source = "Acme Longlife 0W-20 product data sheet, 2024"
"""


def engine_with_oil(tmp_path, oils=USER_OIL, grade="Acme-0W-20", file="my-oils.toml"):
    text = engine_path("iso-example").read_text(encoding="utf-8")
    text = text.replace('grade = "SAE-5W-30"', f'grade = "{grade}"\nfile = "{file}"', 1)
    (tmp_path / "my.toml").write_text(text, encoding="utf-8")
    if oils is not None:
        (tmp_path / "my-oils.toml").write_text(oils, encoding="utf-8")
    return tmp_path / "my.toml"


def test_an_engine_file_names_a_users_oils_file_and_runs_its_oil(tmp_path):
    files = engine_files(engine_with_oil(tmp_path))
    (tmp_path / "my-oils.toml").unlink()  # a study stores the oils file's text: it reruns without the file
    used = load_engine("my", files=files).crank.oil
    assert used.name == "Acme-0W-20" and not used.assumed
    assert float(used.low_shear_viscosity(40.0)) / float(used.density(40.0)) == pytest.approx(45.1e-6, rel=1e-6)


@pytest.mark.parametrize(("oils", "grade", "message"), [
    (USER_OIL.replace("45.1e-6", "45.1"), "Acme-0W-20",
     (r"oils file 'my-oils.toml', key Acme-0W-20.kv40: 45.1 m\^2/s is outside .*a data sheet's cSt \(mm\^2/s\) "
      r"times 1e-6")),
    (USER_OIL.replace("Acme-0W-20", "SAE-0W-20"), "SAE-0W-20",
     "oils file 'my-oils.toml', key SAE-0W-20: is the name of a built-in oil"),
    (USER_OIL, "Acme-0W-2O", r"engine file 'my.toml', key oil.grade: 'Acme-0W-2O' is not one of .*'Acme-0W-20'"),
    (USER_OIL.replace("source", "# source"), "Acme-0W-20", "key Acme-0W-20.source: missing"),
    (None, "Acme-0W-20", "engine file 'my.toml', key oil.file: 'my-oils.toml' does not exist"),
])
def test_a_bad_oils_file_or_grade_is_refused_naming_the_file_and_the_key(tmp_path, oils, grade, message):
    with pytest.raises(ValueError, match=message):
        load_engine(engine_with_oil(tmp_path, oils, grade))
