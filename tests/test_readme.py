"""The README's Python examples, pasted into a script and run as a user runs it (``python script.py``).

Each block is taken from README.md as written; where a block is sized for a
real run (20 million engines, a remote dask cluster) the test shrinks exactly
those values, naming each, and fails if the README no longer holds them.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).parents[1] / "README.md"
SMALL_COMPARE = ["compare", "--n", "100", "--schemes", "iso13778-4", "iso13778-6", "--no-design", "--no-scenarios"]


def python_blocks():
    """The README's ```python blocks, in order."""
    text = README.read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


#: A line of each README block, the one the test of that block finds it by.
TESTED = ("c = ds.clearance_operating", "xr.testing.assert_equal(again, ds)", "stackup.rank(open_comparison(",
          "import stackup.schemes as schemes", "from distributed import Client")


def block(containing):
    found = [b for b in python_blocks() if containing in b]
    assert len(found) == 1, f"README.md: {len(found)} python blocks hold {containing!r}, expected one"
    return found[0]


def shrunk(code, changes):
    """``code`` with each (old, new) replaced; every old text must be in the README's block."""
    for old, new in changes:
        assert old in code, f"README.md: the example no longer holds {old!r}"
        code = code.replace(old, new)
    return code


def run_script(code, cwd, timeout=900):
    """Write ``code`` to cwd/example.py and run it with this Python, as a user would."""
    script = Path(cwd) / "example.py"
    script.write_text(code, encoding="utf-8")
    return subprocess.run([sys.executable, str(script)], cwd=cwd, capture_output=True, text=True, timeout=timeout,
                          env={**os.environ, "PYTHONWARNINGS": "ignore::DeprecationWarning"})


def test_every_python_block_is_run_by_a_test():
    untested = [b for b in python_blocks() if not any(line in b for line in TESTED)]
    assert not untested, f"README.md python blocks without a test here: {untested}"
    assert all(block(line) for line in TESTED)  # each found in exactly one block


@pytest.fixture(scope="module")
def compare_folder(tmp_path_factory):
    """A folder whose reports/compare/ holds a small comparison written by the command line, as the README's."""
    folder = tmp_path_factory.mktemp("readme")
    result = subprocess.run([sys.executable, "-m", "stackup.cli", *SMALL_COMPARE, "--out", "reports/compare"],
                            cwd=folder, capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, result.stderr
    return folder


@pytest.mark.slow
def test_the_datasets_examples_run_and_the_study_rebuilds_from_it_identically(compare_folder):
    for first in ("c = ds.clearance_operating", "xr.testing.assert_equal(again, ds)", "stackup.rank(open_comparison("):
        code = block(first)
        lines = code.splitlines()
        last = lines[-1].split("#")[0].strip()
        if not last.startswith(("xr.testing", "assert")):  # a notebook line: printed, so its value is computed
            code = "\n".join(lines[:-1] + [f"print({last})"])
        result = run_script(code, compare_folder)
        assert result.returncode == 0, result.stderr
        assert "Traceback" not in result.stderr
    # the identity is exact: a dataset stored to 10 nm (--compact) would differ by up to 5 nm
    assert "again = Study.from_dataset(ds).run()" in block("xr.testing.assert_equal(again, ds)")


@pytest.mark.slow
def test_the_library_example_runs_as_a_script(tmp_path):
    code = shrunk(block("import stackup.schemes as schemes"), [
        ('n_engines=10_000, seed=1', 'n_engines=500, seed=1'),
        ('stackup.compare(n_engines=20_000, design={})', 'stackup.compare(n_engines=200, design={}, scenarios={})'),
    ])
    checks = """
assert s4.pair(50.0075e-3, 46.0031e-3) == ('D', 'D')
assert np.allclose(s4.clearance_limits(), (2.6e-05, 4.4e-05), rtol=1e-12, atol=0)
assert r.reactions.shape == (720, 5, 2) and r.converged.all()
assert cold_hot.highest_stress_temperature == -30.0
assert 100 < float(life.life) / 3600, life.life
print("designed:", [str(s) for s in comparison.dataset.scheme.values])
"""
    result = run_script(code + checks, tmp_path, timeout=1800)
    assert result.returncode == 0, result.stderr
    assert "designed: " in result.stdout


@pytest.mark.slow
def test_the_dask_example_runs_as_a_script(tmp_path):
    """Pasted into a script it runs: the processes scheduler, in process, and a dask cluster by its address."""
    from distributed import LocalCluster

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp",
                      dashboard_address=None) as cluster:
        code = shrunk(block("from distributed import Client"), [
            ("n_engines=20_000_000", "n_engines=2_000"),
            ('"tcp://scheduler-host:8786"', repr(cluster.scheduler_address)),
        ])
        code += "\n    print('engines', ds.attrs['n_engines'] if 'n_engines' in ds.attrs else ds.sizes)\n"
        result = run_script(code, tmp_path)
    assert result.returncode == 0, result.stderr
    assert "Nanny failed" not in result.stderr and "Traceback" not in result.stderr
    assert (tmp_path / "runs" / "big.zarr").is_dir()
