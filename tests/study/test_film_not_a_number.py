"""A bearing whose film collapsed is flagged, not a number: through the study chain, ranking and report.

The hard case is the one the film tests use (tests/film/test_cycle.py): a load of
constant size turning at half the shaft speed leaves no squeeze film to carry it
(half-frequency whirl), so the journal is driven to the eccentricity limit. It is
put on one bearing of the first engine of the study's mechanical chain; every
other bearing keeps the engine's own loads.
"""

import dataclasses

import numpy as np
import pytest

import stackup.study.chain as chain
from stackup import rank
from stackup.film.cycle import NOT_A_NUMBER
from stackup.report import bearing_summary, film_summary
from stackup.study import Study
from stackup.study.failures import FailureCount
from stackup.study.schema import FILM_NUMBERS, MECHANICS, flag

BEARING = 2  # main bearing 3
ENGINES = 8
KW = dict(n_engines=60, mechanics_engines=ENGINES, crank_angle_step=4.0, schemes=("iso13778-4",), seed=3,
          pilot_engines=2000, film_method="mobility-finite", progress=False)


def half_speed_on_first_engine(real):
    """``engine_cycles`` whose first engine's bearing 3 carries 8 kN turning at half the shaft speed."""
    def cycles(spec, *, crank_angle, **kw):
        r = real(spec, crank_angle=crank_angle, **kw)
        phase = 0.5 * np.radians(crank_angle)
        loads = r.reactions.copy()
        loads[0, :, BEARING] = 8e3 * np.stack([np.cos(phase), np.sin(phase)], axis=-1)
        return dataclasses.replace(r, reactions=loads)

    return cycles


@pytest.fixture(scope="module")
def collapsed():
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(chain, "engine_cycles", half_speed_on_first_engine(chain.engine_cycles))
        return Study(**KW).run(), Study(**KW, keep="summaries").run()


def test_the_collapsed_bearing_keeps_its_status_and_has_no_film_or_life(collapsed):
    ds, _ = collapsed
    status = ds.film_status.values[0]
    assert status[0, BEARING] == flag(ds.film_status, "collapsed")
    assert not ds.film_valid.values[0, 0, BEARING]
    for name in FILM_NUMBERS:
        if name in ds:
            assert np.isnan(ds[name].values[0, 0, BEARING]), name
            assert "NaN where film_valid is false" in ds[name].attrs["long_name"]
    # the beam's results are not the film's: they stay
    assert np.isfinite(ds.reaction_max.values[0, 0, BEARING]) and np.isfinite(ds.tilt_max.values[0, 0, BEARING])
    # every other bearing has its periodic film and its life
    others = np.ones(status.shape, bool)
    others[0, BEARING] = False
    assert not np.isin(status[others], [MECHANICS["film_status"].flags.index(s) for s in NOT_A_NUMBER]).any()
    assert ds.film_valid.values[0][others].all()
    assert np.all(np.isfinite(ds.h_min.values[0][others])) and np.all(np.isfinite(ds.life.values[0][others]))
    # the engine's life is its weakest bearing's: not a number either
    engine_life = ds.life.values[0].min(axis=-1)
    assert np.isnan(engine_life[0]) and np.all(np.isfinite(engine_life[1:]))


def test_ranking_and_tables_leave_the_collapsed_bearing_out_and_count_it(collapsed):
    ds, summaries = collapsed
    row = rank(ds).loc["iso13778-4"]
    assert row.film_left_out == 1 and row.film_bearings == 5 * ENGINES - 1
    # engine 0 (its bearing's film collapsed) has no life: the engines' life is the others' weakest bearing's
    engine_life = ds.life.values[0].min(axis=-1)[1:] / 3600
    assert np.all(np.isfinite(engine_life))
    assert row.engine_life_median_h == pytest.approx(np.median(engine_life))
    assert np.isfinite(row.alpha_over_limit_pct) and np.isfinite(row.h_min_below_critical_pct)
    # the streaming summaries carry the same NaN and rank alike
    assert rank(summaries).loc["iso13778-4", "film_left_out"] == 1
    assert rank(summaries).loc["iso13778-4", "engine_life_median_h"] == row.engine_life_median_h
    film = film_summary(ds).loc["iso13778-4"]
    assert film.left_out == 1 and film.engines_left_out == 1 and film.engines == ENGINES
    assert np.isfinite(film.engine_life_b10_h[0]) and np.isfinite(film.alpha_mean)
    per_bearing = bearing_summary(ds).loc[("iso13778-4", BEARING + 1)]
    assert per_bearing.engines == ENGINES - 1 and np.isfinite(per_bearing.h_min_median_um[0])
    failures = FailureCount.of_dataset(ds)
    assert failures.failed["film"] == 1 and failures.counted["film"] == 5 * ENGINES


def test_the_report_says_the_collapsed_bearing_is_left_out(collapsed, tmp_path):
    # the report's template filled with the counts: 5 bearings of 8 engines ran, one collapsed, one engine without
    # an engine life (no prose copied here)
    from stackup.report import templates as words
    from stackup.report import write_report

    text = write_report(collapsed[0], tmp_path).read_text()
    assert words.NOT_A_NUMBER.format(
        total=5 * ENGINES, counts=words.NOT_A_NUMBER_COUNT_PART.format(count=1, status="collapsed"), engines=1,
        engines_s=words.plural(1), have=words.plural(1, "have", "has")) in text
