"""The command line as a user meets it, run in this process: exit codes, messages and the files left behind.

What is about the process itself (Ctrl-C, kill, start-up, arguments that are not text) is in test_process.py.
"""

import argparse
import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from cli_helpers import (INLINE6, ISO4, SMALL_COMPARE, listing, no_traceback_nor_warning, one_line_refusal,
                         stackup)

from stackup.cli import main, parser
from stackup.comparison import COMPARE_MIN_ENGINES
from stackup.plan import plan
from stackup.study import Study, open_study
from stackup.study.damage import DamagedStore


# --- help -----------------------------------------------------------------------------------------------------


def _subparsers(p, path=()):
    yield path, p
    for action in p._actions:
        if action.__class__.__name__ == "_SubParsersAction":
            for name, sub in action.choices.items():
                yield from _subparsers(sub, (*path, name))


def test_every_option_of_every_command_has_a_help_text_and_its_default(capsys):
    for path, p in _subparsers(parser()):
        assert main([*path, "--help"]) == 0
        text = " ".join(capsys.readouterr().out.split())
        for action in p._actions:
            assert action.help, (path, action.dest)
            if action.option_strings and action.default not in (None, False, argparse.SUPPRESS):
                assert f"default: {action.default}" in text or "default" in action.help, (path, action.dest)
    assert main(["compare", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for expected in ("(default: iso-example)", "(default: 0)", "default: reports/compare; reports/compare-quick with "
                     "--quick", "default: 100000; 10000 with --quick", "--window LO HI", "micrometres"):
        assert expected in text


# --- plan -----------------------------------------------------------------------------------------------------


def test_plan_answers_in_whole_shells_with_units_and_a_csv_for_the_spreadsheet(tmp_path):
    csv = tmp_path / "shells.csv"
    result = stackup("plan", "--scheme", "iso13778-5", "--volume", 10_000, "--sample", 5000, "--csv", csv)
    assert result.returncode == 0 and result.stderr == ""
    out = result.stdout
    assert out.startswith("How many shells of each grade to make and stock for 10,000 engines of iso-example "
                          "with scheme iso13778-5?")
    assert "covered in 99 % of lots" in out and "the volume is 10 lots of 1,000 engines" in out
    table = pd.read_csv(csv, index_col="grade")
    assert list(table.index) == ["A", "B", "C", "scrapped", "all shells"]
    for column in table.columns:  # units and what each count is for, in the name
        assert column.endswith(("[shells]", "[%]")), column
    assert "stock per lot of 1000 engines [shells]" in table.columns
    grades = table.drop(["scrapped", "all shells"])
    counts = [c for c in table.columns if c.endswith("[shells]")]
    raw = pd.read_csv(csv, index_col="grade", dtype=str)
    assert raw[counts].stack().dropna().str.fullmatch(r"-?\d+").all()  # whole shells, no 9687.9
    # the same plan as the library's, rounded the way a stock must cover demand
    frame = plan("iso13778-5", volume=10_000, sample_engines=5000)
    assert (grades["needed, 10000 engines [shells]"] == np.ceil(frame.demanded - 1e-9)).all()
    assert (grades["stock per lot of 1000 engines [shells]"] == frame.order_up_to).all()
    assert table["made, 10000 engines [shells]"].drop("all shells").sum() == frame.attrs["shells_made"]
    assert (grades["surplus, 10000 engines [shells]"]
            == grades["made, 10000 engines [shells]"] - grades["needed, 10000 engines [shells]"]).all()
    for column in counts:
        if "95 %" not in column:
            assert table.loc["all shells", column] == table[column].drop("all shells").sum()
    # the printed table is the CSV's: every grade row carries the same whole numbers
    row_a = next(line for line in out.splitlines() if line.startswith("A "))
    assert row_a.split()[1:] == [f"{v:.2f}" if c.endswith("[%]") else f"{int(v):,}" for c, v in table.loc["A"].items()]
    # the CSV alone on stdout, for a pipe
    piped = stackup("plan", "--scheme", "iso13778-5", "--volume", 10_000, "--sample", 5000, "--csv", "-")
    assert piped.returncode == 0 and piped.stdout == csv.read_text()


def test_plan_refuses_stock_options_for_graded_parts():
    for option, value in (("--lot", 10), ("--service-level", 0.9)):
        result = stackup("plan", "--scheme", "iso13778-4", "--volume", 100, "--part", "housing", option, value)
        assert result.returncode == 2 and result.stdout == ""
        assert result.stderr == (f"stackup: error: {option}: applies to the shell stock only; housing bores are graded, "
                                 "not stocked: leave it out, or plan the shells\n")


def test_plan_of_graded_journals_counts_them_with_the_ungradable_ones():
    result = stackup("plan", "--scheme", "iso13778-4", "--volume", 1000, "--part", "journal", "--sample", 2000)
    assert result.returncode == 0
    assert "How many crankshaft main journals of each grade will 1,000 engines" in result.stdout
    assert "expected, 1000 engines [journals]" in " ".join(result.stdout.split()) or "[journals]" in result.stdout
    assert any(line.startswith("not gradable") for line in result.stdout.splitlines())


def test_plan_refuses_a_lot_larger_than_the_volume():
    result = stackup("plan", "--scheme", "iso13778-5", "--volume", 10_000, "--lot", 20_000)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == ("stackup: error: --lot: a lot of 20,000 engines is more than the volume of 10,000 "
                             "engines; give a lot of at most 10,000 engines (the whole volume as one lot)\n")


def test_plan_of_a_volume_smaller_than_a_lot_is_one_lot_and_says_so(tmp_path):
    csv = tmp_path / "seven.csv"
    result = stackup("plan", "--scheme", "iso13778-5", "--volume", 7, "--sample", 5000, "--csv", csv)
    assert result.returncode == 0
    assert "The volume of 7 engines is less than the engine's lot of 1,000: planned as one lot of 7 engines." \
        in result.stdout
    table = pd.read_csv(csv, index_col="grade")
    assert "stock per lot of 7 engines [shells]" in table.columns
    assert table.loc["all shells", "made, 7 engines [shells]"] == math.ceil(7 * 5 * 2 * 1.1)
    # a lot this small needs more stock than the 10 % surplus makes: said, not hidden
    assert "Note: that stock" in result.stdout


def test_plan_refuses_an_existing_csv_without_force_before_computing(tmp_path):
    csv = tmp_path / "shells.csv"
    csv.write_text("a planner's own numbers\n")
    result = stackup("plan", "--scheme", "iso13778-5", "--volume", 100, "--csv", csv)
    assert result.returncode == 2 and result.stdout == ""  # nothing computed, nothing printed
    assert "--csv" in result.stderr and "exists; pass --force to replace it" in result.stderr
    assert csv.read_text() == "a planner's own numbers\n"
    result = stackup("plan", "--scheme", "iso13778-5", "--volume", 100, "--sample", 1000, "--csv", csv, "--force")
    assert result.returncode == 0 and csv.read_text().startswith("grade,")
    lone = stackup("plan", "--scheme", "iso13778-5", "--volume", 100, "--force")
    assert lone.returncode == 2 and "--force: replaces an existing --csv FILE" in lone.stderr and lone.stdout == ""
    folder = stackup("plan", "--scheme", "iso13778-5", "--volume", 100, "--csv", tmp_path)
    assert folder.returncode == 2 and "is a folder; give a file name" in folder.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["shells.csv"]  # no temporary file left


# --- compare: output locations, tiny runs, Ctrl-C --------------------------------------------------------------


def test_compare_refuses_an_output_that_is_a_file_or_cannot_be_written(tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    before = listing(tmp_path)
    for out, message in ((afile, "is a file, not a folder"), (afile / "sub", "is a file, not a folder"),
                         ("/proc/stackup-out", "no file can be created in '/proc'")):
        result = stackup(*SMALL_COMPARE, "--out", out)
        assert result.returncode == 2, out
        assert result.stdout == ""  # nothing computed: no stage was started
        assert result.stderr.startswith("stackup: error: --out ") and message in result.stderr
        assert result.stderr.count("\n") == 1 and no_traceback_nor_warning(result)
    assert listing(tmp_path) == before


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_compare_refuses_a_folder_without_write_permission(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        result = stackup(*SMALL_COMPARE, "--out", locked / "run")
    finally:
        locked.chmod(0o700)
    assert result.returncode == 2 and "cannot be written" in result.stderr and list(locked.iterdir()) == []


def test_compare_refuses_a_folder_of_other_files(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    result = stackup(*SMALL_COMPARE, "--out", tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert "is not empty and holds no stackup run (it holds 'notes.txt')" in result.stderr
    assert [p.name for p in tmp_path.iterdir()] == ["notes.txt"]


def test_quick_runs_write_to_their_own_folder(tmp_path):
    (tmp_path / "reports").mkdir()
    (tmp_path / "reports" / "compare-quick").write_text("in the way")  # so the run stops at once and says where
    result = stackup("compare", "--quick", cwd=tmp_path)
    assert result.returncode == 2 and "--out 'reports/compare-quick' is a file" in result.stderr


@pytest.mark.parametrize("n", ["1", "0", "99"])
def test_compare_refuses_too_few_engines_with_the_minimum(tmp_path, n):
    result = stackup("compare", "--n", n, "--out", tmp_path / "run")
    assert result.returncode == 2 and result.stdout == ""
    assert f"argument --n: {n} engine" in result.stderr and f"give at least {COMPARE_MIN_ENGINES}" in result.stderr
    assert no_traceback_nor_warning(result) and not (tmp_path / "run").exists()


def test_compare_refuses_a_window_that_is_not_one_in_micrometres(tmp_path):
    for window in (("65", "45"), ("0.045", "1065")):
        result = stackup("compare", "--window", *window, "--out", tmp_path / "run")
        assert result.returncode == 2 and "--window: " in result.stderr and "in micrometres" in result.stderr




def _fake_run(folder, **study):
    """A folder holding a comparison's dataset with these study parameters (for the refusal; nothing else read)."""
    folder.mkdir()
    parameters = {"engine": "iso-example", "schemes": ["iso13778-4"], "n_engines": 5000, "seed": 1, "window": None,
                  **study}
    xr.Dataset(attrs={"study": json.dumps(parameters)}).to_netcdf(folder / "compare.nc")
    (folder / "report.md").write_text("# an earlier report\n")


def test_compare_refuses_to_replace_another_run_without_force(tmp_path):
    _fake_run(tmp_path / "run")
    before = listing(tmp_path)
    result = stackup(*SMALL_COMPARE, "--out", tmp_path / "run")
    assert result.returncode == 2 and result.stdout == ""
    assert ("holds another run (5,000 engines of iso-example, 1 scheme, seed 1, no scenarios); pass --force to "
            "replace it") in result.stderr
    assert listing(tmp_path) == before



def test_a_run_with_another_tilt_method_is_another_run(tmp_path):
    from stackup.output import run_identity, saved_run

    _fake_run(tmp_path / "run", tilt_method="coupled")
    saved = saved_run(tmp_path / "run")
    same = dict(engine="iso-example", schemes=["iso13778-4"], n_engines=5000, seed=1, window=None, scenarios=[],
                design=False)
    assert saved == run_identity(**same, tilt_method="coupled") != run_identity(**same)
    before = listing(tmp_path)
    result = stackup(*SMALL_COMPARE, "--out", tmp_path / "run")
    assert result.returncode == 2 and "seed 1, tilt coupled, no scenarios" in result.stderr
    assert listing(tmp_path) == before
    # a run saved before the key is an equilibrium one
    _fake_run(tmp_path / "older")
    assert saved_run(tmp_path / "older")["tilt_method"] == "equilibrium"


def test_the_terminal_verdict_is_the_reports_first_verdict_line(tmp_path):
    from stackup.comparison import verdict_line

    report = tmp_path / "report.md"
    report.write_text("# title\n\n<!-- verdict -->\n**Use B** for e: 1 ppm of `x`.\n\n**What it costs:** 2.\n"
                      "<!-- /verdict -->\n", encoding="utf-8")
    assert verdict_line(report) == "Use B for e: 1 ppm of x."









# --- engines and schemes ------------------------------------------------------------------------------------


def test_engines_and_schemes_list_the_built_in_ones_and_what_the_user_path_adds(tmp_path, engine_file):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "house-4.toml").write_text(Path(__file__).parents[2].joinpath("schemes", "iso13778-4.toml").read_text()
                                       .replace('name = "iso13778-4"', 'name = "house-4"'))
    (mine / "broken.toml").write_text("not toml")
    (mine / "test-engine.toml").write_text(engine_file().read_text())
    plain = stackup("schemes", env={"STACKUP_SCHEME_PATH": ""})
    assert plain.returncode == 0 and "iso13778-6" in plain.stdout and "STACKUP_SCHEME_PATH is not set" in plain.stdout
    result = stackup("schemes", env={"STACKUP_SCHEME_PATH": str(mine)})
    assert result.returncode == 0
    built_in, _, added = result.stdout.partition(f"From STACKUP_SCHEME_PATH: {mine}:")
    assert "iso13778-1" in built_in and "house-4" not in built_in
    assert "house-4" in added and "stated clearance 26-44 um" in added
    assert "broken" in added and "cannot be read: scheme file 'broken.toml': not valid TOML" in added
    engines = stackup("engines", env={"STACKUP_ENGINE_PATH": str(mine)})
    assert engines.returncode == 0
    built_in, _, added = engines.stdout.partition(f"From STACKUP_ENGINE_PATH: {mine}:")
    assert "iso-example" in built_in and "rozhdestvensky-4" in built_in and "test-engine" in added
    # a user's engine is found by name, like a built-in one
    found = stackup("plan", "--scheme", "iso13778-5", "--engine", "test-engine", "--volume", 100, "--sample", 500,
                    env={"STACKUP_ENGINE_PATH": str(mine)})
    assert found.returncode == 0 and "engines of test-engine" in found.stdout


# --- a study's store: what it holds, damage, repair ----------------------------------------------------------


def _study(engine_file, store=None):
    return Study(engine=str(engine_file(lot=40)), n_engines=200, seed=5, pilot_engines=2000, chunk_lots=1,
                 mechanics_engines=0, schemes=("iso13778-4", "iso13778-5"), progress=False,
                 store=None if store is None else str(store))


def _corrupt(path):
    data = bytearray(path.read_bytes())
    data[16:48] = bytes(32)
    path.write_bytes(data)


@pytest.mark.integration
def test_a_sound_store_is_checked_whole(engine_file, tmp_path):
    store = tmp_path / "s.zarr"
    _study(engine_file, store).run()
    result = stackup("store", "check", store)
    assert result.returncode == 0
    assert f"{store}: a study of 200 engines x 2 schemes (every engine kept); all 5 chunks computed." in result.stdout
    assert "no damage found" in result.stdout
    missing = stackup("store", "check", tmp_path / "nothing.zarr")
    assert missing.returncode == 2 and "is not a Zarr store" in missing.stderr and no_traceback_nor_warning(missing)


@pytest.mark.integration
def test_a_damaged_chunk_is_named_with_its_recovery_and_recomputed_alone(engine_file, tmp_path, monkeypatch):
    store = tmp_path / "s.zarr"
    reference = _study(engine_file).run()
    _study(engine_file, store).run()
    _corrupt(store / "clearance_operating" / "c" / "0" / "2" / "0")  # scheme 0, engines 80-119, bearings
    where = ("variable 'clearance_operating', Zarr chunk clearance_operating/c/0/2/0 (engines 80 to 119, "
             "study chunk 000002)")
    with pytest.raises(DamagedStore) as raised:
        open_study(store).clearance_operating.load()
    assert where in str(raised.value) and f"`stackup store repair {store}`" in str(raised.value)
    check = stackup("store", "check", store)
    assert check.returncode == 1
    assert f"1 damaged chunk:\n  {where}: error during blosc decompression" in check.stdout
    assert f"To recover: run `stackup store repair {store}` to mark study chunk 000002 to be computed again" \
        in check.stdout
    repair = stackup("store", "repair", store)
    assert repair.returncode == 0 and f"{where}: study chunk 000002 marked to be computed again" in repair.stdout
    status = stackup("store", "check", store)
    assert "4 of 5 chunks computed" in status.stdout and status.returncode == 1  # still unreadable until recomputed
    computed = []
    original = Study.chunk

    def counting(self, first, progress=None):
        computed.append(first)
        return original(self, first, progress)

    monkeypatch.setattr(Study, "chunk", counting)
    recovered = _study(engine_file, store).run()
    assert computed == [2]  # only the damaged chunk is computed again
    xr.testing.assert_identical(recovered.load(), reference)
    assert stackup("store", "check", store).returncode == 0


@pytest.mark.integration
def test_a_damaged_chunk_state_stops_the_resume_naming_it(engine_file, tmp_path):
    store = tmp_path / "s.zarr"
    reference = _study(engine_file).run()
    _study(engine_file, store).run()
    state = next((store / "chunks" / "000001" / "shells" / "made" / "c").rglob("*"))
    while state.is_dir():
        state = next(state.iterdir())
    _corrupt(state)
    with pytest.raises(DamagedStore, match=r"variable 'chunks/000001/shells/made', Zarr chunk chunks/000001/shells/"
                                           r"made/c/.* \(study chunk 000001\) cannot be read"):
        _study(engine_file, store).run()
    assert stackup("store", "repair", store).returncode == 0
    xr.testing.assert_identical(_study(engine_file, store).run().load(), reference)


@pytest.mark.integration
def test_an_interrupted_study_store_says_what_is_saved_and_how_to_resume(engine_file, tmp_path, monkeypatch):
    store = tmp_path / "s.zarr"
    original = Study.chunk

    def interrupted(self, first, progress=None):
        if first == 2:
            raise KeyboardInterrupt
        return original(self, first, progress)

    monkeypatch.setattr(Study, "chunk", interrupted)
    with pytest.raises(KeyboardInterrupt):
        _study(engine_file, store).run()
    result = stackup("store", "check", store)
    assert result.returncode == 0
    assert (f"2 of 5 chunks computed; running the same study with store='{store}' computes the rest and keeps "
            "these.") in result.stdout


@pytest.mark.integration
def test_a_damaged_running_total_of_summaries_restarts_them(engine_file, tmp_path):
    import zarr

    store = tmp_path / "s.zarr"
    kw = dict(keep="summaries")
    summaries = Study(**{**_study(engine_file).parameters(), **kw, "progress": False})
    reference = summaries.run()
    Study(**{**_study(engine_file).parameters(), **kw, "progress": False, "store": str(store)}).run()
    slot = zarr.open_group(str(store / "chunks")).attrs["total"]["slot"]
    chunk = next(p for p in sorted((store / "chunks" / slot).rglob("*")) if p.is_file() and "/c/" in str(p))
    _corrupt(chunk)
    check = stackup("store", "check", store)
    assert check.returncode == 1 and f"chunks/{slot}/" in check.stdout
    assert "to drop the saved running total, then run the same study with the same store" in check.stdout
    repair = stackup("store", "repair", store)
    assert repair.returncode == 0 and "saved running total dropped" in repair.stdout
    rerun = Study(**{**_study(engine_file).parameters(), **kw, "progress": False, "store": str(store)}).run()
    xr.testing.assert_identical(rerun, reference)
    assert stackup("store", "check", store).returncode == 0


@pytest.mark.integration
def test_damaged_store_metadata_is_named_and_not_repaired_chunk_by_chunk(engine_file, tmp_path):
    store = tmp_path / "s.zarr"
    _study(engine_file, store).run()
    (store / "shell_stress" / "zarr.json").write_text('{"zarr_format": 3, "node_ty')
    for action in ("check", "repair"):
        result = stackup("store", action, store)
        assert result.returncode == 2 and no_traceback_nor_warning(result)
        assert ("its metadata file 'shell_stress/zarr.json' cannot be read" in result.stderr
                and "delete the store and run the study again" in result.stderr)


def test_the_quick_start_writes_where_git_tracks_nothing():
    from stackup.comparison import COMPARE_OUT, QUICK_OUT

    root = Path(__file__).resolve().parents[2]
    if not (root / ".git").exists():
        pytest.skip("not a git checkout")
    tracked = subprocess.run(["git", "ls-files", COMPARE_OUT, QUICK_OUT], cwd=root, capture_output=True, text=True)
    assert tracked.returncode == 0 and tracked.stdout == ""
    for path in (f"{COMPARE_OUT}/report.md", f"{QUICK_OUT}/film_life.png"):
        assert subprocess.run(["git", "check-ignore", "-q", path], cwd=root).returncode == 0, path
    assert (root / "reports" / "reference" / "compare" / "report.md").is_file()


# --- what a new user tripped on (issue 36): each case typed as a user types it -------------------------------



def test_a_window_in_millimetres_is_refused_naming_the_likely_mistake(tmp_path):
    result = stackup("compare", "--window", "0.045", "0.065", "--out", tmp_path / "run")
    one_line_refusal(result, "--window: 0.045 0.065 um is no main bearing's clearance",
                      "these look like millimetres: give --window 45 65 (micrometres)")
    assert not (tmp_path / "run").exists()


def test_more_engines_than_the_machine_holds_are_refused_before_any_folder(tmp_path):
    result = stackup("compare", "--n", "10000000000", "--out", tmp_path / "run")
    one_line_refusal(result, "--n: 10,000,000,000 engines would need about", "give --n at most")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("old, new, key, hint", [
    ('housing_material = "nodular-cast-iron"', 'housing_material = "nodular-cast-irn"', "press_fit.housing_material",
     "did you mean 'nodular-cast-iron'?"),
    ('grade = "SAE-5W-30"', 'grade = "SAE-5W30"', "oil.grade", "did you mean 'SAE-5W-30'?"),
    ("firing_order = [1, 5, 3, 6, 2, 4]", "firing_order = [1, 5, 3, 6, 2, 2]", "crank.firing_order",
     "is not a permutation of cylinders 1..6"),
])
def test_an_unknown_material_oil_or_firing_order_names_file_key_and_what_is_valid(tmp_path, old, new, key, hint):
    engine = tmp_path / "my-engine.toml"
    text = INLINE6.read_text(encoding="utf-8")
    assert old in text
    engine.write_text(text.replace(old, new), encoding="utf-8")
    result = stackup("compare", "--engine", engine, "--out", tmp_path / "run")
    one_line_refusal(result, f"engine file '{engine.name}', key {key}: ", hint)
    assert not (tmp_path / "run").exists()


def test_a_key_written_twice_is_named_with_its_line(tmp_path):
    text = ISO4.read_text(encoding="utf-8")
    twice = "grades = { A = [50.000, 50.006] }\n"
    scheme = tmp_path / "twice.toml"
    scheme.write_text(text.replace("[housing]\n", "[housing]\n" + twice), encoding="utf-8")
    line = scheme.read_text().splitlines().index("grades = { A = [50.000, 50.006], B = [50.006, 50.012], "
                                                 "C = [50.012, 50.018] }") + 1
    result = stackup("compare", "--schemes", scheme, "--out", tmp_path / "run")
    one_line_refusal(result, f"scheme file '{scheme.name}': a key is written twice (line {line}: ", "write each key once")
    assert "immutable namespace" not in result.stderr


def test_a_scheme_leaving_parts_ungraded_is_refused_before_the_study_naming_it(tmp_path):
    text = ISO4.read_text(encoding="utf-8").replace('name = "iso13778-4"', 'name = "narrow-c"')
    scheme = tmp_path / "narrow.toml"
    scheme.write_text(text.replace("C = [50.012, 50.018] }", "C = [50.012, 50.013] }", 1), encoding="utf-8")
    result = stackup("compare", "--n", 100, "--no-design", "--no-scenarios", "--schemes", "iso13778-4", scheme, "--out",
                     tmp_path / "run")
    one_line_refusal(result, f"--schemes: scheme narrow-c ({scheme}) leaves ", "of the housing bores read outside",
                      "widen the scheme's grades to the engine's drawing limits")
    assert not (tmp_path / "run").exists()




def test_a_user_scheme_is_found_by_its_file_name_and_by_the_name_the_report_gives_it(tmp_path):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "my-scheme.toml").write_text(ISO4.read_text(encoding="utf-8").replace('name = "iso13778-4"',
                                                                                   'name = "house-4"'))
    env = {"STACKUP_SCHEME_PATH": str(mine)}
    by_file = stackup("plan", "--scheme", "my-scheme", "--volume", 100, "--sample", 100, "--csv", "-", env=env)
    by_name = stackup("plan", "--scheme", "house-4", "--volume", 100, "--sample", 100, "--csv", "-", env=env)
    assert by_file.returncode == by_name.returncode == 0, by_name.stderr
    assert by_file.stdout == by_name.stdout
    typo = stackup("plan", "--scheme", "my-schme", "--volume", 100, env=env)
    one_line_refusal(typo, "scheme: 'my-schme' is not a known scheme", "did you mean 'my-scheme'?")


def test_a_run_claims_its_folder_so_a_second_run_at_once_is_refused(tmp_path):
    from stackup.output import Claim

    out = tmp_path / "run"
    claim = Claim(out, "--out")  # as a run under way holds it
    try:
        result = stackup(*SMALL_COMPARE, "--out", out)
    finally:
        claim.release()
    one_line_refusal(result, f"--out '{out}' is being written by another stackup run (process {os.getpid()})",
                      "wait for it to finish, or give another folder")
    assert not out.exists()










def test_ctrl_c_inside_a_numba_kernel_is_an_interrupt():
    """A Ctrl-C raised inside a compiled call reaches Python as a SystemError whose context is the interrupt."""
    from stackup.cli import _interrupt

    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt:
            raise SystemError("CPUDispatcher(<function kernel>) returned a result with an exception set")
    except SystemError as error:
        assert _interrupt(error)
    assert not _interrupt(SystemError("a real one"))








