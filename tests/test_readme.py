"""The README's and the docs' Python examples, pasted into a script and run as a user runs it (``python script.py``).

Each block is taken from its page (README.md or docs/*.md) as written; where
a block is sized for a real run (the main job's 100,000 engines, 20 million
engines, a remote dask cluster) the test shrinks exactly those values, naming
each, and fails if the page no longer holds them. Every link of these pages
leads to a file of the repository, and an anchor to a heading of it.
"""

import ast
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
#: The pages whose examples and links are checked: the README and every page of docs/.
PAGES = (ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")))

#: A line of each python block, by page: the one the test of that block finds it by.
TESTED = {
    "README.md": ("written = stackup.comparison.run(",),
    "docs/dataset.md": ("for name, variable in ds.data_vars.items():", "c = ds.clearance_operating",
                        "xr.testing.assert_equal(again, ds)"),
    "docs/library.md": ("import stackup.schemes as schemes", "stackup.rank(open_comparison(",
                        "from distributed import Client"),
}
#: The README's main job, shrunk to a small comparison: 100 engines, two schemes, no designer, no scenarios.
SMALL_RUN = ('stackup.comparison.run("reports/compare")',
             'stackup.comparison.run("reports/compare", n_engines=100, schemes=("iso13778-4", "iso13778-6"), '
             'design=None, scenarios={}, uncertainties=None)')


def page_name(path):
    return path.relative_to(ROOT).as_posix()


def fenced(text):
    """``text`` without its fenced code blocks (a ``#`` or a link there is code, not Markdown)."""
    return re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)


def python_blocks(page):
    """The ```python blocks of ``page`` (a path relative to the repository), in order."""
    text = (ROOT / page).read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def block(page, containing):
    found = [b for b in python_blocks(page) if containing in b]
    assert len(found) == 1, f"{page}: {len(found)} python blocks hold {containing!r}, expected one"
    return found[0]


def shrunk(page, code, changes):
    """``code`` with each (old, new) replaced; every old text must be in the page's block."""
    for old, new in changes:
        assert old in code, f"{page}: the example no longer holds {old!r}"
        code = code.replace(old, new)
    return code


def printed(code):
    """``code`` with its last statement printed where it is an expression (a notebook line), so its value is
    computed and shown as a user would see it."""
    tree = ast.parse(code)
    last = tree.body[-1]
    if isinstance(last, ast.Expr):
        tree.body[-1] = ast.Expr(ast.Call(ast.Name("print", ast.Load()), [last.value], []))
    return ast.unparse(ast.fix_missing_locations(tree))


def run_script(code, cwd, timeout=900):
    """Write ``code`` to cwd/example.py and run it with this Python, as a user would."""
    script = Path(cwd) / "example.py"
    script.write_text(code, encoding="utf-8")
    return subprocess.run([sys.executable, str(script)], cwd=cwd, capture_output=True, text=True, timeout=timeout,
                          env={**os.environ, "PYTHONWARNINGS": "ignore::DeprecationWarning"})


def test_every_python_block_is_run_by_a_test():
    assert set(TESTED) <= {page_name(p) for p in PAGES}, "a page of TESTED is gone"
    for path in PAGES:
        page = page_name(path)
        lines = TESTED.get(page, ())
        untested = [b for b in python_blocks(page) if not any(line in b for line in lines)]
        assert not untested, f"{page}: python blocks without a test here: {untested}"
        assert all(block(page, line) for line in lines)  # each found in exactly one block


def anchor(heading):
    """The anchor GitHub gives a Markdown heading: lower case, punctuation dropped, spaces as hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def anchors(path):
    return {anchor(h) for h in re.findall(r"^#+ (.*)$", fenced(path.read_text(encoding="utf-8")), flags=re.M)}


def test_every_link_resolves_to_a_file_and_a_heading():
    broken = []
    for path in PAGES:
        for target in re.findall(r"\]\(([^)\s]+)\)", fenced(path.read_text(encoding="utf-8"))):
            if re.match(r"[a-z]+:", target):  # a web address
                continue
            file, _, heading = target.partition("#")
            linked = (path.parent / file).resolve() if file else path
            if not linked.exists() or ROOT.resolve() not in linked.parents:
                broken.append(f"{page_name(path)}: {target} (no such file in the repository)")
            elif heading and (linked.suffix != ".md" or heading not in anchors(linked)):
                broken.append(f"{page_name(path)}: {target} (no such heading)")
    assert not broken, "\n".join(broken)


def keys(table, within=()):
    """Every key of a TOML table as its path, its sub-tables' (inline ones and arrays of tables too) included."""
    for key, value in table.items():
        yield (*within, key)
        for item in value if isinstance(value, list) else [value]:
            if isinstance(item, dict):
                yield from keys(item, (*within, key))


def test_the_engine_file_page_names_every_key_the_built_in_engines_use():
    """Each key a built-in engine file uses is named on the page: as `key`, or a table as [section.table]."""
    text = (ROOT / "docs" / "engine-file.md").read_text(encoding="utf-8")
    used = {path for file in (ROOT / "stackup" / "data" / "engines").glob("*.toml")
            for path in keys(tomllib.loads(file.read_text(encoding="utf-8")))}
    assert used, "no built-in engine file found"
    unnamed = sorted(".".join(p) for p in used if f"`{p[-1]}`" not in text and f"[{'.'.join(p)}]" not in text)
    assert not unnamed, f"docs/engine-file.md does not name these keys of the built-in engine files: {unnamed}"


@pytest.fixture(scope="module")
def main_job(tmp_path_factory):
    """The README's example run in a fresh folder, shrunk to a small comparison: (folder, its output). The
    folder's reports/compare/ then holds what the docs' dataset examples read."""
    folder = tmp_path_factory.mktemp("readme")
    code = shrunk("README.md", block("README.md", "written = stackup.comparison.run("), [SMALL_RUN])
    checks = """
from pathlib import Path
assert written.folder.resolve() == (Path.cwd() / "reports" / "compare").resolve(), written.folder
assert written.dataset.is_file() and written.report.is_file() and (written.folder / "report.html").is_file()
assert list(written.comparison.dataset.scheme.values) == ["iso13778-4", "iso13778-6"]
print("outside [ppm]:", (1e6 * outside).to_series().to_dict())
"""
    return folder, run_script(code + checks, folder)


@pytest.mark.slow
def test_the_readmes_example_runs_the_main_job_as_a_script(main_job):
    folder, result = main_job
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    verdict, outside = result.stdout.split("outside [ppm]:")
    assert "iso13778-" in verdict  # the verdict names a scheme
    assert "iso13778-4" in outside and "iso13778-6" in outside
    assert (folder / "reports" / "compare" / "compare.nc").is_file()


@pytest.mark.slow
def test_the_datasets_examples_run_and_the_study_rebuilds_from_it_identically(main_job):
    folder, result = main_job
    assert result.returncode == 0, result.stderr
    for page, first in (("docs/dataset.md", "for name, variable in ds.data_vars.items():"),
                        ("docs/dataset.md", "c = ds.clearance_operating"),
                        ("docs/dataset.md", "xr.testing.assert_equal(again, ds)"),
                        ("docs/library.md", "stackup.rank(open_comparison(")):
        result = run_script(printed(block(page, first)), folder)
        assert result.returncode == 0, f"{page}: {result.stderr}"
        assert "Traceback" not in result.stderr
    # the identity is exact: a dataset stored to 10 nm (--compact) would differ by up to 5 nm
    assert "again = Study.from_dataset(ds).run()" in block("docs/dataset.md", "xr.testing.assert_equal(again, ds)")


@pytest.mark.slow
def test_the_library_example_runs_as_a_script(tmp_path):
    page = "docs/library.md"
    code = shrunk(page, block(page, "import stackup.schemes as schemes"), [
        ('n_engines=10_000, seed=1', 'n_engines=500, seed=1'),
        ('stackup.compare(n_engines=20_000, design={})',
         'stackup.compare(n_engines=200, design={"n_engines": 500, "generations": 0}, scenarios={}, uncertainties=None)'),
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

    page = "docs/library.md"
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp",
                      dashboard_address=None) as cluster:
        code = shrunk(page, block(page, "from distributed import Client"), [
            ("n_engines=20_000_000", "n_engines=2_000"),
            ('"tcp://scheduler-host:8786"', repr(cluster.scheduler_address)),
        ])
        code += "\n    print('engines', ds.attrs['n_engines'] if 'n_engines' in ds.attrs else ds.sizes)\n"
        result = run_script(code, tmp_path)
    assert result.returncode == 0, result.stderr
    assert "Nanny failed" not in result.stderr and "Traceback" not in result.stderr
    assert (tmp_path / "runs" / "big.zarr").is_dir()
