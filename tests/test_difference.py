"""``stackup diff``: the verdict, shares, lives and inputs of two saved comparisons, from their datasets alone."""

import json
import shutil

import netCDF4

from stackup.cli import main
from stackup.difference import _scheme_keys, between, lines, read
from stackup.schemes import load, scheme_path


def test_a_scheme_read_from_another_layout_is_the_same_input():
    text = scheme_path("iso13778-4").read_text(encoding="utf-8")
    assert _scheme_keys(text, "s") == _scheme_keys(load("iso13778-4").to_toml_text(), "s")
    assert _scheme_keys(text.replace("1.975", "1.976", 1), "s") != _scheme_keys(text, "s")


def test_a_run_that_is_not_a_saved_comparison_is_refused_in_one_line(tmp_path, capsys):
    assert main(["diff", str(tmp_path / "nothing"), str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "run: " in err and "is not a file" in err


def test_diff_says_what_changed_in_the_inputs_and_nothing_where_the_runs_agree(small_comparison, tmp_path):
    a = small_comparison.folder / "compare.nc"
    first = read(small_comparison.folder)
    same = between(first, first)
    assert same.same_choice and same.inputs == []
    assert not same.schemes.filter(like="_apart").any().any()
    text = "\n".join(lines(same))
    assert "Verdict: both choose" in text and "Inputs: the same" in text
    b = tmp_path / "compare.nc"  # the same numbers, told they came from another engine file and seed
    shutil.copy(a, b)
    with netCDF4.Dataset(b, "a") as nc:
        study, files = json.loads(nc.getncattr("study")), json.loads(nc.getncattr("input_files"))
        study["seed"] += 1
        files["engine"]["text"] = files["engine"]["text"].replace("housing_outer = 90.0", "housing_outer = 95.0", 1)
        nc.setncattr("study", json.dumps(study))
        nc.setncattr("input_files", json.dumps(files))
    changed = between(first, b)
    assert ("engine file press_fit.housing_outer", 90.0, 95.0) in changed.inputs
    assert ("study seed", study["seed"] - 1, study["seed"]) in changed.inputs and len(changed.inputs) == 2
    text = "\n".join(lines(changed))
    assert "engine file press_fit.housing_outer: 90.0 -> 95.0" in text and "outside window [ppm]" in text
