"""ISO 13778's schemes laid on an engine's own drawing (stackup.patterns)."""

import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from stackup._random import lot_generator, seed_sequence
from stackup.engines import load_engine
from stackup.parts import draw_lot
from stackup.patterns import ISO_SCHEMES, adapt, clearance_offset, target_clearance_min
from stackup.schemes import from_dict, load

#: An engine file of another size and bearing count, written as a user would (tests/data).
INLINE_SIX = Path(__file__).parents[1] / "data" / "inline6.toml"
ENGINE_FILE_DOC = Path(__file__).parents[2] / "docs" / "engine-file.md"


def documented_engine(tmp_path):
    """The smallest engine file of the docs' "Your own engine" (docs/engine-file.md), written to ``tmp_path``."""
    text = ENGINE_FILE_DOC.read_text(encoding="utf-8")
    block = re.search(r"A seven-bearing inline six.*?```toml\n(.*?)```", text, re.S)
    assert block, "docs/engine-file.md: the engine-file example of 'Your own engine' is missing"
    path = tmp_path / "readme-six.toml"
    path.write_text(block.group(1), encoding="utf-8")
    return path


def _drawn(engine, *, housing=None, journal=None):
    """``engine`` with other drawing limits (lo, hi) [m] of the housing bore and the journal."""
    out = engine
    if housing is not None:
        out = replace(out, housing_bore=replace(out.housing_bore, lo=housing[0], hi=housing[1]))
    if journal is not None:
        out = replace(out, journal_d=replace(out.journal_d, lo=journal[0], hi=journal[1]))
    return out


@pytest.mark.parametrize("name", ISO_SCHEMES)
@pytest.mark.parametrize("engine", ["iso-example", "iso-example-aluminium"])
def test_on_the_standards_drawing_the_adapted_scheme_is_the_standards_table(name, engine):
    standard, adapted = load(name), adapt(name, engine)
    assert adapted.to_toml_text() == standard.to_toml_text()
    assert adapted.clearance_limits() == standard.clearance_limits()
    assert adapted.stated_clearance == standard.stated_clearance


def test_scheme_4_example_cells_as_the_standard_tabulates_them():
    s = adapt("iso13778-4", "iso-example")
    # housing grade B, journal grade A -> D+D (ISO 13778 scheme 4 table)
    assert s.pair(50.0075e-3, 46.0031e-3) == ("D", "D")
    assert s.grades["shell"]["A"] == pytest.approx((1.975e-3, 1.978e-3), abs=1e-12)


@pytest.mark.parametrize("name", ISO_SCHEMES[:5])
@pytest.mark.parametrize("factor", [0.5, 1.5, 2.0])
def test_adaptation_scales_grades_and_clearance_range_with_the_tolerance(name, factor):
    """Tolerances k times the standard's give grades k times as wide, the same pairs and a clearance range
    k times as wide (schemes 1-5; scheme 6 keeps its 1 um read-out, so its classes do not scale)."""
    base = load_engine("iso-example")
    engine = _drawn(base, housing=(50e-3, 50e-3 + factor * 18e-6), journal=(46e-3, 46e-3 + factor * 18e-6))
    standard, adapted = load(name), adapt(name, engine)
    for dim in ("housing", "journal", "shell"):
        ref, new = getattr(standard, dim), getattr(adapted, dim)
        assert new.labels == ref.labels
        np.testing.assert_allclose(new.hi - new.lo, factor * (ref.hi - ref.lo), atol=1.1e-7)
    np.testing.assert_array_equal(adapted.cell_pairs, standard.cell_pairs)
    width = np.subtract(*adapted.clearance_limits()[::-1])
    reference = np.subtract(*standard.clearance_limits()[::-1])
    assert width == pytest.approx(factor * reference, abs=0.5e-6)
    assert adapted.clearance_limits()[0] == pytest.approx(target_clearance_min(engine, 26e-6), abs=0.25e-6)


@pytest.mark.parametrize("name", ISO_SCHEMES)
def test_a_drawing_moved_by_a_millimetre_moves_only_the_shells(name):
    """Housing and journal 1 mm larger (same tolerances, same window): the grades move with the drawing, the
    pairs and the width of the clearance range stay, the smallest clearance follows the target."""
    base = load_engine("iso-example")
    engine = _drawn(base, housing=(51e-3, 51.018e-3), journal=(47e-3, 47.018e-3))
    standard, adapted = load(name), adapt(name, engine)
    np.testing.assert_array_equal(adapted.cell_pairs, standard.cell_pairs)
    np.testing.assert_allclose(adapted.housing.lo, standard.housing.lo + 1e-3, atol=1e-12)
    assert adapted.clearance_limits()[0] == pytest.approx(target_clearance_min(engine, 26e-6), abs=0.25e-6)
    assert np.subtract(*adapted.clearance_limits()[::-1]) == pytest.approx(
        np.subtract(*standard.clearance_limits()[::-1]), abs=0.25e-6)


def test_smallest_clearance_keeps_its_place_in_the_window():
    """On the heavy diesel the smallest operating clearance (nominal + offset) sits in its window where the
    standard's sits in the example engine's window."""
    example, diesel = load_engine("iso-example"), load_engine("rozhdestvensky-4")
    share0 = (26e-6 + clearance_offset(example) - example.clearance_window[0]) / np.subtract(
        *example.clearance_window[::-1])
    c_min = adapt("iso13778-4", diesel).clearance_limits()[0]
    share = (c_min + clearance_offset(diesel) - diesel.clearance_window[0]) / np.subtract(
        *diesel.clearance_window[::-1])
    assert share == pytest.approx(share0, abs=0.2e-6 / np.subtract(*diesel.clearance_window[::-1]))


def test_light_alloy_block_is_held_at_the_standards_relative_clearance():
    """The aluminium bore grows more than the steel journal when hot: placing its operating clearance in the
    window would ask for a negative clearance at assembly; the floor (the standard's clearance in proportion
    to the journal) holds it at the standard's tables."""
    engine = load_engine("iso-example-aluminium")
    window_place = engine.clearance_window[0] - clearance_offset(engine)
    assert window_place < 0  # what the window alone would ask for
    assert target_clearance_min(engine, 26e-6) == pytest.approx(26e-6, abs=1e-12)


@pytest.mark.parametrize("engine", ["rozhdestvensky-4", "nef-6", str(INLINE_SIX)])
@pytest.mark.parametrize("name", ISO_SCHEMES)
def test_adapted_schemes_grade_the_engines_bearings(engine, name):
    """Every adapted scheme grades at least 95 % of the engine's bearings whose parts were not scrapped."""
    engine = load_engine(engine)
    scheme = adapt(name, engine)
    parts, _ = draw_lot(engine, lot_generator(seed_sequence(1), 0), 2000)
    built = ~(parts.block_scrapped | parts.crank_scrapped)
    h, j = scheme.grade_indices(parts.housing_reading[built], parts.journal_reading[built])
    upper, _ = scheme.pair_indices(h, j)
    assert np.mean(upper >= 0) >= 0.95


def test_the_docs_engine_file_loads_and_its_iso_schemes_grade_its_bearings(tmp_path):
    """The engine file of docs/engine-file.md is complete: it loads strictly, has a window and a crank, and is
    graded."""
    engine = load_engine(documented_engine(tmp_path))
    assert engine.main_bearings == 7 and engine.crank is not None
    assert engine.clearance_window == pytest.approx((0.00075 * 59.981e-3, 0.00125 * 59.981e-3))
    parts, _ = draw_lot(engine, lot_generator(seed_sequence(1), 0), 2000)
    built = ~(parts.block_scrapped | parts.crank_scrapped)
    for name in ISO_SCHEMES:
        h, j = adapt(name, engine).grade_indices(parts.housing_reading[built], parts.journal_reading[built])
        upper, _ = adapt(name, engine).pair_indices(h, j)
        assert np.mean(upper >= 0) >= 0.95, name


def test_adapted_scheme_file_reads_back_identically(tmp_path):
    scheme = adapt("iso13778-6", "rozhdestvensky-4")
    path = scheme.to_toml(tmp_path / "iso13778-6-rozhdestvensky.toml")
    again = load(path)
    assert again.to_toml_text().splitlines()[-40:] == scheme.to_toml_text().splitlines()[-40:]
    np.testing.assert_array_equal(again.cell_pairs, scheme.cell_pairs)
    assert again.clearance_limits() == scheme.clearance_limits()
    assert "laid on the drawing of engine 'rozhdestvensky-4'" in path.read_text()


def test_a_scheme_for_another_drawing_is_adapted_from_its_own_limits():
    """A user's scheme written for another drawing is laid on the engine from its own housing/journal limits."""
    table = {"name": "mine", "units": "mm", "housing": {"limits": [60.0, 60.02]},
             "journal": {"limits": [56.0, 56.02], "grades": {"A": [56.0, 56.01], "B": [56.01, 56.02]}},
             "shell": {"grades": {"X": [1.97, 1.975], "Y": [1.975, 1.98]}},
             "pairing": {"table": {"A": {"-": "Y+Y"}, "B": {"-": "X+X"}}}}
    adapted = adapt(from_dict(table), "rozhdestvensky-4")
    assert adapted.journal.lo[1] == pytest.approx(104.978e-3 + 0.011e-3, abs=1e-10)
    np.testing.assert_array_equal(adapted.cell_pairs, from_dict(table).cell_pairs)


def test_a_study_names_iso_schemes_and_gets_them_on_its_engines_drawing():
    import json

    from stackup import Study
    from stackup.schemes import scheme_path

    ds = Study(engine="rozhdestvensky-4", schemes=("iso13778-4", "iso13778-6"), n_engines=300, mechanics_engines=0,
               progress=False).run()
    texts = json.loads(ds.attrs["input_files"])["schemes"]
    assert all("laid on the drawing of engine 'rozhdestvensky-4'" in text for text in texts.values())
    assert float((ds.status == 0).mean()) > 0.95
    example = Study(schemes=("iso13778-4",), n_engines=100, mechanics_engines=0, progress=False)
    assert example.files["schemes"]["iso13778-4"] == scheme_path("iso13778-4").read_text()


def test_cli_shows_and_writes_the_schemes_laid_on_an_engine(tmp_path, capsys):
    from stackup.cli import main

    command = ["schemes", "--engine", "rozhdestvensky-4"]
    assert main(command) == 0
    shown = capsys.readouterr().out
    assert "iso13778-6" in shown and "nominal clearance 71.3-96.0 um" in shown  # the window moved by press fit and the journal 10 K above its housing
    assert main([*command, "--out", str(tmp_path)]) == 0
    written = sorted(tmp_path.glob("*.toml"))
    assert [p.name for p in written] == [f"iso13778-{k}-rozhdestvensky-4.toml" for k in range(1, 7)]
    for path in written:
        assert load(path).clearance_limits() == adapt(path.name.split("-rozh")[0], "rozhdestvensky-4").clearance_limits()
    capsys.readouterr()
    assert main([*command, "--out", str(tmp_path)]) == 2 and "--force" in capsys.readouterr().err


def test_caveats_flag_grades_under_three_gauge_or_shell_process_sigmas():
    from stackup.patterns import caveats

    fine = caveats("iso13778-6", "iso-example")  # 1 um classes read by a 0.5 um gauge: under 1.5 um
    assert {(n.part, n.of) for n in fine.narrow} == {("housing", "gauge"), ("journal", "gauge")}
    assert caveats("iso13778-4", "iso-example").narrow == ()  # 3 um shell grades, shell sigma 1 um: not under
    engine = load_engine("iso-example")
    coarse = replace(engine, housing_bore=replace(engine.housing_bore,
                                                  gauge=replace(engine.housing_bore.gauge, repeatability=2.5e-6)))
    flagged = caveats("iso13778-4", coarse).narrow  # 6 um housing grades, 3 x 2.5 um = 7.5 um
    assert [(n.part, n.of) for n in flagged] == [("housing", "gauge")]
    assert flagged[0].width == pytest.approx(6e-6, abs=1e-10)
    heavy = caveats("iso13778-4", "rozhdestvensky-4").narrow  # shells made to order: 3.6 um grades, sigma 1.5 um
    assert [(n.part, n.of) for n in heavy] == [("shell", "process")]


def test_caveats_say_where_the_window_moved_nothing_and_the_anchor_is_the_example_engines():
    from stackup.patterns import anchor, caveats

    held = caveats("iso13778-4", "iso-example-aluminium")  # its swell puts the window's target below the floor
    assert held.held and held.window_target < held.floor and not held.adapted
    followed = caveats("iso13778-4", "nef-6")
    assert not followed.held and followed.adapted and followed.window_target >= followed.floor
    where = anchor()
    engine = load_engine("iso-example")
    assert where.engine == "iso-example" and where.window == engine.clearance_window
    assert where.operating_min == pytest.approx(26e-6 + clearance_offset(engine), abs=1e-12)
    lo, hi = engine.clearance_window
    assert where.place == pytest.approx((where.operating_min - lo) / (hi - lo))
    # the anchor is what target_clearance_min keeps: nef-6's operating target sits at the same place in its window
    six = load_engine("nef-6")
    operating = target_clearance_min(six, 26e-6) + clearance_offset(six)
    assert (operating - six.clearance_window[0]) / np.subtract(*six.clearance_window[::-1]) == pytest.approx(
        where.place, abs=1e-9)


def test_schemes_command_prints_the_caveats_and_the_anchor(capsys):
    from stackup.cli import main

    assert main(["schemes", "--engine", "nef-6"]) == 0
    out = capsys.readouterr().out
    assert "warning: iso13778-6 housing and journal grades 1.0 µm < 3 gauge σ (0.8 µm)" in out
    assert "re-centred from iso-example" in out and "assumed housing_outer 90 mm" in out
    assert main(["schemes", "--engine", "iso-example-aluminium"]) == 0
    out = capsys.readouterr().out
    assert out.count("the window moves nothing") == 6 and "not re-centred" in out
