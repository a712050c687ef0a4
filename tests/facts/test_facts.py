"""The facts of a comparison: one computation the ranking and the report share, declared dataset attributes."""

import json
import re

import numpy as np
import pandas as pd
import pytest

import stackup
from stackup.facts import facts, film_summary
from stackup.facts.declared import PressFit, Processes, StudyParameters, Wear
from stackup.rank import rank, ranked

KW = dict(schemes=("iso13778-3", "iso13778-4"), n_engines=500, seed=6, pilot_engines=2000, mechanics_engines=10,
          crank_angle_step=12.0, progress=False)


@pytest.fixture(scope="module")
def study():
    return stackup.Study(**KW).run()


def test_rank_orders_the_rows_the_facts_hold(study):
    known = facts(study)
    pd.testing.assert_frame_equal(ranked(known.ranking), rank(study))
    assert ranked(known.ranking).attrs == rank(study).attrs


def test_the_film_table_and_the_ranking_give_the_same_film_and_life_numbers(study):
    known, ranking = facts(study), rank(study)
    for scheme, row in film_summary(study).iterrows():
        assert row.engine_life_median_h == (ranking.engine_life_median_h[scheme],
                                            *ranking.engine_life_median_h_ci[scheme])
        assert row.engine_life_b10_h == (ranking.engine_life_b10_h[scheme], *ranking.engine_life_b10_h_ci[scheme])
        assert row.life_below_target_pct == (ranking.life_below_target_pct[scheme],
                                             *ranking.life_below_target_pct_ci[scheme])
        assert row.alpha_over_20_pct == (ranking.alpha_over_limit_pct[scheme], *ranking.alpha_over_limit_pct_ci[scheme])
        assert known.film.loc[scheme].equals(row)


def test_the_fit_table_and_the_ranking_give_the_same_operating_clearance(study):
    known, ranking = facts(study), rank(study)
    np.testing.assert_array_equal(known.fit.operating_mean_um[ranking.index], ranking.clearance_mean_um)
    np.testing.assert_array_equal(known.fit.operating_std_um[ranking.index], ranking.clearance_std_um)


def test_a_comparison_gives_its_datasets_to_the_facts(study):
    class Saved:  # what stackup.comparison.Comparison holds
        dataset, scenarios, sensitivity, tails = study, {"same": study}, None, None

    known = facts(Saved())
    assert list(known.ranking.scenarios) == ["same"] and list(known.scenario_rankings) == ["same"]
    assert known.drivers is None and known.design is None


def test_the_declared_attributes_read_what_the_study_wrote(study):
    written = json.loads(study.attrs["study"])
    params = StudyParameters.of(study)
    assert dict(params.items) == written and params.n_engines == KW["n_engines"]
    assert PressFit.of(study).housing_outer == json.loads(study.attrs["press_fit"])["housing_outer"]
    assert Processes.of(study).housing_bore.cpk == json.loads(study.attrs["engine_processes"])["housing_bore"]["cpk"]
    assert Wear.of(study).critical_film_m == json.loads(study.attrs["wear"])["critical_film_m"]


def test_a_missing_attribute_or_key_is_named(study):
    wear = json.loads(study.attrs["wear"])
    del wear["wear_limit_m"]
    broken = study.copy()
    broken.attrs = {**study.attrs, "wear": json.dumps(wear)}
    with pytest.raises(ValueError, match="dataset attribute 'wear': no key 'wear_limit_m'"):
        Wear.of(broken)
    processes = json.loads(study.attrs["engine_processes"])
    del processes["journal_d"]["cpk"]
    broken.attrs = {**study.attrs, "engine_processes": json.dumps(processes)}
    with pytest.raises(ValueError, match="dataset attribute 'engine_processes': no key 'journal_d.cpk'"):
        Processes.of(broken)
    broken.attrs = {k: v for k, v in study.attrs.items() if k != "press_fit"}
    with pytest.raises(ValueError, match="dataset attribute 'press_fit': missing"):
        facts(broken)


def test_every_tier_has_a_note_without_measured_figures():
    from stackup.crank import TIER_NOTES as crank_notes
    from stackup.crank.cycle import METHODS as CRANK_METHODS
    from stackup.film import TIER_NOTES as film_notes
    from stackup.fit import METHODS as FIT_METHODS
    from stackup.fit import TIER_NOTES as fit_notes

    assert set(fit_notes) == set(FIT_METHODS) and set(crank_notes) == set(CRANK_METHODS)
    assert {"short", "finite", "reynolds", "mobility", "mobility-finite", "elrod-coarse",
            "reynolds-transient"} == set(film_notes)
    for note in (*fit_notes.values(), *crank_notes.values(), *film_notes.values()):
        assert not re.search(r"\d", re.sub(r"\(\d{4}\)", "", note)), note  # a year of a source, no figures


def test_lives_are_read_per_position_and_per_engine_never_pooled(study):
    from stackup.facts import position_risks
    from stackup.life import ALPHA_SCUFFING

    d = study.sel(scheme="iso13778-3").copy(deep=True)
    # position 2 scuffs in three engines and lives short in two; position 4 scuffs in one; nothing else does
    d["alpha"][:] = 0.0
    d["life"][:] = 2.0 * float(d.life_target)
    d["alpha"][:3, 1] = ALPHA_SCUFFING + 0.05
    d["alpha"][0, 3] = ALPHA_SCUFFING + 0.05
    d["life"][:2, 1] = 0.5 * float(d.life_target)
    risks = position_risks(d, float(d.life_target) / 3600)
    engines = d.sizes["mech_engine"]
    assert [v[0] for v in risks["alpha_over_limit"]] == pytest.approx([0, 3 / engines, 0, 1 / engines, 0])
    assert [v[0] for v in risks["life_below_target"]] == pytest.approx([0, 2 / engines, 0, 0, 0])
    lo, hi = risks["alpha_over_limit"][1][1:]
    assert lo < 3 / engines < hi  # Clopper-Pearson
    row = stackup.facts.metrics.scheme_metrics(d, (35e-6, 65e-6), float(d.critical_film.max()))
    assert row["alpha_over_limit_pct"] == pytest.approx(300 / engines) and row["alpha_over_limit_position"] == 2
    assert row["life_below_target_pct"] == pytest.approx(200 / engines) and row["life_below_target_position"] == 2
    # the engine's life is its weakest bearing's; nothing pooled over positions is ranked
    weakest = d.life.values.min(axis=1) / 3600
    assert row["engine_life_median_h"] == pytest.approx(np.median(weakest))
    assert "life_median_h" not in row and "life_b10_h" not in row


def test_a_scenario_is_compared_engine_by_engine_per_position(study):
    from stackup.facts import paired_life_changes

    other = study.copy(deep=True)
    other["life"][:, :, 1] = 0.9 * study.life[:, :, 1]  # bearing 2 lives 10 % shorter in every engine
    other["life"][:, :, 4] = study.life[:, :, 4] + 3600.0  # bearing 5 an hour longer
    positions, engines = paired_life_changes(study, other)
    for scheme in study.scheme.values:
        s = str(scheme)
        base = study.life.sel(scheme=scheme).values / 3600
        assert positions.loc[(s, 2), "life_change_h"][0] == pytest.approx(np.median(-0.1 * base[:, 1]))
        assert positions.loc[(s, 2), "life_change_h"][2] < 0  # the whole interval below zero
        assert positions.loc[(s, 1), "life_change_h"] == (0.0, 0.0, 0.0)
        assert positions.loc[(s, 5), "life_change_h"] == pytest.approx((1.0, 1.0, 1.0))
        weakest = np.minimum(0.9 * base[:, 1], np.delete(base, 1, axis=1).min(axis=1))
        assert engines.loc[s, "engine_life_change_h"][0] == pytest.approx(np.median(weakest - base.min(axis=1)))
    # a scenario that did not run the mechanical chain has no paired lives
    assert paired_life_changes(study, other.drop_vars(["life"])) == (None, None)
