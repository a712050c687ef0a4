"""Robustness scenarios applied to an engine."""

from dataclasses import replace

import numpy as np
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


def test_a_journal_hotter_than_its_housing_moves_the_operating_clearance_by_its_thermal_growth():
    # closed form: every bearing's operating clearance falls by d_J * alpha_J * dT; the same parts (same seed)
    from stackup import materials

    kw = dict(n_engines=400, schemes=("iso13778-4",), mechanics_engines=0, pilot_engines=1000, progress=False)
    cold = Study(**kw, scenario={"journal_temperature_excess": 0.0}).run()
    hot = Study(**kw, scenario={"journal_temperature_excess": 20.0}).run()
    ok = cold.status.values == 0
    drop = (cold.clearance_operating.values - hot.clearance_operating.values)[ok]
    expected = cold.journal_d.broadcast_like(cold.status).values[ok] * materials.get("steel").expansion * 20.0
    np.testing.assert_allclose(drop, expected, rtol=1e-6)
    assert 10.0e-6 < drop.mean() < 11.0e-6  # "a journal 20 K hotter takes about 11 um off"
    np.testing.assert_array_equal(cold.housing_swell.values[ok], hot.housing_swell.values[ok])


def test_the_built_in_engines_declare_the_journal_temperature_as_an_assumption():
    from stackup.engines import available_engines

    for name in ("iso-example", "iso-example-aluminium", "rozhdestvensky-4", "nef-6"):
        spec = load_engine(name).press_fit
        assert spec.journal_temperature_excess == 10.0 and spec.journal_temperature_source.startswith("assumed")
        assert spec.kwargs()["journal_temperature"] == spec.temperature + 10.0
    assert set(available_engines()) >= {"iso-example", "nef-6"}


def _engine_copy(tmp_path, extra, name="measured"):
    """A copy of iso-example with lines added to its [press_fit] table."""
    text = (load_engine_path("iso-example")).read_text()
    text = text.replace('name = "iso-example"', f'name = "{name}"')
    key = extra.split("=")[0].strip()
    text = "\n".join(line for line in text.splitlines() if not line.startswith(key + " "))  # the file's own, if any
    text = text.replace("[press_fit]\n", "[press_fit]\n" + extra + "\n", 1)
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return path


def load_engine_path(name):
    from stackup.engines import engine_path

    return engine_path(name)


def test_the_housing_range_is_assumed_around_the_file_unless_fitting_tests_measured_it(tmp_path):
    from stackup.scenarios import HOUSING_RATIO_RANGE, housing_stiffness, model_uncertainties

    engine = load_engine("iso-example")
    assumed = housing_stiffness(engine)
    ends = [s["housing_outer"] for s in assumed.scenarios.values()]
    assert ends == pytest.approx([r * 50e-3 for r in HOUSING_RATIO_RANGE])  # 75 and 150 mm
    assert assumed.assumed and "stackup measure swell" in assumed.measure
    assert list(assumed.scenarios) == ["housing OD 75 mm", "housing OD 150 mm"]
    measured = load_engine(_engine_copy(tmp_path, "housing_outer_interval = [84.0, 97.0]"))
    u = housing_stiffness(measured)
    assert [s["housing_outer"] for s in u.scenarios.values()] == pytest.approx([84e-3, 97e-3])
    assert not u.assumed and u.source.startswith("measured")
    rigid = load_engine(_engine_copy(tmp_path, "housing_outer_interval = [84.0, inf]", name="rigid"))
    assert list(housing_stiffness(rigid).scenarios.values())[1]["housing_outer"] == pytest.approx(0.5)
    inputs = [u.input for u in model_uncertainties(engine)]
    assert inputs == ["housing stiffness (equivalent outer diameter)", "crush height process (mean)",
                      "journal–housing temperature difference",
                      "supports' angular compliance (bulkhead and bore ring)"]


@pytest.mark.parametrize("line, message", [
    ("housing_outer_interval = [40.0, 97.0]", "not an interval above the housing bore"),
    ("housing_outer_interval = [97.0, 84.0]", "not an interval above the housing bore"),
    ("housing_outer_interval = 90.0", r"is not \[lower, upper\]"),
    ("journal_temperature_excess = 500.0", "journal_temperature_excess"),
])
def test_bad_press_fit_uncertainty_keys_are_named(tmp_path, line, message):
    with pytest.raises(ValueError, match=message):
        load_engine(_engine_copy(tmp_path, line))


def test_model_scenarios_change_the_engine_and_are_checked():
    from stackup.scenarios import kind

    engine = load_engine("iso-example")
    changed = apply(engine, {"housing_outer": 0.075, "crush_shift": 1.0, "journal_temperature_excess": 20.0})
    assert changed.press_fit.housing_outer == 0.075 and changed.press_fit.journal_temperature == 120.0
    crush = engine.shell_wall.crush.process
    assert changed.shell_wall.crush.process.mean == pytest.approx(crush.mean + crush.sigma)
    with pytest.raises(ValueError, match="scenario housing_outer: .* not above the housing bore"):
        apply(engine, {"housing_outer": 0.049})
    assert kind({"housing_outer": 0.075}) == "model" and kind({"housing_shift": 1.0}) == "process"


def test_an_assumed_crankshaft_stiffness_is_declared_and_a_sourced_one_is_not(tmp_path):
    from stackup.scenarios import crank_stiffness, model_uncertainties

    assert crank_stiffness(load_engine("iso-example")) is None  # Bellakhdhar et al.'s identified throws
    heavy = load_engine("rozhdestvensky-4")
    u = crank_stiffness(heavy)
    assert u.assumed and "bending test" in u.measure
    low, high = (s["crank_stiffness_scale"] for s in u.scenarios.values())
    # the upper end: the stiffest throw as the plain 105 mm journal, pi D^4 / 64 (1.12e6 mm^4 in the file)
    assert low == 0.5 and high == pytest.approx(np.pi * 105.0**4 / 64 / 1.12e6, rel=0.01)
    assert [x.input for x in model_uncertainties(heavy)][3:] == ["crankshaft bending stiffness (section inertias)",
                                                                  "supports' angular compliance (bulkhead and bore "
                                                                  "ring)"]
    # a file that names no source assumes its inertias
    text = load_engine_path("iso-example").read_text().replace("section_inertia_source", "# section_inertia_source")
    path = tmp_path / "unsourced.toml"
    path.write_text(text.replace('name = "iso-example"', 'name = "unsourced"'))
    assert crank_stiffness(load_engine(path)).assumed
    # a source the user wrote "Assumed: ..." is assumed as well (and its word not repeated)
    path.write_text(text.replace('name = "iso-example"', 'name = "capital"').replace(
        "# section_inertia_source = \"", "section_inertia_source = \"Assumed: "))
    u = crank_stiffness(load_engine(path))
    assert u.assumed and not u.source.lower().startswith("assumed: assumed")


def test_a_source_is_assumed_however_its_first_word_is_written():
    from stackup.facts.declared import ScenarioAbout
    from stackup.scenarios import Uncertainty

    for source, assumed in (("Assumed: a guess", True), ("assumed: a guess", True), ("measured: fitting tests", False)):
        assert Uncertainty("x", {}, source, "y").assumed is assumed
        assert ScenarioAbout("model", "x", source, "y").assumed is assumed


def test_the_supports_tilt_compliance_is_declared_where_the_journals_tilt_reads_it():
    from stackup.scenarios import model_uncertainties

    engine = load_engine("iso-example")
    name = "supports' angular compliance (bulkhead and bore ring)"
    assert name not in [u.input for u in model_uncertainties(engine, "free")]  # the beam's slope held
    assert model_uncertainties(engine, "equilibrium")[-1].input == name
    u = model_uncertainties(engine, "coupled")[-1]
    assert u.input == name and u.assumed
    assert "bulkhead_compliance" in u.source and "ring_tilt_compliance" in u.source
    assert [s["support_angular_scale"] for s in u.scenarios.values()] == [0.5, 2.0]
    # an angular compliance given as numbers still has the ring's own turn derived: still declared
    given = replace(engine.crank.supports, angular_derived=False)
    u = model_uncertainties(replace(engine, crank=replace(engine.crank, supports=given)), "coupled")[-1]
    assert u.input == name and "bulkhead_compliance" not in u.source and "ring_tilt_compliance" in u.source
    rigid_ring = replace(given, ring=None)
    assert name not in [u.input for u in model_uncertainties(
        replace(engine, crank=replace(engine.crank, supports=rigid_ring)), "coupled")]


def test_stiffness_scenarios_change_the_crankshaft_and_its_supports():
    engine = load_engine("rozhdestvensky-4")
    changed = apply(engine, {"crank_stiffness_scale": 2.0, "support_angular_scale": 0.5})
    np.testing.assert_allclose(changed.crank.ei, 2.0 * engine.crank.ei)
    np.testing.assert_allclose(changed.crank.supports.angular, 0.5 * engine.crank.supports.angular)
    np.testing.assert_allclose(changed.crank.supports.ring, 0.5 * engine.crank.supports.ring)
    np.testing.assert_array_equal(changed.crank.supports.linear, engine.crank.supports.linear)
    for bad in ({"crank_stiffness_scale": -1.0}, {"support_angular_scale": -0.5}):
        with pytest.raises(ValueError, match="scenario (crank_stiffness|support_angular)_scale"):
            apply(engine, bad)


def test_a_stiffer_crankshaft_raises_the_heavy_diesels_film_over_the_surface():
    """The declared range matters: on rozhdestvensky-4 coaxial, the film over the surface at bearing 2 is of the
    paper's order (2.68 um, their Table 2) only near the upper end of the crankshaft's stiffness."""
    from stackup.study.chain import mechanical_chain

    def film(engine):
        n = engine.main_bearings
        zero, clearance = np.zeros((1, n, 2)), np.full((1, n), 103e-6)
        out = mechanical_chain(engine, clearance=clearance, journal_d=np.full((1, n), 105e-3), bore_offset=zero,
                               journal_eccentricity=zero, crank_angle=np.arange(720.0), crank_method="bearing-law",
                               film_method="mobility-finite", tilt_method="coupled")
        return out["h_min"][0]

    heavy = load_engine("rozhdestvensky-4")
    nominal, stiff = film(heavy), film(apply(heavy, {"crank_stiffness_scale": 5.0}))
    assert stiff[1] > nominal[1] + 1e-6 and 1.5e-6 < stiff[1] < 5e-6
