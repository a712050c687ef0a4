"""Robustness scenarios applied to an engine."""

import pytest

from stackup.engines import load_engine
from stackup.scenarios import DECLARED, apply
from stackup.study import Study


def test_bore_mean_shift_moves_scheme1_clearance_by_one_sigma():
    kw = dict(n_engines=4000, schemes=("iso13778-1",), mechanics_engines=0, pilot_engines=2000, progress=False)
    base = Study(**kw).run()
    up = Study(**kw, scenario={"housing_shift": 1.0}).run()
    sigma = load_engine("iso-example").housing_bore.process.std
    shift = float(up.clearance_nominal.mean() - base.clearance_nominal.mean())
    assert shift == pytest.approx(sigma, rel=0.02)  # common random numbers: the same parts, moved


def test_gauge_and_misalignment_scenarios_change_the_engine():
    engine = load_engine("iso-example")
    g = apply(engine, {"gauge_repeatability": 2e-6})
    assert g.housing_bore.gauge.repeatability == g.journal_d.gauge.repeatability == g.shell_wall.gauge.repeatability == 2e-6
    m = apply(engine, {"misalignment_scale": 2.0})
    assert m.crank.coaxiality == 2 * engine.crank.coaxiality
    assert apply(engine, None) is engine
    assert set(DECLARED) >= {"bore mean +1σ", "gauge repeatability 2 µm", "misalignment ×2"}


def test_scenario_round_trips_through_the_dataset_attrs():
    import json

    ds = Study(n_engines=50, schemes=("iso13778-4",), mechanics_engines=0, pilot_engines=1000, progress=False,
               scenario={"journal_shift": -1.0}).run()
    assert json.loads(ds.attrs["study"])["scenario"] == {"journal_shift": -1.0}


def test_unknown_scenario_key():
    with pytest.raises(ValueError, match=r"scenario: unknown key\(s\) \['bore_shift'\]"):
        apply(load_engine("iso-example"), {"bore_shift": 1.0})
