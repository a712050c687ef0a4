"""The command line as a process: Ctrl-C at every stage and at start-up, a killed run, arguments that are not
text, a run's log on stdout. Each test starts ``stackup`` in a fresh interpreter, as a user's shell does."""

import os
import signal
import subprocess
import sys
import time

import pytest
from cli_helpers import (INLINE6, SMALL_COMPARE, WINDOW_COMPARE, interruptible, listing, one_line_refusal, start,
                         stackup, stackup_process)

from stackup.io import open_dataset

pytestmark = pytest.mark.integration


def test_ctrl_c_ends_a_run_with_one_line_and_leaves_nothing(tmp_path):
    out = tmp_path / "run"
    process = subprocess.Popen([sys.executable, "-m", "stackup.cli", *SMALL_COMPARE, "--out", str(out)],
                               preexec_fn=interruptible,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = process.stdout.readline()
    assert "study: 100 engines" in first
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130
    assert err == f"stackup: interrupted during study; nothing was saved: {out} was not created\n"
    assert list(tmp_path.iterdir()) == []  # no half-written folder, no staging folder


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    """The smallest comparison written by the command line (25 s here, mostly the tails and Sobol stages)."""
    out = tmp_path_factory.mktemp("compare") / "run"
    return out, stackup_process(*WINDOW_COMPARE, "--out", out)


@pytest.mark.slow
def test_a_run_logs_each_stage_and_writes_its_files_whole(small_run):
    out, result = small_run
    assert result.returncode == 0 and result.stderr == ""  # no progress bars off a terminal, no warnings
    stages = [line.split("] ", 1)[1] for line in result.stdout.splitlines() if line.startswith("[")]
    assert stages[0].startswith("study: 100 engines x 1 scheme")
    assert [s.split(":")[0] for s in stages[1:-2]] == ["tails", "sensitivity"]  # the library's own stages
    assert stages[-2:] == [f"saving the dataset: {out}/compare.nc", f"writing the report: {out}/report.md and report.html"]
    assert result.stdout.splitlines()[-1].startswith("verdict: ")  # the report's first verdict line, plain
    assert "**" not in result.stdout.splitlines()[-1]
    names = {p.name for p in out.iterdir()}
    assert {"compare.nc", "report.md", "report.html", "clearance_histogram.png"} <= names
    assert not any(name.startswith(".stackup-partial") for name in names)
    assert not any(p.name.startswith(".stackup-partial") for p in out.parent.iterdir())
    ds = open_dataset(out / "compare.nc")
    assert ds.clearance_window.values.tolist() == [30e-6, 45e-6]  # the --window, in m


@pytest.mark.slow
def test_a_different_run_into_a_folder_holding_a_run_is_refused(small_run):
    out, _ = small_run
    before = listing(out)
    result = stackup(*WINDOW_COMPARE, "--seed", 3, "--out", out)
    assert result.returncode == 2 and result.stdout == ""
    assert "holds another run (100 engines of iso-example, 1 scheme, seed 0, window 30-45 um, no scenarios)" \
        in result.stderr
    assert listing(out) == before


@pytest.mark.slow
def test_the_same_run_again_replaces_it_and_ctrl_c_while_saving_leaves_it_as_it_was(small_run):
    out, _ = small_run
    before = listing(out)
    process = subprocess.Popen([sys.executable, "-m", "stackup.cli", *WINDOW_COMPARE, "--out", str(out)],
                               preexec_fn=interruptible,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in process.stdout:
        if "saving the dataset" in line:
            break
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130
    assert err == f"stackup: interrupted during saving the dataset; nothing was saved: {out} is as it was\n"
    assert listing(out) == before
    again = stackup(*WINDOW_COMPARE, "--out", out)
    assert again.returncode == 0
    assert all(listing(out)[name][1] > before[name][1] for name in before)  # every file written anew


def test_an_engine_path_that_is_not_utf8_is_refused_before_the_study(tmp_path):
    if sys.platform == "darwin":
        pytest.skip("macOS file names are UTF-8 by construction")
    folder = os.fsencode(tmp_path)
    name = os.path.join(folder, b"motor\xff.toml")
    with open(name, "wb") as file:
        file.write(INLINE6.read_bytes())
    result = subprocess.run([os.fsencode(sys.executable), b"-m", b"stackup.cli", b"compare", b"--engine", name,
                             b"--out", os.path.join(folder, b"run")], capture_output=True, text=True, timeout=120)
    one_line_refusal(result, "the path is not UTF-8 text", "rename the file or its folder with UTF-8 characters")
    assert not os.path.exists(os.path.join(folder, b"run"))


def _wait_for(process, text):
    for line in process.stdout:
        if text in line:
            return line
    raise AssertionError(f"the run ended before {text!r}: {process.stderr.read()}")


@pytest.mark.slow
def test_a_killed_runs_staging_folder_is_removed_by_the_next_run_and_folders_follow_the_umask(tmp_path):
    out = tmp_path / "run"
    killed = start([*WINDOW_COMPARE, "--out", out], umask=0o022)
    _wait_for(killed, "study: ")
    killed.kill()  # kill -9: nothing of the run's own code runs
    killed.communicate(timeout=60)
    left = [p.name for p in tmp_path.iterdir() if p.name.startswith(".stackup-partial-")]
    assert left and not out.exists()
    assert all((tmp_path / name).stat().st_mode & 0o777 == 0o755 for name in left)  # not 0700: a colleague reads
    again = start([*WINDOW_COMPARE, "--out", out], umask=0o022)
    _wait_for(again, "study: ")  # the claim is taken and the stale staging folders removed before the study
    assert not any((tmp_path / name).exists() for name in left)
    again.send_signal(signal.SIGINT)
    _, err = again.communicate(timeout=120)
    assert again.returncode == 130 and err == f"stackup: interrupted during study; nothing was saved: {out} was not created\n"
    assert [p.name for p in tmp_path.iterdir() if not p.name.startswith(".stackup-claim-")] == []


@pytest.mark.slow
@pytest.mark.parametrize("stage", ["study", "tails", "sensitivity", "saving the dataset", "writing the report"])
def test_ctrl_c_at_any_stage_exits_130_with_one_line_saying_what_was_kept(tmp_path, stage):
    out = tmp_path / "run"
    process = start([*WINDOW_COMPARE, "--out", out])
    _wait_for(process, f"] {stage}")
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=300)
    assert process.returncode == 130, err
    assert err == f"stackup: interrupted during {stage}; nothing was saved: {out} was not created\n"
    assert [p.name for p in tmp_path.iterdir() if not p.name.startswith(".stackup-claim-")] == []


def _started_after_imports(args):
    """``stackup ARGS`` in a fresh process that prints "ready" once the package is imported (see the test below)."""
    code = ("import sys; import stackup.cli as cli; import stackup.comparison, stackup.plan, stackup.report; "
            "print('ready', flush=True); "
            f"sys.exit(cli.main({[str(a) for a in args]!r}))")
    process = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=interruptible)
    assert process.stdout.readline() == "ready\n"
    time.sleep(1)  # into the command
    return process


def test_ctrl_c_while_planning_exits_130_with_one_line(tmp_path):
    csv = tmp_path / "plan.csv"
    process = _started_after_imports(["plan", "--scheme", "iso13778-4", "--volume", 10_000, "--sample", 400_000,
                                      "--csv", csv])
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130
    assert err == f"stackup: interrupted during planning shells; nothing was saved: {csv} was not created\n"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_ctrl_c_while_writing_a_report_again_leaves_the_old_report(small_run):
    folder, result = small_run
    assert result.returncode == 0, result.stderr
    before = listing(folder)
    process = _started_after_imports(["report", folder / "compare.nc"])
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130
    assert err in [f"stackup: interrupted during {stage}; nothing was saved: {folder} is as it was\n"
                   for stage in ("reading the dataset", "writing the report")]
    assert listing(folder) == before


@pytest.mark.parametrize("after", [0.3, 0.5, 0.7, 0.9, 1.1])
def test_ctrl_c_while_the_command_starts_exits_130_with_one_line(after):
    # python is up, numpy, scipy, pandas, xarray and numba are being imported: a Ctrl-C inside an extension's
    # initialisation or in code it runs through PyRun_String used to end as an ImportError or by SIGINT. A large
    # sample keeps the command running well past 1.1 s: with the default one it can finish by then on an idle
    # machine, and a Ctrl-C while the interpreter shuts down (its handler gone) ends it by SIGINT
    process = start(["plan", "--scheme", "iso13778-4", "--volume", 100, "--sample", 1_000_000])
    time.sleep(after)
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130 and err.startswith("stackup: interrupted") and err.count("\n") == 1, err



def test_a_reader_that_closes_the_pipe_ends_the_command_without_a_traceback():
    """`stackup schemes | head`: the reader gone before the output is written; exit 141, as a shell reports
    SIGPIPE, and nothing on stderr."""
    process = subprocess.Popen([sys.executable, "-m", "stackup.cli", "schemes"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    process.stdout.close()  # before the command writes: its first write meets a closed pipe
    stderr = process.stderr.read()
    assert process.wait(timeout=120) == 141, stderr
    assert stderr == ""
