"""Grade-quantity planning: conservation, symmetry, service level by simulation, bad input."""

import numpy as np
import pytest

from stackup.cli import main
from stackup.plan import plan, simulate_lot_coverage


@pytest.fixture(scope="module")
def plan4():
    return plan("iso13778-4", volume=10_000, service_level=0.99, sample_engines=20_000)


def test_parts_are_conserved(plan4):
    assert plan4.production_share.sum() + plan4.attrs["scrap_share"] == pytest.approx(1.0, abs=1e-12)
    assert plan4.made.sum() == pytest.approx(plan4.attrs["shells_made"] * (1 - plan4.attrs["scrap_share"]))
    # every paired bearing asks for two shells
    assert plan4.demand_per_1000.sum() == pytest.approx(2 * 5 * 1000, rel=0.002)


def test_symmetric_processes_give_symmetric_demand(plan4):
    d = plan4.demand_per_1000
    half = 0.5 * (plan4.demand_per_1000_hi - plan4.demand_per_1000_lo)
    assert abs(d["A"] - d["E"]) < 2 * np.hypot(half["A"], half["E"])
    assert abs(d["B"] - d["D"]) < 2 * np.hypot(half["B"], half["D"])


def test_safety_stock_meets_the_service_level_in_simulation(plan4):
    lots = 400
    coverage = simulate_lot_coverage("iso13778-4", order_up_to=plan4.order_up_to.to_numpy(),
                                     lot_engines=plan4.attrs["lot_engines"], lots=lots, seed=3)
    tolerance = 3 * np.sqrt(0.99 * 0.01 / lots)
    assert np.all(coverage >= 0.99 - tolerance)


def test_more_service_needs_more_stock():
    low = plan("iso13778-5", volume=1000, service_level=0.9, sample_engines=5000)
    high = plan("iso13778-5", volume=1000, service_level=0.999, sample_engines=5000)
    assert np.all(high.safety_stock >= low.safety_stock) and (high.safety_stock > low.safety_stock).any()


@pytest.mark.parametrize("kw, message", [
    (dict(volume=0), "volume: 0 is not valid; must be >= 1"),
    (dict(volume=100, service_level=1.0), r"service_level: 1.0 is outside the valid range \(0.0, 1.0\)"),
    (dict(volume=100, service_level=0.0), r"service_level: 0.0 is outside the valid range \(0.0, 1.0\)"),
])
def test_bad_input(kw, message):
    with pytest.raises(ValueError, match=message):
        plan("iso13778-5", **kw)


def test_unknown_scheme():
    with pytest.raises(ValueError, match="scheme: 'iso13778-8' is not a known scheme"):
        plan("iso13778-8", volume=100)


def test_cli_plan(capsys):
    assert main(["plan", "--scheme", "iso13778-5", "--volume", "2000", "--sample", "2000"]) == 0
    out = capsys.readouterr().out
    assert "safety" in out and "B" in out
    assert main(["plan", "--scheme", "iso13778-5", "--volume", "-5"]) == 2
