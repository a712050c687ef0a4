"""Test tiers and the fixtures every tier shares.

Tiers (markers, registered in pyproject.toml): ``integration`` (studies,
comparisons and subprocesses; a test that uses the shared comparison,
``small_comparison``, is marked so here), ``slow`` (the long ones: wheel
builds, the README run as scripts, coverage over hundreds of seeds); every
other test is ``unit``, marked here at collection. ``pytest`` alone runs the
unit tier (``-m unit`` in pyproject.toml's addopts); ``pytest -m
integration``, ``pytest -m slow`` the others; the README's test command runs
them all.
"""

import os
import textwrap

import pytest
from hypothesis import settings
from small_runs import DESIGN, SCENARIOS, STUDY

settings.register_profile("default", deadline=None, max_examples=25)
settings.load_profile("default")

#: The tiers a test can be marked with; a test marked with neither is a unit test.
TIERS = ("integration", "slow")
#: Fixtures that run a comparison: a test that uses one (itself or through another fixture) is an integration test.
COMPARISONS = ("small_comparison", "snapshot_comparison")


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Mark the tests that use a comparison ``integration`` and every other test that is in no tier ``unit``,
    before ``-m`` selects (hence ``tryfirst``); then order them slow, integration, unit, so that two workers start
    the long tests first and end on short ones rather than one worker finishing a long test alone."""
    for item in items:
        if any(item.get_closest_marker(tier) for tier in TIERS):
            continue
        comparisons = set(COMPARISONS) & set(getattr(item, "fixturenames", ()))
        item.add_marker(pytest.mark.integration if comparisons else pytest.mark.unit)
    items.sort(key=lambda item: next(k for k, tier in enumerate(("slow", "integration", "unit"))
                                     if item.get_closest_marker(tier)))


@pytest.fixture
def write_toml(tmp_path):
    """Write a TOML text into tmp_path/name and return its path."""

    def write(name, text):
        path = tmp_path / name
        path.write_text(textwrap.dedent(text))
        return path

    return write


ENGINE_TEMPLATE = """
name = "test-engine"
units = "mm"
main_bearings = {bearings}

[housing_bore]
limits = [50.000, 50.018]
process = {{ distribution = "normal", cpk = {cpk} }}
shared = 0.3
gauge = {{ repeatability = {gauge} }}

[journal_d]
limits = [46.000, 46.018]
process = {{ distribution = "normal", cpk = {cpk} }}
shared = 0.2
gauge = {{ repeatability = {gauge} }}

[crush_height]
limits = [0.100, 0.137]
process = {{ distribution = "normal", cpk = 1.33 }}

[press_fit]
housing_outer = 90.0
housing_material = "nodular-cast-iron"
shell_material = "steel-back"
length = 22.0
temperature = 100.0

[shell_wall]
supply = "{supply}"
sigma = 0.001
process = {{ distribution = "normal", cpk = 1.0 }}
gauge = {{ repeatability = {gauge} }}
lot_engines = {lot}
surplus = {surplus}
"""


@pytest.fixture(scope="session")
def engine_file(tmp_path_factory):
    """An engine TOML with chosen gauge repeatability [mm], lot size, surplus and supply.

    Session-scoped (files are named by their parameters and never change), so
    hypothesis tests can use it.
    """
    folder = tmp_path_factory.mktemp("engines")

    def make(*, gauge=0.0005, lot=50, surplus=0.1, supply="to-order", cpk=1.33, bearings=5):
        text = ENGINE_TEMPLATE.format(gauge=gauge, lot=lot, surplus=surplus, supply=supply, cpk=cpk, bearings=bearings)
        path = folder / f"engine-{gauge}-{lot}-{surplus}-{supply}-{cpk}-{bearings}.toml"
        path.write_text(text)
        return path

    return make


@pytest.fixture(scope="session")
def small_comparison(tmp_path_factory):
    """The main job (:func:`stackup.comparison.run`) of tests/small_runs.py's parameters, written once per test
    session into a folder every test worker reads: the first worker to ask writes it under a lock, the others open
    it. ``.comparison`` is the comparison as saved and opened again, what the report reads."""
    import fcntl

    import stackup.comparison
    from stackup.io import open_comparison

    if os.environ.get("PYTEST_XDIST_WORKER") is None:  # one process: its own folder
        return stackup.comparison.run(tmp_path_factory.mktemp("small-comparison") / "run", **STUDY, scenarios=SCENARIOS, design=DESIGN)
    root = tmp_path_factory.getbasetemp().parent  # this session's, shared by its workers
    folder = root / "small-comparison"
    with open(root / "small-comparison.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if (folder / "report.md").is_file():
            return stackup.comparison.Written(folder, open_comparison(folder / "compare.nc"), 0.0)
        return stackup.comparison.run(folder, **STUDY, scenarios=SCENARIOS, design=DESIGN)
