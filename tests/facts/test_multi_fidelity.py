"""The study's film checked by the mass-conserving tier on some engines, combined by control variates."""

import numpy as np
import pytest

import stackup
from stackup.facts import multi_fidelity

KW = dict(schemes=("iso13778-3",), n_engines=200, seed=3, pilot_engines=1000, crank_angle_step=6.0, progress=False)


@pytest.fixture(scope="module")
def checked():
    return stackup.Study(**KW, mechanics_engines=6, film_check_engines=6).run()


def test_the_check_runs_on_the_first_engines_only_and_no_check_is_the_default():
    ds = stackup.Study(**KW, mechanics_engines=5, film_check_engines=2).run()
    valid = ds.film_valid.values[0]
    for name in ("h_min_check", "h_min_mean_check", "life_check"):
        values = ds[name].values[0]
        assert np.all(np.isnan(values[2:]))
        assert np.all(np.isfinite(values[:2][valid[:2]]))
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"]
    # the checked engines' own films are the study's, unchanged by the check
    plain = stackup.Study(**KW, mechanics_engines=5).run()
    np.testing.assert_array_equal(plain.h_min.values, ds.h_min.values)
    assert np.all(np.isnan(plain.h_min_check.values)) and multi_fidelity(plain).empty


def test_the_mass_conserving_tier_thins_the_films_and_shortens_the_lives(checked):
    # the mobility tier carries no film content: its cycle-mean film is thick (reports/film_speed_vs_error.md)
    d = checked.isel(scheme=0)
    assert np.nanmedian(d.h_min_mean_check / d.h_min_mean) < 0.95
    assert np.nanmedian(d.life_check / d.life) < 0.95
    # films of micrometres where the study's film is; an edge the rigid film holds at the wall stays there
    thick = (d.h_min > 1e-6).values
    assert np.nanmedian(d.h_min_check.values[thick]) > 0.5e-6
    assert np.all((d.h_min_check > 0.05e-6) | np.isnan(d.h_min_check))


def test_checked_in_full_the_corrected_mean_is_the_accurate_mean(checked):
    # every engine checked: the control-variate estimate is the check tier's own mean, and its interval holds it
    corrected = multi_fidelity(checked)
    for bearing in checked.bearing.values:
        row = corrected.loc[("iso13778-3", int(bearing))]
        accurate = np.nanmean(checked.life_check.sel(scheme="iso13778-3", bearing=bearing).values)
        estimate, lower, upper = row.life_corrected
        assert estimate == pytest.approx(accurate, rel=1e-12) and lower <= accurate <= upper
        assert row.pairs == row.engines


def test_a_check_on_part_of_the_engines_covers_the_full_check(checked):
    # the first three engines' check, against the mean of all six: within the stated interval
    part = checked.copy(deep=True)
    for name in ("h_min_check", "h_min_mean_check", "life_check"):
        part[name][:, 3:] = np.nan
    full, estimate = multi_fidelity(checked), multi_fidelity(part)
    for index, row in estimate.iterrows():
        assert row.pairs == 3 and row.engines == 6
        lower, upper = row.h_min_mean_corrected[1:]
        assert lower <= full.loc[index, "h_min_mean_corrected"][0] <= upper


def test_the_report_states_the_corrected_means_and_a_check_below_the_target(checked, tmp_path):
    # the sentences are the report's templates filled with the numbers of the check (no prose copied here)
    from stackup.report import format as fmt
    from stackup.report import templates as words
    from stackup.report import write_report

    corrected = multi_fidelity(checked).xs("iso13778-3", level="scheme")
    life, lower, upper = (np.array([q[k] / 3600 for q in corrected.life_corrected]) for k in range(3))
    cheap = corrected.life_cheap.to_numpy() / 3600
    text = write_report(checked, tmp_path).read_text()
    # the corrected lives over the positions, their widest half-interval and the study tier's lives
    assert words.CORRECTED_SPAN.format(
        lo=fmt.significant(life.min()), hi=fmt.significant(life.max()),
        half=fmt.significant(np.max(np.maximum(life - lower, upper - life))),
        cheap_lo=fmt.significant(cheap.min()), cheap_hi=fmt.significant(cheap.max())) in text
    # the film tier's error the Methods quote is this engine's, as the check measured it

    def thick(name):
        return 100 * max(c / q[0] - 1 for c, q in zip(corrected[f"{name}_cheap"], corrected[f"{name}_corrected"]))

    assert words.CHECKED_ERRORS_PART.format(h_min=thick("h_min"), h_min_mean=thick("h_min_mean")) in text
    # a target above every corrected life: the first page says where the check falls short
    target = 2 * life.max()
    short = checked.assign(life_target=target * 3600)
    worst = stackup.rank(short).loc["iso13778-3"]
    first_page = write_report(short, tmp_path / "short").read_text().split("<!-- /verdict -->")[0]
    assert words.SHORT_LIFE_NOTE.format(
        bearing=worst.life_below_target_position, share=fmt.interval(worst.life_below_target_pct,
                                                                     worst.life_below_target_pct_ci, 1),
        scheme="iso13778-3", target=fmt.whole(target), checked=words.CHECKED_PART) in first_page
