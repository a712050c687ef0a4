"""The minimum clearance at assembly and cold start: the engine file's keys and defaults, and the clearance the press
fit's model gives there (physics.md sec. 4b; issue 51, item 2)."""

import numpy as np
import pytest
from test_engines import _engine_file

from stackup.engines import (
    COLD_START,
    COLD_START_SOURCE,
    MINIMUM_CLEARANCE,
    MINIMUM_CLEARANCE_SOURCE,
    load_engine,
)
from stackup.materials import get as material
from stackup.study.clearance import operating_clearance, soaked_clearances

WINDOW = "relative_clearance = [0.00075, 0.00125]"


def test_the_minimum_clearance_and_the_cold_start_default_to_sourced_values():
    e = load_engine("iso-example")
    assert e.minimum_clearance == MINIMUM_CLEARANCE and e.minimum_clearance_source == MINIMUM_CLEARANCE_SOURCE
    assert "0.001-0.011 mm" in MINIMUM_CLEARANCE_SOURCE and COLD_START_SOURCE.startswith("assumed")
    assert e.press_fit.cold_start_temperature == -25.0  # the file's own cold_temperature
    assert e.press_fit.cold_start_source == "press_fit.cold_temperature"
    rozhdestvensky = load_engine("rozhdestvensky-4")  # no cold_temperature: the default, said to be assumed
    assert rozhdestvensky.press_fit.cold_start_temperature == COLD_START
    assert rozhdestvensky.press_fit.cold_start_source == COLD_START_SOURCE


def test_an_engine_file_sets_its_minimum_clearance_with_its_source(tmp_path):
    e = load_engine(_engine_file(tmp_path, {WINDOW: WINDOW + '\nminimum_clearance = 0.004\n'
                                                              'minimum_clearance_source = "maker\'s drawing"'}))
    assert e.minimum_clearance == pytest.approx(4e-6) and e.minimum_clearance_source == "maker's drawing"


@pytest.mark.parametrize("change, message", [
    ("minimum_clearance = 4.0", r"minimum_clearance: 4 mm is not a plausible minimum clearance"),
    ("minimum_clearance = -0.001", r"minimum_clearance: -0.001 mm is not a plausible"),
    ('minimum_clearance_source = "drawing"', r"minimum_clearance_source: given without minimum_clearance"),
])
def test_a_bad_minimum_clearance_is_named_with_its_file_and_key(tmp_path, change, message):
    with pytest.raises(ValueError, match=message):
        load_engine(_engine_file(tmp_path, {WINDOW: WINDOW + "\n" + change}))


def _bearing(engine, wall=1.98e-3):
    """One bearing at the middle of the engine's drawing limits (both shells alike)."""
    crush = 0.5 * (engine.shell_wall.crush.lo + engine.shell_wall.crush.hi)
    return {"housing_bore": 0.5 * (engine.housing_bore.lo + engine.housing_bore.hi),
            "journal_d": 0.5 * (engine.journal_d.lo + engine.journal_d.hi), "upper_wall": wall, "lower_wall": wall,
            "upper_crush": crush, "lower_crush": crush}


def test_an_aluminium_housing_closes_its_bearings_cold_an_iron_one_hardly_moves():
    alu, iron = load_engine("iso-example-aluminium"), load_engine("iso-example")
    a_assembly, a_cold = soaked_clearances(alu, **_bearing(alu))
    a_operating = operating_clearance(alu, **_bearing(alu)).clearance
    # aluminium grows about twice as much as steel per kelvin: open hot, closed cold
    assert a_cold < a_assembly < a_operating
    # the 50 K from assembly to the -30 degC cold start: at most the free growth mismatch of bore and journal
    dt = alu.press_fit.assembly_temperature - alu.press_fit.cold_start_temperature
    free = (material("aluminium").expansion * 50e-3 - material("steel").expansion * 46e-3) * dt
    assert 0.5 * free < a_assembly - a_cold < free
    i_assembly, i_cold = soaked_clearances(iron, **_bearing(iron))
    assert abs(i_assembly - i_cold) < 0.1 * (a_assembly - a_cold)


def test_housing_shells_and_journal_of_one_steel_keep_their_clearance_at_every_temperature(tmp_path):
    steel = load_engine(_engine_file(tmp_path, {'housing_material = "nodular-cast-iron"': 'housing_material = "steel"',
                                                'shell_material = "steel-back"': 'shell_material = "steel"',
                                                'lining_material = "aluminium-tin"': 'lining_material = "steel"'}))
    bearing = _bearing(steel)
    at_assembly, cold = soaked_clearances(steel, **bearing)
    # one material: every size scales by the same (1 + alpha dT); the clearance by 45 K x 12e-6 of itself
    np.testing.assert_allclose(cold, at_assembly, rtol=1e-3)
