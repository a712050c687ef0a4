"""The bearing stage on real load histories of both built-in engines: heat balance, film and life together."""

import numpy as np
import pytest

from stackup.crank.cycle import engine_cycles
from stackup.engines import load_engine
from stackup.film import journal_position, min_film_thickness
from stackup.film.heat import heat_balance
from stackup.life import alpha, cycle_film, levanov_method1


@pytest.mark.parametrize("name", ["iso-example", "rozhdestvensky-4"])
def test_every_bearing_balances_and_healthy_bearings_live_thousands_of_hours(name):
    engine = load_engine(name)
    spec, wear = engine.crank, engine.wear
    lo, hi = engine.clearance_window
    clearance = np.array([[lo] * 5, [hi] * 5, [0.5 * (lo + hi)] * 5])
    journal = np.full(clearance.shape, engine.journal_d.lo)
    angle = np.arange(0.0, 720.0, 2.0)
    zero = np.zeros((3, 5, 2))
    loads = np.moveaxis(engine_cycles(spec, bore_offset=zero, journal_eccentricity=zero, clearance=clearance,
                                      crank_angle=angle).reactions, 1, 2)
    # the unloaded case too: every bearing, loaded or not, gets a balance
    loads = np.concatenate([loads, np.zeros_like(loads[:1])])
    clearance, journal = np.concatenate([clearance, clearance[:1]]), np.concatenate([journal, journal[:1]])
    heat = heat_balance(loads, journal_d=journal, bearing_width=spec.bearing_width, clearance=clearance, speed=spec.speed,
                        oil=spec.oil, supply_temperature=spec.oil_supply_temperature, feed=engine.oil_feed,
                        method="finite")
    assert np.all(heat.status == 0)
    assert np.all((heat.temperature > spec.oil_supply_temperature) & (heat.temperature < 160.0))
    assert np.all(heat.feed_flow > 0) and np.all(heat.friction_power > 0)
    film = min_film_thickness(np.linalg.norm(loads[:3], axis=-1), journal_d=journal[:3, :, None],
                              bearing_width=spec.bearing_width, clearance=clearance[:3, :, None],
                              viscosity=heat.viscosity[:3, :, None], speed=spec.speed, method="finite")
    position = journal_position(loads[:3], eccentricity=film.eccentricity, attitude_angle=film.attitude_angle,
                                clearance=clearance[:3, :, None])
    np.testing.assert_allclose(clearance[:3, :, None] / 2 - np.linalg.norm(position, axis=-1), film.h_min, atol=1e-15)
    life = levanov_method1(cycle_film(film.h_min), h_lim_cr=wear.critical_film, wear_limit=wear.wear_limit,
                           wear_rate=wear.wear_rate)
    # healthy bearings (boundary friction well under the 20 % scuffing share): thousands of hours (Levanov et al. 2015)
    assert np.all(alpha(film.h_min, h_lim_cr=wear.critical_film) < 0.2)
    assert np.all(life.life_hours > 2000)
