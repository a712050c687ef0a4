"""Engine files: the [wear] and [oil_feed] tables (surfaces, wear limits, oil feed) with their sources."""

import numpy as np
import pytest

from stackup.engines import DEFAULT_WEAR, load_engine

WEAR = """
[wear]
journal_rz = 0.0006
journal_rq = 0.00015
shell_rz = 0.0012
shell_rq = 0.0003
wear_limit = 0.025
wear_rate = 2.0e-10
roughness_source = "test"
wear_source = "test"
"""


@pytest.fixture
def with_tables(engine_file, tmp_path):
    def make(text):
        path = tmp_path / "engine.toml"
        path.write_text(engine_file().read_text() + text)
        return path

    return make


def test_builtin_engines_take_the_critical_film_from_their_surfaces():
    iso, diesel = load_engine("iso-example").wear, load_engine("rozhdestvensky-4").wear
    assert iso.critical_film == pytest.approx(iso.journal_rz + iso.shell_rz) == pytest.approx(1.8e-6)
    assert diesel.critical_film == pytest.approx(1.9e-6)  # Levanov et al. 2015, sec. 4, for a 130 x 150 mm diesel
    for w in (iso, diesel):
        assert w.wear_limit == pytest.approx(30e-6) and w.wear_rate == pytest.approx(1e-13)
        assert "Levanov" in w.wear_source and w.roughness_source
    feed = load_engine("rozhdestvensky-4").oil_feed
    assert feed.kind == "groove" and np.degrees(feed.groove_arc) == pytest.approx([100.0, 260.0])
    assert feed.supply_pressure > 0 and "Rozhdestvensky" in feed.source


def test_file_tables_in_file_units(with_tables):
    e = load_engine(with_tables(WEAR + """
[oil_feed]
feed = "hole"
supply_pressure = 0.4e6
hole_diameter = 4.0
hole_angle = 180.0
source = "test"
"""))
    assert e.wear.critical_film == pytest.approx(1.8e-6) and e.wear.wear_rate == pytest.approx(2e-13)
    assert e.wear.wear_limit == pytest.approx(25e-6) and e.wear.shell_rq == pytest.approx(0.3e-6)
    assert e.oil_feed.kind == "hole" and e.oil_feed.hole_diameter == pytest.approx(4e-3)
    assert e.oil_feed.hole_angle == pytest.approx(np.pi)


def test_defaults_without_the_tables_say_so(engine_file):
    e = load_engine(engine_file())
    assert e.wear == DEFAULT_WEAR and e.wear.roughness_source.startswith("default")
    assert e.oil_feed.kind == "groove" and e.oil_feed.source.startswith("default")
    assert e.oil_feed.groove_width == pytest.approx(0.15 * e.press_fit.bearing_width)


@pytest.mark.parametrize("extra, message", [
    (WEAR + "critical_film = 0.0015\n", r"critical_film: 0.0015 is below journal_rz \+ shell_rz = 0.0018"),
    (WEAR.replace("shell_rq = 0.0003", "shell_rq = 0.002"), "shell_rq: 0.002 is not below shell_rz 0.0012"),
    (WEAR.replace('wear_source = "test"', ""), "key wear.wear_source: missing"),
    (WEAR + "colour = 1\n", r"key wear: unknown key 'colour'; valid keys: critical_film, journal_rq"),
    ('\n[oil_feed]\nfeed = "slot"\nsupply_pressure = 1e5\nsource = "x"\n', "oil_feed.feed: 'slot' is not one of"),
    ('\n[oil_feed]\nfeed = "groove"\nsupply_pressure = 1e5\ngroove_arc = [200.0, 100.0]\ngroove_width = 2.0\n'
     'source = "x"\n', r"groove_arc: \[200.0, 100.0\] deg is not valid"),
    ('\n[oil_feed]\nfeed = "groove"\nsupply_pressure = 1e5\ngroove_width = 2.0\n', "key oil_feed.source: missing"),
])
def test_bad_tables(with_tables, extra, message):
    with pytest.raises(ValueError, match=message):
        load_engine(with_tables(extra))


def test_press_fit_length_is_read_as_the_bearing_width(engine_file):
    # the file's key stays press_fit.length; the spec and the fit functions call it bearing_width
    spec = load_engine(engine_file()).press_fit
    assert spec.kwargs()["bearing_width"] == spec.bearing_width and "length" not in spec.kwargs()
    assert spec.record()["length"] == spec.bearing_width and "bearing_width" not in spec.record()
    with pytest.warns(DeprecationWarning, match=r"PressFitSpec.length is deprecated; use bearing_width"):
        assert spec.length == spec.bearing_width


def test_method_1_has_its_own_limiting_wear_on_the_scale_of_the_papers_results(with_tables):
    """Method 1's Δh_lim/γ is 1e8 s (the paper's results), method 2 keeps the text's 30 µm (Levanov et al. 2015)."""
    from stackup.life import METHOD1_SCALE

    for name in ("iso-example", "rozhdestvensky-4", "nef-6"):
        w = load_engine(name).wear
        assert w.method1_wear_limit / w.wear_rate == pytest.approx(1e8) and w.wear_limit == pytest.approx(30e-6)
    assert DEFAULT_WEAR.method1_wear_limit / DEFAULT_WEAR.wear_rate == pytest.approx(METHOD1_SCALE)
    # a file without the key: the paper's scale at the file's own wear speed (2e-13 m/s here)
    assert load_engine(with_tables(WEAR)).wear.method1_wear_limit == pytest.approx(METHOD1_SCALE * 2e-13)
    given = load_engine(with_tables(WEAR.replace("wear_rate", "method1_wear_limit = 0.008\nwear_rate")))
    assert given.wear.method1_wear_limit == pytest.approx(8e-6)
    with pytest.raises(ValueError, match=r"engine\.toml.*wear\.method1_wear_limit"):
        load_engine(with_tables(WEAR.replace("wear_rate", "method1_wear_limit = -0.008\nwear_rate")))
