"""The comparison the report's snapshot and browser tests share, built once per session: without a designed scheme,
whose search is not yet deterministic (issue 49), so its first page can be a snapshot."""

import pytest

import stackup


@pytest.fixture(scope="session")
def snapshot_comparison():
    """Two ISO schemes on the built-in engine, 400 engines, one process scenario and the engine's declared model
    uncertainties, no designed scheme: deterministic (seed 2) and small."""
    return stackup.compare(schemes=("iso13778-3", "iso13778-4"), n_engines=400, seed=2, pilot_engines=3000,
                           mechanics_engines=10, crank_angle_step=12.0, progress=False,
                           scenarios={"bore mean +1σ": {"housing_shift": 1.0}})
