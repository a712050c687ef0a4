"""Sampled parts: the measurement processes of ISO 13778's notes and the bolt-tension scatter."""

from dataclasses import replace

import numpy as np
import pytest

from stackup import schemes
from stackup._random import lot_generator, seed_sequence
from stackup.engines import load_engine
from stackup.parts import draw_lot
from stackup.tolerances import FormError


def _draw(engine, engines=4000, seed=0):
    return draw_lot(engine, lot_generator(seed_sequence(seed), 0), engines)


def _plain(engine):
    """The engine without form errors, bolt scatter and repeated readings."""
    return replace(engine, journal_d=replace(engine.journal_d, form=None, gauge=replace(engine.journal_d.gauge, readings=1)),
                   housing_bore=replace(engine.housing_bore, bolt_scatter=0.0))


def test_extra_processes_leave_the_other_draws_unchanged():
    engine = load_engine("iso-example-aluminium")
    full, normals = _draw(engine)
    plain, plain_normals = _draw(_plain(engine))
    np.testing.assert_array_equal(full.journal_d, plain.journal_d)
    np.testing.assert_array_equal(full.housing_reading, plain.housing_reading)
    np.testing.assert_array_equal(normals.size, plain_normals.size)
    np.testing.assert_array_equal(full.journal_eccentricity, plain.journal_eccentricity)
    assert not np.array_equal(full.journal_reading, plain.journal_reading)


def test_bolt_scatter_moves_the_assembled_bore_from_the_bore_read():
    engine = load_engine("iso-example-aluminium")
    exact = replace(engine, housing_bore=replace(engine.housing_bore, gauge=replace(engine.housing_bore.gauge,
                                                                                      repeatability=0.0)))
    parts, _ = _draw(exact)
    moved = parts.housing_bore - parts.housing_reading
    assert moved.std() == pytest.approx(engine.housing_bore.bolt_scatter, rel=0.03)
    assert abs(moved.mean()) < 0.05e-6


@pytest.mark.parametrize("scheme", ["iso13778-6", "iso13778-4"])
def test_one_journal_reading_misgrades_more_than_the_mean_of_four(scheme):
    # ISO 13778: journals may need readings in several planes and directions to get the mean diameter;
    # one 2-point reading sees the ovality and, off centre, the taper
    s = schemes.load(scheme)
    engine = load_engine("iso-example")
    one = replace(engine, journal_d=replace(engine.journal_d, form=FormError(3e-6, 3e-6, (0.25,), 1),
                                            gauge=replace(engine.journal_d.gauge, readings=1)))
    share = {}
    for label, e in (("four", engine), ("one", one)):
        parts, _ = _draw(e, engines=20_000)
        read = s.journal.classify(s.read(parts.housing_reading, parts.journal_reading)[1])
        true = s.journal.classify(s.read(parts.housing_bore, parts.journal_d)[1])
        share[label] = np.mean(read != true)
    assert share["one"] > 1.3 * share["four"]
