"""Ranking and sensitivity."""

import numpy as np
import pytest
import xarray as xr

import stackup
from stackup.sensitivity import contributions


@pytest.fixture(scope="module")
def study():
    return stackup.Study(n_engines=3000, mechanics_engines=30, crank_angle_step=4.0, seed=11, pilot_engines=4000,
                         progress=False).run()


def test_ranking_does_not_depend_on_scheme_order(study):
    a = stackup.rank(study)["rank"]
    b = stackup.rank(study.isel(scheme=[5, 2, 0, 4, 1, 3]))["rank"]
    assert a.sort_index().equals(b.sort_index())


def test_ranking_is_reproducible_with_a_seed(study):
    again = stackup.Study(n_engines=3000, mechanics_engines=30, crank_angle_step=4.0, seed=11, pilot_engines=4000,
                          progress=False).run()
    assert stackup.rank(study).equals(stackup.rank(again))


def test_a_strictly_better_scheme_ranks_first(study):
    best = study.copy(deep=True)
    i = list(best.scheme.values).index("iso13778-1")  # the worst for this window, made the best
    centre = float(best.clearance_window.mean())
    ok = best.status.values[i] == 0
    best["clearance_operating"].values[i][ok] = centre
    best["alpha"].values[i] = np.where(np.isfinite(best.alpha.values[i]), 0.0, np.nan)
    best["life"].values[i] = best.life.values[i] * 100
    ranking = stackup.rank(best)
    assert ranking.index[0] == "iso13778-1" and ranking.loc["iso13778-1", "rank"] == 1
    assert (ranking["rank"] == 1).sum() == 1


def test_identical_schemes_tie(study):
    twin = xr.concat([study.sel(scheme=["iso13778-4"]), study.sel(scheme=["iso13778-4"]).assign_coords(scheme=["twin"])],
                     dim="scheme", data_vars="all", coords="different", compat="equals", join="outer")
    ranking = stackup.rank(twin)
    assert list(ranking["rank"]) == [1, 1]


def test_scenarios_give_the_worst_degradation(study):
    shifted = study.copy(deep=True)
    shifted["clearance_operating"] = shifted.clearance_operating + 8e-6
    ranking = stackup.rank(study, scenarios={"bore +8 um": shifted, "same": study})
    assert set(ranking["worst_outside_window_ppm_scenario"]) <= {"bore +8 um", "same"}
    assert ranking.loc["iso13778-1", "worst_outside_window_ppm"] > 0



def test_a_scenario_on_fewer_engines_is_compared_on_the_same_engines(study):
    # the study's own first 10 engines of the mechanical chain as a "scenario": nothing changed, so no change,
    # although their life median differs from that of all 30 engines
    same = study.isel(mech_engine=slice(0, 10))
    r = stackup.rank(study, scenarios={"first ten": same}, window=(40e-6, 70e-6))
    np.testing.assert_array_equal(r.worst_engine_life_median_h.to_numpy(), 0.0)
    assert np.any(stackup.rank(same, window=(40e-6, 70e-6)).engine_life_median_h != r.engine_life_median_h)

def test_bad_window(study):
    with pytest.raises(ValueError, match="window: .* is not a"):
        stackup.rank(study, window=(70e-6, 40e-6))


def test_sensitivity_recovers_known_variance_shares():
    # a synthetic one-scheme dataset whose clearance is a known linear function of the inputs
    from stackup.sensitivity import INPUTS

    rng = np.random.default_rng(0)
    n = 4000
    ds = stackup.Study(n_engines=n, mechanics_engines=0, schemes=("iso13778-1",), seed=1, pilot_engines=2000,
                       progress=False).run()
    d = ds.sel(scheme="iso13778-1")
    bore = np.broadcast_to(d.housing_bore.values, d.status.shape)
    journal = np.broadcast_to(d.journal_d.values, d.status.shape)
    y = 2.0 * (bore - bore.mean()) / bore.std() + 1.0 * (journal - journal.mean()) / journal.std()
    y = y + 0.0 * rng.standard_normal(y.shape)
    ds["clearance_operating"].values[0] = np.where(d.status.values == 0, y, np.nan)
    frame = contributions(ds, "iso13778-1", within_bearing=False, bootstrap=50)
    assert frame.attrs["r2"] == pytest.approx(1.0, abs=1e-9)
    assert frame.loc["housing bore", "share"] == pytest.approx(0.8, abs=0.02)
    assert frame.loc["journal", "share"] == pytest.approx(0.2, abs=0.02)
    assert set(frame.index) <= set(INPUTS)


def test_summaries_rank_like_the_full_dataset():
    import pandas as pd

    from stackup import Study, rank

    kw = dict(n_engines=2500, mechanics_engines=25, crank_angle_step=12.0, progress=False, pilot_engines=3000,
              schemes=("iso13778-1", "iso13778-4"))
    full, summary = rank(Study(**kw).run()), rank(Study(**kw, keep="summaries").run())
    exact = ["bearings", "outside_window_ppm", "stockout_ppm", "shell_grades", "surplus_pct", "engine_life_median_h",
             "alpha_over_limit_pct", "life_below_target_pct", "rank"]
    pd.testing.assert_frame_equal(summary[exact], full[exact])
    np.testing.assert_allclose(summary.clearance_mean_um, full.clearance_mean_um, rtol=1e-12)
    np.testing.assert_allclose(summary.clearance_std_um, full.clearance_std_um, rtol=1e-9)
    with pytest.raises(ValueError, match="window: .* differs from .* the window the summaries count"):
        rank(Study(**{**kw, "mechanics_engines": 0}, keep="summaries").run(), window=(40e-6, 70e-6))


@pytest.mark.integration
@pytest.mark.parametrize("method", ["conditional", "splitting"])
def test_too_few_counted_bearings_rank_on_the_tail_estimate(study, method):
    from stackup.facts import MIN_COUNTED, TAIL_SOURCES
    from stackup.comparison import tails_dataset

    tails = tails_dataset("iso-example", list(study.scheme.values), n_level=1000, method=method)
    ranking = stackup.rank(study, tails=tails)
    for name, row in ranking.iterrows():
        t = tails.sel(scheme=name)
        if row.outside_window_counted < MIN_COUNTED:
            assert row.outside_window_source == TAIL_SOURCES[method]
            assert row.outside_window_ppm == pytest.approx(1e6 * float(t.tail_share.sum()))
            lo, hi = row.outside_window_ppm_ci
            assert lo <= row.outside_window_ppm <= hi and hi - lo > 0
        else:
            assert row.outside_window_source == "counted"
    assert (ranking.outside_window_source == "counted").any()
    with pytest.raises(ValueError, match="tails: estimated for the window"):
        stackup.rank(study, tails=tails.assign_attrs(window=[40e-6, 70e-6]))


def _rows(**schemes):
    """RankingRows of made-up schemes: name -> (share outside [ppm], its interval, shell grades, stock-outs [ppm])."""
    from stackup.facts import RankingRows

    rows = {name: {"outside_window_ppm": share, "outside_window_ppm_ci": ci, "outside_window_source": "counted",
                   "shell_grades": grades, "part_grades": 6, "stockout_ppm": stockouts,
                   "stockout_ppm_ci": (0.8 * stockouts, 1.2 * stockouts + 1), "surplus_pct": 9.0,
                   "clearance_mean_um": 45.0, "clearance_std_um": 2.5}
            for name, (share, ci, grades, stockouts) in schemes.items()}
    return RankingRows(rows, {}, (34.5e-6, 57.5e-6), {})


def test_shares_less_than_negligible_apart_leave_the_choice_to_cost():
    from dataclasses import replace

    from stackup.rank import ranked

    # the case: the designed scheme 0.050 ppm, 4 grades, 150 ppm stock-outs; ISO 5 0.78 ppm, 3 grades, 22
    rows = _rows(designed=(0.050, (0.034, 0.065), 4, 150.0), iso5=(0.78, (0.70, 0.86), 3, 22.0),
                 iso4=(8.0, (7.3, 8.7), 5, 458.0))
    r = ranked(rows)
    assert list(r.index) == ["iso5", "designed", "iso4"] and list(r["rank"]) == [1, 2, 3]
    assert r.attrs["negligible_ppm"] == 1.0 and "by 1 or more" in r.attrs["rule"]
    # a threshold below their difference: the clearance decides again
    strict = ranked(replace(rows, negligible=0.5))
    assert list(strict.index) == ["designed", "iso5", "iso4"]
    # a threshold above every difference: cost alone
    assert list(ranked(replace(rows, negligible=100.0)).index) == ["iso5", "designed", "iso4"]


def test_overlapping_intervals_do_not_separate_however_far_apart_the_shares():
    from stackup.rank import ranked

    rows = _rows(few=(0.0, (0.0, 74.0), 3, 0.0), cheap=(40.0, (5.0, 144.0), 1, 0.0))
    assert list(ranked(rows).index) == ["cheap", "few"]  # cannot be told apart on the clearance: cost


def test_groups_are_taken_from_the_best_so_no_cycle_leaves_the_first_rank_empty():
    # a ~ b and b ~ c on the clearance but a beats c: pairwise wins would cycle (b > a on cost, c > b, a > c)
    from stackup.rank import ranked

    rows = _rows(a=(0.0, (0.0, 0.0), 5, 0.0), b=(0.8, (0.8, 0.8), 3, 0.0), c=(1.5, (1.5, 1.5), 2, 0.0))
    r = ranked(rows)
    assert list(r.index) == ["b", "a", "c"] and list(r["rank"]) == [1, 2, 3]
    flipped = ranked(_rows(c=(1.5, (1.5, 1.5), 2, 0.0), b=(0.8, (0.8, 0.8), 3, 0.0), a=(0.0, (0.0, 0.0), 5, 0.0)))
    assert list(flipped.index) == list(r.index)


@pytest.mark.integration
def test_a_comparison_ranks_as_its_report_and_its_bare_study_dataset_is_refused(study, tmp_path):
    from stackup.comparison import COMPARISON_NOTE, Comparison
    from stackup.io import open_comparison, save_comparison
    from stackup.comparison import tails_dataset

    tails = tails_dataset("iso-example", list(study.scheme.values), n_level=1000)
    ds = study.assign_attrs(comparison=COMPARISON_NOTE, negligible_ppm=2.0)
    empty = xr.Dataset(coords={"output": [], "scheme": [], "input": []})
    path = save_comparison(Comparison(ds, {}, empty, tails), tmp_path / "compare.nc", compact=False)
    with pytest.raises(ValueError, match=r"stackup.rank\(stackup.io.open_comparison\(path\)\)"):
        stackup.rank(xr.open_dataset(path))
    saved = stackup.rank(open_comparison(path))
    pd_testing = __import__("pandas").testing
    pd_testing.assert_frame_equal(saved, stackup.rank(ds, tails=tails))
    assert saved.attrs["negligible_ppm"] == 2.0  # the comparison's threshold
    assert stackup.rank(ds, tails=tails, negligible=0.0).attrs["negligible_ppm"] == 0.0
