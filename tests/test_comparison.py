"""The main job as one library call (stackup.comparison.run): the folder ``stackup compare`` writes, the same
refusals in the library's words, before anything is computed."""

import pytest
import xarray as xr

import stackup.comparison
import stackup.schemes
from stackup.cli import main
from stackup.io import open_comparison

#: The smallest main job, with its own window (the command line's WINDOW_COMPARE, tests/cli).
SMALLEST = dict(n_engines=100, schemes=("iso13778-4",), scenarios={}, uncertainties=None, design=None,
                window=(30e-6, 45e-6))
SMALLEST_OPTIONS = ["--n", "100", "--schemes", "iso13778-4", "--no-scenarios", "--no-design", "--window", "30", "45"]


@pytest.mark.integration
def test_run_writes_the_folder_the_command_writes(tmp_path, capsys):
    written = stackup.comparison.run(tmp_path / "library", **SMALLEST)
    assert main(["compare", *SMALLEST_OPTIONS, "--out", str(tmp_path / "command")]) == 0
    assert f"verdict: {written.verdict}" in capsys.readouterr().out
    library, command = open_comparison(written.dataset), open_comparison(tmp_path / "command" / "compare.nc")
    assert library.scenarios.keys() == command.scenarios.keys() == set()
    for part in ("dataset", "sensitivity", "tails"):
        xr.testing.assert_identical(getattr(library, part), getattr(command, part))  # no designer: no wall time
    assert written.report.read_text() == (tmp_path / "command" / "report.md").read_text()
    assert sorted(p.name for p in written.folder.iterdir()) == sorted(p.name for p in (tmp_path / "command").iterdir())


def test_a_scheme_leaving_parts_ungraded_is_refused_naming_it_before_any_folder(tmp_path, write_toml):
    text = (stackup.schemes.builtin_folder() / "iso13778-4.toml").read_text(encoding="utf-8")
    narrow = write_toml("narrow.toml", text.replace('name = "iso13778-4"', 'name = "narrow-c"')
                        .replace("C = [50.012, 50.018] }", "C = [50.012, 50.013] }", 1))
    with pytest.raises(ValueError, match=r"^schemes: scheme narrow-c \(.*narrow.toml\) leaves .* widen the scheme's"):
        stackup.comparison.run(tmp_path / "run", **{**SMALLEST, "schemes": ("iso13778-4", narrow)})
    with pytest.raises(ValueError, match=r"^schemes: scheme narrow-c"):  # the library's compare too, at once
        stackup.compare(schemes=(narrow,), n_engines=100, scenarios={}, uncertainties=None)
    assert not (tmp_path / "run").exists()


@pytest.mark.parametrize("changes, message", [
    ({"n_engines": 99}, r"^n_engines: 99 is not valid"),
    ({"n_engines": 10**10}, r"^n_engines: 10,000,000,000 engines would need about .* give n_engines at most"),
    ({"negligible": -1.0}, r"^negligible: "),
    ({"scenarios": {"a": {"housing_shift": "x"}}}, r"housing_shift"),
])
def test_bad_input_is_refused_before_any_folder(tmp_path, changes, message):
    with pytest.raises(ValueError, match=message):
        stackup.comparison.run(tmp_path / "run", **{**SMALLEST, **changes})
    assert list(tmp_path.iterdir()) == []


def test_an_output_that_is_a_file_or_holds_another_run_is_refused_in_the_librarys_words(tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    with pytest.raises(ValueError, match=r"^out '.*afile' is a file, not a folder"):
        stackup.comparison.run(afile, **SMALLEST)
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "mine.txt").write_text("mine")
    with pytest.raises(ValueError, match=r"is not empty and holds no stackup run \(it holds 'mine.txt'\)"):
        stackup.comparison.run(tmp_path / "notes", **SMALLEST)


def test_the_tail_and_sensitivity_stages_show_progress_as_the_study_does(capsys):
    from stackup._comparison import bar, tails_dataset

    tails_dataset("iso-example", ["iso13778-4"], progress=True)
    assert "tails: 100%" in capsys.readouterr().err
    with bar(3, "sensitivity", "run", False) as quiet:
        quiet.update(3)
    with bar(2, "sensitivity", "run", True) as shown:
        shown.update(2)
    err = capsys.readouterr().err
    assert err.count("sensitivity") >= 1 and "2/2" in err and "3/3" not in err
