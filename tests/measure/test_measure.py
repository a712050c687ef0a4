"""Measured data in (issue 35): process fits, bad data refused, the housing calibrated, engine files written."""

import os
import re
import subprocess
import sys
import tomllib
import warnings

import numpy as np
import pytest
from scipy import stats

import stackup
from stackup import cli
from stackup.engines import engine_path, load_engine
from stackup.measure import calibrate_housing, fit_csv, fit_process, write_engine
from stackup.measure.coverage import BORE_LIMITS, synthetic_fitting_tests
from stackup.measure.models import SkewNormalModel, _skew_fit, skew_centred, skew_direct
from stackup.measure.process import anderson_darling
from stackup.measure.shared import shared_share
from stackup.tolerances import MAX_SKEWNESS, Normal, SkewNormal, process_from_spec, quantile_cpk

MM, UM = 1e-3, 1e-6


def _normal_sample(n=200, seed=0, mean=50.009e-3, sigma=2e-6):
    return mean + sigma * np.random.default_rng(seed).standard_normal(n)


def _csv(tmp_path, name, lines):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


# --- the skew-normal process an engine file can now declare ------------------------------------------------

@pytest.mark.parametrize("skewness", [-0.9, -0.3, 0.0, 0.6, 0.99])
def test_skew_normal_centred_parameters_are_the_distributions_moments(skewness):
    p = SkewNormal(1.0, 0.2, skewness)
    alpha, xi, omega = p.direct
    mean, var, skew = stats.skewnorm.stats(alpha, loc=xi, scale=omega, moments="mvs")
    assert mean == pytest.approx(1.0, abs=1e-12)
    assert np.sqrt(var) == pytest.approx(0.2, rel=1e-12)
    assert skew == pytest.approx(skewness, abs=1e-9)
    x = np.linspace(0.0, 2.0, 101)
    np.testing.assert_allclose(p.cdf(x), stats.skewnorm.cdf(x, alpha, loc=xi, scale=omega), atol=1e-12)
    u = np.array([1e-4, 0.01, 0.3, 0.5, 0.9, 0.9999])
    # the tabulated quantile: within 1e-4 sigma also at the short tail of a nearly half-normal process
    np.testing.assert_allclose(p.ppf(u), stats.skewnorm.ppf(u, alpha, loc=xi, scale=omega), atol=1e-4 * 0.2)


def test_quantile_cpk_is_the_classic_one_for_a_normal_and_reads_the_skewed_tail():
    lo, hi = 50.000e-3, 50.018e-3
    assert quantile_cpk(Normal(50.0095e-3, 2e-6), lo, hi) == pytest.approx(0.0085e-3 / 6e-6, rel=1e-9)
    process = SkewNormal(50.0085e-3, 2.2e-6, 0.6)
    alpha, xi, omega = process.direct
    low, mid, high = stats.skewnorm.ppf(stats.norm.cdf([-3.0, 0.0, 3.0]), alpha, loc=xi, scale=omega)
    expected = min((hi - mid) / (high - mid), (mid - lo) / (mid - low))  # ISO 22514-2 with scipy's quantiles
    assert quantile_cpk(process, lo, hi) == pytest.approx(expected, rel=1e-4)
    # the long upper tail faces the upper limit: less than the moment form min(U - mu, mu - L) / 3 sigma
    assert quantile_cpk(process, lo, hi) < (hi - 50.0085e-3) / (3 * 2.2e-6)


def test_skew_normal_engine_file_form_is_read_in_file_units():
    p = process_from_spec({"distribution": "skew-normal", "mean": 50.009, "sigma": 0.002, "skewness": -0.4},
                          lo=50e-3, hi=50.018e-3, scale=1e-3, field="housing_bore.process")
    assert type(p) is SkewNormal
    assert (p.mean, p.sigma, p.skewness) == pytest.approx((50.009e-3, 2e-6, -0.4), rel=1e-12)
    assert p.shifted(1e-6).mean == pytest.approx(50.010e-3)
    with pytest.raises(ValueError, match=r"housing_bore.process.skewness: 1.2 is not valid; a skew-normal's "
                                         r"skewness lies in \(-0.9953, 0.9953\)"):
        process_from_spec({"distribution": "skew-normal", "sigma": 0.002, "skewness": 1.2}, lo=50e-3, hi=50.018e-3,
                          scale=1e-3, field="housing_bore.process")
    assert MAX_SKEWNESS == pytest.approx(0.99527, abs=1e-5)  # the half-normal's skewness


# --- the fits ------------------------------------------------------------------------------------------------

def test_skew_normal_maximum_likelihood_matches_scipy():
    x = SkewNormal(0.0, 1.0, 0.7).from_normal(np.random.default_rng(4).standard_normal(400))
    p, ll = _skew_fit(x[None], np.ones((1, x.size)), starts=(1.0, 0.5, 0.0))
    a, loc, scale = stats.skewnorm.fit(x)
    assert ll[0] >= stats.skewnorm.logpdf(x, a, loc, scale).sum() - 1e-6
    np.testing.assert_allclose(p[0], skew_centred(a, loc, scale), atol=2e-4)
    alpha, xi, omega = skew_direct(*p[0])
    assert stats.skewnorm.logpdf(x, alpha, loc=xi, scale=omega).sum() == pytest.approx(ll[0], rel=1e-10)
    params, loglik = SkewNormalModel().refit(x)
    assert loglik[0] == pytest.approx(ll[0], rel=1e-10)


def test_anderson_darling_statistic_is_scipys():
    x = _normal_sample(150, seed=3)
    u = stats.norm.cdf(x, x.mean(), x.std(ddof=1))
    with warnings.catch_warnings():  # scipy 1.17 asks for a p-value method; the statistic is the same
        warnings.simplefilter("ignore", FutureWarning)
        reference = stats.anderson(x, dist="norm").statistic
    assert float(anderson_darling(u)) == pytest.approx(reference, rel=1e-9)


def test_normal_fit_removes_the_gauge_from_sigma_and_cpk():
    x = _normal_sample(200, seed=1)
    r = 0.8e-6
    fit = fit_process(x, limits=BORE_LIMITS, gauge_repeatability=r, resamples=300)
    s_read = x.std(ddof=1)
    s_proc = np.sqrt(s_read**2 - r * r)
    assert fit.model == "normal"
    assert fit.params["sigma"].value == pytest.approx(s_proc, rel=1e-12)
    cpk = min(BORE_LIMITS[1] - x.mean(), x.mean() - BORE_LIMITS[0]) / (3 * s_proc)
    assert fit.cpk == pytest.approx(cpk, rel=1e-9)
    assert fit.cpk_ci[0] < cpk < fit.cpk_ci[1]
    # mean: Student's t; sigma: chi-square on the readings' variance, then R^2 removed
    t_half = stats.t.ppf(0.975, 199) * s_read / np.sqrt(200)
    assert (fit.params["mean"].lo, fit.params["mean"].hi) == pytest.approx((x.mean() - t_half, x.mean() + t_half))
    var_hi = 199 * s_read**2 / stats.chi2.ppf(0.025, 199)
    assert fit.params["sigma"].hi == pytest.approx(np.sqrt(var_hi - r * r), rel=1e-12)
    plain = fit_process(x, limits=BORE_LIMITS, resamples=300)
    assert fit.cpk > plain.cpk  # the process is better than it reads


def test_drift_is_chosen_with_a_sequence_and_written_as_tool_wear():
    n = 150
    rng = np.random.default_rng(7)
    x = 0.074e-3 + 0.008e-3 * np.arange(n) / (n - 1) + 1.5e-6 * rng.standard_normal(n)
    fit = fit_process(x, limits=(0.065e-3, 0.090e-3), sequence=np.arange(n) * 10.0 + 3.0, resamples=200)
    assert fit.model == "drift"
    spec = fit.process_spec("mm")
    assert spec["distribution"] == "tool-wear"
    assert spec["start"] == pytest.approx(0.074, abs=0.0008) and spec["end"] == pytest.approx(0.082, abs=0.0008)
    assert fit_process(x, limits=(0.065e-3, 0.090e-3), resamples=200).model != "drift"


def test_shared_share_of_balanced_groups_is_searles_anova():
    rng = np.random.default_rng(5)
    codes = np.repeat(np.arange(40), 5)
    z = np.sqrt(0.4) * rng.standard_normal(40)[codes] + np.sqrt(0.6) * rng.standard_normal(200)
    share = shared_share(z, codes)
    from stackup.measure.shared import normal_scores
    y = normal_scores(z)
    means = np.array([y[codes == g].mean() for g in range(40)])
    msb = 5 * np.sum((means - y.mean()) ** 2) / 39
    msw = sum(np.sum((y[codes == g] - means[g]) ** 2) for g in range(40)) / 160
    f = msb / msw
    assert share.value == pytest.approx((f - 1) / (f - 1 + 5), rel=1e-12)
    f_lo = f / stats.f.ppf(0.975, 39, 160)
    assert share.lo == pytest.approx((f_lo - 1) / (f_lo - 1 + 5), rel=1e-12)
    assert share.lo < 0.4 < share.hi
    # the gauge's noise is not shared: the process's share is the readings' times (sigma_p^2 + R^2) / sigma_p^2
    assert shared_share(z, codes, gauge_factor=1.25).value == pytest.approx(1.25 * share.value)


# --- bad data refused: file, column, row, what is valid ----------------------------------------------------

def test_text_in_a_numeric_column_names_file_column_and_line(tmp_path):
    path = _csv(tmp_path, "bores.csv", ["# measured 2024", "block,bore", "B1,50.0091", "B1,n.a.x", "B1,50.0102"])
    with pytest.raises(ValueError, match=r"'bores.csv', column 'bore', line 4: 'n.a.x' is not a number \(text in a "
                                         r"numeric column\)"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


def test_decimal_commas_get_a_hint(tmp_path):
    path = _csv(tmp_path, "bores.csv", ["block;bore", "B1;50,0091"])
    with pytest.raises(ValueError, match=r"line 2: '50,0091' is not a number .*write decimals with a point"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


def test_empty_and_nan_cells_are_counted_refused_or_left_out(tmp_path):
    values = [f"B{k},{50.009 + 0.002 * z:.4f}" for k, z in enumerate(np.random.default_rng(0).standard_normal(40))]
    values[3], values[10] = "B3,", "B10,NaN"
    path = _csv(tmp_path, "bores.csv", ["block,bore"] + values)
    with pytest.raises(ValueError, match=r"'bores.csv': 2 rows with an empty or NaN cell in 'bore' \(lines 5, 12\); "
                                         r"fill them, or leave those rows out \(--drop-missing\)"):
        fit_csv(path, "bore", limits=(50.000, 50.018))
    fit = fit_csv(path, "bore", limits=(50.000, 50.018), drop_missing=True, resamples=200)
    assert fit.n == 38
    assert fit.notes[0] == "2 rows with an empty or NaN cell left out (lines 5, 12)"
    with pytest.raises(ValueError, match=r"values: 1 NaN or infinite value \(index 2\); remove or fill them"):
        fit_process([50.009e-3, 50.01e-3, np.nan], limits=BORE_LIMITS)


@pytest.mark.parametrize("factor, unit", [(1e3, "µm"), (1e-3, "m")])
def test_values_in_the_wrong_unit_are_named(tmp_path, factor, unit):
    x = _normal_sample(40) / MM * factor
    path = _csv(tmp_path, "bores.csv", ["bore"] + [f"{v:.10g}" for v in x])
    with pytest.raises(ValueError, match=rf"'bores.csv', column 'bore': 40 values look like {unit}, not mm like the "
                                         rf"limits \[50, 50.018\] \(lines 2, 3, 4, 5, 6 and 35 more"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


def test_one_value_in_micrometres_among_millimetres_is_named(tmp_path):
    x = [f"{v:.4f}" for v in _normal_sample(40) / MM]
    x[7] = "50009"
    path = _csv(tmp_path, "bores.csv", ["bore"] + x)
    with pytest.raises(ValueError, match=r"1 value looks like µm, not mm .*line 9: 50009"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


def test_a_far_typing_error_is_refused(tmp_path):
    x = [f"{v:.4f}" for v in _normal_sample(40) / MM]
    x[0] = "50.9"
    path = _csv(tmp_path, "bores.csv", ["bore"] + x)
    with pytest.raises(ValueError, match=r"1 value more than 10 tolerance widths off the limits \[50, 50.018\] mm "
                                         r"\(line 2: 50.9\)"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


def test_too_few_values_say_how_many_are_needed():
    with pytest.raises(ValueError, match=r"values: 12 values; a fit \(the normal model; skew-normal 50, mixture 100\) "
                                         r"needs at least 25"):
        fit_process(_normal_sample(12), limits=BORE_LIMITS)
    fit = fit_process(_normal_sample(40), limits=BORE_LIMITS)
    assert "40 readings; the mixture model needs at least 100" in fit.notes


def test_readings_all_equal_or_on_too_coarse_a_grid_are_refused():
    with pytest.raises(ValueError, match=r"values: all 30 readings are equal \(0.05001 m\): no spread to fit"):
        fit_process(np.full(30, 50.010e-3), limits=BORE_LIMITS)
    with pytest.raises(ValueError, match=r"only 2 different readings in 30"):
        fit_process(np.repeat([50.010e-3, 50.011e-3], 15), limits=BORE_LIMITS)


def test_limits_in_the_wrong_order_are_refused(tmp_path):
    with pytest.raises(ValueError, match=r"limits: upper limit 50 m is below lower limit 50.018 m; give the lower "
                                         r"limit first"):
        fit_process(_normal_sample(), limits=(50.018, 50.000))
    path = _csv(tmp_path, "b.csv", ["bore"] + [f"{v:.4f}" for v in _normal_sample() / MM])
    code = cli.main(["measure", "fit", str(path), "--column", "bore", "--limits", "50.018", "50.000"])
    assert code == 2


def test_a_gauge_coarser_than_the_spread_is_refused_clearly():
    with pytest.raises(ValueError, match=r"the gauge's repeatability 3e-06 m is not below the readings' standard "
                                         r"deviation \d\.\d+e-06 m, so the process spread sigma_process\^2 = "
                                         r"sigma_read\^2 - R\^2 is not positive"):
        fit_process(_normal_sample(), limits=BORE_LIMITS, gauge_repeatability=3e-6)
    with pytest.raises(ValueError, match=r"gauge_repeatability: 0.5 m is more than the tolerance width"):
        fit_process(_normal_sample(), limits=BORE_LIMITS, gauge_repeatability=0.5)


def test_a_missing_column_is_named_with_the_columns_there(tmp_path):
    path = _csv(tmp_path, "b.csv", ["block,bore_mm", "B1,50.01"])
    with pytest.raises(ValueError, match=r"'b.csv': no column 'bore' \(did you mean 'bore_mm'\?\); its columns: "
                                         r"block, bore_mm"):
        fit_csv(path, "bore", limits=(50.000, 50.018))


# --- engine files --------------------------------------------------------------------------------------------

def _grouped_fit():
    rng = np.random.default_rng(11)
    codes = np.repeat(np.arange(30), 5)
    z = np.sqrt(0.3) * rng.standard_normal(30)[codes] + np.sqrt(0.7) * rng.standard_normal(150)
    x = SkewNormal(50.0085e-3, 2.2e-6, 0.7).from_normal(z) + 0.5e-6 * rng.standard_normal(150)
    return fit_process(x, limits=BORE_LIMITS, gauge_repeatability=0.5e-6, groups=codes, resamples=200)


def test_to_toml_is_the_engine_files_process_entry():
    fit = _grouped_fit()
    text = fit.to_toml()
    data = tomllib.loads(text)
    assert set(data) == {"process", "shared"}
    again = process_from_spec(data["process"], lo=50.0, hi=50.018, scale=1e-3, field="housing_bore.process")
    assert type(again) is type(fit.process)
    assert again.mean == pytest.approx(fit.process.mean, abs=1e-9)
    assert again.std == pytest.approx(fit.process.std, rel=1e-6)
    assert data["shared"] == pytest.approx(fit.shared, abs=1e-3)
    assert re.search(r"^# .*gauge repeatability 0.5 um removed", text, re.M)


@pytest.mark.integration
def test_the_engine_file_written_from_fits_loads_strictly_and_runs_the_main_job(tmp_path):
    fit = _grouped_fit()
    out = write_engine("iso-example", tmp_path / "measured.toml", fit.entries("housing_bore"), name="measured")
    original = engine_path("iso-example").read_text()
    text = out.read_text()
    for line in original.splitlines():  # every comment of the user's file is kept
        if line.lstrip().startswith("#"):
            assert line in text
    engine = load_engine(out)
    assert engine.name == "measured"
    assert type(engine.housing_bore.process) is type(fit.process)
    assert engine.housing_bore.process.mean == pytest.approx(fit.process.mean, abs=1e-9)
    assert engine.housing_bore.shared == pytest.approx(fit.shared, abs=1e-3)
    result = stackup.compare(engine=out, schemes=("iso13778-4",), n_engines=200, design=None, scenarios={},
                             mechanics_engines=10, progress=False)
    ranking = stackup.rank(result)
    assert ranking.loc["iso13778-4", "bearings"] == 1000


@pytest.mark.slow
def test_the_engine_file_written_from_measurements_runs_stackup_compare(tmp_path):
    """The user's route end to end: fits and fitting tests -> engine file -> `stackup compare --engine FILE` (1,000
    engines, one scheme, without the designer and the scenarios, which have their own tests on engine files)."""
    housing = calibrate_housing(synthetic_fitting_tests(12, 75e-3, np.random.default_rng(5)), "iso-example")
    written = write_engine("iso-example", tmp_path / "written.toml",
                           [*_grouped_fit().entries("housing_bore"), housing.entry()], name="written")
    result = subprocess.run([sys.executable, "-m", "stackup.cli", "compare", "--engine", str(written), "--n", "1000",
                             "--schemes", "iso13778-4", "--no-design", "--no-scenarios"], cwd=tmp_path, capture_output=True, text=True, timeout=3600,
                            env=dict(os.environ))
    assert result.returncode == 0, result.stderr[-2000:]
    assert "Traceback" not in result.stderr
    report = (tmp_path / "reports" / "compare" / "report.md").read_text()
    assert "written" in report


def test_write_engine_never_replaces_a_file_unless_asked(tmp_path):
    out = tmp_path / "e.toml"
    out.write_text("mine")
    with pytest.raises(ValueError, match=r"out: .*e.toml' exists; pass force=True \(--force\) to replace it"):
        write_engine("iso-example", out, [])
    assert out.read_text() == "mine"
    builtin = engine_path("iso-example")
    with pytest.raises(ValueError, match=r"is the engine file itself"):
        write_engine(builtin, builtin, [])


# --- the housing from fitting tests --------------------------------------------------------------------------

def test_calibrate_housing_recovers_the_outer_diameter_and_its_interval_shrinks_with_tests():
    table = synthetic_fitting_tests(40, 75e-3, np.random.default_rng([1, 37]))
    widths = []
    for n in (5, 10, 20, 40):
        result = calibrate_housing({k: v[:n] for k, v in table.items()}, "iso-example")
        lo, hi = result.housing_outer_ci
        assert lo <= 75e-3 <= hi, n
        widths.append(hi - lo)
        assert result.residuals.shape == (n,)
        assert result.residual_sigma == pytest.approx(1.3e-6, rel=0.6)  # the tests' gauge noise
    assert all(a > b for a, b in zip(widths, widths[1:])), widths


def test_calibrated_engine_copy_carries_the_value_and_its_interval(tmp_path):
    table = synthetic_fitting_tests(12, 75e-3, np.random.default_rng([2, 37]))
    result = calibrate_housing(table, "iso-example")
    out = result.write_engine(tmp_path / "cal.toml")
    text = out.read_text()
    lo, hi = result.housing_outer_ci
    assert f"profile-likelihood interval {lo / MM:.6g} to {hi / MM:.6g}" in text
    assert "the file assumed 90" in text
    assert load_engine(out).press_fit.housing_outer == pytest.approx(result.housing_outer, rel=1e-7)
    assert load_engine(result.write_engine(tmp_path / "lo.toml", which="lower")).press_fit.housing_outer == \
        pytest.approx(lo, rel=1e-7)


def test_fitting_tests_in_millimetres_are_named(tmp_path):
    table = synthetic_fitting_tests(6, 75e-3, np.random.default_rng(3))
    table["assembled_bore"] = table["assembled_bore"] / MM
    with pytest.raises(ValueError, match=r"tests\['assembled_bore'\]: 6 values look like mm, not m"):
        calibrate_housing(table, "iso-example")
    with pytest.raises(ValueError, match=r"tests: 2 fitting tests; the calibration needs at least 3"):
        calibrate_housing({k: v[:2] for k, v in synthetic_fitting_tests(2, 75e-3, 1).items()}, "iso-example")


# --- the command line ----------------------------------------------------------------------------------------

def test_measure_fit_command_prints_the_entry_and_draws(tmp_path, capsys):
    rng = np.random.default_rng(0)
    lines = ["# SYNTHETIC", "block,position,bore"]
    lines += [f"B{i // 5},{i % 5 + 1},{50.009 + 0.002 * z:.4f}" for i, z in enumerate(rng.standard_normal(100))]
    path = _csv(tmp_path, "b.csv", lines)
    figure = tmp_path / "b.png"
    code = cli.main(["measure", "fit", str(path), "--column", "bore", "--limits", "50.000", "50.018",
                             "--gauge-repeatability", "0.0005", "--group", "block", "--resamples", "200",
                             "--figure", str(figure)])
    out = capsys.readouterr().out
    assert code == 0
    assert re.search(r'^process = \{ distribution = "normal", mean = 50\.00\d+, sigma = 0\.00\d+ \}$', out, re.M)
    assert re.search(r"^shared = 0\.\d+", out, re.M)
    assert figure.stat().st_size > 10_000


def test_stackup_measure_is_a_subcommand_of_stackup(tmp_path, capsys):
    table = synthetic_fitting_tests(6, 75e-3, np.random.default_rng(6))
    path = _csv(tmp_path, "t.csv", [",".join(table)] + [",".join(f"{table[c][i]:.9g}" for c in table)
                                                         for i in range(6)])
    assert cli.main(["measure", "swell", str(path), "--units", "m"]) == 0
    assert re.search(r"housing_outer = \d+\.\d mm", capsys.readouterr().out)
    assert cli.main(["measure", "fit", str(path), "--column", "nothing", "--limits", "50", "50.018"]) == 2
    assert "no column 'nothing'" in capsys.readouterr().err


def test_measure_swell_command_writes_a_copy(tmp_path, capsys):
    table = synthetic_fitting_tests(8, 75e-3, np.random.default_rng(4))
    path = _csv(tmp_path, "t.csv", [",".join(table)] + [",".join(f"{table[c][i]:.9g}" for c in table)
                                                         for i in range(8)])
    out = tmp_path / "eng.toml"
    assert cli.main(["measure", "swell", str(path), "--units", "m", "--engine", "iso-example", "--out",
                     str(out)]) == 0
    assert "housing_outer = " in capsys.readouterr().out
    assert load_engine(out).name == "eng"
    assert cli.main(["measure", "swell", str(path), "--units", "m", "--out", str(out)]) == 2
    assert "--out: " in capsys.readouterr().err


# --- one unit convention for both measure commands, and fit --out -------------------------------------------------


def _fitting_tests_csv(tmp_path, name, scale):
    """Eight synthetic fitting tests as a CSV file, lengths in m times ``scale``."""
    table = synthetic_fitting_tests(8, 75e-3, np.random.default_rng(4))
    rows = [",".join(f"{table[c][i] * (1 if c == 'temperature' else scale):.9g}" for c in table) for i in range(8)]
    return _csv(tmp_path, name, [",".join(table), *rows])


def test_measure_swell_reads_the_tests_in_mm_like_the_engine_file_and_names_a_metre_file(tmp_path, capsys):
    in_mm, in_m = _fitting_tests_csv(tmp_path, "mm.csv", 1e3), _fitting_tests_csv(tmp_path, "m.csv", 1.0)
    assert calibrate_housing(in_mm, "iso-example", units="mm").housing_outer == pytest.approx(
        calibrate_housing(in_m, "iso-example").housing_outer, rel=1e-6)
    assert cli.main(["measure", "swell", str(in_mm)]) == 0  # mm by default, as the engine file and `measure fit`
    assert re.search(r"housing_outer = \d+\.\d mm", capsys.readouterr().out)
    assert cli.main(["measure", "swell", str(in_m)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "look like m, not mm" in err


def test_measure_fit_out_writes_the_fitted_process_into_a_copy_of_the_engine_file(tmp_path, capsys):
    rng = np.random.default_rng(3)
    values = 50.009 + 0.002 * rng.standard_normal(120)
    path = _csv(tmp_path, "bores.csv", ["housing_bore", *(f"{v:.4f}" for v in values)])
    out = tmp_path / "fitted.toml"
    fit = ["measure", "fit", str(path), "--column", "housing_bore", "--limits", "50.000", "50.018", "--resamples",
           "100"]
    assert cli.main([*fit, "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    engine = load_engine(out)
    mean = re.search(r"mean = ([\d.]+)", printed).group(1)
    assert engine.name == "fitted" and engine.housing_bore.process.mean == pytest.approx(float(mean) * 1e-3)
    assert engine.journal_d.process == load_engine("iso-example").journal_d.process  # nothing else changed
    assert "process fitted by stackup.measure" in out.read_text()
    assert cli.main([*fit, "--out", str(out)]) == 2 and "--force" in capsys.readouterr().err
    bores = _csv(tmp_path, "b.csv", ["bore", *(f"{v:.4f}" for v in values)])
    assert cli.main(["measure", "fit", str(bores), "--column", "bore", "--limits", "50.000", "50.018", "--out",
                     str(tmp_path / "other.toml")]) == 2
    assert "--dimension" in capsys.readouterr().err and not (tmp_path / "other.toml").exists()
