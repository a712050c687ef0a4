"""Streaming summaries: they agree with the full dataset and memory does not grow with n."""

import tracemalloc

import numpy as np
import pytest
import xarray as xr

from stackup import Study
from stackup.study.summaries import BIN_WIDTH, quantile_ci

KW = dict(n_engines=4000, mechanics_engines=0, progress=False, pilot_engines=3000, chunk_lots=1)


@pytest.fixture(scope="module")
def pair():
    return Study(**KW).run(), Study(**KW, keep="summaries").run()


def test_summaries_agree_with_the_full_dataset(pair):
    full, summary = pair
    for scheme in full.scheme.values:
        d = full.sel(scheme=scheme)
        s = summary.sel(scheme=scheme)
        ok = d.status.values == 0
        c = d.clearance_operating.values[ok]
        assert float(s.clearance_operating_mean) == pytest.approx(c.mean(), rel=1e-12)
        assert float(s.clearance_operating_std) == pytest.approx(c.std(ddof=1), rel=1e-9)
        assert int(s.clearance_operating_histogram.sum()) == c.size
        lo, hi = full.clearance_window.values
        assert int(s.outside_window_count) == np.count_nonzero((c < lo) | (c > hi))
        assert np.array_equal(s.status_count.values, np.bincount(d.status.values.ravel(), minlength=5))
        assert float(s.worst_low.sel(rank=1, field="clearance_operating")) == c.min()
        assert float(s.worst_high.sel(rank=1, field="clearance_operating")) == c.max()
        assert abs(quantile_ci(s.clearance_operating_histogram.values, 0.5)[0] - np.median(c)) <= BIN_WIDTH
        xr.testing.assert_equal(s.shells_made, d.shells_made)


def test_summaries_are_identical_whatever_the_chunking(pair):
    _, summary = pair
    xr.testing.assert_equal(Study(**{**KW, "chunk_lots": 3}, keep="summaries").run(), summary)


def peak_memory(n):
    tracemalloc.start()
    Study(**{**KW, "n_engines": n}, keep="summaries").run()
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


@pytest.mark.integration
def test_memory_of_a_streaming_study_does_not_grow_with_n():
    Study(**{**KW, "n_engines": 1000}, keep="summaries").run()  # warm caches
    small, large = peak_memory(4000), peak_memory(16000)
    assert large < 1.2 * small


def test_summaries_cover_the_press_fit_and_the_mechanical_chain():
    kw = dict(n_engines=2500, mechanics_engines=30, crank_angle_step=12.0, progress=False, pilot_engines=3000,
              chunk_lots=1, schemes=("iso13778-3", "iso13778-4"))
    full, summary = Study(**kw).run(), Study(**kw, keep="summaries").run()
    assert summary.attrs["mechanics_engines_used"] == 30
    for name in ("reaction_max", "h_min", "h_min_mean", "alpha", "life", "film_temperature", "crank_status"):
        np.testing.assert_array_equal(summary[name].values, full[name].values)
    np.testing.assert_array_equal(summary.clearance_operating_sampled.values,
                                  full.clearance_operating.isel(engine=slice(0, 30)).values)
    for scheme in full.scheme.values:
        d, s = full.sel(scheme=scheme), summary.sel(scheme=scheme)
        ok = d.status.values == 0
        # the checks are over every declared temperature, hence no looser than at the operating one
        p, sigma = d.contact_pressure_lowest.values[ok], d.shell_stress_highest.values[ok]
        assert np.all(p <= d.contact_pressure.values[ok]) and np.all(sigma >= d.shell_stress.values[ok])
        assert float(s.contact_pressure_min) == p.min() and float(s.shell_stress_max) == sigma.max()
        assert int(s.low_contact_pressure_count) == np.count_nonzero(p < float(s.design_contact_pressure_min))
        assert int(s.high_shell_stress_count) == np.count_nonzero(sigma > float(s.design_shell_stress_max))
        assert int(s.loss_of_fit_count) == np.count_nonzero(d.loss_of_fit_any_temperature.values[ok])
        assert float(s.housing_swell_mean) == pytest.approx(d.housing_swell.values[ok].mean(), rel=1e-12)
    xr.testing.assert_equal(Study(**{**kw, "chunk_lots": 3}, keep="summaries").run(), summary)


def test_summaries_count_the_bearings_below_the_minimum_clearance_as_the_full_dataset(tmp_path):
    from stackup.engines import builtin_folder
    from stackup.facts.tables import soaked

    # the aluminium block with a minimum clearance its ISO 13778 schemes straddle at the -30 degC cold start
    text = (builtin_folder() / "iso-example-aluminium.toml").read_text()
    window = "relative_clearance = [0.00075, 0.00125]"
    engine = tmp_path / "alu.toml"
    engine.write_text(text.replace(window, window + '\nminimum_clearance = 0.047\nminimum_clearance_source = "test"'))
    kw = dict(KW, n_engines=1000, engine=engine, schemes=("iso13778-4",))
    full, summary = Study(**kw).run(), Study(**kw, keep="summaries").run()
    d, s = full.sel(scheme="iso13778-4"), summary.sel(scheme="iso13778-4")
    ok = d.status.values == 0
    at_assembly, cold = d.clearance_assembly.values[ok], d.clearance_cold.values[ok]
    below = np.count_nonzero(np.fmin(at_assembly, cold) < 47e-6)
    assert 0 < below < ok.sum() and np.all(cold < at_assembly)  # aluminium: closed cold
    assert int(s.below_minimum_clearance_count) == below
    for counted in (soaked(d), soaked(s)):
        assert counted.below_minimum == below and counted.assembled == ok.sum()
        assert counted.cold_mean == pytest.approx(cold.mean(), rel=1e-12)
        assert counted.assembly_std == pytest.approx(at_assembly.std(ddof=1), rel=1e-9)
